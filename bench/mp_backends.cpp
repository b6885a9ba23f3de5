// appell's MPFR and MPFI backends against Boost's, in one run (issue "speed without the heap",
// point 3): the kernel of a Taylor step, the Cauchy product of two series of `n` coefficients
// (c_k = sum_j a_j b_{k-j}, every coefficient, each product a new value as the library's code
// makes it), at 113, 256 and 512 bits.  appell::mpfr keeps a significand of up to 256 bits inside
// the value (mpfr_backend.hpp); Boost's mpfr_float_backend<0> allocates one per value (and takes
// its precision in decimal digits: 113 asked is 114, 256 is 257, so Boost's side does a little
// more work; the bits are printed).  appell::mpfi likewise against Boost's mpfi_float_backend<0>.
// Each row: the median time of one product over interleaved repetitions, both ways, and the
// ratio Boost / appell.  Not a test: a table.
// Usage: appell_bench_mp_backends [n]   (default n = 40, the order of the long-horizon references)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <boost/multiprecision/mpfi.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "appell/scalar/types.hpp"

namespace {

using boost_mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
using boost_mpfi = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<0>, boost::multiprecision::et_off>;

template <class T>
std::vector<T> series(int n, int seed) {
  std::vector<T> a;
  for (int k = 0; k < n; ++k) a.push_back(T(1) / T(k + seed));
  return a;
}

template <class T>
T cauchy_checksum(const std::vector<T>& a, const std::vector<T>& b) {
  const int n = static_cast<int>(a.size());
  T check = 0;
  for (int k = 0; k < n; ++k) {
    T c = 0;
    for (int j = 0; j <= k; ++j) c = c + a[j] * b[k - j];
    check = check + c;
  }
  return check;
}

template <class T>
double seconds_per_product(const std::vector<T>& a, const std::vector<T>& b, int reps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) {
    volatile bool sink = cauchy_checksum(a, b) > 0;
    (void)sink;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class A, class B>
void row(const char* name, unsigned bits, int n, long (*bits_of_a)(), long (*bits_of_b)()) {
  const std::vector<A> a1 = series<A>(n, 1), a2 = series<A>(n, 2);
  const std::vector<B> b1 = series<B>(n, 1), b2 = series<B>(n, 2);
  const int reps = std::max(1, static_cast<int>(0.02 / std::max(seconds_per_product(a1, a2, 1), 1e-7)));
  std::vector<double> ta, tb;
  for (int k = 0; k < 15; ++k) {  // interleaved
    ta.push_back(seconds_per_product(a1, a2, reps));
    tb.push_back(seconds_per_product(b1, b2, reps));
  }
  const double ma = median(ta), mb = median(tb);
  std::printf("%-6s %6u %10ld %10ld %14.2f %14.2f %8.2f\n", name, bits, bits_of_a(), bits_of_b(), ma * 1e6, mb * 1e6, mb / ma);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 40;
  if (n < 1) return 2;
  std::printf("Cauchy product of two series of %d coefficients (microseconds, medians of 15 interleaved runs)\n", n);
  std::printf("%-6s %6s %10s %10s %14s %14s %8s\n", "scalar", "asked", "appell_bits", "boost_bits", "appell_us", "boost_us",
              "boost/appell");
  for (const unsigned bits : {113u, 256u, 512u}) {
    const appell::mp_precision_scope scope(bits);
    unsigned d10 = 1;  // Boost's precision in decimal digits: the fewest that hold `bits` bits
    while (boost::multiprecision::detail::digits10_2_2(d10) < bits) ++d10;
    boost_mpfr::default_precision(d10);
    boost_mpfi::default_precision(d10);
    row<appell::mpfr, boost_mpfr>(
        "mpfr", bits, n, [] { return static_cast<long>(appell::mpfr(1).backend().prec()); },
        [] { return static_cast<long>(mpfr_get_prec(boost_mpfr(1).backend().data())); });
    row<appell::mpfi, boost_mpfi>(
        "mpfi", bits, n, [] { return static_cast<long>(appell::mpfi(1).backend().prec()); },
        [] { return static_cast<long>(mpfi_get_prec(boost_mpfi(1).backend().data())); });
  }
}
