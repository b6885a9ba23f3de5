// appell/scalar/mpfi_ops.hpp -- + - * of MPFI intervals as direct endpoint operations.
//
// MPFI's mpfi_add, mpfi_sub, mpfi_mul compute the two bounds with MPFR under
// directed rounding, and around that spend time on checks this library does
// not need on finite data: NaN flags, bound reversal, and for products two
// extra MPFR products (and a temporary) whenever a bound's sign case is not the
// simplest.  Measured (bench/appell_bench, `elementary`): a*b + c cost
// 2.55-2.8x the same in mpfr; with these, about 2.1x.
//
// The functions below compute exactly what MPFI computes -- the same endpoint
// formulas, each rounded outward, with MPFI's signed-zero convention (a lower
// bound is never -0, an upper bound never +0) -- and defer to MPFI for every
// other case: a NaN bound, a product with an infinite bound or of two
// intervals that both straddle 0, and aliasing that the endpoint formulas
// cannot handle.  They serve appell::mp::mpfi_backend (mpfi_backend.hpp) and
// write a bound only through MPFR's arithmetic (never a swap with another
// number), as that backend requires.  tests/mpfi_ops.cpp checks bound-for-bound
// equality with MPFI on random operands of every sign case.
#pragma once

#include <mpfi.h>

namespace appell::detail {

// MPFI's convention for zero bounds: [+0, x] and [x, -0].
inline void mpfi_fix_zero_signs(mpfi_ptr r) {
  if (mpfr_zero_p(&r->left) && mpfr_signbit(&r->left)) mpfr_neg(&r->left, &r->left, MPFR_RNDU);
  if (mpfr_zero_p(&r->right) && !mpfr_signbit(&r->right)) mpfr_neg(&r->right, &r->right, MPFR_RNDD);
}

/// A per-thread scratch number of the given precision (its value is not kept).
inline mpfr_ptr mpfi_scratch(mpfr_prec_t prec) {
  struct holder {
    mpfr_t v;
    holder() { mpfr_init2(v, MPFR_PREC_MIN); }
    ~holder() { mpfr_clear(v); }
  };
  thread_local holder h;
  if (mpfr_get_prec(h.v) != prec) mpfr_set_prec(h.v, prec);
  return h.v;
}

inline bool mpfi_all_finite(mpfi_srcptr a, mpfi_srcptr b) {
  return mpfr_number_p(&a->left) && mpfr_number_p(&a->right) && mpfr_number_p(&b->left) && mpfr_number_p(&b->right);
}
inline bool mpfi_no_nan(mpfi_srcptr a, mpfi_srcptr b) {
  return !mpfr_nan_p(&a->left) && !mpfr_nan_p(&a->right) && !mpfr_nan_p(&b->left) && !mpfr_nan_p(&b->right);
}
/// [0, 0] (MPFI's mpfi_is_zero, inline: it sits in the product's hot path).
inline bool mpfi_is_zero(mpfi_srcptr a) { return mpfr_zero_p(&a->left) && mpfr_zero_p(&a->right); }

/// r = a * b by the endpoint product of its sign case; false (nothing written)
/// where MPFI must do it (an infinite or NaN bound, both operands straddling 0).
/// Zero bounds need no case of their own: a bound that is 0 enters the
/// products of its case as 0 (a = [0, x] is handled as straddling 0).
inline bool mpfi_mul_endpoints(mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) {
  if (!mpfi_all_finite(a, b)) return false;
  if (mpfi_is_zero(a) || mpfi_is_zero(b)) {  // [0, 0] times a finite interval
    mpfr_set_zero(&r->left, 1);
    mpfr_set_zero(&r->right, -1);
    return true;
  }
  const bool a_pos = mpfr_sgn(&a->left) > 0, a_neg = mpfr_sgn(&a->right) < 0;
  const bool b_pos = mpfr_sgn(&b->left) > 0, b_neg = mpfr_sgn(&b->right) < 0;
  mpfr_srcptr l1, l2, u1, u2;  // lower = l1 l2 rounded down, upper = u1 u2 rounded up
  if (a_pos) {
    if (b_pos) l1 = &a->left, l2 = &b->left, u1 = &a->right, u2 = &b->right;
    else if (b_neg) l1 = &a->right, l2 = &b->left, u1 = &a->left, u2 = &b->right;
    else l1 = &a->right, l2 = &b->left, u1 = &a->right, u2 = &b->right;
  } else if (a_neg) {
    if (b_pos) l1 = &a->left, l2 = &b->right, u1 = &a->right, u2 = &b->left;
    else if (b_neg) l1 = &a->right, l2 = &b->right, u1 = &a->left, u2 = &b->left;
    else l1 = &a->left, l2 = &b->right, u1 = &a->left, u2 = &b->left;
  } else {  // a straddles 0
    if (b_pos) l1 = &a->left, l2 = &b->right, u1 = &a->right, u2 = &b->right;
    else if (b_neg) l1 = &a->right, l2 = &b->left, u1 = &a->left, u2 = &b->left;
    else return false;  // four products: MPFI
  }
  if (r == a || r == b) {  // in place: the lower bound goes to a scratch value until the upper one is done
    mpfr_ptr t = mpfi_scratch(mpfr_get_prec(&r->left));
    mpfr_mul(t, l1, l2, MPFR_RNDD);
    mpfr_mul(&r->right, u1, u2, MPFR_RNDU);  // MPFR allows its output to be an input
    mpfr_set(&r->left, t, MPFR_RNDD);        // exact: same precision (a copy, not a swap: see above)
  } else {
    mpfr_mul(&r->left, l1, l2, MPFR_RNDD);
    mpfr_mul(&r->right, u1, u2, MPFR_RNDU);
  }
  mpfi_fix_zero_signs(r);
  return true;
}

/// r = a + b.  Lower bounds only from lower bounds, upper from upper: aliasing is
/// harmless.  Infinite bounds are fine (MPFI never has a lower bound +inf or an
/// upper bound -inf, so no inf - inf).
inline void mpfi_add_endpoints(mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) {
  if (!mpfi_no_nan(a, b)) {
    mpfi_add(r, a, b);
    return;
  }
  mpfr_add(&r->left, &a->left, &b->left, MPFR_RNDD);
  mpfr_add(&r->right, &a->right, &b->right, MPFR_RNDU);
  mpfi_fix_zero_signs(r);
}

/// r = a - b.
inline void mpfi_sub_endpoints(mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) {
  if (r == b || !mpfi_no_nan(a, b)) {
    mpfi_sub(r, a, b);  // r aliasing b: b's lower bound is read after r's is written
    return;
  }
  mpfr_sub(&r->left, &a->left, &b->right, MPFR_RNDD);
  mpfr_sub(&r->right, &a->right, &b->left, MPFR_RNDU);
  mpfi_fix_zero_signs(r);
}

}  // namespace appell::detail
