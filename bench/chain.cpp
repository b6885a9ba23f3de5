// Cost against size: a planar N-link pendulum (N = 1 to 64) written on the
// public API (dynamics/gibbs_appell.hpp), its accelerations by the generic
// Gibbs-Appell path in double and in interval, beside Simbody's forward
// dynamics (O(N) articulated-body recursion) on the same chain, in one run.
//
// The chain: N uniform links of mass 1 and length 1, pinned end to end, the
// first to the ground at the origin; central inertia 1/12 about every axis;
// gravity 9.81 along -y; coordinates the relative joint angles, speeds their
// rates (Simbody's Pin mobilizers).  Before timing, appell's accelerations
// are compared with Simbody's for every N (relative 1e-9: two formulations,
// Appell's equations against the articulated-body recursion).
// After the runs: the table, and the exponent p of cost ~ N^p fitted on N >= 8.
// Run: build/bench/appell_bench_chain
#include <benchmark/benchmark.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/policy.hpp"
#include "median_reporter.hpp"
#include "../examples/planar_chain.hpp"

#ifdef APPELL_HAVE_SIMBODY
#include "simbody_chain.hpp"
#endif

using namespace appell;
using appell::examples::planar_chain;

namespace {

const int sizes[] = {1, 2, 4, 8, 16, 32, 64};

template <Scalar T>
void state_of(int n, vector_t<T>& q, vector_t<T>& u) {
  q.resize(n);
  u.resize(n);
  for (int i = 0; i < n; ++i) {
    q(i) = rational<T>(10 + 2 * i, 100);  // 0.1 + 0.02 i
    u(i) = rational<T>(30 - i, 100);      // 0.3 - 0.01 i
  }
}

template <Scalar T>
vector_t<T> appell_accelerations(const planar_chain<T>& chain, const vector_t<T>& q, const vector_t<T>& u) {
  return gibbs_appell(chain, q, u, T(0)).accelerations();
}

template <Scalar T>
void bench_appell(benchmark::State& state, int n) {
  const evaluation_scope<T> scope;
  const planar_chain<T> chain{n};
  vector_t<T> q, u;
  state_of(n, q, u);
  for (auto _ : state) benchmark::DoNotOptimize(appell_accelerations(chain, q, u));
  scope.verify();
}

#ifdef APPELL_HAVE_SIMBODY
simbody_chain make_simbody_chain(int n) {
  vector_t<double> q, u;
  state_of(n, q, u);
  return simbody_chain(n, std::vector<double>(q.data(), q.data() + n), std::vector<double>(u.data(), u.data() + n));
}

void bench_simbody(benchmark::State& state, int n) {
  simbody_chain chain = make_simbody_chain(n);
  for (auto _ : state) benchmark::DoNotOptimize(chain.accelerations()[0]);
}

/// appell's accelerations against Simbody's: exit 4 if they differ.
void cross_check(int n) {
  const planar_chain<double> chain{n};
  vector_t<double> q, u;
  state_of(n, q, u);
  const vector_t<double> a = appell_accelerations(chain, q, u);
  simbody_chain sb = make_simbody_chain(n);
  const double* b = sb.accelerations();
  double scale = 1, worst = 0;
  for (int i = 0; i < n; ++i) {
    scale = std::max(scale, std::abs(a(i)));
    worst = std::max(worst, std::abs(a(i) - b[i]));
  }
  if (!(worst <= 1e-9 * scale)) {
    std::cerr << "chain of " << n << ": appell and Simbody differ by " << worst << "\n";
    std::exit(4);
  }
}
#endif

class table_reporter : public median_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    const char* columns[] = {"double", "interval", "simbody"};
    std::cout << "\nplanar N-link pendulum, accelerations from the state (ns)\n  " << std::setw(4) << "N";
    for (const char* c : columns) std::cout << std::setw(14) << c;
    std::cout << std::setw(18) << "interval/double" << std::setw(18) << "double/simbody" << "\n";
    for (int n : sizes) {
      std::cout << "  " << std::setw(4) << n;
      for (const char* c : columns) std::cout << std::setw(14) << std::fixed << std::setprecision(0) << at(c, n);
      std::cout << std::setw(18) << std::setprecision(1) << at("interval", n) / at("double", n) << std::setw(18)
                << at("double", n) / at("simbody", n) << "\n";
    }
    std::cout << "fitted exponent p of cost ~ N^p (least squares on N = 8 to 64):";
    for (const char* c : columns) {
      double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
      for (int n : sizes) {
        if (n < 8 || !(at(c, n) > 0)) continue;
        const double x = std::log(n), y = std::log(at(c, n));
        sx += x, sy += y, sxx += x * x, sxy += x * y, m += 1;
      }
      if (m >= 2) std::cout << "  " << c << " " << std::setprecision(2) << (m * sxy - sx * sy) / (m * sxx - sx * sx);
    }
    std::cout << "\n";
  }

 private:
  double at(const std::string& column, int n) {
    const double t = ns(column + "/" + std::to_string(n));
    return t > 0 ? t : std::nan("");
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (int n : sizes) {
#ifdef APPELL_HAVE_SIMBODY
    cross_check(n);
    benchmark::RegisterBenchmark(("simbody/" + std::to_string(n)).c_str(), bench_simbody, n);
#endif
    benchmark::RegisterBenchmark(("double/" + std::to_string(n)).c_str(), bench_appell<double>, n);
    benchmark::RegisterBenchmark(("interval/" + std::to_string(n)).c_str(), bench_appell<interval>, n);
  }
  benchmark::Initialize(&argc, argv);
  table_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
