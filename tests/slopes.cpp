// Slopes of the Taylor coefficients (derivatives/slope.hpp, ode::taylor_series_slopes), the matrix
// appell enclose steps with, against true differences computed in MPFR at 332 bits:
//   - on random boxes X and centres xh in X, at random points x of X (corners included), every
//     coefficient's difference x_k(x) - x_k(xh) lies in S_k (x - xh), on five problems through
//     the generic path: Euler's body (quadratic), the heavy top and the pendulum (sines, a solve),
//     Example I's cone (an expression), the sphere in a bowl (Cotton's elimination);
//   - each slope is no wider than the Jacobian over X (the mean-value form it replaces), and on
//     Euler's body, whose right-hand side is quadratic, about half as wide;
//   - a tree of links (a generated chain, the recursion's right-hand side) carried at run time
//     (slope<T, runtime_slopes>: vectors, a constant's empty) gives, entry for entry, the slopes
//     of the fixed capacity padded with zeros, and they hold true differences as above.
//   - about the box itself (centre = box: enclose's variational linear part), the slopes of the
//     right-hand side hold its Jacobian at every point of the box, on trees with contacts.
#define BOOST_TEST_MODULE slopes
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"
#include "appell/io/scene.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "generated_chain.hpp"
#include "appell/models/system.hpp"
#include "pendulum_problem.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/ode/enclose.hpp"

using namespace appell;

namespace {

constexpr unsigned truth_bits = 332;

mpfr lower_m(const interval& x) { return mpfr(x.lower()); }  // exact: a double at 332 bits
mpfr upper_m(const interval& x) { return mpfr(x.upper()); }

[[maybe_unused]] scene_input scene_file(const std::string& file) {  // unused where the quick tier leaves its cases out
  return read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
}

struct tally {
  long checks = 0, misses = 0;
  double slope_width = 0, jacobian_width = 0;  ///< summed over k >= 1
  long wider = 0;                              ///< entries where the slope is wider than the Jacobian
  long on_bound = 0;                           ///< differences beyond a bound by the truth's error only
  double attained = 0;                         ///< the largest such excess, relative
  std::string first_miss;
};

/// `trials` random boxes around the state x0 of the problem made by make<T>() (T = interval,
/// and mpfr for the truth), each with `points` random points.
template <class Make>
tally check(Make&& make, const std::vector<double>& x0, const std::vector<double>& scale, int q, int trials,
            int points, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  const int n = static_cast<int>(x0.size());
  tally t;
  const auto prob_i = make(std::type_identity<interval>{});
  for (int trial = 0; trial < trials; ++trial) {
    // X: around x0 moved by up to 10% of the scale, radii 10^-1 .. 10^-7 of the scale.
    vector_t<interval> X(n), xh(n);
    std::vector<double> lo(static_cast<std::size_t>(n)), hi(static_cast<std::size_t>(n)), h(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const std::size_t s = static_cast<std::size_t>(i);
      const double c = x0[s] + 0.1 * scale[s] * sym(rng);
      const double r = scale[s] * std::pow(10.0, -1 - 6 * u01(rng));
      lo[s] = c - r;
      hi[s] = c + r;
      h[s] = lo[s] + (hi[s] - lo[s]) * u01(rng);  // the centre: anywhere in X
      X(i) = interval(lo[s], hi[s]);
      xh(i) = interval(h[s]);
    }
    std::vector<matrix_t<interval>> S, D;
    ode::series<interval> c;
    {
      const evaluation_scope<interval> scope;
      ode::taylor_series_slopes(prob_i, xh, X, q, S);
      using P = std::remove_cvref_t<decltype(prob_i)>;
      if constexpr (P::dim == runtime_slopes) {  // multi_dual has a fixed count: the Jacobian padded to 12
        BOOST_REQUIRE(n <= 12);
        vector_t<interval> X12 = vector_t<interval>::Zero(12);
        X12.head(n) = X;
        std::vector<matrix_t<interval>> D12;
        ode::taylor_series_jacobian(prob_i.template with_capacity<12>(), X12, q, c, D12);
        for (const auto& m : D12) D.push_back(m.topLeftCorner(n, n));
      } else {
        ode::taylor_series_jacobian(prob_i, X, q, c, D);
      }
    }
    for (int k = 1; k <= q; ++k)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const double ws = boost::numeric::width(S[static_cast<std::size_t>(k)](i, j));
          const double wd = boost::numeric::width(D[static_cast<std::size_t>(k)](i, j));
          t.slope_width += ws;
          t.jacobian_width += wd;
          if (ws > wd * (1 + 1e-9) + 1e-300) ++t.wider;
        }
    const mp_precision_scope bits(truth_bits);
    const auto prob_m = make(std::type_identity<mpfr>{});
    vector_t<mpfr> xm(n);
    for (int i = 0; i < n; ++i) xm(i) = mpfr(h[static_cast<std::size_t>(i)]);
    const ode::series<mpfr> at_centre = ode::taylor_series(prob_m, xm, q, false);
    for (int pt = 0; pt < points; ++pt) {
      vector_t<mpfr> x(n);
      std::vector<mpfr> delta(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const std::size_t s = static_cast<std::size_t>(i);
        // points 0 and 1: opposite corners; the others inside
        const double v = pt == 0 ? lo[s] : pt == 1 ? hi[s] : lo[s] + (hi[s] - lo[s]) * u01(rng);
        x(i) = mpfr(v);
        delta[s] = x(i) - xm(i);  // exact at 332 bits
      }
      const ode::series<mpfr> at_x = ode::taylor_series(prob_m, x, q, false);
      for (int k = 0; k <= q; ++k)
        for (int i = 0; i < n; ++i) {
          const mpfr diff = at_x[static_cast<std::size_t>(k)](i) - at_centre[static_cast<std::size_t>(k)](i);
          mpfr low = 0, up = 0;
          for (int j = 0; j < n; ++j) {
            const interval& s = S[static_cast<std::size_t>(k)](i, j);
            const mpfr& d = delta[static_cast<std::size_t>(j)];
            const mpfr a = lower_m(s) * d, b = upper_m(s) * d;
            low += a < b ? a : b;
            up += a < b ? b : a;
          }
          ++t.checks;
          // The truth's own error: each coefficient at 332 bits is within about 2^-300 of its scale
          // (q passes of a few dozen roundings each); a bound the slope attains exactly (a
          // quadratic at a corner of X) may then be crossed by that much, never by an ulp of double.
          const mpfr margin = ldexp(mpfr(1), -290) * (abs(low) + abs(up) + abs(at_x[static_cast<std::size_t>(k)](i)) +
                                                      abs(at_centre[static_cast<std::size_t>(k)](i)) + 1);
          if (!(low - margin <= diff && diff <= up + margin) && t.misses++ == 0)
            t.first_miss = "trial " + std::to_string(trial) + " point " + std::to_string(pt) + " x_" +
                           std::to_string(k) + "[" + std::to_string(i) + "]: " + diff.str(25) + " outside [" +
                           low.str(25) + ", " + up.str(25) + "]";
          if (!(low <= diff && diff <= up)) {
            const mpfr excess = diff < low ? mpfr(low - diff) : mpfr(diff - up);
            const double rel = static_cast<double>(excess / (abs(diff) + 1e-300));
            t.attained = std::max(t.attained, rel);
            ++t.on_bound;
          }
        }
    }
  }
  return t;
}

void report(const char* name, const tally& t) {
  BOOST_TEST_MESSAGE(name << ": " << t.checks << " differences checked, " << t.misses << " misses (" << t.on_bound
                          << " on a bound, by at most " << t.attained << " relative); slope / Jacobian width "
                          << t.slope_width / t.jacobian_width << ", " << t.wider << " entries wider than the Jacobian");
  BOOST_TEST(t.misses == 0, name << ": " << t.first_miss);
  BOOST_TEST(t.checks > 0);
  BOOST_TEST(t.wider == 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(slopes_of_euler_s_body_hold_true_differences_with_half_the_jacobian_s_width, *test::needs_scalars({"mpfr"})) {
#if APPELL_TEST_HAS(mpfr)  // the truth: the model's motion in mpfr
  auto make = []<class T>(std::type_identity<T>) {
    return ode::euler_body_problem<T>{euler_body<T>{vec3<T>(T(1), T(2), T(3)), vec3<T>(T(0), T(0), T(0))}};
  };
  const tally t = check(make, {1, 1, 1}, {1, 1, 1}, 10, 60, 6, 20261125u);
  report("euler_body", t);
  // Quadratic: to first order in the box's radius the slope has half the Jacobian's width.
  BOOST_TEST(t.slope_width <= 0.55 * t.jacobian_width);
#endif
}

BOOST_AUTO_TEST_CASE(slopes_of_the_heavy_top_and_the_pendulum_hold_true_differences) {
  auto top = []<class T>(std::type_identity<T>) { return ode::heavy_top_problem<T>{T(1), T(2), T(1), T(1), T(1)}; };
  const tally a = check(top, {0, 1, 0, 0.5, 0, 5}, {1, 1, 1, 1, 1, 5}, 8, 30, 5, 20261126u);
  report("heavy_top", a);
  BOOST_TEST(a.slope_width < a.jacobian_width);
  // On the fixed axes the pendulum's path forms products (M = m l^2 (cos^2 + sin^2)), where the
  // slope is narrower than the Jacobian; on the rod's axes it is theta'' = -(g / l) sin theta, a
  // single function, whose slope is its derivative over the box: the Jacobian itself.
  auto pendulum = []<class T>(std::type_identity<T>) { return ode::pendulum_problem<T>{T(1), T(1), T(1), false}; };
  const tally b = check(pendulum, {1, 0}, {1, 1}, 10, 60, 6, 20261127u);
  report("pendulum (fixed axes)", b);
  BOOST_TEST(b.slope_width < b.jacobian_width);
  auto on_rod = []<class T>(std::type_identity<T>) { return ode::pendulum_problem<T>{T(1), T(1), T(1), true}; };
  const tally c = check(on_rod, {1, 0}, {1, 1}, 10, 60, 6, 20261128u);
  report("pendulum (rod axes)", c);
  BOOST_TEST(c.slope_width <= c.jacobian_width);
}

BOOST_AUTO_TEST_CASE(slopes_of_example_one_and_the_sphere_in_a_bowl_hold_true_differences, *test::needs_scalars({"mpfr"})) {
#if APPELL_TEST_HAS(mpfr)  // the truth: the model's motion in mpfr
  const scene_input cone_scene = scene_file("top_on_cone.json");
  auto cone = [&]<class T>(std::type_identity<T>) {
    const auto m = top_on_cone_model::prepare<T>(cone_scene.as<top_on_cone_input>());
    return ode::top_on_cone_problem<T>{m.top, m.cone};
  };
  const tally a = check(cone, {0.7, 0.3, 1.2, 40}, {1, 1, 1, 10}, 6, 12, 4, 20261128u);
  report("top_on_cone", a);
  BOOST_TEST(a.slope_width < a.jacobian_width);
  const scene_input bowl = scene_file("rolling_sphere_bowl.json");
  std::vector<double> x0;
  auto sphere = [&]<class T>(std::type_identity<T>) {
    const auto m = rolling_sphere_model::prepare<T>(bowl.as<rolling_sphere_input>());
    return ode::rolling_sphere_problem<T>{m.M, m.A, m.a, m.surface, m.F, m.tau};
  };
  {
    const auto m = rolling_sphere_model::prepare<double>(bowl.as<rolling_sphere_input>());
    x0 = {m.c(0), m.c(1), m.c(2), m.omega(0), m.omega(1), m.omega(2)};
  }
  std::vector<double> scale(6);
  for (int i = 0; i < 6; ++i) scale[static_cast<std::size_t>(i)] = 1e-2 * std::max(1.0, std::fabs(x0[static_cast<std::size_t>(i)]));
  const tally b = check(sphere, x0, scale, 6, 12, 4, 20261129u);
  report("rolling_sphere (bowl)", b);
  BOOST_TEST(b.slope_width < b.jacobian_width);
#endif
}

namespace {
/// The motion of a `system` (or urdf) scene carried in D components (D = runtime_slopes: its own size).
template <Scalar T, int D>
system_problem<T, D> tree_problem(const scene_input& scene) {
  const auto m = system_model::prepare<T>(scene.as<system_input>());
  return model_motion<system_model>::start<T>(m).first.template with_capacity<D>();
}
}  // namespace

BOOST_AUTO_TEST_CASE(slopes_of_a_tree_carried_at_run_time_equal_the_fixed_capacity_s_and_hold_true_differences) {
  const scene_input scene = read_scene_file(testing::generated_chain_scene(5, "appell_test_slopes_chain"));
  const auto point = tree_problem<double, runtime_slopes>(scene);
  BOOST_REQUIRE(point.recursion());
  const int n = point.size();
  BOOST_REQUIRE(n == 10);
  const vector_t<double> x0d = point.initial_state();
  std::vector<double> x0(x0d.data(), x0d.data() + n), scale(static_cast<std::size_t>(n), 1e-2);  // radii up to 1e-3
  // The same box and centre through both: the run-time slopes are the padded capacity's n x n
  // block, bit for bit (the same operations on the same numbers), and the padding's are 0.
  {
    const auto run_time = tree_problem<interval, runtime_slopes>(scene);
    const auto padded = tree_problem<interval, 12>(scene);
    vector_t<interval> X(n), xh(n), X12 = vector_t<interval>::Zero(12), xh12 = vector_t<interval>::Zero(12);
    for (int i = 0; i < n; ++i) {
      const double c = x0[static_cast<std::size_t>(i)];
      X(i) = X12(i) = interval(c - 1e-3, c + 2e-3);
      xh(i) = xh12(i) = interval(c + 1e-4);
    }
    std::vector<matrix_t<interval>> S, S12;
    const evaluation_scope<interval> scope;
    ode::taylor_series_slopes(run_time, xh, X, 8, S);
    ode::taylor_series_slopes(padded, xh12, X12, 8, S12);
    long differ = 0, padding = 0;
    for (std::size_t k = 0; k <= 8; ++k)
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) {
          const interval& b = S12[k](i, j);
          if (i < n && j < n) differ += !(b.lower() == S[k](i, j).lower() && b.upper() == S[k](i, j).upper());
          else if (i != j || k > 0) padding += !(b.lower() == 0 && b.upper() == 0);
        }
    BOOST_TEST(differ == 0);
    BOOST_TEST(padding == 0);
    BOOST_TEST(S[1].rows() == n);
  }
  auto make = [&]<class T>(std::type_identity<T>) { return tree_problem<T, runtime_slopes>(scene); };
  const tally t = check(make, x0, scale, 6, 8, 4, 20261204u);
  report("generated chain of 5 links (run-time slopes)", t);
  BOOST_TEST(t.slope_width < t.jacobian_width);
}

BOOST_AUTO_TEST_CASE(the_memo_changes_no_digit_of_a_tree_s_series_or_slopes) {
  // The memo (jet.hpp, detail::jet_memo) keeps each operation's operands and results between a
  // series' passes and appends only what a pass adds; enclose's two evaluations on a tree (the
  // series over a box, the slopes about a centre) with it and without it, on the KR5 and the WAM
  // from data/scenes and a generated chain of 8 links, at random boxes about their states: every
  // coefficient and every slope bit for bit.
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> off(-0.3, 0.3), rad(0.0, 1e-6);
  const std::string chain = testing::generated_chain_scene(8, "appell_test_slopes_memo_chain");
  long compared = 0, differ = 0;
  const std::string scenes = std::string(APPELL_SOURCE_DIR + "/data/scenes/");
  for (const std::string& file : {scenes + "urdf_kr5.json", scenes + "urdf_wam.json", chain}) {
    const scene_input scene = read_scene_file(file);
    const auto prob = tree_problem<interval, runtime_slopes>(scene);
    BOOST_REQUIRE(prob.recursion());
    const vector_t<double> x0 = tree_problem<double, runtime_slopes>(scene).initial_state();
    const int n = static_cast<int>(x0.size());
    const evaluation_scope<interval> scope;
    for (int trial = 0; trial < 3; ++trial) {
      vector_t<interval> X(n), xh(n);
      for (int i = 0; i < n; ++i) {
        const double c = x0(i) + off(rng), r = rad(rng);
        X(i) = interval(c - r, c + r);
        xh(i) = interval(c);
      }
      const auto with = ode::taylor_series(prob, X, 12, true), without = ode::taylor_series(prob, X, 12, false);
      std::vector<matrix_t<interval>> Sw, So;
      ode::series<interval> cw, co;
      ode::taylor_series_slopes(prob, xh, X, 6, Sw, true, &cw);
      ode::taylor_series_slopes(prob, xh, X, 6, So, false, &co);
      auto same = [&](const interval& a, const interval& b) {
        ++compared;
        differ += !detail::identical(a, b);
      };
      for (std::size_t k = 0; k < with.size(); ++k)
        for (int i = 0; i < n; ++i) same(with[k](i), without[k](i));
      for (std::size_t k = 0; k < Sw.size(); ++k) {
        for (int i = 0; i < n; ++i) {
          same(cw[k](i), co[k](i));
          for (int j = 0; j < n; ++j) same(Sw[k](i, j), So[k](i, j));
        }
      }
    }
  }
  BOOST_TEST_MESSAGE("memo on trees: " << compared << " coefficients and slopes compared");
  BOOST_TEST(compared > 10000);
  BOOST_TEST(differ == 0);
}

BOOST_AUTO_TEST_CASE(slopes_about_the_box_itself_hold_the_jacobian_at_every_point_of_it) {
  // enclose's variational linear part (ode/enclose.hpp, detail::flow_jacobian) takes the
  // right-hand side's Jacobian over a step's box B as the slopes about B itself:
  // taylor_series_slopes(prob, B, B, 1) (every rule of derivatives/slope.hpp is an identity for
  // each centre of the centre's enclosure, so with the centre B its d holds f(x) - f(y) = S (x - y)
  // for all x, y in B, and the derivative at each x as the limit).  Checked against the Jacobian
  // at random points of random boxes, by central differences in MPFR at 332 bits (step 1e-40:
  // their error about 1e-60 of the scale): a generated chain of 5 links, the block and arm on its
  // sole (a floating base, six constraints) and Atlas on both soles (54 components; where
  // Debian's dart-doc is installed).
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  std::vector<std::string> files{testing::generated_chain_scene(5, "appell_test_slopes_box_chain"),
                                 std::string(APPELL_SOURCE_DIR + "/data/scenes/urdf_block_arm_push.json")};
  if (std::filesystem::exists("/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf"))
    files.push_back(std::string(APPELL_SOURCE_DIR + "/data/scenes/urdf_atlas_standing.json"));
  long checks = 0, misses = 0;
  std::string first_miss;
  for (const std::string& file : files) {
    const scene_input scene = read_scene_file(file);
    const auto prob_i = tree_problem<interval, runtime_slopes>(scene);
    const vector_t<double> x0 = tree_problem<double, runtime_slopes>(scene).initial_state();
    const int n = static_cast<int>(x0.size());
    const bool big = n > 20;
    for (int trial = 0; trial < (big ? 2 : 6); ++trial) {
      vector_t<interval> B(n);
      std::vector<double> lo(static_cast<std::size_t>(n)), hi(static_cast<std::size_t>(n));
      // radii 1e-3 to 1e-7 (Atlas: 1e-7 to 1e-10, a step's box; its 21 x 21 solve, of condition
      // about 1.6e5, is not certified over much wider ones)
      const double radius = big ? std::pow(10.0, -7 - 3 * u01(rng)) : std::pow(10.0, -3 - 4 * u01(rng));
      for (int i = 0; i < n; ++i) {
        const std::size_t s = static_cast<std::size_t>(i);
        const double c = x0(i) + 1e-3 * sym(rng), r = radius * (0.5 + u01(rng)) * std::max(1.0, std::fabs(x0(i)));
        lo[s] = c - r;
        hi[s] = c + r;
        B(i) = interval(lo[s], hi[s]);
      }
      std::vector<matrix_t<interval>> D;
      {
        const evaluation_scope<interval> scope;
        ode::taylor_series_slopes(prob_i, B, B, 1, D, false);
      }
      const mp_precision_scope bits(truth_bits);
      const auto prob_m = tree_problem<mpfr, runtime_slopes>(scene);
      const mpfr step("1e-40");
      for (int pt = 0; pt < (big ? 2 : 4); ++pt) {
        vector_t<mpfr> x(n);
        for (int i = 0; i < n; ++i) {
          const std::size_t s = static_cast<std::size_t>(i);
          x(i) = mpfr(pt == 0 ? lo[s] : pt == 1 ? hi[s] : lo[s] + (hi[s] - lo[s]) * u01(rng));
        }
        for (int j = 0; j < n; ++j) {
          vector_t<mpfr> xp = x, xm = x;
          xp(j) += step;
          xm(j) -= step;
          const vector_t<mpfr> fp = prob_m.template rhs<mpfr>(xp), fm = prob_m.template rhs<mpfr>(xm);
          for (int i = 0; i < n; ++i) {
            const mpfr d = (fp(i) - fm(i)) / (2 * step);
            const interval& e = D[1](i, j);
            const mpfr slack = mpfr("1e-45") * std::max(1.0, std::fabs(static_cast<double>(d)));
            ++checks;
            if (d < mpfr(e.lower()) - slack || d > mpfr(e.upper()) + slack) {
              if (misses++ == 0)
                first_miss = file + ": d f_" + std::to_string(i) + "/d x_" + std::to_string(j) + " = " +
                             d.str(20) + " outside [" + std::to_string(e.lower()) + ", " + std::to_string(e.upper()) + "]";
            }
          }
        }
      }
    }
  }
  BOOST_TEST_MESSAGE("slopes about the box: " << checks << " Jacobian entries checked, " << misses << " outside");
  BOOST_TEST(checks > 5000);
  BOOST_TEST(misses == 0, first_miss);
}

BOOST_AUTO_TEST_CASE(series_with_their_linear_part_apart_hold_every_point_s_series) {
  // ode::taylor_series_split (enclose's series on the steps that try the variational part): each
  // coefficient of f(x(t)) as A0 x_k + G_k, A0 the right-hand side's Jacobian over a box holding
  // X0 (the slopes about that box), intersected with the whole pass's enclosure.  At random
  // points of random boxes, the series in MPFR at 332 bits (no memo) lies in it, every
  // coefficient, on a generated chain of 5 links and the block and arm on its sole (a floating
  // base, six constraints, a torque in t); A0 over the box itself and over a box 4 times as wide
  // (enclose's Bg).  A mutant, A0 halved, is refused or misses: the test can fail.  And the point
  // of it, on Atlas held by joint stiffness (where Debian's dart-doc is installed): order 18's
  // coefficients over a step's box 10^6 times narrower than the whole passes'.
  std::mt19937_64 rng(20261208);
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  const int q = 10;
  long checks = 0, misses = 0, mutant_failures = 0;
  std::string first_miss;
  for (const std::string& file : {testing::generated_chain_scene(5, "appell_test_split_chain"),
                                  std::string(APPELL_SOURCE_DIR + "/data/scenes/urdf_block_arm_push.json")}) {
    const scene_input scene = read_scene_file(file);
    const auto prob_i = tree_problem<interval, runtime_slopes>(scene);
    const vector_t<double> x0 = tree_problem<double, runtime_slopes>(scene).initial_state();
    const int n = static_cast<int>(x0.size());
    for (int trial = 0; trial < 6; ++trial) {
      vector_t<interval> X(n), wide(n);
      std::vector<double> lo(static_cast<std::size_t>(n)), hi(static_cast<std::size_t>(n));
      const double radius = std::pow(10.0, -3 - 4 * u01(rng));
      for (int i = 0; i < n; ++i) {
        const std::size_t s = static_cast<std::size_t>(i);
        const double c = x0(i) + 1e-3 * sym(rng), r = radius * (0.5 + u01(rng)) * std::max(1.0, std::fabs(x0(i)));
        lo[s] = c - r;
        hi[s] = c + r;
        X(i) = interval(lo[s], hi[s]);
        wide(i) = interval(c - 4 * r, c + 4 * r);
      }
      ode::series<interval> split, mutant;
      bool mutant_refused = false;
      {
        const evaluation_scope<interval> scope;
        std::vector<matrix_t<interval>> D;
        ode::taylor_series_slopes(prob_i, trial % 2 ? wide : X, trial % 2 ? wide : X, 1, D, true);
        split = ode::taylor_series_split(prob_i, X, q, D[1]);
        try {
          mutant = ode::taylor_series_split(prob_i, X, q, matrix_t<interval>(D[1] * interval(0.5)));
        } catch (const std::logic_error&) {
          mutant_refused = true;  // the two enclosures disjoint
        }
      }
      if (mutant_refused) {
        ++mutant_failures;
      } else {
        const mp_precision_scope bits(truth_bits);
        const auto prob_m = tree_problem<mpfr, runtime_slopes>(scene);
        vector_t<mpfr> x(n);
        for (int i = 0; i < n; ++i) x(i) = mpfr(lo[static_cast<std::size_t>(i)]);
        const ode::series<mpfr> truth = ode::taylor_series(prob_m, x, q, false);
        bool missed = false;
        for (int k = 0; k <= q; ++k)
          for (int i = 0; i < n; ++i) {
            const interval& e = mutant[static_cast<std::size_t>(k)](i);
            const mpfr& v = truth[static_cast<std::size_t>(k)](i);
            missed = missed || v < mpfr(e.lower()) || v > mpfr(e.upper());
          }
        mutant_failures += missed;
      }
      const mp_precision_scope bits(truth_bits);
      const auto prob_m = tree_problem<mpfr, runtime_slopes>(scene);
      for (int pt = 0; pt < 4; ++pt) {
        vector_t<mpfr> x(n);
        for (int i = 0; i < n; ++i) {
          const std::size_t s = static_cast<std::size_t>(i);
          x(i) = mpfr(pt == 0 ? lo[s] : pt == 1 ? hi[s] : lo[s] + (hi[s] - lo[s]) * u01(rng));
        }
        const ode::series<mpfr> truth = ode::taylor_series(prob_m, x, q, false);
        for (int k = 0; k <= q; ++k)
          for (int i = 0; i < n; ++i) {
            const interval& e = split[static_cast<std::size_t>(k)](i);
            const mpfr& v = truth[static_cast<std::size_t>(k)](i);
            // the truth's own error: q passes of a few dozen roundings at 332 bits
            const mpfr slack = ldexp(mpfr(1), -290) * (1 + abs(v));
            ++checks;
            if (v < mpfr(e.lower()) - slack || v > mpfr(e.upper()) + slack) {
              if (misses++ == 0)
                first_miss = file + ": x_" + std::to_string(k) + "(" + std::to_string(i) + ") = " + v.str(20) +
                             " outside [" + std::to_string(e.lower()) + ", " + std::to_string(e.upper()) + "]";
            }
          }
      }
    }
  }
  BOOST_TEST_MESSAGE("series with their linear part apart: " << checks << " coefficients checked, " << misses
                                                            << " outside; the mutant failed " << mutant_failures << " of 12 boxes");
  BOOST_TEST(checks > 3000);
  BOOST_TEST(misses == 0, first_miss);
  BOOST_TEST(mutant_failures >= 6);
  if (std::filesystem::exists("/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf")) {
    const scene_input scene = scene_file("urdf_atlas_standing_held.json");
    const auto prob = tree_problem<interval, runtime_slopes>(scene);
    const vector_t<double> x0 = tree_problem<double, runtime_slopes>(scene).initial_state();
    const int n = static_cast<int>(x0.size());
    vector_t<interval> X(n);
    for (int i = 0; i < n; ++i) X(i) = interval(x0(i) - 1e-10, x0(i) + 1e-10);
    const evaluation_scope<interval> scope;
    std::vector<matrix_t<interval>> D;
    ode::taylor_series_slopes(prob, X, X, 1, D, true);
    const ode::series<interval> split = ode::taylor_series_split(prob, X, 18, D[1]), whole = ode::taylor_series(prob, X, 18);
    double ws = 0, ww = 0;
    for (int i = 0; i < n; ++i) {
      ws = std::max(ws, boost::numeric::width(split[18](i)));
      ww = std::max(ww, boost::numeric::width(whole[18](i)));
    }
    BOOST_TEST_MESSAGE("Atlas held, order 18 over a box of radius 1e-10: widest " << ws << " apart, " << ww << " whole");
    BOOST_TEST(ws < 1e-6 * ww);
    // coefficient 1, f(x_0), in its mean-value form about the box's midpoint as well
    double ws1 = 0, ww1 = 0;
    for (int i = 0; i < n; ++i) {
      ws1 = std::max(ws1, boost::numeric::width(split[1](i)));
      ww1 = std::max(ww1, boost::numeric::width(whole[1](i)));
    }
    BOOST_TEST_MESSAGE("Atlas held, f(x_0) over that box: widest " << ws1 << " apart, " << ww1 << " whole");
    BOOST_TEST(ws1 < 0.1 * ww1);
  }
}

BOOST_AUTO_TEST_CASE(steps_that_split_their_series_hold_the_motion_from_every_point_of_the_box) {
  // enclose's steps that try the variational part take the series split (f(x_0) in its mean-value
  // form, each coefficient's linear part through A0) and the flow's Jacobian as the product of the
  // flow's over 4 pieces of the step, a step whose spread is too wide taken again shorter.  From a
  // box about the start of a generated chain of 5 links and of the block and arm on its sole (a
  // floating base, six constraints, a torque in t), to T: the motion from random points of the box
  // (corners among them), simulated in MPFR at 332 bits to order 40, lies in the last step's box,
  // and steps kept the variational part (its pieces were used: the chain's).
  std::mt19937_64 rng(20261209);
  std::uniform_real_distribution<double> u01(0, 1);
  long checked = 0, outside = 0, variational = 0, steps = 0, rejected = 0;
  std::string first_out;
  for (const auto& [file, T] : {std::pair{testing::generated_chain_scene(5, "appell_test_split_steps_chain"), 0.05},
                               std::pair{std::string(APPELL_SOURCE_DIR + "/data/scenes/urdf_block_arm_push.json"), 0.1}}) {
    const scene_input scene = read_scene_file(file);
    const vector_t<double> x0 = tree_problem<double, runtime_slopes>(scene).initial_state();
    const int n = static_cast<int>(x0.size());
    std::vector<double> lo(static_cast<std::size_t>(n)), hi(static_cast<std::size_t>(n));
    vector_t<interval> X(n), end;
    for (int i = 0; i < n; ++i) {
      const std::size_t s = static_cast<std::size_t>(i);
      const double r = 1e-7 * std::max(1.0, std::fabs(x0(i)));
      lo[s] = x0(i) - r;
      hi[s] = x0(i) + r;
      X(i) = interval(lo[s], hi[s]);
    }
    {
      const evaluation_scope<interval> scope;
      const auto prob = tree_problem<interval, runtime_slopes>(scene);
      const ode::enclose_stats st = ode::enclose(prob, X, interval(T), 24, std::ldexp(1.0, -53), 1.0, 2,
                                                 [&](const ode::enclosed_step<interval>& s) { end = s.end; });
      BOOST_TEST_REQUIRE(st.complete, st.reason);
      variational += st.variational;
      steps += st.steps;
      rejected += st.rejected;
    }
    const mp_precision_scope bits(truth_bits);
    const auto prob_m = tree_problem<mpfr, runtime_slopes>(scene);
    for (int pt = 0; pt < 6; ++pt) {
      vector_t<mpfr> x(n), last;
      for (int i = 0; i < n; ++i) {
        const std::size_t s = static_cast<std::size_t>(i);
        x(i) = mpfr(pt == 0 ? lo[s] : pt == 1 ? hi[s] : pt == 2 ? (i % 2 ? lo[s] : hi[s]) : lo[s] + (hi[s] - lo[s]) * u01(rng));
      }
      ode::simulate(prob_m, x, mpfr(T), mpfr(T), 40, std::ldexp(1.0, -300), [&](const ode::sample<mpfr>& s) { last = s.x; });
      BOOST_TEST_REQUIRE(last.size() == n);
      for (int i = 0; i < n; ++i) {
        const mpfr slack = ldexp(mpfr(1), -280) * (1 + abs(last(i)));
        ++checked;
        if (last(i) < lower_m(end(i)) - slack || last(i) > upper_m(end(i)) + slack) {
          if (outside++ == 0)
            first_out = file + ": x" + std::to_string(i) + "(T) = " + last(i).str(20) + " outside [" +
                        std::to_string(end(i).lower()) + ", " + std::to_string(end(i).upper()) + "]";
        }
      }
    }
  }
  BOOST_TEST_MESSAGE("steps with the series split: " << steps << " steps (" << variational << " variational, " << rejected
                                                     << " refused), " << checked << " components of the motion checked, "
                                                     << outside << " outside");
  BOOST_TEST(outside == 0, first_out);
  BOOST_TEST(variational >= 4);  // the chain's (the block and arm's two steps took the slopes: 2026-12-07)
}
