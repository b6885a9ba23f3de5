// Why `enclose` steps short on robots and collapses on deep chains: the Taylor coefficients of a
// tree's motion in `interval`, over boxes of the state of half-width w, against the true
// coefficients (MPFR at 200 bits, at the box's centre).  For each order k it prints the true
// coefficient's magnitude (the largest over the state's components), the interval coefficient's
// widest width over the box, and their ratio: where the ratio passes 1 the interval coefficient
// says nothing of the motion, and `enclose`'s remainder x_p(B) h^p (within the tolerance) forces
// h down to (tol / width)^(1/p), whatever the motion's own radius of convergence, |x_k|^(-1/k).
// Usage: appell_bench_series_widths [SCENE | --chain N]...   (default: the WAM and chains of 4, 8
// and 12 links, tests/generated_chain.hpp)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "../tests/generated_chain.hpp"
#include "appell/io/scene.hpp"
#include "appell/models/system.hpp"
#include "appell/ode/taylor.hpp"

using namespace appell;

namespace {

void report(const std::string& label, const std::string& file) {
  const scene_input scene = read_scene_file(file);
  const std::vector<int> orders{1, 4, 8, 12, 16, 24};
  std::vector<double> truth;
  {
    const mp_precision_scope bits(200);
    const auto m = system_model::prepare<mpfr>(scene.as<system_input>());
    const auto [prob, x] = model_motion<system_model>::start<mpfr>(m);
    const auto c = ode::taylor_series(prob, x, orders.back());
    for (int k : orders) {
      double mag = 0;
      for (Eigen::Index i = 0; i < x.size(); ++i) mag = std::max(mag, std::fabs(static_cast<double>(c[static_cast<std::size_t>(k)](i))));
      truth.push_back(mag);
    }
  }
  std::printf("%s: true |x_k| (MPFR 200 bits), radius |x_k|^(-1/k):", label.c_str());
  for (std::size_t j = 0; j < orders.size(); ++j)
    std::printf("  k=%d %.3g (%.3g s)", orders[j], truth[j], std::pow(truth[j], -1.0 / orders[j]));
  std::printf("\n");
  const evaluation_scope<interval> scope;
  const auto m = system_model::prepare<interval>(scene.as<system_input>());
  const auto [p0, x0] = model_motion<system_model>::start<interval>(m);
  const auto prob = p0.template with_capacity<runtime_slopes>();
  for (double w : {0.0, 1e-12, 1e-8, 1e-4}) {
    vector_t<interval> B(x0.size());
    for (Eigen::Index i = 0; i < x0.size(); ++i) B(i) = x0(i) + interval(-w, w);
    std::printf("  w = %-7.0e width(x_k) / |x_k|:", w);
    try {
      const auto c = ode::taylor_series(prob, B, orders.back());
      for (std::size_t j = 0; j < orders.size(); ++j) {
        double width = 0;
        for (Eigen::Index i = 0; i < B.size(); ++i)
          width = std::max(width, boost::numeric::width(c[static_cast<std::size_t>(orders[j])](i)));
        std::printf("  k=%d %.2g", orders[j], width / truth[j]);
      }
      std::printf("\n");
    } catch (const std::exception& e) {
      std::printf("  refused: %.120s\n", e.what());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::pair<std::string, std::string>> runs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--chain") == 0 && i + 1 < argc) {
      const int n = std::atoi(argv[++i]);
      runs.emplace_back("chain of " + std::to_string(n) + " links", testing::generated_chain_scene(n, "appell_bench_widths"));
    } else {
      runs.emplace_back(argv[i], argv[i]);
    }
  }
  if (runs.empty()) {
    runs.emplace_back("the WAM", APPELL_SOURCE_DIR + "/data/scenes/urdf_wam.json");
    for (int n : {4, 8, 12})
      runs.emplace_back("chain of " + std::to_string(n) + " links", testing::generated_chain_scene(n, "appell_bench_widths"));
  }
  for (const auto& [label, file] : runs) report(label, file);
}
