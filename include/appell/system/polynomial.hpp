// appell/system/polynomial.hpp -- characteristic polynomials and their roots,
// enclosed.
//
//   characteristic_polynomial(A)   det(s I - A) by Faddeev-LeVerrier (exact
//                                  operations: in interval types an enclosure);
//   determinant(A)                 by elimination; a pivot that may be 0 in an
//                                  interval type: certification_error;
//   hurwitz_determinant(c)         Delta_(n-1) of c_0 + ... + c_n s^n: by
//                                  Orlando's formula, +-c_n^(n-1) prod_(i<j)
//                                  (s_i + s_j), it vanishes exactly when two roots
//                                  sum to 0 (a pair +-i w on the imaginary axis);
//   polynomial_roots(c)            every root of a monic polynomial, enclosed.
// The roots: approximations z_i (Eigen on the midpoints, then Newton in the
// bound type), then, with W_i = p(z_i) / prod_(j != i) (z_i - z_j), p is the
// characteristic polynomial of diag(z) - W 1^T, whose Gerschgorin discs are
// centred at z_i - W_i with radius (n - 1)|W_i|; they lie in the discs
// |s - z_i| <= n |W_i|.  So every root lies in the union of those discs, and a
// disc disjoint from the others holds exactly one root (Gerschgorin; for a
// polynomial with interval coefficients, for every polynomial they hold, with
// |W_i| bounded over all of them).  A real centre's isolated disc holds a real
// root (the conjugate of a complex one would be a second root in it).  Point
// types get the approximations with radius 0 (nothing certified).
#pragma once

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <vector>

#include "appell/derivatives/dual.hpp"
#include "appell/linalg/solve.hpp"

namespace appell {

namespace detail {
/// T's value of a bound (the thin interval for interval types).
template <Scalar T>
T from_bound(const bound_t<T>& p) {
  if constexpr (scalar_traits<T>::is_interval) return scalar_traits<T>::from_bounds(p, p);
  else return p;
}
}  // namespace detail

/// det(s I - A) = c_0 + c_1 s + ... + s^n: returns c_0 .. c_n.  S: a scalar or a dual of one.
template <class S>
std::vector<S> characteristic_polynomial(const matrix_t<S>& A) {
  const Eigen::Index n = A.rows();
  std::vector<S> c(static_cast<std::size_t>(n + 1), S(0));
  c[static_cast<std::size_t>(n)] = S(1);
  matrix_t<S> Mk = matrix_t<S>::Zero(n, n), AM(n, n);
  for (Eigen::Index k = 1; k <= n; ++k) {
    // M_k = A M_(k-1) + c_(n-k+1) I;  c_(n-k) = -tr(A M_k) / k
    matrix_t<S> next = k == 1 ? matrix_t<S>(matrix_t<S>::Zero(n, n)) : detail::product(A, Mk);
    for (Eigen::Index i = 0; i < n; ++i) next(i, i) += c[static_cast<std::size_t>(n - k + 1)];
    Mk = next;
    S trace = S(0);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) trace += A(i, j) * Mk(j, i);
    c[static_cast<std::size_t>(n - k)] = -trace / S(static_cast<int>(k));
  }
  return c;
}

/// det A: up to 6 x 6 by expansion in minors (no division: defined whatever
/// the entries, in interval types an enclosure), larger by Gaussian elimination
/// with pivots chosen on the values' midpoints.
template <class S>
S determinant(matrix_t<S> A) {
  const Eigen::Index n = A.rows();
  if (n == 0) return S(1);
  if (n == 1) return A(0, 0);
  if (n <= 6) {
    S det = S(0);
    for (Eigen::Index j = 0; j < n; ++j) {
      if (structurally_zero(A(0, j))) continue;
      matrix_t<S> minor(n - 1, n - 1);
      for (Eigen::Index r = 1; r < n; ++r)
        for (Eigen::Index c = 0, k = 0; c < n; ++c)
          if (c != j) minor(r - 1, k++) = A(r, c);
      const S term = A(0, j) * determinant(minor);
      det = j % 2 == 0 ? S(det + term) : S(det - term);
    }
    return det;
  }
  S det = S(1);
  for (Eigen::Index p = 0; p < n; ++p) {
    Eigen::Index best = p;
    double best_abs = -1;
    for (Eigen::Index r = p; r < n; ++r) {
      const double a = std::abs(approx_double(detail::value_of(A(r, p))));
      if (a > best_abs) best_abs = a, best = r;
    }
    if (best != p) {
      A.row(p).swap(A.row(best));
      det = -det;
    }
    const auto& pivot = detail::value_of(A(p, p));
    if (possibly_zero(pivot)) {
      if (!scalar_traits<base_scalar_t<S>>::is_interval) return S(0);
      throw certification_error("determinant: a pivot may be 0");
    }
    det *= A(p, p);
    for (Eigen::Index r = p + 1; r < n; ++r) {
      const S f = A(r, p) / A(p, p);
      for (Eigen::Index j = p + 1; j < n; ++j) A(r, j) -= f * A(p, j);
    }
  }
  return det;
}

/// Delta_(n-1), the Hurwitz determinant of order n - 1 of c_0 + ... + c_n s^n (n >= 2).
template <class S>
S hurwitz_determinant(const std::vector<S>& c) {
  const int n = static_cast<int>(c.size()) - 1;
  auto a = [&](int k) { return k < 0 || k > n ? S(0) : c[static_cast<std::size_t>(k)]; };
  matrix_t<S> H(n - 1, n - 1);
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) H(i - 1, j - 1) = a(n - 2 * j + i);
  return determinant(H);
}

/// One root of a polynomial: centre z, radius r (an upper bound; 0 for point
/// types) and its enclosure as real and imaginary parts in T.
template <Scalar T>
struct root_enclosure {
  bound_t<T> re, im, radius;
  T real_part, imaginary_part;
  bool isolated = false;  ///< its disc meets no other: exactly one root in it
};

/// The roots of c_0 + c_1 s + ... + c_n s^n, c_n = 1 (see the top of this file).
template <Scalar T>
std::vector<root_enclosure<T>> polynomial_roots(const std::vector<T>& c) {
  using P = bound_t<T>;
  const int n = static_cast<int>(c.size()) - 1;
  std::vector<root_enclosure<T>> out;
  if (n < 1) return out;
  // Approximations: the companion matrix's eigenvalues in double, then Newton in P.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i < n; ++i) C(i, i - 1) = 1;
  for (int i = 0; i < n; ++i) C(i, n - 1) = -approx_double(c[static_cast<std::size_t>(i)]);
  const Eigen::VectorXcd z0 = Eigen::EigenSolver<Eigen::MatrixXd>(C, false).eigenvalues();
  std::vector<P> cm(static_cast<std::size_t>(n + 1));
  for (int k = 0; k <= n; ++k) cm[static_cast<std::size_t>(k)] = scalar_traits<T>::mid(c[static_cast<std::size_t>(k)]);
  struct cx {
    P re, im;
  };
  auto mul = [](const cx& a, const cx& b) { return cx{P(a.re * b.re - a.im * b.im), P(a.re * b.im + a.im * b.re)}; };
  std::vector<cx> z;
  const int bits = static_cast<int>(scalar_traits<T>::precision_bits());
  for (int i = 0; i < n; ++i) {
    cx x{P(z0(i).real()), P(z0(i).imag())};
    for (int it = 0; it < 8 + bits / 8; ++it) {
      cx p{cm[static_cast<std::size_t>(n)], P(0)}, dp{P(0), P(0)};
      for (int k = n - 1; k >= 0; --k) {
        dp = mul(dp, x);
        dp.re += p.re, dp.im += p.im;
        p = mul(p, x);
        p.re += cm[static_cast<std::size_t>(k)];
      }
      const P den = dp.re * dp.re + dp.im * dp.im;
      if (!(den > 0)) break;
      const cx step{P((p.re * dp.re + p.im * dp.im) / den), P((p.im * dp.re - p.re * dp.im) / den)};
      x.re -= step.re, x.im -= step.im;
      using std::abs;
      const P size = abs(x.re) + abs(x.im);
      if (!(abs(step.re) + abs(step.im) > size * P(std::ldexp(1.0, -std::min(bits, 1000) + 2)))) break;
    }
    z.push_back(x);
  }
  // Enclosures: radius n |W_i| bounded above in T.
  struct ct {
    T re, im;
  };
  auto cmul = [](const ct& a, const ct& b) { return ct{T(a.re * b.re - a.im * b.im), T(a.re * b.im + a.im * b.re)}; };
  std::vector<P> radius(static_cast<std::size_t>(n), P(0));
  if constexpr (scalar_traits<T>::is_interval) {
    for (int i = 0; i < n; ++i) {
      const ct zi{detail::from_bound<T>(z[static_cast<std::size_t>(i)].re), detail::from_bound<T>(z[static_cast<std::size_t>(i)].im)};
      ct p{c[static_cast<std::size_t>(n)], T(0)};
      for (int k = n - 1; k >= 0; --k) {
        p = cmul(p, zi);
        p.re += c[static_cast<std::size_t>(k)];
      }
      T den(1);
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        const T dr = zi.re - detail::from_bound<T>(z[static_cast<std::size_t>(j)].re);
        const T di = zi.im - detail::from_bound<T>(z[static_cast<std::size_t>(j)].im);
        using std::sqrt;
        den *= sqrt(T(sqr(dr) + sqr(di)));
      }
      if (!certainly_positive(den)) throw certification_error("polynomial roots: two approximations coincide");
      using std::sqrt;
      const T w = T(n) * sqrt(T(sqr(p.re) + sqr(p.im))) / den;
      radius[static_cast<std::size_t>(i)] = upper(w);
    }
  }
  for (int i = 0; i < n; ++i) {
    root_enclosure<T> r;
    r.re = z[static_cast<std::size_t>(i)].re;
    r.im = z[static_cast<std::size_t>(i)].im;
    r.radius = radius[static_cast<std::size_t>(i)];
    r.isolated = true;
    if constexpr (scalar_traits<T>::is_interval) {
      for (int j = 0; j < n && r.isolated; ++j) {
        if (j == i) continue;
        const T dr = detail::from_bound<T>(r.re) - detail::from_bound<T>(z[static_cast<std::size_t>(j)].re);
        const T di = detail::from_bound<T>(r.im) - detail::from_bound<T>(z[static_cast<std::size_t>(j)].im);
        const T gap = T(sqr(dr) + sqr(di)) -
                      sqr(T(detail::from_bound<T>(r.radius) + detail::from_bound<T>(radius[static_cast<std::size_t>(j)])));
        r.isolated = certainly_positive(gap);
      }
      const T spread = scalar_traits<T>::from_bounds(P(-r.radius), r.radius);
      r.real_part = detail::from_bound<T>(r.re) + spread;
      // an isolated disc centred on the real axis holds a real root
      r.imaginary_part = r.isolated && r.im == 0 ? T(0) : T(detail::from_bound<T>(r.im) + spread);
    } else {
      r.real_part = r.re;
      r.imaginary_part = r.im;
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace appell
