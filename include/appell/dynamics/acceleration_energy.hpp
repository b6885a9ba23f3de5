// appell/dynamics/acceleration_energy.hpp -- Appell's S evaluated from the bodies.
//
//   S(u') = sum 1/2 m |a_G|^2 + 1/2 alpha . I alpha + alpha . (omega x I omega)
// with a_G, alpha from one dual pass seeded with (q', u', 1).  This is a
// verification tool (proofs/, tests/): it includes S0, which the equations
// never need and gibbs_appell() never forms (Cotton sec. 2).
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

template <Scalar T, class Sys>
T acceleration_energy(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                      const vector_t<T>& udot) {
  std::vector<body_state<T>> plain;
  sys.template bodies<T>(q, u, t, plain);
  const vector_t<T> qd = sys.template qdot<T>(q, u, t);
  std::vector<body_state<dual<T>>> acc;
  sys.template bodies<dual<T>>(detail::seeded<T>(q, &qd), detail::seeded<T>(u, &udot), dual<T>(t, T(1)), acc);
  T S = T(0);
  for (std::size_t i = 0; i < plain.size(); ++i) {
    const body_state<T>& s = plain[i];
    const vec3<T> a = detail::derivative(acc[i].velocity) + cross(s.frame_rate, s.velocity);
    const vec3<T> alpha = detail::derivative(acc[i].omega) + frame_cross_omega(s);
    S += s.mass * dot(a, a) / T(2) + dot(alpha, mat_vec(s.inertia, alpha)) / T(2) +
         dot(alpha, cross(s.omega, mat_vec(s.inertia, s.omega)));
  }
  return S;
}

}  // namespace appell
