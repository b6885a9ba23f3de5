// The scene model "system" against the dedicated models (Google Benchmark):
// compute<T>() of a paper scene written as a system file (data/scenes/system_*.json)
// and of the same scene in its dedicated model, side by side in one run, in
// double and in interval; prints system / dedicated with the goal (<= 3).
// Run: build/bench/appell_bench_system
//   (steadier: --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true: medians are used).
#include <benchmark/benchmark.h>

#include <iomanip>
#include <iostream>

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
  const scene_input scene = read_scene_file(std::string(APPELL_SOURCE_DIR "/data/scenes/") + file);
  with_scalar(scalar, std::nullopt, [&]<class T>(std::type_identity<T>) {
    const prepared_scene<T> prepared = prepare<T>(scene);
    for (auto _ : state) benchmark::DoNotOptimize(compute<T>(prepared));
    return 0;
  });
}

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
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (const auto& [sys, model] : pairs)
    for (const char* scalar : scalars)
      for (const char* file : {model, sys})
        benchmark::RegisterBenchmark((std::string(scalar) + "/" + file).c_str(), bench, std::string(scalar),
                                     std::string(file));
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
