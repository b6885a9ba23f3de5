// appell/scenes/top_on_pivot.hpp -- the heavy symmetric top on a fixed point O
// of its axis, no cone: the classical benchmark, with the force of the pivot.
//
// Cotton's way (paper sec. 5, last paragraph): start from the free solid, k + s
// = 6 speeds, and add the fixed point as s = 3 constraints.  Speeds
//   v = (psi', theta', phi', w_x, w_y, w_z),
// w the velocity of the body's material point at O, on the fixed axes; the
// pivot is w = 0, the last three speeds.  The pivot force F at O does the
// virtual power F . w, so Cotton's Q'_c (eq. 14) on (w_x, w_y, w_z) is F itself,
// on the fixed axes: no wrench solve is needed.  Coordinates q = (psi, theta,
// phi, x_O, y_O, z_O) (the body's point at O; q' = v); Euler angles z-x-z as in
// top_on_cone.hpp.  The body is described on Resal's trihedron (n, e_z x n,
// e_z), which turns with psi' e3 + theta' n: there the inertia is constant,
// the spin sits in one component of omega, and the interval enclosures stay
// tight (see heavy_top_resal); w enters through its components on that
// trihedron, R^T w.
//
// The independent check: the same top as a free body on the fixed axes, speeds
// (x_G', y_G', z_G', psi', theta', phi'), with the pivot written as the
// constraint v_O = v_G - omega x l e_z = 0 (three rows, linear in the speeds)
// and solved by Lagrange's multipliers: they are F again.  The tests add a
// third route, Newton-Euler written out in closed form (F = m a_G + m g e3).
//
// The Euler angles are singular where sin theta = 0 (the axis on the
// vertical): Appell's equations lose rank there; the model refuses theta = 0
// exactly and the scalars' error amplification reports the neighbourhood.
#pragma once

#include "appell/scenes/top_on_cone.hpp"  // heavy_top, heavy_top_resal: the top's body

namespace appell {

/// The top as a free body with its point O as three speeds (Cotton's speeds):
/// heavy_top_resal's body, with R^T w added to the velocity of G.
template <Scalar T>
struct free_top_resal {
  T A, C, mass, l, g;  ///< A: transverse moment about O; C: axial; l = OG

  static constexpr int max_speeds = 6;  ///< differentiated in one pass (system.hpp)
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& v, const S&) const {
    return v;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& v, const S& t, std::vector<body_state<S>>& out) const {
    const vector_t<S> angles = q.head(3), rates = v.head(3);
    heavy_top_resal<T>{A, C, mass, l, g}.bodies(angles, rates, t, out);
    const mat3<S> R = heavy_top_resal<T>::axes(angles);
    body_state<S>& b = out.back();
    for (int i = 0; i < 3; ++i)  // (R^T w)_i = column i of R . w
      b.velocity(i) += R(0, i) * v(3) + R(1, i) * v(4) + R(2, i) * v(5);
  }
};

/// The same top as a free body on the fixed axes, speeds (x_G', y_G', z_G', psi', theta', phi'):
/// heavy_top's body, with the velocity of G as three speeds of its own.
template <Scalar T>
struct free_top_fixed_axes {
  T A, C, mass, l, g;

  static constexpr int max_speeds = 6;
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    const vector_t<S> angles = q.tail(3), rates = u.tail(3);
    heavy_top<T>{A, C, mass, l, g}.bodies(angles, rates, t, out);
    out.back().velocity = vec3<S>(u(0), u(1), u(2));
  }
};

/// v_O = v_G - omega x l e_z = 0 on free_top_fixed_axes: A u = 0 with
/// A = [I_3, -l e3 x e_z, -l n x e_z, 0] (omega = psi' e3 + theta' n + phi' e_z).
template <Scalar T>
struct pivot_constraint {
  T l;
  int count() const { return 3; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    vec3<S> n, ez;
    heavy_top<T>::axes(vector_t<S>(q.tail(3)), n, ez);
    const vec3<S> e3(S(0), S(0), S(1));
    const vec3<S> c_psi = cross(e3, ez), c_theta = cross(n, ez);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(i, j) = i == j ? S(1) : S(0);
      A(i, 3) = -(S(l) * c_psi(i));
      A(i, 4) = -(S(l) * c_theta(i));
      A(i, 5) = S(0);
      a(i) = S(0);
    }
  }
};

template <Scalar T>
struct top_on_pivot_state {
  T psi, theta, phi, psi_dot, theta_dot, phi_dot;
};

template <Scalar T>
struct top_on_pivot_result {
  T psi_ddot, theta_ddot, phi_ddot;
  vec3<T> pivot_force;            ///< Cotton's Q'_c on w: the force of the pivot on the top, fixed axes
  T virtual_work_residual;        ///< eq. (4) in Cotton's speeds: 0 on the motion
  vec3<T> pivot_force_lagrange;   ///< the multipliers of v_O = 0 on the free body on fixed axes
  T psi_ddot_lagrange, theta_ddot_lagrange, phi_ddot_lagrange;
};

namespace detail {
/// The free top's positions (Euler angles, then the pivot at the origin) and its free speeds.
template <Scalar T>
vector_t<T> pivot_positions(const top_on_pivot_state<T>& s) {
  vector_t<T> q(6);
  q << s.psi, s.theta, s.phi, T(0), T(0), T(0);
  return q;
}
template <Scalar T>
vector_t<T> pivot_free_speeds(const top_on_pivot_state<T>& s) {
  vector_t<T> v_a(3);
  v_a << s.psi_dot, s.theta_dot, s.phi_dot;
  return v_a;
}
}  // namespace detail

/// Cotton's method on the free top with the pivot as its last three speeds:
/// (psi'', theta'', phi'') and the pivot force (fixed axes).  What `appell eval`
/// reports, and what `appell simulate` / `enclose` report along the motion (their
/// right-hand side is top_on_pivot_accelerations, below).
template <Scalar T>
cotton_result<T> top_on_pivot_cotton(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                     const top_on_pivot_state<T>& s) {
  const free_top_resal<T> sys{A, C, mass, l, g};
  return cotton_reactions(sys, detail::pivot_positions(s), detail::pivot_free_speeds(s), T(0), 3);
}

/// top_on_pivot_cotton's (psi'', theta'', phi'') alone, bit for bit, without the pivot force:
/// the right-hand side of the motion (ode/problems.hpp), which needs no reaction.
template <Scalar T>
vector_t<T> top_on_pivot_accelerations(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                       const top_on_pivot_state<T>& s) {
  const free_top_resal<T> sys{A, C, mass, l, g};
  return cotton_free_accelerations<4>(sys, detail::pivot_positions(s), detail::pivot_free_speeds(s), T(0), 3);
}

/// The heavy top on its pivot: Cotton's method from the free body, and the
/// Lagrange multipliers of the free body on the fixed axes as the check.
template <Scalar T>
top_on_pivot_result<T> top_on_pivot_motion(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                           const top_on_pivot_state<T>& s) {
  const T t = T(0);
  top_on_pivot_result<T> r;
  {
    const free_top_resal<T> sys{A, C, mass, l, g};
    const vector_t<T> q = detail::pivot_positions(s), v_a = detail::pivot_free_speeds(s);
    const cotton_result<T> c = top_on_pivot_cotton(A, C, mass, l, g, s);
    r.psi_ddot = c.free_accelerations(0);
    r.theta_ddot = c.free_accelerations(1);
    r.phi_ddot = c.free_accelerations(2);
    r.pivot_force = vec3<T>(c.reactions(0), c.reactions(1), c.reactions(2));
    vector_t<T> v = vector_t<T>::Zero(6), vdot = vector_t<T>::Zero(6);
    v.head(3) = v_a;
    vdot.head(3) = c.free_accelerations;
    const vector_t<T> ones = vector_t<T>::Ones(6);
    r.virtual_work_residual = virtual_work_residual(sys, c.equations, q, v, t, vdot, ones);
  }
  {
    const free_top_fixed_axes<T> sys{A, C, mass, l, g};
    // G = l e_z (O at the origin), v_G = omega x l e_z.
    vector_t<T> q(6), u(6);
    q << T(0), T(0), T(0), s.psi, s.theta, s.phi;
    vec3<T> n, ez;
    heavy_top<T>::axes(vector_t<T>(q.tail(3)), n, ez);
    for (int i = 0; i < 3; ++i) q(i) = l * ez(i);
    const vec3<T> omega = vec3<T>(T(0), T(0), s.psi_dot) + n * s.theta_dot + ez * s.phi_dot;
    const vec3<T> vG = cross(omega, vec3<T>(ez * l));
    u << vG(0), vG(1), vG(2), s.psi_dot, s.theta_dot, s.phi_dot;
    const constrained_motion<T> lag = lagrange_multipliers(sys, pivot_constraint<T>{l}, q, u, t);
    r.pivot_force_lagrange = vec3<T>(lag.reactions(0), lag.reactions(1), lag.reactions(2));
    r.psi_ddot_lagrange = lag.accelerations(3);
    r.theta_ddot_lagrange = lag.accelerations(4);
    r.phi_ddot_lagrange = lag.accelerations(5);
  }
  return r;
}

}  // namespace appell
