// appell/scalar/mpfi_backend.hpp -- the Boost.Multiprecision backend of appell::mpfi.
//
// An MPFI interval is two MPFR numbers.  Boost's mpfi_float_backend creates each
// value with mpfi_init2, which makes two heap allocations (one per bound) and
// sets the value twice (NaN, then 0); the library's code creates a value per
// operation, so that bookkeeping, not the arithmetic, was most of an mpfi
// evaluation's time (callgrind, euler_body at 113 bits: malloc, free and
// mpfr_init2 above 60% of the instructions) and twice what an mpfr value costs.
//
// mpfi_backend keeps both bounds' significands in ONE block, through MPFR's
// documented custom interface (mpfr_custom_init_set): a value costs one
// allocation, as an mpfr value does, and a new value is set to [+0, -0]
// without a call into MPFR.  The bounds remain ordinary MPFR numbers to every
// MPFR and MPFI function, with three exceptions that the MPFR manual states
// for custom numbers: mpfr_set_prec, mpfr_prec_round and mpfr_clear must
// never see them.  Hence:
//   * NEVER call mpfi_set_prec, mpfi_round_prec, mpfi_clear (or mpfr_set_prec,
//     mpfr_prec_round, mpfr_clear on a bound) on data(); use set_prec() and
//     round_prec() below, which reallocate the block.
//   * mpfr_swap of a bound with a number outside this value is forbidden
//     (the two bounds of one value may be swapped: MPFI does, to reorder them).
// The block's owner checks at release that both bounds still point into it,
// and aborts with a message otherwise (never a silent heap corruption).
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
#include <cstdlib>
#include <ios>
#include <stdexcept>
#include <string>

#include "appell/scalar/mpfi_ops.hpp"

namespace appell::mp {

/// Thrown by undecided comparisons and signs of intervals (as Boost's backend does).
struct interval_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class mpfi_backend {
 public:
  using signed_types = boost::mpl::list<long, long long>;
  using unsigned_types = boost::mpl::list<unsigned long, unsigned long long>;
  using float_types = boost::mpl::list<double, long double>;
  using exponent_type = long;

  mpfi_backend() { allocate(default_bits_); }
  mpfi_backend(const mpfi_backend& o) {
    allocate(o.prec());
    copy_bounds(o);
  }
  mpfi_backend(mpfi_backend&& o) noexcept : block_(o.block_) {
    v_[0] = o.v_[0];
    o.block_ = nullptr;
  }
  /// From an MPFR number (Boost's mpfr backend): enclosed at the default precision.
  mpfi_backend(const boost::multiprecision::backends::mpfr_float_backend<0>& x) {
    allocate(default_bits_);
    mpfi_set_fr(v_, x.data());
  }
  ~mpfi_backend() { release(); }

  mpfi_backend& operator=(const mpfi_backend& o) {
    if (this != &o) {
      reshape(o.prec());
      copy_bounds(o);
    }
    return *this;
  }
  mpfi_backend& operator=(mpfi_backend&& o) noexcept {
    swap(o);
    return *this;
  }
  mpfi_backend& operator=(unsigned long i) {
    ensure();
    mpfr_set_ui(&v_->left, i, MPFR_RNDD);
    mpfr_set_ui(&v_->right, i, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  mpfi_backend& operator=(long i) {
    ensure();
    mpfr_set_si(&v_->left, i, MPFR_RNDD);
    mpfr_set_si(&v_->right, i, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  mpfi_backend& operator=(unsigned long long i) {
    ensure();
    mpfr_set_uj(&v_->left, i, MPFR_RNDD);
    mpfr_set_uj(&v_->right, i, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  mpfi_backend& operator=(long long i) {
    ensure();
    mpfr_set_sj(&v_->left, i, MPFR_RNDD);
    mpfr_set_sj(&v_->right, i, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  mpfi_backend& operator=(double d) {
    ensure();
    mpfi_set_d(v_, d);
    return *this;
  }
  mpfi_backend& operator=(long double d) {
    ensure();
    mpfr_set_ld(&v_->left, d, MPFR_RNDD);
    mpfr_set_ld(&v_->right, d, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(v_);
    return *this;
  }
  /// A decimal number or MPFI's "[a, b]", enclosed outward; throws std::runtime_error otherwise.
  mpfi_backend& operator=(const char* s);
  mpfi_backend& operator=(const boost::multiprecision::backends::mpfr_float_backend<0>& x) {
    ensure();
    mpfi_set_fr(v_, x.data());
    return *this;
  }

  void swap(mpfi_backend& o) noexcept {
    __mpfi_struct t = v_[0];
    v_[0] = o.v_[0];
    o.v_[0] = t;
    mp_limb_t* b = block_;
    block_ = o.block_;
    o.block_ = b;
  }
  /// The value (a point) or "{lower,upper}", as Boost's backend writes it.
  std::string str(std::streamsize digits, std::ios_base::fmtflags f) const;
  void negate() noexcept {  // [a, b] -> [-b, -a]: exact; the bounds trade places within the block
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

  mpfi_ptr data() noexcept { return v_; }
  mpfi_srcptr data() const noexcept { return v_; }
  mpfr_prec_t prec() const noexcept { return mpfr_get_prec(&v_->left); }

  /// Boost's precision interface, in decimal digits.
  static unsigned default_precision() noexcept { return default_digits10_; }
  static void default_precision(unsigned digits10) noexcept {
    default_digits10_ = digits10;
    default_bits_ = static_cast<mpfr_prec_t>(boost::multiprecision::detail::digits10_2_2(digits10));
  }
  unsigned precision() const noexcept {
    return static_cast<unsigned>(boost::multiprecision::detail::digits2_2_10(static_cast<unsigned long>(prec())));
  }
  void precision(unsigned digits10) {  // keeps the value, enclosed outward
    round_prec(static_cast<mpfr_prec_t>(boost::multiprecision::detail::digits10_2_2(digits10)));
  }
  /// The default precision in bits.
  static mpfr_prec_t default_bits() noexcept { return default_bits_; }

  /// mpfi_set_prec for this backend: precision p, value NaN.
  void set_prec(mpfr_prec_t p);
  /// mpfi_round_prec for this backend: precision p, the value enclosed outward.
  void round_prec(mpfr_prec_t p);

 private:
  static mp_size_t limbs(mpfr_prec_t p) noexcept {
    return static_cast<mp_size_t>((p + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS);
  }
  // One block for both significands; the value is [+0, -0] (MPFI's zero).
  void allocate(mpfr_prec_t p) {
    const mp_size_t n = limbs(p);
    block_ = static_cast<mp_limb_t*>(std::malloc(2 * static_cast<std::size_t>(n) * sizeof(mp_limb_t)));
    if (!block_) throw std::bad_alloc();
    mpfr_custom_init_set(&v_->left, MPFR_ZERO_KIND, 0, p, block_);
    mpfr_custom_init_set(&v_->right, -MPFR_ZERO_KIND, 0, p, block_ + n);
  }
  void release() noexcept {
    if (!block_) return;
    const mp_limb_t* const a = block_;
    const mp_limb_t* const b = block_ + limbs(prec());
    const void* const l = mpfr_custom_get_significand(&v_->left);
    const void* const r = mpfr_custom_get_significand(&v_->right);
    if (!((l == a && r == b) || (l == b && r == a))) ownership_violation();
    std::free(block_);
    block_ = nullptr;
  }
  [[noreturn]] static void ownership_violation() noexcept;
  void ensure() {
    if (!block_) allocate(default_bits_);
  }
  // Precision p, value unspecified: the block is kept when it has the room.
  void reshape(mpfr_prec_t p) {
    if (block_ && prec() == p) return;
    if (block_ && limbs(p) == limbs(prec())) {
      mpfr_custom_init_set(&v_->left, MPFR_ZERO_KIND, 0, p, block_);
      mpfr_custom_init_set(&v_->right, -MPFR_ZERO_KIND, 0, p, block_ + limbs(p));
      return;
    }
    release();
    allocate(p);
  }
  void copy_bounds(const mpfi_backend& o) noexcept {  // same precision: exact
    mpfr_set(&v_->left, &o.v_->left, MPFR_RNDD);
    mpfr_set(&v_->right, &o.v_->right, MPFR_RNDU);
  }

  mpfi_t v_;
  mp_limb_t* block_ = nullptr;

  // Boost's default for mpfi_float_backend<0> until set_mp_precision_bits is called.
  inline static unsigned default_digits10_ = BOOST_MULTIPRECISION_MPFI_DEFAULT_PRECISION;
  inline static mpfr_prec_t default_bits_ = static_cast<mpfr_prec_t>(
      boost::multiprecision::detail::digits10_2_2(BOOST_MULTIPRECISION_MPFI_DEFAULT_PRECISION));
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

// --- classification and conversion (midpoint, as Boost's backend) ------------
inline bool eval_is_zero(const mpfi_backend& x) noexcept { return detail::mpfi_is_zero(x.data()); }
/// 0 for [0, 0], 1 / -1 when certainly positive / negative; interval_error otherwise.
int eval_get_sign(const mpfi_backend& x);
int eval_fpclassify(const mpfi_backend& x) noexcept;
void eval_convert_to(double* r, const mpfi_backend& x) noexcept;
void eval_convert_to(long double* r, const mpfi_backend& x) noexcept;
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
}  // namespace boost::multiprecision
