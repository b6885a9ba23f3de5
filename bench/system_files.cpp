// The scene model "system" against the dedicated models (Google Benchmark):
// compute<T>() of a paper scene written as a system file (data/scenes/system_*.json)
// and of the same scene in its dedicated model, side by side in one run, in
// double and in interval; prints system / dedicated with the goal (<= 3).
// Also the Whipple bicycle's `appell linearize` report in mpfi at 113 bits (goal: under
// a second) and in interval and double, from the scene read.
// Run: build/bench/appell_bench_system
//   (steadier: --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true: medians are used).
#include <benchmark/benchmark.h>

#include <iomanip>
#include <iostream>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/models/system.hpp"
#include "appell/io/scene.hpp"
#include "median_reporter.hpp"

using namespace appell;

namespace {

const std::pair<const char*, const char*> pairs[] = {
    {"system_euler_body.json", "euler_body.json"},
    {"system_top_on_cone.json", "top_on_cone.json"},
    {"system_rolling_sphere_plane.json", "rolling_sphere_plane.json"},
    {"system_rolling_sphere_bowl.json", "rolling_sphere_bowl.json"},
};
const char* const scalars[] = {"double", "interval"};

void bench(benchmark::State& state, std::string scalar, std::string file) {
  const scene_input scene = read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
  with_scalar(scalar, std::nullopt, [&]<class T>(std::type_identity<T>) {
    const prepared_scene<T> prepared = prepare<T>(scene);
    for (auto _ : state) benchmark::DoNotOptimize(compute<T>(prepared));
    return 0;
  });
}

// linearize_scene<T> of the bicycle: the matrices, 11 spectra and the critical speeds.
void bench_linearize(benchmark::State& state, std::string scalar, std::optional<unsigned> bits) {
  const scene_input scene = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/system_whipple_bicycle.json");
  const system_input& in = scene.as<system_input>();
  with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    for (auto _ : state) benchmark::DoNotOptimize(linearize_scene<T>(in));
    return 0;
  });
}
const std::pair<const char*, std::optional<unsigned>> linearize_scalars[] = {
    {"double", std::nullopt}, {"interval", std::nullopt}, {"mpfi", 113u}};

class ratio_reporter : public median_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::cout << "\nratios from this run (goal: at most 3)\n  " << std::left << std::setw(34) << "system file"
              << std::setw(10) << "scalar" << std::right << std::setw(14) << "dedicated ns" << std::setw(12)
              << "system ns" << std::setw(18) << "system/dedicated\n";
    for (const auto& [sys, model] : pairs)
      for (const char* scalar : scalars) {
        const double d = ns(std::string(scalar) + "/" + model), s = ns(std::string(scalar) + "/" + sys);
        if (!(d > 0 && s > 0)) continue;
        std::cout << "  " << std::left << std::setw(34) << sys << std::setw(10) << scalar << std::right << std::fixed
                  << std::setprecision(1) << std::setw(14) << d << std::setw(12) << s << std::setw(12) << s / d
                  << (s / d <= 3 ? " met" : " MISSED") << "\n";
      }
    std::cout << "\nthe Whipple bicycle's linearization (appell linearize: matrices, 11 spectra, critical speeds)\n";
    for (const auto& [scalar, bits] : linearize_scalars) {
      const std::string name = std::string("linearize/") + scalar + (bits ? "-" + std::to_string(*bits) : "");
      const double t = ns(name);
      if (!(t > 0)) continue;
      std::cout << "  " << std::left << std::setw(16) << name.substr(10) << std::right << std::fixed << std::setprecision(1)
                << std::setw(10) << t / 1e6 << " ms"
                << (bits ? (t < 1e9 ? "   (goal: under 1000 ms) met" : "   (goal: under 1000 ms) MISSED") : "") << "\n";
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (const auto& [sys, model] : pairs)
    for (const char* scalar : scalars)
      for (const char* file : {model, sys})
        benchmark::RegisterBenchmark((std::string(scalar) + "/" + file).c_str(), bench, std::string(scalar),
                                     std::string(file));
  for (const auto& [scalar, bits] : linearize_scalars)
    benchmark::RegisterBenchmark((std::string("linearize/") + scalar + (bits ? "-" + std::to_string(*bits) : "")).c_str(),
                                 bench_linearize, std::string(scalar), bits);
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
