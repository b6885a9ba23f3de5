// appell/reactions/lagrange.hpp -- the same reactions by Lagrange multipliers.
//
// M u' + b = Q + A^T lambda,  A u' + h = 0  with  h = A' u - a' (the
// constraint differentiated along the motion, by a dual pass), i.e. the
// saddle-point system  [M  -A^T; A  0] [u'; lambda] = [Q - b; -h],
// solved by LU (point types) or the verified solver (interval types).
// lambda is the generalized force of the constraints on the speeds' scale of
// A u = a: it equals Cotton's Q'_c in the speeds adapted with v_c = A u - a.
#pragma once

#include "appell/linalg/scratch.hpp"
#include "appell/reactions/cotton.hpp"

namespace appell {

/// The saddle-point system on the equations e = (M, b, Q) of sys at (q, u, t), formed by the
/// caller (a tree's recursions: system/tree_constraints.hpp).
template <Scalar T, class Sys, class Constraint>
void lagrange_multipliers_with_into(const appell_equations<T>& e, const Sys& sys, const Constraint& con,
                                    const vector_t<T>& q, const vector_t<T>& u, const T& t,
                                    constrained_motion<T>& out) {
  const int n = sys.speeds(), s = con.count();
  struct site;  // this function's pools (linalg/scratch.hpp: an Eigen object keeps one size)
  // working storage borrowed (linalg/scratch.hpp)
  const scratch<matrix_t<T>, site> A_held, K_held;
  const scratch<vector_t<T>, site> a_held, h_held, rhs_held;
  const scratch<matrix_t<dual<T>>, site> Ad_held;
  const scratch<vector_t<dual<T>>, site> ad_held;
  matrix_t<T>&A = *A_held, &K = *K_held;
  vector_t<T>&a = *a_held, &h = *h_held, &rhs = *rhs_held;
  matrix_t<dual<T>>& Ad = *Ad_held;
  vector_t<dual<T>>& ad = *ad_held;
  A.resize(s, n), a.resize(s), Ad.resize(s, n), ad.resize(s), h.resize(s);
  con.template eval<T>(q, t, A, a);
  // h = d/dt (A u - a) at fixed u.
  const scratch<vector_t<T>, site> qd_held;
  const scratch<vector_t<dual<T>>, site> qs_held;
  vector_t<T>& qd = *qd_held;
  if constexpr (requires { sys.template qdot_into<T>(q, u, t, qd); })
    sys.template qdot_into<T>(q, u, t, qd);
  else
    qd = sys.template qdot<T>(q, u, t);
  vector_t<dual<T>>& qs = *qs_held;  // detail::seeded's values
  qs.resize(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) qs(i) = dual<T>(q(i), qd(i));
  con.template eval<dual<T>>(qs, dual<T>(t, T(1)), Ad, ad);
  for (int i = 0; i < s; ++i) {
    T x = -ad(i).d;
    for (int j = 0; j < n; ++j) x += Ad(i, j).d * u(j);
    h(i) = x;
  }
  K.setZero(n + s, n + s);
  rhs.resize(n + s);
  K.topLeftCorner(n, n) = e.M;
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < n; ++j) {
      K(j, n + i) = -A(i, j);
      K(n + i, j) = A(i, j);
    }
  rhs.head(n) = e.Q - e.b;
  rhs.tail(s) = -h;
  const scratch<vector_t<T>, site> x_held;
  const vector_t<T>& x = *x_held;
  solve_into<site>(K, rhs, *x_held);
  out.accelerations = x.head(n);  // into out's storage
  out.reactions = x.tail(s);
}
/// The same with the equations by the generic path (gibbs_appell).
template <Scalar T, class Sys, class Constraint>
void lagrange_multipliers_into(const Sys& sys, const Constraint& con, const vector_t<T>& q, const vector_t<T>& u,
                               const T& t, constrained_motion<T>& out) {
  struct site;
  const scratch<appell_equations<T>, site> e_held;
  gibbs_appell_into(sys, q, u, t, *e_held);
  lagrange_multipliers_with_into(*e_held, sys, con, q, u, t, out);
}
template <Scalar T, class Sys, class Constraint>
constrained_motion<T> lagrange_multipliers(const Sys& sys, const Constraint& con, const vector_t<T>& q,
                                           const vector_t<T>& u, const T& t) {
  constrained_motion<T> out;
  lagrange_multipliers_into(sys, con, q, u, t, out);
  return out;
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
