// appell::mp::mpfr_backend: the out-of-line members and functions (see mpfr_backend.hpp).
#include "appell/scalar/mpfr_backend.hpp"

#include <stdexcept>

namespace appell::mp {

namespace {
using boost_mpfr = boost::multiprecision::backends::mpfr_float_backend<0>;

// x as Boost's backend at x's precision (exact): for the few operations whose exact
// behaviour this backend takes over from Boost's (text, integer conversions).
boost_mpfr as_boost(const mpfr_backend& x) {
  boost_mpfr b;
  mpfr_set_prec(b.data(), x.prec());
  mpfr_set(b.data(), x.data(), MPFR_RNDN);
  return b;
}
}  // namespace

mpfr_backend& mpfr_backend::operator=(const char* s) {
  mpfr_backend t;  // parsed apart: a failure leaves *this as it was
  t.set_prec(prec());
  if (!s || mpfr_set_str(t.data(), s, 10, MPFR_RNDN) != 0)
    throw std::runtime_error(std::string("not a number: \"") + (s ? s : "") + "\"");
  swap(t);
  return *this;
}

std::string mpfr_backend::str(std::streamsize digits, std::ios_base::fmtflags f) const {
  return as_boost(*this).str(digits, f);
}

void mpfr_backend::round_prec(mpfr_prec_t p) {
  if (p == prec()) return;
  mpfr_backend t;
  t.set_prec(p);
  mpfr_set(t.data(), data(), MPFR_RNDN);
  swap(t);
}

void eval_convert_to(long* r, const mpfr_backend& x) { boost::multiprecision::backends::eval_convert_to(r, as_boost(x)); }
void eval_convert_to(unsigned long* r, const mpfr_backend& x) {
  boost::multiprecision::backends::eval_convert_to(r, as_boost(x));
}
void eval_convert_to(long long* r, const mpfr_backend& x) { boost::multiprecision::backends::eval_convert_to(r, as_boost(x)); }
void eval_convert_to(unsigned long long* r, const mpfr_backend& x) {
  boost::multiprecision::backends::eval_convert_to(r, as_boost(x));
}

void eval_modf(mpfr_backend& r, const mpfr_backend& x, mpfr_backend* integer_part) {
  mpfr_backend i;
  i.set_prec(x.prec());
  mpfr_modf(integer_part ? integer_part->data() : i.data(), r.data(), x.data(), MPFR_RNDN);
}

void eval_pow(mpfr_backend& r, const mpfr_backend& b, const mpfr_backend& e) {
  const mpfr_srcptr bp = b.data(), ep = e.data();
  if (mpfr_zero_p(bp) && mpfr_integer_p(ep) && !mpfr_signbit(ep) && mpfr_fits_ulong_p(ep, MPFR_RNDN) &&
      (mpfr_get_ui(ep, MPFR_RNDN) & 1))
    mpfr_set(r.data(), bp, MPFR_RNDN);
  else
    mpfr_pow(r.data(), bp, ep, MPFR_RNDN);
}

namespace {
// f(x) under Boost's precision guard for x, as Boost's number-level functions.
mpfr_number apply(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), const mpfr_number& x) {
  const boost::multiprecision::detail::scoped_default_precision<mpfr_number> guard(x);
  mpfr_number r;
  f(r.backend().data(), x.backend().data(), MPFR_RNDN);
  return r;
}
}  // namespace

mpfr_number cbrt(const mpfr_number& x) { return apply(mpfr_cbrt, x); }
mpfr_number log1p(const mpfr_number& x) { return apply(mpfr_log1p, x); }
mpfr_number expm1(const mpfr_number& x) { return apply(mpfr_expm1, x); }
mpfr_number asinh(const mpfr_number& x) { return apply(mpfr_asinh, x); }
mpfr_number acosh(const mpfr_number& x) { return apply(mpfr_acosh, x); }
mpfr_number atanh(const mpfr_number& x) { return apply(mpfr_atanh, x); }

}  // namespace appell::mp
