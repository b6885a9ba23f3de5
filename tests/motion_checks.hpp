// The motion checks that hold in every interval type, written once (issue "honest tests"):
// tests/motion.cpp runs them in interval<double>, tests/motion_mpfi.cpp in MPFI at 113 bits.
//   euler_body_holds_the_elliptic_solution: Euler's free body, random bodies and starts on a
//     decimal grid, enclosed to T = 5; over every step the solution at the step's start, and at
//     T the solution, in Jacobi elliptic functions (Boost.Math, 100 digits), lie in the enclosure;
//   pendulum_energy_holds_its_initial_value: the simple pendulum on the generic path (one body,
//     on its rod's turning axes or on the fixed axes): the energy over every step to t_end holds
//     -cos 1, and at t_end the state holds the elliptic solution.
// Each returns the widest enclosure it saw, for the caller's bound on usefulness.
#pragma once

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <string>

#include "appell/ode/enclose.hpp"
#include "appell/models/euler_body.hpp"
#include "pendulum_problem.hpp"
#include "appell/scalar/decimal.hpp"
#include "affine_check.hpp"

namespace motion_checks {

using truth_t = affine_check::truth;  // MPFR, 100 decimal digits
using affine_check::holds;

/// A decimal in [lo, hi] thousandths, on the grid of thousandths.
inline std::string decimal_on_grid(std::mt19937_64& rng, int lo_thousandths, int hi_thousandths) {
  std::uniform_int_distribution<int> d(lo_thousandths, hi_thousandths);
  const int v = d(rng);
  return std::to_string(v / 1000) + "." + std::to_string(1000 + v % 1000).substr(1);
}

template <class I>
double width_of(const I& x) {
  return appell::approx_double(I(appell::scalar_traits<I>::width(x)));
}

template <class I>
std::string text_of(const I& x) {
  return "[" + affine_check::lower_of(x).str(25) + ", " + affine_check::upper_of(x).str(25) + "]";
}

/// `bodies` random bodies (seed `seed`) enclosed to T = 5 at the given order and tolerance.
template <class I>
double euler_body_holds_the_elliptic_solution(unsigned seed, int bodies, int order, double tol) {
  using namespace appell;
  std::mt19937_64 rng(seed);
  int cases = 0;
  double widest = 0;
  while (cases < bodies) {
    const std::string I1 = decimal_on_grid(rng, 500, 1500);
    const std::string d2 = decimal_on_grid(rng, 100, 1200), d3 = decimal_on_grid(rng, 100, 1200);
    const truth_t i1(I1), i2 = i1 + truth_t(d2), i3 = i2 + truth_t(d3);
    if (!(i3 < i1 + i2)) continue;  // a body's moments satisfy the triangle inequality
    const std::string a = decimal_on_grid(rng, 200, 1500), c = decimal_on_grid(rng, 200, 1500);
    const truth_t ta(a), tc(c);
    if (!(i1 * (i1 - i2) * ta * ta + i3 * (i3 - i2) * tc * tc > 0)) continue;  // M^2 > 2 E I2
    const std::string T = "5";
    const ode::euler_free_body_solution<truth_t> truth{i1, i2, i3, ta, tc};
    const std::array<truth_t, 3> w = truth.at(truth_t(T));
    const evaluation_scope<I> scope;
    const I J1 = from_decimal<I>(I1), J2 = J1 + from_decimal<I>(d2), J3 = J2 + from_decimal<I>(d3);
    const ode::euler_body_problem<I> prob{{vec3<I>(J1, J2, J3), vec3<I>(I(0), I(0), I(0))}};
    vector_t<I> x0(3);
    x0 << from_decimal<I>(a), I(0), from_decimal<I>(c);
    vector_t<I> end;
    const ode::enclose_stats st =
        ode::enclose(prob, x0, from_decimal<I>(T), order, tol, 1.0, 2, [&](const ode::enclosed_step<I>& s) {
          end = s.end;
          // over every step: the solution at the step's start lies in it
          const std::array<truth_t, 3> w0 = truth.at(affine_check::lower_of(s.t0));
          for (int i = 0; i < 3; ++i) BOOST_TEST(holds(s.over(i), w0[static_cast<std::size_t>(i)]));
        });
    BOOST_TEST_REQUIRE(st.complete, st.reason);
    for (int i = 0; i < 3; ++i) {
      BOOST_TEST(holds(end(i), w[static_cast<std::size_t>(i)]),
                 "I = (" << I1 << ", +" << d2 << ", +" << d3 << ") omega0 = (" << a << ", 0, " << c << "): component " << i
                         << " misses " << w[static_cast<std::size_t>(i)].str(20) << ": " << text_of(end(i)));
      widest = std::max(widest, width_of(end(i)));
    }
    ++cases;
  }
  return widest;
}

/// theta'' = -sin theta, theta0 = 1, to t_end (a decimal; a turning point every K(sin 1/2) = 1.7).
template <class I>
double pendulum_energy_holds_its_initial_value(bool rod_axes, int order, double tol, const std::string& t_end) {
  using namespace appell;
  const evaluation_scope<I> scope;
  const ode::pendulum_problem<I> prob{I(1), I(1), I(1), rod_axes};
  vector_t<I> x0(2);
  x0 << I(1), I(0);
  const truth_t e0 = -cos(truth_t(1));  // m l^2 0 / 2 - m g l cos 1
  long steps = 0;
  double widest = 0;
  vector_t<I> end;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, from_decimal<I>(t_end), order, tol, 1.0, 2, [&](const ode::enclosed_step<I>& s) {
        ++steps;
        BOOST_TEST(holds(s.invariants[0].values[0], e0), "energy over step " << steps);
        widest = std::max(widest, width_of(s.invariants[0].values[0]));
        end = s.end;
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  const std::array<truth_t, 2> exact = ode::pendulum_solution<truth_t>{truth_t(1), truth_t(1)}.at(truth_t(t_end));
  BOOST_TEST(holds(end(0), exact[0]), text_of(end(0)) << " vs " << exact[0]);
  BOOST_TEST(holds(end(1), exact[1]), text_of(end(1)) << " vs " << exact[1]);
  widest = std::max({widest, width_of(end(0)), width_of(end(1))});
  BOOST_TEST_MESSAGE("pendulum (rod axes " << rod_axes << ") to t = " << t_end << ": energy over " << steps
                                                << " steps, widest " << widest);
  return widest;
}

}  // namespace motion_checks
