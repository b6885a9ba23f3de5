// appell::mp::mpfi_backend: the out-of-line members and functions (see mpfi_backend.hpp).
#include "appell/scalar/mpfi_backend.hpp"

#include <cctype>
#include <cstdio>
#include <string_view>

#include "appell/scalar/decimal.hpp"   // is_decimal_literal, decimal_sign_of_sum
#include "appell/scalar/interval.hpp"  // appell::domain_error
#include "enclosure_text.hpp"

namespace appell::mp {

namespace {
using mpfr_b = boost::multiprecision::backends::mpfr_float_backend<0>;

// The midpoint of x at x's precision, as Boost's backend converts.
mpfr_b midpoint(const mpfi_backend& x) {
  mpfr_b t;
  mpfr_set_prec(t.data(), x.prec());
  mpfi_mid(t.data(), x.data());
  return t;
}

// f on x restricted to [0, +inf) (IEEE 1788): empty when x < 0 (or x <= 0 when
// zero_is_outside, for the logarithms, where log 0 = -inf is only a limit).
template <class F>
void on_nonnegative_part(mpfi_backend& r, const mpfi_backend& x, bool zero_is_outside, const char* what, F f) {
  const int s = mpfr_sgn(&x.data()->right);
  if (s < 0 || (zero_is_outside && s == 0)) throw appell::domain_error(what);
  if (mpfr_sgn(&x.data()->left) < 0) {
    mpfi_backend clipped = x;
    mpfr_set_zero(&clipped.data()->left, 1);
    f(r.data(), clipped.data());
  } else {
    f(r.data(), x.data());
  }
}
}  // namespace

void mpfi_backend::ownership_violation() noexcept {
  std::fputs(
      "appell: internal error: an mpfi value's bound no longer points into its own block "
      "(mpfi_set_prec, mpfi_round_prec or a swap with a foreign number was applied to it; "
      "see appell/scalar/mpfi_backend.hpp)\n",
      stderr);
  std::abort();
}

namespace {
std::string_view trimmed(std::string_view t) {
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
  return t;
}
// One bound: a decimal literal (appell::is_decimal_literal) or [+-]inf; NaN is refused.
bool is_bound_text(std::string_view t) {
  return appell::is_decimal_literal(t) || t == "inf" || t == "+inf" || t == "-inf";
}
// The text's number rounded in direction rnd into b (whole text consumed: checked before).
void read_bound(mpfr_ptr b, std::string_view t, mpfr_rnd_t rnd) {
  const std::string z(t);
  mpfr_strtofr(b, z.c_str(), nullptr, 10, rnd);
}
}  // namespace

mpfi_backend& mpfi_backend::operator=(const char* s) {
  // "x", "[a, b]" (MPFI) or "{a,b}" (str()); a and b decimal literals or +-inf, a <= b
  // decided on the exact decimals (never after rounding), bounds rounded outward.
  const std::string_view text = trimmed(s ? std::string_view(s) : std::string_view());
  const auto bad = [&](const char* why) {
    return std::runtime_error("not a number or interval (" + std::string(why) + "): \"" + std::string(text) + "\"");
  };
  std::string_view lo = text, hi = text;
  if (!text.empty() && (text.front() == '[' || text.front() == '{')) {
    const char close = text.front() == '[' ? ']' : '}';
    if (text.back() != close) throw bad("unclosed interval");
    const std::string_view inner = text.substr(1, text.size() - 2);
    const std::size_t comma = inner.find(',');
    if (comma == std::string_view::npos || inner.find(',', comma + 1) != std::string_view::npos)
      throw bad("an interval has two bounds");
    lo = trimmed(inner.substr(0, comma));
    hi = trimmed(inner.substr(comma + 1));
  }
  if (!is_bound_text(lo) || !is_bound_text(hi)) throw bad("bounds are decimal numbers or +-inf");
  if (lo == "inf" || lo == "+inf" || hi == "-inf") throw bad("lower bound above upper bound");
  if (appell::is_decimal_literal(lo) && appell::is_decimal_literal(hi) && lo != hi &&
      appell::decimal_sign_of_sum({{1, lo}, {-1, hi}}) > 0)
    throw bad("lower bound above upper bound");
  mpfi_backend t;  // parsed apart: a failure leaves *this as it was
  t.set_prec(prec());
  read_bound(&t.v_->left, lo, MPFR_RNDD);
  read_bound(&t.v_->right, hi, MPFR_RNDU);
  detail::mpfi_fix_zero_signs(t.v_);
  swap(t);
  return *this;
}

std::string mpfi_backend::str(std::streamsize digits, std::ios_base::fmtflags f) const {
  const mpfi_srcptr x = data();
  return enclosure_text(&x->left, &x->right, digits, f);  // both bounds at prec()
}

int mpfi_backend::compare(const mpfi_backend& o) const {
  const mpfi_srcptr x = data(), y = o.data();
  if (mpfr_cmp(&x->right, &y->left) < 0) return -1;
  if (mpfr_cmp(&x->left, &y->right) > 0) return 1;
  if (mpfr_equal_p(&x->left, &y->left) && mpfr_equal_p(&x->right, &y->right)) return 0;
  throw interval_error("undecided comparison of two intervals");
}

void mpfi_backend::set_prec(mpfr_prec_t p) {
  reshape(p);
  mpfr_set_nan(&v_->left);
  mpfr_set_nan(&v_->right);
}

void mpfi_backend::round_prec(mpfr_prec_t p) {
  if (p == prec()) return;
  mpfi_backend t;
  t.set_prec(p);
  mpfr_set(&t.v_->left, &v_->left, MPFR_RNDD);
  mpfr_set(&t.v_->right, &v_->right, MPFR_RNDU);
  detail::mpfi_fix_zero_signs(t.v_);
  swap(t);
}

int eval_get_sign(const mpfi_backend& x) {
  mpfi_srcptr p = x.data();
  if (detail::mpfi_is_zero(p)) return 0;
  if (mpfr_sgn(&p->left) > 0) return 1;
  if (mpfr_sgn(&p->right) < 0) return -1;
  throw interval_error("undecided sign of an interval");
}

int eval_fpclassify(const mpfi_backend& x) {
  mpfi_srcptr p = x.data();
  return mpfi_nan_p(p) ? FP_NAN : mpfi_inf_p(p) ? FP_INFINITE : detail::mpfi_is_zero(p) ? FP_ZERO : FP_NORMAL;
}

void eval_convert_to(double* r, const mpfi_backend& x) { *r = mpfi_get_d(x.data()); }
void eval_convert_to(long double* r, const mpfi_backend& x) { *r = mpfr_get_ld(midpoint(x).data(), MPFR_RNDN); }
void eval_convert_to(long* r, const mpfi_backend& x) { boost::multiprecision::backends::eval_convert_to(r, midpoint(x)); }
void eval_convert_to(unsigned long* r, const mpfi_backend& x) {
  boost::multiprecision::backends::eval_convert_to(r, midpoint(x));
}
void eval_convert_to(long long* r, const mpfi_backend& x) { boost::multiprecision::backends::eval_convert_to(r, midpoint(x)); }
void eval_convert_to(unsigned long long* r, const mpfi_backend& x) {
  boost::multiprecision::backends::eval_convert_to(r, midpoint(x));
}

void eval_sqrt(mpfi_backend& r, const mpfi_backend& x) {
  on_nonnegative_part(r, x, false, "sqrt of an interval below 0", mpfi_sqrt);
}
void eval_log(mpfi_backend& r, const mpfi_backend& x) {
  on_nonnegative_part(r, x, true, "log of an interval with no positive point", mpfi_log);
}
void eval_log2(mpfi_backend& r, const mpfi_backend& x) {
  on_nonnegative_part(r, x, true, "log2 of an interval with no positive point", mpfi_log2);
}
void eval_log10(mpfi_backend& r, const mpfi_backend& x) {
  on_nonnegative_part(r, x, true, "log10 of an interval with no positive point", mpfi_log10);
}
void eval_abs(mpfi_backend& r, const mpfi_backend& x) { mpfi_abs(r.data(), x.data()); }
void eval_fabs(mpfi_backend& r, const mpfi_backend& x) { mpfi_abs(r.data(), x.data()); }
void eval_exp(mpfi_backend& r, const mpfi_backend& x) { mpfi_exp(r.data(), x.data()); }
void eval_exp2(mpfi_backend& r, const mpfi_backend& x) { mpfi_exp2(r.data(), x.data()); }
void eval_asin(mpfi_backend& r, const mpfi_backend& x) { mpfi_asin(r.data(), x.data()); }
void eval_acos(mpfi_backend& r, const mpfi_backend& x) { mpfi_acos(r.data(), x.data()); }
void eval_atan(mpfi_backend& r, const mpfi_backend& x) { mpfi_atan(r.data(), x.data()); }
void eval_atan2(mpfi_backend& r, const mpfi_backend& y, const mpfi_backend& x) {
  mpfi_atan2(r.data(), y.data(), x.data());
}
void eval_hypot(mpfi_backend& r, const mpfi_backend& a, const mpfi_backend& b) { mpfi_hypot(r.data(), a.data(), b.data()); }
void eval_sinh(mpfi_backend& r, const mpfi_backend& x) { mpfi_sinh(r.data(), x.data()); }
void eval_cosh(mpfi_backend& r, const mpfi_backend& x) { mpfi_cosh(r.data(), x.data()); }
void eval_tanh(mpfi_backend& r, const mpfi_backend& x) { mpfi_tanh(r.data(), x.data()); }

// b^e into r, which aliases neither.  exp(e log b) where b >= 0 makes sense of it
// (MPFI: log 0 = -inf, exp(-inf) = 0), an integer e for b < 0; NaN bounds where
// no real power is defined on all of b and e (never a box that could miss).
static void pow_into(mpfi_backend& r, const mpfi_backend& b, const mpfi_backend& e) {
  mpfi_srcptr bp = b.data(), ep = e.data();
  const auto nan = [&] { r.set_prec(r.prec()); };
  if (mpfi_nan_p(bp) || mpfi_nan_p(ep)) return nan();
  const bool e_positive = mpfr_sgn(&ep->left) > 0;
  if (detail::mpfi_is_zero(bp)) {  // 0^e: 1 at e = 0, 0 for e > 0
    if (detail::mpfi_is_zero(ep)) r = 1ul;
    else if (e_positive) r = 0ul;
    else if (mpfr_zero_p(&ep->left)) mpfi_interv_ui(r.data(), 0, 1);  // e in [0, x]: {0, 1}
    else nan();
    return;
  }
  const bool e_integer = mpfr_equal_p(&ep->left, &ep->right) && mpfr_integer_p(&ep->left);
  if (mpfr_sgn(&bp->left) > 0 || (mpfr_zero_p(&bp->left) && e_positive)) {
    mpfi_log(r.data(), bp);
    mpfi_mul(r.data(), r.data(), ep);
    mpfi_exp(r.data(), r.data());
    return;
  }
  if (mpfr_sgn(&bp->right) < 0 && e_integer) {  // (-|b|)^n = (-1)^n |b|^n
    mpfi_backend nb = b;
    nb.negate();
    pow_into(r, nb, e);
    mpfr_b half;
    mpfr_set_prec(half.data(), e.prec());
    mpfr_div_2ui(half.data(), &ep->left, 1, MPFR_RNDN);  // exact
    if (!mpfr_integer_p(half.data())) r.negate();
    return;
  }
  nan();
}

void eval_pow(mpfi_backend& r, const mpfi_backend& b, const mpfi_backend& e) {
  mpfi_backend t;  // r may be b or e
  t.set_prec(r.prec());
  pow_into(t, b, e);
  r.swap(t);
}

// floor (rnd = RNDD) or ceil (RNDU) of both bounds, which must agree (as Boost's backend).
static void integer_part(mpfi_backend& r, const mpfi_backend& x, mpfr_rnd_t rnd, const char* what) {
  mpfr_b a, b;
  mpfr_set_prec(a.data(), x.prec());
  mpfr_set_prec(b.data(), x.prec());
  mpfr_rint(a.data(), &x.data()->left, rnd);  // exact: an integer at x's precision
  mpfr_rint(b.data(), &x.data()->right, rnd);
  if (!mpfr_equal_p(a.data(), b.data())) throw interval_error(std::string(what) + " of an interval that straddles an integer");
  mpfi_set_fr(r.data(), a.data());
}

void eval_floor(mpfi_backend& r, const mpfi_backend& x) { integer_part(r, x, MPFR_RNDD, "floor"); }
void eval_ceil(mpfi_backend& r, const mpfi_backend& x) { integer_part(r, x, MPFR_RNDU, "ceil"); }

void eval_ldexp(mpfi_backend& r, const mpfi_backend& x, long e) { mpfi_mul_2si(r.data(), x.data(), e); }

void eval_frexp(mpfi_backend& r, const mpfi_backend& x, long* e) {
  // The exponent of the midpoint; both bounds scaled by it (exact).
  const mpfr_b m = midpoint(x);
  *e = mpfr_zero_p(m.data()) || !mpfr_number_p(m.data()) ? 0 : mpfr_get_exp(m.data());
  mpfi_mul_2si(r.data(), x.data(), -*e);
}

void eval_frexp(mpfi_backend& r, const mpfi_backend& x, int* e) {
  long l = 0;
  eval_frexp(r, x, &l);
  *e = static_cast<int>(l);
}

void assign_components(mpfi_backend& r, const mpfr_backend& a, const mpfr_backend& b) {
  if (mpfr_nan_p(a.data()) || mpfr_nan_p(b.data()) || mpfr_cmp(a.data(), b.data()) > 0)
    throw std::runtime_error("an interval needs lower <= upper, and no NaN");
  mpfi_interv_fr(r.data(), a.data(), b.data());  // outward at r's precision
}

void generic_interconvert(mpfr_backend& to, const mpfi_backend& from,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&,
                          const boost::mpl::int_<boost::multiprecision::number_kind_floating_point>&) {
  mpfi_mid(to.data(), from.data());
}

namespace {
// f(x) at x's precision, as Boost's number-level functions of its mpfi backend.
mpfi_number apply(int (*f)(mpfi_ptr, mpfi_srcptr), const mpfi_number& x) {
  mpfi_number r;
  r.backend().set_prec(x.backend().prec());
  f(r.backend().data(), x.backend().data());
  return r;
}
}  // namespace

mpfi_number cbrt(const mpfi_number& x) { return apply(mpfi_cbrt, x); }
mpfi_number log1p(const mpfi_number& x) { return apply(mpfi_log1p, x); }
mpfi_number expm1(const mpfi_number& x) { return apply(mpfi_expm1, x); }
mpfi_number asinh(const mpfi_number& x) { return apply(mpfi_asinh, x); }
mpfi_number acosh(const mpfi_number& x) { return apply(mpfi_acosh, x); }
mpfi_number atanh(const mpfi_number& x) { return apply(mpfi_atanh, x); }

}  // namespace appell::mp
