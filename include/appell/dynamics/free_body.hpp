// appell/dynamics/free_body.hpp -- paper sec. 4: a free rigid body referred to
// axes Gxyz through its centre of mass that move relative to the body and to
// space (rotation P, Q, R); moments and products of inertia A..F vary with time.
//
// Speeds (u, v, w, p, q, r): the velocity of G and the body's rotation, on the
// moving axes; parameters with dq_1 = u dt, ..., dq_6 = r dt.  The generic path
// gives Appell's equations; Cotton's eqs. (7) and (8),
//   M (u' + Q w - R v) = X, ...      d sigma/dt + Omega x sigma = (L, M, N),
// with sigma = I omega and d sigma/dt = I' omega + I omega', are written out in
// newton_euler() for comparison (tests, proofs).
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

/// Axes: axes.template rate<S>(t) -> (P, Q, R); axes.template inertia<S>(t) -> the
/// tensor [[A, -F, -E], [-F, B, -D], [-E, -D, C]] on the axes at time t.
template <Scalar T, class Axes>
struct free_body_on_moving_axes {
  T mass;
  Axes axes;
  vec3<T> force, couple;  ///< X, Y, Z and L, M, N on the axes

  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>&, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    body_state<S> b;
    b.mass = S(mass);
    b.velocity = vec3<S>(u(0), u(1), u(2));
    b.omega = vec3<S>(u(3), u(4), u(5));
    b.frame_rate = axes.template rate<S>(t);
    b.inertia = axes.template inertia<S>(t);
    for (int i = 0; i < 3; ++i) {
      b.force(i) = S(force(i));
      b.couple(i) = S(couple(i));
    }
    out.push_back(b);
  }

  /// The left-hand sides of Cotton's (7) and (8) at accelerations udot.
  vector_t<T> newton_euler(const vector_t<T>& u, const T& t, const vector_t<T>& udot) const {
    const vec3<T> Om = axes.template rate<T>(t);
    const mat3<T> I = axes.template inertia<T>(t);
    const mat3<dual<T>> Id = axes.template inertia<dual<T>>(dual<T>(t, T(1)));
    mat3<T> Idot;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Idot(i, j) = Id(i, j).d;
    const vec3<T> v(u(0), u(1), u(2)), w(u(3), u(4), u(5)), vd(udot(0), udot(1), udot(2)),
        wd(udot(3), udot(4), udot(5));
    const vec3<T> lin = (vd + cross(Om, v)) * mass;                                         // (7)
    const vec3<T> sigma = mat_vec(I, w);
    const vec3<T> ang = mat_vec(Idot, w) + mat_vec(I, wd) + cross(Om, sigma);               // (8)
    vector_t<T> P(6);
    P << lin(0), lin(1), lin(2), ang(0), ang(1), ang(2);
    return P;
  }
};

}  // namespace appell
