// appell/dynamics/symmetric_top.hpp -- the body of a heavy symmetric top on a fixed point O of
// its axis, which two scene models share: the top on its pivot (models/heavy_top.hpp) and the top
// forced onto a cone (paper sec. 6, Example I: models/top_on_cone.hpp).  symmetric_top describes
// it on the fixed axes, symmetric_top_resal on Resal's trihedron; symmetric_top_energy is its
// energy, conserved on the pivot and on a fixed frictionless cone.
//
// Euler angles z-x-z (SCENES.md): psi about e3, theta about the line of nodes
// n = (cos psi, sin psi, 0), phi about the body axis
// e_z = (sin theta sin psi, -sin theta cos psi, cos theta).  Everything on the
// fixed frame:  omega = psi' e3 + theta' n + phi' e_z,  G = l e_z,
// v_G = omega x l e_z,  central inertia (A - m l^2)(1 - e_z e_z^T) + C e_z e_z^T,
// weight -m g e3 through G.  Nothing else is written by hand: the library
// differentiates this kinematics and forms Appell's equations.
//
// Angles: how the coordinates give the angles' sines and cosines.  euler_angles
// (the default) takes the coordinates to be psi, theta, phi; half_angle_tangents
// takes tau = tan(angle / 2) for psi and theta, so that sin, cos and q' are
// rational in the coordinates and the shipped code runs in exact rational
// arithmetic (proofs/).  phi never enters the kinematics (the top is symmetric).
#pragma once

#include <type_traits>
#include <vector>

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

/// The coordinates are the Euler angles themselves.
struct euler_angles {
  template <class S>
  static void sin_cos(const S& angle, S& s, S& c) {
    using std::sin, std::cos;
    s = sin(angle);
    c = cos(angle);
  }
  /// The coordinate's rate from the angle's rate.
  template <class S>
  static S rate(const S&, const S& angle_rate) {
    return angle_rate;
  }
};

/// The coordinates are tau = tan(angle / 2): sin = 2 tau / (1 + tau^2),
/// cos = (1 - tau^2) / (1 + tau^2), tau' = (1 + tau^2) / 2 angle'.
struct half_angle_tangents {
  template <class S>
  static void sin_cos(const S& tau, S& s, S& c) {
    const S d = S(1) + tau * tau;
    s = S(2) * tau / d;
    c = (S(1) - tau * tau) / d;
  }
  template <class S>
  static S rate(const S& tau, const S& angle_rate) {
    return (S(1) + tau * tau) / S(2) * angle_rate;
  }
};

namespace detail {
template <class Angles, class S>
vector_t<S> euler_rates_to_qdot(const vector_t<S>& q, const vector_t<S>& u) {
  if constexpr (std::is_same_v<Angles, euler_angles>) {
    (void)q;
    return u;
  } else {
    vector_t<S> d(3);
    d << Angles::rate(q(0), u(0)), Angles::rate(q(1), u(1)), u(2);
    return d;
  }
}
/// The same into d (its storage reused).
template <class Angles, class S>
void euler_rates_to_qdot_into(const vector_t<S>& q, const vector_t<S>& u, vector_t<S>& d) {
  if constexpr (std::is_same_v<Angles, euler_angles>) {
    (void)q;
    d = u;
  } else {
    d.resize(3);
    d << Angles::rate(q(0), u(0)), Angles::rate(q(1), u(1)), u(2);
  }
}
}  // namespace detail

template <Scalar T, class Angles = euler_angles>
struct symmetric_top {
  T A, C, mass, l, g;

  static constexpr int max_speeds = 3;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S&) const {
    return detail::euler_rates_to_qdot<Angles>(q, u);
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>& q, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    detail::euler_rates_to_qdot_into<Angles>(q, u, qd);
  }
  /// The body axis e_z and the line of nodes n at (psi, theta) = (q(0), q(1)).
  template <class V, class S>
  static void axes(const V& q, vec3<S>& n, vec3<S>& ez) {
    S sp, cp, st, ct;
    Angles::sin_cos(q(0), sp, cp);
    Angles::sin_cos(q(1), st, ct);
    n = vec3<S>(cp, sp, S(0));
    ez = vec3<S>(st * sp, -st * cp, ct);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    vec3<S> n, ez;
    axes(q, n, ez);
    body_state<S> b;
    b.mass = S(mass);
    b.omega = vec3<S>(S(0), S(0), u(0)) + n * u(1) + ez * u(2);
    b.velocity = cross(b.omega, vec3<S>(ez * S(l)));
    const S transverse = S(A) - S(mass) * S(l) * S(l);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b.inertia(i, j) = (S(C) - transverse) * ez(i) * ez(j) + (i == j ? transverse : S(0));
    b.force = vec3<S>(S(0), S(0), -S(mass) * S(g));
    out.push_back(b);
  }
};

/// The same top on Resal's trihedron (n, e_z x n, e_z), which turns with
/// psi' e3 + theta' n.  On it omega = (theta', psi' sin theta, psi' cos theta + phi'):
/// the spin phi' sits in one component only, the central inertia is the
/// constant diag(A - m l^2, A - m l^2, C), G = (0, 0, l), the weight is
/// -m g (0, sin theta, cos theta).  M, b and Q do not depend on the frame, so
/// this describes the same Appell equations as symmetric_top; but on the fixed axes
/// the fast spin (phi' = 40 in the paper scene) enters every component of omega
/// and cancels in omega x I omega and in the velocity-product terms, which made
/// interval enclosures of the reaction 700 times wider than the rounding error
/// of double (measured: 2.3e-12 relative against a double error of 3e-15).
template <Scalar T, class Angles = euler_angles>
struct symmetric_top_resal {
  T A, C, mass, l, g;

  static constexpr int max_speeds = 3;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S&) const {
    return detail::euler_rates_to_qdot<Angles>(q, u);
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>& q, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    detail::euler_rates_to_qdot_into<Angles>(q, u, qd);
  }
  /// The trihedron's axes n, e_z x n, e_z as the columns of a rotation (fixed-axis components).
  template <class V, class S = typename V::Scalar>
  static mat3<S> axes(const V& q) {
    S sp, cp, st, ct;
    Angles::sin_cos(q(0), sp, cp);
    Angles::sin_cos(q(1), st, ct);
    mat3<S> R;
    R << cp, -ct * sp, st * sp,  //
        sp, ct * cp, -st * cp,   //
        S(0), st, ct;
    return R;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    S st, ct;
    Angles::sin_cos(q(1), st, ct);
    out.push_back(body(st, ct, vec3<S>(u(1), u(0) * st, u(0) * ct), vec3<S>(u(1), u(0) * st, u(0) * ct + u(2))));
  }
  /// The top on the trihedron at theta (sin, cos), turning with frame_rate, its angular velocity
  /// omega: G = (0, 0, l), v_G = omega x (0, 0, l), the central inertia diag(A - m l^2, A - m l^2, C),
  /// the weight -m g (0, sin theta, cos theta).  Also the body of the top in Resal's speeds
  /// (ode::heavy_top_resal_problem), whose omega is its speeds.
  template <class S>
  body_state<S> body(const S& st, const S& ct, const vec3<S>& frame_rate, const vec3<S>& omega) const {
    body_state<S> b;
    b.mass = S(mass);
    b.frame_rate = frame_rate;
    b.omega = omega;
    b.velocity = vec3<S>(S(l) * omega(1), -(S(l) * omega(0)), S(0));
    const S transverse = S(A) - S(mass) * S(l) * S(l);
    b.inertia(0, 0) = transverse;
    b.inertia(1, 1) = transverse;
    b.inertia(2, 2) = S(C);
    const S weight = S(mass) * S(g);
    b.force = vec3<S>(S(0), -(weight * st), -(weight * ct));
    return b;
  }
};

/// The top's energy 1/2 A (theta'^2 + psi'^2 sin^2 theta) + 1/2 C r^2 + m g l cos theta, with the
/// spin r = phi' + psi' cos theta, at theta given by its sine and cosine (A about O, C about the
/// axis, l = OG): conserved on the pivot and on a fixed frictionless cone, whose couple does no work.
template <class S, class T>
S symmetric_top_energy(const T& A, const T& C, const T& mass, const T& g, const T& l, const S& sin_theta,
                       const S& cos_theta, const S& psi_dot, const S& theta_dot, const S& phi_dot) {
  const S r = phi_dot + psi_dot * cos_theta;
  const S sA(A), sC(C);
  return (sA * (theta_dot * theta_dot + psi_dot * psi_dot * sin_theta * sin_theta) + sC * r * r) / S(2) +
         S(mass) * S(g) * S(l) * cos_theta;
}

}  // namespace appell
