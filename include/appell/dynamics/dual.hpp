// appell/dynamics/dual.hpp -- forward-mode differentiation over any scalar.
//
// A dual number x + x' eps (eps^2 = 0) carries one directional derivative.
// appell uses it to differentiate the user's kinematics without hand-written
// derivatives:
//   * seeding u_k' = 1 (and nothing else) gives the column dv/du_k = J e_k
//     of a velocity v = J(q,t) u + j(q,t);
//   * seeding q' = W u + w and t' = 1, with u held fixed, gives
//     d/dt [J(q,t)] u + d/dt j(q,t) = J' u + j', the velocity-product part of
//     the acceleration  a = J u' + (J' u + j').
// Every rule below is the chain rule, one line each; T may be an interval,
// in which case the derivative is enclosed as rigorously as the value.
#pragma once

#include <cmath>

#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

template <class S> bool structurally_zero(const S& x);

template <class T>
struct dual {
  T v;  ///< value
  T d;  ///< derivative along the seeded direction

  dual() : v(0), d(0) {}
  dual(const T& value) : v(value), d(0) {}  // NOLINT: constants convert implicitly
  dual(const T& value, const T& derivative) : v(value), d(derivative) {}
  template <class N>
    requires std::is_arithmetic_v<N>
  dual(N n) : v(T(n)), d(0) {}  // NOLINT

  dual& operator+=(const dual& o) { v += o.v; d += o.d; return *this; }
  dual& operator-=(const dual& o) { v -= o.v; d -= o.d; return *this; }
  dual& operator*=(const dual& o) { *this = *this * o; return *this; }
  dual& operator/=(const dual& o) { *this = *this / o; return *this; }
  friend dual operator-(const dual& a) { return {-a.v, -a.d}; }
  friend dual operator+(const dual& a) { return a; }
  friend dual operator+(const dual& a, const dual& b) { return {a.v + b.v, a.d + b.d}; }
  friend dual operator-(const dual& a, const dual& b) { return {a.v - b.v, a.d - b.d}; }
  friend dual operator*(const dual& a, const dual& b) {
    if constexpr (!std::is_floating_point_v<T>) {
      // For scalars whose product costs more than a test (intervals, multiple precision, dd),
      // exact zero derivatives -- constants, unseeded variables -- skip their products.
      const bool az = structurally_zero(a.d), bz = structurally_zero(b.d);
      if (az || bz) {
        if (az && bz) return {a.v * b.v, T(0)};
        return {a.v * b.v, az ? T(a.v * b.d) : T(a.d * b.v)};
      }
    }
    return {a.v * b.v, a.d * b.v + a.v * b.d};
  }
  friend dual operator/(const dual& a, const dual& b) {  // (a/b)' = (a' - (a/b) b') / b
    const T q = a.v / b.v;
    return {q, (a.d - q * b.d) / b.v};
  }
};

template <class T> dual<T> sin(const dual<T>& x) {
  T s, c;
  sin_cos(x.v, s, c);
  return {s, c * x.d};
}
template <class T> dual<T> cos(const dual<T>& x) {
  T s, c;
  sin_cos(x.v, s, c);
  return {c, -s * x.d};
}
template <class T> dual<T> tan(const dual<T>& x) {  // tan' = 1 + tan^2
  using std::tan;
  const T t = tan(x.v);
  return {t, (T(1) + sqr(t)) * x.d};
}
template <class T> dual<T> atan(const dual<T>& x) { using std::atan; return {atan(x.v), x.d / (T(1) + sqr(x.v))}; }
template <class T> dual<T> exp(const dual<T>& x) { using std::exp; const T e = exp(x.v); return {e, e * x.d}; }
template <class T> dual<T> log(const dual<T>& x) { using std::log; return {log(x.v), x.d / x.v}; }
template <class T> dual<T> sqrt(const dual<T>& x) {  // sqrt' = 1 / (2 sqrt)
  using std::sqrt;
  const T s = sqrt(x.v);
  return {s, x.d / (T(2) * s)};
}
template <class T> dual<T> pown(const dual<T>& x, int n) {  // (x^n)' = n x^(n-1) x'
  if (n == 0) return dual<T>(T(1));
  return {appell::pown(x.v, n), T(n) * appell::pown(x.v, n - 1) * x.d};
}
template <class T> dual<T> sqr(const dual<T>& x) { return {sqr(x.v), T(2) * x.v * x.d}; }

template <class T> struct is_dual : std::false_type {};
template <class T> struct is_dual<dual<T>> : std::true_type {};

/// The base scalar of a (possibly nested) dual type.
template <class T> struct base_scalar { using type = T; };
template <class T> struct base_scalar<dual<T>> { using type = typename base_scalar<T>::type; };
template <class T> using base_scalar_t = typename base_scalar<T>::type;

/// Exactly 0 / exactly 1 (value and every derivative part) for scalars and duals alike.
template <class S> bool structurally_zero(const S& x) {
  if constexpr (is_dual<S>::value) return structurally_zero(x.v) && structurally_zero(x.d);
  else return exactly_zero(x);
}
template <class S> bool structurally_one(const S& x) {
  if constexpr (is_dual<S>::value) return structurally_one(x.v) && structurally_zero(x.d);
  else return exactly_one(x);
}

/// x^n for scalars and duals alike.
template <class S> S power(const S& x, int n) {
  if constexpr (is_dual<S>::value) return pown(x, n);
  else return appell::pown(x, n);
}
template <class S> S square(const S& x) {
  if constexpr (is_dual<S>::value) return sqr(x);
  else return appell::sqr(x);
}

}  // namespace appell
