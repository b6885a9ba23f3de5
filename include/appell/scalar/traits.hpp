// appell/scalar/traits.hpp -- one trait per scalar: what library code may ask
// of a number without knowing its type.
//
//   scalar_traits<T>::name          CLI name ("double", "interval", ...)
//   is_interval / is_rigorous       whether T is a set that encloses the truth
//   bound_type                      type of lower()/upper()/mid() (double for
//                                   interval, mpfr for mpfi, T for point types)
//   lower upper mid width           width rounded up; 0 for point types
//   hull                            smallest T holding both (point: undefined -> interval only)
//   precision_bits()                significand bits of a value made now
//   to_mpfr(x, lo, hi)              the bounds of x, exactly, as MPFR numbers
//   from_mpfr(v)                    v rounded to nearest (point) / enclosed (interval)
//   from_mpfr_bounds(lo, hi)        interval types: the enclosure of [lo, hi]
//   runtime_precision               precision chosen at run time (mpfr, mpfi: --bits)
//   working_bits(p)                 the evaluation policy's working precision for
//                                   p-bit results (guard bits: mpfi; p otherwise)
//   needs_upward_rounding           interval<double>: evaluations run in one
//                                   upward-rounding scope
// The evaluation policy built on them (evaluation_scope, consistent_with_zero)
// is in scalar/policy.hpp.
//
// Library code never compares interval values with < or ==: an undecided
// comparison throws (mp::interval_error for mpfi).  It uses the predicates at the end of
// this file (certainly_positive, possibly_zero, ...), which are decided on the
// bounds and therefore safe for every scalar.
#pragma once

#include <mpfr.h>

#include <string>
#include <type_traits>

#include "appell/scalar/types.hpp"

namespace appell {

template <class T>
struct scalar_traits;  // specialised below for the eight standard scalars

template <class T>
concept Scalar = requires { scalar_traits<T>::name; };

/// An owned mpfr_t (RAII), used at the seams to MPFR.
class mpfr_value {
 public:
  explicit mpfr_value(mpfr_prec_t prec = 53) { mpfr_init2(v_, prec); }
  ~mpfr_value() { mpfr_clear(v_); }
  mpfr_value(const mpfr_value& o) {
    mpfr_init2(v_, mpfr_get_prec(o.v_));
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  mpfr_value& operator=(const mpfr_value& o) {
    if (this != &o) {
      mpfr_set_prec(v_, mpfr_get_prec(o.v_));
      mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    return *this;
  }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  operator mpfr_ptr() { return v_; }
  operator mpfr_srcptr() const { return v_; }

 private:
  mpfr_t v_;
};

// --- exact bridges to MPFR (src/scalar/decimal.cpp) -------------------------
// to_mpfr_exact: sets `out` (its precision adjusted as needed) to x exactly.
void to_mpfr_exact(double x, mpfr_value& out);
void to_mpfr_exact(long double x, mpfr_value& out);
void to_mpfr_exact(const dd& x, mpfr_value& out);
void to_mpfr_exact(const float128& x, mpfr_value& out);
void to_mpfr_exact(const mpfr& x, mpfr_value& out);
// round_to_*: v rounded to the format in direction rnd (IEEE subnormals honoured).
double round_to_double(mpfr_srcptr v, mpfr_rnd_t rnd);
long double round_to_long_double(mpfr_srcptr v, mpfr_rnd_t rnd);
dd round_to_dd(mpfr_srcptr v, mpfr_rnd_t rnd);
float128 round_to_float128(mpfr_srcptr v, mpfr_rnd_t rnd);
mpfr round_to_mpfr(mpfr_srcptr v, mpfr_rnd_t rnd);  // at the current mp precision

// --- point types ------------------------------------------------------------
template <class T>
struct point_traits_base {
  static constexpr bool is_interval = false;
  static constexpr bool is_rigorous = false;
  static constexpr bool runtime_precision = false;
  static constexpr bool needs_upward_rounding = false;
  static unsigned working_bits(unsigned p) { return p; }
  using bound_type = T;
  static T lower(const T& x) { return x; }
  static T upper(const T& x) { return x; }
  static T mid(const T& x) { return x; }
  static T width(const T&) { return T(0); }
  static void to_mpfr(const T& x, mpfr_value& lo, mpfr_value& hi) {
    to_mpfr_exact(x, lo);
    hi = lo;
  }
};

template <>
struct scalar_traits<double> : point_traits_base<double> {
  static constexpr const char* name = "double";
  static unsigned precision_bits() { return 53; }
  static double from_mpfr(mpfr_srcptr v) { return round_to_double(v, MPFR_RNDN); }
};

template <>
struct scalar_traits<long double> : point_traits_base<long double> {
  static constexpr const char* name = "long-double";
  static unsigned precision_bits() { return 64; }
  static long double from_mpfr(mpfr_srcptr v) { return round_to_long_double(v, MPFR_RNDN); }
};

template <>
struct scalar_traits<dd> : point_traits_base<dd> {
  static constexpr const char* name = "dd";
  static unsigned precision_bits() { return 106; }  // hi + lo, each 53 bits
  static dd from_mpfr(mpfr_srcptr v) { return round_to_dd(v, MPFR_RNDN); }
};

template <>
struct scalar_traits<float128> : point_traits_base<float128> {
  static constexpr const char* name = "float128";
  static unsigned precision_bits() { return 113; }
  static float128 from_mpfr(mpfr_srcptr v) { return round_to_float128(v, MPFR_RNDN); }
};

template <>
struct scalar_traits<mpfr> : point_traits_base<mpfr> {
  static constexpr const char* name = "mpfr";
  static constexpr bool runtime_precision = true;
  /// The bits new values get: exactly those asked for (appell's own backend,
  /// mpfr_backend.hpp; Boost 1.74's mpfr_float gave 113 -> 114).
  static unsigned precision_bits() { return mpfr_precision_bits(); }
  static mpfr from_mpfr(mpfr_srcptr v) { return round_to_mpfr(v, MPFR_RNDN); }
};

// --- interval types ---------------------------------------------------------
template <>
struct scalar_traits<interval> {
  static constexpr const char* name = "interval";
  static constexpr bool is_interval = true;
  static constexpr bool is_rigorous = true;
  static constexpr bool runtime_precision = false;
  static constexpr bool needs_upward_rounding = true;
  static unsigned working_bits(unsigned p) { return p; }
  using bound_type = double;
  static unsigned precision_bits() { return 53; }
  static double lower(const interval& x) { return x.lower(); }
  static double upper(const interval& x) { return x.upper(); }
  static double mid(const interval& x) { return boost::numeric::median(x); }
  static double width(const interval& x) { return boost::numeric::width(x); }  // rounded up
  static interval hull(const interval& a, const interval& b) { return boost::numeric::hull(a, b); }
  static interval from_bounds(double lo, double hi) { return interval(lo, hi); }
  static void to_mpfr(const interval& x, mpfr_value& lo, mpfr_value& hi) {
    to_mpfr_exact(x.lower(), lo);
    to_mpfr_exact(x.upper(), hi);
  }
  static interval from_mpfr(mpfr_srcptr v) {
    return interval(round_to_double(v, MPFR_RNDD), round_to_double(v, MPFR_RNDU));
  }
  static interval from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi) {
    return interval(round_to_double(lo, MPFR_RNDD), round_to_double(hi, MPFR_RNDU));
  }
};

/// The bounds of an mpfi value as mpfr numbers at the value's own precision.
mpfr mpfi_lower(const mpfi& x);
mpfr mpfi_upper(const mpfi& x);
mpfr mpfi_mid(const mpfi& x);
mpfr mpfi_width(const mpfi& x);  // rounded up
mpfi mpfi_from_bounds(const mpfr& lo, const mpfr& hi);
mpfi mpfi_from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi);

template <>
struct scalar_traits<mpfi> {
  static constexpr const char* name = "mpfi";
  static constexpr bool is_interval = true;
  static constexpr bool is_rigorous = true;
  static constexpr bool runtime_precision = true;
  static constexpr bool needs_upward_rounding = false;
  /// Guard bits: the dependency effects of naive interval evaluation, which
  /// magnify the input enclosures' width by up to ~10^3 on the paper scenes,
  /// are paid in at least 12 extra bits and the rest of the last 64-bit limb,
  /// which costs nothing (MPFR works limb by limb): 113 bits work at 128, 256 at 320.
  static unsigned working_bits(unsigned p) { return (p + 12 + 63) / 64 * 64; }
  using bound_type = mpfr;
  static unsigned precision_bits() { return mp_precision_bits(); }
  static mpfr lower(const mpfi& x) { return mpfi_lower(x); }
  static mpfr upper(const mpfi& x) { return mpfi_upper(x); }
  static mpfr mid(const mpfi& x) { return mpfi_mid(x); }
  static mpfr width(const mpfi& x) { return mpfi_width(x); }
  static mpfi hull(const mpfi& a, const mpfi& b) {
    mpfi r;
    mpfi_union(r.backend().data(), a.backend().data(), b.backend().data());
    return r;
  }
  static mpfi from_bounds(const mpfr& lo, const mpfr& hi) { return mpfi_from_bounds(lo, hi); }
  static void to_mpfr(const mpfi& x, mpfr_value& lo, mpfr_value& hi) {
    mpfr_set_prec(lo, mpfi_get_prec(x.backend().data()));
    mpfr_set_prec(hi, mpfi_get_prec(x.backend().data()));
    mpfi_get_left(lo, x.backend().data());   // exact: same precision
    mpfi_get_right(hi, x.backend().data());
  }
  static mpfi from_mpfr(mpfr_srcptr v) { return mpfi_from_mpfr_bounds(v, v); }
  static mpfi from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi) {
    return mpfi_from_mpfr_bounds(lo, hi);
  }
};

/// The bounds and parts of an arb ball as MPFR numbers (src/scalar/arb_backend.cpp): lower
/// rounded down and upper rounded up to the value's precision, the midpoint to nearest, the
/// width (twice the radius) rounded up.
mpfr ball_lower(const arb& x);
mpfr ball_upper(const arb& x);
mpfr ball_mid(const arb& x);
mpfr ball_width(const arb& x);
arb ball_from_bounds(const mpfr& lo, const mpfr& hi);
arb ball_from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi);
/// x's bounds exactly (each MPFR number's precision set to hold them: the ball's ends may need
/// more bits than its midpoint has; format.hpp prints them rounded outward to the midpoint's).
void ball_to_mpfr(const arb& x, mpfr_value& lo, mpfr_value& hi);
arb ball_hull(const arb& a, const arb& b);
/// A ball holding the intersection of a and b; certification_error where they are disjoint
/// (two enclosures of one number never are).
arb ball_intersect(const arb& a, const arb& b);
bool ball_is_finite(const arb& x);
bool ball_is_exact(const arb& x, long value);  // the point `value`
/// The same ball, word for word (midpoint and radius).
bool ball_identical(const arb& a, const arb& b);

template <>
struct scalar_traits<arb> {
  static constexpr const char* name = "arb";
  static constexpr bool is_interval = true;
  static constexpr bool is_rigorous = true;
  static constexpr bool runtime_precision = true;
  static constexpr bool needs_upward_rounding = false;
  /// The guard bits of mpfi (the same dependency effects): 113 bits work at 128, 256 at 320.
  static unsigned working_bits(unsigned p) { return (p + 12 + 63) / 64 * 64; }
  using bound_type = mpfr;
  static unsigned precision_bits() { return mp_precision_bits(); }
  static mpfr lower(const arb& x) { return ball_lower(x); }
  static mpfr upper(const arb& x) { return ball_upper(x); }
  static mpfr mid(const arb& x) { return ball_mid(x); }
  static mpfr width(const arb& x) { return ball_width(x); }
  static arb hull(const arb& a, const arb& b) { return ball_hull(a, b); }
  static arb from_bounds(const mpfr& lo, const mpfr& hi) { return ball_from_bounds(lo, hi); }
  static void to_mpfr(const arb& x, mpfr_value& lo, mpfr_value& hi) { ball_to_mpfr(x, lo, hi); }
  static arb from_mpfr(mpfr_srcptr v) { return ball_from_mpfr_bounds(v, v); }
  static arb from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi) { return ball_from_mpfr_bounds(lo, hi); }
};

template <class T>
inline constexpr bool is_interval_v = scalar_traits<T>::is_interval;

template <class T>
using bound_t = typename scalar_traits<T>::bound_type;

// --- accessors as free functions --------------------------------------------
template <Scalar T> bound_t<T> lower(const T& x) { return scalar_traits<T>::lower(x); }
template <Scalar T> bound_t<T> upper(const T& x) { return scalar_traits<T>::upper(x); }
template <Scalar T> bound_t<T> mid(const T& x) { return scalar_traits<T>::mid(x); }
template <Scalar T> bound_t<T> width(const T& x) { return scalar_traits<T>::width(x); }

// --- predicates: decided on bounds, safe for every scalar ---------------------
template <Scalar T> bool certainly_positive(const T& x) { return lower(x) > 0; }
template <Scalar T> bool certainly_negative(const T& x) { return upper(x) < 0; }
template <Scalar T> bool certainly_nonnegative(const T& x) { return lower(x) >= 0; }
template <Scalar T> bool certainly_nonpositive(const T& x) { return upper(x) <= 0; }
template <Scalar T> bool possibly_zero(const T& x) { return lower(x) <= 0 && upper(x) >= 0; }
template <Scalar T> bool possibly_positive(const T& x) { return upper(x) > 0; }
template <Scalar T> bool possibly_negative(const T& x) { return lower(x) < 0; }
template <Scalar T> bool certainly_less(const T& a, const T& b) { return upper(a) < lower(b); }
template <Scalar T> bool certainly_less_equal(const T& a, const T& b) { return upper(a) <= lower(b); }
template <Scalar T> bool possibly_less(const T& a, const T& b) { return lower(a) < upper(b); }
/// x is exactly 0 (the point 0, or [0, 0]): a structural zero that a computation may skip.
template <Scalar T> bool exactly_zero(const T& x) {
  if constexpr (std::is_same_v<T, mpfi>) return detail::mpfi_is_zero(x.backend().data());  // no bound copies
  else if constexpr (std::is_same_v<T, arb>) return ball_is_exact(x, 0);
  else if constexpr (!scalar_traits<T>::is_interval) return x == 0;
  else return lower(x) == 0 && upper(x) == 0;
}
/// x is exactly 1 (the point 1, or [1, 1]).
template <Scalar T> bool exactly_one(const T& x) {
  if constexpr (std::is_same_v<T, mpfi>)
    return mpfr_cmp_ui(&x.backend().data()->left, 1) == 0 && mpfr_cmp_ui(&x.backend().data()->right, 1) == 0;
  else if constexpr (std::is_same_v<T, arb>) return ball_is_exact(x, 1);
  else if constexpr (!scalar_traits<T>::is_interval) return x == 1;
  else return lower(x) == 1 && upper(x) == 1;
}
/// Both bounds finite (point types: the value is finite).
template <Scalar T> bool is_finite(const T& x) {
  using std::isfinite;
  if constexpr (std::is_same_v<T, dd>) return x.isfinite();
  else if constexpr (std::is_same_v<T, mpfi>) {
    return mpfi_bounded_p(x.backend().data()) != 0;
  } else if constexpr (std::is_same_v<T, arb>) {
    return ball_is_finite(x);
  } else if constexpr (std::is_same_v<bound_t<T>, mpfr>) {
    return mpfr_number_p(lower(x).backend().data()) && mpfr_number_p(upper(x).backend().data());
  } else if constexpr (std::is_same_v<bound_t<T>, float128>) {
    return boost::multiprecision::isfinite(lower(x)) && boost::multiprecision::isfinite(upper(x));
  } else {
    return isfinite(lower(x)) && isfinite(upper(x));
  }
}

/// A double near x (its midpoint for intervals): for choices and messages, never for results.
template <Scalar T> double approx_double(const T& x) {
  if constexpr (std::is_same_v<T, dd>) return x.x[0];
  else if constexpr (std::is_same_v<bound_t<T>, dd>) return mid(x).x[0];  // a dual of dd
  else return static_cast<double>(mid(x));
}

/// x contains the real number v (given exactly as an MPFR value).
template <Scalar T>
bool contains(const T& x, mpfr_srcptr v) {
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(x, lo, hi);
  return mpfr_lessequal_p(lo, v) && mpfr_lessequal_p(v, hi);
}

}  // namespace appell
