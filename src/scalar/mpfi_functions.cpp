// Tight integer powers of mpfi values (MPFI has sqr but no pown); sin and cos of narrow arguments.
#include <mpfi.h>

#include "appell/scalar/functions.hpp"
#include "appell/scalar/interval.hpp"

namespace appell {
namespace {
mpfr pow_dir(const mpfr& x, long n, mpfr_rnd_t rnd) {
  mpfr r;
  r.backend().set_prec(x.backend().prec());
  mpfr_pow_si(r.backend().data(), x.backend().data(), n, rnd);
  return r;
}
}  // namespace

mpfi pown_mpfi(const mpfi& x, int n) {
  // Same case analysis as pown(interval) in interval_functions.cpp.
  const mpfr lo = mpfi_lower(x), hi = mpfi_upper(x);
  const auto d = [n](const mpfr& v) { return pow_dir(v, n, MPFR_RNDD); };
  const auto u = [n](const mpfr& v) { return pow_dir(v, n, MPFR_RNDU); };
  const mpfr inf = std::numeric_limits<mpfr>::infinity();
  const mpfr zero = 0;
  if (n == 0) return mpfi(1);
  const bool even = n % 2 == 0;
  if (n > 0) {
    if (!even || lo >= 0) return mpfi_from_bounds(d(lo), u(hi));
    if (hi <= 0) return mpfi_from_bounds(d(hi), u(lo));
    return mpfi_from_bounds(zero, u(-lo > hi ? mpfr(-lo) : hi));
  }
  if (lo > 0) return mpfi_from_bounds(d(hi), u(lo));
  if (hi < 0) return even ? mpfi_from_bounds(d(lo), u(hi)) : mpfi_from_bounds(d(hi), u(lo));
  if (lo == 0 && hi == 0) throw domain_error("negative power of [0, 0]");
  if (even) return mpfi_from_bounds(d(-lo > hi ? mpfr(-lo) : hi), inf);
  if (lo == 0) return mpfi_from_bounds(d(hi), inf);
  if (hi == 0) return mpfi_from_bounds(-inf, u(lo));
  return mpfi_from_bounds(-inf, inf);
}

}  // namespace appell

namespace appell {

// sin and cos of a narrow mpfi argument from one mpfr_sin_cos at its midpoint m:
// with r >= max |x - m|, |sin x - sin m| <= r |cos m| + r^2 / 2 (Taylor, Lagrange
// remainder), and likewise for cos: wider than the endpoint enclosure by about
// r^2.  sin m and cos m come correctly rounded to nearest, the direction of each
// rounding read off the ternary value; every bound below is rounded outward.  Arguments that are not
// narrow (r > 2^-20) or not finite go to MPFI's endpoint functions.
void sin_cos_mpfi(const mpfi& x, mpfi& s, mpfi& c) { sin_cos_mpfi(x.backend(), s.backend(), c.backend()); }

void sin_cos_mpfi(const mp::mpfi_backend& x, mp::mpfi_backend& s, mp::mpfi_backend& c) {
  mpfi_srcptr xp = x.data();
  mpfi_ptr sp = s.data(), cp = c.data();
  const mpfr_prec_t pw = std::max(mpfi_get_prec(sp), mpfi_get_prec(cp));
  auto fallback = [&] {
    mpfi_sin(sp, xp);
    mpfi_cos(cp, xp);
  };
  if (sp == xp || cp == xp) {  // s or c is x itself: work on a copy (review: sin_cos(X, X, C) gave cos(sin X))
    const mp::mpfi_backend copy = x;
    return sin_cos_mpfi(copy, s, c);
  }
  if (!mpfr_number_p(&xp->left) || !mpfr_number_p(&xp->right)) return fallback();
  // Bounded work whatever the argument: an argument at least 7 > 2 pi wide covers a period, so
  // sin and cos range over [-1, 1] exactly, said without reducing its ends modulo 2 pi (MPFI's
  // endpoint functions take pi to as many bits as the ends' exponent: an angle given as 1e999999
  // is 3.3 million bits, minutes for each call); a narrow argument beyond 2^(2^20) is refused.
  {
    mpfr_t width;
    mpfr_init2(width, 64);
    mpfr_sub(width, &xp->right, &xp->left, MPFR_RNDD);
    const bool period = mpfr_cmp_ui(width, 7) >= 0;
    mpfr_clear(width);
    if (period) {
      for (mpfi_ptr out : {sp, cp}) mpfi_interv_si(out, -1, 1);
      return;
    }
    constexpr mpfr_exp_t most = mpfr_exp_t(1) << 20;
    if ((!mpfr_zero_p(&xp->left) && mpfr_get_exp(&xp->left) > most) ||
        (!mpfr_zero_p(&xp->right) && mpfr_get_exp(&xp->right) > most))
      throw appell::domain_error("sin, cos: an argument of magnitude beyond 2^1048576 narrower than 2 pi (its "
                                 "reduction modulo pi would take pi to more than a million bits)");
  }
  struct scratch {
    mpfr_t m, r, t, sm, cm, lo, hi, ds, dc;
    scratch() { mpfr_inits2(64, m, r, t, sm, cm, lo, hi, ds, dc, static_cast<mpfr_ptr>(nullptr)); }
    ~scratch() { mpfr_clears(m, r, t, sm, cm, lo, hi, ds, dc, static_cast<mpfr_ptr>(nullptr)); }
  };
  thread_local scratch w;
  // m in [lo, hi]: (lo + hi) / 2 with one more bit than x (exact when lo and hi share
  // an exponent; otherwise rounded to nearest, still between lo and hi)
  mpfr_set_prec(w.m, mpfi_get_prec(xp) + 1);
  mpfr_add(w.m, &xp->left, &xp->right, MPFR_RNDN);
  mpfr_div_2ui(w.m, w.m, 1, MPFR_RNDN);
  if (mpfr_cmp(w.m, &xp->left) < 0 || mpfr_cmp(w.m, &xp->right) > 0) return fallback();
  mpfr_set_prec(w.r, pw);
  mpfr_set_prec(w.t, pw);
  mpfr_sub(w.r, &xp->right, w.m, MPFR_RNDU);
  mpfr_sub(w.t, w.m, &xp->left, MPFR_RNDU);
  mpfr_max(w.r, w.r, w.t, MPFR_RNDU);  // r >= max |x - m| (rounded up)
  // not narrow: r > 2^-20 (radians, whatever |m|: the overestimation r^2 is absolute)
  if (mpfr_cmp_ui_2exp(w.r, 1, -20) > 0) return fallback();
  for (mpfr_ptr v : {w.sm, w.cm, w.ds, w.dc}) mpfr_set_prec(v, pw);
  const int ternary = mpfr_sin_cos(w.sm, w.cm, w.m, MPFR_RNDN);
  // delta(y) = r (|y| + 2^(1-pw) + r/2), rounded up: |y| + 2^(1-pw) bounds |cos m| (resp.
  // |sin m|), as y is within one ulp <= 2^-pw of it (|y| <= 1); Taylor with Lagrange remainder,
  // |sin x - sin m| <= |cos m| r + r^2/2 (likewise cos)
  auto delta = [&](mpfr_srcptr y, mpfr_ptr out) {
    mpfr_abs(out, y, MPFR_RNDU);
    mpfr_set_ui_2exp(w.t, 1, 1 - pw, MPFR_RNDU);
    mpfr_add(out, out, w.t, MPFR_RNDU);
    mpfr_div_2ui(w.t, w.r, 1, MPFR_RNDU);
    mpfr_add(out, out, w.t, MPFR_RNDU);
    mpfr_mul(out, out, w.r, MPFR_RNDU);
  };
  // the exact value v of a rounded y: ternary 1: y > v, so v in [y-, y]; 2: v in [y, y+]; 0: v = y
  // (y- and y+ the neighbours of y at y's own precision pw)
  auto enclose = [&](mpfi_ptr out, mpfr_srcptr y, int t, mpfr_srcptr d) {
    mpfr_set_prec(w.lo, pw);
    mpfr_set_prec(w.hi, pw);
    mpfr_set(w.lo, y, MPFR_RNDN);  // exact
    mpfr_set(w.hi, y, MPFR_RNDN);
    if (t == 1) mpfr_nextbelow(w.lo);
    if (t == 2) mpfr_nextabove(w.hi);
    mpfr_sub(&out->left, w.lo, d, MPFR_RNDD);
    mpfr_add(&out->right, w.hi, d, MPFR_RNDU);
    if (mpfr_cmp_si(&out->left, -1) < 0) mpfr_set_si(&out->left, -1, MPFR_RNDD);
    if (mpfr_cmp_ui(&out->right, 1) > 0) mpfr_set_ui(&out->right, 1, MPFR_RNDU);
    detail::mpfi_fix_zero_signs(out);
  };
  delta(w.cm, w.ds);  // sin moves by at most r |cos m| + r^2/2
  delta(w.sm, w.dc);
  enclose(sp, w.sm, ternary & 3, w.ds);
  enclose(cp, w.cm, (ternary >> 2) & 3, w.dc);
}

}  // namespace appell

namespace appell::mp {

// r = sin x: the cosine goes to a scratch value of r's precision.
void eval_sin(mpfi_backend& r, const mpfi_backend& x) {
  mpfi_backend c;
  c.set_prec(r.prec());
  appell::sin_cos_mpfi(x, r, c);
}

void eval_cos(mpfi_backend& r, const mpfi_backend& x) {
  mpfi_backend s;
  s.set_prec(r.prec());
  appell::sin_cos_mpfi(x, s, r);
}

// r = tan x = sin x / cos x, both from sin_cos_mpfi (an enclosure: the quotient
// of enclosures contains the quotient; a cos that may vanish gives the whole
// line).  MPFI's own mpfi_tan finds the quadrant by dividing by pi/2 at a
// precision of the order of the exponent: minutes for x = pi^-679404116 (a
// fuzzing finding); the narrow path of sin_cos_mpfi is one mpfr_sin_cos.
void eval_tan(mpfi_backend& r, const mpfi_backend& x) {
  mpfi_backend s, c;
  s.set_prec(r.prec() + 8);
  c.set_prec(r.prec() + 8);
  appell::sin_cos_mpfi(x, s, c);
  mpfi_div(r.data(), s.data(), c.data());
}

}  // namespace appell::mp
