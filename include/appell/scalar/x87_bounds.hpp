// appell/scalar/x87_bounds.hpp -- the 64-bit error bounds of `appell reference` in interval,
// computed by the x87 unit instead of MPFR.
//
// For a double d inside an enclosure [lo, hi] of doubles, `appell reference` prints
//   absolute = max(d - lo, hi - d),  relative = absolute / min |x| over [lo, hi] (0 not in it),
//   tolerance = 16 w,
// each rounded upward to a 64-bit significand: what MPFR computes at 64 bits with MPFR_RNDU.
// The x87 unit set to its 64-bit significand and to upward rounding gives the same numbers
// (one correct rounding of the same exact value at the same precision): no difference,
// maximum, quotient or power-of-2 multiple of doubles leaves x87's exponent range (+-16382) or
// reaches its subnormals.  About a dozen MPFR calls less a quantity (docs/reference-values.md).
// tests/decimal.cpp checks the numbers bit for bit against MPFR on random enclosures.
#pragma once

namespace appell {

/// The bounds, as 64-bit long doubles (each rounded upward).
struct error_bounds_64 {
  long double absolute = 0;   ///< max(d - lo, hi - d)
  long double relative = 0;   ///< absolute / min |x| over [lo, hi]; 0 when has_relative is false
  bool has_relative = false;  ///< lo > 0 or hi < 0
  long double tolerance = 0;  ///< 16 w
};

/// Whether x87_error_bounds is available: an x87 unit with a 64-bit long double (x86-64 GCC or
/// Clang).  Elsewhere the caller computes the same numbers with MPFR.
bool x87_bounds_available();

/// The bounds of d in [lo, hi] (lo <= d <= hi, all finite) and the tolerance of w >= 0, each
/// rounded upward to 64 bits.  Throws std::logic_error where x87_bounds_available() is false.
error_bounds_64 x87_error_bounds(double d, double lo, double hi, double w);

}  // namespace appell
