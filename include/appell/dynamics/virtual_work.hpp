// appell/dynamics/virtual_work.hpp -- Cotton's eq. (4): P . du is minus the
// virtual work of the inertia forces, the same number in every choice of speeds.
//
// inertia_virtual_work() computes  sum m a_G . dr_G + (I alpha + omega x I omega) . dtheta
// body by body, from two dual passes of the user's kinematics (one seeded with
// (q', u', 1) for the accelerations, one seeded with du for the displacements),
// without going through M and b.  The residual  P(u') . du - that  must be 0
// (an interval holding 0 for interval types): a check of the assembly that
// every `appell eval` result carries.
#pragma once

#include "appell/dynamics/system.hpp"

namespace appell {

template <Scalar T, class Sys>
T inertia_virtual_work(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                       const vector_t<T>& udot, const vector_t<T>& du) {
  std::vector<body_state<T>> plain;
  sys.template bodies<T>(q, u, t, plain);
  const vector_t<T> qd = sys.template qdot<T>(q, u, t);
  std::vector<body_state<dual<T>>> acc, disp;
  sys.template bodies<dual<T>>(detail::seeded<T>(q, &qd), detail::seeded<T>(u, &udot), dual<T>(t, T(1)), acc);
  sys.template bodies<dual<T>>(detail::seeded<T>(q, nullptr), detail::seeded<T>(u, &du), dual<T>(t), disp);
  T work = T(0);
  for (std::size_t i = 0; i < plain.size(); ++i) {
    const body_state<T>& s = plain[i];
    const vec3<T> a = detail::derivative(acc[i].velocity) + cross(s.frame_rate, s.velocity);
    const vec3<T> alpha = detail::derivative(acc[i].omega) + cross(s.frame_rate, s.omega);
    const vec3<T> dr = detail::derivative(disp[i].velocity), dtheta = detail::derivative(disp[i].omega);
    const vec3<T> moment = mat_vec(s.inertia, alpha) + cross(s.omega, mat_vec(s.inertia, s.omega));
    work += s.mass * dot(a, dr) + dot(moment, dtheta);
  }
  return work;
}

/// P(u') . du - (the same from the bodies): 0 in exact arithmetic.
template <Scalar T, class Sys>
T virtual_work_residual(const Sys& sys, const appell_equations<T>& eq, const vector_t<T>& q,
                        const vector_t<T>& u, const T& t, const vector_t<T>& udot, const vector_t<T>& du) {
  const vector_t<T> P = eq.P(udot);
  T pdu = T(0);
  for (Eigen::Index i = 0; i < du.size(); ++i) pdu += P(i) * du(i);
  return pdu - inertia_virtual_work(sys, q, u, t, udot, du);
}

}  // namespace appell
