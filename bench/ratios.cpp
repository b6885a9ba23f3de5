// Speed ratios of the scalars on the paper scenes (Google Benchmark).
//
// Each benchmark times compute<T>() of a prepared scene (the dynamics; inputs
// converted once), for every standard scalar (mpfr and mpfi at 113 and 256 bits).  After the runs, the ratios that issue "make intervals
// cheap" tracks are printed from this same run, with their goals:
//   interval / double <= 4,  dd / double <= 12,  float128 / double <= 80,
//   mpfi / mpfr <= 2.2 at equal bits, arb / mpfr <= 1.3 at equal bits (issue 57).
// Run: build/bench/appell_bench  (or, steadier on a shared machine, with
//   --benchmark_min_time=0.2 --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true:
//   the ratios then use the median of the repetitions).
#include <benchmark/benchmark.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/io/scene.hpp"
#include "appell/scalar/arb_access.hpp"  // in_place/arb: Arb's functions called directly
#include "median_reporter.hpp"

using namespace appell;

namespace {

// Every shipped scene: the three of the paper's sections first, then the variants.
const char* const scenes[] = {"euler_body.json",           "top_on_cone.json",          "rolling_sphere_bowl.json",
                              "top_on_cone_constant.json", "top_on_cone_steep.json",    "rolling_sphere_plane.json",
                              "rolling_sphere_globe.json", "rolling_sphere_pipe.json",  "rolling_sphere_tube.json"};

void bench_scene(benchmark::State& state, const std::string& scalar, std::optional<unsigned> bits, const char* file) {
  with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    const scene_input scene = read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
    const prepared_scene<T> prepared = prepare<T>(scene);
    for (auto _ : state) benchmark::DoNotOptimize(compute<T>(prepared));
    return 0;
  });
}

// The floor of the mpfi/mpfr ratio: one product and one sum, s = a b + c (plus
// a = s - b to keep the values moving), as the scenes' code does them -- a
// fresh value per operation.  mpfi at its working precision (guard bits), as compute uses.
template <class T>
void bench_elementary(benchmark::State& state, unsigned bits) {
  const mp_precision_scope scope(scalar_traits<T>::working_bits(bits));
  T a = T(1) / 3, b = T(2) / 7, c = T(5) / 11;
  for (auto _ : state) {
    T s = a * b + c;
    benchmark::DoNotOptimize(s);
    a = s - b;
  }
}

// The same a b + c with no new values: the outputs exist beforehand and the
// operations write into them (MPFR's C interface; for mpfi the endpoint
// operations that appell::mpfi's + - * use).  What the bounds' arithmetic costs
// alone: two directed roundings per operation against one.
template <class T>
void bench_in_place(benchmark::State& state, unsigned bits) {
  const mp_precision_scope scope(scalar_traits<T>::working_bits(bits));
  T a = T(1) / 3, b = T(2) / 7, c = T(5) / 11, s;
  for (auto _ : state) {
    if constexpr (std::is_same_v<T, arb>) {  // Arb's own functions, in place: what the balls cost alone
      const slong p = s.backend().prec();
      arb_mul(mp::arb_of(s.backend()), mp::arb_of(a.backend()), mp::arb_of(b.backend()), p);
      arb_add(mp::arb_of(s.backend()), mp::arb_of(s.backend()), mp::arb_of(c.backend()), p);
      arb_sub(mp::arb_of(a.backend()), mp::arb_of(s.backend()), mp::arb_of(b.backend()), p);
    } else if constexpr (std::is_same_v<T, mpfr>) {
      mpfr_mul(s.backend().data(), a.backend().data(), b.backend().data(), MPFR_RNDN);
      mpfr_add(s.backend().data(), s.backend().data(), c.backend().data(), MPFR_RNDN);
      mpfr_sub(a.backend().data(), s.backend().data(), b.backend().data(), MPFR_RNDN);
    } else {
      if (!detail::mpfi_mul_endpoints(s.backend().data(), a.backend().data(), b.backend().data()))
        state.SkipWithError("mpfi product outside the endpoint cases");
      detail::mpfi_add_endpoints(s.backend().data(), s.backend().data(), c.backend().data());
      detail::mpfi_sub_endpoints(a.backend().data(), s.backend().data(), b.backend().data());
    }
    benchmark::DoNotOptimize(s);
  }
}

class ratio_reporter : public median_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::cout << "\nratios from this run (goal in brackets):\n";
    for (const char* s : scenes) {
      auto t = [&](const std::string& name) { return ns(name + "/" + s); };
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
      line("arb / mpfr at 113 bits", t("arb113") / t("mpfr113"), 1.3);
      line("arb / mpfr at 256 bits", t("arb256") / t("mpfr256"), 1.3);
    }
    const double e113 = ns("elementary/mpfi113") / ns("elementary/mpfr113");
    const double e256 = ns("elementary/mpfi256") / ns("elementary/mpfr256");
    if (e113 > 0 && std::isfinite(e113))
      std::cout << "  elementary s = a b + c: mpfi / mpfr " << std::setprecision(3) << e113 << " at 113 bits, " << e256
                << " at 256 bits (a new value per operation, as the scenes compute)\n";
    const double a113 = ns("elementary/arb113") / ns("elementary/mpfr113");
    const double a256 = ns("elementary/arb256") / ns("elementary/mpfr256");
    if (a113 > 0 && std::isfinite(a113))
      std::cout << "  elementary s = a b + c: arb / mpfr " << std::setprecision(3) << a113 << " at 113 bits, " << a256
                << " at 256 bits\n";
    const double i113 = ns("in_place/mpfi113") / ns("in_place/mpfr113");
    const double i256 = ns("in_place/mpfi256") / ns("in_place/mpfr256");
    if (i113 > 0 && std::isfinite(i113))
      std::cout << "  in place s = a b + c:   mpfi / mpfr " << std::setprecision(3) << i113 << " at 113 bits, " << i256
                << " at 256 bits (no new values: the bounds' arithmetic alone)\n";
    const double b113 = ns("in_place/arb113") / ns("in_place/mpfr113");
    const double b256 = ns("in_place/arb256") / ns("in_place/mpfr256");
    if (b113 > 0 && std::isfinite(b113))
      std::cout << "  in place s = a b + c:   arb / mpfr " << std::setprecision(3) << b113 << " at 113 bits, " << b256
                << " at 256 bits (Arb's arb_mul, arb_add, arb_sub against MPFR's: the floor of arb's ratio)\n";
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* s : scenes)
    for (const scalar_info& scalar : standard_scalar_infos()) {
      if (!scalar.runtime_precision) {
        benchmark::RegisterBenchmark((scalar.name + "/" + s).c_str(), bench_scene, scalar.name, std::nullopt, s);
        continue;
      }
      for (unsigned bits : {113u, 256u})
        benchmark::RegisterBenchmark((scalar.name + std::to_string(bits) + "/" + s).c_str(), bench_scene, scalar.name,
                                     std::optional<unsigned>(bits), s);
    }
  for (unsigned bits : {113u, 256u}) {
    benchmark::RegisterBenchmark(("elementary/mpfr" + std::to_string(bits)).c_str(), bench_elementary<mpfr>, bits);
    benchmark::RegisterBenchmark(("elementary/mpfi" + std::to_string(bits)).c_str(), bench_elementary<mpfi>, bits);
    benchmark::RegisterBenchmark(("elementary/arb" + std::to_string(bits)).c_str(), bench_elementary<arb>, bits);
    benchmark::RegisterBenchmark(("in_place/mpfr" + std::to_string(bits)).c_str(), bench_in_place<mpfr>, bits);
    benchmark::RegisterBenchmark(("in_place/mpfi" + std::to_string(bits)).c_str(), bench_in_place<mpfi>, bits);
    benchmark::RegisterBenchmark(("in_place/arb" + std::to_string(bits)).c_str(), bench_in_place<arb>, bits);
  }
  benchmark::Initialize(&argc, argv);
  ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
