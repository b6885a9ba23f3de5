// appell/dynamics/virtual_work.hpp -- Cotton's eq. (4): P . du is minus the
// virtual work of the inertia forces, the same number in every choice of speeds.
//
// inertia_virtual_work() computes  sum m a_G . dr_G + (I alpha + omega x I omega) . dtheta
// body by body, from one evaluation of the user's kinematics on two-slot dual
// numbers (one slot seeded with (q', u', 1) for the accelerations, one with du
// for the displacements),
// without going through M and b.  The residual  P(u') . du - that  must be 0
// (an interval holding 0 for interval types): a check of the assembly that
// every `appell eval` result carries.
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

template <Scalar T, class Sys>
T inertia_virtual_work(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                       const vector_t<T>& udot, const vector_t<T>& du) {
  // One evaluation on multi_dual<T, 2>: slot 0 seeded with (q', u', 1) (the
  // accelerations), slot 1 with (0, du, 0) (the displacements); the values are
  // the plain evaluation's.
  using D = multi_dual<T, 2>;
  // working storage borrowed (linalg/scratch.hpp)
  struct site;
  const scratch<vector_t<T>, site> qd_held;
  const scratch<vector_t<D>, site> qs_held, us_held;
  const scratch<std::vector<body_state<D>>, site> bodies_held;
  if constexpr (requires { sys.template qdot_into<T>(q, u, t, *qd_held); })
    sys.template qdot_into<T>(q, u, t, *qd_held);
  else
    *qd_held = sys.template qdot<T>(q, u, t);
  const vector_t<T>& qd = *qd_held;
  vector_t<D>&qs = *qs_held, &us = *us_held;
  std::vector<body_state<D>>& bodies = *bodies_held;
  qs.resize(q.size()), us.resize(u.size());
  bodies.clear();
  for (Eigen::Index i = 0; i < q.size(); ++i) qs(i) = D(q(i), {qd(i), T(0)});
  for (Eigen::Index i = 0; i < u.size(); ++i) us(i) = D(u(i), {udot(i), du(i)});
  sys.template bodies<D>(qs, us, D(t, {T(1), T(0)}), bodies);
  T work = T(0);
  for (const body_state<D>& b : bodies) {
    const body_state<T> s = detail::values<T>(b);
    const vec3<T> a = detail::derivative(b.velocity, 0) + cross(s.frame_rate, s.velocity);
    const vec3<T> alpha = detail::derivative(b.omega, 0) + frame_cross_omega(s);
    const vec3<T> dr = detail::derivative(b.velocity, 1), dtheta = detail::derivative(b.omega, 1);
    const vec3<T> moment = mat_vec(s.inertia, alpha) + gyroscopic(s.inertia, s.omega);
    work += s.mass * dot(a, dr) + dot(moment, dtheta);
  }
  return work;
}

/// P(u') . du - (the same from the bodies): 0 in exact arithmetic.
template <Scalar T, class Sys>
T virtual_work_residual(const Sys& sys, const appell_equations<T>& eq, const vector_t<T>& q,
                        const vector_t<T>& u, const T& t, const vector_t<T>& udot, const vector_t<T>& du) {
  // P = M u' + b, row by row as eq.P computes it (detail::product's sums), without the vector
  T pdu = T(0);
  for (Eigen::Index i = 0; i < du.size(); ++i) {
    T sum = eq.M(i, 0) * udot(0);
    for (Eigen::Index k = 1; k < eq.M.cols(); ++k) sum += eq.M(i, k) * udot(k);
    const T P = sum + eq.b(i);
    pdu += P * du(i);
  }
  return pdu - inertia_virtual_work(sys, q, u, t, udot, du);
}

}  // namespace appell
