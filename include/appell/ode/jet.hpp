// appell/ode/jet.hpp -- truncated Taylor series over any scalar.
//
// A jet x(t) = x_0 + x_1 t + ... + x_n t^n carries the Taylor coefficients of a
// quantity along a motion.  The existing templated dynamics (the generic
// Gibbs-Appell path, Cotton's reactions, the scenes) run on jet<T> unchanged:
// evaluated on the jet of the state, a scene's accelerations come out as the
// jet of the accelerations, and the ODE's coefficients follow by
// x_{k+1} = f(x)_k / (k + 1) (ode/taylor.hpp).
//
// The order n is the same for every jet of one evaluation: a thread-local set
// by jet_order_scope.  A jet stores only its leading coefficients; the ones it
// does not store are exact zeros (a constant stores one coefficient), so
// constants cost what a scalar costs, and a product's length is the sum of
// its factors' lengths, capped at n + 1.  Every rule is the classical
// recurrence (Moore 1966; Griewank & Walther, ch. 13), one loop each; with
// interval coefficients each coefficient is enclosed as rigorously as the
// scalar operations it is made of.
//
// Comparisons are not defined on jets: library code uses the predicates of
// scalar/traits.hpp, which on a jet decide on its constant term (the value
// at t = 0).  Linear solves go order by order with the constant-term matrix
// factorized once (solve_spd below).
#pragma once

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

#include "appell/dynamics/dual.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/scalar/eigen.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

namespace detail {
inline thread_local int jet_current_order = 0;
}

/// The order of the jets made in this thread (the highest power kept).
inline int jet_order() { return detail::jet_current_order; }

/// Sets the order of the jets for a scope.
class jet_order_scope {
 public:
  explicit jet_order_scope(int n) : saved_(detail::jet_current_order) {
    if (n < 0) throw std::invalid_argument("jet order must be nonnegative");
    detail::jet_current_order = n;
  }
  ~jet_order_scope() { detail::jet_current_order = saved_; }
  jet_order_scope(const jet_order_scope&) = delete;
  jet_order_scope& operator=(const jet_order_scope&) = delete;

 private:
  int saved_;
};

template <class T>
struct jet {
  /// c[k] = coefficient of t^k; those past c.size() are exact zeros.  A constant keeps its one
  /// coefficient inline (no allocation): most jets of a scene's evaluation are constants.
  boost::container::small_vector<T, 1> c;

  jet() : c(1, T(0)) {}
  jet(const T& v) : c(1, v) {}  // NOLINT: constants convert implicitly
  template <class N>
    requires std::is_arithmetic_v<N>
  jet(N n) : c(1, T(n)) {}  // NOLINT
  explicit jet(const std::vector<T>& coefficients) : c(coefficients.begin(), coefficients.end()) {
    if (c.empty()) c.assign(1, T(0));
    truncate();
  }

  /// Coefficient k (an exact zero past the stored ones).
  T operator[](int k) const { return k < size() ? c[static_cast<std::size_t>(k)] : T(0); }
  int size() const { return static_cast<int>(c.size()); }
  const T& value() const { return c[0]; }
  void truncate() {
    const auto cap = static_cast<std::size_t>(jet_order() + 1);
    if (c.size() > cap) c.resize(cap);
  }

  jet& operator+=(const jet& o) {
    if (o.c.size() > c.size()) c.resize(std::min(o.c.size(), static_cast<std::size_t>(jet_order() + 1)), T(0));
    for (std::size_t k = 0; k < c.size() && k < o.c.size(); ++k) c[k] += o.c[k];
    return *this;
  }
  jet& operator-=(const jet& o) {
    if (o.c.size() > c.size()) c.resize(std::min(o.c.size(), static_cast<std::size_t>(jet_order() + 1)), T(0));
    for (std::size_t k = 0; k < c.size() && k < o.c.size(); ++k) c[k] -= o.c[k];
    return *this;
  }
  jet& operator*=(const jet& o) { return *this = *this * o; }
  jet& operator/=(const jet& o) { return *this = *this / o; }

  friend jet operator+(const jet& a) { return a; }
  friend jet operator-(const jet& a) {
    jet r = a;
    for (T& x : r.c) x = -x;
    return r;
  }
  friend jet operator+(const jet& a, const jet& b) {
    if (b.c.size() > a.c.size()) return b + a;
    jet r(a);
    for (std::size_t k = 0; k < b.c.size(); ++k) r.c[k] += b.c[k];
    return r;
  }
  friend jet operator-(const jet& a, const jet& b) {
    if (b.c.size() > a.c.size()) {
      jet r(-b);
      for (std::size_t k = 0; k < a.c.size(); ++k) r.c[k] += a.c[k];
      return r;
    }
    jet r(a);
    for (std::size_t k = 0; k < b.c.size(); ++k) r.c[k] -= b.c[k];
    return r;
  }
  friend jet operator*(const jet& a, const jet& b) {
    const int n = jet_order();
    const int la = std::min(a.size(), n + 1), lb = std::min(b.size(), n + 1);
    if (lb == 1) {
      jet r;
      r.c.resize(static_cast<std::size_t>(la));
      for (int k = 0; k < la; ++k) r.c[static_cast<std::size_t>(k)] = a.c[static_cast<std::size_t>(k)] * b.c[0];
      return r;
    }
    if (la == 1) return b * a;
    const int lr = std::min(la + lb - 1, n + 1);
    jet r;
    r.c.assign(static_cast<std::size_t>(lr), T(0));
    for (int k = 0; k < lr; ++k) {
      T s = T(0);
      const int lo = std::max(0, k - lb + 1), hi = std::min(k, la - 1);
      for (int i = lo; i <= hi; ++i) s += a.c[static_cast<std::size_t>(i)] * b.c[static_cast<std::size_t>(k - i)];
      r.c[static_cast<std::size_t>(k)] = s;
    }
    return r;
  }
  /// q = a / b: q_k = (a_k - sum_{j=1..k} b_j q_{k-j}) / b_0.
  friend jet operator/(const jet& a, const jet& b) {
    const int n = jet_order();
    const int lb = std::min(b.size(), n + 1);
    if (lb == 1) {
      jet r = a;
      r.truncate();
      for (T& x : r.c) x /= b.c[0];
      return r;
    }
    jet r;
    r.c.assign(static_cast<std::size_t>(n + 1), T(0));
    for (int k = 0; k <= n; ++k) {
      T s = a[k];
      for (int j = 1; j <= std::min(k, lb - 1); ++j) s -= b.c[static_cast<std::size_t>(j)] * r.c[static_cast<std::size_t>(k - j)];
      r.c[static_cast<std::size_t>(k)] = s / b.c[0];
    }
    return r;
  }
};


/// s = sin x, c = cos x together: k s_k = sum_j j x_j c_{k-j}, k c_k = -sum_j j x_j s_{k-j}.
template <class T>
void sin_cos(const jet<T>& x, jet<T>& s, jet<T>& c) {
  const int n = x.size() == 1 ? 0 : jet_order();
  T s0, c0;
  sin_cos(x.c[0], s0, c0);
  s.c.assign(static_cast<std::size_t>(n + 1), T(0));
  c.c.assign(static_cast<std::size_t>(n + 1), T(0));
  s.c[0] = s0;
  c.c[0] = c0;
  const int lx = x.size();
  for (int k = 1; k <= n; ++k) {
    T a = T(0), b = T(0);
    for (int j = 1; j <= std::min(k, lx - 1); ++j) {
      const T jx = T(j) * x.c[static_cast<std::size_t>(j)];
      a += jx * c.c[static_cast<std::size_t>(k - j)];
      b += jx * s.c[static_cast<std::size_t>(k - j)];
    }
    s.c[static_cast<std::size_t>(k)] = a / T(k);
    c.c[static_cast<std::size_t>(k)] = -b / T(k);
  }
}
template <class T> jet<T> sin(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return s; }
template <class T> jet<T> cos(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return c; }
template <class T> jet<T> tan(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return s / c; }
/// r = sqrt(x): r_0 = sqrt(x_0), r_k = (x_k - sum_{j=1..k-1} r_j r_{k-j}) / (2 r_0).
template <class T> jet<T> sqrt(const jet<T>& x) {
  using std::sqrt;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  r.c[0] = sqrt(x.c[0]);
  const T two_r0 = T(2) * r.c[0];
  for (int k = 1; k <= n; ++k) {
    T s = x[k];
    for (int j = 1; j < k; ++j) s -= r.c[static_cast<std::size_t>(j)] * r.c[static_cast<std::size_t>(k - j)];
    r.c[static_cast<std::size_t>(k)] = s / two_r0;
  }
  return r;
}
/// e = exp(x): k e_k = sum_j j x_j e_{k-j}.
template <class T> jet<T> exp(const jet<T>& x) {
  using std::exp;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> e;
  e.c.assign(static_cast<std::size_t>(n + 1), T(0));
  e.c[0] = exp(x.c[0]);
  for (int k = 1; k <= n; ++k) {
    T s = T(0);
    for (int j = 1; j <= std::min(k, x.size() - 1); ++j) s += T(j) * x.c[static_cast<std::size_t>(j)] * e.c[static_cast<std::size_t>(k - j)];
    e.c[static_cast<std::size_t>(k)] = s / T(k);
  }
  return e;
}
/// l = log(x): x_0 k l_k = k x_k - sum_{j=1..k-1} j l_j x_{k-j}.
template <class T> jet<T> log(const jet<T>& x) {
  using std::log;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> l;
  l.c.assign(static_cast<std::size_t>(n + 1), T(0));
  l.c[0] = log(x.c[0]);
  for (int k = 1; k <= n; ++k) {
    T s = T(k) * x[k];
    for (int j = 1; j < k; ++j) s -= T(j) * l.c[static_cast<std::size_t>(j)] * x[k - j];
    l.c[static_cast<std::size_t>(k)] = s / (T(k) * x.c[0]);
  }
  return l;
}
/// atan(x) = integral of x' / (1 + x^2).
template <class T> jet<T> atan(const jet<T>& x) {
  using std::atan;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  r.c[0] = atan(x.c[0]);
  if (n == 0) return r;
  jet<T> dx;  // x'
  dx.c.assign(static_cast<std::size_t>(n), T(0));
  for (int k = 1; k <= n; ++k) dx.c[static_cast<std::size_t>(k - 1)] = T(k) * x[k];
  const jet<T> q = dx / (jet<T>(T(1)) + x * x);
  for (int k = 1; k <= n; ++k) r.c[static_cast<std::size_t>(k)] = q[k - 1] / T(k);
  return r;
}
template <class T> jet<T> pown(const jet<T>& x, int n) {
  if (n < 0) return jet<T>(T(1)) / pown(x, -n);
  jet<T> r(T(1)), b = x;
  while (n > 0) {  // x^n by squaring: exact powers of the series
    if (n & 1) r = r * b;
    n >>= 1;
    if (n > 0) b = b * b;
  }
  return r;
}
template <class T> jet<T> sqr(const jet<T>& x) { return x * x; }

template <class T>
  requires Scalar<T>
struct scalar_traits<jet<T>> {
  static constexpr const char* name = "jet";
  static constexpr bool is_interval = false;  // a jet is not a set: predicates decide on its constant term
  static constexpr bool is_rigorous = scalar_traits<T>::is_rigorous;
  static constexpr bool runtime_precision = scalar_traits<T>::runtime_precision;
  static constexpr bool needs_upward_rounding = scalar_traits<T>::needs_upward_rounding;
  using bound_type = bound_t<T>;
  static unsigned precision_bits() { return scalar_traits<T>::precision_bits(); }
  static bound_type lower(const jet<T>& x) { return scalar_traits<T>::lower(x.c[0]); }
  static bound_type upper(const jet<T>& x) { return scalar_traits<T>::upper(x.c[0]); }
  static bound_type mid(const jet<T>& x) { return scalar_traits<T>::mid(x.c[0]); }
  static bound_type width(const jet<T>& x) { return scalar_traits<T>::width(x.c[0]); }
};

template <class T> bool exactly_zero(const jet<T>& x) {
  for (const T& v : x.c)
    if (!exactly_zero(v)) return false;
  return true;
}
template <class T> bool exactly_one(const jet<T>& x) {
  if (!exactly_one(x.c[0])) return false;
  for (std::size_t k = 1; k < x.c.size(); ++k)
    if (!exactly_zero(x.c[k])) return false;
  return true;
}
template <class T> bool is_finite(const jet<T>& x) {
  for (const T& v : x.c)
    if (!is_finite(v)) return false;
  return true;
}

/// Coefficient k of every entry of a matrix of jets.
template <class T, int R, int C>
Eigen::Matrix<T, R, C> coefficient(const Eigen::Matrix<jet<T>, R, C>& m, int k) {
  Eigen::Matrix<T, R, C> r(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) r(i, j) = m(i, j)[k];
  return r;
}

namespace detail {
/// A x = b on jets, order by order: A_0 x_k = b_k - sum_{j=1..k} A_j x_{k-j},
/// A_0 factorized once (point types: Cholesky when spd, else LU with partial
/// pivoting); for interval coefficients the value is a verified solve with A_0
/// (linalg/solve.hpp) and the higher orders are products with a verified
/// enclosure of A_0^-1 (its columns solved once), so every coefficient encloses
/// the exact one.
template <class T>
vector_t<jet<T>> jet_solve(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b, bool spd) {
  check_square(A, b.rows());
  const Eigen::Index m = A.rows();
  const int n = jet_order();
  int la = 1;
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) la = std::max(la, std::min(A(i, j).size(), n + 1));
  const matrix_t<T> A0 = coefficient(A, 0);
  std::vector<matrix_t<T>> Aj(static_cast<std::size_t>(la));
  for (int j = 1; j < la; ++j) Aj[static_cast<std::size_t>(j)] = coefficient(A, j);
  vector_t<jet<T>> x(m);
  for (Eigen::Index i = 0; i < m; ++i) x(i).c.assign(static_cast<std::size_t>(n + 1), T(0));
  std::optional<Eigen::LLT<matrix_t<T>>> llt;
  std::optional<Eigen::PartialPivLU<matrix_t<T>>> lu;
  matrix_t<T> inverse;  // interval: the columns enclose A^-1 e_j for every A in [A_0]
  if constexpr (!scalar_traits<T>::is_interval) {
    if (spd) {
      llt.emplace(A0);
      if (llt->info() != Eigen::Success) throw certification_error("Cholesky: the matrix is not positive definite");
    } else {
      lu.emplace(A0);
      using std::abs;
      for (Eigen::Index i = 0; i < m; ++i)
        if (!(abs(lu->matrixLU()(i, i)) > 0)) throw certification_error("LU: the matrix is singular");
    }
  } else if (n > 0) {
    inverse.resize(m, m);
    for (Eigen::Index j = 0; j < m; ++j) {
      vector_t<T> e = vector_t<T>::Zero(m);
      e(j) = T(1);
      inverse.col(j) = verified_solve(A0, e);
    }
  }
  for (int k = 0; k <= n; ++k) {
    vector_t<T> r(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      T s = b(i)[k];
      for (int j = 1; j <= std::min(k, la - 1); ++j)
        for (Eigen::Index l = 0; l < m; ++l) {
          const T& a = Aj[static_cast<std::size_t>(j)](i, l);
          if (!exactly_zero(a)) s -= a * x(l).c[static_cast<std::size_t>(k - j)];
        }
      r(i) = s;
    }
    vector_t<T> xk;
    if constexpr (scalar_traits<T>::is_interval) {
      // x_k = A_0^-1 r_k with the true A_0 and the true r_k: sum_j (r_k)_j A_0^-1 e_j lies in
      // inverse * r_k.  The value (k = 0) keeps the tighter direct verified solve.
      xk = (k == 0 || n == 0) ? verified_solve(A0, r) : vector_t<T>(detail::product(inverse, r));
    } else {
      xk = spd ? vector_t<T>(llt->solve(r)) : vector_t<T>(lu->solve(r));
    }
    for (Eigen::Index i = 0; i < m; ++i) x(i).c[static_cast<std::size_t>(k)] = xk(i);
  }
  return x;
}
}  // namespace detail

/// A x = b on jets, A symmetric positive definite (detail::jet_solve).
template <class T>
vector_t<jet<T>> solve_spd(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b) {
  return detail::jet_solve(A, b, true);
}
/// A x = b on jets, A general (detail::jet_solve): Lagrange's saddle-point systems.
template <class T>
vector_t<jet<T>> solve(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b) {
  return detail::jet_solve(A, b, false);
}

}  // namespace appell
