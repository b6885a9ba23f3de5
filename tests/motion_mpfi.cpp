// appell enclose in MPFI (113 bits): Euler's free body against its closed-form solution in
// Jacobi elliptic functions (Boost.Math at 100 digits), and the simple pendulum's energy
// (the generic path on a one-body system) inside its initial value at 256 bits over every step.
// One heavy scalar in this unit (tests/motion.cpp has interval<double>).
#define BOOST_TEST_MODULE motion_mpfi
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <random>

#include "appell/ode/closed_forms.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "affine_check.hpp"

using namespace appell;
using truth_t = boost::multiprecision::mpfr_float_100;

namespace {
bool holds(const mpfi& x, const truth_t& v) {
  return mpfr_lessequal_p(&x.backend().data()->left, v.backend().data()) &&
         mpfr_lessequal_p(v.backend().data(), &x.backend().data()->right);
}
double width_of(const mpfi& x) { return approx_double(mpfi(scalar_traits<mpfi>::width(x))); }
}  // namespace

BOOST_AUTO_TEST_CASE(euler_body_at_113_bits_holds_the_elliptic_solution) {
  // I = (1, 1.5, 2.25), omega0 = (0.8, 0, 1.1): M^2 - 2 E I2 = 1 (1 - 1.5) 0.64 + 2.25 (0.75) 1.21 > 0.
  const truth_t I1(1), I2("1.5"), I3("2.25"), a("0.8"), c("1.1"), T(5);
  const std::array<truth_t, 3> w = ode::euler_free_body_solution<truth_t>{I1, I2, I3, a, c}.at(T);

  const mp_precision_scope precision(113);
  const evaluation_scope<mpfi> scope;
  const ode::euler_body_problem<mpfi> prob{{vec3<mpfi>(mpfi(1), from_decimal<mpfi>("1.5"), from_decimal<mpfi>("2.25")),
                                            vec3<mpfi>(mpfi(0), mpfi(0), mpfi(0))}};
  vector_t<mpfi> x0(3);
  x0 << from_decimal<mpfi>("0.8"), mpfi(0), from_decimal<mpfi>("1.1");
  vector_t<mpfi> end;
  const ode::enclose_stats st = ode::enclose(prob, x0, mpfi(5), 40, std::ldexp(1.0, -113), 1.0, 2,
                                             [&](const ode::enclosed_step<mpfi>& s) { end = s.end; });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  double widest = 0;
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(holds(end(i), w[i]), "component " << i << " misses " << w[i].str(40));
    widest = std::max(widest, width_of(end(i)));
  }
  BOOST_TEST_MESSAGE("euler_body at 113 bits, T = 5: " << st.steps << " steps, widest " << widest);
  BOOST_TEST(widest < 1e-25);
}

BOOST_AUTO_TEST_CASE(pendulum_energy_stays_inside_its_initial_value) {
  const mp_precision_scope precision(113);
  const evaluation_scope<mpfi> scope;
  const ode::pendulum_problem<mpfi> prob{mpfi(1), mpfi(1), mpfi(1)};
  vector_t<mpfi> x0(2);
  x0 << mpfi(1), mpfi(0);
  truth_t e0;
  {
    truth_t one(1);
    e0 = -cos(one);  // m l^2 0 / 2 - m g l cos 1
  }
  long steps = 0;
  double widest = 0;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, mpfi(10), 40, std::ldexp(1.0, -113), 1.0, 2, [&](const ode::enclosed_step<mpfi>& s) {
        ++steps;
        BOOST_TEST(holds(s.invariants[0].values[0], e0), "energy over step " << steps);
        widest = std::max(widest, width_of(s.invariants[0].values[0]));
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  BOOST_TEST_MESSAGE("pendulum at 113 bits: energy over " << steps << " steps to T = 10, widest " << widest);
}

BOOST_AUTO_TEST_CASE(the_affine_set_holds_every_true_point_through_steps_and_merges) {
  // The interval-product path of the affine set (tests/affine_check.hpp), at 113 bits.
  const mp_precision_scope precision(113);
  const evaluation_scope<mpfi> scope;
  for (int n : {1, 3, 6}) {
    const affine_check::outcome o = affine_check::run<mpfi>(n, 60, 40, 20261126u + static_cast<unsigned>(n));
    BOOST_TEST_MESSAGE("affine set, mpfi 113, n = " << n << ": " << o.checks << " components checked, " << o.merges
                                                     << " merges, " << o.misses << " misses, widest " << o.widest);
    BOOST_TEST(o.misses == 0, o.first_miss);
    BOOST_TEST(o.merges > 100);
  }
}
