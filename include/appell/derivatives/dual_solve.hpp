// appell/derivatives/dual_solve.hpp -- linear solves on multi_dual numbers.
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
// For slopes (derivatives/slope.hpp), with A and b given over a box (v), at its centre (c) and by
// their slopes (d_k):
//   y_c = A_c^-1 b_c,  y_v = A_v^-1 b_v,  y_k = A_v^-1 (b_k - A_k y_c),
// from y(x) - y(xh) = A(x)^-1 ((b(x) - b(xh)) - (A(x) - A(xh)) y(xh)): the slope's solve has the
// box's matrix and the centre's solution where the derivative's has the value's twice.
#pragma once

#include <algorithm>

#include "appell/derivatives/dual.hpp"
#include "appell/derivatives/slope.hpp"
#include "appell/linalg/solve.hpp"

namespace appell {

namespace detail {
/// The derivative parts d_k of the solution of A y = b: A_m^-1 (b_k - A_k y), each into r(i).d[k]
/// (multi_dual: A_m the value's matrix and y the value; slope: A_m the box's matrix and y the
/// centre's solution).  A direction in which A and b are exactly constant is skipped (0).
template <class X, class T, class Solve>
void solve_derivatives(const matrix_t<X>& A, const vector_t<X>& b, const matrix_t<T>& Am, const vector_t<T>& y,
                       vector_t<X>& r, Solve&& value_solve) {
  const Eigen::Index n = A.rows();
  // slopes of a run-time count: a constant's list is empty (every slope 0); the others' as long
  std::size_t count = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    count = std::max(count, b(i).d.size());
    for (Eigen::Index j = 0; j < n; ++j) count = std::max(count, A(i, j).d.size());
  }
  auto part = [](const X& x, std::size_t k) -> T {
    if constexpr (requires { x.part(k); }) return x.part(k);
    else return x.d[k];
  };
  for (std::size_t k = 0; k < count; ++k) {
    bool constant = true;
    vector_t<T> rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      T x = part(b(i), k);
      constant = constant && structurally_zero(x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (k >= A(i, j).d.size() || structurally_zero(A(i, j).d[k])) continue;
        constant = false;
        x -= A(i, j).d[k] * y(j);
      }
      rhs(i) = x;
    }
    if (constant) continue;
    const vector_t<T> yk = value_solve(Am, rhs);
    for (Eigen::Index i = 0; i < n; ++i) {
      if constexpr (requires { r(i).d.resize(count); })  // a run-time count: the result may start empty
        if (r(i).d.size() < count) r(i).d.resize(count);
      r(i).d[k] = yk(i);
    }
  }
}
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
  solve_derivatives(A, b, Av, y, r, value_solve);
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
  solve_derivatives(A, b, Av, yc, r, value_solve);
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
