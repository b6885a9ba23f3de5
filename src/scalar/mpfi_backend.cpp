// appell::mp::mpfi_backend: the out-of-line members and functions (see mpfi_backend.hpp).
#include "appell/scalar/mpfi_backend.hpp"

#include <cstdio>

#include "appell/scalar/interval.hpp"  // appell::domain_error

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

mpfi_backend& mpfi_backend::operator=(const char* s) {
  ensure();
  if (!s || mpfi_set_str(v_, s, 10) != 0)
    throw std::runtime_error(std::string("not a number or interval: \"") + (s ? s : "") + "\"");
  return *this;
}

std::string mpfi_backend::str(std::streamsize digits, std::ios_base::fmtflags f) const {
  mpfr_b a, b;
  mpfr_set_prec(a.data(), prec());
  mpfr_set_prec(b.data(), prec());
  mpfr_set(a.data(), &v_->left, MPFR_RNDN);  // exact
  mpfr_set(b.data(), &v_->right, MPFR_RNDN);
  if (mpfr_equal_p(a.data(), b.data())) return a.str(digits, f);
  return "{" + a.str(digits, f) + "," + b.str(digits, f) + "}";
}

int mpfi_backend::compare(const mpfi_backend& o) const {
  if (mpfr_cmp(&v_->right, &o.v_->left) < 0) return -1;
  if (mpfr_cmp(&v_->left, &o.v_->right) > 0) return 1;
  if (mpfr_equal_p(&v_->left, &o.v_->left) && mpfr_equal_p(&v_->right, &o.v_->right)) return 0;
  throw interval_error("undecided comparison of two intervals");
}

void mpfi_backend::set_prec(mpfr_prec_t p) {
  reshape(p);
  mpfr_set_nan(&v_->left);
  mpfr_set_nan(&v_->right);
}

void mpfi_backend::round_prec(mpfr_prec_t p) {
  if (block_ && p == prec()) return;
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

int eval_fpclassify(const mpfi_backend& x) noexcept {
  mpfi_srcptr p = x.data();
  return mpfi_nan_p(p) ? FP_NAN : mpfi_inf_p(p) ? FP_INFINITE : detail::mpfi_is_zero(p) ? FP_ZERO : FP_NORMAL;
}

void eval_convert_to(double* r, const mpfi_backend& x) noexcept { *r = mpfi_get_d(x.data()); }
void eval_convert_to(long double* r, const mpfi_backend& x) noexcept { *r = mpfr_get_ld(midpoint(x).data(), MPFR_RNDN); }
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
void eval_tan(mpfi_backend& r, const mpfi_backend& x) { mpfi_tan(r.data(), x.data()); }
void eval_asin(mpfi_backend& r, const mpfi_backend& x) { mpfi_asin(r.data(), x.data()); }
void eval_acos(mpfi_backend& r, const mpfi_backend& x) { mpfi_acos(r.data(), x.data()); }
void eval_atan(mpfi_backend& r, const mpfi_backend& x) { mpfi_atan(r.data(), x.data()); }
void eval_atan2(mpfi_backend& r, const mpfi_backend& y, const mpfi_backend& x) {
  mpfi_atan2(r.data(), y.data(), x.data());
}
void eval_sinh(mpfi_backend& r, const mpfi_backend& x) { mpfi_sinh(r.data(), x.data()); }
void eval_cosh(mpfi_backend& r, const mpfi_backend& x) { mpfi_cosh(r.data(), x.data()); }
void eval_tanh(mpfi_backend& r, const mpfi_backend& x) { mpfi_tanh(r.data(), x.data()); }

void eval_pow(mpfi_backend& r, const mpfi_backend& b, const mpfi_backend& e) {
  // The cases of Boost's mpfi_float_backend: b = [0, 0] gives 1 (e = [0, 0]) or 0;
  // b > 0 gives exp(e log b); b < 0 needs an integer e; anything else is NaN.
  if (detail::mpfi_is_zero(b.data())) {
    r = detail::mpfi_is_zero(e.data()) ? 1ul : 0ul;
    return;
  }
  if (mpfr_sgn(&b.data()->left) > 0) {
    mpfi_log(r.data(), b.data());
    mpfi_mul(r.data(), r.data(), e.data());
    mpfi_exp(r.data(), r.data());
    return;
  }
  if (mpfr_sgn(&b.data()->right) < 0 && mpfr_equal_p(&e.data()->left, &e.data()->right) &&
      mpfr_integer_p(&e.data()->left)) {
    mpfi_backend nb = b;
    nb.negate();
    eval_pow(r, nb, e);  // |b|^e, then the sign of an odd power
    mpfr_b half;
    mpfr_set_prec(half.data(), e.prec());
    mpfr_div_2ui(half.data(), &e.data()->left, 1, MPFR_RNDN);  // exact
    if (!mpfr_integer_p(half.data())) r.negate();
    return;
  }
  r.set_prec(r.prec());  // NaN: no real power defined on all of b
}

void eval_floor(mpfi_backend& r, const mpfi_backend& x) {
  mpfr_b a, b;
  mpfr_set_prec(a.data(), x.prec());
  mpfr_set_prec(b.data(), x.prec());
  mpfr_floor(a.data(), &x.data()->left);
  mpfr_floor(b.data(), &x.data()->right);
  if (!mpfr_equal_p(a.data(), b.data())) throw interval_error("floor of an interval that straddles an integer");
  mpfi_set_fr(r.data(), a.data());
}

void eval_ceil(mpfi_backend& r, const mpfi_backend& x) {
  mpfr_b a, b;
  mpfr_set_prec(a.data(), x.prec());
  mpfr_set_prec(b.data(), x.prec());
  mpfr_ceil(a.data(), &x.data()->left);
  mpfr_ceil(b.data(), &x.data()->right);
  if (!mpfr_equal_p(a.data(), b.data())) throw interval_error("ceil of an interval that straddles an integer");
  mpfi_set_fr(r.data(), a.data());
}

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

}  // namespace appell::mp
