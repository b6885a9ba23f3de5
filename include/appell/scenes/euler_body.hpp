// appell/scenes/euler_body.hpp -- paper sec. 3: Euler's equations.
//
// A rigid body turns about a fixed point that is its centre of mass; body
// axes are principal, with moments A, B, C; speeds p, q, r are the components
// of the angular velocity on those axes; L, M, N the applied torque.
// Appell's S = 1/2 (A p'^2 + B q'^2 + C r'^2) + (C - B) q r p' + (A - C) r p q'
//            + (B - A) p q r' + ..., and dS/dp' = L etc. give
//   A p' = (B - C) q r + L,   B q' = (C - A) r p + M,   C r' = (A - B) p q + N.
// euler_omega_dot() writes them directly (the reference of the tests);
// euler_system is the same body for the generic Gibbs-Appell path:
// components on the body axes, a frame turning with omega itself, speeds
// u = (p, q, r), parameters with lambda' = p, ... (sec. 3).
// euler_body_motion() is the result function `appell eval` calls: the generic
// path, and the checks eq. (4) and the power balance.
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/dynamics/virtual_work.hpp"

namespace appell {

template <Scalar T>
struct euler_body {
  vec3<T> inertia;  ///< principal moments A, B, C
  vec3<T> torque;   ///< L, M, N on the body axes
};

/// (p', q', r') at angular velocity omega = (p, q, r).
template <Scalar T>
vec3<T> euler_omega_dot(const euler_body<T>& body, const vec3<T>& omega) {
  const T &A = body.inertia(0), &B = body.inertia(1), &C = body.inertia(2);
  const T &p = omega(0), &q = omega(1), &r = omega(2);
  return vec3<T>(((B - C) * q * r + body.torque(0)) / A,
                 ((C - A) * r * p + body.torque(1)) / B,
                 ((A - B) * p * q + body.torque(2)) / C);
}

/// The power balance dT/dt - omega . torque = omega . (I omega') - omega . torque,
/// which vanishes on every motion (the gyroscopic couple does no work): an
/// independent check of omega', 0 (point) or an interval holding 0.
template <Scalar T>
T euler_power_residual(const euler_body<T>& body, const vec3<T>& omega, const vec3<T>& omega_dot) {
  T residual = T(0);
  for (int i = 0; i < 3; ++i)
    residual += omega(i) * (body.inertia(i) * omega_dot(i) - body.torque(i));
  return residual;
}

/// Euler's body as a system for the generic path.
template <Scalar T>
struct euler_system {
  euler_body<T> body;
  static constexpr int max_speeds = 3;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;  // lambda' = p, mu' = q, nu' = r
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    qd = u;
  }
  template <class S>
  void bodies(const vector_t<S>&, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    body_state<S> b;  // mass irrelevant: G is fixed
    b.omega = vec3<S>(u(0), u(1), u(2));
    b.frame_rate = b.omega;  // the body axes turn with the body
    b.frame_is_body = true;
    for (int i = 0; i < 3; ++i) {
      b.inertia(i, i) = S(body.inertia(i));
      b.couple(i) = S(body.torque(i));
    }
    out.push_back(b);
  }
};

template <Scalar T>
struct euler_body_result {
  vec3<T> omega_dot;        ///< (p', q', r')
  T virtual_work_residual;  ///< eq. (4): 0 on the motion
  T power_residual;         ///< omega . (I omega') - omega . torque: 0 on the motion
};

/// Appell's equations of Euler's body at angular velocity omega (the generic path):
/// what `appell eval` solves, and what `appell simulate` / `enclose` run on jets.
template <Scalar T>
appell_equations<T> euler_body_equations(const euler_body<T>& body, const vec3<T>& omega) {
  return gibbs_appell(euler_system<T>{body}, vector_t<T>(vector_t<T>::Zero(3)), vector_t<T>(omega), T(0));
}

/// Euler's body through the generic Gibbs-Appell path at angular velocity omega.
template <Scalar T>
euler_body_result<T> euler_body_motion(const euler_body<T>& body, const vec3<T>& omega) {
  const euler_system<T> sys{body};
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q, u, udot, ones;
  const scratch<appell_equations<T>, site> eq;
  q->setZero(3);
  *u = omega;
  ones->setOnes(3);
  gibbs_appell_into(sys, *q, *u, T(0), *eq);  // euler_body_equations' equations
  eq->accelerations_into(*udot);
  euler_body_result<T> r;
  r.omega_dot = vec3<T>((*udot)(0), (*udot)(1), (*udot)(2));
  r.virtual_work_residual = virtual_work_residual(sys, *eq, *q, *u, T(0), *udot, *ones);
  r.power_residual = euler_power_residual(body, omega, r.omega_dot);
  return r;
}

}  // namespace appell
