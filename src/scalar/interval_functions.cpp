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
#include <cstdint>
#include <cstring>
#include <limits>

namespace appell {
namespace {

using unary_mpfr = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

// Directed double operations for the mean-value bounds (the SSE unit is in
// round-to-nearest here: switch it for the one operation).
double directed(double a, double b, bool add, unsigned mode) {
  const unsigned csr = detail::read_mxcsr();
  detail::write_mxcsr((csr & ~detail::mxcsr_mode) | mode);
  const double r = add ? interval_arith::opaque(interval_arith::opaque(a) + interval_arith::opaque(b))
                       : interval_arith::opaque(interval_arith::opaque(a) - interval_arith::opaque(b));
  detail::write_mxcsr(csr);
  return r;
}
double up_add(double a, double b) { return directed(a, b, true, detail::mxcsr_upward); }
double up_sub(double a, double b) { return directed(a, b, false, detail::mxcsr_upward); }
double down_sub(double a, double b) { return directed(a, b, false, 0x2000); }

// Two 53-bit MPFR numbers per thread, made once (mpfr_init/clear per call cost
// as much as a 53-bit sine).
struct scratch {
  mpfr_value a{53}, r{53};
};
scratch& work() {
  thread_local scratch s;
  return s;
}

// f(x) rounded to a double in direction rnd.  A 53-bit MPFR result is rounded
// again by mpfr_get_d only in the subnormal range, and in the same direction.
double eval(unary_mpfr f, double x, mpfr_rnd_t rnd) {
  scratch& s = work();
  mpfr_set_d(s.a, x, MPFR_RNDN);  // exact
  f(s.r, s.a, rnd);
  return mpfr_get_d(s.r, rnd);
}

// A small per-thread memo of recent results: the kinematics of one evaluation
// ask for sin and cos of the same angles many times (once per differentiated
// pass).  Keyed on the exact bounds and the function; results are pure.
struct memo {
  struct entry {
    const void* fn = nullptr;
    double lo = 0, hi = 0;
    std::uint64_t epoch = 0;
    interval value;
  };
  std::uint64_t epoch = 1;  // entries of earlier evaluations are stale
  static constexpr std::size_t size = 64;
  entry slots[size];
  static std::uint64_t mix(std::uint64_t z) {  // splitmix64 finaliser
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  static std::size_t slot(const void* fn, double lo, double hi) {
    std::uint64_t a, b;
    std::memcpy(&a, &lo, 8);
    std::memcpy(&b, &hi, 8);
    return static_cast<std::size_t>(mix(a ^ mix(b ^ mix(reinterpret_cast<std::uintptr_t>(fn)))) % size);
  }
  bool find(const void* fn, const interval& x, interval& out) {
    const entry& e = slots[slot(fn, x.lower(), x.upper())];
    if (e.epoch == epoch && e.fn == fn && std::memcmp(&e.lo, &x.lower(), 8) == 0 &&
        std::memcmp(&e.hi, &x.upper(), 8) == 0) {
      out = e.value;
      return true;
    }
    return false;
  }
  void put(const void* fn, const interval& x, const interval& v) {
    entry& e = slots[slot(fn, x.lower(), x.upper())];
    e.epoch = epoch;
    e.fn = fn;
    e.lo = x.lower();
    e.hi = x.upper();
    e.value = v;
  }
  template <class F>
  interval get(const void* fn, const interval& x, F compute) {
    entry& e = slots[slot(fn, x.lower(), x.upper())];
    // bitwise comparison of the bounds (so -0 and +0, or NaN, never alias)
    if (e.epoch == epoch && e.fn == fn && std::memcmp(&e.lo, &x.lower(), 8) == 0 &&
        std::memcmp(&e.hi, &x.upper(), 8) == 0)
      return e.value;
    const interval v = compute();
    e.epoch = epoch;
    e.fn = fn;
    e.lo = x.lower();
    e.hi = x.upper();
    e.value = v;
    return v;
  }
};
memo& cache() {
  thread_local memo m;
  return m;
}
double down(unary_mpfr f, double x) { return eval(f, x, MPFR_RNDD); }
double up(unary_mpfr f, double x) { return eval(f, x, MPFR_RNDU); }

// Both directed roundings of f(x) from one MPFR call: y = RN(f(x)) with its
// ternary value t tells on which side of y the exact value lies (t > 0: y is
// above it, so RD = pred(y); t < 0: RU = succ(y); t = 0: exact).
std::pair<double, double> both(unary_mpfr f, double x) {
  scratch& s = work();
  mpfr_set_d(s.a, x, MPFR_RNDN);
  const int t = f(s.r, s.a, MPFR_RNDN);
  if (t == 0) return {mpfr_get_d(s.r, MPFR_RNDD), mpfr_get_d(s.r, MPFR_RNDU)};
  mpfr_set(s.a, s.r, MPFR_RNDN);  // the neighbour, at 53 bits, exact
  if (t > 0) mpfr_nextbelow(s.a);
  else mpfr_nextabove(s.a);
  const double y_lo = t > 0 ? mpfr_get_d(s.a, MPFR_RNDD) : mpfr_get_d(s.r, MPFR_RNDD);
  const double y_hi = t > 0 ? mpfr_get_d(s.r, MPFR_RNDU) : mpfr_get_d(s.a, MPFR_RNDU);
  return {y_lo, y_hi};
}

// Thin or narrow arguments far from every multiple of pi/2 need no certified
// range reduction: t = x (2/pi) in double is within 1e-9 of the true value for
// |x| < 2^20, so if [t_lo - 1e-8, t_hi + 1e-8] holds no integer, neither does
// the true [lo, hi] (2/pi).
bool clear_of_quadrant_boundaries(const interval& x) {
  if (!(std::abs(x.lower()) < 1048576.0 && std::abs(x.upper()) < 1048576.0)) return false;
  const double two_over_pi = 0.63661977236758134;
  const double a = x.lower() * two_over_pi - 1e-8, b = x.upper() * two_over_pi + 1e-8;
  return std::floor(a) == std::floor(b);  // no integer in (a, b], so none in [t_lo, t_hi]
}

double pow_dir(double x, long n, mpfr_rnd_t rnd) {
  scratch& s = work();
  mpfr_set_d(s.a, x, MPFR_RNDN);
  mpfr_pow_si(s.r, s.a, n, rnd);
  return mpfr_get_d(s.r, rnd);
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

// IEEE 754 square root is correctly rounded in every rounding mode: the
// hardware's, under downward and upward rounding of the SSE unit (the flag
// -fno-builtin-sqrt keeps GCC from folding it under the wrong mode).
double sqrt_directed(double x, unsigned mode) {
  const unsigned csr = detail::read_mxcsr();
  detail::write_mxcsr((csr & ~detail::mxcsr_mode) | mode);
  const double r = interval_arith::opaque(std::sqrt(interval_arith::opaque(x)));
  detail::write_mxcsr(csr);
  return r;
}

static interval sqrt_uncached(const interval& x) {
  if (boost::numeric::empty(x)) return x;
  if (x.upper() < 0) throw domain_error("sqrt of an interval below 0");
  const double lo = x.lower() <= 0 ? 0.0 : sqrt_directed(x.lower(), 0x2000);
  return interval(lo, sqrt_directed(x.upper(), detail::mxcsr_upward));
}

static interval exp_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  return interval(both(mpfr_exp, x.lower()).first, both(mpfr_exp, x.upper()).second);
}

static interval log_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  if (x.upper() <= 0) throw domain_error("log of an interval with no positive point");
  double lo = x.lower() <= 0 ? -inf : down(mpfr_log, x.lower());
  return interval(lo, up(mpfr_log, x.upper()));
}

static interval atan_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  return interval(both(mpfr_atan, x.lower()).first, both(mpfr_atan, x.upper()).second);
}

static interval sin_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return interval(-1.0, 1.0);
  const auto [a_lo, a_hi] = both(mpfr_sin, x.lower());
  if (x.lower() == x.upper()) return interval(a_lo, a_hi);
  const auto [b_lo, b_hi] = both(mpfr_sin, x.upper());
  double lo = std::min(a_lo, b_lo), hi = std::max(a_hi, b_hi);
  if (clear_of_quadrant_boundaries(x)) return interval(lo, hi);
  const quadrants q = locate(x);
  if (q.crosses(1)) hi = 1.0;   // sin(pi/2 + 2 k pi) = 1
  if (q.crosses(3)) lo = -1.0;  // sin(3 pi/2 + 2 k pi) = -1
  return interval(lo, hi);
}

static interval cos_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return interval(-1.0, 1.0);
  const auto [a_lo, a_hi] = both(mpfr_cos, x.lower());
  if (x.lower() == x.upper()) return interval(a_lo, a_hi);
  const auto [b_lo, b_hi] = both(mpfr_cos, x.upper());
  double lo = std::min(a_lo, b_lo), hi = std::max(a_hi, b_hi);
  if (clear_of_quadrant_boundaries(x)) return interval(lo, hi);
  const quadrants q = locate(x);
  if (q.crosses(0)) hi = 1.0;   // cos(2 k pi) = 1
  if (q.crosses(2)) lo = -1.0;  // cos(pi + 2 k pi) = -1
  return interval(lo, hi);
}

static interval tan_uncached(const interval& x) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
  if (boost::numeric::empty(x)) return x;
  if (has_infinite_bound(x) || covers_period(x)) return entire();
  if (x.lower() != x.upper() && !clear_of_quadrant_boundaries(x)) {
    const quadrants q = locate(x);
    if (q.crosses(1) || q.crosses(3)) return entire();  // a pole pi/2 + k pi inside
  }
  return interval(both(mpfr_tan, x.lower()).first, both(mpfr_tan, x.upper()).second);
}

namespace {
const char sin_tag = 0, cos_tag = 0;

// sin and cos of a narrow argument from one MPFR call: both are 1-Lipschitz,
// so with m a double in x and r >= max |x - m|,
//   sin(x) in [RD(sin m) - r, RU(sin m) + r],  cos(x) likewise,
// the two roundings of each value read off mpfr_sin_cos's ternary result.
// The mean-value form of both methods below: a double m in x and r >= max |x - m|
// (rounded up), for finite arguments no wider than 1e-9 relative; false otherwise.
bool narrow_midpoint(const interval& x, double& m, double& r) {
  const double lo = x.lower(), hi = x.upper();
  if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
  m = lo + (hi - lo) / 2;  // any double in [lo, hi] will do
  if (!(lo <= m && m <= hi)) return false;
  r = std::max(up_sub(hi, m), up_sub(m, lo));
  return r <= 1e-9 * std::max(1.0, std::abs(m));  // narrow arguments only
}

bool sin_cos_narrow(const interval& x, interval& s, interval& c) {
  double m, r;
  if (!narrow_midpoint(x, m, r)) return false;
  scratch& w = work();
  mpfr_set_d(w.a, m, MPFR_RNDN);
  thread_local mpfr_value cm(53);
  const int t = mpfr_sin_cos(w.r, cm, w.a, MPFR_RNDN);
  // t = ts + 4 tc, with ts, tc = 0 (exact), 1 (rounded up) or 2 (rounded down)
  auto bounds = [](mpfr_ptr y, int ternary, double& b_lo, double& b_hi) {
    thread_local mpfr_value n(53);
    mpfr_set(n, y, MPFR_RNDN);
    if (ternary == 1) mpfr_nextbelow(n);  // y above the exact value
    if (ternary == 2) mpfr_nextabove(n);  // y below it
    b_lo = mpfr_get_d(ternary == 1 ? n.get() : y, MPFR_RNDD);
    b_hi = mpfr_get_d(ternary == 2 ? n.get() : y, MPFR_RNDU);
  };
  double s_lo, s_hi, c_lo, c_hi;
  bounds(w.r, t & 3, s_lo, s_hi);
  bounds(cm, (t >> 2) & 3, c_lo, c_hi);
  s = interval(std::max(-1.0, down_sub(s_lo, r)), std::min(1.0, up_add(s_hi, r)));
  c = interval(std::max(-1.0, down_sub(c_lo, r)), std::min(1.0, up_add(c_hi, r)));
  return true;
}

// sin and cos of an argument of modest size (|x| < 2^20, width < 1e-3) in
// interval<double> arithmetic, four times cheaper than one mpfr_sin_cos:
//  1. Cody-Waite reduction y = x - k pi/2, pi/2 = P1 + P2 + P3 with P1, P2 of
//     33 bits (k P1 and k P2 exact for k < 2^20; x - k P1 exact by Sterbenz)
//     and P3 an enclosure of the rest, every step in interval arithmetic;
//     (at a double mid of x; the result is widened by r >= |x - mid|, as
//     sin and cos are 1-Lipschitz: tight to first order in x's width);
//  2. Taylor polynomials on |y| <= pi/4 + 1e-3, sin to degree 19 and cos to
//     degree 18, coefficients 1/n! enclosed, Horner in interval arithmetic,
//     plus the Lagrange remainder |y|^21/21! (resp. |y|^20/20!) as [-R, R];
//  3. the quadrant k mod 4 maps (sin y, cos y) to (sin x, cos x).
// Each constant is made once by MPFR with directed rounding.
struct sin_cos_tables {
  double P1, P2;
  interval P3;
  interval inv_factorial[21];  // 1/n!, n = 0..20
  interval rest_sin, rest_cos; // 1/21!, 1/20!
  sin_cos_tables() {
    const nearest_rounding mode;
    mpfr_value pio2(400), part(400), t(400);
    mpfr_const_pi(pio2, MPFR_RNDN);
    mpfr_div_2ui(pio2, pio2, 1, MPFR_RNDN);  // pi/2 to 400 bits (the enclosure of the rest uses it +- 2^-398)
    mpfr_value p33(33);
    mpfr_set(p33, pio2, MPFR_RNDN);
    P1 = mpfr_get_d(p33, MPFR_RNDN);  // exact: 33 bits
    mpfr_sub(part, pio2, p33, MPFR_RNDN);  // exact at 400 bits
    mpfr_set(p33, part, MPFR_RNDN);
    P2 = mpfr_get_d(p33, MPFR_RNDN);
    mpfr_sub(part, part, p33, MPFR_RNDN);  // the rest, to ~2^-398 of pi/2
    mpfr_value lo(400), hi(400);
    mpfr_set_d(t, 0x1p-390, MPFR_RNDN);
    mpfr_sub(lo, part, t, MPFR_RNDD);
    mpfr_add(hi, part, t, MPFR_RNDU);
    P3 = interval(mpfr_get_d(lo, MPFR_RNDD), mpfr_get_d(hi, MPFR_RNDU));
    mpfr_value f(400);
    mpfr_set_ui(f, 1, MPFR_RNDN);
    for (unsigned n = 0; n <= 21; ++n) {
      if (n > 0) mpfr_mul_ui(f, f, n, MPFR_RNDN);  // n! exactly (21! < 2^400)
      mpfr_ui_div(t, 1, f, MPFR_RNDD);
      const double d = mpfr_get_d(t, MPFR_RNDD);
      mpfr_ui_div(t, 1, f, MPFR_RNDU);
      const interval v(d, mpfr_get_d(t, MPFR_RNDU));
      if (n <= 20) inv_factorial[n] = v;
      if (n == 20) rest_cos = v;
      if (n == 21) rest_sin = v;
    }
  }
};

bool sin_cos_polynomial(const interval& x, interval& s, interval& c) {
  if (!(std::abs(x.lower()) < 1048576.0 && std::abs(x.upper()) < 1048576.0)) return false;
  // Mean-value form, as in sin_cos_narrow: evaluate at a double mid in x, then
  // widen by r >= max |x - mid| (sin and cos are 1-Lipschitz).  Wider arguments:
  // endpoints and quadrants.
  double mid, r;
  if (!narrow_midpoint(x, mid, r)) return false;
  static const sin_cos_tables tab;
  const double k = std::nearbyint(mid * 0.63661977236758134);  // any integer near mid / (pi/2)
  const upward_rounding mode;
  const interval kI(k);
  // mid - k P1 - k P2 - k P3; the first two products are exact, the rest is interval arithmetic
  const interval y = ((interval(mid) - interval(k * tab.P1)) - interval(k * tab.P2)) - kI * tab.P3;
  const double m = std::max(std::abs(y.lower()), std::abs(y.upper()));
  if (!(m <= 0.7863981633974483)) return false;  // pi/4 + 1e-3: the remainders below assume it
  const interval y2 = y * y;
  interval ps = tab.inv_factorial[19], pc = tab.inv_factorial[18];
  for (int n = 17; n >= 1; n -= 2) ps = tab.inv_factorial[n] - y2 * ps;  // 1/n! - y^2 (...)
  for (int n = 16; n >= 0; n -= 2) pc = tab.inv_factorial[n] - y2 * pc;
  // sin y = y ps + R, |R| <= m^21/21!;  cos y = pc + R, |R| <= m^20/20!
  // powers of m >= 0, each product rounded up (upward mode): upper bounds
  auto up_mul = [](double a, double b) { return interval_arith::opaque(interval_arith::opaque(a) * interval_arith::opaque(b)); };
  const double m2 = up_mul(m, m), m4 = up_mul(m2, m2), m8 = up_mul(m4, m4), m16 = up_mul(m8, m8);
  const double p20 = up_mul(m16, m4);
  const double r_cos = up_mul(p20, tab.rest_cos.upper());
  const double r_sin = up_mul(up_mul(p20, m), tab.rest_sin.upper());
  const double ws = interval_arith::opaque(r_sin + r), wc = interval_arith::opaque(r_cos + r);  // rounded up
  const interval sy = y * ps + interval(-ws, ws), cy = pc + interval(-wc, wc);
  const long q = static_cast<long>(std::fmod(k, 4.0) + 4) % 4;
  const interval unit(-1.0, 1.0);
  switch (q) {
    case 0: s = sy; c = cy; break;
    case 1: s = cy; c = -sy; break;
    case 2: s = -sy; c = -cy; break;
    default: s = -cy; c = sy; break;
  }
  s = boost::numeric::intersect(s, unit);
  c = boost::numeric::intersect(c, unit);
  return true;
}

// both values at once, remembered under both tags
interval sin_or_cos(const interval& x, bool want_sin) {
  const char* mine = want_sin ? &sin_tag : &cos_tag;
  interval value;
  if (cache().find(mine, x, value)) return value;
  const nearest_rounding mpfr_mode;
  interval s, c;
  if (sin_cos_polynomial(x, s, c) || sin_cos_narrow(x, s, c)) {
    cache().put(&sin_tag, x, s);
    cache().put(&cos_tag, x, c);
    return want_sin ? s : c;
  }
  const interval v = want_sin ? sin_uncached(x) : cos_uncached(x);
  cache().put(mine, x, v);
  return v;
}
}  // namespace

interval sin(const interval& x) { return sin_or_cos(x, true); }

interval cos(const interval& x) { return sin_or_cos(x, false); }



interval tan(const interval& x) {
  static const char tag = 0;
  return cache().get(&tag, x, [&] { return tan_uncached(x); });
}

interval exp(const interval& x) {
  static const char tag = 0;
  return cache().get(&tag, x, [&] { return exp_uncached(x); });
}

interval log(const interval& x) {
  static const char tag = 0;
  return cache().get(&tag, x, [&] { return log_uncached(x); });
}

interval atan(const interval& x) {
  static const char tag = 0;
  return cache().get(&tag, x, [&] { return atan_uncached(x); });
}

interval sqrt(const interval& x) {
  static const char tag = 0;
  return cache().get(&tag, x, [&] { return sqrt_uncached(x); });
}

interval pown(const interval& x, int n) {
  const nearest_rounding mpfr_mode;  // MPFR and the bound logic below assume round-to-nearest
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

void forget_interval_function_values() { ++cache().epoch; }

}  // namespace appell
