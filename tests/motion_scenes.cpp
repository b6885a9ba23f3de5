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

#include "appell/io/models/rolling_sphere.hpp"
#include "appell/io/models/top_on_cone.hpp"
#include "appell/io/scene.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/ode/problems.hpp"
#include "appell/ode/taylor.hpp"

using namespace appell;
using truth_t = boost::multiprecision::mpfr_float_100;
using rational_t = boost::multiprecision::mpq_rational;

namespace {

template <class I>
bool holds(const I& x, const truth_t& v) {
  mpfr_value a, b;
  scalar_traits<I>::to_mpfr(x, a, b);
  truth_t lo, hi;
  mpfr_set(lo.backend().data(), a, MPFR_RNDD);
  mpfr_set(hi.backend().data(), b, MPFR_RNDU);
  return lo <= v && v <= hi;
}
/// A rational as a 100-digit truth (its error, 1e-100, far below any enclosure's width).
truth_t truth(const rational_t& q) { return truth_t(numerator(q)) / truth_t(denominator(q)); }

scene_input scene_of(const std::string& json) { return read_scene(parse_json(json)); }
scene_input scene_file(const std::string& file) {
  return read_scene_file(std::string(APPELL_SOURCE_DIR "/data/scenes/") + file);
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
  run(std::type_identity<dd>{}, 36, std::ldexp(1.0, -104));
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

BOOST_AUTO_TEST_CASE(a_sphere_in_a_bowl_keeps_its_energy_and_its_constraints) {
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
}

BOOST_AUTO_TEST_CASE(the_top_on_its_cone_keeps_its_energy) {
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
}
