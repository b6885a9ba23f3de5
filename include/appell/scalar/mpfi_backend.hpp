// appell/scalar/mpfi_backend.hpp -- the Boost.Multiprecision backend of appell::mpfi.
//
// An MPFI interval is two MPFR numbers.  Boost's mpfi_float_backend creates each
// value with mpfi_init2, which makes two heap allocations (one per bound) and
// sets the value twice (NaN, then 0); the library's code creates a value per
// operation, so that bookkeeping, not the arithmetic, was most of an mpfi
// evaluation's time (callgrind, Euler's body at 113 bits: malloc, free and
// mpfr_init2 above 60% of the instructions) and twice what an mpfr value costs.
//
// mpfi_backend keeps both bounds' significands inside the value up to
// `inline_bits` bits a bound (320: `--bits 256` computes at 320 with its guard
// bits, scalar_traits<mpfi>::working_bits), and in ONE block above, through MPFR's
// documented custom interface (mpfr_custom_init_set): up to 320 bits a value
// costs no allocation at all, above one, and a new value is set to [+0, -0]
// without a call into MPFR.  An inline value's significand pointers point into
// the object itself; they are re-aimed on access (data(), ensure()) when the
// object was relocated bitwise (Eigen's conservativeResize reallocs its elements).  The bounds remain ordinary MPFR numbers to every
// MPFR and MPFI function, with three exceptions that the MPFR manual states
// for custom numbers: mpfr_set_prec, mpfr_prec_round and mpfr_clear must
// never see them.  Hence:
//   * NEVER call mpfi_set_prec, mpfi_round_prec, mpfi_clear (or mpfr_set_prec,
//     mpfr_prec_round, mpfr_clear on a bound) on data(); use set_prec() and
//     round_prec() below, which reallocate the block.
//   * mpfr_swap of a bound with a number outside this value is forbidden
//     (the two bounds of one value may be swapped: MPFI does, to reorder them).
// The block's owner checks at release that both bounds still point into it,
// and an inline value on access that its bounds are its own two halves (or
// both moved by one relocation), and aborts with a message otherwise (never a
// silent heap corruption).
// MPFI's functions were checked for this (objdump of libmpfi: only
// mpfi_set_prec, mpfi_round_prec and mpfi_swap change or exchange a bound's
// significand, and mpfi_revert_if_needed swaps the two bounds of one value).
//
// Semantics follow Boost's mpfi_float_backend<0> (variable precision):
// a new value takes the default precision, a copy the source's precision,
// assignment from another value takes that value's precision, assignment
// from a built-in number keeps the precision; results of + - * / take the
// largest operand precision; compare() and the sign throw interval_error
// when undecided; conversions to built-in numbers use the midpoint.
// Arithmetic: + - * are MPFI's endpoint formulas done directly
// (mpfi_ops.hpp: bound for bound equal to MPFI's, tests/mpfi_ops.cpp);
// sqrt, log, log2, log10 restrict their argument to the domain (IEEE 1788) and
// throw appell::domain_error on an empty result; sin and cos use sin_cos_mpfi;
// every other function is MPFI's own.
#pragma once

#include <mpfi.h>
#include <mpfr.h>

#include <boost/mpl/list.hpp>
#include <boost/multiprecision/mpfi.hpp>  // BOOST_MULTIPRECISION_MPFI_DEFAULT_PRECISION
#include <boost/multiprecision/mpfr.hpp>
#include <boost/multiprecision/number.hpp>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ios>
#include <stdexcept>
#include <string>

#include "appell/errors.hpp"
#include "appell/scalar/mp_default_precision.hpp"
#include "appell/scalar/mpfi_ops.hpp"
#include "appell/scalar/mpfr_backend.hpp"

namespace appell::mp {

class mpfi_backend {
 public:
  using signed_types = boost::mpl::list<long, long long>;
  using unsigned_types = boost::mpl::list<unsigned long, unsigned long long>;
  using float_types = boost::mpl::list<double, long double>;
  using exponent_type = long;

  /// Significands of at most this many limbs a bound live inside the value (320 bits:
  /// the working precision of the default --bits 256).
  static constexpr int inline_limbs = 5;
  static constexpr mpfr_prec_t inline_bits = inline_limbs * GMP_NUMB_BITS;

  mpfi_backend() { init_zero(defaults_.bits()); }
  mpfi_backend(const mpfi_backend& o) {
    const mpfi_srcptr src = o.data();
    const mpfr_prec_t p = mpfr_get_prec(&src->left);
    if (is_inline(p)) {  // the fields and both significands as they are (what mpfr_set does here)
      v_[0] = *src;
      std::memcpy(limbs_, o.limbs_, sizeof limbs_);
      aim_halves(o.left_is_first_half());
    } else {
      init_zero(p);
      copy_bounds(src);
    }
  }
  // A value moved from keeps its precision and holds [+0, -0].  Above 320 bits it
  // owns no block: data() gives it a new one on first use (so it never reads or
  // writes the block it gave away); its significand pointers are cleared, so that a
  // path that bypassed data() would fault at once instead of aliasing.  (That first
  // use writes even through const access: a moved-from value shared between threads
  // must be assigned before it is read.)
  mpfi_backend(mpfi_backend&& o) noexcept { take(o); }
  /// From an MPFR number (appell's mpfr backend): enclosed at the default precision.
  explicit mpfi_backend(const mpfr_backend& x) {
    init_zero(defaults_.bits());
    mpfi_set_fr(v_, x.data());
  }
  ~mpfi_backend() { release(); }

  mpfi_backend& operator=(const mpfi_backend& o) {
    if (this != &o) {
      const mpfi_srcptr src = o.data();
      reshape(mpfr_get_prec(&src->left));
      copy_bounds(src);
    }
    return *this;
  }
  mpfi_backend& operator=(mpfi_backend&& o) noexcept {
    swap(o);
    return *this;
  }
  // Built-in numbers: each bound set with its own rounding (exact when the
  // precision holds the number), the precision kept.
  mpfi_backend& operator=(unsigned long i) { return set_bounds(i, [](mpfr_ptr b, unsigned long v, mpfr_rnd_t r) { mpfr_set_ui(b, v, r); }); }
  mpfi_backend& operator=(long i) { return set_bounds(i, [](mpfr_ptr b, long v, mpfr_rnd_t r) { mpfr_set_si(b, v, r); }); }
  mpfi_backend& operator=(unsigned long long i) {
    return set_bounds(i, [](mpfr_ptr b, unsigned long long v, mpfr_rnd_t r) { mpfr_set_uj(b, v, r); });
  }
  mpfi_backend& operator=(long long i) { return set_bounds(i, [](mpfr_ptr b, long long v, mpfr_rnd_t r) { mpfr_set_sj(b, v, r); }); }
  mpfi_backend& operator=(double d) {  // NaN gives NaN bounds, as MPFI's mpfi_set_d
    ensure();
    mpfi_set_d(v_, d);
    return *this;
  }
  mpfi_backend& operator=(long double d) { return set_bounds(d, [](mpfr_ptr b, long double v, mpfr_rnd_t r) { mpfr_set_ld(b, v, r); }); }
  /// A decimal number, or an interval "[a, b]" (MPFI) or "{a,b}" (str()) of decimal
  /// numbers or +-inf, enclosed outward; throws std::runtime_error otherwise (NaN,
  /// trailing text, a > b decided on the exact decimals).
  mpfi_backend& operator=(const char* s);
  mpfi_backend& operator=(const mpfr_backend& x) {
    ensure();
    mpfi_set_fr(v_, x.data());
    return *this;
  }

  void swap(mpfi_backend& o) noexcept {
    if (this == &o) return;
    mpfi_backend t(std::move(o));
    o.take(*this);
    take(t);
  }
  /// The value (a point) or "{lower,upper}": with digits <= 0 every bound exactly
  /// (as Boost's backend writes it; operator= reads it back); with digits > 0 that many
  /// significant digits in scientific notation, lower bound rounded down, upper up.
  std::string str(std::streamsize digits, std::ios_base::fmtflags f) const;
  void negate() {  // [a, b] -> [-b, -a]: exact; the bounds trade places within the block
    ensure();
    mpfr_swap(&v_->left, &v_->right);
    mpfr_neg(&v_->left, &v_->left, MPFR_RNDD);
    mpfr_neg(&v_->right, &v_->right, MPFR_RNDU);
  }
  /// -1 (certainly less), 1 (certainly greater), 0 (same bounds); interval_error otherwise.
  int compare(const mpfi_backend& o) const;
  template <class V>
  int compare(V v) const {
    mpfi_backend t;
    t = v;
    return compare(t);
  }

  mpfi_ptr data() {
    ensure();
    return v_;
  }
  mpfi_srcptr data() const {
    ensure();
    return v_;
  }
  mpfr_prec_t prec() const { return mpfr_get_prec(&data()->left); }

  /// Boost's precision interface, in decimal digits.
  static unsigned default_precision() noexcept { return defaults_.digits10(); }
  static void default_precision(unsigned digits10) noexcept { defaults_.set_digits10(digits10); }
  /// appell's interface, in bits (set_mp_precision_bits): new values get exactly `bits` bits.
  static unsigned default_bits() noexcept { return static_cast<unsigned>(defaults_.bits()); }
  static void default_bits(unsigned bits) noexcept { defaults_.set_bits(bits); }
  unsigned precision() const { return precision_default::digits10_of(static_cast<unsigned long>(prec())); }
  void precision(unsigned digits10) {  // keeps the value, enclosed outward
    round_prec(precision_default::bits_of(digits10));
  }
  /// mpfi_set_prec for this backend: precision p, value NaN.
  void set_prec(mpfr_prec_t p);
  /// mpfi_round_prec for this backend: precision p, the value enclosed outward.
  void round_prec(mpfr_prec_t p);

 private:
  static mp_size_t limbs(mpfr_prec_t p) noexcept {
    return static_cast<mp_size_t>((p + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS);
  }
  static bool is_inline(mpfr_prec_t p) noexcept { return p <= inline_bits; }
  // One block for both significands.
  [[gnu::noinline]] static mp_limb_t* new_block(mpfr_prec_t p) {
    void* const b = std::malloc(2 * static_cast<std::size_t>(limbs(p)) * sizeof(mp_limb_t));
    if (!b) throw std::bad_alloc();
    return static_cast<mp_limb_t*>(b);
  }
  // Takes block b (of precision p) as this value's; the value is [+0, -0] (MPFI's zero).
  void adopt(mp_limb_t* b, mpfr_prec_t p) const noexcept {
    block_ = b;
    mpfr_custom_init_set(&v_->left, MPFR_ZERO_KIND, 0, p, b);
    mpfr_custom_init_set(&v_->right, -MPFR_ZERO_KIND, 0, p, b + limbs(p));
  }
  // The inline halves: [+0, -0] of precision p in the value's own limbs.
  void inline_zero(mpfr_prec_t p) const noexcept {
    block_ = nullptr;
    mpfr_custom_init_set(&v_->left, MPFR_ZERO_KIND, 0, p, limbs_);
    mpfr_custom_init_set(&v_->right, -MPFR_ZERO_KIND, 0, p, limbs_ + inline_limbs);
  }
  // A fresh [+0, -0] of precision p (nothing held before).
  void init_zero(mpfr_prec_t p) {
    if (is_inline(p)) inline_zero(p);
    else adopt(new_block(p), p);
  }
  mpfr_prec_t raw_prec() const noexcept { return mpfr_get_prec(&v_->left); }
  // Moves o's value here (this holds nothing); o keeps its precision and holds
  // [+0, -0] (above 320 bits: no block, made again on first use).
  void take(mpfi_backend& o) noexcept {
    v_[0] = o.v_[0];
    const mpfr_prec_t p = raw_prec();
    if (is_inline(p)) {
      const bool left_first = o.left_is_first_half();
      std::memcpy(limbs_, o.limbs_, sizeof limbs_);
      aim_halves(left_first);
      o.inline_zero(p);
    } else {
      block_ = o.block_;
      o.block_ = nullptr;
      o.v_->left._mpfr_d = nullptr;
      o.v_->right._mpfr_d = nullptr;
    }
  }
  // Which half of the limbs the lower bound uses (MPFI may swap the two bounds of one
  // value); decided on the pointers' order, which a bitwise relocation keeps.
  bool left_is_first_half() const noexcept {
    return reinterpret_cast<std::uintptr_t>(mpfr_custom_get_significand(&v_->left)) <
           reinterpret_cast<std::uintptr_t>(mpfr_custom_get_significand(&v_->right));
  }
  void aim_halves(bool left_first) const noexcept {
    mpfr_custom_move(&v_->left, left_first ? limbs_ : limbs_ + inline_limbs);
    mpfr_custom_move(&v_->right, left_first ? limbs_ + inline_limbs : limbs_);
  }
  void release() noexcept {
    if (!block_) return;
    const mp_limb_t* const a = block_;
    const mp_limb_t* const b = block_ + limbs(raw_prec());
    const void* const l = mpfr_custom_get_significand(&v_->left);
    const void* const r = mpfr_custom_get_significand(&v_->right);
    if (!((l == a && r == b) || (l == b && r == a))) ownership_violation();
    std::free(block_);
    block_ = nullptr;
  }
  [[noreturn]] static void ownership_violation() noexcept;
  // Before any access: an inline value's bounds point into this object (re-aimed
  // after a bitwise relocation: both pointers moved by the same distance, one half
  // apart); a value above 320 bits that gave its block away gets a new one.
  // Inlined (every access goes through it); re-aiming and a new block are out of line.
  [[gnu::always_inline]] void ensure() const {
    const mpfr_prec_t p = raw_prec();
    if (is_inline(p)) [[likely]] {
      const void* const l = mpfr_custom_get_significand(&v_->left);
      const void* const r = mpfr_custom_get_significand(&v_->right);
      const mp_limb_t* const h = limbs_ + inline_limbs;
      if ((l == limbs_ && r == h) || (l == h && r == limbs_)) [[likely]] return;
      re_aim(l, r);
    } else if (!block_) {
      adopt(new_block(p), p);
    }
  }
  [[gnu::noinline, gnu::cold]] void re_aim(const void* l, const void* r) const {
    const auto li = reinterpret_cast<std::uintptr_t>(l), ri = reinterpret_cast<std::uintptr_t>(r);
    if ((li > ri ? li - ri : ri - li) != inline_limbs * sizeof(mp_limb_t)) ownership_violation();
    aim_halves(li < ri);
  }
  template <class V, class Set>
  mpfi_backend& set_bounds(V v, Set set) {
    ensure();
    set(&v_->left, v, MPFR_RNDD);
    set(&v_->right, v, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  // Precision p, value unspecified: the storage is kept when it has the room.  A
  // new block is allocated before the old one is freed (strong guarantee).
  void reshape(mpfr_prec_t p) {
    const mpfr_prec_t q = raw_prec();
    if (!is_inline(q) && !block_) {  // moved from above 320 bits: no block to keep or to free
      if (is_inline(p)) inline_zero(p);
      else adopt(new_block(p), p);
      return;
    }
    ensure();  // an inline value re-aimed (release() checks the halves)
    if (q == p) return;
    if (is_inline(p)) {
      release();
      inline_zero(p);
      return;
    }
    if (block_ && limbs(p) == limbs(q)) {
      adopt(block_, p);
      return;
    }
    mp_limb_t* const b = new_block(p);
    release();
    adopt(b, p);
  }
  void copy_bounds(mpfi_srcptr o) noexcept {  // same precision: exact
    mpfr_set(&v_->left, &o->left, MPFR_RNDD);
    mpfr_set(&v_->right, &o->right, MPFR_RNDU);
  }

  // mutable: a moved-from value gets its block on first use, and an inline value's
  // pointers are re-aimed, also through const access.
  mutable mpfi_t v_;
  mutable mp_limb_t* block_ = nullptr;  // the heap block above 320 bits, else null
  mutable mp_limb_t limbs_[2 * inline_limbs];

  // Boost's default for mpfi_float_backend<0> until set_mp_precision_bits is called.
  inline static constinit precision_default defaults_{BOOST_MULTIPRECISION_MPFI_DEFAULT_PRECISION};
};

// --- arithmetic ---------------------------------------------------------------
inline void eval_add(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b) {
  detail::mpfi_add_endpoints(r.data(), a.data(), b.data());
}
inline void eval_add(mpfi_backend& r, const mpfi_backend& b) { eval_add(r, r, b); }
inline void eval_subtract(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b) {
  detail::mpfi_sub_endpoints(r.data(), a.data(), b.data());
}
inline void eval_subtract(mpfi_backend& r, const mpfi_backend& b) { eval_subtract(r, r, b); }
inline void eval_multiply(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b) {
  if (&a == &b) mpfi_sqr(r.data(), a.data());
  else if (!detail::mpfi_mul_endpoints(r.data(), a.data(), b.data())) mpfi_mul(r.data(), a.data(), b.data());
}
inline void eval_multiply(mpfi_backend& r, const mpfi_backend& b) { eval_multiply(r, r, b); }
inline void eval_divide(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b) {
  mpfi_div(r.data(), a.data(), b.data());
}
inline void eval_divide(mpfi_backend& r, const mpfi_backend& b) { eval_divide(r, r, b); }
inline void eval_multiply(mpfi_backend& r, const mpfi_backend& a, unsigned long b) { mpfi_mul_ui(r.data(), a.data(), b); }
inline void eval_multiply(mpfi_backend& r, unsigned long b) { mpfi_mul_ui(r.data(), r.data(), b); }
inline void eval_divide(mpfi_backend& r, const mpfi_backend& a, unsigned long b) { mpfi_div_ui(r.data(), a.data(), b); }
inline void eval_divide(mpfi_backend& r, unsigned long b) { mpfi_div_ui(r.data(), r.data(), b); }

/// [a, b] from two MPFR numbers (number(lo, hi)), rounded outward; a > b throws.
void assign_components(mpfi_backend& r, const mpfr_backend& a,
                       const mpfr_backend& b);
/// Any other pair (strings, doubles): Boost's generic version rounds each to nearest, which
/// need not enclose; write mpfi("[a, b]") or mpfi(mpfr, mpfr) instead.
template <class A, class B>
void assign_components(mpfi_backend&, const A&, const B&) = delete;
/// To another floating-point type (e.g. static_cast<mpfr>(x)): the midpoint, as Boost's backend.
void generic_interconvert(mpfr_backend& to, const mpfi_backend& from,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&);

// --- classification and conversion (midpoint, as Boost's backend) ------------
inline bool eval_is_zero(const mpfi_backend& x) { return detail::mpfi_is_zero(x.data()); }
/// 0 for [0, 0], 1 / -1 when certainly positive / negative; interval_error otherwise.
int eval_get_sign(const mpfi_backend& x);
int eval_fpclassify(const mpfi_backend& x);
void eval_convert_to(double* r, const mpfi_backend& x);
void eval_convert_to(long double* r, const mpfi_backend& x);
void eval_convert_to(long* r, const mpfi_backend& x);
void eval_convert_to(unsigned long* r, const mpfi_backend& x);
void eval_convert_to(long long* r, const mpfi_backend& x);
void eval_convert_to(unsigned long long* r, const mpfi_backend& x);

// --- functions (src/scalar/mpfi_backend.cpp, src/scalar/mpfi_functions.cpp) --
void eval_sqrt(mpfi_backend& r, const mpfi_backend& x);   // domain-restricted
void eval_log(mpfi_backend& r, const mpfi_backend& x);    // domain-restricted
void eval_log2(mpfi_backend& r, const mpfi_backend& x);   // domain-restricted
void eval_log10(mpfi_backend& r, const mpfi_backend& x);  // domain-restricted
void eval_sin(mpfi_backend& r, const mpfi_backend& x);    // sin_cos_mpfi
void eval_cos(mpfi_backend& r, const mpfi_backend& x);    // sin_cos_mpfi
void eval_abs(mpfi_backend& r, const mpfi_backend& x);
void eval_fabs(mpfi_backend& r, const mpfi_backend& x);
void eval_exp(mpfi_backend& r, const mpfi_backend& x);
void eval_exp2(mpfi_backend& r, const mpfi_backend& x);
void eval_tan(mpfi_backend& r, const mpfi_backend& x);
void eval_asin(mpfi_backend& r, const mpfi_backend& x);
void eval_acos(mpfi_backend& r, const mpfi_backend& x);
void eval_atan(mpfi_backend& r, const mpfi_backend& x);
void eval_atan2(mpfi_backend& r, const mpfi_backend& y, const mpfi_backend& x);
void eval_hypot(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b);  // MPFI's
void eval_sinh(mpfi_backend& r, const mpfi_backend& x);
void eval_cosh(mpfi_backend& r, const mpfi_backend& x);
void eval_tanh(mpfi_backend& r, const mpfi_backend& x);
/// b^e = exp(e log b) for b > 0; integer e for b < 0; NaN bounds where undefined.
void eval_pow(mpfi_backend& r, const mpfi_backend& b, const mpfi_backend& e);
/// floor / ceil of both bounds; interval_error where they differ.
void eval_floor(mpfi_backend& r, const mpfi_backend& x);
void eval_ceil(mpfi_backend& r, const mpfi_backend& x);
void eval_ldexp(mpfi_backend& r, const mpfi_backend& x, long e);
void eval_frexp(mpfi_backend& r, const mpfi_backend& x, int* e);
void eval_frexp(mpfi_backend& r, const mpfi_backend& x, long* e);

// MPFI's functions where Boost.Multiprecision has none for a backend (number-level, as Boost's
// mpfi.hpp has them): cbrt, log1p, expm1, asinh, acosh, atanh.
using mpfi_number = boost::multiprecision::number<mpfi_backend, boost::multiprecision::et_off>;
mpfi_number cbrt(const mpfi_number& x);
mpfi_number log1p(const mpfi_number& x);
mpfi_number expm1(const mpfi_number& x);
mpfi_number asinh(const mpfi_number& x);
mpfi_number acosh(const mpfi_number& x);
mpfi_number atanh(const mpfi_number& x);

// Boost.Multiprecision's generic versions of these assume a point number and
// are wrong on intervals (fmod([1, inf], 3) = 0, trunc([1.5, inf]) = [1.5, inf],
// logb([0.9, 1.1]) = 0, ...): deleted, so that a use fails to compile instead.
void eval_fmod(mpfi_backend&, const mpfi_backend&, const mpfi_backend&) = delete;
template <class A> void eval_fmod(mpfi_backend&, const mpfi_backend&, const A&) = delete;
template <class A> void eval_fmod(mpfi_backend&, const A&, const mpfi_backend&) = delete;
void eval_fdim(mpfi_backend&, const mpfi_backend&, const mpfi_backend&) = delete;
template <class A> void eval_fdim(mpfi_backend&, const mpfi_backend&, const A&) = delete;
template <class A> void eval_fdim(mpfi_backend&, const A&, const mpfi_backend&) = delete;
void eval_remquo(mpfi_backend&, const mpfi_backend&, const mpfi_backend&, int*) = delete;
template <class U, class V> void eval_remainder(mpfi_backend&, const U&, const V&) = delete;
template <class U, class V> void eval_hypot(mpfi_backend&, const U&, const V&) = delete;  // but MPFI's, above
void eval_trunc(mpfi_backend&, const mpfi_backend&) = delete;
void eval_round(mpfi_backend&, const mpfi_backend&) = delete;
void eval_modf(mpfi_backend&, const mpfi_backend&, mpfi_backend*) = delete;
void eval_nearbyint(mpfi_backend&, const mpfi_backend&) = delete;
void eval_rint(mpfi_backend&, const mpfi_backend&) = delete;
long eval_ilogb(const mpfi_backend&) = delete;
void eval_logb(mpfi_backend&, const mpfi_backend&) = delete;

}  // namespace appell::mp

namespace boost::multiprecision {
template <>
struct number_category<appell::mp::mpfi_backend> : public mpl::int_<number_kind_floating_point> {};
template <>
struct is_interval_number<appell::mp::mpfi_backend> : public mpl::true_ {};
namespace detail {
template <>
struct is_variable_precision<appell::mp::mpfi_backend> : public true_type {};
}  // namespace detail
// mpfi(lower, upper) from two mpfr numbers (assign_components above).
template <expression_template_option ET>
struct component_type<number<appell::mp::mpfi_backend, ET>> {
  using type = number<appell::mp::mpfr_backend, ET>;
};
}  // namespace boost::multiprecision

namespace std {
// Like Boost's for mpfi_float_backend<0>, is_specialized stays false: Boost.Math's
// generic algorithms (tgamma, erf, ...) would treat an interval as a point, and
// refuse such a type at compile time.  Unlike Boost's (which answers 0 to
// everything), the values a caller can use are real: infinity, NaN, epsilon,
// max, min at the default precision (variable precision: digits is 0).
template <boost::multiprecision::expression_template_option ET>
class numeric_limits<boost::multiprecision::number<appell::mp::mpfi_backend, ET>> {
  using number_type = boost::multiprecision::number<appell::mp::mpfi_backend, ET>;
  template <class F>
  static number_type both(F set) {  // the point interval [v, v] of a representable v
    number_type r;
    set(&r.backend().data()->left);
    set(&r.backend().data()->right);
    return r;
  }

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
  static number_type infinity() { return both([](mpfr_ptr b) { mpfr_set_inf(b, 1); }); }
  static number_type quiet_NaN() { return both([](mpfr_ptr b) { mpfr_set_nan(b); }); }
  static number_type signaling_NaN() { return quiet_NaN(); }
  static number_type epsilon() {  // 2^(1-p)
    return both([](mpfr_ptr b) { mpfr_set_ui_2exp(b, 1, 1 - mpfr_get_prec(b), MPFR_RNDN); });
  }
  static number_type round_error() { return both([](mpfr_ptr b) { mpfr_set_ui(b, 1, MPFR_RNDN); }); }
  static number_type(max)() {
    return both([](mpfr_ptr b) {
      mpfr_set_inf(b, 1);
      mpfr_nextbelow(b);
    });
  }
  static number_type lowest() { return -(max)(); }
  static number_type(min)() {
    return both([](mpfr_ptr b) {
      mpfr_set_zero(b, 1);
      mpfr_nextabove(b);
    });
  }
  static number_type denorm_min() { return (min)(); }
};
}  // namespace std
