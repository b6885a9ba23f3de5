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
// A bound of an mpfi or arb value as a double rounded outward (down for the lower bound).
template <class I>
double bound_as_double(const I& x, bool upper_bound) {
  if constexpr (std::is_same_v<I, mpfi>) {
    const mpfi_srcptr a = x.backend().data();
    return upper_bound ? mpfr_get_d(&a->right, MPFR_RNDU) : mpfr_get_d(&a->left, MPFR_RNDD);
  } else {
    const mpfr v = upper_bound ? upper(x) : lower(x);
    return mpfr_get_d(v.backend().data(), upper_bound ? MPFR_RNDU : MPFR_RNDD);
  }
}

// The residual fast path for I = mpfi or arb (the header's comment): x~ by mpfr LU on the
// midpoints, r = b - A x~ in I, the rest in double.
template <class I>
std::optional<vector_t<I>> mp_residual_solve(const matrix_t<I>& A, const vector_t<I>& b) {
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
  vector_t<I> r = b;
  I t;  // scratch at the working precision
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      if (exactly_zero(A(i, j)) || exactly_zero(xt(j))) continue;
      if constexpr (std::is_same_v<I, mpfi>) {
        mpfi_mul_fr(t.backend().data(), A(i, j).backend().data(), xt(j).backend().data());
        mpfi_sub(r(i).backend().data(), r(i).backend().data(), t.backend().data());
      } else {
        t = scalar_traits<I>::from_mpfr(xt(j).backend().data());  // exactly: a ball of radius 0
        mp::arb_subtract_product(r(i).backend(), A(i, j).backend(), t.backend());
      }
    }
  // r's bounds as MPFR numbers: mpfi's own, read in place; arb's ends, exactly, once.
  std::vector<mpfr_value> arb_ends;
  if constexpr (std::is_same_v<I, arb>) {
    arb_ends.resize(2 * static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      scalar_traits<I>::to_mpfr(r(i), arb_ends[2 * static_cast<std::size_t>(i)], arb_ends[2 * static_cast<std::size_t>(i) + 1]);
  }
  const auto ends = [&](Eigen::Index i) -> std::pair<mpfr_srcptr, mpfr_srcptr> {
    if constexpr (std::is_same_v<I, mpfi>) {
      const mpfi_srcptr ri = r(i).backend().data();
      return {&ri->left, &ri->right};
    } else {
      return {arb_ends[2 * static_cast<std::size_t>(i)].get(), arb_ends[2 * static_cast<std::size_t>(i) + 1].get()};
    }
  };
  // Scale r by 2^k (exact) so that its largest bound is about 1, and enclose it in double.
  long e_max = LONG_MIN;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto [l, h] = ends(i);
    for (mpfr_srcptr v : {l, h}) {
      if (!mpfr_number_p(v)) return std::nullopt;
      if (!mpfr_zero_p(v)) e_max = std::max<long>(e_max, mpfr_get_exp(v));
    }
  }
  const long k = e_max == LONG_MIN ? 0 : -e_max;
  vector_t<interval> rd(n);
  mpfr_value s(prec);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto [l, h] = ends(i);
    // at the bound's own precision the scaling is exact (r may carry b's precision,
    // above the working one); the directions keep it an enclosure even if it were not
    mpfr_set_prec(s, mpfr_get_prec(l));
    mpfr_mul_2si(s, l, k, MPFR_RNDD);
    const double lo = mpfr_get_d(s, MPFR_RNDD);
    mpfr_set_prec(s, mpfr_get_prec(h));
    mpfr_mul_2si(s, h, k, MPFR_RNDU);
    const double hi = mpfr_get_d(s, MPFR_RNDU);
    rd(i) = interval(lo, hi, true);
  }
  const std::optional<vector_t<interval>> e =
      n <= small_system_max ? residual_enclosure<true>(R, Ad, rd) : residual_enclosure<false>(R, Ad, rd);
  if (!e) return std::nullopt;
  vector_t<I> x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<I, mpfi>) {
      x(i).backend().set_prec(prec);
      mpfi_ptr xi = x(i).backend().data();
      mpfi_interv_d(t.backend().data(), (*e)(i).lower(), (*e)(i).upper());  // outward (exact at 53 bits and more)
      mpfi_mul_2si(t.backend().data(), t.backend().data(), -k);             // exact
      mpfi_add_fr(xi, t.backend().data(), xt(i).backend().data());          // outward
    } else {
      mpfr_value el(53), eh(53);
      mpfr_set_d(el, (*e)(i).lower(), MPFR_RNDN);  // exact
      mpfr_set_d(eh, (*e)(i).upper(), MPFR_RNDN);
      mpfr_mul_2si(el, el, -k, MPFR_RNDN);  // exact (MPFR's exponent range)
      mpfr_mul_2si(eh, eh, -k, MPFR_RNDN);
      x(i) = scalar_traits<I>::from_mpfr_bounds(el, eh) + scalar_traits<I>::from_mpfr(xt(i).backend().data());
    }
  }
  return x;
}
}  // namespace

std::optional<vector_t<mpfi>> mpfi_residual_solve(const matrix_t<mpfi>& A, const vector_t<mpfi>& b) {
  return mp_residual_solve<mpfi>(A, b);
}
std::optional<vector_t<arb>> arb_residual_solve(const matrix_t<arb>& A, const vector_t<arb>& b) {
  return mp_residual_solve<arb>(A, b);
}

}  // namespace appell::detail
