// appell::mp::arb_backend: every operation, as calls into Arb (see arb_backend.hpp).
#include "appell/scalar/arb_access.hpp"

#include <cstddef>
#include <algorithm>
#include <cstdio>

#include "appell/scalar/interval.hpp"      // appell::domain_error
#include "appell/scalar/mpfi_backend.hpp"  // the text of an interval, read as mpfi reads it
#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"
#include "enclosure_text.hpp"

namespace appell::mp {

// The layout arb_backend.hpp assumes (its words and its test for heap storage).
static_assert(sizeof(arb_struct) == sizeof(arb_words), "arb_struct is six words");
static_assert(offsetof(arb_struct, mid) == 0 && offsetof(arf_struct, exp) == 0 && offsetof(arf_struct, size) == 8,
              "the midpoint's exponent and size are words 0 and 1");
static_assert(offsetof(arb_struct, rad) == 32 && offsetof(mag_struct, exp) == 0, "the radius's exponent is word 4");
static_assert(FLINT_BITS == 64 && SMALL_FMPZ_BITCOUNT_MAX == 62, "fmpz's small values: 62 bits");

namespace {
arb_ptr A(arb_backend& x) { return arb_of(x); }
arb_srcptr A(const arb_backend& x) { return arb_of(x); }

// Midpoints' limbs kept for reuse, per thread.  Above 128 bits a midpoint's limbs are on the heap
// and every temporary of an expression (Boost's number<>, expression templates off) would take
// them from malloc and give them back: at 256 bits that is about a quarter of an addition and a
// multiplication together (docs/benchmarks.md, "Ball arithmetic").  A value that dies with its
// limbs on the heap leaves its struct here (clear(); its value no longer matters), and a result
// about to be written into a value that holds no limbs of its own takes one (fresh()): Arb writes
// into the limbs it finds when they are enough (arf.h, ARF_GET_MPN_WRITE) and reallocates
// otherwise, so any struct serves any precision.  A struct is pooled only when nothing but its
// midpoint's limbs is on the heap (no exponent of Arb's big-integer form), and the pool empties
// itself when its thread ends.  Values that outlive their thread's pool (held in a thread_local
// object destroyed after it, such as a scratch pool of linalg/scratch.hpp) are cleared as before.
// The pool is plain data (constant-initialized: no guard on the operations' path); the object
// that empties it at the thread's end is made when the first struct is kept, and marks the pool
// gone (a store into the pool, which outlives it).  At 128 bits and less a midpoint's limbs are
// inline (two limbs), so results there skip the pool altogether.
struct limb_pool {
  static constexpr int capacity = 256;  // 12 KiB of structs a thread: a vector's values die in bursts
  arb_struct kept[capacity];
  int n;
  bool armed, gone;
};
thread_local limb_pool pool;  // zero-initialized
struct limb_pool_emptier {
  ~limb_pool_emptier() {
    while (pool.n > 0) arb_clear(pool.kept + --pool.n);
    pool.gone = true;
  }
};
void arm_pool() {
  static thread_local limb_pool_emptier emptier;  // made on this thread's first use, destroyed at its end
  (void)emptier;
  pool.armed = true;
}
constexpr long inline_bits = 128;  // ARF_NOPTR_LIMBS limbs of 64 bits

// Neither exponent in Arb's big-integer form (a pointer to an mpz): the midpoint's limbs are then
// all the struct may hold on the heap.
bool small_exponents(arb_srcptr x) { return !COEFF_IS_MPZ(ARF_EXP(arb_midref(x))) && !COEFF_IS_MPZ(MAG_EXP(arb_radref(x))); }
bool only_limbs_on_heap(arb_srcptr x) { return ARF_HAS_PTR(arb_midref(x)) && small_exponents(x); }
bool nothing_on_heap(arb_srcptr x) { return !ARF_HAS_PTR(arb_midref(x)) && small_exponents(x); }

// r, about to receive a result that reads neither r nor anything r points to, given a pooled
// struct's limbs where it holds none (its value is overwritten by the operation that follows).
void fresh(arb_backend& r) {
  if (r.prec() <= inline_bits) return;
  limb_pool& p = pool;
  if (p.n > 0 && nothing_on_heap(arb_of(r))) *arb_of(r) = p.kept[--p.n];
}
// Only where an operand's limbs are on the heap: a result of small exact operands (0, 1, an
// integer) often fits inline, and a pooled struct handed to it would have its limbs freed by Arb.
bool limbs_on_heap(const arb_backend& x) { return ARF_HAS_PTR(arb_midref(arb_of(x))); }
void fresh(arb_backend& r, const arb_backend& a) {
  if (&r != &a && limbs_on_heap(a)) fresh(r);
}
void fresh(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  if (&r != &a && &r != &b && (limbs_on_heap(a) || limbs_on_heap(b))) fresh(r);
}

// r = op(r, ...) (an accumulation: r is read), written into a pooled struct where r holds no
// limbs (a sum begun at 0, a small exact value), which then replaces r's words: they hold nothing
// on the heap.  op(dst) writes the result into dst, reading r's value through A(r);
// operand_on_heap: whether the other operand's limbs are on the heap (as for fresh, above; a
// quotient by an integer counts as such: it rarely fits inline).
template <class Op>
void in_place(arb_backend& r, bool operand_on_heap, Op op) {
  limb_pool& p = pool;
  if (!operand_on_heap || r.prec() <= inline_bits || p.n == 0 || !nothing_on_heap(arb_of(r))) return op(arb_of(r));
  arb_struct t = p.kept[--p.n];
  op(&t);
  *arb_of(r) = t;
}

// The whole line: Arb's answer where nothing better is known.
void whole_line(arb_ptr r) {
  arf_zero(arb_midref(r));
  mag_inf(arb_radref(r));
}

// An MPFR number at exactly `bits` bits.
struct mpfr_tmp {
  mpfr_t v;
  explicit mpfr_tmp(mpfr_prec_t bits) { mpfr_init2(v, bits); }
  ~mpfr_tmp() { mpfr_clear(v); }
  mpfr_tmp(const mpfr_tmp&) = delete;
  mpfr_tmp& operator=(const mpfr_tmp&) = delete;
};

// r = v exactly (the midpoint holds every bit, radius 0); NaN: the whole line; +-inf: the point.
void set_exact(arb_ptr r, mpfr_srcptr v) {
  if (mpfr_nan_p(v)) {
    whole_line(r);
  } else if (mpfr_inf_p(v)) {
    if (mpfr_sgn(v) > 0) arb_pos_inf(r);
    else arb_neg_inf(r);
  } else {
    arf_set_mpfr(arb_midref(r), v);
    mag_zero(arb_radref(r));
  }
}

// The midpoint, rounded to nearest at the value's precision.
void midpoint_to(mpfr_ptr out, const arb_backend& x) { arf_get_mpfr(out, arb_midref(A(x)), MPFR_RNDN); }
}  // namespace

void arb_backend::clear() noexcept {  // the value dies (the destructor): its limbs pooled where they can be
  if (limb_pool& p = pool; !p.gone && p.n < limb_pool::capacity && only_limbs_on_heap(A(*this))) {
    if (!p.armed) arm_pool();
    p.kept[p.n++] = *A(*this);
    v_ = arb_words{};
    return;
  }
  arb_clear(A(*this));
  v_ = arb_words{};
}

void arb_backend::set(const arb_backend& o) {
  fresh(*this, o);
  arb_set(A(*this), A(o));
}

arb_backend& arb_backend::operator=(unsigned long i) {
  arb_set_ui(A(*this), i);
  return *this;
}
arb_backend& arb_backend::operator=(long i) {
  arb_set_si(A(*this), i);
  return *this;
}
arb_backend& arb_backend::operator=(double d) {
  if (d != d) whole_line(A(*this));
  else arb_set_d(A(*this), d);  // exact
  return *this;
}
arb_backend& arb_backend::operator=(long double d) {
  if (d != d) {
    whole_line(A(*this));
    return *this;
  }
  mpfr_tmp t(64);
  mpfr_set_ld(t.v, d, MPFR_RNDN);  // exact: 64 bits
  set_exact(A(*this), t.v);
  return *this;
}
arb_backend& arb_backend::operator=(const mpfr_backend& x) {
  set_exact(A(*this), x.data());
  return *this;
}

arb_backend& arb_backend::operator=(const char* s) {
  // Read as an mpfi interval of the same precision (the syntax and its checks in one place),
  // then the ball around it.  An infinite bound gives the ball of infinite radius.
  mpfi_backend t;
  t.set_prec(prec_);
  t = s;
  const mpfi_srcptr p = t.data();
  if (!mpfr_number_p(&p->left) || !mpfr_number_p(&p->right)) whole_line(A(*this));
  else arb_set_interval_mpfr(A(*this), &p->left, &p->right, prec_);
  return *this;
}

// x's bounds, exactly, in two MPFR numbers sized to hold them (+-inf where the ball is not finite).
void exact_bounds_of(const arb_backend& x, mpfr_value& lo, mpfr_value& hi) {
  arb_srcptr p = A(x);
  if (!arb_is_finite(p)) {  // a NaN midpoint or an infinite radius: the whole line, or an infinity
    mpfr_set_prec(lo, 53);
    mpfr_set_prec(hi, 53);
    if (arf_is_pos_inf(arb_midref(p)) && mag_is_finite(arb_radref(p))) mpfr_set_inf(lo, 1);
    else mpfr_set_inf(lo, -1);
    if (arf_is_neg_inf(arb_midref(p)) && mag_is_finite(arb_radref(p))) mpfr_set_inf(hi, -1);
    else mpfr_set_inf(hi, 1);
    return;
  }
  arf_t b;
  arf_init(b);
  for (int side = 0; side < 2; ++side) {
    mpfr_value& out = side == 0 ? lo : hi;
    if (side == 0) arb_get_lbound_arf(b, p, ARF_PREC_EXACT);
    else arb_get_ubound_arf(b, p, ARF_PREC_EXACT);
    const slong bits = arf_bits(b);
    mpfr_set_prec(out, bits < 2 ? 2 : bits);
    arf_get_mpfr(out, b, MPFR_RNDN);  // exact: the precision holds every bit
  }
  arf_clear(b);
}

std::string arb_backend::str(std::streamsize digits, std::ios_base::fmtflags f) const {
  mpfr_value lo, hi;
  exact_bounds_of(*this, lo, hi);
  return enclosure_text(lo, hi, digits, f);
}

void arb_backend::negate() { arb_neg(A(*this), A(*this)); }

int arb_backend::compare(const arb_backend& o) const {
  if (arb_lt(A(*this), A(o))) return -1;
  if (arb_gt(A(*this), A(o))) return 1;
  if (arb_equal(A(*this), A(o))) return 0;
  throw interval_error("undecided comparison of two balls");
}

void arb_backend::round_prec(long p) {
  prec_ = p;
  arb_set_round(A(*this), A(*this), p);
}

// --- arithmetic ------------------------------------------------------------------------
void eval_add(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  fresh(r, a, b);
  arb_add(A(r), A(a), A(b), r.prec());
}
void eval_add(arb_backend& r, const arb_backend& b) {
  in_place(r, limbs_on_heap(b), [&](arb_ptr d) { arb_add(d, A(r), A(b), r.prec()); });
}
void eval_subtract(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  fresh(r, a, b);
  arb_sub(A(r), A(a), A(b), r.prec());
}
void eval_subtract(arb_backend& r, const arb_backend& b) {
  in_place(r, limbs_on_heap(b), [&](arb_ptr d) { arb_sub(d, A(r), A(b), r.prec()); });
}
void eval_multiply(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  fresh(r, a, b);
  if (&a == &b) {  // x * x >= 0: Arb's square of a ball that holds 0 reaches below 0, so its part >= 0
    arb_sqr(A(r), A(a), r.prec());
    if (!arb_is_nonnegative(A(r))) arb_nonnegative_part(A(r), A(r));
  } else {
    arb_mul(A(r), A(a), A(b), r.prec());
  }
}
void eval_multiply(arb_backend& r, const arb_backend& b) {
  if (&r == &b) return eval_multiply(r, r, r);  // a square: its part >= 0 (above)
  in_place(r, limbs_on_heap(b), [&](arb_ptr d) { arb_mul(d, A(r), A(b), r.prec()); });
}
void eval_divide(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  fresh(r, a, b);
  arb_div(A(r), A(a), A(b), r.prec());
}
void eval_divide(arb_backend& r, const arb_backend& b) {
  in_place(r, limbs_on_heap(b), [&](arb_ptr d) { arb_div(d, A(r), A(b), r.prec()); });
}
void eval_multiply(arb_backend& r, const arb_backend& a, unsigned long b) {
  fresh(r, a);
  arb_mul_ui(A(r), A(a), b, r.prec());
}
void eval_multiply(arb_backend& r, unsigned long b) {
  in_place(r, false, [&](arb_ptr d) { arb_mul_ui(d, A(r), b, r.prec()); });
}
void eval_divide(arb_backend& r, const arb_backend& a, unsigned long b) {
  fresh(r, a);
  arb_div_ui(A(r), A(a), b, r.prec());
}
void eval_divide(arb_backend& r, unsigned long b) {
  in_place(r, true, [&](arb_ptr d) { arb_div_ui(d, A(r), b, r.prec()); });
}
void arb_add_product(arb_backend& s, const arb_backend& x, const arb_backend& y) {
  in_place(s, limbs_on_heap(x) || limbs_on_heap(y), [&](arb_ptr d) {
    if (d != A(s)) arb_set(d, A(s));  // a pooled struct: arb_addmul accumulates into it, s's value first
    arb_addmul(d, A(x), A(y), s.prec());
  });
}
void arb_subtract_product(arb_backend& s, const arb_backend& x, const arb_backend& y) {
  in_place(s, limbs_on_heap(x) || limbs_on_heap(y), [&](arb_ptr d) {
    if (d != A(s)) arb_set(d, A(s));
    arb_submul(d, A(x), A(y), s.prec());
  });
}
void arb_sum_of_products(arb_backend& r, const arb_backend* const* x, const arb_backend* const* y, int n, unsigned subtract) {
  // arb_dot reads its operands as arrays of arb_struct with a stride; appell's values are not
  // laid out so (each carries its precision beside the struct). Copies of the structs (their
  // words: the limbs they may point to are shared, read only, and never cleared from here) make
  // the arrays; a subtracted term's copy has its midpoint's sign flipped, in the copy alone.
  arb_struct xs[3], ys[3];
  long prec = 0;
  for (int k = 0; k < n; ++k) prec = std::max({prec, x[k]->prec(), y[k]->prec()});
  for (int k = 0; k < n; ++k) {
    xs[k] = *A(*x[k]);
    ys[k] = *A(*y[k]);
    if (!(subtract >> k & 1u) || arf_is_zero(arb_midref(xs + k))) continue;
    if (arf_is_special(arb_midref(xs + k))) {  // an infinite or NaN midpoint: Arb's own operations
      arb_t s, t;
      arb_init(s);
      arb_init(t);
      for (int j = 0; j < n; ++j) {
        arb_mul(t, A(*x[j]), A(*y[j]), prec);
        if (subtract >> j & 1u) arb_sub(s, s, t, prec);
        else arb_add(s, s, t, prec);
      }
      r.set_prec_keep(prec);
      arb_swap(A(r), s);
      arb_clear(s);
      arb_clear(t);
      return;
    }
    ARF_NEG(arb_midref(xs + k));  // the sign bit of the copy's size word
  }
  r.set_prec_keep(prec);
  if (std::none_of(x, x + n, [&](const arb_backend* v) { return v == &r; }) &&
      std::none_of(y, y + n, [&](const arb_backend* v) { return v == &r; }))
    fresh(r);
  arb_dot(A(r), nullptr, 0, xs, 1, ys, 1, n, prec);
}

void assign_components(arb_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  if (mpfr_nan_p(a.data()) || mpfr_nan_p(b.data()) || mpfr_cmp(a.data(), b.data()) > 0)
    throw std::runtime_error("an interval needs lower <= upper, and no NaN");
  if (!mpfr_number_p(a.data()) || !mpfr_number_p(b.data())) whole_line(A(r));
  else arb_set_interval_mpfr(A(r), a.data(), b.data(), r.prec());
}

void generic_interconvert(mpfr_backend& to, const arb_backend& from,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&) {
  midpoint_to(to.data(), from);
}

// --- classification and conversion -----------------------------------------------------
bool eval_is_zero(const arb_backend& x) { return arb_is_zero(A(x)) != 0; }
int eval_get_sign(const arb_backend& x) {
  if (arb_is_zero(A(x))) return 0;
  if (arb_is_positive(A(x))) return 1;
  if (arb_is_negative(A(x))) return -1;
  throw interval_error("undecided sign of a ball");
}
int eval_fpclassify(const arb_backend& x) {
  arb_srcptr p = A(x);
  if (arf_is_nan(arb_midref(p))) return FP_NAN;
  if (!arb_is_finite(p)) return mag_is_inf(arb_radref(p)) ? FP_NAN : FP_INFINITE;
  return arb_is_zero(p) ? FP_ZERO : FP_NORMAL;
}
void eval_convert_to(double* r, const arb_backend& x) { *r = arf_get_d(arb_midref(A(x)), ARF_RND_NEAR); }
void eval_convert_to(long double* r, const arb_backend& x) {
  mpfr_tmp t(static_cast<mpfr_prec_t>(x.prec() < 64 ? 64 : x.prec()));
  midpoint_to(t.v, x);
  *r = mpfr_get_ld(t.v, MPFR_RNDN);
}
namespace {
template <class I>
void to_integer(I* r, const arb_backend& x) {
  boost::multiprecision::backends::mpfr_float_backend<0> m;  // Boost's conversions, as mpfi's
  mpfr_set_prec(m.data(), static_cast<mpfr_prec_t>(x.prec() < 2 ? 2 : x.prec()));
  midpoint_to(m.data(), x);
  boost::multiprecision::backends::eval_convert_to(r, m);
}
}  // namespace
void eval_convert_to(long* r, const arb_backend& x) { to_integer(r, x); }
void eval_convert_to(unsigned long* r, const arb_backend& x) { to_integer(r, x); }
void eval_convert_to(long long* r, const arb_backend& x) { to_integer(r, x); }
void eval_convert_to(unsigned long long* r, const arb_backend& x) { to_integer(r, x); }

// --- functions -------------------------------------------------------------------------
namespace {
// The upper bound of x, as a double rounded up (for the domain tests below: its sign only).
int upper_sign(const arb_backend& x) {
  arf_t u;
  arf_init(u);
  arb_get_ubound_arf(u, A(x), 30);
  const int s = arf_is_nan(u) ? 1 : arf_sgn(u);
  arf_clear(u);
  return s;
}
// x restricted to (0, +inf) for the logarithms: empty when x <= 0; the whole line when x
// reaches 0 (a ball cannot hold [-inf, log b]); else f.
template <class F>
void on_positive_part(arb_backend& r, const arb_backend& x, const char* what, F f) {
  if (upper_sign(x) <= 0) throw appell::domain_error(what);
  if (!arb_is_positive(A(x))) return whole_line(A(r));
  fresh(r, x);
  f(A(r), A(x), r.prec());
}
}  // namespace

void eval_sqrt(arb_backend& r, const arb_backend& x) {
  if (upper_sign(x) < 0) throw appell::domain_error("sqrt of a ball below 0");
  fresh(r, x);
  arb_sqrtpos(A(r), A(x), r.prec());  // the part >= 0 (IEEE 1788's restriction)
}
void eval_log(arb_backend& r, const arb_backend& x) {
  on_positive_part(r, x, "log of a ball with no positive point", arb_log);
}
void eval_log2(arb_backend& r, const arb_backend& x) {
  on_positive_part(r, x, "log2 of a ball with no positive point",
                   [](arb_ptr z, arb_srcptr a, slong prec) { arb_log_base_ui(z, a, 2, prec); });
}
void eval_log10(arb_backend& r, const arb_backend& x) {
  on_positive_part(r, x, "log10 of a ball with no positive point",
                   [](arb_ptr z, arb_srcptr a, slong prec) { arb_log_base_ui(z, a, 10, prec); });
}
void eval_sin(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_sin(A(r), A(x), r.prec());
}
void eval_cos(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_cos(A(r), A(x), r.prec());
}
void eval_abs(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_abs(A(r), A(x));
}
void eval_fabs(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_abs(A(r), A(x));
}
void eval_exp(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_exp(A(r), A(x), r.prec());
}
void eval_exp2(arb_backend& r, const arb_backend& x) {
  arb_t two;
  arb_init(two);
  arb_set_ui(two, 2);
  arb_pow(A(r), two, A(x), r.prec());
  arb_clear(two);
}
void eval_tan(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_tan(A(r), A(x), r.prec());
}
void eval_asin(arb_backend& r, const arb_backend& x) { arb_asin(A(r), A(x), r.prec()); }
void eval_acos(arb_backend& r, const arb_backend& x) { arb_acos(A(r), A(x), r.prec()); }
void eval_atan(arb_backend& r, const arb_backend& x) {
  fresh(r, x);
  arb_atan(A(r), A(x), r.prec());
}
void eval_atan2(arb_backend& r, const arb_backend& y, const arb_backend& x) {
  fresh(r, y, x);
  arb_atan2(A(r), A(y), A(x), r.prec());
}
void eval_hypot(arb_backend& r, const arb_backend& a, const arb_backend& b) {
  fresh(r, a, b);
  arb_hypot(A(r), A(a), A(b), r.prec());
}
void eval_sinh(arb_backend& r, const arb_backend& x) { arb_sinh(A(r), A(x), r.prec()); }
void eval_cosh(arb_backend& r, const arb_backend& x) { arb_cosh(A(r), A(x), r.prec()); }
void eval_tanh(arb_backend& r, const arb_backend& x) { arb_tanh(A(r), A(x), r.prec()); }

void eval_pow(arb_backend& r, const arb_backend& b, const arb_backend& e) {
  arb_backend t;  // r may be b or e
  t.set_prec_keep(r.prec());
  if (arb_is_exact(A(e)) && arb_is_int(A(e))) {
    fmpz_t n;
    fmpz_init(n);
    arf_get_fmpz(n, arb_midref(A(e)), ARF_RND_DOWN);  // exact: an integer
    if (fmpz_sgn(n) < 0 && arb_contains_zero(A(b))) whole_line(A(t));
    else arb_pow_fmpz(A(t), A(b), n, t.prec());
    fmpz_clear(n);
  } else if (arb_is_positive(A(b)) || (arb_is_nonnegative(A(b)) && arb_is_positive(A(e)))) {
    arb_pow(A(t), A(b), A(e), t.prec());  // exp(e log b); Arb: 0^e = 0 for e > 0
  } else {
    whole_line(A(t));
  }
  r.swap(t);
}

namespace {
// floor (down) or ceil (up) of both ends, which must agree.
void integer_part(arb_backend& r, const arb_backend& x, bool up, const char* what) {
  mpfr_value lo, hi;
  exact_bounds_of(x, lo, hi);
  if (up) {
    mpfr_ceil(lo, lo);
    mpfr_ceil(hi, hi);
  } else {
    mpfr_floor(lo, lo);
    mpfr_floor(hi, hi);
  }
  if (!mpfr_number_p(lo) || !mpfr_equal_p(lo, hi))
    throw interval_error(std::string(what) + " of a ball that straddles an integer");
  arf_set_mpfr(arb_midref(A(r)), lo);
  mag_zero(arb_radref(A(r)));
}
}  // namespace

void eval_floor(arb_backend& r, const arb_backend& x) { integer_part(r, x, false, "floor"); }
void eval_ceil(arb_backend& r, const arb_backend& x) { integer_part(r, x, true, "ceil"); }
void eval_ldexp(arb_backend& r, const arb_backend& x, long e) { arb_mul_2exp_si(A(r), A(x), e); }
void eval_frexp(arb_backend& r, const arb_backend& x, long* e) {
  // The exponent of the midpoint; the ball scaled by it (exact).
  arf_srcptr m = arb_midref(A(x));
  *e = arf_is_special(m) || !fmpz_fits_si(ARF_EXPREF(m)) ? 0 : fmpz_get_si(ARF_EXPREF(m));
  arb_mul_2exp_si(A(r), A(x), -*e);
}
void eval_frexp(arb_backend& r, const arb_backend& x, int* e) {
  long l = 0;
  eval_frexp(r, x, &l);
  *e = static_cast<int>(l);
}

namespace {
arb_number apply(void (*f)(arb_ptr, arb_srcptr, slong), const arb_number& x) {
  arb_number r;
  r.backend().set_prec_keep(x.backend().prec());
  f(A(r.backend()), A(x.backend()), r.backend().prec());
  return r;
}
}  // namespace

arb_number cbrt(const arb_number& x) {
  return apply([](arb_ptr z, arb_srcptr a, slong prec) { arb_root_ui(z, a, 3, prec); }, x);
}
arb_number log1p(const arb_number& x) { return apply(arb_log1p, x); }
arb_number expm1(const arb_number& x) { return apply(arb_expm1, x); }
arb_number asinh(const arb_number& x) { return apply(arb_asinh, x); }
arb_number acosh(const arb_number& x) { return apply(arb_acosh, x); }
arb_number atanh(const arb_number& x) { return apply(arb_atanh, x); }

arb_number arb_special(int kind) {
  arb_number r;
  arb_ptr p = A(r.backend());
  const slong prec = r.backend().prec();
  switch (kind) {
    case 0: whole_line(p); break;
    case 1: arb_pos_inf(p); break;
    case 2: arb_one(p); arb_mul_2exp_si(p, p, 1 - prec); break;  // 2^(1-p)
    case 3: {  // the largest number MPFR holds at this precision: Arb's range is wider
      mpfr_tmp t(prec);
      mpfr_set_inf(t.v, 1);
      mpfr_nextbelow(t.v);
      arf_set_mpfr(arb_midref(p), t.v);
      break;
    }
    default: {  // the smallest positive MPFR number
      mpfr_tmp t(prec);
      mpfr_set_zero(t.v, 1);
      mpfr_nextabove(t.v);
      arf_set_mpfr(arb_midref(p), t.v);
      break;
    }
  }
  return r;
}

}  // namespace appell::mp

namespace appell {

using mp::arb_of;

namespace {
mpfr mpfr_of_prec(long prec) {
  mpfr r;
  r.backend().set_prec(static_cast<mpfr_prec_t>(prec < 2 ? 2 : prec));
  return r;
}
// A bound of x rounded outward to x's precision: lower (down) or upper (up); +-inf where
// the ball is not finite.
mpfr bound(const arb& x, bool up) {
  mpfr r = mpfr_of_prec(x.backend().prec());
  arb_srcptr p = arb_of(x.backend());
  if (!arb_is_finite(p)) {
    mpfr_value lo, hi;
    mp::exact_bounds_of(x.backend(), lo, hi);
    mpfr_set(r.backend().data(), up ? hi.get() : lo.get(), MPFR_RNDN);  // an infinity, exact
    return r;
  }
  arf_t b;
  arf_init(b);
  if (up) arb_get_ubound_arf(b, p, ARF_PREC_EXACT);
  else arb_get_lbound_arf(b, p, ARF_PREC_EXACT);
  arf_get_mpfr(r.backend().data(), b, up ? MPFR_RNDU : MPFR_RNDD);
  arf_clear(b);
  return r;
}
}  // namespace

mpfr ball_lower(const arb& x) { return bound(x, false); }
mpfr ball_upper(const arb& x) { return bound(x, true); }
mpfr ball_mid(const arb& x) {
  mpfr r = mpfr_of_prec(x.backend().prec());
  arf_get_mpfr(r.backend().data(), arb_midref(arb_of(x.backend())), MPFR_RNDN);
  return r;
}
mpfr ball_width(const arb& x) {
  mpfr r = mpfr_of_prec(x.backend().prec());
  arb_srcptr p = arb_of(x.backend());
  if (!arb_is_finite(p)) {
    mpfr_set_inf(r.backend().data(), 1);
    return r;
  }
  arf_t w;
  arf_init(w);
  arf_set_mag(w, arb_radref(p));
  arf_mul_2exp_si(w, w, 1);
  arf_get_mpfr(r.backend().data(), w, MPFR_RNDU);
  arf_clear(w);
  return r;
}
arb ball_from_bounds(const mpfr& lo, const mpfr& hi) {
  return ball_from_mpfr_bounds(lo.backend().data(), hi.backend().data());
}
arb ball_from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi) {
  arb r;
  arb_ptr p = arb_of(r.backend());
  if (mpfr_equal_p(lo, hi)) mp::set_exact(p, lo);  // a point, an infinity included (never NaN: NaN equals nothing)
  else if (!mpfr_number_p(lo) || !mpfr_number_p(hi)) mp::whole_line(p);  // NaN, or a half line
  else arb_set_interval_mpfr(p, lo, hi, r.backend().prec());
  return r;
}
void ball_to_mpfr(const arb& x, mpfr_value& lo, mpfr_value& hi) { mp::exact_bounds_of(x.backend(), lo, hi); }
arb ball_hull(const arb& a, const arb& b) {
  arb r;
  arb_union(arb_of(r.backend()), arb_of(a.backend()), arb_of(b.backend()), r.backend().prec());
  return r;
}
arb ball_intersect(const arb& a, const arb& b) {
  arb r;
  if (!arb_intersection(arb_of(r.backend()), arb_of(a.backend()), arb_of(b.backend()), r.backend().prec()))
    throw certification_error("two enclosures of one number are disjoint (an internal error: please report it)");
  return r;
}
bool ball_is_finite(const arb& x) { return arb_is_finite(arb_of(x.backend())) != 0; }
bool ball_is_exact(const arb& x, long value) {
  arb_srcptr p = arb_of(x.backend());
  return arb_is_exact(p) && arf_equal_si(arb_midref(p), value);
}
bool ball_identical(const arb& a, const arb& b) {
  arb_srcptr x = arb_of(a.backend()), y = arb_of(b.backend());
  return arf_equal(arb_midref(x), arb_midref(y)) && mag_equal(arb_radref(x), arb_radref(y));
}

arb pown_arb(const arb& x, int n) {
  arb r;
  arb_ptr p = arb_of(r.backend());
  arb_srcptr a = arb_of(x.backend());
  const slong prec = r.backend().prec();
  if (n == 0) {
    arb_one(p);
  } else if (n > 0 && n % 2 == 0 && arb_contains_zero(a) && arb_is_finite(a)) {
    // [0, max |x|^n]: Arb's powering of a ball around 0 would reach below 0.
    arf_t u;
    arf_init(u);
    arb_get_abs_ubound_arf(u, a, prec);
    arb_t m;
    arb_init(m);
    arb_set_arf(m, u);
    arb_pow_ui(m, m, static_cast<ulong>(n), prec);
    arb_get_ubound_arf(u, m, prec);
    arf_t zero;
    arf_init(zero);
    arb_set_interval_arf(p, zero, u, prec);
    arf_clear(zero);
    arb_clear(m);
    arf_clear(u);
  } else if (n > 0) {
    arb_pow_ui(p, a, static_cast<ulong>(n), prec);
  } else if (arb_contains_zero(a)) {
    if (arb_is_zero(a)) throw domain_error("negative power of [0, 0]");
    arf_zero(arb_midref(p));
    mag_inf(arb_radref(p));
  } else {
    fmpz_t e;
    fmpz_init_set_si(e, n);
    arb_pow_fmpz(p, a, e, prec);
    fmpz_clear(e);
  }
  return r;
}

void sin_cos_arb(const arb& x, arb& s, arb& c) {
  if (&s == &x || &c == &x) {  // s or c is x itself: work on a copy
    const arb copy = x;
    return sin_cos_arb(copy, s, c);
  }
  arb_sin_cos(arb_of(s.backend()), arb_of(c.backend()), arb_of(x.backend()),
              std::max(s.backend().prec(), c.backend().prec()));
}

}  // namespace appell
