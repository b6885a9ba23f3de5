// appell/linalg/dual_solve.hpp -- linear solves on multi_dual numbers.
//
// For A(x) y = b(x) with A, b carrying N derivatives (multi_dual<T, N>):
//   y   = A^-1 b                    (the value: solve or solve_spd in T),
//   y_k = A^-1 (b_k - A_k y)        (each derivative: the same matrix, the
//                                    right-hand side of the differentiated system).
// In interval types each solve is the verified one, and the right-hand side
// b_k - A_k y is formed with the enclosure of y: the true derivative solves the
// true system, whose matrix and right-hand side lie in the enclosed ones, so
// its enclosure holds it.  A direction in which A and b are exactly constant
// (every part structurally 0) has derivative exactly 0 and costs nothing.
// The overloads below are more specialized than solve.hpp's templates and are
// found by argument-dependent lookup wherever the generic path calls solve.
//
// For slopes (dynamics/slope.hpp), with A and b given over a box (v), at its centre (c) and by
// their slopes (d_k):
//   y_c = A_c^-1 b_c,  y_v = A_v^-1 b_v,  y_k = A_v^-1 (b_k - A_k y_c),
// from y(x) - y(xh) = A(x)^-1 ((b(x) - b(xh)) - (A(x) - A(xh)) y(xh)): the slope's solve has the
// box's matrix and the centre's solution where the derivative's has the value's twice.
#pragma once

#include "appell/dynamics/dual.hpp"
#include "appell/dynamics/slope.hpp"
#include "appell/linalg/solve.hpp"

namespace appell {

namespace detail {
template <class T, int N, class Solve>
vector_t<multi_dual<T, N>> dual_solve(const matrix_t<multi_dual<T, N>>& A, const vector_t<multi_dual<T, N>>& b,
                                      Solve&& value_solve) {
  check_square(A, b.rows());
  const Eigen::Index n = A.rows();
  matrix_t<T> Av(n, n);
  vector_t<T> bv(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    bv(i) = b(i).v;
    for (Eigen::Index j = 0; j < n; ++j) Av(i, j) = A(i, j).v;
  }
  const vector_t<T> y = value_solve(Av, bv);
  vector_t<multi_dual<T, N>> r(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = multi_dual<T, N>(y(i));
  for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
    bool constant = true;
    vector_t<T> rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      T x = b(i).d[k];
      constant = constant && structurally_zero(x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (structurally_zero(A(i, j).d[k])) continue;
        constant = false;
        x -= A(i, j).d[k] * y(j);
      }
      rhs(i) = x;
    }
    if (constant) continue;
    const vector_t<T> yk = value_solve(Av, rhs);
    for (Eigen::Index i = 0; i < n; ++i) r(i).d[k] = yk(i);
  }
  return r;
}

template <class T, int N, class Solve>
vector_t<slope<T, N>> slope_solve(const matrix_t<slope<T, N>>& A, const vector_t<slope<T, N>>& b, Solve&& value_solve) {
  check_square(A, b.rows());
  const Eigen::Index n = A.rows();
  matrix_t<T> Av(n, n), Ac(n, n);
  vector_t<T> bv(n), bc(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    bv(i) = b(i).v;
    bc(i) = b(i).c;
    for (Eigen::Index j = 0; j < n; ++j) {
      Av(i, j) = A(i, j).v;
      Ac(i, j) = A(i, j).c;
    }
  }
  const vector_t<T> yv = value_solve(Av, bv), yc = value_solve(Ac, bc);
  vector_t<slope<T, N>> r(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = slope<T, N>(yv(i), yc(i));
  for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
    bool constant = true;
    vector_t<T> rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      T x = b(i).d[k];
      constant = constant && structurally_zero(x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (structurally_zero(A(i, j).d[k])) continue;
        constant = false;
        x -= A(i, j).d[k] * yc(j);
      }
      rhs(i) = x;
    }
    if (constant) continue;
    const vector_t<T> yk = value_solve(Av, rhs);
    for (Eigen::Index i = 0; i < n; ++i) r(i).d[k] = yk(i);
  }
  return r;
}
}  // namespace detail

template <class T, int N>
vector_t<slope<T, N>> solve(const matrix_t<slope<T, N>>& A, const vector_t<slope<T, N>>& b) {
  return detail::slope_solve(A, b, [](const matrix_t<T>& M, const vector_t<T>& r) { return solve(M, r); });
}

template <class T, int N>
vector_t<slope<T, N>> solve_spd(const matrix_t<slope<T, N>>& A, const vector_t<slope<T, N>>& b) {
  return detail::slope_solve(A, b, [](const matrix_t<T>& M, const vector_t<T>& r) { return solve_spd(M, r); });
}

template <class T, int N>
vector_t<multi_dual<T, N>> solve(const matrix_t<multi_dual<T, N>>& A, const vector_t<multi_dual<T, N>>& b) {
  return detail::dual_solve(A, b, [](const matrix_t<T>& M, const vector_t<T>& r) { return solve(M, r); });
}

template <class T, int N>
vector_t<multi_dual<T, N>> solve_spd(const matrix_t<multi_dual<T, N>>& A, const vector_t<multi_dual<T, N>>& b) {
  return detail::dual_solve(A, b, [](const matrix_t<T>& M, const vector_t<T>& r) { return solve_spd(M, r); });
}

}  // namespace appell
