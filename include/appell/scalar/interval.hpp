// appell/scalar/interval.hpp -- the rigorous `interval<double>` of appell.
//
// Rigour contract (in the spirit of CAPD): every operation returns a box that
// contains the exact real result for every point of its arguments.  We do not
// assume that libm rounds correctly, nor that it honours the rounding mode.
//  * + - * /: IEEE 754 operations under directed rounding (upward mode; lower
//    bounds as -((-x) op y)), each operand made opaque to the optimiser.  This
//    also needs -frounding-math -ffp-contract=off and no -ffast-math, which the
//    appell::appell target carries (docs/design.md §3).
//  * sqrt sin cos tan atan exp log pown: each bound is MPFR's correctly rounded value
//    at 53 bits with MPFR_RNDD / MPFR_RNDU, converted to double with the same
//    direction.  Extrema inside wide arguments are located by a certified
//    range reduction (src/scalar/interval_functions.cpp).
// Empty sets are allowed in arithmetic (for IEEE 1788 test vectors) but a
// function whose result would be empty throws `appell::domain_error`.
#pragma once

#include <boost/numeric/interval/interval.hpp>
#include <boost/numeric/interval/policies.hpp>
#include <boost/numeric/interval/hw_rounding.hpp>
#include <boost/numeric/interval/rounded_arith.hpp>
#include <boost/numeric/interval/checking.hpp>
#include <boost/numeric/interval/compare.hpp>
#include <boost/numeric/interval/utility.hpp>
#include <boost/numeric/interval/arith.hpp>
#include <boost/numeric/interval/arith2.hpp>

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#if !defined(__x86_64__)
#error "appell's interval<double> controls the SSE rounding mode: x86-64 only"
#endif
#include <string>

#include "appell/errors.hpp"
#include "appell/scalar/rounding_state.hpp"

namespace appell {

// Rounding for interval<double>.  Every operation needs the SSE unit in
// upward mode; lower bounds are computed by negation, -((-x) - y), so only
// that one mode is ever needed (sqrt_down, the one exception, switches to
// downward and back itself).  Every operation constructs an interval_rounding
// (below), which first tests a thread-local flag, detail::upward_known, set by
// an `upward_rounding` scope: inside one it does nothing at all -- no MXCSR
// read, no switch -- because the scope set the mode once for the whole
// evaluation.  Outside any scope (or inside a nearest_rounding one) it reads
// MXCSR and, only if the mode is not upward, sets it and restores it when the
// operation ends: correct anywhere, fast inside a scope (Boost's save_state
// would switch twice per operation, ~70x slower than double).
// Every operand and result passes through an empty `asm volatile`: without
// it GCC, even with -frounding-math, folds or reuses a result computed in
// another rounding mode (measured here: the upper bound of [1]/[3], computed
// upward, was reused for a later round-to-nearest 1.0/3.0, GCC bug 34678).
// Declared in namespace appell itself (not a nested one) so that
// argument-dependent lookup on an interval finds appell::sin and friends.
namespace detail {
inline unsigned read_mxcsr() {
  unsigned csr;
  asm volatile("stmxcsr %0" : "=m"(csr));
  return csr;
}
inline void write_mxcsr(unsigned csr) { asm volatile("ldmxcsr %0" : : "m"(csr)); }
/// The MXCSR bits appell sets: the rounding control (0x6000), and flush-to-zero (0x8000) and
/// denormals-are-zero (0x0040), which every mode it sets turns off: a program linked with
/// -ffast-math (GCC's crtfastmath) starts with both on, and a subnormal upper bound flushed to 0
/// is no upper bound.  A mode is "upward" only with both off.
constexpr unsigned mxcsr_mode = 0x6000 | 0x8000 | 0x0040, mxcsr_upward = 0x4000;
/// upward_known (scalar/rounding_state.hpp): true while this thread is inside an upward_rounding
/// scope (and not inside a nearest_rounding one within it): the SSE unit is then known to round
/// upward and interval operations skip reading MXCSR (measured: the read cost 40% of an interval
/// addition).  Declared there, defined in libappell_rounding.so, read initial-exec everywhere.
inline bool mxcsr_is_upward() { return (read_mxcsr() & mxcsr_mode) == mxcsr_upward; }
}  // namespace detail

/// Sets upward rounding (SSE) for a scope and restores the previous mode:
/// wrap an evaluation in it and its interval operations neither switch modes
/// nor read MXCSR.  Inside it, plain double arithmetic rounds upward too.
/// Contract: code inside the scope must not change the rounding mode except
/// through nearest_rounding or a switch it undoes before the next interval
/// operation (all of appell's code does so); intact() tells whether the mode
/// is still upward, and compute<interval> refuses a result when it is not.
class upward_rounding {
 public:
  upward_rounding() : saved_(detail::read_mxcsr()), was_known_(detail::upward_known) {
    detail::write_mxcsr((saved_ & ~detail::mxcsr_mode) | detail::mxcsr_upward);
    detail::upward_known = true;
  }
  ~upward_rounding() {
    detail::write_mxcsr(saved_);
    detail::upward_known = was_known_;
  }
  /// The unit still rounds upward (nobody changed the mode behind the scope's back).
  bool intact() const { return detail::mxcsr_is_upward(); }
  upward_rounding(const upward_rounding&) = delete;
  upward_rounding& operator=(const upward_rounding&) = delete;

 private:
  unsigned saved_;
  bool was_known_;
};

/// The opposite: round to nearest for a scope (around code that assumes it, e.g. MPFR calls).
class nearest_rounding {
 public:
  nearest_rounding() : saved_(detail::read_mxcsr()), was_known_(detail::upward_known) {
    detail::upward_known = false;
    detail::write_mxcsr(saved_ & ~detail::mxcsr_mode);
  }
  ~nearest_rounding() {
    detail::write_mxcsr(saved_);
    detail::upward_known = was_known_;
  }
  nearest_rounding(const nearest_rounding&) = delete;
  nearest_rounding& operator=(const nearest_rounding&) = delete;

 private:
  unsigned saved_;
  bool was_known_;
};

/// Inside an upward_rounding scope the interval operations trust the mode without reading it:
/// refuses (certification_error naming `who`) when code run inside the scope left the unit
/// rounding otherwise, so that nothing computed after the change is given out as proved.  Outside
/// a scope it checks nothing (each operation then sets the mode itself).
inline void verify_upward_rounding(const char* who) {
  if (detail::upward_known && !detail::mxcsr_is_upward())
    throw certification_error(std::string(who) +
                              ": the rounding mode was changed inside an upward-rounding scope (by code the scope ran: a "
                              "callback, another library); nothing computed after the change is proved");
}

struct interval_arith : boost::numeric::interval_lib::rounded_arith_opp<double> {
  static double opaque(double x) {
    asm volatile("" : "+x"(x));
    return x;
  }
  template <class U>
  double conv_down(const U& v) { return -opaque(-static_cast<double>(opaque(v))); }
  template <class U>
  double conv_up(const U& v) { return opaque(static_cast<double>(opaque(v))); }
  double add_down(double x, double y) { return -opaque(opaque(-x) - opaque(y)); }
  double sub_down(double x, double y) { return -opaque(opaque(y) - opaque(x)); }
  double mul_down(double x, double y) { return -opaque(opaque(x) * opaque(-y)); }
  double div_down(double x, double y) { return -opaque(opaque(x) / opaque(-y)); }
  double add_up(double x, double y) { return opaque(opaque(x) + opaque(y)); }
  double sub_up(double x, double y) { return opaque(opaque(x) - opaque(y)); }
  double mul_up(double x, double y) { return opaque(opaque(x) * opaque(y)); }
  double div_up(double x, double y) { return opaque(opaque(x) / opaque(y)); }
  // Boost's versions of the following switch modes with fesetround, which
  // also sets the x87 unit and would leave it upward (long double computations
  // would then round upward).  These stay on the SSE unit and never leave a mode behind.
  double median(double x, double y) { return opaque(opaque(x) / 2 + opaque(y) / 2); }  // in [x, y]
  double sqrt_up(double x) { return opaque(std::sqrt(opaque(x))); }                    // upward mode
  double sqrt_down(double x) {
    const unsigned csr = detail::read_mxcsr();
    detail::write_mxcsr((csr & ~detail::mxcsr_mode) | 0x2000);  // downward
    const double r = opaque(std::sqrt(opaque(x)));
    detail::write_mxcsr(csr);
    return r;
  }
  double int_down(double x) { return std::floor(x); }
  double int_up(double x) { return std::ceil(x); }
};

/// Boost's rounding-state protocol: constructed around every interval operation.
/// Inside an upward_rounding scope it does nothing; elsewhere it reads MXCSR and
/// switches to upward (and back) only if needed.
struct interval_rounding : interval_arith {
  [[gnu::always_inline]] interval_rounding() {
    if (detail::upward_known) [[likely]] {
      restore_ = false;
      return;
    }
    saved_ = detail::read_mxcsr();
    restore_ = (saved_ & detail::mxcsr_mode) != detail::mxcsr_upward;
    if (restore_) detail::write_mxcsr((saved_ & ~detail::mxcsr_mode) | detail::mxcsr_upward);
  }
  [[gnu::always_inline]] ~interval_rounding() {
    if (restore_) detail::write_mxcsr(saved_);
  }
  interval_rounding(const interval_rounding&) = delete;
  interval_rounding& operator=(const interval_rounding&) = delete;
  using unprotected_rounding = interval_rounding;  // never unprotected

 private:
  unsigned saved_ = 0;
  bool restore_;
};
struct interval_checking : boost::numeric::interval_lib::checking_base<double> {};

using interval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<interval_rounding, interval_checking>>;

}  // namespace appell

// An int converts to a double exactly: construct [v, v] without a rounding
// object (Boost's generic converting constructor makes one for every T(0) and
// T(1) of the generic code -- 16% of an evaluation when profiled).
template <>
template <>
inline appell::interval::interval(int const& v) : low(static_cast<double>(v)), up(static_cast<double>(v)) {}

// + - * of two intervals, forced inline (GCC kept Boost's out of line: 40% of
// an interval evaluation was calls to them).  Same rounding protocol as
// interval_rounding: upward mode, lower bounds by negation.  The product is
// branch-free: the four bound products rounded up give the upper bound, the
// four products with x negated, rounded up, give minus the lower bound (Boost
// picks two of them by nine sign cases, whose branches mispredict on the sign
// patterns of dynamics).  Bounds that are infinite go to a slow path that uses
// 0 x inf = 0 (IEEE 1788's rule for bound products); empty sets stay empty.
namespace appell::detail {
[[gnu::always_inline]] inline __m128d opaque_pd(__m128d v) {
  asm volatile("" : "+x"(v));
  return v;
}
inline double bound_product_up(double a, double b) {  // a*b rounded up, 0 x inf = 0
  return (a == 0 || b == 0) ? 0.0 : interval_arith::opaque(interval_arith::opaque(a) * interval_arith::opaque(b));
}
[[gnu::noinline]] inline interval multiply_slow(double xl, double xu, double yl, double yu) {
  if (!(xl <= xu) || !(yl <= yu)) return interval::empty();
  const interval_rounding rnd;
  const double hi = std::max(std::max(bound_product_up(xl, yl), bound_product_up(xl, yu)),
                             std::max(bound_product_up(xu, yl), bound_product_up(xu, yu)));
  const double mlo = std::max(std::max(bound_product_up(-xl, yl), bound_product_up(-xl, yu)),
                              std::max(bound_product_up(-xu, yl), bound_product_up(-xu, yu)));
  return interval(-mlo, hi, true);
}
/// Both x and y have finite bounds, the lower not above the upper (NaN, the empty set's bound,
/// fails every comparison): -max <= lower <= upper <= max, both operands' lanes at once, one
/// branch for the caller instead of six.
[[gnu::always_inline]] inline __m128d ordinary_mask(const interval& x, const interval& y) {
  const __m128d lo = _mm_set_pd(y.lower(), x.lower()), hi = _mm_set_pd(y.upper(), x.upper());
  const __m128d big = _mm_set1_pd(std::numeric_limits<double>::max());
  return _mm_and_pd(_mm_and_pd(_mm_cmple_pd(lo, hi), _mm_cmple_pd(hi, big)), _mm_cmple_pd(_mm_xor_pd(big, _mm_set1_pd(-0.0)), lo));
}
[[gnu::always_inline]] inline bool ordinary_pair(const interval& x, const interval& y) {
  return _mm_movemask_pd(ordinary_mask(x, y)) == 3;
}
[[gnu::always_inline]] inline interval multiply(const interval& x, const interval& y) {
  const double xl = x.lower(), xu = x.upper(), yl = y.lower(), yu = y.upper();
  if (!ordinary_pair(x, y)) [[unlikely]]
    return multiply_slow(xl, xu, yl, yu);
  const interval_rounding rnd;
  const __m128d xs = opaque_pd(_mm_set_pd(xu, xl));             // (xl, xu)
  const __m128d neg = _mm_set1_pd(-0.0);
  const __m128d ys_l = opaque_pd(_mm_set1_pd(yl)), ys_u = opaque_pd(_mm_set1_pd(yu));
  const __m128d nxs = _mm_xor_pd(xs, neg);                         // (-xl, -xu), exact
  const __m128d up = _mm_max_pd(_mm_mul_pd(xs, ys_l), _mm_mul_pd(xs, ys_u));
  const __m128d dn = _mm_max_pd(_mm_mul_pd(nxs, ys_l), _mm_mul_pd(nxs, ys_u));
  // (max dn, max up) lane-wise: r = (-lower, upper)
  const __m128d r = opaque_pd(_mm_max_pd(_mm_unpacklo_pd(dn, up), _mm_unpackhi_pd(dn, up)));
  return interval(-_mm_cvtsd_f64(r), _mm_cvtsd_f64(_mm_unpackhi_pd(r, r)), true);
}
[[gnu::always_inline]] inline interval add(const interval& x, const interval& y) {
  if (!(x.lower() <= x.upper()) || !(y.lower() <= y.upper())) [[unlikely]]
    return interval::empty();
  interval_rounding rnd;
  return interval(rnd.add_down(x.lower(), y.lower()), rnd.add_up(x.upper(), y.upper()), true);
}
[[gnu::always_inline]] inline interval subtract(const interval& x, const interval& y) {
  if (!(x.lower() <= x.upper()) || !(y.lower() <= y.upper())) [[unlikely]]
    return interval::empty();
  interval_rounding rnd;
  return interval(rnd.sub_down(x.lower(), y.upper()), rnd.sub_up(x.upper(), y.lower()), true);
}

// Sums of two and three products in one pass (the 3 x 3 products and cross products of the
// trees' recursions: a third of an interval evaluation). Each product is kept as the pair
// (-lower, upper), both rounded up, as `multiply` forms it; a sum of such pairs, lane by lane
// in upward mode, is (-lower, upper) of the sum with every bound rounded outward, and the
// negation of a product swaps its lanes (exactly). The bounds are those of the same
// operations done one by one (a + b computes its lower bound as -((-a) - b), the same
// rounding of the same numbers), without forming and checking the intermediate intervals.
// Operands with an infinite, NaN (empty) or reversed bound (ordinary_mask, above) take the
// operations one by one.
/// (-lower, upper) of x y, rounded up (upward mode; bounds finite).
[[gnu::always_inline]] inline __m128d product_pair(const interval& x, const interval& y) {
  const __m128d xs = opaque_pd(_mm_set_pd(x.upper(), x.lower()));  // (xl, xu)
  const __m128d ys_l = opaque_pd(_mm_set1_pd(y.lower())), ys_u = opaque_pd(_mm_set1_pd(y.upper()));
  const __m128d nxs = _mm_xor_pd(xs, _mm_set1_pd(-0.0));
  const __m128d up = _mm_max_pd(_mm_mul_pd(xs, ys_l), _mm_mul_pd(xs, ys_u));
  const __m128d dn = _mm_max_pd(_mm_mul_pd(nxs, ys_l), _mm_mul_pd(nxs, ys_u));
  return _mm_max_pd(_mm_unpacklo_pd(dn, up), _mm_unpackhi_pd(dn, up));
}
[[gnu::always_inline]] inline interval from_pair(__m128d r) {
  r = opaque_pd(r);
  return interval(-_mm_cvtsd_f64(r), _mm_cvtsd_f64(_mm_unpackhi_pd(r, r)), true);
}
/// a0 b0 + a1 b1 + a2 b2, the bounds of ((a0 b0) + (a1 b1)) + (a2 b2).
inline interval interval_sum_of_products(const interval& a0, const interval& b0, const interval& a1, const interval& b1,
                                const interval& a2, const interval& b2) {
  if (_mm_movemask_pd(_mm_and_pd(_mm_and_pd(ordinary_mask(a0, b0), ordinary_mask(a1, b1)), ordinary_mask(a2, b2))) != 3)
      [[unlikely]]
    return add(add(multiply(a0, b0), multiply(a1, b1)), multiply(a2, b2));
  const interval_rounding rnd;
  const __m128d s = _mm_add_pd(opaque_pd(_mm_add_pd(product_pair(a0, b0), product_pair(a1, b1))), product_pair(a2, b2));
  return from_pair(s);
}
/// a0 b0 - a1 b1, the bounds of (a0 b0) - (a1 b1).
inline interval interval_difference_of_products(const interval& a0, const interval& b0, const interval& a1, const interval& b1) {
  if (_mm_movemask_pd(_mm_and_pd(ordinary_mask(a0, b0), ordinary_mask(a1, b1))) != 3) [[unlikely]]
    return subtract(multiply(a0, b0), multiply(a1, b1));
  const interval_rounding rnd;
  const __m128d q = product_pair(a1, b1);
  return from_pair(_mm_add_pd(product_pair(a0, b0), _mm_shuffle_pd(q, q, 1)));  // + (-upper, lower) of a1 b1
}
}  // namespace appell::detail

namespace boost::numeric {
template <>
[[gnu::always_inline]] inline appell::interval operator*(const appell::interval& x, const appell::interval& y) {
  return appell::detail::multiply(x, y);
}
template <>
[[gnu::always_inline]] inline appell::interval operator+(const appell::interval& x, const appell::interval& y) {
  return appell::detail::add(x, y);
}
template <>
[[gnu::always_inline]] inline appell::interval operator-(const appell::interval& x, const appell::interval& y) {
  return appell::detail::subtract(x, y);
}
}  // namespace boost::numeric

namespace appell {

// Rigorous elementary functions (definitions in src/scalar/interval_functions.cpp).
interval sqrt(const interval& x);
interval sin(const interval& x);
interval cos(const interval& x);
interval tan(const interval& x);
interval atan(const interval& x);
interval exp(const interval& x);
interval log(const interval& x);
interval pown(const interval& x, int n);  ///< x^n for integer n, tight at 0
interval sqr(const interval& x);          ///< x^2, tight at 0 (not x*x)
interval abs(const interval& x);

/// The tightest enclosure of pi.
interval interval_pi();

/// sin, cos, tan, exp, log, atan and sqrt remember their recent results (per
/// thread) so that one evaluation asking for sin(theta) in every differentiated
/// pass pays once.  This starts a new evaluation: earlier results are not reused
/// (so benchmarks of repeated evaluations measure real work).
void forget_interval_function_values();

}  // namespace appell
