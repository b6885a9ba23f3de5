// appell/scalar/arb_backend.hpp -- the Boost.Multiprecision backend of appell::arb: Arb's balls.
//
// Arb (libflint-arb) represents a real number by a ball, a midpoint of any precision and a
// radius of 30 bits, and rounds every operation's midpoint to the precision asked for while
// adding the rounding error and the propagated error to the radius: an enclosure, like MPFI's,
// in about one MPFR operation instead of two (the radius is a cheap 30-bit number).  appell::arb
// is the rigorous scalar that pays least for its proof at 100 bits and more.
//
// The value is opaque here: arb.h (through flint.h) defines `ulong` and `slong` as macros and a
// few dozen others, which no translation unit of the library should inherit.  The backend holds
// the 48 bytes of an arb_struct as words (checked against arb.h in src/scalar/arb_backend.cpp)
// and every operation is a call into src/scalar/arb_backend.cpp, which includes arb.h; code that
// needs Arb's own functions includes appell/scalar/arb_access.hpp (the arb_ptr of a value).
// An arb_struct holds no pointer into itself (its midpoint's limbs are inline up to 128 bits
// and on the heap above), so a value is moved by copying its words and zeroing the source (the
// all-zero words are Arb's exact 0, needing no clear); Eigen's bitwise relocation is safe.
//
// Semantics follow appell::mpfi (mpfi_backend.hpp): a value carries its precision in bits; a
// new value takes the default precision (set_mp_precision_bits, as mpfr and mpfi), a copy the
// source's; an operation rounds its midpoint to the result's precision; compare() and the sign
// throw interval_error when undecided; conversions to built-in numbers use the midpoint.  Where
// a function is undefined somewhere on the ball, the IEEE 1788 rule of restricting to the domain
// holds for sqrt (the part >= 0) and the logarithms (the part > 0), which throw
// appell::domain_error on an empty result; a ball cannot hold a half line, so log of a ball that
// reaches 0 is the whole line (an enclosure, the honest one a ball can give).  Elsewhere Arb's
// answer where it is undefined is the whole line too (never a ball that could miss).
#pragma once

#include <boost/mpl/list.hpp>
#include <boost/multiprecision/number.hpp>
#include <cstdint>
#include <ios>
#include <limits>
#include <string>

#include "appell/errors.hpp"
#include "appell/scalar/mp_default_precision.hpp"
#include "appell/scalar/mpfr_backend.hpp"

namespace appell::mp {

/// The words of an arb_struct (arb.h), opaque here.
struct arb_words {
  std::uint64_t w[6];
};

class arb_backend {
 public:
  using signed_types = boost::mpl::list<long, long long>;
  using unsigned_types = boost::mpl::list<unsigned long, unsigned long long>;
  using float_types = boost::mpl::list<double, long double>;
  using exponent_type = long;

  arb_backend() noexcept : prec_(defaults_.bits()) {}
  arb_backend(const arb_backend& o) : prec_(o.prec_) { set(o); }
  arb_backend(arb_backend&& o) noexcept : v_(o.v_), prec_(o.prec_) { o.v_ = arb_words{}; }
  /// From an MPFR number: exactly (the midpoint holds every bit), at the default precision.
  explicit arb_backend(const mpfr_backend& x) : prec_(defaults_.bits()) { *this = x; }
  ~arb_backend() {
    if (needs_clear()) clear();
  }

  arb_backend& operator=(const arb_backend& o) {
    if (this != &o) {
      prec_ = o.prec_;
      set(o);
    }
    return *this;
  }
  arb_backend& operator=(arb_backend&& o) noexcept {
    swap(o);
    return *this;
  }
  // Built-in numbers: exactly (the precision kept).
  arb_backend& operator=(unsigned long i);
  arb_backend& operator=(long i);
  arb_backend& operator=(unsigned long long i) { return *this = static_cast<unsigned long>(i); }
  arb_backend& operator=(long long i) { return *this = static_cast<long>(i); }
  arb_backend& operator=(double d);  // NaN: the whole line
  arb_backend& operator=(long double d);
  /// A decimal number, or an interval "[a, b]" or "{a,b}" (str()) of decimal numbers or
  /// +-inf (read as mpfi reads them, mpfi_backend.hpp), enclosed; throws std::runtime_error
  /// otherwise.
  arb_backend& operator=(const char* s);
  arb_backend& operator=(const mpfr_backend& x);  // exactly

  void swap(arb_backend& o) noexcept {
    std::swap(v_, o.v_);
    std::swap(prec_, o.prec_);
  }
  /// The value (an exact ball) or "{lower,upper}": with digits <= 0 every bound exactly;
  /// with digits > 0 that many significant digits, the lower bound rounded down, the upper up.
  std::string str(std::streamsize digits, std::ios_base::fmtflags f) const;
  void negate();
  /// -1 (certainly less), 1 (certainly greater), 0 (the same ball); interval_error otherwise.
  int compare(const arb_backend& o) const;
  template <class V>
  int compare(V v) const {
    arb_backend t;
    t = v;
    return compare(t);
  }

  /// The arb_struct (an arb_ptr through appell/scalar/arb_access.hpp).
  void* raw() noexcept { return &v_; }
  const void* raw() const noexcept { return &v_; }
  /// The precision, in bits, to which operations into this value round their midpoint.
  long prec() const noexcept { return prec_; }

  /// Boost's precision interface, in decimal digits.
  static unsigned default_precision() noexcept { return defaults_.digits10(); }
  static void default_precision(unsigned digits10) noexcept { defaults_.set_digits10(digits10); }
  /// appell's interface, in bits (set_mp_precision_bits).
  static unsigned default_bits() noexcept { return static_cast<unsigned>(defaults_.bits()); }
  static void default_bits(unsigned bits) noexcept { defaults_.set_bits(bits); }
  unsigned precision() const noexcept { return precision_default::digits10_of(static_cast<unsigned long>(prec_)); }
  void precision(unsigned digits10) { round_prec(precision_default::bits_of(digits10)); }
  /// Precision p, the value enclosed (its midpoint rounded to p bits, the radius widened).
  void round_prec(long p);
  /// Precision p, the value kept as it is (for a result about to be written).
  void set_prec_keep(long p) noexcept { prec_ = p; }

 private:
  // Whether the words hold anything on the heap: Arb's own tests (arf.h's ARF_HAS_PTR: the
  // midpoint's size field, (limbs << 1) | sign, above 5 when its limbs are on the heap; fmpz.h's
  // COEFF_IS_MPZ: an exponent whose top two bits are 01 is a pointer), on the words of the
  // layout the .cpp checks: 0 the midpoint's exponent, 1 its size, 4 the radius's exponent.
  bool needs_clear() const noexcept {
    const auto is_mpz = [](std::uint64_t e) { return (static_cast<std::int64_t>(e) >> 62) == 1; };
    return is_mpz(v_.w[0]) || static_cast<std::int64_t>(v_.w[1]) > 5 || is_mpz(v_.w[4]);
  }
  void clear() noexcept;
  void set(const arb_backend& o);

  arb_words v_{};  // all zero: Arb's exact 0
  long prec_;

  inline static constinit precision_default defaults_{50};
};

// --- arithmetic (src/scalar/arb_backend.cpp) ----------------------------------------
void eval_add(arb_backend& r, const arb_backend& a, const arb_backend& b);
void eval_add(arb_backend& r, const arb_backend& b);
void eval_subtract(arb_backend& r, const arb_backend& a, const arb_backend& b);
void eval_subtract(arb_backend& r, const arb_backend& b);
void eval_multiply(arb_backend& r, const arb_backend& a, const arb_backend& b);
void eval_multiply(arb_backend& r, const arb_backend& b);
void eval_divide(arb_backend& r, const arb_backend& a, const arb_backend& b);
void eval_divide(arb_backend& r, const arb_backend& b);
void eval_multiply(arb_backend& r, const arb_backend& a, unsigned long b);
void eval_multiply(arb_backend& r, unsigned long b);
void eval_divide(arb_backend& r, const arb_backend& a, unsigned long b);
void eval_divide(arb_backend& r, unsigned long b);
/// s += x y and s -= x y in one rounding (Arb's addmul): jets' and matrices' inner products.
void arb_add_product(arb_backend& s, const arb_backend& x, const arb_backend& y);
void arb_subtract_product(arb_backend& s, const arb_backend& x, const arb_backend& y);
/// r = x[0] y[0] + ... + x[n-1] y[n-1] (n <= 3), the term k subtracted where `subtract` has its bit
/// k, in one call of Arb's arb_dot: each product exact, one rounding of the sum (a 3-term sum at
/// 113 bits in a third of the time of three products and two sums, and a ball as tight or
/// tighter). The precision: the operands' largest (as a product's). r may alias no operand.
void arb_sum_of_products(arb_backend& r, const arb_backend* const* x, const arb_backend* const* y, int n, unsigned subtract);

/// [a, b] from two MPFR numbers (number(lo, hi)), enclosed; a > b or NaN throws.
void assign_components(arb_backend& r, const mpfr_backend& a, const mpfr_backend& b);
template <class A, class B>
void assign_components(arb_backend&, const A&, const B&) = delete;
/// To an MPFR number (static_cast<mpfr>(x)): the midpoint, rounded to nearest.
void generic_interconvert(mpfr_backend& to, const arb_backend& from,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&);

// --- classification and conversion (the midpoint, as mpfi's) --------------------------
bool eval_is_zero(const arb_backend& x);
/// 0 for the exact 0, 1 / -1 when certainly positive / negative; interval_error otherwise.
int eval_get_sign(const arb_backend& x);
int eval_fpclassify(const arb_backend& x);
void eval_convert_to(double* r, const arb_backend& x);
void eval_convert_to(long double* r, const arb_backend& x);
void eval_convert_to(long* r, const arb_backend& x);
void eval_convert_to(unsigned long* r, const arb_backend& x);
void eval_convert_to(long long* r, const arb_backend& x);
void eval_convert_to(unsigned long long* r, const arb_backend& x);

// --- functions ---------------------------------------------------------------------
void eval_sqrt(arb_backend& r, const arb_backend& x);   // domain-restricted
void eval_log(arb_backend& r, const arb_backend& x);    // domain-restricted
void eval_log2(arb_backend& r, const arb_backend& x);   // domain-restricted
void eval_log10(arb_backend& r, const arb_backend& x);  // domain-restricted
void eval_sin(arb_backend& r, const arb_backend& x);
void eval_cos(arb_backend& r, const arb_backend& x);
void eval_abs(arb_backend& r, const arb_backend& x);
void eval_fabs(arb_backend& r, const arb_backend& x);
void eval_exp(arb_backend& r, const arb_backend& x);
void eval_exp2(arb_backend& r, const arb_backend& x);
void eval_tan(arb_backend& r, const arb_backend& x);
void eval_asin(arb_backend& r, const arb_backend& x);
void eval_acos(arb_backend& r, const arb_backend& x);
void eval_atan(arb_backend& r, const arb_backend& x);
void eval_atan2(arb_backend& r, const arb_backend& y, const arb_backend& x);
void eval_hypot(arb_backend& r, const arb_backend& a, const arb_backend& b);
void eval_sinh(arb_backend& r, const arb_backend& x);
void eval_cosh(arb_backend& r, const arb_backend& x);
void eval_tanh(arb_backend& r, const arb_backend& x);
/// b^e: binary powering for an exact integer e, exp(e log b) for b > 0; the whole line where
/// no real power is defined on all of b and e.
void eval_pow(arb_backend& r, const arb_backend& b, const arb_backend& e);
/// floor / ceil of the ball, which must be one integer; interval_error otherwise.
void eval_floor(arb_backend& r, const arb_backend& x);
void eval_ceil(arb_backend& r, const arb_backend& x);
void eval_ldexp(arb_backend& r, const arb_backend& x, long e);
void eval_frexp(arb_backend& r, const arb_backend& x, int* e);
void eval_frexp(arb_backend& r, const arb_backend& x, long* e);

using arb_number = boost::multiprecision::number<arb_backend, boost::multiprecision::et_off>;
arb_number cbrt(const arb_number& x);
arb_number log1p(const arb_number& x);
arb_number expm1(const arb_number& x);
arb_number asinh(const arb_number& x);
arb_number acosh(const arb_number& x);
arb_number atanh(const arb_number& x);

// Boost.Multiprecision's generic versions assume a point number (mpfi_backend.hpp): deleted.
void eval_fmod(arb_backend&, const arb_backend&, const arb_backend&) = delete;
template <class A> void eval_fmod(arb_backend&, const arb_backend&, const A&) = delete;
template <class A> void eval_fmod(arb_backend&, const A&, const arb_backend&) = delete;
void eval_fdim(arb_backend&, const arb_backend&, const arb_backend&) = delete;
template <class A> void eval_fdim(arb_backend&, const arb_backend&, const A&) = delete;
template <class A> void eval_fdim(arb_backend&, const A&, const arb_backend&) = delete;
void eval_remquo(arb_backend&, const arb_backend&, const arb_backend&, int*) = delete;
template <class U, class V> void eval_remainder(arb_backend&, const U&, const V&) = delete;
template <class U, class V> void eval_hypot(arb_backend&, const U&, const V&) = delete;
void eval_trunc(arb_backend&, const arb_backend&) = delete;
void eval_round(arb_backend&, const arb_backend&) = delete;
void eval_modf(arb_backend&, const arb_backend&, arb_backend*) = delete;
void eval_nearbyint(arb_backend&, const arb_backend&) = delete;
void eval_rint(arb_backend&, const arb_backend&) = delete;
long eval_ilogb(const arb_backend&) = delete;
void eval_logb(arb_backend&, const arb_backend&) = delete;

/// The whole line at the default precision, and the special values numeric_limits gives.
arb_number arb_special(int kind);  // 0: NaN (the whole line), 1: +inf, 2: epsilon, 3: max, 4: min

}  // namespace appell::mp

namespace boost::multiprecision {
template <>
struct number_category<appell::mp::arb_backend> : public mpl::int_<number_kind_floating_point> {};
template <>
struct is_interval_number<appell::mp::arb_backend> : public mpl::true_ {};
namespace detail {
template <>
struct is_variable_precision<appell::mp::arb_backend> : public true_type {};
}  // namespace detail
template <expression_template_option ET>
struct component_type<number<appell::mp::arb_backend, ET>> {
  using type = number<appell::mp::mpfr_backend, ET>;
};
}  // namespace boost::multiprecision

namespace std {
// As for appell::mpfi: is_specialized false (Boost.Math's algorithms would treat a ball as a
// point), the values a caller can use real, at the default precision.
template <boost::multiprecision::expression_template_option ET>
class numeric_limits<boost::multiprecision::number<appell::mp::arb_backend, ET>> {
  using number_type = boost::multiprecision::number<appell::mp::arb_backend, ET>;

 public:
  static constexpr bool is_specialized = false;
  static constexpr int digits = 0, digits10 = 0, max_digits10 = 0, radix = 2;
  static constexpr bool is_signed = true, is_integer = false, is_exact = false;
  static constexpr bool has_infinity = true, has_quiet_NaN = true, has_signaling_NaN = false;
  static constexpr float_denorm_style has_denorm = denorm_absent;
  static constexpr bool has_denorm_loss = false, is_iec559 = false, is_bounded = true, is_modulo = false;
  static constexpr bool traps = false, tinyness_before = false;
  static constexpr float_round_style round_style = round_indeterminate;
  static constexpr int min_exponent = 0, min_exponent10 = 0, max_exponent = 0, max_exponent10 = 0;
  static number_type infinity() { return appell::mp::arb_special(1); }
  static number_type quiet_NaN() { return appell::mp::arb_special(0); }
  static number_type signaling_NaN() { return quiet_NaN(); }
  static number_type epsilon() { return appell::mp::arb_special(2); }
  static number_type round_error() { return number_type(1); }
  static number_type(max)() { return appell::mp::arb_special(3); }
  static number_type lowest() { return -(max)(); }
  static number_type(min)() { return appell::mp::arb_special(4); }
  static number_type denorm_min() { return (min)(); }
};
}  // namespace std
