// Motion over time of the paper's constrained scenes (issue 12, point 4), each
// through the scene's own reader and dynamics (as appell simulate / enclose run
// them), against an independent truth:
//   - a sphere rolling down an incline (the plane with gravity tilted) from a
//     moving start: its centre accelerates at exactly 5/7 of the tangential
//     gravity, so at T the enclosed centre and omega hold the exact rational
//     motion, and over every step the centre's acceleration, the contact force
//     (2/7 of the tangential weight back up the slope, the normal weight) and
//     the energy hold their exact values;
//   - a sphere rolling in a bowl (paper sec. 7): the energy over every step holds
//     its initial value at 256 bits, the two constraints (the centre on the
//     surface of centres, no pivoting) hold 0 over every step;
//   - Example I, the top forced onto its cone: the energy (the frictionless
//     cone's couple does no work) over every step holds its 256-bit initial value;
//   - point trajectories (double, dd) inside the enclosures.
#define BOOST_TEST_MODULE motion_scenes
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/gmp.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"
#include "appell/io/scene.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "pendulum_problem.hpp"
#include "appell/ode/taylor.hpp"
#include "affine_check.hpp"

using namespace appell;
using truth_t = boost::multiprecision::mpfr_float_100;
using rational_t = boost::multiprecision::mpq_rational;

namespace {

using affine_check::holds;
/// A rational as a 100-digit truth (its error, 1e-100, far below any enclosure's width).
truth_t truth(const rational_t& q) { return truth_t(numerator(q)) / truth_t(denominator(q)); }

scene_input scene_of(const std::string& json) { return read_scene(parse_json(json)); }
scene_input scene_file(const std::string& file) {
  return read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
}

template <Scalar T>
ode::rolling_sphere_problem<T> sphere_problem(const scene_input& scene, vector_t<T>& x0) {
  const auto m = rolling_sphere_model::prepare<T>(scene.as<rolling_sphere_input>());
  x0.resize(6);
  x0 << m.c(0), m.c(1), m.c(2), m.omega(0), m.omega(1), m.omega(2);
  return {m.M, m.A, m.a, m.surface, m.F, m.tau};
}
template <Scalar T>
ode::top_on_cone_problem<T> cone_problem(const scene_input& scene, vector_t<T>& x0) {
  const auto m = top_on_cone_model::prepare<T>(scene.as<top_on_cone_input>());
  x0.resize(4);
  x0 << m.theta, m.phi, m.theta_dot, m.phi_dot;
  return {m.top, m.cone};
}

/// The invariants at the initial state, at 256 bits (the truth they must keep).
template <class Problem>
std::vector<truth_t> initial_invariants(const scene_input& scene, Problem (*make)(const scene_input&, vector_t<mpfr>&)) {
  const mp_precision_scope p(256);
  vector_t<mpfr> x0;
  const Problem prob = make(scene, x0);
  std::vector<ode::named_values<mpfr>> out;
  prob.invariants(x0, out);
  std::vector<truth_t> v;
  for (const auto& o : out) v.emplace_back(o.values[0].str(0, std::ios_base::scientific));
  return v;
}

/// Point trajectories (double, dd) at T inside the enclosure widened by `slack`.
template <template <class> class Problem>
void point_runs_inside(const scene_input& scene, Problem<mpfr> (*)(const scene_input&, vector_t<mpfr>&),
                       const vector_t<interval>& end, const std::string& T, double slack) {
  auto run = [&]<class S>(std::type_identity<S>, int order, double tol) {
    const evaluation_scope<S> scope;
    vector_t<S> x0;
    Problem<S> prob = [&] {
      if constexpr (std::is_same_v<Problem<S>, ode::rolling_sphere_problem<S>>) return sphere_problem<S>(scene, x0);
      else return cone_problem<S>(scene, x0);
    }();
    vector_t<S> last;
    ode::simulate(prob, x0, from_decimal<S>(T), from_decimal<S>(T), order, tol, [&](const ode::sample<S>& s) { last = s.x; });
    for (Eigen::Index i = 0; i < end.size(); ++i) {
      const double v = approx_double(last(i));
      BOOST_TEST(v >= end(i).lower() - slack, scalar_traits<S>::name << " x" << i << " = " << v << " below " << end(i).lower());
      BOOST_TEST(v <= end(i).upper() + slack, scalar_traits<S>::name << " x" << i << " = " << v << " above " << end(i).upper());
    }
  };
  run(std::type_identity<double>{}, 20, std::ldexp(1.0, -53));
  test::if_built<dd>([&](auto type) { run(type, 36, std::ldexp(1.0, -104)); });
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_sphere_rolling_down_an_incline_accelerates_at_five_sevenths_of_g_sin_alpha) {
  // Mass 2, radius 1/10 (A = 2/5 M a^2 = 1/125), gravity (3, 0, -9): the slope's pull is 3 along
  // x.  Rolling: x'' = 5/7 * 3 = 15/7 exactly; from omega = (0, 5, 0), v = omega x a e_z = (1/2, 0, 0).
  const scene_input scene = scene_of(R"({"model": "rolling_sphere", "sphere": {"mass": "2", "radius": "0.1"},
    "surface": {"type": "plane"}, "gravity": ["3", "0", "-9"],
    "state": {"center": ["0", "0", "0.1"], "omega": ["0", "5", "0"]}})");
  const rational_t M(2), a(1, 10), gx(3), gz(9), v0(1, 2), acc = rational_t(5, 7) * gx, T(2);
  const evaluation_scope<interval> scope;
  vector_t<interval> x0;
  const auto prob = sphere_problem<interval>(scene, x0);
  const truth_t E0 = truth(M * v0 * v0 / 2 + rational_t(2, 5) * M * a * a * (v0 / a) * (v0 / a) / 2 + M * gz * a);
  long steps = 0;
  vector_t<interval> end;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, interval(2), 24, std::ldexp(1.0, -53), 1.0, 2, [&](const ode::enclosed_step<interval>& s) {
        ++steps;
        end = s.end;
        const auto& r = s.results;  // center_ddot, omega_dot, contact_force, normal_force, pivot_couple
        BOOST_TEST(holds(r[0].values[0], truth(acc)), "x'' over step " << steps << ": " << to_string(r[0].values[0]));
        BOOST_TEST(holds(r[0].values[1], truth_t(0)));
        BOOST_TEST(holds(r[0].values[2], truth_t(0)));
        BOOST_TEST(holds(r[2].values[0], truth(M * (acc - gx))), "friction " << to_string(r[2].values[0]));
        BOOST_TEST(holds(r[2].values[2], truth(M * gz)));
        BOOST_TEST(holds(r[3].values[0], truth(M * gz)));
        BOOST_TEST(holds(s.invariants[0].values[0], E0), "energy over step " << steps);
        BOOST_TEST(holds(s.invariants[1].values[0], truth_t(0)));  // c_z - a
        BOOST_TEST(holds(s.invariants[2].values[0], truth_t(0)));  // omega . n
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  const rational_t x = v0 * T + acc * T * T / 2, vx = v0 + acc * T;
  BOOST_TEST(holds(end(0), truth(x)), to_string(end(0)) << " vs " << truth(x));
  BOOST_TEST(holds(end(1), truth_t(0)));
  BOOST_TEST(holds(end(2), truth(a)));
  BOOST_TEST(holds(end(3), truth_t(0)));
  BOOST_TEST(holds(end(4), truth(vx / a)), to_string(end(4)) << " vs " << truth(vx / a));
  BOOST_TEST(holds(end(5), truth_t(0)));
  BOOST_TEST(boost::numeric::width(end(0)) < 1e-12);
  BOOST_TEST_MESSAGE("incline: " << steps << " steps to T = 2, x(T) = " << to_string(end(0)) << " (exact 1 + 30/7)");
}

BOOST_AUTO_TEST_CASE(a_sphere_in_a_bowl_keeps_its_energy_and_its_constraints, *test::needs_scalars({"mpfr", "dd"})) {
#if APPELL_TEST_HAS(mpfr) && APPELL_TEST_HAS(dd)
  const scene_input scene = scene_file("rolling_sphere_bowl.json");
  const std::vector<truth_t> initial = initial_invariants(scene, &sphere_problem<mpfr>);
  BOOST_TEST_REQUIRE(initial.size() == 3u);  // energy, surface_residual, pivot_residual
  const evaluation_scope<interval> scope;
  vector_t<interval> x0;
  const auto prob = sphere_problem<interval>(scene, x0);
  long steps = 0;
  double widest = 0;
  vector_t<interval> end;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, interval(2), 24, std::ldexp(1.0, -53), 1.0, 2, [&](const ode::enclosed_step<interval>& s) {
        ++steps;
        end = s.end;
        BOOST_TEST_REQUIRE(s.invariants.size() == initial.size());
        for (std::size_t q = 0; q < initial.size(); ++q) {
          BOOST_TEST(holds(s.invariants[q].values[0], initial[q]), s.invariants[q].name << " over step " << steps << ": "
                                                                                        << to_string(s.invariants[q].values[0]));
          widest = std::max(widest, boost::numeric::width(s.invariants[q].values[0]));
        }
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  BOOST_TEST_MESSAGE("bowl: " << steps << " steps to T = 2; energy and constraints over every step, widest " << widest);
  BOOST_TEST(widest < 1e-9);
  point_runs_inside(scene, &sphere_problem<mpfr>, end, "2", 1e-13);
#endif
}

BOOST_AUTO_TEST_CASE(the_top_on_its_cone_keeps_its_energy, *test::needs_scalars({"mpfr", "dd"})) {
#if APPELL_TEST_HAS(mpfr) && APPELL_TEST_HAS(dd)
  const scene_input scene = scene_file("top_on_cone.json");
  const std::vector<truth_t> initial = initial_invariants(scene, &cone_problem<mpfr>);
  BOOST_TEST_REQUIRE(initial.size() == 1u);
  const evaluation_scope<interval> scope;
  vector_t<interval> x0;
  const auto prob = cone_problem<interval>(scene, x0);
  long steps = 0;
  double widest = 0;
  vector_t<interval> end;
  const ode::enclose_stats st =
      ode::enclose(prob, x0, interval(1), 24, std::ldexp(1.0, -53), 1.0, 2, [&](const ode::enclosed_step<interval>& s) {
        ++steps;
        end = s.end;
        BOOST_TEST(holds(s.invariants[0].values[0], initial[0]), "energy over step " << steps << ": "
                                                                                     << to_string(s.invariants[0].values[0]));
        widest = std::max(widest, boost::numeric::width(s.invariants[0].values[0]));
      });
  BOOST_TEST_REQUIRE(st.complete, st.reason);
  BOOST_TEST_MESSAGE("top on its cone: " << steps << " steps to T = 1; energy over every step, widest " << widest);
  BOOST_TEST(widest < 1e-9);
  point_runs_inside(scene, &cone_problem<mpfr>, end, "1", 1e-12);
#endif
}

namespace {
/// A right-hand side whose operations change between the passes of one series: while theta's
/// series is exactly 0 it multiplies other operands (pass 0), then not (pass 1 on): the memo must
/// compute the differing operations afresh.
struct branching_problem {
  static constexpr int dim = 2;
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    vector_t<S> d(2);
    if (exactly_zero(x(0))) {
      const S w = x(1) * x(1);
      d << S(1) + w * w, x(1) * S(3);
    } else {
      const S w = x(0) * x(1);
      d << x(1) / (S(2) + w * w), sin(x(0)) * x(1) - w;
    }
    return d;
  }
};

/// The series of prob from x0 with and without the memo, bit for bit; returns the memo's counts.
template <class P, class S>
std::pair<long, long> series_identical(const P& prob, const vector_t<S>& x0, int p, const std::string& what) {
  detail::jet_memo<S> stats;
  const auto with = ode::taylor_series(prob, x0, p, true, &stats);
  const auto without = ode::taylor_series(prob, x0, p, false);
  long differ = 0;
  for (int k = 0; k <= p; ++k)
    for (Eigen::Index i = 0; i < x0.size(); ++i)
      if (!detail::identical(with[static_cast<std::size_t>(k)](i), without[static_cast<std::size_t>(k)](i))) ++differ;
  BOOST_TEST(differ == 0, what << " (" << scalar_traits<S>::name << "): " << differ << " coefficients differ with the memo");
  return {stats.reused, stats.computed};
}

template <class S>
vector_t<S> jittered(const vector_t<S>& x, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  vector_t<S> r = x;
  for (Eigen::Index i = 0; i < r.size(); ++i) r(i) = r(i) + S(d(rng));
  return r;
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_taylor_memo_changes_no_digit_of_any_series) {
  // taylor_series takes each operation's low coefficients from the previous pass (jet.hpp,
  // detail::jet_memo).  Against the series computed without it, on every scene's problem, in
  // point and interval scalars, from 8 random states each: every coefficient bit for bit.  And the
  // memo must serve: most operations reuse (otherwise it only costs).
  std::mt19937_64 rng(20261125);
  long reused = 0, computed = 0;
  auto tally = [&](std::pair<long, long> c) {
    reused += c.first;
    computed += c.second;
  };
  auto all = [&]<class S>(std::type_identity<S>, int p) {
    const evaluation_scope<S> scope;
    for (int trial = 0; trial < 8; ++trial) {
      {
        const ode::euler_body_problem<S> prob{{vec3<S>(S(1), S(2), S(3)), vec3<S>(S(0), S(0), S(0.25))}};
        tally(series_identical(prob, jittered(vector_t<S>(vector_t<S>::Constant(3, S(1))), rng), p, "euler_body"));
      }
      {
        const ode::heavy_top_problem<S> prob{S(1), S(2), S(1), S(1), S(1)};
        vector_t<S> x0(6);
        x0 << S(0), S(1), S(0), S(0.5), S(0), S(5);
        tally(series_identical(prob, jittered(x0, rng), p, "heavy_top"));
      }
      {
        const ode::pendulum_problem<S> prob{S(1), S(1), S(1)};
        vector_t<S> x0(2);
        x0 << S(1), S(0);
        tally(series_identical(prob, jittered(x0, rng), p, "pendulum"));
      }
      for (const char* file : {"rolling_sphere_bowl.json", "rolling_sphere_plane.json", "rolling_sphere_pipe.json"}) {
        vector_t<S> x0;
        const scene_input scene = scene_file(file);
        const auto prob = sphere_problem<S>(scene, x0);
        vector_t<S> x = x0;
        for (int i = 3; i < 6; ++i) x(i) = jittered(x0, rng)(i);  // omega only: the centre stays on its surface
        tally(series_identical(prob, x, p, file));
      }
      {
        vector_t<S> x0;
        const scene_input scene = scene_file("top_on_cone.json");  // the problem refers to the scene's cone
        const auto prob = cone_problem<S>(scene, x0);
        tally(series_identical(prob, jittered(x0, rng), p, "top_on_cone"));
      }
      vector_t<S> b(2);
      b << S(0), S(0.5);
      tally(series_identical(branching_problem{}, b, p, "branching"));
    }
  };
  all(std::type_identity<double>{}, 20);
  all(std::type_identity<interval>{}, 24);
  test::if_built<dd>([&](auto type) { all(type, 30); });
  {
    const mp_precision_scope bits(200);
    all(std::type_identity<mpfi>{}, 12);
  }
  BOOST_TEST_MESSAGE("taylor memo: " << reused << " operations took their low coefficients from the memo, "
                                     << computed << " were computed in full");
  BOOST_TEST(reused > 5 * computed);
}

BOOST_AUTO_TEST_CASE(the_taylor_memo_changes_no_digit_of_the_variational_series) {
  // The Jacobians d x_k / d x0 over a box (multi_dual of jets), with and without the memo.
  const evaluation_scope<interval> scope;
  const ode::heavy_top_problem<interval> prob{interval(1), interval(2), interval(1), interval(1), interval(1)};
  vector_t<interval> X(6);
  X << interval(0), interval(0.99, 1.01), interval(0), interval(0.5), interval(-0.01, 0.01), interval(5);
  ode::series<interval> c1, c2;
  std::vector<matrix_t<interval>> D1, D2;
  ode::taylor_series_jacobian(prob, X, 14, c1, D1, true);
  ode::taylor_series_jacobian(prob, X, 14, c2, D2, false);
  long differ = 0;
  for (std::size_t k = 0; k < c1.size(); ++k)
    for (int i = 0; i < 6; ++i) {
      if (!detail::identical(c1[k](i), c2[k](i))) ++differ;
      for (int j = 0; j < 6; ++j)
        if (!detail::identical(D1[k](i, j), D2[k](i, j))) ++differ;
    }
  BOOST_TEST(differ == 0);
}

namespace {
/// a and b the same number bit for bit; on jets, every coefficient.
template <class S>
bool same_bits(const S& a, const S& b) {
  if constexpr (requires { a.c; a.size(); }) {
    if (a.size() != b.size()) return false;
    for (int k = 0; k < a.size(); ++k)
      if (!detail::identical(a[k], b[k])) return false;
    return true;
  } else {
    return detail::identical(a, b);
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_right_hand_sides_leave_the_reactions_out_and_change_no_digit) {
  // The motion's right-hand sides form the free speeds' columns only (cotton_free_accelerations,
  // cotton_free_motion: 4 directions instead of 7 on the top on its pivot, 3 instead of 4 on the
  // cone, 3 instead of 7 for the sphere).  Against the accelerations of the full Cotton's method
  // (what appell eval reports), from random states, in point, interval and jet scalars: bit for bit.
  std::mt19937_64 rng(20261126);
  long compared = 0, differ = 0;
  auto check = [&](const auto& a, const auto& b, const std::string& what) {
    for (Eigen::Index i = 0; i < a.size(); ++i) {
      ++compared;
      if (!same_bits(a(i), b(i))) {
        ++differ;
        BOOST_TEST_MESSAGE(what << ": component " << i << " differs");
      }
    }
  };
  auto all = [&]<class S>(std::type_identity<S>) {
    using B = base_scalar_t<S>;
    const evaluation_scope<B> scope;
    auto lift = [](const vector_t<B>& x) {
      vector_t<S> y(x.size());
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        if constexpr (std::is_same_v<S, B>) {
          y(i) = x(i);
        } else {  // a jet: the state plus a random-looking series
          std::vector<B> c{x(i)};
          for (int k = 1; k <= jet_order(); ++k) c.push_back(B(0.1 * (k + i)) / B(k * k + 1));
          y(i) = S(c);
        }
      }
      return y;
    };
    for (int trial = 0; trial < 10; ++trial) {
      {
        const ode::heavy_top_problem<B> prob{B(1), B(2), B(1), B(1), B(1)};
        vector_t<B> x0(6);
        x0 << B(0), B(1), B(0), B(0.5), B(0), B(5);
        const vector_t<S> x = lift(jittered(x0, rng));
        const vector_t<S> full =
            top_on_pivot_cotton(S(1), S(2), S(1), S(1), S(1), top_on_pivot_state<S>{x(0), x(1), x(2), x(3), x(4), x(5)})
                .free_accelerations;
        check(vector_t<S>(prob.template rhs<S>(x).tail(3)), full, "heavy_top");
      }
      {
        vector_t<B> x0;
        const scene_input scene = scene_file("top_on_cone.json");
        const auto prob = cone_problem<B>(scene, x0);
        const vector_t<S> x = lift(jittered(x0, rng));
        const vector_t<S> full = top_on_cone_cotton(prob.template top_in<S>(), prob.cone, prob.state(x)).free_accelerations;
        check(vector_t<S>(prob.template rhs<S>(x).tail(2)), full, "top_on_cone");
      }
      for (const char* file : {"rolling_sphere_bowl.json", "rolling_sphere_plane.json", "rolling_sphere_pipe.json"}) {
        vector_t<B> x0;
        const scene_input scene = scene_file(file);
        const auto prob = sphere_problem<B>(scene, x0);
        vector_t<B> xb = x0;
        for (int i = 3; i < 6; ++i) xb(i) = jittered(x0, rng)(i);
        const vector_t<S> x = lift(xb);
        const auto with = prob.template motion<S>(x, false, true), without = prob.template motion<S>(x, false, false);
        check(with.center_velocity, without.center_velocity, file);
        check(with.omega_dot, without.omega_dot, file);
        check(with.center_ddot, without.center_ddot, file);
      }
    }
  };
  all(std::type_identity<double>{});
  all(std::type_identity<interval>{});
  int scalars = 5;  // double, interval, mpfi and the two jets; dd where this build compiled it
  test::if_built<dd>([&](auto type) { all(type); ++scalars; });
  {
    const mp_precision_scope bits(200);
    all(std::type_identity<mpfi>{});
  }
  {
    const jet_order_scope order(6);
    all(std::type_identity<jet<interval>>{});
    all(std::type_identity<jet<double>>{});
  }
  BOOST_TEST_MESSAGE("right-hand sides without reactions: " << compared << " values compared, " << differ << " differ");
  BOOST_TEST(compared == scalars * 10 * (3 + 2 + 3 * 9));  // 6 scalars in a build of every scalar, 10 states, 32 values each
  BOOST_TEST(differ == 0);
}
