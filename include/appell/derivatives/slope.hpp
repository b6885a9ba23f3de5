// appell/derivatives/slope.hpp -- first-order slopes (Krawczyk & Neumaier 1985) over any scalar.
//
// A slope of f over a box X with centre xh (xh in X) is a matrix S (an enclosure of one) with
//     f(x) - f(xh) = S* (x - xh)   for some S* in S, for every x in X.
// The mean-value theorem gives S = f'(X), the derivative over the whole box; a slope can be
// much narrower: for f(x) = x^2, f(x) - f(xh) = (x + xh)(x - xh), so S = X + xh, of half the
// width of f'(X) = 2 X.  A quadratic map's slope has half the spread of its Jacobian over the
// box, so the mean-value form's wrapping of the nonlinear part is halved (ode/enclose.hpp
// steps with it).
//
// slope<T, N> carries, through an evaluation, for one quantity a(x):
//   v   an enclosure of a over the box X (as multi_dual's value),
//   c   an enclosure of a(xh) at the centre,
//   d   N slopes: a(x) - a(xh) = sum_i s_i (x_i - xh_i), s_i in d[i], for every x in X.
// The rules (each an identity, then enclosed; every one also holds for T a ring of truncated
// power series, jets, which is commutative: ode/taylor.hpp runs them on jet<I>):
//   a b:   a(x) b(x) - a(xh) b(xh) = (a(x) - a(xh)) b(x) + a(xh) (b(x) - b(xh)):
//          d = d_a v_b + c_a d_b;
//   a / b: a(x)/b(x) - a(xh)/b(xh) = ((a(x) - a(xh)) - (a/b)(xh) (b(x) - b(xh))) / b(x):
//          d = (d_a - c_{a/b} d_b) / v_b;
//   f(a):  f(a(x)) - f(a(xh)) = (integral_0^1 f'(a(xh) + t (a(x) - a(xh))) dt) (a(x) - a(xh)),
//          the argument of f' between a(xh) and a(x), both in v_a: d = f'(v_a) d_a;
//          exactly, sqrt(a) - sqrt(b) = (a - b) / (sqrt a + sqrt b) and
//          a^2 - b^2 = (a + b)(a - b): d = d_a / (sqrt(v_a) + sqrt(c_a)), d = (v_a + c_a) d_a;
//   A y = b (derivatives/dual_solve.hpp): y(x) - y(xh) = A(x)^-1 ((b(x) - b(xh)) - (A(x) - A(xh)) y(xh)):
//          d = A_v^-1 (d_b - d_A c_y).
// The variable x_i is slope(X_i, xh_i, e_i).  Every slope enclosure is contained in the
// corresponding derivative enclosure over X (c in v), so the slope is never the wider of the two
// in exact interval arithmetic; tests/motion.cpp checks containment of 332-bit true differences
// on random boxes and states, and the width against the Jacobian's.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "appell/derivatives/dual.hpp"

namespace appell {

template <class T, int N>
struct slope {
  T v;                 ///< over the box
  T c;                 ///< at the centre
  std::array<T, N> d;  ///< slopes along the N variables

  slope() : v(0), c(0) { zero_fill(d); }
  slope(const T& value) : v(value), c(value) { zero_fill(d); }  // NOLINT: constants convert implicitly
  template <class X>
    requires std::is_arithmetic_v<X>
  slope(X n) : v(T(n)), c(T(n)) { zero_fill(d); }  // NOLINT
  slope(T box, T centre) : v(std::move(box)), c(std::move(centre)) { zero_fill(d); }  // by value: temporaries move in

  slope& operator+=(const slope& o) { v += o.v; c += o.c; for (int i = 0; i < N; ++i) d[i] += o.d[i]; return *this; }
  slope& operator-=(const slope& o) { v -= o.v; c -= o.c; for (int i = 0; i < N; ++i) d[i] -= o.d[i]; return *this; }
  slope& operator*=(const slope& o) { *this = *this * o; return *this; }
  slope& operator/=(const slope& o) { *this = *this / o; return *this; }
  friend slope operator-(const slope& a) {
    slope r(-a.v, -a.c);
    for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
    return r;
  }
  friend slope operator+(const slope& a) { return a; }
  friend slope operator+(const slope& a, const slope& b) {
    slope r(a.v + b.v, a.c + b.c);
    for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  friend slope operator-(const slope& a, const slope& b) {
    slope r(a.v - b.v, a.c - b.c);
    for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  friend slope operator*(const slope& a, const slope& b) {
    slope r(a.v * b.v, a.c * b.c);
    for (int i = 0; i < N; ++i) {
      if constexpr (!std::is_floating_point_v<T>) {  // exact zeros skip their products
        const bool az = structurally_zero(a.d[i]), bz = structurally_zero(b.d[i]);
        if (az || bz) {
          if (!(az && bz)) r.d[i] = az ? T(a.c * b.d[i]) : T(a.d[i] * b.v);
          continue;
        }
      }
      r.d[i] = a.d[i] * b.v + a.c * b.d[i];
    }
    return r;
  }
  friend slope operator/(const slope& a, const slope& b) {
    slope r(a.v / b.v, a.c / b.c);
    for (int i = 0; i < N; ++i) {
      if constexpr (!std::is_floating_point_v<T>) {
        if (structurally_zero(b.d[i])) {
          if (!structurally_zero(a.d[i])) r.d[i] = a.d[i] / b.v;
          continue;
        }
      }
      r.d[i] = (a.d[i] - r.c * b.d[i]) / b.v;
    }
    return r;
  }
  /// f(x) with f over the box `box`, at the centre `centre`, and s enclosing the slope of f
  /// between x's centre value and any of its box values: d_i = s x.d_i.
  static slope chain(const T& box, const T& centre, const T& s, const slope& x) {
    slope r(box, centre);
    for (int i = 0; i < N; ++i)
      if (!structurally_zero(x.d[i])) r.d[i] = s * x.d[i];
    return r;
  }
  /// As chain, with the slope 1 / den: d_i = x.d_i / den.
  static slope chain_over(const T& box, const T& centre, const T& den, const slope& x) {
    slope r(box, centre);
    for (int i = 0; i < N; ++i)
      if (!structurally_zero(x.d[i])) r.d[i] = x.d[i] / den;
    return r;
  }
  /// Every slope exactly 0.
  bool derivatives_zero() const {
    for (const T& di : d)
      if (!structurally_zero(di)) return false;
    return true;
  }
};

/// The number of slopes given at run time: slope<T, runtime_slopes> keeps them in a vector, empty
/// while every slope is exactly 0 (a constant: most quantities of a tree's recursion are), else
/// one per variable, as many as the seeded variables have.  The rules are those above, the
/// missing slopes of a constant read as exact zeros; enclose carries a state of any size so (a
/// humanoid's 54 components and more), where the fixed capacities stop at 12 components.
inline constexpr int runtime_slopes = -1;

template <class T>
struct slope<T, runtime_slopes> {
  T v;               ///< over the box
  T c;               ///< at the centre
  std::vector<T> d;  ///< the slopes, or empty: all exactly 0

  slope() : v(0), c(0) {}
  slope(const T& value) : v(value), c(value) {}  // NOLINT: constants convert implicitly
  template <class X>
    requires std::is_arithmetic_v<X>
  slope(X n) : v(T(n)), c(T(n)) {}  // NOLINT
  slope(T box, T centre) : v(std::move(box)), c(std::move(centre)) {}

  /// The k-th slope (an exact 0 past a constant's empty list).
  T part(std::size_t k) const { return k < d.size() ? d[k] : T(0); }

  slope& operator+=(const slope& o) {
    v += o.v;
    c += o.c;
    if (d.empty()) d = o.d;
    else if (!o.d.empty()) for (std::size_t i = 0; i < d.size(); ++i) d[i] += o.d[i];
    return *this;
  }
  slope& operator-=(const slope& o) { *this = *this - o; return *this; }
  slope& operator*=(const slope& o) { *this = *this * o; return *this; }
  slope& operator/=(const slope& o) { *this = *this / o; return *this; }
  friend slope operator-(const slope& a) {
    slope r(-a.v, -a.c);
    r.d.reserve(a.d.size());
    for (const T& x : a.d) r.d.push_back(-x);
    return r;
  }
  friend slope operator+(const slope& a) { return a; }
  friend slope operator+(const slope& a, const slope& b) {
    slope r(a.v + b.v, a.c + b.c);
    if (a.d.empty()) r.d = b.d;
    else if (b.d.empty()) r.d = a.d;
    else {
      r.d.resize(a.d.size());
      for (std::size_t i = 0; i < a.d.size(); ++i) r.d[i] = a.d[i] + b.d[i];
    }
    return r;
  }
  friend slope operator-(const slope& a, const slope& b) {
    slope r(a.v - b.v, a.c - b.c);
    if (b.d.empty()) r.d = a.d;
    else if (a.d.empty()) {
      r.d.reserve(b.d.size());
      for (const T& x : b.d) r.d.push_back(-x);
    } else {
      r.d.resize(a.d.size());
      for (std::size_t i = 0; i < a.d.size(); ++i) r.d[i] = a.d[i] - b.d[i];
    }
    return r;
  }
  friend slope operator*(const slope& a, const slope& b) {
    slope r(a.v * b.v, a.c * b.c);
    const std::size_t n = std::max(a.d.size(), b.d.size());
    if (n == 0) return r;
    r.d.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const bool az = i >= a.d.size() || structurally_zero(a.d[i]), bz = i >= b.d.size() || structurally_zero(b.d[i]);
      if (az && bz) continue;
      if (az) r.d[i] = a.c * b.d[i];
      else if (bz) r.d[i] = a.d[i] * b.v;
      else r.d[i] = a.d[i] * b.v + a.c * b.d[i];
    }
    return r;
  }
  friend slope operator/(const slope& a, const slope& b) {
    slope r(a.v / b.v, a.c / b.c);
    const std::size_t n = std::max(a.d.size(), b.d.size());
    if (n == 0) return r;
    r.d.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const bool az = i >= a.d.size() || structurally_zero(a.d[i]), bz = i >= b.d.size() || structurally_zero(b.d[i]);
      if (az && bz) continue;
      if (bz) r.d[i] = a.d[i] / b.v;
      else if (az) r.d[i] = -(r.c * b.d[i]) / b.v;
      else r.d[i] = (a.d[i] - r.c * b.d[i]) / b.v;
    }
    return r;
  }
  static slope chain(const T& box, const T& centre, const T& s, const slope& x) {
    slope r(box, centre);
    r.d.resize(x.d.size());
    for (std::size_t i = 0; i < x.d.size(); ++i)
      if (!structurally_zero(x.d[i])) r.d[i] = s * x.d[i];
    return r;
  }
  static slope chain_over(const T& box, const T& centre, const T& den, const slope& x) {
    slope r(box, centre);
    r.d.resize(x.d.size());
    for (std::size_t i = 0; i < x.d.size(); ++i)
      if (!structurally_zero(x.d[i])) r.d[i] = x.d[i] / den;
    return r;
  }
  bool derivatives_zero() const {
    for (const T& di : d)
      if (!structurally_zero(di)) return false;
    return true;
  }
};

template <class T, int N> void sin_cos(const slope<T, N>& x, slope<T, N>& s, slope<T, N>& c) {
  T sv, cv, sc, cc;
  sin_cos(x.v, sv, cv);
  sin_cos(x.c, sc, cc);
  s = slope<T, N>::chain(sv, sc, cv, x);
  c = slope<T, N>::chain(cv, cc, -sv, x);
}
template <class T, int N> slope<T, N> sin(const slope<T, N>& x) {
  slope<T, N> s, c;
  sin_cos(x, s, c);
  return s;
}
template <class T, int N> slope<T, N> cos(const slope<T, N>& x) {
  slope<T, N> s, c;
  sin_cos(x, s, c);
  return c;
}
template <class T, int N> slope<T, N> tan(const slope<T, N>& x) {  // tan' = 1 + tan^2 over the box
  using std::tan;
  const T t = tan(x.v);
  return slope<T, N>::chain(t, tan(x.c), T(1) + sqr(t), x);
}
template <class T, int N> slope<T, N> atan(const slope<T, N>& x) {
  using std::atan;
  return slope<T, N>::chain_over(atan(x.v), atan(x.c), T(1) + sqr(x.v), x);
}
template <class T, int N> slope<T, N> exp(const slope<T, N>& x) {
  using std::exp;
  const T e = exp(x.v);
  return slope<T, N>::chain(e, exp(x.c), e, x);
}
template <class T, int N> slope<T, N> log(const slope<T, N>& x) {
  using std::log;
  return slope<T, N>::chain_over(log(x.v), log(x.c), x.v, x);
}
template <class T, int N> slope<T, N> sqrt(const slope<T, N>& x) {  // sqrt a - sqrt b = (a - b) / (sqrt a + sqrt b)
  using std::sqrt;
  const T sv = sqrt(x.v), sc = sqrt(x.c);
  return slope<T, N>::chain_over(sv, sc, sv + sc, x);
}
template <class T, int N> slope<T, N> sqr(const slope<T, N>& x) {  // a^2 - b^2 = (a + b)(a - b)
  return slope<T, N>::chain(sqr(x.v), sqr(x.c), x.v + x.c, x);
}
template <class T, int N> slope<T, N> pown(const slope<T, N>& x, int n) {  // n x^(n-1) over the box
  if (n == 0) return slope<T, N>(T(1));
  if (n == 1) return x;
  if (n == 2) return sqr(x);
  return slope<T, N>::chain(appell::pown(x.v, n), appell::pown(x.c, n), T(n) * appell::pown(x.v, n - 1), x);
}

/// slope<T, N> is a scalar of the generic path, as multi_dual is: its bounds and predicates are
/// those of its box value, and the linear solves go to derivatives/dual_solve.hpp.
template <class T, int N>
  requires Scalar<T>
struct scalar_traits<slope<T, N>> : derivative_carrier_traits<slope<T, N>, T> {
  static constexpr const char* name = "slope";
};

// A slope is treated as a multi_dual wherever the library asks (structurally_zero, value_of,
// from_base, power): its value is the box value v.
template <class T, int N> struct is_dual<slope<T, N>> : std::true_type {};
template <class T, int N> struct is_multi_dual<slope<T, N>> : std::true_type {};
template <class T, int N> struct base_scalar<slope<T, N>> { using type = typename base_scalar<T>::type; };

}  // namespace appell
