// appell/scalar/mpfr_backend.hpp -- the Boost.Multiprecision backend of appell::mpfr.
//
// Why not Boost's mpfr_float_backend<0>.  Two costs that every precision study paid:
//  * bits: Boost 1.74 sets a variable precision in decimal digits, so `--bits 113` gave
//    114 bits and `--bits 256` 257; a study that sets mpfr against float128 compared
//    114 bits with 113.  Here new values get exactly the bits asked for.
//  * the heap: every value (and the library makes one per operation) was an mpfr_init2,
//    a malloc, and an mpfr_clear, a free; at 256 bits malloc and free were about half of
//    a Taylor step's time (perf, the cone's long-horizon reference).  Here a value of at
//    most `inline_bits` bits keeps its significand inside the object, through MPFR's
//    documented custom interface (mpfr_custom_init_set, the interface MPFR offers for
//    numbers on a stack): making, copying and destroying one touches no heap.  Above
//    `inline_bits` the significand is one block from GMP's allocation functions (as
//    MPFR's own numbers).
//
// The significand pointer of an inline value points into the object itself.  The pointer
// is therefore re-aimed on every access (data(): one comparison), which keeps a value
// valid after a bitwise relocation (Eigen's conservativeResize moves its elements with
// realloc).  MPFR's custom numbers must never meet mpfr_set_prec, mpfr_prec_round,
// mpfr_clear or an mpfr_swap with a number outside this value: use set_prec(),
// round_prec() and swap() below.
//
// Semantics follow Boost's mpfr_float_backend<0> (variable precision), as the library
// relied on them: a new value takes the default precision, a copy the source's
// precision, assignment from another value takes that value's precision, assignment from
// a built-in number keeps the precision, results of + - * / get the precision of the
// value written (the default, or more when Boost's precision guard raises it for a more
// precise operand); every operation rounds to nearest (MPFR's, correctly rounded); str()
// writes what Boost's backend writes.  A value moved from keeps its precision and reads
// as +0.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <boost/mpl/list.hpp>
#include <boost/multiprecision/detail/digits.hpp>
#include <boost/multiprecision/mpfr.hpp>  // BOOST_MULTIPRECISION_MPFR_DEFAULT_PRECISION
#include <boost/multiprecision/number.hpp>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <ios>
#include <new>
#include <string>

#include "appell/scalar/mp_default_precision.hpp"

namespace appell::mp {

class mpfr_backend {
 public:
  using signed_types = boost::mpl::list<long, long long>;
  using unsigned_types = boost::mpl::list<unsigned long, unsigned long long>;
  using float_types = boost::mpl::list<double, long double>;
  using exponent_type = long;

  /// Significands of at most this many limbs live inside the value (256 bits: the
  /// precision of the long-horizon references; a value is then 64 bytes).
  static constexpr int inline_limbs = 4;
  static constexpr mpfr_prec_t inline_bits = inline_limbs * GMP_NUMB_BITS;

  mpfr_backend() { init_zero(defaults_.bits()); }
  mpfr_backend(const mpfr_backend& o) {
    const mpfr_srcptr src = o.data();
    const mpfr_prec_t p = mpfr_get_prec(src);
    if (is_inline(p)) {  // the fields and the significand as they are (what mpfr_set does here)
      v_ = *src;
      std::memcpy(limbs_, o.limbs_, sizeof limbs_);
      mpfr_custom_move(&v_, limbs_);
    } else {
      init_zero(p);
      mpfr_set(&v_, src, MPFR_RNDN);  // exact: same precision
    }
  }
  mpfr_backend(mpfr_backend&& o) noexcept { take(o); }
  /// An MPFR number, at its own precision (exact).
  explicit mpfr_backend(mpfr_srcptr x) {
    init_zero(mpfr_get_prec(x));
    mpfr_set(&v_, x, MPFR_RNDN);
  }
  /// Boost's MPFR number, at its own precision (exact).
  explicit mpfr_backend(const boost::multiprecision::backends::mpfr_float_backend<0>& x) : mpfr_backend(x.data()) {}
  ~mpfr_backend() { release(); }

  mpfr_backend& operator=(const mpfr_backend& o) {
    if (this != &o) {
      const mpfr_srcptr src = o.data();
      reshape(mpfr_get_prec(src));
      mpfr_set(&v_, src, MPFR_RNDN);
    }
    return *this;
  }
  mpfr_backend& operator=(mpfr_backend&& o) noexcept {
    if (this != &o) {
      release();
      take(o);
    }
    return *this;
  }
  // Built-in numbers: rounded to nearest at this value's precision (kept).
  mpfr_backend& operator=(unsigned long i) {
    mpfr_set_ui(data(), i, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(long i) {
    mpfr_set_si(data(), i, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(unsigned long long i) {
    mpfr_set_uj(data(), i, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(long long i) {
    mpfr_set_sj(data(), i, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(double d) {
    mpfr_set_d(data(), d, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(long double d) {
    mpfr_set_ld(data(), d, MPFR_RNDN);
    return *this;
  }
  /// Decimal text as MPFR reads it (mpfr_set_str, base 10), rounded to nearest; throws
  /// std::runtime_error when it is not a number (the value is then unchanged).
  mpfr_backend& operator=(const char* s);
  mpfr_backend& operator=(mpfr_srcptr x) {  // takes x's precision
    reshape(mpfr_get_prec(x));
    mpfr_set(&v_, x, MPFR_RNDN);
    return *this;
  }
  mpfr_backend& operator=(const boost::multiprecision::backends::mpfr_float_backend<0>& x) { return *this = x.data(); }

  void swap(mpfr_backend& o) noexcept {
    if (this == &o) return;
    mpfr_backend t(std::move(o));
    o.take(*this);
    take(t);
  }
  /// As Boost's mpfr_float_backend writes it (iostreams' digits and flags).
  std::string str(std::streamsize digits, std::ios_base::fmtflags f) const;
  void negate() { mpfr_neg(data(), data(), MPFR_RNDN); }  // exact
  int compare(const mpfr_backend& o) const { return mpfr_cmp(data(), o.data()); }
  int compare(unsigned long v) const { return mpfr_cmp_ui(data(), v); }
  int compare(long v) const { return mpfr_cmp_si(data(), v); }
  int compare(double v) const { return mpfr_cmp_d(data(), v); }
  int compare(long double v) const { return mpfr_cmp_ld(data(), v); }
  template <class V>
  int compare(V v) const {
    mpfr_backend t;
    t = v;
    return compare(t);
  }

  mpfr_ptr data() {
    aim();
    return &v_;
  }
  mpfr_srcptr data() const {
    aim();
    return &v_;
  }
  mpfr_prec_t prec() const noexcept { return mpfr_get_prec(&v_); }

  /// Boost's precision interface, in decimal digits (Boost's precision guard uses it).
  static unsigned default_precision() noexcept { return defaults_.digits10(); }
  static void default_precision(unsigned digits10) noexcept { defaults_.set_digits10(digits10); }
  /// appell's interface, in bits (set_mp_precision_bits): new values get exactly `bits` bits.
  static unsigned default_bits() noexcept { return static_cast<unsigned>(defaults_.bits()); }
  static void default_bits(unsigned bits) noexcept { defaults_.set_bits(bits); }
  unsigned precision() const noexcept { return precision_default::digits10_of(static_cast<unsigned long>(prec())); }
  void precision(unsigned digits10) {  // keeps the value, rounded to nearest
    round_prec(precision_default::bits_of(digits10));
  }
  /// mpfr_set_prec for this backend: precision p, value NaN.
  void set_prec(mpfr_prec_t p) {
    reshape(p);
    mpfr_set_nan(&v_);
  }
  /// mpfr_prec_round for this backend: precision p, the value rounded to nearest.
  void round_prec(mpfr_prec_t p);

 private:
  static bool is_inline(mpfr_prec_t p) noexcept { return p <= inline_bits; }
  static std::size_t block_bytes(mpfr_prec_t p) noexcept { return mpfr_custom_get_size(p); }
  // A fresh +0 of precision p (no value held before: nothing released).  Inlined: a value is
  // made for every temporary of an expression (the heap branch is out of line).
  [[gnu::always_inline]] void init_zero(mpfr_prec_t p) {
    if (is_inline(p)) [[likely]] {
      mpfr_custom_init_set(&v_, MPFR_ZERO_KIND, 0, p, limbs_);
    } else {
      mpfr_custom_init_set(&v_, MPFR_ZERO_KIND, 0, p, allocate(p));
    }
  }
  // A block through GMP's allocation functions (those MPFR uses for its own numbers; a
  // test counts them with mp_set_memory_functions).  GMP's functions never return null.
  [[gnu::noinline, gnu::cold]] static void* allocate(mpfr_prec_t p) {
    void* (*f)(std::size_t) = nullptr;
    mp_get_memory_functions(&f, nullptr, nullptr);
    return f(block_bytes(p));
  }
  static void deallocate(void* b, mpfr_prec_t p) noexcept {
    void (*f)(void*, std::size_t) = nullptr;
    mp_get_memory_functions(nullptr, nullptr, &f);
    f(b, block_bytes(p));
  }
  // Moves o's value here (this holds nothing); o keeps its precision and reads as +0.
  // No call into MPFR: the fields are set with MPFR's custom-interface macros, and an
  // inline significand is copied whole (32 bytes; the limbs past the precision are
  // copied too, unread).
  void take(mpfr_backend& o) noexcept {
    v_ = o.v_;
    const mpfr_prec_t p = mpfr_get_prec(&v_);
    if (is_inline(p)) {
      std::memcpy(limbs_, o.limbs_, sizeof limbs_);
      mpfr_custom_move(&v_, limbs_);
      mpfr_custom_init_set(&o.v_, MPFR_ZERO_KIND, 0, p, o.limbs_);
    } else {
      // The block changes hands; o's is made again, on first use.
      mpfr_custom_init_set(&o.v_, MPFR_ZERO_KIND, 0, p, nullptr);
    }
  }
  static long limbs_of(mpfr_prec_t p) noexcept { return (p + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS; }
  // The significand pointer of an inline value is re-aimed at the object (it may have
  // been relocated bitwise); a heap value that gave its block away gets a new one.
  // Inlined (every access goes through it: it was 8% of a long-horizon reference's time as a
  // call); the block made again is out of line.
  [[gnu::always_inline]] void aim() const {
    void* const d = mpfr_custom_get_significand(&v_);
    if (is_inline(mpfr_get_prec(&v_))) [[likely]] {
      if (d != limbs_) [[unlikely]] mpfr_custom_move(&v_, limbs_);
    } else if (!d) {
      make_block_again();
    }
  }
  [[gnu::noinline, gnu::cold]] void make_block_again() const {
    mpfr_custom_move(&v_, allocate(mpfr_get_prec(&v_)));
    mpfr_set_zero(&v_, 1);
  }
  void release() noexcept {
    if (is_inline(prec())) return;
    void* const d = mpfr_custom_get_significand(&v_);
    if (d) deallocate(d, prec());
  }
  // Precision p, value unspecified; the storage is kept when it has the room.  A new
  // block is allocated before the old one is freed (strong guarantee).
  void reshape(mpfr_prec_t p) {
    const mpfr_prec_t q = prec();
    if (p == q) return;
    if (is_inline(p)) {
      release();
      mpfr_custom_init_set(&v_, MPFR_ZERO_KIND, 0, p, limbs_);
      return;
    }
    void* const d = mpfr_custom_get_significand(&v_);
    if (!is_inline(q) && d && limbs_of(p) == limbs_of(q)) {  // keep the block
      mpfr_custom_init_set(&v_, MPFR_ZERO_KIND, 0, p, d);
      return;
    }
    void* const b = allocate(p);
    release();
    mpfr_custom_init_set(&v_, MPFR_ZERO_KIND, 0, p, b);
  }

  // mutable: data() re-aims the significand pointer, also through const access.
  mutable __mpfr_struct v_;
  mutable mp_limb_t limbs_[inline_limbs];

  // Boost's default for mpfr_float_backend<0> until set_mp_precision_bits is called.
  inline static constinit precision_default defaults_{BOOST_MULTIPRECISION_MPFR_DEFAULT_PRECISION};
};

// --- arithmetic (MPFR, rounded to nearest at the result's precision) ------------
inline void eval_add(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_add(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_add(mpfr_backend& r, const mpfr_backend& b) { eval_add(r, r, b); }
inline void eval_subtract(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_sub(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_subtract(mpfr_backend& r, const mpfr_backend& b) { eval_subtract(r, r, b); }
inline void eval_multiply(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  if (&a == &b) mpfr_sqr(r.data(), a.data(), MPFR_RNDN);
  else mpfr_mul(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_multiply(mpfr_backend& r, const mpfr_backend& b) { eval_multiply(r, r, b); }
inline void eval_divide(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_div(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_divide(mpfr_backend& r, const mpfr_backend& b) { eval_divide(r, r, b); }
// With an integer (exact operand, one rounding, as Boost's backend).
inline void eval_add(mpfr_backend& r, const mpfr_backend& a, unsigned long b) { mpfr_add_ui(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_add(mpfr_backend& r, const mpfr_backend& a, long b) { mpfr_add_si(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_add(mpfr_backend& r, unsigned long a, const mpfr_backend& b) { mpfr_add_ui(r.data(), b.data(), a, MPFR_RNDN); }
inline void eval_add(mpfr_backend& r, long a, const mpfr_backend& b) { mpfr_add_si(r.data(), b.data(), a, MPFR_RNDN); }
inline void eval_add(mpfr_backend& r, unsigned long b) { eval_add(r, r, b); }
inline void eval_add(mpfr_backend& r, long b) { eval_add(r, r, b); }
inline void eval_subtract(mpfr_backend& r, const mpfr_backend& a, unsigned long b) {
  mpfr_sub_ui(r.data(), a.data(), b, MPFR_RNDN);
}
inline void eval_subtract(mpfr_backend& r, const mpfr_backend& a, long b) { mpfr_sub_si(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_subtract(mpfr_backend& r, unsigned long a, const mpfr_backend& b) {
  mpfr_ui_sub(r.data(), a, b.data(), MPFR_RNDN);
}
inline void eval_subtract(mpfr_backend& r, long a, const mpfr_backend& b) { mpfr_si_sub(r.data(), a, b.data(), MPFR_RNDN); }
inline void eval_subtract(mpfr_backend& r, unsigned long b) { eval_subtract(r, r, b); }
inline void eval_subtract(mpfr_backend& r, long b) { eval_subtract(r, r, b); }
inline void eval_multiply(mpfr_backend& r, const mpfr_backend& a, unsigned long b) {
  mpfr_mul_ui(r.data(), a.data(), b, MPFR_RNDN);
}
inline void eval_multiply(mpfr_backend& r, const mpfr_backend& a, long b) { mpfr_mul_si(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_multiply(mpfr_backend& r, unsigned long a, const mpfr_backend& b) {
  mpfr_mul_ui(r.data(), b.data(), a, MPFR_RNDN);
}
inline void eval_multiply(mpfr_backend& r, long a, const mpfr_backend& b) { mpfr_mul_si(r.data(), b.data(), a, MPFR_RNDN); }
inline void eval_multiply(mpfr_backend& r, unsigned long b) { eval_multiply(r, r, b); }
inline void eval_multiply(mpfr_backend& r, long b) { eval_multiply(r, r, b); }
inline void eval_divide(mpfr_backend& r, const mpfr_backend& a, unsigned long b) { mpfr_div_ui(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_divide(mpfr_backend& r, const mpfr_backend& a, long b) { mpfr_div_si(r.data(), a.data(), b, MPFR_RNDN); }
inline void eval_divide(mpfr_backend& r, unsigned long a, const mpfr_backend& b) { mpfr_ui_div(r.data(), a, b.data(), MPFR_RNDN); }
inline void eval_divide(mpfr_backend& r, long a, const mpfr_backend& b) { mpfr_si_div(r.data(), a, b.data(), MPFR_RNDN); }
inline void eval_divide(mpfr_backend& r, unsigned long b) { eval_divide(r, r, b); }
inline void eval_divide(mpfr_backend& r, long b) { eval_divide(r, r, b); }
// fma / fms: one rounding (Boost's fma() and its expression templates use these).
inline void eval_multiply_add(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_fma(r.data(), a.data(), b.data(), r.data(), MPFR_RNDN);
}
inline void eval_multiply_add(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b, const mpfr_backend& c) {
  mpfr_fma(r.data(), a.data(), b.data(), c.data(), MPFR_RNDN);
}
inline void eval_multiply_subtract(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_fms(r.data(), a.data(), b.data(), r.data(), MPFR_RNDN);
  r.negate();
}
inline void eval_multiply_subtract(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b, const mpfr_backend& c) {
  mpfr_fms(r.data(), a.data(), b.data(), c.data(), MPFR_RNDN);
}

// --- classification and conversion ------------------------------------------------
inline bool eval_is_zero(const mpfr_backend& x) { return mpfr_zero_p(x.data()) != 0; }
inline int eval_get_sign(const mpfr_backend& x) { return mpfr_sgn(x.data()); }
inline int eval_fpclassify(const mpfr_backend& x) {
  const mpfr_srcptr p = x.data();
  return mpfr_inf_p(p) ? FP_INFINITE : mpfr_nan_p(p) ? FP_NAN : mpfr_zero_p(p) ? FP_ZERO : FP_NORMAL;
}
inline int eval_signbit(const mpfr_backend& x) { return mpfr_signbit(x.data()) ? 1 : 0; }
inline void eval_convert_to(double* r, const mpfr_backend& x) { *r = mpfr_get_d(x.data(), MPFR_RNDN); }
inline void eval_convert_to(long double* r, const mpfr_backend& x) { *r = mpfr_get_ld(x.data(), MPFR_RNDN); }
inline void eval_convert_to(float* r, const mpfr_backend& x) { *r = mpfr_get_flt(x.data(), MPFR_RNDN); }
// Integers as Boost's backend converts them (toward zero; NaN and overflow throw or clamp).
void eval_convert_to(long* r, const mpfr_backend& x);
void eval_convert_to(unsigned long* r, const mpfr_backend& x);
void eval_convert_to(long long* r, const mpfr_backend& x);
void eval_convert_to(unsigned long long* r, const mpfr_backend& x);

// --- functions: MPFR's, correctly rounded to nearest at the result's precision ------
#define APPELL_MPFR_UNARY(name, fn) \
  inline void name(mpfr_backend& r, const mpfr_backend& x) { fn(r.data(), x.data(), MPFR_RNDN); }
APPELL_MPFR_UNARY(eval_sqrt, mpfr_sqrt)
APPELL_MPFR_UNARY(eval_abs, mpfr_abs)
APPELL_MPFR_UNARY(eval_fabs, mpfr_abs)
APPELL_MPFR_UNARY(eval_exp, mpfr_exp)
APPELL_MPFR_UNARY(eval_exp2, mpfr_exp2)
APPELL_MPFR_UNARY(eval_log, mpfr_log)
APPELL_MPFR_UNARY(eval_log2, mpfr_log2)
APPELL_MPFR_UNARY(eval_log10, mpfr_log10)
APPELL_MPFR_UNARY(eval_sin, mpfr_sin)
APPELL_MPFR_UNARY(eval_cos, mpfr_cos)
APPELL_MPFR_UNARY(eval_tan, mpfr_tan)
APPELL_MPFR_UNARY(eval_asin, mpfr_asin)
APPELL_MPFR_UNARY(eval_acos, mpfr_acos)
APPELL_MPFR_UNARY(eval_atan, mpfr_atan)
APPELL_MPFR_UNARY(eval_sinh, mpfr_sinh)
APPELL_MPFR_UNARY(eval_cosh, mpfr_cosh)
APPELL_MPFR_UNARY(eval_tanh, mpfr_tanh)
#undef APPELL_MPFR_UNARY
inline void eval_ceil(mpfr_backend& r, const mpfr_backend& x) { mpfr_ceil(r.data(), x.data()); }
inline void eval_floor(mpfr_backend& r, const mpfr_backend& x) { mpfr_floor(r.data(), x.data()); }
inline void eval_trunc(mpfr_backend& r, const mpfr_backend& x) { mpfr_trunc(r.data(), x.data()); }
inline void eval_atan2(mpfr_backend& r, const mpfr_backend& y, const mpfr_backend& x) {
  mpfr_atan2(r.data(), y.data(), x.data(), MPFR_RNDN);
}
inline void eval_hypot(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_hypot(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_fmod(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_fmod(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_remainder(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  mpfr_remainder(r.data(), a.data(), b.data(), MPFR_RNDN);
}
inline void eval_remquo(mpfr_backend& r, const mpfr_backend& a, const mpfr_backend& b, int* q) {
  long l = 0;
  mpfr_remquo(r.data(), &l, a.data(), b.data(), MPFR_RNDN);
  if (q) *q = static_cast<int>(l);
}
void eval_modf(mpfr_backend& r, const mpfr_backend& x, mpfr_backend* integer_part);
/// b^e (MPFR's mpfr_pow; 0^odd integer keeps the sign of the zero, as Boost's backend).
void eval_pow(mpfr_backend& r, const mpfr_backend& b, const mpfr_backend& e);
inline void eval_pow(mpfr_backend& r, const mpfr_backend& b, long e) { mpfr_pow_si(r.data(), b.data(), e, MPFR_RNDN); }
inline void eval_pow(mpfr_backend& r, const mpfr_backend& b, int e) { mpfr_pow_si(r.data(), b.data(), e, MPFR_RNDN); }
inline void eval_pow(mpfr_backend& r, const mpfr_backend& b, unsigned long e) { mpfr_pow_ui(r.data(), b.data(), e, MPFR_RNDN); }
inline void eval_pow(mpfr_backend& r, const mpfr_backend& b, unsigned e) { mpfr_pow_ui(r.data(), b.data(), e, MPFR_RNDN); }
inline void eval_ldexp(mpfr_backend& r, const mpfr_backend& x, long e) { mpfr_mul_2si(r.data(), x.data(), e, MPFR_RNDN); }
inline void eval_frexp(mpfr_backend& r, const mpfr_backend& x, long* e) {
  mpfr_get_d_2exp(e, x.data(), MPFR_RNDN);  // Boost's: the exponent of x as MPFR has it (0 for 0)
  eval_ldexp(r, x, -*e);
}
inline void eval_frexp(mpfr_backend& r, const mpfr_backend& x, int* e) {
  long l = 0;
  eval_frexp(r, x, &l);
  *e = static_cast<int>(l);
}

// MPFR's functions where Boost.Multiprecision has no backend hook (number-level, as
// Boost's mpfr.hpp has them).
using mpfr_number = boost::multiprecision::number<mpfr_backend, boost::multiprecision::et_off>;
mpfr_number cbrt(const mpfr_number& x);
mpfr_number log1p(const mpfr_number& x);
mpfr_number expm1(const mpfr_number& x);
mpfr_number asinh(const mpfr_number& x);
mpfr_number acosh(const mpfr_number& x);
mpfr_number atanh(const mpfr_number& x);

}  // namespace appell::mp

namespace boost::multiprecision {
template <>
struct number_category<appell::mp::mpfr_backend> : public mpl::int_<number_kind_floating_point> {};
namespace detail {
template <>
struct is_variable_precision<appell::mp::mpfr_backend> : public true_type {};
}  // namespace detail
}  // namespace boost::multiprecision

namespace std {
// As Boost's for mpfr_float_backend<0>: is_specialized false (a precision chosen at run
// time), with values a caller can use at the default precision.
template <boost::multiprecision::expression_template_option ET>
class numeric_limits<boost::multiprecision::number<appell::mp::mpfr_backend, ET>> {
  using number_type = boost::multiprecision::number<appell::mp::mpfr_backend, ET>;
  template <class F>
  static number_type make(F set) {
    number_type r;
    set(r.backend().data());
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
  static constexpr float_round_style round_style = round_to_nearest;
  static constexpr int min_exponent = 0, min_exponent10 = 0, max_exponent = 0, max_exponent10 = 0;
  static number_type infinity() { return make([](mpfr_ptr b) { mpfr_set_inf(b, 1); }); }
  static number_type quiet_NaN() { return make([](mpfr_ptr b) { mpfr_set_nan(b); }); }
  static number_type signaling_NaN() { return quiet_NaN(); }
  static number_type epsilon() {  // 2^(1-p)
    return make([](mpfr_ptr b) { mpfr_set_ui_2exp(b, 1, 1 - mpfr_get_prec(b), MPFR_RNDN); });
  }
  static number_type round_error() {  // half an ulp of 1
    return make([](mpfr_ptr b) { mpfr_set_ui_2exp(b, 1, -1, MPFR_RNDN); });
  }
  static number_type(max)() {
    return make([](mpfr_ptr b) {
      mpfr_set_inf(b, 1);
      mpfr_nextbelow(b);
    });
  }
  static number_type lowest() { return -(max)(); }
  static number_type(min)() {  // the least positive normal number: MPFR has no subnormals
    return make([](mpfr_ptr b) {
      mpfr_set_zero(b, 1);
      mpfr_nextabove(b);
    });
  }
  static number_type denorm_min() { return (min)(); }
};
}  // namespace std
