// The x87 error bounds (appell/scalar/x87_bounds.hpp).
#include "appell/scalar/x87_bounds.hpp"

#include <limits>
#include <stdexcept>

namespace appell {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
namespace {

/// The x87 unit at its full 64-bit significand, rounding upward, for a scope (the SSE unit, which
/// does double arithmetic, is left as it is).  An x87 operation on operands of at most 64 bits is
/// then one correct upward rounding to 64 bits.
class x87_upward {
 public:
  x87_upward() {
    asm volatile("fnstcw %0" : "=m"(saved_));
    const unsigned short upward = static_cast<unsigned short>((saved_ & ~0x0F00u) | 0x0B00u);  // PC 64 bits, RC up
    asm volatile("fldcw %0" : : "m"(upward) : "memory");
  }
  ~x87_upward() { asm volatile("fldcw %0" : : "m"(saved_) : "memory"); }
  x87_upward(const x87_upward&) = delete;
  x87_upward& operator=(const x87_upward&) = delete;
  /// x, as the compiler must compute it here (not moved across the mode's switches)
  static long double opaque(long double x) {
    asm volatile("" : "+t"(x));
    return x;
  }

 private:
  unsigned short saved_ = 0;
};

}  // namespace

bool x87_bounds_available() { return std::numeric_limits<long double>::digits == 64; }

error_bounds_64 x87_error_bounds(double d, double lo, double hi, double w) {
  if (!x87_bounds_available()) throw std::logic_error("x87_error_bounds: long double is not the x87 64-bit format");
  error_bounds_64 b;
  b.has_relative = lo > 0 || hi < 0;
  const x87_upward up;
  const long double ld = x87_upward::opaque(d), ll = x87_upward::opaque(lo), lh = x87_upward::opaque(hi);
  const long double e1 = x87_upward::opaque(ld - ll), e2 = x87_upward::opaque(lh - ld);
  b.absolute = e1 < e2 ? e2 : e1;
  if (lo > 0) b.relative = x87_upward::opaque(b.absolute / ll);
  else if (hi < 0) b.relative = x87_upward::opaque(b.absolute / -lh);
  b.tolerance = x87_upward::opaque(x87_upward::opaque(static_cast<long double>(w)) * 16);
  return b;
}
#else
bool x87_bounds_available() { return false; }

error_bounds_64 x87_error_bounds(double, double, double, double) {
  throw std::logic_error("x87_error_bounds: no x87 unit on this target");
}
#endif

}  // namespace appell
