// appell/reactions/lagrange.hpp -- the same reactions by Lagrange multipliers.
//
// M u' + b = Q + A^T lambda,  A u' + h = 0  with  h = A' u - a' (the
// constraint differentiated along the motion, by a dual pass), i.e. the
// saddle-point system  [M  -A^T; A  0] [u'; lambda] = [Q - b; -h],
// solved by LU (point types) or the verified solver (interval types).
// lambda is the generalized force of the constraints on the speeds' scale of
// A u = a: it equals Cotton's Q'_c in the speeds adapted with v_c = A u - a.
#pragma once

#include "appell/reactions/cotton.hpp"

namespace appell {

template <Scalar T, class Sys, class Constraint>
constrained_motion<T> lagrange_multipliers(const Sys& sys, const Constraint& con, const vector_t<T>& q,
                                           const vector_t<T>& u, const T& t) {
  const int n = sys.speeds(), s = con.count();
  const appell_equations<T> e = gibbs_appell(sys, q, u, t);
  matrix_t<T> A(s, n);
  vector_t<T> a(s);
  con.template eval<T>(q, t, A, a);
  // h = d/dt (A u - a) at fixed u.
  const vector_t<T> qd = sys.template qdot<T>(q, u, t);
  matrix_t<dual<T>> Ad(s, n);
  vector_t<dual<T>> ad(s);
  con.template eval<dual<T>>(detail::seeded<T>(q, &qd), dual<T>(t, T(1)), Ad, ad);
  vector_t<T> h(s);
  for (int i = 0; i < s; ++i) {
    T x = -ad(i).d;
    for (int j = 0; j < n; ++j) x += Ad(i, j).d * u(j);
    h(i) = x;
  }
  matrix_t<T> K = matrix_t<T>::Zero(n + s, n + s);
  vector_t<T> rhs(n + s);
  K.topLeftCorner(n, n) = e.M;
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < n; ++j) {
      K(j, n + i) = -A(i, j);
      K(n + i, j) = A(i, j);
    }
  rhs.head(n) = e.Q - e.b;
  rhs.tail(s) = -h;
  const vector_t<T> x = solve(K, rhs);
  return {x.head(n), x.tail(s)};
}

/// A u - a at the state: the constraints' residual (0 on a consistent state).
template <Scalar T, class Constraint>
vector_t<T> constraint_residual(const Constraint& con, const vector_t<T>& q, const vector_t<T>& u, const T& t) {
  const int s = con.count();
  matrix_t<T> A(s, u.size());
  vector_t<T> a(s);
  con.template eval<T>(q, t, A, a);
  return vector_t<T>(detail::product(A, u) - a);
}

}  // namespace appell
