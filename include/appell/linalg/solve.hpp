// appell/linalg/solve.hpp -- linear solves for every scalar.
//
//   solve_spd(A, b)   A symmetric positive definite (the mass matrix M of
//                     Appell's equations M u' + b = Q).  Point types: Cholesky.
//   solve(A, b)       general A.  Point types: LU with partial pivoting.
// Interval types go, for both, to verified_solve.  It first tries a residual
// bound (src/linalg/verified_solve.cpp): with R ~ mid(A)^-1 in double and
// r = b - A x~ enclosed at the working precision, if every row sum of
// |I - R A| is at most beta <= 2^-10, then x lies in
// x~ + R r + [-s_i eps, s_i eps] with eps = ||R r||/(1 - beta); for mpfi only
// r is computed at p bits (scaled by a power of 2 into double's range), the
// n^3 part in double.  The row sums s_i come from an enclosure of I - R A (three
// products in double, the tightest) up to small_system_max unknowns, and above it
// from one product R mid(A) in floating point with its rounding bounded a priori
// (residual_row_sums_into: a third of the work, the solution's bounds the same
// but for an ulp where a bound of the correction was exactly zero).  Otherwise (ill-conditioned systems, entries outside
// double's range) it runs Krawczyk's operator with a
// midpoint-inverse preconditioner and epsilon-inflation (Rump 1983).  With
// R ~ mid(A)^-1, x~ ~ R mid(b), z = R (b - A x~) and C = I - R A (both in
// interval arithmetic), if  z + C Y  lies in the interior of Y then every
// A in [A] is nonsingular and every solution of A x = b, b in [b], lies in
// x~ + (z + C Y).  Eigen never pivots on interval values here: R and x~ are
// computed on midpoints, in the bound type.  When the inclusion cannot be
// established (a singular matrix in [A], or one too ill-conditioned for the
// precision) the solve refuses with certification_error; it never returns a
// box it has not proved.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "appell/linalg/scratch.hpp"
#include "appell/scalar/eigen.hpp"
#include "appell/scalar/policy.hpp"

namespace appell {

namespace detail {

template <class I>
I thin(const bound_t<I>& p) {
  if constexpr (std::is_same_v<I, interval>) return interval(p);
  else if constexpr (std::is_same_v<I, arb>) return ball_from_bounds(p, p);
  else return mpfi_from_bounds(p, p);
}

template <class I>
I intersect(const I& a, const I& b) {
  if constexpr (std::is_same_v<I, interval>) {
    return boost::numeric::intersect(a, b);
  } else if constexpr (std::is_same_v<I, arb>) {
    return ball_intersect(a, b);
  } else {
    I r;
    mpfi_intersect(r.backend().data(), a.backend().data(), b.backend().data());
    return r;
  }
}

// a lies in the interior of b.
template <class I>
bool in_interior(const I& a, const I& b) {
  return lower(b) < lower(a) && upper(a) < upper(b);
}

// A B by plain dot products.  Eigen's blocked GEMM/GEMV kernels produce NaN
// entries on mpfi (measured: 7x7 products, Eigen 3.4 with Boost 1.74), so
// interval products in this library are coefficient-based.
template <class T>
matrix_t<T> product(const matrix_t<T>& A, const matrix_t<T>& B) {
  matrix_t<T> C(A.rows(), B.cols());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      T sum = A(i, 0) * B(0, j);
      for (Eigen::Index k = 1; k < A.cols(); ++k) sum += A(i, k) * B(k, j);
      C(i, j) = sum;
    }
  return C;
}
template <class T>
vector_t<T> product(const matrix_t<T>& A, const vector_t<T>& x) {
  vector_t<T> y(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    T sum = A(i, 0) * x(0);
    for (Eigen::Index k = 1; k < A.cols(); ++k) sum += A(i, k) * x(k);
    y(i) = sum;
  }
  return y;
}

/// K Eigen objects of type M for one call: borrowed from a pool (linalg/scratch.hpp, one pool per
/// Site: the caller's own) where M's size is dynamic, on the stack where its capacity is fixed;
/// the same operations either way.
template <class M, int K, class Site>
class scratch_matrices {
 public:
  M& operator[](int k) {
    if constexpr (borrowed) {
      if (!held_[k]) held_[k].emplace();
      return **held_[k];
    } else {
      return local_[k];
    }
  }

 private:
  static constexpr bool borrowed = M::MaxRowsAtCompileTime == Eigen::Dynamic;
  std::optional<scratch<M, Site>> held_[K];
  M local_[borrowed ? 1 : K];
};

/// The three double products of identity_minus_product_into (below) in one
/// pass: up = RU(R Am) >= R Am, neg_down = RU((-R) Am) >= -(R Am) and
/// rad = RU(|R| Ar) >= |R| Ar, every operation in the caller's rounding mode,
/// which must be upward.  Out of line (and the asm barrier at the end) so that
/// no operation of it can be moved across the caller's mode switch.
/// Column j of each result is summed down the columns of R (contiguous, column-major), k after
/// k, so that the inner loop runs over independent rows and vectorizes; every partial sum is
/// rounded up, so it bounds the exact one from above in any order of summation.
template <class DM>
[[gnu::noinline]] void rump_products(const DM& R, const DM& Am, const DM& Ar, DM& up, DM& neg_down, DM& rad) {
  static_assert(!DM::IsRowMajor, "rump_products walks columns");
  const Eigen::Index n = R.rows(), m = Am.cols(), K = R.cols();
  for (Eigen::Index j = 0; j < m; ++j) {
    double* __restrict u = up.data() + j * up.outerStride();
    double* __restrict d = neg_down.data() + j * neg_down.outerStride();
    double* __restrict r = rad.data() + j * rad.outerStride();
    for (Eigen::Index i = 0; i < n; ++i) u[i] = 0, d[i] = 0, r[i] = 0;
    for (Eigen::Index k = 0; k < K; ++k) {
      const double b = Am(k, j), br = Ar(k, j);
      const double* __restrict a = R.data() + k * R.outerStride();
      for (Eigen::Index i = 0; i < n; ++i) {
        u[i] += a[i] * b;
        d[i] += (-a[i]) * b;
        r[i] += std::abs(a[i]) * br;
      }
    }
  }
  asm volatile("" : : "r"(up.data()), "r"(neg_down.data()), "r"(rad.data()) : "memory");
}

/// C = an enclosure of I - R A for a double matrix R and an interval matrix A,
/// by midpoint-radius arithmetic (Rump): with A in [Am - Ar, Am + Ar],
///   I - R A  in  [I - RU(R Am) - RU(|R| Ar),  I - RD(R Am) + RU(|R| Ar)],
/// where RU / RD are products with every operation rounded up / down (the
/// latter as -RU((-R) Am)); Am, Ar and the products are formed in one upward-
/// rounding scope (rump_products).  n^3 double operations instead of n^3
/// interval ones.
/// DM: a double matrix type, IMA/IMC: interval matrix types (heap or
/// fixed-capacity storage).
/// A dynamic DM's five matrices are borrowed (linalg/scratch.hpp) from a pool of Site's (each
/// caller whose systems have a size of their own passes a Site of its own: an Eigen matrix keeps
/// one size), a fixed-capacity one's are on the stack; the same operations either way.
template <class Site = void, class DM, class IMA, class IMC>
void identity_minus_product_into(const DM& R, const IMA& A, IMC& C) {
  const Eigen::Index n = A.rows();
  struct site;
  scratch_matrices<DM, 5, site> matrix;
  DM &Am = matrix[0], &Ar = matrix[1], &up = matrix[2], &neg_down = matrix[3], &rad = matrix[4];
  for (DM* M : {&Am, &Ar, &up, &neg_down, &rad}) M->resize(n, n);
  {
    const upward_rounding mode;
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const double lo = A(i, j).lower(), hi = A(i, j).upper();
        const double m = lo + (hi - lo) * 0.5;
        Am(i, j) = (lo <= m && m <= hi) ? m : lo;
        const auto sub_up = [](double a, double b) {
          return interval_arith::opaque(interval_arith::opaque(a) - interval_arith::opaque(b));
        };
        Ar(i, j) = std::max(sub_up(hi, Am(i, j)), sub_up(Am(i, j), lo));  // rounded up
      }
    rump_products(R, Am, Ar, up, neg_down, rad);
  }
  C.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      const interval one_ij(i == j ? 1.0 : 0.0);
      // [-(up + rad), neg_down + rad] encloses -(R A)_ij; add delta_ij in interval arithmetic
      const interval minus_RA(-(interval(up(i, j)) + interval(rad(i, j))).upper(),
                              (interval(neg_down(i, j)) + interval(rad(i, j))).upper());
      C(i, j) = one_ij + minus_RA;
    }
}

inline matrix_t<interval> identity_minus_product(const Eigen::MatrixXd& R, const matrix_t<interval>& A) {
  matrix_t<interval> C;
  identity_minus_product_into(R, A, C);
  return C;
}

/// The largest row sum of |I - R A| the residual bound accepts: beyond it the
/// norm bound is loose and Krawczyk's iteration is used instead.
inline constexpr double max_contraction = 1.0 / 1024;

/// Sum_k a_k d_k for intervals a_k = a(k) and doubles d_k = d(k), k < n, with the bounds of the
/// products and sums done one by one in interval arithmetic (a product by the thin [d, d] is
/// [a_lo d, a_hi d] or [a_hi d, a_lo d] by d's sign: one product per bound, not four), each
/// product kept as the pair (-lower, upper) and the pairs added in upward mode, as
/// interval_sum_of_products does.  Every a_k and d_k finite; the caller inside an upward scope
/// (upward_rounding: this function switches nothing, and every caller holds one).  Terms with
/// d_k = 0 (either sign) are exactly zero and left out.
template <class A, class D>
interval sum_of_point_products(Eigen::Index n, const A& a, const D& d) {
  __m128d s = _mm_setzero_pd();
  const __m128d low_sign = _mm_set_pd(0.0, -0.0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double dk = d(k);
    if (dk == 0) continue;
    const interval& ak = a(k);
    __m128d p = _mm_xor_pd(_mm_set_pd(ak.upper(), ak.lower()), low_sign);  // (-lower, upper)
    if (dk < 0) p = _mm_shuffle_pd(p, p, 1);                               // (upper, -lower)
    s = _mm_add_pd(s, opaque_pd(_mm_mul_pd(p, _mm_set1_pd(std::fabs(dk)))));
  }
  return from_pair(s);
}

/// Upper bounds of the row sums of |I - R A| over every A in [A], for a double matrix R and an
/// interval matrix A, into row_sum (what the residual bound needs of I - R A: not the matrix
/// itself).  With A = Am + D, |D| <= Ar (Am, Ar: midpoints and radii rounded up), and G the
/// product R Am in floating point (Eigen's, in whatever order and rounding mode: every operation's
/// relative error is below u = 2^-52, and an underflowing product's absolute error below 2^-1074),
///   |G_ij - (R Am)_ij| <= gamma_n (|R| |Am|)_ij + 2 n 2^-1074,   gamma_n = n u / (1 - n u)
/// (Higham, Accuracy and Stability of Numerical Algorithms, sec. 3.5), so that
///   sum_j |delta_ij - (R A)_ij| <= sum_j |delta_ij - G_ij| + (|R| (gamma_n |Am| + Ar) 1)_i + 2 n^2 2^-1074,
/// every term rounded up.  One product of n x n matrices in double (Eigen's blocked kernel) and
/// two matrix-vector products, where the enclosure of I - R A itself (identity_minus_product_into,
/// which Krawczyk's iteration needs) takes three products.  The bound is looser than that
/// enclosure's by about gamma_n |R| |Am|; it enters the solution's radius only multiplied by the
/// correction's norm (residual_enclosure_into), far below the radius R r itself contributes.
/// Matrices of a dynamic DM borrowed from a pool of Site's, as in identity_minus_product_into.
template <class Site = void, class DM, class IMA, class SV>
void residual_row_sums_into(const DM& R, const IMA& A, SV& row_sum) {
  const Eigen::Index n = A.rows();
  struct site;
  scratch_matrices<DM, 2, site> matrix;
  scratch_matrices<SV, 1, site> vector;
  DM &Am = matrix[0], &G = matrix[1];
  SV& w = vector[0];  // w_k = sum_j (gamma_n |Am_kj| + Ar_kj), rounded up
  Am.resize(n, n);
  w.resize(n);
  row_sum.resize(n);
  // Every operation rounded upward has its operands and its result passed through opaque (as
  // interval_arith's): neither can be computed before the mode switch nor folded.
  const auto opaque = [](double v) { return interval_arith::opaque(v); };
  const auto add_up = [&](double a, double b) { return opaque(opaque(a) + opaque(b)); };
  const auto sub_up = [&](double a, double b) { return opaque(opaque(a) - opaque(b)); };
  const auto mul_up = [&](double a, double b) { return opaque(opaque(a) * opaque(b)); };
  {
    const upward_rounding mode;
    const double nu = mul_up(static_cast<double>(n), 0x1p-52);                    // exact
    const double gamma = opaque(opaque(nu) / -sub_up(nu, 1.0));                   // n u / (1 - n u), rounded up
    for (Eigen::Index k = 0; k < n; ++k) w(k) = 0;
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index k = 0; k < n; ++k) {
        const double lo = A(k, j).lower(), hi = A(k, j).upper();
        const double m = lo + (hi - lo) * 0.5;  // any point of [lo, hi] will do
        Am(k, j) = (lo <= m && m <= hi) ? m : lo;
        const double ar = std::max(sub_up(hi, Am(k, j)), sub_up(Am(k, j), lo));  // >= |A - Am|
        w(k) = add_up(w(k), add_up(ar, mul_up(gamma, std::fabs(Am(k, j)))));
      }
  }
  G.resize(n, n);
  G.noalias() = R * Am;  // in any rounding mode: the bound above holds for each
  {
    const upward_rounding mode;
    const double underflow = mul_up(static_cast<double>(2 * n * n), 0x1p-1074);
    for (Eigen::Index i = 0; i < n; ++i) row_sum(i) = underflow;
    for (Eigen::Index j = 0; j < n; ++j)  // down the columns (contiguous)
      for (Eigen::Index i = 0; i < n; ++i) {
        const double g = G(i, j);
        const double e = i == j ? std::max(sub_up(1.0, g), sub_up(g, 1.0)) : std::fabs(g);  // >= |delta_ij - g|
        row_sum(i) = add_up(row_sum(i), add_up(e, mul_up(std::fabs(R(i, j)), w(j))));
      }
  }
}

/// Encloses A^-1 r for every A in [A] and r in [r] given an approximate
/// inverse R of mid(A) and row_sum bounding the row sums of |I - R A| for every A in [A]
/// (residual_row_sums_into), or false if some row sum exceeds max_contraction.
template <class DM, class SV, class IV>
bool residual_enclosure_into(const DM& R, const SV& row_sum, const IV& r, IV& z) {
  const Eigen::Index n = R.rows();
  const upward_rounding mode;  // plain double operations below round upward
  const auto opaque = [](double v) { return interval_arith::opaque(v); };
  double beta = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(row_sum(i) <= max_contraction)) return false;  // NaN fails too
    beta = std::max(beta, row_sum(i));
  }
  for (Eigen::Index j = 0; j < n; ++j)
    if (!is_finite(r(j))) return false;
  z.resize(n);
  double z_max = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const interval s = sum_of_point_products(n, r, [&](Eigen::Index j) { return R(i, j); });
    z(i) = s;
    z_max = std::max(z_max, std::max(-s.lower(), s.upper()));
  }
  if (!(z_max <= std::numeric_limits<double>::max())) return false;
  const double one_minus_beta_down = -opaque(opaque(beta) - 1.0);  // 1 - beta rounded down (> 0)
  const double eps = opaque(opaque(z_max) / one_minus_beta_down);  // >= ||e||_inf, rounded up
  for (Eigen::Index i = 0; i < n; ++i) {
    const double delta = opaque(row_sum(i) * eps);
    z(i) += interval(-delta, delta, true);
  }
  for (Eigen::Index i = 0; i < n; ++i)
    if (!is_finite(z(i))) return false;
  return true;
}
/// The row sums of |C| for an interval matrix C (an enclosure of I - R A:
/// identity_minus_product_into), rounded up, into row_sum.
template <class IM, class SV>
void row_sums_of_magnitudes_into(const IM& C, SV& row_sum) {
  const Eigen::Index n = C.rows();
  const upward_rounding mode;
  row_sum.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    double s = 0;
    for (Eigen::Index j = 0; j < n; ++j)
      s = interval_arith::opaque(s + std::max(-C(i, j).lower(), C(i, j).upper()));
    row_sum(i) = s;
  }
}
/// The residual bound's correction A^-1 r from the enclosure C of I - R A (three products in
/// double: the tightest row sums, for systems small enough that they cost little), or from
/// residual_row_sums_into (one product: large systems); nullopt where the bound does not apply.
template <bool from_enclosure, class DM, class IM, class IV>
std::optional<IV> residual_enclosure(const DM& R, const IM& A, const IV& r) {
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, IV::MaxRowsAtCompileTime, 1> row_sum;
  if constexpr (from_enclosure) {
    Eigen::Matrix<interval, Eigen::Dynamic, Eigen::Dynamic, 0, IV::MaxRowsAtCompileTime, IV::MaxRowsAtCompileTime> C;
    identity_minus_product_into(R, A, C);
    row_sums_of_magnitudes_into(C, row_sum);
  } else {
    residual_row_sums_into(R, A, row_sum);
  }
  IV z;
  if (!residual_enclosure_into(R, row_sum, r, z)) return std::nullopt;
  return z;
}

/// The interval residual path for systems of at most small_system_max unknowns,
/// with every temporary on the stack (the heap-allocated temporaries of the
/// general path were ~60 allocations per evaluation of Example I, an interval-only
/// cost).  The same steps as residual_solve_into's, on fixed-capacity storage: false where the
/// residual bound does not apply or the midpoint is singular (the caller then decides).
inline constexpr Eigen::Index small_system_max = 12;
/// Into x (of its size already: no allocation); false where it does not apply.
bool small_interval_solve_into(const matrix_t<interval>& A, const vector_t<interval>& b, vector_t<interval>& x);
/// mpfi systems by the residual bound: x~ by mpfr LU, r = b - A x~ in mpfi,
/// the rest in double.  nullopt where it does not apply (the caller falls back).
std::optional<vector_t<mpfi>> mpfi_residual_solve(const matrix_t<mpfi>& A, const vector_t<mpfi>& b);
/// The same for arb, x~ from the double LU refined in mixed precision (no LU at the working
/// precision), r = b - A x~ by Arb's arb_dot, the rest as mpfi's.
std::optional<vector_t<arb>> arb_residual_solve(const matrix_t<arb>& A, const vector_t<arb>& b);

template <class M>
void check_square(const M& A, Eigen::Index rhs_rows) {
  if (A.rows() != A.cols() || A.rows() != rhs_rows)
    throw std::invalid_argument("solve: matrix is " + std::to_string(A.rows()) + "x" +
                                std::to_string(A.cols()) + ", right-hand side has " +
                                std::to_string(rhs_rows) + " rows");
}

}  // namespace detail

namespace detail {
/// verified_solve's refusal of data that are not square or not finite.
template <class I>
void check_finite_square(const matrix_t<I>& A, const vector_t<I>& b) {
  check_square(A, b.rows());
  const Eigen::Index n = A.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!is_finite(b(i))) throw certification_error("verified solve: right-hand side is not finite");
    for (Eigen::Index j = 0; j < n; ++j)
      if (!is_finite(A(i, j))) throw certification_error("verified solve: matrix is not finite");
  }
}
template <class Site>
bool residual_solve_into(const matrix_t<interval>& A, const vector_t<interval>& b, vector_t<interval>& x);

/// verified_solve without the mpfi residual path (finite data checked by the
/// caller): for interval, the residual bound first (try_residual_bound), then
/// Krawczyk's iteration.  Exposed for tests that compare the two.
template <class I>
vector_t<I> residual_or_krawczyk_solve(const matrix_t<I>& A, const vector_t<I>& b, bool try_residual_bound) {
  using P = bound_t<I>;
  const Eigen::Index n = A.rows();
  if constexpr (std::is_same_v<I, interval>)
    if (try_residual_bound) {  // the residual bound: on the stack up to small_system_max unknowns
      vector_t<I> x;
      if (n <= small_system_max ? small_interval_solve_into(A, b, x) : residual_solve_into<void>(A, b, x)) return x;
    }
  // Midpoint system, in the bound type.
  matrix_t<P> Am(n, n);
  vector_t<P> bm(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    bm(i) = mid(b(i));
    for (Eigen::Index j = 0; j < n; ++j) Am(i, j) = mid(A(i, j));
  }
  Eigen::PartialPivLU<matrix_t<P>> lu(Am);
  using std::abs;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(abs(lu.matrixLU()(i, i)) > 0))
      throw certification_error("verified solve: the midpoint matrix is singular");
  const matrix_t<P> R = lu.inverse();
  if (!R.allFinite()) throw certification_error("verified solve: the midpoint matrix is singular");
  vector_t<P> xt = R * bm;
  xt += R * (bm - Am * xt);  // one refinement step: a better centre, a thinner box

  // Krawczyk operator in interval arithmetic.
  const vector_t<I> xI = xt.unaryExpr([](const P& p) { return detail::thin<I>(p); });
  const vector_t<I> residual = b - detail::product(A, xI);
  // (past the residual bound, which has failed on these data or was not asked for)
  matrix_t<I> C;
  if constexpr (std::is_same_v<I, interval>) C = detail::identity_minus_product(R, A);  // midpoint-radius, O(n^3) in double
  const matrix_t<I> RI = R.unaryExpr([](const P& p) { return detail::thin<I>(p); });
  if constexpr (!std::is_same_v<I, interval>) {
    C = -detail::product(RI, A);
    for (Eigen::Index i = 0; i < n; ++i) C(i, i) += I(1);
  }
  const vector_t<I> z = detail::product(RI, residual);

  const I inflate = scalar_traits<I>::from_bounds(P(-0.1), P(0.1));  // Rump's epsilon-inflation
  const I tiny = scalar_traits<I>::from_bounds(-std::numeric_limits<double>::min(),
                                               std::numeric_limits<double>::min());
  vector_t<I> Y = z;
  for (int iteration = 0; iteration < 15; ++iteration) {
    for (Eigen::Index i = 0; i < n; ++i) Y(i) = Y(i) + inflate * Y(i) + tiny;
    vector_t<I> Ynew = z + detail::product(C, Y);
    bool inside = true;
    for (Eigen::Index i = 0; i < n && inside; ++i) inside = detail::in_interior(Ynew(i), Y(i));
    if (inside) {
      // Proved.  Contractions Y <- (z + C Y) /\ Y only tighten the box: up to
      // three, stopping once one gains less than 1/8 of the total width.
      auto total_width = [&](const vector_t<I>& y) {
        P w = P(0);
        for (Eigen::Index i = 0; i < n; ++i) w += width(y(i));
        return w;
      };
      P before = total_width(Ynew);
      for (int k = 0; k < 3; ++k) {
        vector_t<I> Yk = z + detail::product(C, Ynew);
        for (Eigen::Index i = 0; i < n; ++i) Ynew(i) = detail::intersect(Yk(i), Ynew(i));
        const P after = total_width(Ynew);
        if (!(after < before - before / 8)) break;
        before = after;
      }
      return xI + Ynew;
    }
    Y = Ynew;
  }
  // Refuse, with an estimate of why.
  P cond = P(0);
  {
    using std::abs;
    P norm_a = P(0), norm_r = P(0);
    for (Eigen::Index i = 0; i < n; ++i) {
      P ra = P(0), rr = P(0);
      for (Eigen::Index j = 0; j < n; ++j) {
        ra += abs(Am(i, j));
        rr += abs(R(i, j));
      }
      if (ra > norm_a) norm_a = ra;
      if (rr > norm_r) norm_r = rr;
    }
    cond = norm_a * norm_r;
  }
  std::ostringstream why;
  why << "verified solve: cannot certify the " << n << "x" << n
      << " system (the interval matrix may contain a singular one; estimated condition number "
      << static_cast<double>(cond) << " at " << scalar_traits<I>::precision_bits() << " bits)";
  throw certification_error(why.str());
}
}  // namespace detail

/// Every solution of A x = b for A in [A], b in [b], enclosed; or certification_error.
template <Scalar I>
  requires(scalar_traits<I>::is_interval)
vector_t<I> verified_solve(const matrix_t<I>& A, const vector_t<I>& b) {
  detail::check_finite_square(A, b);
  const Eigen::Index n = A.rows();
  if (n == 0) return vector_t<I>(0);
  if constexpr (std::is_same_v<I, mpfi>)
    if (auto x = detail::mpfi_residual_solve(A, b)) return *x;
  if constexpr (std::is_same_v<I, arb>)
    if (auto x = detail::arb_residual_solve(A, b)) return *x;
  return detail::residual_or_krawczyk_solve(A, b, /*try_residual_bound=*/true);
}

namespace detail {
/// The residual bound for an interval system of more than small_system_max unknowns, every
/// matrix borrowed from Site's pool (linalg/scratch.hpp): R ~ mid(A)^-1 by LU in double, x~ with
/// one refinement step, r = b - A x~ enclosed, the row sums of |I - R A| bounded a priori
/// (residual_row_sums_into), then residual_enclosure_into;
/// false where the bound does not give an enclosure (verified_solve then decides: Krawczyk's
/// iteration, or the refusal).
template <class Site>
bool residual_solve_into(const matrix_t<interval>& A, const vector_t<interval>& b, vector_t<interval>& x) {
  using P = double;
  const Eigen::Index n = A.rows();
  const scratch<matrix_t<P>, Site> Am_held, R_held;
  const scratch<vector_t<P>, Site> bm_held, xt_held, t_held, u_held;
  const scratch<Eigen::PartialPivLU<matrix_t<P>>, Site> lu;
  const scratch<vector_t<interval>, Site> xI_held, residual_held, e_held;
  const scratch<vector_t<P>, Site> row_sum_held;
  matrix_t<P>&Am = *Am_held, &R = *R_held;
  vector_t<P>&bm = *bm_held, &xt = *xt_held, &t = *t_held, &u = *u_held;
  vector_t<interval>&xI = *xI_held, &residual = *residual_held, &e = *e_held;
  Am.resize(n, n), bm.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    bm(i) = mid(b(i));
    for (Eigen::Index j = 0; j < n; ++j) Am(i, j) = mid(A(i, j));
  }
  lu->compute(Am);
  using std::abs;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(abs(lu->matrixLU()(i, i)) > 0)) return false;
  // lu.inverse()'s steps (P I, then the two triangular solves in place), without the copy of the
  // factors that assigning an Inverse expression makes
  R = lu->solve(matrix_t<P>::Identity(n, n));
  if (!R.allFinite()) return false;
  xt.noalias() = R * bm;
  // xt += R * (bm - Am * xt), as Eigen evaluates it there: Am xt, the difference, R times it,
  // each into a vector of its own, then the sum
  t.noalias() = Am * xt;
  t = bm - t;
  u.noalias() = R * t;
  xt += u;
  if (!xt.allFinite()) return false;
  xI = xt.unaryExpr([](const P& p) { return thin<interval>(p); });
  residual.resize(n);
  {
    const upward_rounding mode;
    for (Eigen::Index i = 0; i < n; ++i)  // b - A x~
      residual(i) = b(i) - sum_of_point_products(n, [&](Eigen::Index k) -> const interval& { return A(i, k); }, xt);
  }
  residual_row_sums_into<Site>(R, A, *row_sum_held);
  if (!residual_enclosure_into(R, *row_sum_held, residual, e)) return false;
  x.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = xI(i) + e(i);
  return true;
}
}  // namespace detail

/// verified_solve into x: for interval systems, the residual bound into x's storage (at most
/// small_system_max unknowns on the stack, more in borrowed storage), the same enclosure as
/// verified_solve's; where the bound does not apply, verified_solve itself.
template <class Site = void, Scalar I>
  requires(scalar_traits<I>::is_interval)
void verified_solve_into(const matrix_t<I>& A, const vector_t<I>& b, vector_t<I>& x) {
  if constexpr (std::is_same_v<I, interval>) {
    detail::check_finite_square(A, b);  // verified_solve's refusals
    const Eigen::Index n = A.rows();
    // verified_solve's own path (residual_or_krawczyk_solve: this bound first)
    if (n > 0 && n <= detail::small_system_max && detail::small_interval_solve_into(A, b, x)) return;
    if (n > detail::small_system_max && detail::residual_solve_into<Site>(A, b, x)) return;
  }
  x = verified_solve(A, b);  // Krawczyk's iteration, or its refusal
}

template <Scalar T>
vector_t<T> solve(const matrix_t<T>& A, const vector_t<T>& b);

namespace detail {
/// The scalars whose solves run here (the others, numbers carrying derivatives, have overloads
/// of solve and solve_spd of their own: derivatives/, found by argument-dependent lookup).
template <class T>
inline constexpr bool solved_here = std::is_same_v<T, double> || std::is_same_v<T, long double> ||
                                    std::is_same_v<T, dd> || std::is_same_v<T, float128> ||
                                    std::is_same_v<T, mpfr> || std::is_same_v<T, interval> || std::is_same_v<T, mpfi> ||
                                    std::is_same_v<T, arb>;
/// Cholesky's solve of a point system into x, the factor borrowed from Site's pool (linalg/scratch.hpp).
template <class Site, class T>
void cholesky_solve_into(const matrix_t<T>& A, const vector_t<T>& b, vector_t<T>& x) {
  check_square(A, b.rows());
  const scratch<Eigen::LLT<matrix_t<T>>, Site> llt;
  llt->compute(A);
  if (llt->info() != Eigen::Success) throw certification_error("Cholesky: the matrix is not positive definite");
  x.resize(b.rows());
  x = llt->solve(b);
}
/// LU's solve (partial pivoting) of a point system into x, the factors borrowed from Site's pool.
template <class Site, class T>
void lu_solve_into(const matrix_t<T>& A, const vector_t<T>& b, vector_t<T>& x) {
  check_square(A, b.rows());
  const scratch<Eigen::PartialPivLU<matrix_t<T>>, Site> lu;
  lu->compute(A);
  using std::abs;
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    if (!(abs(lu->matrixLU()(i, i)) > 0)) throw certification_error("LU: the matrix is singular");
  x.resize(b.rows());
  x = lu->solve(b);
}
}  // namespace detail

/// A x = b for a symmetric positive definite A.
template <Scalar T>
vector_t<T> solve_spd(const matrix_t<T>& A, const vector_t<T>& b) {
  if constexpr (scalar_traits<T>::is_interval) {
    return verified_solve(A, b);
  } else if constexpr (requires { scalar_traits<T>::is_exact; }) {
    return solve(A, b);  // exact rationals have no square root: LU is exact
  } else {
    struct site;
    vector_t<T> x;
    detail::cholesky_solve_into<site>(A, b, x);
    return x;
  }
}

/// The same into x (point types: the factor's and x's storage reused, no allocation when they
/// have their sizes already; interval types: verified_solve_into).
/// Site: the caller's tag for the factor's storage (linalg/scratch.hpp: an Eigen object keeps one
/// size, so each caller whose systems have a size of their own keeps a factor of its own).
template <class Site = void, class T>  // T unconstrained: the derivative types go to their own overloads
void solve_spd_into(const matrix_t<T>& A, const vector_t<T>& b, vector_t<T>& x) {
  if constexpr (!detail::solved_here<T>) {
    x = solve_spd(A, b);  // an overload of the type's own, or the exact types' LU
  } else if constexpr (scalar_traits<T>::is_interval) {
    verified_solve_into<Site>(A, b, x);
  } else {
    detail::cholesky_solve_into<Site>(A, b, x);
  }
}

/// The same into x (point types: the factors' and x's storage reused; interval types:
/// verified_solve_into).
template <class Site = void, class T>  // as solve_spd_into
void solve_into(const matrix_t<T>& A, const vector_t<T>& b, vector_t<T>& x) {
  if constexpr (!detail::solved_here<T>) {
    x = solve(A, b);  // an overload of the type's own, or the exact types' LU
  } else if constexpr (scalar_traits<T>::is_interval) {
    verified_solve_into<Site>(A, b, x);
  } else {
    detail::lu_solve_into<Site>(A, b, x);
  }
}

/// A x = b for a general square A.
template <Scalar T>
vector_t<T> solve(const matrix_t<T>& A, const vector_t<T>& b) {
  if constexpr (scalar_traits<T>::is_interval) {
    return verified_solve(A, b);
  } else {
    struct site;  // the factors' storage reused
    vector_t<T> x;
    detail::lu_solve_into<site>(A, b, x);
    return x;
  }
}

}  // namespace appell
