// Bit-for-bit equality of two MPFR numbers, for the backends' differential tests
// (tests/mpfr_backend.cpp, tests/mpfi_backend.cpp).
#pragma once

#include <mpfr.h>

namespace appell::test {

/// Value and precision, bit for bit: NaN matches NaN, zeros must agree in sign.
inline bool same(mpfr_srcptr a, mpfr_srcptr b) {
  if (mpfr_get_prec(a) != mpfr_get_prec(b)) return false;
  if (mpfr_nan_p(a) || mpfr_nan_p(b)) return mpfr_nan_p(a) && mpfr_nan_p(b);
  return mpfr_equal_p(a, b) && mpfr_signbit(a) == mpfr_signbit(b);
}

}  // namespace appell::test
