// Rigorous elementary functions of appell::interval.
//
// Each bound is a value of MPFR (correctly rounded, in the direction asked)
// at an exactly representable double, so no assumption is made on libm.
// Monotone functions take their bounds at the endpoints; for sin, cos and tan
// the extrema and poles inside the argument are located by the quadrant index
// floor(x / (pi/2)) of each endpoint, computed with enclosures of pi at a
// precision that grows until the floor is certain (exact for every double,
// however large: the reduction is done at exponent(x) + 128 bits or more).
#include <mpfr.h>
#include <gmp.h>

#include "appell/scalar/interval.hpp"
#include "appell/scalar/decimal.hpp"

#include <cmath>
#include <limits>

namespace appell {
namespace {

using unary_mpfr = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

// f(x) rounded to a double in direction rnd.  A 53-bit MPFR result is rounded
// again by mpfr_get_d only in the subnormal range, and in the same direction.
double eval(unary_mpfr f, double x, mpfr_rnd_t rnd) {
  mpfr_value a(53), r(53);
  mpfr_set_d(a, x, MPFR_RNDN);  // exact
  f(r, a, rnd);
  return mpfr_get_d(r, rnd);
}
double down(unary_mpfr f, double x) { return eval(f, x, MPFR_RNDD); }
double up(unary_mpfr f, double x) { return eval(f, x, MPFR_RNDU); }

double pow_dir(double x, long n, mpfr_rnd_t rnd) {
  mpfr_value a(53), r(53);
  mpfr_set_d(a, x, MPFR_RNDN);
  mpfr_pow_si(r, a, n, rnd);
  return mpfr_get_d(r, rnd);
}

constexpr double inf = std::numeric_limits<double>::infinity();

interval entire() { return interval(-inf, inf); }

// floor(x / (pi/2)) for finite x, certified.
void quadrant(double x, mpz_t k) {
  if (x == 0) {
    mpz_set_si(k, 0);
    return;
  }
  int e = 0;
  std::frexp(x, &e);
  mpz_t k_other;
  mpz_init(k_other);
  for (mpfr_prec_t prec = std::max(e, 0) + 128;; prec *= 2) {
    mpfr_value pi_lo(prec), pi_hi(prec), two_x(prec), t_lo(prec), t_hi(prec);
    mpfr_const_pi(pi_lo, MPFR_RNDD);
    mpfr_const_pi(pi_hi, MPFR_RNDU);
    mpfr_set_d(two_x, x, MPFR_RNDN);
    mpfr_mul_2ui(two_x, two_x, 1, MPFR_RNDN);  // exact
    // t = 2x/pi lies in [t_lo, t_hi].
    if (x > 0) {
      mpfr_div(t_lo, two_x, pi_hi, MPFR_RNDD);
      mpfr_div(t_hi, two_x, pi_lo, MPFR_RNDU);
    } else {
      mpfr_div(t_lo, two_x, pi_lo, MPFR_RNDD);
      mpfr_div(t_hi, two_x, pi_hi, MPFR_RNDU);
    }
    mpfr_get_z(k, t_lo, MPFR_RNDD);
    mpfr_get_z(k_other, t_hi, MPFR_RNDD);
    if (mpz_cmp(k, k_other) == 0) break;
    if (prec > 1 << 16) {  // cannot happen for a double: pi is irrational
      mpz_clear(k_other);
      throw domain_error("range reduction did not converge");
    }
  }
  mpz_clear(k_other);
}

// Quadrant indices of the endpoints: ka = floor(lo/(pi/2)), diff = kb - ka.
struct quadrants {
  long ka_mod4;
  long diff;
  // Is there a multiple q of pi/2 in (lo, hi] with q = c (mod 4)?
  bool crosses(long c) const {
    long offset = (((c - ka_mod4 - 1) % 4) + 4) % 4;
    return offset < diff;
  }
};

quadrants locate(const interval& x) {
  mpz_t ka, kb;
  mpz_init(ka);
  mpz_init(kb);
  quadrant(x.lower(), ka);
  quadrant(x.upper(), kb);
  quadrants q{static_cast<long>(mpz_fdiv_ui(ka, 4)), 0};
  mpz_sub(kb, kb, ka);
  q.diff = mpz_get_si(kb);
  mpz_clear(ka);
  mpz_clear(kb);
  return q;
}

bool has_infinite_bound(const interval& x) {
  return !std::isfinite(x.lower()) || !std::isfinite(x.upper());
}

// Wider than 2 pi for sure (6.3 > 2 pi even after a rounding error).
bool covers_period(const interval& x) { return x.upper() - x.lower() > 6.3; }

}  // namespace

interval sqrt(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (x.upper() < 0) throw domain_error("sqrt of an interval below 0");
  double lo = x.lower() <= 0 ? 0.0 : down(mpfr_sqrt, x.lower());
  return interval(lo, up(mpfr_sqrt, x.upper()));
}

interval exp(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  return interval(down(mpfr_exp, x.lower()), up(mpfr_exp, x.upper()));
}

interval log(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (x.upper() <= 0) throw domain_error("log of an interval with no positive point");
  double lo = x.lower() <= 0 ? -inf : down(mpfr_log, x.lower());
  return interval(lo, up(mpfr_log, x.upper()));
}

interval atan(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  return interval(down(mpfr_atan, x.lower()), up(mpfr_atan, x.upper()));
}

interval sin(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return interval(-1.0, 1.0);
  const quadrants q = locate(x);
  double lo = std::min(down(mpfr_sin, x.lower()), down(mpfr_sin, x.upper()));
  double hi = std::max(up(mpfr_sin, x.lower()), up(mpfr_sin, x.upper()));
  if (q.crosses(1)) hi = 1.0;   // sin(pi/2 + 2 k pi) = 1
  if (q.crosses(3)) lo = -1.0;  // sin(3 pi/2 + 2 k pi) = -1
  return interval(lo, hi);
}

interval cos(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return interval(-1.0, 1.0);
  const quadrants q = locate(x);
  double lo = std::min(down(mpfr_cos, x.lower()), down(mpfr_cos, x.upper()));
  double hi = std::max(up(mpfr_cos, x.lower()), up(mpfr_cos, x.upper()));
  if (q.crosses(0)) hi = 1.0;   // cos(2 k pi) = 1
  if (q.crosses(2)) lo = -1.0;  // cos(pi + 2 k pi) = -1
  return interval(lo, hi);
}

interval tan(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return entire();
  const quadrants q = locate(x);
  if (q.crosses(1) || q.crosses(3)) return entire();  // a pole pi/2 + k pi inside
  return interval(down(mpfr_tan, x.lower()), up(mpfr_tan, x.upper()));
}

interval pown(const interval& x, int n) {
  if (boost::numeric::empty(x)) return x;
  const double lo = x.lower(), hi = x.upper();
  const auto d = [n](double v) { return pow_dir(v, n, MPFR_RNDD); };
  const auto u = [n](double v) { return pow_dir(v, n, MPFR_RNDU); };
  if (n == 0) return interval(1.0, 1.0);
  const bool even = n % 2 == 0;
  if (n > 0) {
    if (!even) return interval(d(lo), u(hi));
    if (lo >= 0) return interval(d(lo), u(hi));
    if (hi <= 0) return interval(d(hi), u(lo));
    return interval(0.0, u(std::max(-lo, hi)));
  }
  // n < 0: x^n = 1 / x^|n|
  if (lo > 0) return interval(d(hi), u(lo));
  if (hi < 0) return even ? interval(d(lo), u(hi)) : interval(d(hi), u(lo));
  if (lo == 0 && hi == 0) throw domain_error("negative power of [0, 0]");
  if (even) return interval(d(std::max(-lo, hi)), inf);
  if (lo == 0) return interval(d(hi), inf);
  if (hi == 0) return interval(-inf, u(lo));
  return entire();
}

interval sqr(const interval& x) { return pown(x, 2); }

interval abs(const interval& x) { return boost::numeric::abs(x); }

interval interval_pi() { return constant_pi<interval>(); }

}  // namespace appell
