// The residual fast path of the verified solver (declared in appell/linalg/solve.hpp).
//
// With an approximate inverse R (double) and an approximate solution x~, the error
// e = x - x~ of every system A x = b, A in [A], b in [b], satisfies A e = r with
// r = b - A x~ in [r], hence  e = R r + C e,  C = I - R A.  If every row sum of
// |C| is at most beta < 1 (bounded for every A in [A]: up to 12 unknowns from an
// enclosure of C by midpoint-radius products, above from one product R mid(A) with
// its rounding bounded a priori), every such A is nonsingular, ||e||_inf <= ||R r||_inf / (1 - beta)
// =: eps, and e_i lies in (R r)_i + [-s_i eps, s_i eps] with s_i the i-th row sum.
// Only r needs the working precision: for mpfi it is computed at p bits, then
// scaled by a power of two and enclosed in double, where the rest runs (n^3
// double operations instead of n^3 mpfi ones).  The result is x~ + e-box,
// as wide as the residual's enclosure makes it; where beta is not small the
// caller falls back to Krawczyk's iteration at full precision.
#include <mpfi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <utility>
#include <vector>

#include "appell/linalg/solve.hpp"
// Last: arb.h (through flint.h) defines macros such as `ulong` and `slong`.
#include "appell/scalar/arb_access.hpp"

namespace appell::detail {

bool small_interval_solve_into(const matrix_t<interval>& A, const vector_t<interval>& b, vector_t<interval>& x) {
  constexpr int M = static_cast<int>(small_system_max);
  using DM = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, M, M>;
  using DV = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, M, 1>;
  using IV = Eigen::Matrix<interval, Eigen::Dynamic, 1, 0, M, 1>;
  const Eigen::Index n = A.rows();
  if (n == 0 || n > small_system_max) return false;
  DM Am(n, n);
  DV bm(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    bm(i) = mid(b(i));
    for (Eigen::Index j = 0; j < n; ++j) Am(i, j) = mid(A(i, j));
  }
  const Eigen::PartialPivLU<DM> lu(Am);
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(std::abs(lu.matrixLU()(i, i)) > 0)) return false;
  const DM R = lu.inverse();
  if (!R.allFinite()) return false;
  DV xt = R * bm;
  xt += R * (bm - Am * xt);  // one refinement step, as residual_solve_into
  if (!xt.allFinite()) return false;
  IV xI(n), residual(n);
  for (Eigen::Index i = 0; i < n; ++i) xI(i) = thin<interval>(xt(i));
  {
    const upward_rounding mode;
    for (Eigen::Index i = 0; i < n; ++i)  // b - A x~, as residual_solve_into
      residual(i) = b(i) - sum_of_point_products(n, [&](Eigen::Index k) -> const interval& { return A(i, k); }, xt);
  }
  const std::optional<IV> e = residual_enclosure<true>(R, A, residual);
  if (!e) return false;
  x.resize(n);  // of its size already: no allocation
  for (Eigen::Index i = 0; i < n; ++i) x(i) = xI(i) + (*e)(i);
  return true;
}

namespace {
// A bound of an mpfi value as a double rounded outward (down for the lower bound).
double bound_as_double(const mpfi& x, bool upper_bound) {
  const mpfi_srcptr a = x.backend().data();
  return upper_bound ? mpfr_get_d(&a->right, MPFR_RNDU) : mpfr_get_d(&a->left, MPFR_RNDD);
}

}  // namespace

// The residual fast path for mpfi (the header's comment): x~ by mpfr LU on the midpoints,
// r = b - A x~ in mpfi, the rest in double.
std::optional<vector_t<mpfi>> mpfi_residual_solve(const matrix_t<mpfi>& A, const vector_t<mpfi>& b) {
  const Eigen::Index n = A.rows();
  // Approximate solution at the working precision (mpfr LU on the midpoints).
  matrix_t<mpfr> Am(n, n);
  vector_t<mpfr> bm(n);
  Eigen::MatrixXd Ad_mid(n, n);
  matrix_t<interval> Ad(n, n);  // outward double enclosure of [A]
  for (Eigen::Index i = 0; i < n; ++i) {
    bm(i) = mid(b(i));
    for (Eigen::Index j = 0; j < n; ++j) {
      Am(i, j) = mid(A(i, j));
      const double lo = bound_as_double(A(i, j), false), hi = bound_as_double(A(i, j), true);
      if (!(std::fabs(lo) <= std::numeric_limits<double>::max() && std::fabs(hi) <= std::numeric_limits<double>::max()))
        return std::nullopt;  // outside double's range: the full-precision path
      Ad(i, j) = interval(lo, hi, true);
      Ad_mid(i, j) = lo / 2 + hi / 2;
    }
  }
  const Eigen::PartialPivLU<matrix_t<mpfr>> lu(Am);
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(abs(lu.matrixLU()(i, i)) > 0)) return std::nullopt;  // the fallback explains the refusal
  const vector_t<mpfr> xt = lu.solve(bm);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lud(Ad_mid);
  const Eigen::MatrixXd R = lud.inverse();
  if (!R.allFinite()) return std::nullopt;

  // r = b - A x~ at the working precision, exact zeros skipped.
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(mp_precision_bits());
  vector_t<mpfi> r = b;
  mpfi t;  // scratch at the working precision
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      if (exactly_zero(A(i, j)) || exactly_zero(xt(j))) continue;
      mpfi_mul_fr(t.backend().data(), A(i, j).backend().data(), xt(j).backend().data());
      mpfi_sub(r(i).backend().data(), r(i).backend().data(), t.backend().data());
    }
  // Scale r by 2^k (exact) so that its largest bound is about 1, and enclose it in double.
  long e_max = LONG_MIN;
  for (Eigen::Index i = 0; i < n; ++i) {
    const mpfi_srcptr ri = r(i).backend().data();
    for (mpfr_srcptr v : {&ri->left, &ri->right}) {
      if (!mpfr_number_p(v)) return std::nullopt;
      if (!mpfr_zero_p(v)) e_max = std::max<long>(e_max, mpfr_get_exp(v));
    }
  }
  const long k = e_max == LONG_MIN ? 0 : -e_max;
  vector_t<interval> rd(n);
  mpfr_value s(prec);
  for (Eigen::Index i = 0; i < n; ++i) {
    const mpfi_srcptr ri = r(i).backend().data();
    // at the bound's own precision the scaling is exact (r may carry b's precision,
    // above the working one); the directions keep it an enclosure even if it were not
    mpfr_set_prec(s, mpfr_get_prec(&ri->left));
    mpfr_mul_2si(s, &ri->left, k, MPFR_RNDD);
    const double lo = mpfr_get_d(s, MPFR_RNDD);
    mpfr_set_prec(s, mpfr_get_prec(&ri->right));
    mpfr_mul_2si(s, &ri->right, k, MPFR_RNDU);
    const double hi = mpfr_get_d(s, MPFR_RNDU);
    rd(i) = interval(lo, hi, true);
  }
  const std::optional<vector_t<interval>> e =
      n <= small_system_max ? residual_enclosure<true>(R, Ad, rd) : residual_enclosure<false>(R, Ad, rd);
  if (!e) return std::nullopt;
  vector_t<mpfi> x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    x(i).backend().set_prec(prec);
    mpfi_ptr xi = x(i).backend().data();
    mpfi_interv_d(t.backend().data(), (*e)(i).lower(), (*e)(i).upper());  // outward (exact at 53 bits and more)
    mpfi_mul_2si(t.backend().data(), t.backend().data(), -k);             // exact
    mpfi_add_fr(xi, t.backend().data(), xt(i).backend().data());          // outward
  }
  return x;
}

// The residual fast path for arb, with no LU at the working precision: x~ is refined in mixed
// precision from 0 with the LU of mid(A) in double that R comes from: r = b - A x~ by Arb's
// arb_dot (each row one call: the products exact, the sum rounded once, the balls' radii
// carried), the correction d = the double LU's solve of mid(r), x~ += d at the working
// precision, until d is below x~'s last bit (at most max_refinements).  The last r, computed for
// the x~ kept, is the residual the bound uses: the enclosure is rigorous whatever x~ is, and as
// tight as the working precision allows once x~ is accurate to it (a mass matrix of 27 unknowns:
// a few refinements of n^2 products each, where an LU in mpfr takes n^3 / 3).
std::optional<vector_t<arb>> arb_residual_solve(const matrix_t<arb>& A, const vector_t<arb>& b) {
  const Eigen::Index n = A.rows();
  const slong prec = static_cast<slong>(mp_precision_bits());
  // Arb's dot product reads arrays of arb_struct with a stride: A's and b's structs copied
  // (their words; any limbs they point to are shared, read only, and never cleared from here),
  // A row by row.
  std::vector<arb_struct> As(static_cast<std::size_t>(n * n)), bs(static_cast<std::size_t>(n));
  Eigen::MatrixXd Ad_mid(n, n);
  matrix_t<interval> Ad(n, n);  // outward double enclosure of [A]
  arf_t lo_f, hi_f;
  arf_init(lo_f);
  arf_init(hi_f);
  struct arf_guard {
    arf_ptr a, b;
    ~arf_guard() {
      arf_clear(a);
      arf_clear(b);
    }
  } arf_cleared{lo_f, hi_f};
  // [lo, hi] in double, outward; false where a bound is not a finite double.
  const auto double_bounds = [&](arb_srcptr v, double& lo, double& hi) {
    arb_get_lbound_arf(lo_f, v, 53);
    arb_get_ubound_arf(hi_f, v, 53);
    lo = arf_get_d(lo_f, ARF_RND_FLOOR);
    hi = arf_get_d(hi_f, ARF_RND_CEIL);
    return std::fabs(lo) <= std::numeric_limits<double>::max() && std::fabs(hi) <= std::numeric_limits<double>::max();
  };
  for (Eigen::Index i = 0; i < n; ++i) {
    double lo = 0, hi = 0;
    bs[static_cast<std::size_t>(i)] = *mp::arb_of(b(i).backend());
    for (Eigen::Index j = 0; j < n; ++j) {
      const arb_srcptr a = mp::arb_of(A(i, j).backend());
      As[static_cast<std::size_t>(i * n + j)] = *a;
      if (!double_bounds(a, lo, hi)) return std::nullopt;  // outside double's range: the full-precision path
      Ad(i, j) = interval(lo, hi, true);
      Ad_mid(i, j) = lo / 2 + hi / 2;
    }
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lud(Ad_mid);
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(std::fabs(lud.matrixLU()(i, i)) > 0)) return std::nullopt;  // the fallback explains the refusal
  const Eigen::MatrixXd R = lud.inverse();
  if (!R.allFinite()) return std::nullopt;

  // x~ (points: radius 0, from 0) and r, Arb's own vectors, cleared on every way out.
  struct arb_vector {
    slong n;
    arb_ptr v;
    explicit arb_vector(slong size) : n(size), v(_arb_vec_init(size)) {}
    arb_vector(const arb_vector&) = delete;
    arb_vector& operator=(const arb_vector&) = delete;
    ~arb_vector() { _arb_vec_clear(v, n); }
  };
  arb_vector xt(static_cast<slong>(n)), r(static_cast<slong>(n));
  const auto residual = [&] {
    for (Eigen::Index i = 0; i < n; ++i)
      arb_dot(r.v + i, bs.data() + i, 1, As.data() + i * n, 1, xt.v, 1, static_cast<slong>(n), prec);
  };
  // The largest exponent e of the midpoints v[0..n) (each |v_i| < 2^e), WORD_MIN if all are 0.
  const auto top_exponent = [&](arb_srcptr v) {
    slong e = WORD_MIN;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!arf_is_zero(arb_midref(v + i))) e = std::max(e, arf_abs_bound_lt_2exp_si(arb_midref(v + i)));
    return e;
  };
  // The refinement, each step on mid(r) scaled by 2^s into double's range (exact), so that
  // neither b's scale nor the corrections' (below x~'s last bit, far below double's smallest
  // normal number at 1000 bits) leave it: each step gains about 53 - log2(cond) bits;
  // max_refinements covers 30 bits a step, and a matrix whose double LU gains less leaves x~ less
  // accurate, the enclosure still rigorous (and wider: tests compare the width with mpfi's).
  const int max_refinements = static_cast<int>(prec / 30) + 4;
  Eigen::VectorXd rm(n), d(n);
  for (int step = 0;; ++step) {
    residual();
    if (step == max_refinements) break;
    const slong r_exp = top_exponent(r.v);
    if (r_exp == WORD_MIN) break;  // r's midpoints all 0: x~ solves the midpoint system
    const slong s = -r_exp;
    for (Eigen::Index i = 0; i < n; ++i) {
      arf_mul_2exp_si(lo_f, arb_midref(r.v + i), s);  // exact
      rm(i) = arf_get_d(lo_f, ARF_RND_NEAR);
    }
    d = lud.solve(rm);  // the correction times 2^s
    if (!d.allFinite()) return std::nullopt;
    const double d_max = d.lpNorm<Eigen::Infinity>();
    if (d_max == 0) break;
    // below x~'s last bit at the working precision (|d| < 2^(ilogb + 1 - s)): nothing more to gain
    const slong x_exp = top_exponent(xt.v);
    if (x_exp != WORD_MIN && std::ilogb(d_max) + 1 - s < x_exp - prec) break;
    for (Eigen::Index i = 0; i < n; ++i) {
      arf_set_d(lo_f, d(i));
      arf_mul_2exp_si(lo_f, lo_f, -s);  // exact
      arf_add(arb_midref(xt.v + i), arb_midref(xt.v + i), lo_f, prec, ARF_RND_NEAR);
    }
  }
  // Scale r by 2^k (exact in Arb) so that its largest bound is below 1, and enclose it in double:
  // each bound rounded outward to 53 bits, scaled, then converted (Arb's arf_get_d rounds in the
  // direction asked for, underflow included).
  std::vector<arf_struct> r_bounds(2 * static_cast<std::size_t>(n));
  struct arf_vector_guard {
    std::vector<arf_struct>& v;
    ~arf_vector_guard() {
      for (arf_struct& a : v) arf_clear(&a);
    }
  } r_bounds_cleared{r_bounds};
  for (arf_struct& a : r_bounds) arf_init(&a);
  slong e_max = WORD_MIN;
  for (Eigen::Index i = 0; i < n; ++i) {
    arf_ptr l = &r_bounds[2 * static_cast<std::size_t>(i)], h = l + 1;
    arb_get_lbound_arf(l, r.v + i, 53);
    arb_get_ubound_arf(h, r.v + i, 53);
    for (arf_srcptr v : {arf_srcptr(l), arf_srcptr(h)}) {
      if (arf_is_zero(v)) continue;
      if (!arf_is_finite(v)) return std::nullopt;
      e_max = std::max(e_max, arf_abs_bound_lt_2exp_si(v));
    }
  }
  const slong k = e_max == WORD_MIN ? 0 : -e_max;
  vector_t<interval> rd(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    arf_ptr l = &r_bounds[2 * static_cast<std::size_t>(i)], h = l + 1;
    arf_mul_2exp_si(l, l, k);
    arf_mul_2exp_si(h, h, k);
    rd(i) = interval(arf_get_d(l, ARF_RND_FLOOR), arf_get_d(h, ARF_RND_CEIL), true);
  }
  const std::optional<vector_t<interval>> e =
      n <= small_system_max ? residual_enclosure<true>(R, Ad, rd) : residual_enclosure<false>(R, Ad, rd);
  if (!e) return std::nullopt;
  // x = x~ + 2^-k e, each bound of e exact in Arb, the sum enclosed at the working precision.
  vector_t<arb> x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    arf_set_d(lo_f, (*e)(i).lower());
    arf_set_d(hi_f, (*e)(i).upper());
    arf_mul_2exp_si(lo_f, lo_f, -k);
    arf_mul_2exp_si(hi_f, hi_f, -k);
    const arb_ptr xi = mp::arb_of(x(i).backend());
    arb_set_interval_arf(xi, lo_f, hi_f, prec);
    arb_add_arf(xi, xi, arb_midref(xt.v + i), prec);
  }
  return x;
}

}  // namespace appell::detail
