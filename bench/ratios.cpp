// Speed ratios of the scalars on the paper scenes (Google Benchmark).
//
// Each benchmark times compute<T>() of a bound scene (the dynamics; inputs
// converted once).  After the runs, the ratios that issue "make intervals
// cheap" tracks are printed from this same run, with their goals:
//   interval / double <= 4,  dd / double <= 12,  float128 / double <= 80,
//   mpfi / mpfr <= 2.2 at equal bits.
// Run: build/bench/appell_bench  (or with --benchmark_min_time=0.5 for steadier numbers).
#include <benchmark/benchmark.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

#include "appell/io/scene.hpp"

using namespace appell;

namespace {

const char* const scenes[] = {"euler_body.json", "top_on_cone.json", "rolling_sphere_bowl.json"};

template <class T>
void bench_scene(benchmark::State& state, const char* file, unsigned bits) {
  std::optional<mp_precision_scope> scope;
  if (bits) scope.emplace(bits);
  const scene_input scene = read_scene_file(std::string(APPELL_SOURCE_DIR "/data/scenes/") + file);
  const bound_scene<T> bound = bind<T>(scene);
  for (auto _ : state) benchmark::DoNotOptimize(compute<T>(bound));
}

class ratio_reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) ns_[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::cout << "\nratios from this run (goal in brackets):\n";
    for (const char* s : scenes) {
      auto t = [&](const std::string& name) { return ns_[name + "/" + s]; };
      auto line = [&](const std::string& what, double ratio, double goal) {
        if (!(ratio > 0) || !std::isfinite(ratio)) return;  // filtered out of this run
        std::cout << "  " << std::left << std::setw(26) << s << std::setw(24) << what << std::right << std::setw(8)
                  << std::setprecision(3) << ratio << "  [<= " << goal << "]  " << (ratio <= goal ? "met" : "MISSED")
                  << "\n";
      };
      line("interval / double", t("interval") / t("double"), 4);
      line("dd / double", t("dd") / t("double"), 12);
      line("float128 / double", t("float128") / t("double"), 80);
      line("mpfi / mpfr at 113 bits", t("mpfi113") / t("mpfr113"), 2.2);
      line("mpfi / mpfr at 256 bits", t("mpfi256") / t("mpfr256"), 2.2);
    }
  }

 private:
  std::map<std::string, double> ns_;
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* s : scenes) {
    benchmark::RegisterBenchmark((std::string("double/") + s).c_str(), bench_scene<double>, s, 0u);
    benchmark::RegisterBenchmark((std::string("dd/") + s).c_str(), bench_scene<dd>, s, 0u);
    benchmark::RegisterBenchmark((std::string("float128/") + s).c_str(), bench_scene<float128>, s, 0u);
    benchmark::RegisterBenchmark((std::string("interval/") + s).c_str(), bench_scene<interval>, s, 0u);
    benchmark::RegisterBenchmark((std::string("mpfr113/") + s).c_str(), bench_scene<mpfr>, s, 113u);
    benchmark::RegisterBenchmark((std::string("mpfi113/") + s).c_str(), bench_scene<mpfi>, s, 113u);
    benchmark::RegisterBenchmark((std::string("mpfr256/") + s).c_str(), bench_scene<mpfr>, s, 256u);
    benchmark::RegisterBenchmark((std::string("mpfi256/") + s).c_str(), bench_scene<mpfi>, s, 256u);
  }
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
