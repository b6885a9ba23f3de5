// The Taylor coefficients of the scenes' motions with and without the memo (derivatives/jet.hpp,
// detail::jet_memo), side by side in one run: each pass of taylor_series computes only its new
// coefficient of every product, quotient, elementary function and solve, instead of all of them.
// For each scene and scalar at the order `simulate` uses (interval: `enclose`'s 24), prints the
// median time of one series over alternating repetitions, both ways, and their ratio.
// Usage: appell_bench_taylor [--quick]   (--quick: double and interval only)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"
#include "appell/io/scene.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/scalar/standard_scalars.hpp"

using namespace appell;

namespace {

scene_input scene_file(const std::string& file) {
  return read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
}

template <class P, class S>
void time_series(const char* scene, const P& prob, const vector_t<S>& x0, int order) {
  using clock = std::chrono::steady_clock;
  std::vector<double> with, without;
  // Repetitions alternate the two ways; each repetition runs for about 20 ms.
  int reps = 1;
  {
    const auto t0 = clock::now();
    ode::taylor_series(prob, x0, order, false);
    const double s = std::chrono::duration<double>(clock::now() - t0).count();
    reps = std::max(1, static_cast<int>(0.02 / std::max(s, 1e-7)));
  }
  for (int round = 0; round < 7; ++round)
    for (bool memo : {true, false}) {
      const auto t0 = clock::now();
      for (int r = 0; r < reps; ++r) ode::taylor_series(prob, x0, order, memo);
      const double ms = std::chrono::duration<double>(clock::now() - t0).count() * 1e3 / reps;
      (memo ? with : without).push_back(ms);
    }
  std::sort(with.begin(), with.end());
  std::sort(without.begin(), without.end());
  const double a = without[without.size() / 2], b = with[with.size() / 2];
  std::printf("| %s | %s | %d | %.4g | %.4g | %.1f |\n", scene, scalar_traits<S>::name, order, a, b, a / b);
  std::fflush(stdout);
}

template <class S>
void scenes(int order) {
  const evaluation_scope<S> scope;
  {
    const ode::euler_body_problem<S> prob{{vec3<S>(S(1), S(2), S(3)), vec3<S>(S(0), S(0), S(0))}};
    time_series("euler_body", prob, vector_t<S>(vector_t<S>::Constant(3, S(1))), order);
  }
  {
    const ode::heavy_top_problem<S> prob{S(1), S(2), S(1), S(1), S(1)};
    vector_t<S> x0(6);
    x0 << S(0), S(1), S(0), S(0.5), S(0), S(5);
    time_series("heavy_top", prob, x0, order);
  }
  {
    const scene_input scene = scene_file("top_on_cone.json");
    const auto m = top_on_cone_model::prepare<S>(scene.as<top_on_cone_input>());
    vector_t<S> x0(4);
    x0 << m.theta, m.phi, m.theta_dot, m.phi_dot;
    time_series("top_on_cone", ode::top_on_cone_problem<S>{m.top, m.cone}, x0, order);
  }
  {
    const scene_input scene = scene_file("rolling_sphere_bowl.json");
    const auto m = rolling_sphere_model::prepare<S>(scene.as<rolling_sphere_input>());
    vector_t<S> x0(6);
    x0 << m.c(0), m.c(1), m.c(2), m.omega(0), m.omega(1), m.omega(2);
    time_series("rolling_sphere_bowl", ode::rolling_sphere_problem<S>{m.M, m.A, m.a, m.surface, m.F, m.tau}, x0, order);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && !std::strcmp(argv[1], "--quick");
  std::printf("taylor_series without and with the memo (median ms of one series; ratio = without / with)\n\n");
  std::printf("| scene | scalar | order | without ms | with ms | ratio |\n|---|---|---|---|---|---|\n");
  scenes<double>(20);
  scenes<interval>(24);
  if (quick) return 0;
  scenes<long double>(24);
  scenes<dd>(39);
  scenes<float128>(41);
  {
    const mp_precision_scope bits(256);
    scenes<mpfr>(91);
  }
  return 0;
}
