// appell/scenes/top_on_cone.hpp -- paper sec. 6, Example I: a heavy symmetric
// top on a fixed point O of its axis, the axis forced onto the cone psi = f(theta).
//
// Euler angles z-x-z (SCENES.md): psi about e3, theta about the line of nodes
// n = (cos psi, sin psi, 0), phi about the body axis
// e_z = (sin theta sin psi, -sin theta cos psi, cos theta).  Everything on the
// fixed frame:  omega = psi' e3 + theta' n + phi' e_z,  G = l e_z,
// v_G = omega x l e_z,  central inertia (A - m l^2)(1 - e_z e_z^T) + C e_z e_z^T,
// weight -m g e3 through G.  Nothing else is written by hand: the library
// differentiates this kinematics and forms Appell's equations.
//
// heavy_top:          the unconstrained top, speeds u = (psi', theta', phi').
// cone_constraint:    psi' - f'(theta) theta' = 0, i.e. A u = a with
//                     A = [1, -f'(theta), 0], a = 0 (for Lagrange multipliers
//                     and for the library-built adapted speeds).
// cone_speeds:        Cotton's change (18), psi = psi_1 + f(theta): speeds
//                     v = (theta', phi', psi_1') with psi' = psi_1' + f'(theta) theta';
//                     the added constraint is psi_1' = 0 (19).
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/system.hpp"
#include "appell/expr/expression.hpp"

namespace appell {

template <Scalar T>
struct heavy_top {
  T A, C, mass, l, g;

  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  /// The body axis e_z and the line of nodes n at (psi, theta).
  template <class S>
  static void axes(const vector_t<S>& q, vec3<S>& n, vec3<S>& ez) {
    using std::sin, std::cos;
    const S sp = sin(q(0)), cp = cos(q(0)), st = sin(q(1)), ct = cos(q(1));
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
/// this describes the same Appell equations as heavy_top; but on the fixed axes
/// the fast spin (phi' = 40 in the paper scene) enters every component of omega
/// and cancels in omega x I omega and in the velocity-product terms, which made
/// interval enclosures of the reaction 700 times wider than the rounding error
/// of double (measured: 2.3e-12 relative against a double error of 3e-15).
template <Scalar T>
struct heavy_top_resal {
  T A, C, mass, l, g;

  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  /// The trihedron's axes n, e_z x n, e_z as the columns of a rotation (fixed-axis components).
  template <class S>
  static mat3<S> axes(const vector_t<S>& q) {
    using std::sin, std::cos;
    const S sp = sin(q(0)), cp = cos(q(0)), st = sin(q(1)), ct = cos(q(1));
    mat3<S> R;
    R << cp, -ct * sp, st * sp,  //
        sp, ct * cp, -st * cp,   //
        S(0), st, ct;
    return R;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    using std::sin, std::cos;
    const S st = sin(q(1)), ct = cos(q(1));
    body_state<S> b;
    b.mass = S(mass);
    b.frame_rate = vec3<S>(u(1), u(0) * st, u(0) * ct);
    b.omega = vec3<S>(u(1), u(0) * st, u(0) * ct + u(2));
    b.velocity = vec3<S>(S(l) * b.omega(1), -(S(l) * b.omega(0)), S(0));  // omega x (0, 0, l)
    const S transverse = S(A) - S(mass) * S(l) * S(l);
    b.inertia(0, 0) = transverse;
    b.inertia(1, 1) = transverse;
    b.inertia(2, 2) = S(C);
    const S weight = S(mass) * S(g);
    b.force = vec3<S>(S(0), -(weight * st), -(weight * ct));
    out.push_back(b);
  }
};

/// psi' - f'(theta) theta' = 0.
template <Scalar T>
struct cone_constraint {
  const bound_expression<T>* fprime;
  int count() const { return 1; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    A(0, 0) = S(1);
    A(0, 1) = -fprime->eval(q(1));
    A(0, 2) = S(0);
    a(0) = S(0);
  }
};

/// Cotton's speeds (theta', phi', psi_1') -> (psi', theta', phi').
template <Scalar T>
struct cone_speeds {
  const bound_expression<T>* fprime;
  template <class S>
  vector_t<S> apply(const vector_t<S>& q, const vector_t<S>& v, const S&) const {
    vector_t<S> u(3);
    u(0) = v(2) + fprime->eval(q(1)) * v(0);
    u(1) = v(0);
    u(2) = v(1);
    return u;
  }
};

}  // namespace appell
