// Motion over time (ode/): jets, Taylor coefficients, the point integrator and
// the verified enclosure, each against an independent truth:
//   - jet rules against series known in closed form (sin, cos, exp, log,
//     sqrt, atan, quotient), and interval jets containing MPFR jets at 256 bits
//     on random series;
//   - the Taylor coefficients of Euler's body from the generic Gibbs-Appell
//     path (the scene's code on jets) against those of Euler's equations
//     written out (euler_omega_dot on jets), and against finite sums of the
//     closed-form solution's derivatives;
//   - the enclosure of Euler's free body at T against the closed-form solution
//     in Jacobi elliptic functions (Boost.Math, 100 digits), on random bodies;
//   - the heavy top's energy and two momenta, enclosed over every whole step,
//     each containing its initial value computed at 256 bits;
//   - point trajectories (double, dd) inside the enclosures widened by their
//     precision.
#define BOOST_TEST_MODULE motion
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <random>

#include "built_scalars.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "pendulum_problem.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/scalar/decimal.hpp"
#include "affine_check.hpp"
#include "motion_checks.hpp"

using namespace appell;
using truth_t = boost::multiprecision::mpfr_float_100;

namespace {

using affine_check::holds;

using motion_checks::decimal_on_grid;

}  // namespace

BOOST_AUTO_TEST_CASE(jet_rules_match_closed_form_series) {
  // x(t) = 0.3 + t: sin, cos, exp of x have coefficients f^(k)(0.3) / k!; 1 / (1 - t) has all 1;
  // sqrt(1 + t) and log(1 + t), atan(t) their binomial / alternating series.
  const int n = 12;
  const jet_order_scope order(n);
  const jet<double> x(std::vector<double>{0.3, 1.0});
  const jet<double> s = sin(x), c = cos(x), e = exp(x);
  double fact = 1;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) fact *= k;
    const double dk_sin = (k % 4 == 0) ? std::sin(0.3) : (k % 4 == 1) ? std::cos(0.3) : (k % 4 == 2) ? -std::sin(0.3) : -std::cos(0.3);
    const double dk_cos = (k % 4 == 0) ? std::cos(0.3) : (k % 4 == 1) ? -std::sin(0.3) : (k % 4 == 2) ? -std::cos(0.3) : std::sin(0.3);
    BOOST_TEST(std::fabs(s[k] - dk_sin / fact) <= 1e-15);
    BOOST_TEST(std::fabs(c[k] - dk_cos / fact) <= 1e-15);
    BOOST_TEST(std::fabs(e[k] - std::exp(0.3) / fact) <= 1e-15);
  }
  const jet<double> t(std::vector<double>{0.0, 1.0});
  const jet<double> geo = jet<double>(1.0) / (jet<double>(1.0) - t);
  const jet<double> sq = sqrt(jet<double>(1.0) + t), lg = log(jet<double>(1.0) + t), at = atan(t);
  double binom = 1;  // C(1/2, k)
  for (int k = 0; k <= n; ++k) {
    BOOST_TEST(geo[k] == 1.0);
    BOOST_TEST(std::fabs(sq[k] - binom) <= 1e-16);
    binom *= (0.5 - k) / (k + 1);
    if (k > 0) BOOST_TEST(std::fabs(lg[k] - ((k % 2) ? 1.0 : -1.0) / k) <= 1e-16);
    const double atk = (k % 2 == 0) ? 0.0 : (((k / 2) % 2) ? -1.0 : 1.0) / k;
    BOOST_TEST(std::fabs(at[k] - atk) <= 1e-16);
  }
  // A jet's powers are its products: pown(x, 5) = x x x x x.
  const jet<double> p5 = pown(x, 5), m5 = x * x * x * x * x;
  for (int k = 0; k <= n; ++k) BOOST_TEST(std::fabs(p5[k] - m5[k]) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(interval_jets_contain_mpfr_jets_at_256_bits) {
  // Random series with decimal coefficients, enclosed; the same operations in MPFR at 256 bits
  // on the exact decimals (each coefficient's error ~1e-75): every interval coefficient holds it.
  std::mt19937_64 rng(20261124);
  const evaluation_scope<interval> scope;
  const int n = 16;
  long checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::string> a(n + 1), b(n + 1);
    for (int k = 0; k <= n; ++k) {
      a[static_cast<std::size_t>(k)] = (rng() % 2 ? "-" : "") + decimal_on_grid(rng, 1, 2000);
      b[static_cast<std::size_t>(k)] = decimal_on_grid(rng, 1, 2000);
    }
    b[0] = decimal_on_grid(rng, 2000, 3000);  // b_0 > |...|: sqrt, log and the quotient defined
    std::vector<interval> ai, bi;
    std::vector<mpfr> am, bm;
    {
      const mp_precision_scope p(256);
      for (int k = 0; k <= n; ++k) {
        ai.push_back(from_decimal<interval>(a[static_cast<std::size_t>(k)]));
        bi.push_back(from_decimal<interval>(b[static_cast<std::size_t>(k)]));
        am.push_back(from_decimal<mpfr>(a[static_cast<std::size_t>(k)]));
        bm.push_back(from_decimal<mpfr>(b[static_cast<std::size_t>(k)]));
      }
      const jet_order_scope order(n);
      const jet<interval> A(ai), B(bi);
      const jet<mpfr> Am(am), Bm(bm);
      const std::vector<std::pair<jet<interval>, jet<mpfr>>> results{
          {A * B, Am * Bm}, {A / B, Am / Bm},         {sin(A), sin(Am)}, {cos(B), cos(Bm)},
          {sqrt(B), sqrt(Bm)}, {log(B), log(Bm)},     {atan(A), atan(Am)}, {exp(A / B), exp(Am / Bm)},
          {pown(A, 3), pown(Am, 3)}, {A - B * A, Am - Bm * Am}};
      for (const auto& [ri, rm] : results)
        for (int k = 0; k <= n; ++k) {
          const truth_t v(rm[k].str(0, std::ios_base::scientific));
          if (!holds(ri[k], v)) BOOST_ERROR("coefficient " << k << " misses the 256-bit value at trial " << trial);
          ++checked;
        }
    }
  }
  BOOST_TEST(checked == 200L * 10 * 17);
  BOOST_TEST_MESSAGE("interval jets: " << checked << " coefficients, each holding the 256-bit value");
}

namespace {
/// Euler's equations written out (euler_omega_dot), as a problem: the second route.
struct euler_direct {
  euler_body<double> body;
  static constexpr int dim = 3;
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const euler_body<S> b{vec3<S>(S(body.inertia(0)), S(body.inertia(1)), S(body.inertia(2))), vec3<S>(S(0), S(0), S(0))};
    return vector_t<S>(euler_omega_dot(b, vec3<S>(x(0), x(1), x(2))));
  }
};
}  // namespace

BOOST_AUTO_TEST_CASE(euler_body_coefficients_from_the_generic_path_equal_euler_s_equations) {
  // The scene's code (gibbs_appell on the body, then the order-by-order solve) on jets against
  // Euler's equations written out (euler_omega_dot) on jets: two routes to the same series.
  const euler_body<double> body{vec3<double>(1.0, 2.0, 3.0), vec3<double>(0.0, 0.0, 0.0)};
  const ode::euler_body_problem<double> prob{body};
  const vector_t<double> x0 = vector_t<double>(vec3<double>(1.0, 1.0, 1.0));
  const auto c1 = ode::taylor_series(prob, x0, 24);
  const auto c2 = ode::taylor_series(euler_direct{body}, x0, 24);
  for (int k = 0; k <= 24; ++k)
    for (int i = 0; i < 3; ++i) {
      const double a = c1[static_cast<std::size_t>(k)](i), b = c2[static_cast<std::size_t>(k)](i);
      BOOST_TEST(std::fabs(a - b) <= 1e-14 * std::max(1.0, std::fabs(b)), "k=" << k << " i=" << i << ": " << a << " vs " << b);
    }
}


BOOST_AUTO_TEST_CASE(euler_body_enclosure_holds_the_elliptic_solution) {
  const double widest = motion_checks::euler_body_holds_the_elliptic_solution<interval>(7, 12, 24, std::ldexp(1.0, -53));
  BOOST_TEST_MESSAGE("euler_body: 12 random bodies enclosed to T = 5 hold the elliptic solution; widest " << widest);
  BOOST_TEST(widest < 1e-10);  // a verified but useful enclosure, not merely a true one
}

BOOST_AUTO_TEST_CASE(heavy_top_invariants_stay_inside_their_initial_values) {
  // I1 = I2 = 1 (A about O), I3 = 2, m g l = 1, theta0 = 1, phi'0 = 0.5, psi'0 = 5 (the top:
  // its psi, phi are appell's phi, psi: Euler angles z-x-z with psi about the vertical).
  const evaluation_scope<interval> scope;
  const ode::heavy_top_problem<interval> prob{interval(1), interval(2), interval(1), interval(1), interval(1)};
  vector_t<interval> x0(6);
  x0 << interval(0), interval(1), interval(0), from_decimal<interval>("0.5"), interval(0), interval(5);
  std::vector<ode::named_values<mpfr>> initial;
  {
    const mp_precision_scope p(256);
    const ode::heavy_top_problem<mpfr> pm{mpfr(1), mpfr(2), mpfr(1), mpfr(1), mpfr(1)};
    vector_t<mpfr> xm(6);
    xm << mpfr(0), mpfr(1), mpfr(0), mpfr("0.5"), mpfr(0), mpfr(5);
    pm.invariants(xm, initial);
  }
  long steps = 0;
  double widest = 0;
  vector_t<interval> end;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, interval(10), 24, std::ldexp(1.0, -53), 1.0, 2, [&](const ode::enclosed_step<interval>& s) {
        ++steps;
        end = s.end;
        BOOST_TEST_REQUIRE(s.invariants.size() == initial.size());
        for (std::size_t q = 0; q < initial.size(); ++q) {
          const truth_t v(initial[q].values[0].str(0, std::ios_base::scientific));
          BOOST_TEST(holds(s.invariants[q].values[0], v), initial[q].name << " over step " << steps);
          widest = std::max(widest, boost::numeric::width(s.invariants[q].values[0]));
        }
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  BOOST_TEST_MESSAGE("heavy_top: energy and momenta over " << steps << " steps to T = 10, widest " << widest);
  // theta and theta' at T = 10 hold the nutation in Jacobi elliptic functions (heavy_top_nutation, models/heavy_top.hpp)
  const ode::heavy_top_nutation<truth_t> nutation(truth_t(1), truth_t(2), truth_t(1), truth_t(1), truth_t("0.5"), truth_t(0),
                                                  truth_t(5));
  const std::array<truth_t, 2> th = nutation.at(truth_t(10));
  BOOST_TEST(holds(end(1), th[0]), to_string(end(1)) << " vs " << th[0]);
  BOOST_TEST(holds(end(4), th[1]), to_string(end(4)) << " vs " << th[1]);
}

BOOST_AUTO_TEST_CASE(heavy_top_nutation_from_a_moving_start_holds_the_closed_form) {
  // The shipped top (data/scenes/heavy_top.json: A = 0.08, C = 0.02, m = 1.5, l = 0.2, g = 9.81,
  // theta0 = 0.7, theta'0 = 1.2, psi'0 = 1.5, phi'0 = 40): the closed form's phase comes from an
  // incomplete K and the sign of theta'; theta, theta' enclosed at T = 1.5 hold it.
  const evaluation_scope<interval> scope;
  const auto d = [](const char* x) { return from_decimal<interval>(x); };
  const ode::heavy_top_problem<interval> prob{d("0.08"), d("0.02"), d("1.5"), d("0.2"), d("9.81")};
  vector_t<interval> x0(6);
  x0 << interval(0), d("0.7"), d("0.3"), d("1.5"), d("1.2"), d("40");
  vector_t<interval> end;
  const ode::enclose_stats st = ode::enclose(prob, x0, d("1.5"), 24, std::ldexp(1.0, -53), 1.0, 2,
                                             [&](const ode::enclosed_step<interval>& s) { end = s.end; });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  const truth_t mgl = truth_t("1.5") * truth_t("0.2") * truth_t("9.81");
  const ode::heavy_top_nutation<truth_t> nutation(truth_t("0.08"), truth_t("0.02"), mgl, truth_t("0.7"), truth_t("1.5"),
                                                  truth_t("1.2"), truth_t(40));
  const std::array<truth_t, 2> th = nutation.at(truth_t("1.5"));
  BOOST_TEST(holds(end(1), th[0]), to_string(end(1)) << " vs " << th[0]);
  BOOST_TEST(holds(end(4), th[1]), to_string(end(4)) << " vs " << th[1]);
  BOOST_TEST(boost::numeric::width(end(1)) < 1e-10);
}

BOOST_AUTO_TEST_CASE(point_trajectories_agree_with_the_enclosure) {
  // Euler's body (1, 2, 3), omega0 = (1, 0, 1) to T = 10, where the elliptic solution is known:
  // the interval enclosure holds it; double lies inside the enclosure widened by a few hundred
  // units of its last place; dd lies within 1e-26 of the solution (100 digits), which no double
  // trajectory can (double's own error there is about 1e-14).
  const ode::euler_free_body_solution<truth_t> truth{truth_t(1), truth_t(2), truth_t(3), truth_t(1), truth_t(1)};
  const std::array<truth_t, 3> w = truth.at(truth_t(10));
  vector_t<interval> end;
  {
    const evaluation_scope<interval> scope;
    const ode::euler_body_problem<interval> prob{{vec3<interval>(interval(1), interval(2), interval(3)), vec3<interval>::Zero()}};
    vector_t<interval> x0(3);
    x0 << interval(1), interval(0), interval(1);
    const auto st = ode::enclose(prob, x0, interval(10), 24, std::ldexp(1.0, -53), 1.0, 2,
                                 [&](const ode::enclosed_step<interval>& s) { end = s.end; });
    BOOST_TEST_REQUIRE(st.complete, st.reason);
    for (int i = 0; i < 3; ++i) BOOST_TEST(holds(end(i), w[static_cast<std::size_t>(i)]));
  }
  auto run = [&]<class T>(std::type_identity<T>) {
    const ode::euler_body_problem<T> prob{{vec3<T>(T(1), T(2), T(3)), vec3<T>(T(0), T(0), T(0))}};
    vector_t<T> x0(3), last;
    x0 << T(1), T(0), T(1);
    ode::simulate(prob, x0, T(10), T(1), 20 + 10 * (sizeof(T) > 8), std::ldexp(1.0, -53 * (1 + (sizeof(T) > 8))),
                  [&](const ode::sample<T>& s) { last = s.x; });
    return last;
  };
  const vector_t<double> d = run(std::type_identity<double>{});
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(d(i) >= end(i).lower() - 1e-13);
    BOOST_TEST(d(i) <= end(i).upper() + 1e-13);
  }
  test::if_built<dd>([&]<class DD>(std::type_identity<DD> type) {
    const vector_t<DD> q = run(type);
    double worst_dd = 0, worst_double = 0;
    for (int i = 0; i < 3; ++i) {
      const truth_t exact = w[static_cast<std::size_t>(i)];
      // dd's value exactly: the sum of its two doubles, at 100 digits
      const truth_t got = truth_t(q(i).x[0]) + truth_t(q(i).x[1]);
      worst_dd = std::max(worst_dd, static_cast<double>(abs(got - exact)));
      worst_double = std::max(worst_double, static_cast<double>(abs(truth_t(d(i)) - exact)));
    }
    BOOST_TEST_MESSAGE("Euler's body to T = 10: largest error " << worst_double << " in double, " << worst_dd << " in dd");
    BOOST_TEST(worst_dd < 1e-26);
    BOOST_TEST(worst_double > 1e-26);  // what makes the dd bound a test of dd
  });
}

BOOST_AUTO_TEST_CASE(pendulum_energy_holds_its_initial_value_and_the_state_its_period) {
  // theta'' = -sin theta, theta0 = 1 as a one-body system on the generic path, in both of its
  // descriptions (on the rod's turning axes, and on the fixed axes).  The energy over every step
  // holds -cos 1 and the state at t = 2.5 the elliptic solution (motion_checks.hpp); to 3 periods
  // 4 K(sin(1/2)) the energy over every step holds -cos 1 and the state is back to (1, 0).
  for (const bool rod_axes : {true, false}) {
  BOOST_TEST_CONTEXT("rod_axes " << rod_axes) {
  BOOST_TEST(motion_checks::pendulum_energy_holds_its_initial_value<interval>(rod_axes, 24, std::ldexp(1.0, -53), "2.5") < 1e-12);
  const evaluation_scope<interval> scope;
  const ode::pendulum_problem<interval> prob{interval(1), interval(1), interval(1), rod_axes};
  vector_t<interval> x0(2);
  x0 << interval(1), interval(0);
  const truth_t e0 = -cos(truth_t(1));
  const truth_t period = ode::pendulum_solution<truth_t>{truth_t(1), truth_t(1)}.period();
  // the enclosure at 3 periods (an interval t_end, from the 100-digit period)
  const truth_t t3 = 3 * period;
  const interval t_end(std::nextafter(static_cast<double>(t3), 0.0), std::nextafter(static_cast<double>(t3), 100.0));
  vector_t<interval> end;
  long steps = 0;
  const ode::enclose_stats st = ode::enclose(prob, x0, t_end, 24, std::ldexp(1.0, -53), 1.0, 2,
                                             [&](const ode::enclosed_step<interval>& s) {
                                               ++steps;
                                               BOOST_TEST(holds(s.invariants[0].values[0], e0), "energy over step " << steps);
                                               end = s.end;
                                             });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  // t_end is an interval of two ulps around 3 periods: the state at every time in it is enclosed,
  // the true one at exactly 3 periods among them.
  BOOST_TEST(holds(end(0), truth_t(1)), to_string(end(0)));
  BOOST_TEST(holds(end(1), truth_t(0)), to_string(end(1)));
  BOOST_TEST(boost::numeric::width(end(0)) < 1e-12);
  }
  }
}

BOOST_AUTO_TEST_CASE(the_pendulum_on_its_rod_axes_and_on_the_fixed_axes_is_one_motion) {
  // The two descriptions of pendulum_problem against theta'' = -(g / l) sin theta at 332 bits, on
  // 2000 random states and parameters: interval results hold it, double ones meet it to a few ulps.
  std::mt19937_64 rng(20261126u);
  std::uniform_real_distribution<double> angle(-3.1, 3.1), rate(-20, 20), par(0.1, 10);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const double th = angle(rng), w = rate(rng), m = par(rng), l = par(rng), g = par(rng);
    const truth_t exact = -(truth_t(g) / truth_t(l)) * sin(truth_t(th));
    for (const bool rod_axes : {true, false}) {
      vector_t<interval> xi(2);
      xi << interval(th), interval(w);
      {
        const evaluation_scope<interval> scope;
        const ode::pendulum_problem<interval> pi{interval(m), interval(l), interval(g), rod_axes};
        const interval a = pi.rhs(xi)(1);
        BOOST_TEST(holds(a, exact), "rod_axes " << rod_axes << " at " << th << ": " << to_string(a) << " vs " << exact);
      }
      vector_t<double> xd(2);
      xd << th, w;
      const ode::pendulum_problem<double> pd{m, l, g, rod_axes};
      const double a = pd.rhs(xd)(1);
      // the fixed axes' b = -l^2 s c u^2 + l^2 s c u^2 rounds at the scale of l^2 u^2, not of the result
      const double scale = (g / l + (rod_axes ? 0.0 : w * w)) * 1e-14;
      BOOST_TEST(std::abs(a - static_cast<double>(exact)) <= scale, "rod_axes " << rod_axes << " at " << th);
      ++checked;
    }
  }
  BOOST_TEST(checked == 4000);
}

BOOST_AUTO_TEST_CASE(the_affine_set_holds_every_true_point_through_steps_and_merges) {
  // 1, 3 and 6 components, 300 runs of 40 steps each (tests/affine_check.hpp).
  const evaluation_scope<interval> scope;
  for (int n : {1, 3, 6}) {
    const affine_check::outcome o = affine_check::run<interval>(n, 300, 40, 20261125u + static_cast<unsigned>(n));
    BOOST_TEST_MESSAGE("affine set, interval, n = " << n << ": " << o.checks << " components checked, " << o.merges
                                                     << " merges, " << o.misses << " misses, widest " << o.widest);
    BOOST_TEST(o.misses == 0, o.first_miss);
    BOOST_TEST(o.merges > 500);
  }
}

BOOST_AUTO_TEST_CASE(the_flow_jacobian_holds_the_variational_equation_s_solution) {
  // ode::detail::flow_jacobian (enclose's variational linear part) against Phi(h) of
  // Phi' = (A0 + t E) Phi, Phi(0) = 1, computed apart: its Taylor series at 332 bits,
  // (k + 1) Phi_(k+1) = A0 Phi_k + E Phi_(k-1), summed until the terms are below 1e-80.  The
  // interval input is A0 + [0, h] E, which holds A(t) over the step; 400 random systems of 2 to
  // 7 components, h from 1e-4 to 0.3, entries of A0 up to 20 and of E up to 5 (h |A| up to
  // about 40, in practice below 30; the refusals, h |A| >= 30 and an unbounded entry, at the end).
  // Then the same 400 systems badly scaled, D A D^-1 with d_i = 10^(+-3) at random (not powers of
  // 2: the truth is computed from the scaled entries): the remainder is bounded in a balanced norm
  // and spread over the entries by d_j / d_i, each of which must still hold the truth; most of
  // them have h ||A||_inf far above 30 and are taken only because of the balancing.  Every entry
  // inside, and with E = 0 (a point A) the enclosure is thin: its width below 1e-12 e^(h ||A||)
  // (unscaled; times d_i / d_j when scaled), not a wide one that holds anything.
  const evaluation_scope<interval> scope;
  std::mt19937_64 gen(20261207u);
  std::uniform_real_distribution<double> u(-1.0, 1.0), lh(std::log(1e-4), std::log(0.3));
  std::uniform_int_distribution<int> dim(2, 7);
  for (const bool scaled : {false, true}) {
    int checked = 0, refused = 0, thin_cases = 0, beyond_plain_norm = 0;
    double widest_thin = 0;
    for (int c = 0; c < 400; ++c) {
      const int n = dim(gen);
      const double h = std::exp(lh(gen));
      const double a_scale = 20 * std::abs(u(gen)), e_scale = c % 4 == 0 ? 0.0 : 5 * std::abs(u(gen));
      Eigen::MatrixXd A0(n, n), E(n, n);
      Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
      if (scaled)
        for (int i = 0; i < n; ++i) d(i) = std::pow(10.0, 3 * u(gen));
      double row_max = 0;  // the scale of Phi's terms: e^(h ||A0||), unscaled
      for (int i = 0; i < n; ++i) {
        double row = 0;
        for (int j = 0; j < n; ++j) {
          const double a = a_scale * u(gen), e = e_scale * u(gen);
          row += std::abs(a);
          A0(i, j) = a * d(i) / d(j);
          E(i, j) = e * d(i) / d(j);
        }
        row_max = std::max(row_max, row);
      }
      matrix_t<interval> A(n, n);
      const interval tau(0.0, h);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) A(i, j) = interval(A0(i, j)) + tau * interval(E(i, j));
      matrix_t<interval> J;
      if (!ode::detail::flow_jacobian(A, interval(h), J)) {
        ++refused;
        continue;
      }
      double plain_norm = 0;
      for (int i = 0; i < n; ++i) {
        double row = 0;
        for (int j = 0; j < n; ++j) row += std::max(std::abs(A(i, j).lower()), std::abs(A(i, j).upper()));
        plain_norm = std::max(plain_norm, row);
      }
      if (h * plain_norm >= 30) ++beyond_plain_norm;
      // the truth, in plain loops (row-major n x n)
      using M = std::vector<truth_t>;
      const auto at = [n](int i, int j) { return static_cast<std::size_t>(i * n + j); };
      M a0(static_cast<std::size_t>(n * n)), e(a0.size()), prev(a0.size(), truth_t(0)), cur(a0.size(), truth_t(0));
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          a0[at(i, j)] = truth_t(A0(i, j));
          e[at(i, j)] = truth_t(E(i, j));
          cur[at(i, j)] = truth_t(i == j ? 1 : 0);
        }
      M phi = cur;
      truth_t hk(1);
      const truth_t th(h);
      for (int k = 0; k < 4000; ++k) {
        M next(a0.size(), truth_t(0));
        truth_t big(0);
        hk *= th;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) {
            truth_t s(0);
            for (int l = 0; l < n; ++l) s += a0[at(i, l)] * cur[at(l, j)] + e[at(i, l)] * prev[at(l, j)];
            next[at(i, j)] = s / (k + 1);
            const truth_t term = next[at(i, j)] * hk;
            phi[at(i, j)] += term;
            if (abs(term) > big) big = abs(term);
          }
        prev = std::move(cur);
        cur = std::move(next);
        if (k > 5 && big < truth_t("1e-80")) break;
      }
      const double scale = std::exp(h * row_max);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          BOOST_TEST(truth_t(J(i, j).lower()) <= phi[at(i, j)]);
          BOOST_TEST(phi[at(i, j)] <= truth_t(J(i, j).upper()));
          if (e_scale == 0) widest_thin = std::max(widest_thin, (J(i, j).upper() - J(i, j).lower()) / (scale * d(i) / d(j)));
        }
      ++checked;
      if (e_scale == 0) ++thin_cases;
    }
    BOOST_TEST_MESSAGE("flow_jacobian" << (scaled ? " (scaled)" : "") << ": " << checked << " systems checked, " << refused
                                       << " refused (h |A| >= 30 balanced), " << beyond_plain_norm
                                       << " with h ||A||_inf >= 30 taken, " << thin_cases << " with a point A, widest entry there "
                                       << widest_thin << " e^(h ||A||)");
    BOOST_TEST(checked >= 300);
    BOOST_TEST(thin_cases >= 60);
    BOOST_TEST(widest_thin < 1e-12);
    if (scaled) BOOST_TEST(beyond_plain_norm >= 100);
  }
  // A stiff second-order system, x'' = -K x with K = diag(10^4, 1) (two pairs, not coupled), as a
  // state's rates: A = [[0, 1], [-K, 0]], ||A||_inf = 10^4 but spectral radius 100: h = 0.01 has
  // h ||A||_inf = 100, refused by the plain norm, and h a about 1.3 balanced, taken; the truth
  // Phi(h) = [[cos(w h), sin(w h) / w], [-w sin(w h), cos(w h)]] of each pair.
  {
    matrix_t<interval> A = matrix_t<interval>::Zero(4, 4), J;
    A(0, 2) = A(1, 3) = interval(1.0);
    A(2, 0) = interval(-1e4);
    A(3, 1) = interval(-1.0);
    BOOST_TEST_REQUIRE(ode::detail::flow_jacobian(A, interval(0.01), J));
    const truth_t w(100), th(0.01);  // the double h, exactly
    BOOST_TEST(truth_t(J(0, 0).lower()) <= cos(w * th));
    BOOST_TEST(cos(w * th) <= truth_t(J(0, 0).upper()));
    BOOST_TEST(truth_t(J(0, 2).lower()) <= sin(w * th) / w);
    BOOST_TEST(sin(w * th) / w <= truth_t(J(0, 2).upper()));
    BOOST_TEST(truth_t(J(2, 0).lower()) <= -w * sin(w * th));
    BOOST_TEST(-w * sin(w * th) <= truth_t(J(2, 0).upper()));
    BOOST_TEST(truth_t(J(3, 1).lower()) <= -sin(th));
    BOOST_TEST(-sin(th) <= truth_t(J(3, 1).upper()));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) BOOST_TEST(J(i, j).upper() - J(i, j).lower() < 1e-12 * std::max(1.0, std::abs(J(i, j).upper())));
  }
  // The remainder itself: in mpfi at 1200 bits the series stops at 2^-(1000 + 16 + range) (the
  // target's precision is capped at 1000 bits), far above the rounding, so only the remainder makes
  // J hold the truth: left out, or spread over the entries the wrong way (rho d_i / d_j for
  // rho d_j / d_i), it leaves the truth outside.  x'' = -2^14 x, A = [[0, 1], [-2^14, 0]]: |A|'s
  // Perron root 128, balanced exactly by d = (2^7, 1) (both rows of D |A| D^-1 sum to 128); at
  // h = 2^-8, Phi(h) = [[cos 0.5, sin 0.5 / 128], [-128 sin 0.5, cos 0.5]], the truth at 1500 bits.
  {
    const mp_precision_scope bits(1200);
    const evaluation_scope<mpfi> mp_scope;
    matrix_t<mpfi> A = matrix_t<mpfi>::Zero(2, 2), J;
    A(0, 1) = mpfi(1);
    A(1, 0) = mpfi(-16384);
    BOOST_TEST_REQUIRE(ode::detail::flow_jacobian(A, mpfi(std::ldexp(1.0, -8)), J));
    std::array<mpfr, 4> truth;
    {
      const mp_precision_scope truth_bits(1500);
      const mpfr w(128), th(std::ldexp(1.0, -8));
      truth = {cos(w * th), sin(w * th) / w, -w * sin(w * th), cos(w * th)};
    }
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const mpfr& t = truth[static_cast<std::size_t>(2 * i + j)];
        BOOST_TEST((lower(J(i, j)) <= t && t <= upper(J(i, j))), "entry " << i << j);
        // and thin: within 2^-990 times the entry's scale (the remainder, not a wide interval)
        BOOST_TEST(mpfr(upper(J(i, j)) - lower(J(i, j))) < mpfr(std::ldexp(1.0, -990)) * (i == 1 && j == 0 ? 128 : 1));
      }
  }
  // refused, never carried: an unbounded entry, and h |A| >= 30
  matrix_t<interval> A = matrix_t<interval>::Identity(2, 2), J;
  A(0, 1) = interval(0.0, std::numeric_limits<double>::infinity());
  BOOST_TEST(!ode::detail::flow_jacobian(A, interval(0.01), J));
  A(0, 1) = interval(0.0);
  BOOST_TEST(ode::detail::flow_jacobian(A, interval(0.01), J));
  BOOST_TEST(!ode::detail::flow_jacobian(A, interval(30.0), J));
}
