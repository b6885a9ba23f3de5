// Robots from URDF (Google Benchmark): one `eval` of a `urdf` scene -- the forward dynamics and
// every joint's wrench, with their checks -- in double, interval and mpfi at 113 bits, on the
// robots Debian's dart-doc ships (the WAM arm, 7 joints; the KUKA KR5, 6; the Atlas humanoid,
// 27, pelvis fixed) and appell's own arm, in one run.  Goals (issue 32): the WAM within 1 ms in
// interval and 20 ms in mpfi at 113 bits; the Atlas within 10 ms in interval.
// Run: build/bench/appell_bench_urdf
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iomanip>
#include <iostream>

#include "appell/io/scene.hpp"
#include "median_reporter.hpp"

using namespace appell;

namespace {

const char* const robots[] = {"urdf_appell_arm.json", "urdf_wam.json", "urdf_kr5.json", "urdf_atlas.json"};
const std::pair<const char*, std::optional<unsigned>> scalars[] = {{"double", std::nullopt}, {"interval", std::nullopt},
                                                                   {"mpfi", 113u}};

void bench(benchmark::State& state, std::string scalar, std::optional<unsigned> bits, std::string file) {
  const scene_input scene = read_scene_file(std::string(APPELL_SOURCE_DIR "/data/scenes/") + file);
  with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    const prepared_scene<T> prepared = prepare<T>(scene);
    for (auto _ : state) benchmark::DoNotOptimize(compute<T>(prepared));
    return 0;
  });
}

class table_reporter : public median_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::cout << "\none eval (forward dynamics and every joint's wrench), microseconds\n  " << std::left << std::setw(24)
              << "robot" << std::right;
    for (const auto& [s, b] : scalars) std::cout << std::setw(12) << s;
    std::cout << "   goal\n";
    for (const char* r : robots) {
      std::cout << "  " << std::left << std::setw(24) << r << std::right;
      for (const auto& [s, b] : scalars) {
        const double t = ns(std::string(s) + "/" + r);
        std::cout << std::setw(12) << std::fixed << std::setprecision(1) << (t > 0 ? t / 1e3 : std::nan(""));
      }
      const std::string name = r;
      if (name == "urdf_wam.json") {
        const double i = ns(std::string("interval/") + r), m = ns(std::string("mpfi/") + r);
        std::cout << "   interval <= 1000 " << (i <= 1e6 ? "met" : "MISSED") << ", mpfi <= 20000 " << (m <= 2e7 ? "met" : "MISSED");
      }
      if (name == "urdf_atlas.json") {
        const double i = ns(std::string("interval/") + r);
        std::cout << "   interval <= 10000 " << (i <= 1e7 ? "met" : "MISSED");
      }
      std::cout << "\n";
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* r : robots) {
    if (std::string(r) != "urdf_appell_arm.json" && !std::filesystem::exists("/usr/share/doc/dart/data")) continue;
    for (const auto& [s, b] : scalars)
      benchmark::RegisterBenchmark((std::string(s) + "/" + r).c_str(), bench, std::string(s), b, std::string(r));
  }
  benchmark::Initialize(&argc, argv);
  table_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
