// Tight integer powers of mpfi values (MPFI has sqr but no pown).
#include <mpfi.h>

#include "appell/scalar/functions.hpp"
#include "appell/scalar/interval.hpp"

namespace appell {
namespace {
mpfr pow_dir(const mpfr& x, long n, mpfr_rnd_t rnd) {
  mpfr r;
  mpfr_set_prec(r.backend().data(), mpfr_get_prec(x.backend().data()));
  mpfr_pow_si(r.backend().data(), x.backend().data(), n, rnd);
  return r;
}
}  // namespace

mpfi pown_mpfi(const mpfi& x, int n) {
  // Same case analysis as pown(interval) in interval_functions.cpp.
  const mpfr lo = mpfi_lower(x), hi = mpfi_upper(x);
  const auto d = [n](const mpfr& v) { return pow_dir(v, n, MPFR_RNDD); };
  const auto u = [n](const mpfr& v) { return pow_dir(v, n, MPFR_RNDU); };
  const mpfr inf = std::numeric_limits<mpfr>::infinity();
  const mpfr zero = 0;
  if (n == 0) return mpfi(1);
  const bool even = n % 2 == 0;
  if (n > 0) {
    if (!even || lo >= 0) return mpfi_from_bounds(d(lo), u(hi));
    if (hi <= 0) return mpfi_from_bounds(d(hi), u(lo));
    return mpfi_from_bounds(zero, u(-lo > hi ? mpfr(-lo) : hi));
  }
  if (lo > 0) return mpfi_from_bounds(d(hi), u(lo));
  if (hi < 0) return even ? mpfi_from_bounds(d(lo), u(hi)) : mpfi_from_bounds(d(hi), u(lo));
  if (lo == 0 && hi == 0) throw domain_error("negative power of [0, 0]");
  if (even) return mpfi_from_bounds(d(-lo > hi ? mpfr(-lo) : hi), inf);
  if (lo == 0) return mpfi_from_bounds(d(hi), inf);
  if (hi == 0) return mpfi_from_bounds(-inf, u(lo));
  return mpfi_from_bounds(-inf, inf);
}

}  // namespace appell

namespace boost::multiprecision {

appell_mpfi sqrt(const appell_mpfi& x) {
  if (mpfr_sgn(&x.backend().data()->right) < 0) throw appell::domain_error("sqrt of an interval below 0");
  appell_mpfi r, clipped = x;
  if (mpfr_sgn(&x.backend().data()->left) < 0) mpfr_set_ui(&clipped.backend().data()->left, 0, MPFR_RNDD);
  mpfi_sqrt(r.backend().data(), clipped.backend().data());
  return r;
}

appell_mpfi log(const appell_mpfi& x) {
  if (mpfr_sgn(&x.backend().data()->right) <= 0)
    throw appell::domain_error("log of an interval with no positive point");
  appell_mpfi r, clipped = x;  // log 0 = -inf in MPFI
  if (mpfr_sgn(&x.backend().data()->left) < 0) mpfr_set_ui(&clipped.backend().data()->left, 0, MPFR_RNDD);
  mpfi_log(r.backend().data(), clipped.backend().data());
  return r;
}

}  // namespace boost::multiprecision
