// appell/derivatives/dual.hpp -- forward-mode differentiation over any scalar.
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

#include <array>
#include <cmath>

#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

template <class S> bool structurally_zero(const S& x);
// Declared before dual's rules, which call appell::pown on their values: a dual
// of a multi_dual (a multi_dual's derivative pass inside a linearization) finds them.
template <class T, int N> struct multi_dual;
template <class T, int N> multi_dual<T, N> pown(const multi_dual<T, N>& x, int n);
template <class T> struct jet;  // truncated Taylor series (derivatives/jet.hpp): a dual of jets finds its pown
template <class T, int N> struct slope;  // slopes (derivatives/slope.hpp): a multi_dual of slopes finds their pown
template <class T, int N> slope<T, N> pown(const slope<T, N>& x, int n);
template <class T> jet<T> pown(const jet<T>& x, int n);

template <class T> struct dual;

/// T() is an exact zero, as T(0) is: the derivative carriers below, jets and intervals.  Their
/// constructors then leave default-constructed parts as they are instead of assigning T(0) over
/// them again (a multi_dual<slope<jet>> of zeros is 25 jets; perf: a tenth of an enclosure).
template <class T>
inline constexpr bool default_is_zero = false;
template <class T>
inline constexpr bool default_is_zero<dual<T>> = true;
template <class T, int N>
inline constexpr bool default_is_zero<multi_dual<T, N>> = true;
template <class T, int N>
inline constexpr bool default_is_zero<slope<T, N>> = true;
template <class T>
inline constexpr bool default_is_zero<jet<T>> = true;
template <class T, class P>
inline constexpr bool default_is_zero<boost::numeric::interval<T, P>> = true;

/// d = 0 for an array of N carriers just default-constructed.
template <class T, std::size_t N>
void zero_fill(std::array<T, N>& d) {
  if constexpr (!default_is_zero<T>) d.fill(T(0));
}

/// A fixed-size Eigen matrix of zeros, built in place (no zero assigned over default zeros).
template <class M>
M zero_matrix() {
  if constexpr (default_is_zero<typename M::Scalar>) return M();
  else return M::Zero();
}

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

/// N directional derivatives carried at once (N fixed at compile time): one
/// evaluation of the user's kinematics gives every column of J and the
/// velocity-product terms (gibbs_appell.hpp), where N single duals would evaluate
/// it N times.  Each slot's arithmetic is exactly that of a single dual seeded
/// with that slot's direction (the same operations in the same order, the same
/// exact-zero skips), so the derivatives are the same numbers bit for bit;
/// the values are computed once.
template <class T, int N>
struct multi_dual {
  T v;                 ///< value
  std::array<T, N> d;  ///< derivatives along the N seeded directions

  multi_dual() : v(0) { zero_fill(d); }
  multi_dual(const T& value) : v(value) { zero_fill(d); }  // NOLINT: constants convert implicitly
  multi_dual(T&& value) : v(std::move(value)) { zero_fill(d); }  // NOLINT: a temporary moves in
  template <class X>
    requires std::is_arithmetic_v<X>
  multi_dual(X n) : v(T(n)) { zero_fill(d); }  // NOLINT
  multi_dual(const T& value, const std::array<T, N>& derivatives) : v(value), d(derivatives) {}

  multi_dual& operator+=(const multi_dual& o) { v += o.v; for (int i = 0; i < N; ++i) d[i] += o.d[i]; return *this; }
  multi_dual& operator-=(const multi_dual& o) { v -= o.v; for (int i = 0; i < N; ++i) d[i] -= o.d[i]; return *this; }
  multi_dual& operator*=(const multi_dual& o) { *this = *this * o; return *this; }
  multi_dual& operator/=(const multi_dual& o) { *this = *this / o; return *this; }
  friend multi_dual operator-(const multi_dual& a) {
    multi_dual r(-a.v);
    for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
    return r;
  }
  friend multi_dual operator+(const multi_dual& a) { return a; }
  friend multi_dual operator+(const multi_dual& a, const multi_dual& b) {
    multi_dual r(a.v + b.v);
    for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  friend multi_dual operator-(const multi_dual& a, const multi_dual& b) {
    multi_dual r(a.v - b.v);
    for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  friend multi_dual operator*(const multi_dual& a, const multi_dual& b) {
    multi_dual r(a.v * b.v);
    for (int i = 0; i < N; ++i) {
      if constexpr (!std::is_floating_point_v<T>) {  // as dual: exact zeros skip their products
        const bool az = structurally_zero(a.d[i]), bz = structurally_zero(b.d[i]);
        if (az || bz) {
          if (!(az && bz)) r.d[i] = az ? T(a.v * b.d[i]) : T(a.d[i] * b.v);
          continue;
        }
      }
      r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    }
    return r;
  }
  friend multi_dual operator/(const multi_dual& a, const multi_dual& b) {
    multi_dual r(a.v / b.v);
    for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) / b.v;
    return r;
  }
  /// f(x) with f(x.v) = value and f'(x.v) = slope: d_i = slope * x.d_i.
  static multi_dual chain(const T& value, const T& slope, const multi_dual& x) {
    multi_dual r(value);
    for (int i = 0; i < N; ++i) r.d[i] = slope * x.d[i];
    return r;
  }
  /// f(x) with f'(x.v) = 1 / den: d_i = x.d_i / den (as dual's rules divide, not multiply by 1 / den).
  static multi_dual chain_over(const T& value, const T& den, const multi_dual& x) {
    multi_dual r(value);
    for (int i = 0; i < N; ++i) r.d[i] = x.d[i] / den;
    return r;
  }
  /// Every derivative exactly 0.
  bool derivatives_zero() const {
    for (const T& di : d)
      if (!structurally_zero(di)) return false;
    return true;
  }
};

template <class T, int N> multi_dual<T, N> sin(const multi_dual<T, N>& x) {
  T s, c;
  sin_cos(x.v, s, c);
  return multi_dual<T, N>::chain(s, c, x);
}
template <class T, int N> multi_dual<T, N> cos(const multi_dual<T, N>& x) {
  T s, c;
  sin_cos(x.v, s, c);
  return multi_dual<T, N>::chain(c, -s, x);
}
template <class T, int N> multi_dual<T, N> tan(const multi_dual<T, N>& x) {
  using std::tan;
  const T t = tan(x.v);
  return multi_dual<T, N>::chain(t, T(1) + sqr(t), x);
}
template <class T, int N> multi_dual<T, N> atan(const multi_dual<T, N>& x) {
  using std::atan;
  return multi_dual<T, N>::chain_over(atan(x.v), T(1) + sqr(x.v), x);
}
template <class T, int N> multi_dual<T, N> exp(const multi_dual<T, N>& x) {
  using std::exp;
  const T e = exp(x.v);
  return multi_dual<T, N>::chain(e, e, x);
}
template <class T, int N> multi_dual<T, N> log(const multi_dual<T, N>& x) {
  using std::log;
  return multi_dual<T, N>::chain_over(log(x.v), x.v, x);
}
template <class T, int N> multi_dual<T, N> sqrt(const multi_dual<T, N>& x) {
  using std::sqrt;
  const T s = sqrt(x.v);
  return multi_dual<T, N>::chain_over(s, T(2) * s, x);
}
template <class T, int N> multi_dual<T, N> pown(const multi_dual<T, N>& x, int n) {
  if (n == 0) return multi_dual<T, N>(T(1));
  return multi_dual<T, N>::chain(appell::pown(x.v, n), T(n) * appell::pown(x.v, n - 1), x);
}
template <class T, int N> multi_dual<T, N> sqr(const multi_dual<T, N>& x) {
  return multi_dual<T, N>::chain(sqr(x.v), T(2) * x.v, x);
}

/// The traits of a scalar that carries derivative parts beside a value `v` (multi_dual, slope):
/// not a set; bounds and predicates those of the value.
template <class D, class T>
struct derivative_carrier_traits {
  static constexpr bool is_interval = false;
  static constexpr bool is_rigorous = scalar_traits<T>::is_rigorous;
  static constexpr bool runtime_precision = scalar_traits<T>::runtime_precision;
  static constexpr bool needs_upward_rounding = scalar_traits<T>::needs_upward_rounding;
  using bound_type = bound_t<T>;
  static unsigned precision_bits() { return scalar_traits<T>::precision_bits(); }
  static bound_type lower(const D& x) { return scalar_traits<T>::lower(x.v); }
  static bound_type upper(const D& x) { return scalar_traits<T>::upper(x.v); }
  static bound_type mid(const D& x) { return scalar_traits<T>::mid(x.v); }
  static bound_type width(const D& x) { return scalar_traits<T>::width(x.v); }
};

/// multi_dual<T, N> over a scalar T is itself a scalar of the generic path: the
/// whole pipeline (Appell's equations, Cotton's reactions, the solves) runs on it
/// and carries N derivatives of every result along, each enclosed as rigorously
/// as the value (linearize.hpp differentiates the motion so).  It is not itself a
/// set: its bounds and predicates are those of its value, and the linear solves
/// go to the overloads in derivatives/dual_solve.hpp.
template <class T, int N>
  requires Scalar<T>
struct scalar_traits<multi_dual<T, N>> : derivative_carrier_traits<multi_dual<T, N>, T> {
  static constexpr const char* name = "dual";
};

template <class T> struct is_dual : std::false_type {};
template <class T> struct is_dual<dual<T>> : std::true_type {};
template <class T, int N> struct is_dual<multi_dual<T, N>> : std::true_type {};
template <class T> struct is_multi_dual : std::false_type {};
template <class T, int N> struct is_multi_dual<multi_dual<T, N>> : std::true_type {};

template <class T> struct is_jet : std::false_type {};
template <class T> struct is_jet<jet<T>> : std::true_type {};

/// The base scalar of a (possibly nested) dual type, or of a jet.
template <class T> struct base_scalar { using type = T; };
template <class T> struct base_scalar<dual<T>> { using type = typename base_scalar<T>::type; };
template <class T, int N> struct base_scalar<multi_dual<T, N>> { using type = typename base_scalar<T>::type; };
template <class T> struct base_scalar<jet<T>> { using type = typename base_scalar<T>::type; };
template <class T> using base_scalar_t = typename base_scalar<T>::type;

namespace detail {
/// The value of a scalar, or of a (nested) dual's base scalar, or a jet's constant term (over
/// an enclosure's box, the value at every point the series is expanded at).
template <class S>
const base_scalar_t<S>& value_of(const S& x) {
  if constexpr (is_dual<S>::value) return value_of(x.v);
  else if constexpr (is_jet<S>::value) return value_of(x.c[0]);
  else return x;
}
/// A base scalar as S (a scalar, or a nested dual or jet of it), wrapped level by level.
template <class S>
S from_base(const base_scalar_t<S>& x) {
  if constexpr (is_dual<S>::value) return S(from_base<std::remove_cvref_t<decltype(std::declval<const S&>().v)>>(x));
  else return S(x);
}
}  // namespace detail

/// Exactly 0 / exactly 1 (value and every derivative part) for scalars and duals alike.
template <class S> bool structurally_zero(const S& x) {
  if constexpr (is_multi_dual<S>::value) {
    return x.derivatives_zero() && structurally_zero(x.v);
  } else if constexpr (is_dual<S>::value) {
    return structurally_zero(x.v) && structurally_zero(x.d);
  } else {
    return exactly_zero(x);
  }
}
template <class S> bool structurally_one(const S& x) {
  if constexpr (is_multi_dual<S>::value) {
    return x.derivatives_zero() && structurally_one(x.v);
  } else if constexpr (is_dual<S>::value) {
    return structurally_one(x.v) && structurally_zero(x.d);
  } else {
    return exactly_one(x);
  }
}

/// x^n for scalars and duals alike.
template <class S> S power(const S& x, int n) {
  if constexpr (is_dual<S>::value || is_jet<S>::value) return pown(x, n);
  else return appell::pown(x, n);
}
template <class S> S square(const S& x) {
  if constexpr (is_dual<S>::value || is_jet<S>::value) return sqr(x);
  else return appell::sqr(x);
}

}  // namespace appell
