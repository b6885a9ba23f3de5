// The generic Gibbs-Appell path against hand-written closed forms (Google Benchmark).
//
// For Euler's body, the rolling sphere on a plane and in a bowl, and Example I,
// in double and in interval, one run times side by side:
//   closed   the closed form (tests/independent/hand_derived.hpp) with its power balance;
//   generic  the model's result function: the library differentiates the
//            kinematics, forms Appell's equations, solves, and computes the
//            checks `appell eval` prints (eq. (4), Cotton = Lagrange);
//   eval     compute<T>() of the prepared scene, what `appell eval` runs: the
//            generic path plus naming the results and the scalar's policy.
// It prints generic / closed and eval / closed with the goal (<= 10).
// Before timing, each closed form is compared with the generic results.
// Run: build/bench/appell_bench_generic
//   (steadier: --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true: medians are used).
#include <benchmark/benchmark.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <set>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/models/euler_body.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"
#include "appell/io/scene.hpp"
#include "../tests/independent/hand_derived.hpp"
#include "median_reporter.hpp"

using namespace appell;

namespace {

const char* const scenes[] = {"euler_body.json", "rolling_sphere_plane.json", "rolling_sphere_bowl.json",
                              "top_on_cone.json"};
const char* const scalars[] = {"double", "interval"};

scene_input load(const std::string& file) { return read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file); }

/// Runs `f(prepared model inputs)` for the scene's model in T.
template <Scalar T, class F>
void with_model(const scene_input& scene, F&& f) {
  if (scene.model == euler_body_model::name)
    f(euler_body_model::prepare<T>(scene.as<euler_body_input>()));
  else if (scene.model == rolling_sphere_model::name)
    f(rolling_sphere_model::prepare<T>(scene.as<rolling_sphere_input>()));
  else
    f(top_on_cone_model::prepare<T>(scene.as<top_on_cone_input>()));
}

template <Scalar T>
auto closed(const euler_body_model::prepared<T>& m) { return independent::euler(m.body, m.omega); }
template <Scalar T>
auto closed(const rolling_sphere_model::prepared<T>& m) {
  return independent::rolling_sphere(m.M, m.A, m.a, m.surface, m.c, m.omega, m.F, m.tau);
}
template <Scalar T>
auto closed(const top_on_cone_model::prepared<T>& m) {
  static const independent::example_one_cone<T> cone;
  T f, fp, fpp;
  cone.all(m.theta, f, fp, fpp);
  const symmetric_top<T>& t = m.top;
  return independent::top_on_cone(t.A, t.C, t.mass, t.l, t.g, m.theta, m.theta_dot, m.phi_dot, f, fp, fpp);
}

template <Scalar T>
auto generic(const euler_body_model::prepared<T>& m) { return euler_body_motion(m.body, m.omega); }
template <Scalar T>
auto generic(const rolling_sphere_model::prepared<T>& m) {
  return rolling_sphere_motion(m.M, m.A, m.a, m.surface, m.c, m.omega, m.F, m.tau);
}
template <Scalar T>
auto generic(const top_on_cone_model::prepared<T>& m) {
  const top_on_cone_state<T> s{m.cone.psi(m.theta), m.theta, m.phi, m.theta_dot, m.phi_dot};
  return top_on_cone_motion(m.top, m.cone, s);
}

// The closed form's results against the generic path's, in double (relative 1e-12).
void expect_close(const char* what, double closed_value, double generic_value, double scale) {
  if (!(std::abs(closed_value - generic_value) <= 1e-12 * scale)) {
    std::cerr << "closed form and generic path differ on " << what << ": " << closed_value << " against "
              << generic_value << "\n";
    std::exit(4);
  }
}
void agree(const independent::euler_result<double>& c, const euler_body_result<double>& g) {
  for (int i = 0; i < 3; ++i) expect_close("omega_dot", c.omega_dot(i), g.omega_dot(i), g.omega_dot.norm());
}
void agree(const independent::sphere_result<double>& c, const rolling_sphere_result<double>& g) {
  const double s = g.contact_force.norm() + std::abs(g.pivot_couple) + 1;
  for (int i = 0; i < 3; ++i) {
    expect_close("center_ddot", c.center_ddot(i), g.center_ddot(i), g.center_ddot.norm() + 1);
    expect_close("omega_dot", c.omega_dot(i), g.omega_dot(i), g.omega_dot.norm() + 1);
    expect_close("contact_force", c.contact_force(i), g.contact_force(i), s);
  }
  expect_close("normal_force", c.normal_force, g.normal_force, s);
  expect_close("pivot_couple", c.pivot_couple, g.pivot_couple, s);
  expect_close("tangential_force", c.tangential_force, g.tangential_force(), s);
}
void agree(const independent::top_result<double>& c, const top_on_cone_result<double>& g) {
  const double s = std::abs(g.theta_ddot) + std::abs(g.phi_ddot) + std::abs(g.psi_ddot) + std::abs(g.H) + 1;
  expect_close("theta_ddot", c.theta_ddot, g.theta_ddot, s);
  expect_close("phi_ddot", c.phi_ddot, g.phi_ddot, s);
  expect_close("psi_ddot", c.psi_ddot, g.psi_ddot, s);
  expect_close("H", c.H, g.H, s);
  for (int i = 0; i < 3; ++i) expect_close("couple", c.couple(i), g.couple(i), g.couple.norm() + 1);
}

enum class path { closed, generic, eval, solve };

/// Euler's body only: the solve of Appell's equations M u' = Q - b alone (M, b, Q formed once),
/// the one the generic path's u' comes from.  appell eval's output must stay byte-identical, so
/// this solve (Cholesky in point types, verified in interval) is part of any generic path: its
/// time is a floor under the generic column.
template <Scalar T>
void solve_alone(benchmark::State& state, const euler_body_model::prepared<T>& m) {
  const appell_equations<T> eq = euler_body_equations(m.body, m.omega);
  for (auto _ : state) benchmark::DoNotOptimize(eq.accelerations());
}
template <Scalar T, class M>
void solve_alone(benchmark::State&, const M&) {}

/// Double only: the same M solved by Eigen's fixed-size 3 x 3 Cholesky (no heap), and how many
/// of its results differ in the last bit from the dynamic-size one the path runs (random SPD).
void solve_fixed_size(benchmark::State& state) {
  const scene_input scene = load("euler_body.json");
  const auto m = euler_body_model::prepare<double>(scene.as<euler_body_input>());
  const appell_equations<double> eq = euler_body_equations(m.body, m.omega);
  const Eigen::Matrix3d M = eq.M;
  const Eigen::Vector3d r = eq.Q - eq.b;
  for (auto _ : state) {
    const Eigen::Vector3d x = M.llt().solve(r);
    benchmark::DoNotOptimize(x);
  }
}
long fixed_size_differences(long& compared) {
  std::mt19937_64 rng(20261126u);
  std::uniform_real_distribution<double> u(-1, 1);
  long differ = 0;
  compared = 0;
  for (int k = 0; k < 100000; ++k) {
    Eigen::Matrix3d A;
    for (int i = 0; i < 9; ++i) A.data()[i] = u(rng);
    const Eigen::Matrix3d S = A * A.transpose() + 0.1 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d b(u(rng), u(rng), u(rng));
    const Eigen::Vector3d x = S.llt().solve(b);
    const vector_t<double> y = solve_spd(matrix_t<double>(S), vector_t<double>(b));
    for (int i = 0; i < 3; ++i, ++compared) differ += x(i) != y(i);
  }
  return differ;
}

void bench(benchmark::State& state, std::string scalar, const char* file, path which) {
  const scene_input scene = load(file);
  with_scalar(scalar, std::nullopt, [&]<class T>(std::type_identity<T>) {
    if (which == path::eval) {
      const prepared_scene<T> prepared = prepare<T>(scene);
      for (auto _ : state) benchmark::DoNotOptimize(compute<T>(prepared));
      return 0;
    }
    const evaluation_scope<T> scope;  // interval: upward rounding, as compute<T> runs
    with_model<T>(scene, [&](const auto& m) {
      if (which == path::closed)
        for (auto _ : state) benchmark::DoNotOptimize(closed(m));
      else if (which == path::solve)
        solve_alone<T>(state, m);
      else
        for (auto _ : state) benchmark::DoNotOptimize(generic(m));
    });
    scope.verify();
    return 0;
  });
}

class ratio_reporter : public median_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::cout << "\nratios from this run (goal: at most 10)\n"
              << "  " << std::left << std::setw(27) << "scene" << std::setw(10) << "scalar" << std::right
              << std::setw(12) << "closed ns" << std::setw(12) << "generic ns" << std::setw(17)
              << "generic/closed" << std::setw(14) << "eval/closed\n";
    for (const char* s : scenes)
      for (const char* scalar : scalars) {
        const std::string key = std::string(scalar) + "/" + s + "/";
        const double c = ns(key + "closed"), g = ns(key + "generic"), e = ns(key + "eval");
        if (!(c > 0)) continue;
        auto ratio = [&](double x) {
          std::ostringstream o;
          if (x > 0) o << std::fixed << std::setprecision(1) << x / c << (x / c <= 10 ? " met" : " MISSED");
          return o.str();
        };
        std::cout << "  " << std::left << std::setw(27) << s << std::setw(10) << scalar << std::right << std::fixed
                  << std::setprecision(1) << std::setw(12) << c << std::setw(12) << g << std::setw(17) << ratio(g)
                  << std::setw(14) << ratio(e) << "\n";
      }
    std::cout << "\nthe floor on Euler's body: the solve of M u' = Q - b alone (M, b, Q given), which a\n"
              << "byte-identical generic path must run, against the whole closed form\n";
    for (const char* scalar : scalars) {
      const std::string key = std::string(scalar) + "/euler_body.json/";
      const double c = ns(key + "closed"), f = ns(key + "solve");
      if (c > 0 && f > 0)
        std::cout << "  " << std::left << std::setw(10) << scalar << std::right << std::fixed << std::setprecision(1)
                  << "solve " << f << " ns = " << f / c << " x the closed form (goal for the whole path: 10)\n";
    }
    const double c = ns("double/euler_body.json/closed"), f = ns("double/euler_body.json/solve_fixed_size");
    if (c > 0 && f > 0) {
      long compared = 0;
      const long differ = fixed_size_differences(compared);
      std::cout << "  double    Eigen's fixed-size 3 x 3 Cholesky, no heap: " << f << " ns = " << f / c
                << " x the closed form; its results differ in the last bit from the path's on " << differ << " of "
                << compared << " random SPD components (byte-identical output rules it out)\n";
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* s : scenes) {
    const scene_input scene = load(s);
    if (scene.model == top_on_cone_model::name && scene.as<top_on_cone_input>().cone_text != "0.5*theta + 0.1*sin(2*theta)") {
      std::cerr << s << ": the closed form is written for Example I's cone\n";
      return 4;
    }
    with_model<double>(scene, [](const auto& m) { agree(closed(m), generic(m)); });
    for (const char* scalar : scalars)
      for (auto [name, which] : {std::pair{"closed", path::closed}, std::pair{"generic", path::generic},
                                 std::pair{"eval", path::eval}})
        benchmark::RegisterBenchmark((std::string(scalar) + "/" + s + "/" + name).c_str(), bench, std::string(scalar),
                                     s, which);
    if (scene.model == euler_body_model::name) {  // the floor (the ratio reporter's last lines)
      for (const char* scalar : scalars)
        benchmark::RegisterBenchmark((std::string(scalar) + "/" + s + "/solve").c_str(), bench, std::string(scalar), s,
                                     path::solve);
      benchmark::RegisterBenchmark((std::string("double/") + s + "/solve_fixed_size").c_str(), solve_fixed_size);
    }
  }
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
