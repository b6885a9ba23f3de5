// appell/scenes/heavy_top.hpp -- the heavy symmetric top on a fixed point O of its axis:
// its body (heavy_top on the fixed axes, heavy_top_resal on Resal's trihedron) and the model
// on its pivot, no cone (free_top_resal, top_on_pivot_motion).  Example I (top_on_cone.hpp)
// forces the same body's axis onto a cone.
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
//
// The top on its pivot: the classical benchmark, with the force of the pivot.
//
// Cotton's way (paper sec. 5, last paragraph): start from the free solid, k + s
// = 6 speeds, and add the fixed point as s = 3 constraints.  Speeds
//   v = (psi', theta', phi', w_x, w_y, w_z),
// w the velocity of the body's material point at O, on the fixed axes; the
// pivot is w = 0, the last three speeds.  The pivot force F at O does the
// virtual power F . w, so Cotton's Q'_c (eq. 14) on (w_x, w_y, w_z) is F itself,
// on the fixed axes: no wrench solve is needed.  Coordinates q = (psi, theta,
// phi, x_O, y_O, z_O) (the body's point at O; q' = v); Euler angles z-x-z as
// above.  The body is described on Resal's trihedron (n, e_z x n,
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

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"

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
struct heavy_top {
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
/// this describes the same Appell equations as heavy_top; but on the fixed axes
/// the fast spin (phi' = 40 in the paper scene) enters every component of omega
/// and cancels in omega x I omega and in the velocity-product terms, which made
/// interval enclosures of the reaction 700 times wider than the rounding error
/// of double (measured: 2.3e-12 relative against a double error of 3e-15).
template <Scalar T, class Angles = euler_angles>
struct heavy_top_resal {
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


/// The top as a free body with its point O as three speeds (Cotton's speeds):
/// heavy_top_resal's body, with R^T w added to the velocity of G.
template <Scalar T>
struct free_top_resal {
  T A, C, mass, l, g;  ///< A: transverse moment about O; C: axial; l = OG

  static constexpr int max_speeds = 6;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& v, const S&) const {
    return v;
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& v, const S&, vector_t<S>& qd) const {
    qd = v;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& v, const S& t, std::vector<body_state<S>>& out) const {
    struct site;  // borrowed (linalg/scratch.hpp)
    const scratch<vector_t<S>, site> angles, rates;
    *angles = q.head(3);
    *rates = v.head(3);
    heavy_top_resal<T>{A, C, mass, l, g}.bodies(*angles, *rates, t, out);
    const mat3<S> R = heavy_top_resal<T>::axes(*angles);
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
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    qd = u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    struct site;  // borrowed (linalg/scratch.hpp)
    const scratch<vector_t<S>, site> angles, rates;
    *angles = q.tail(3);
    *rates = u.tail(3);
    heavy_top<T>{A, C, mass, l, g}.bodies(*angles, *rates, t, out);
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
    heavy_top<T>::axes(q.tail(3), n, ez);
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
/// the right-hand side of the motion (the model's problem, models/<name>.hpp), which needs no reaction.
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
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q_held, u_held, v_held, vdot_held, ones;
  vector_t<T>&q = *q_held, &u = *u_held, &v = *v_held, &vdot = *vdot_held;
  {
    const free_top_resal<T> sys{A, C, mass, l, g};
    q.resize(6);
    q << s.psi, s.theta, s.phi, T(0), T(0), T(0);  // detail::pivot_positions
    v.setZero(6);
    v(0) = s.psi_dot, v(1) = s.theta_dot, v(2) = s.phi_dot;  // the free speeds, then the pivot's 0
    const scratch<cotton_result<T>, site> c_held;
    const cotton_result<T>& c = *c_held;
    const scratch<vector_t<T>, site> v_a;
    *v_a = v.head(3);  // detail::pivot_free_speeds
    cotton_reactions_into(sys, q, *v_a, t, 3, *c_held);  // top_on_pivot_cotton
    r.psi_ddot = c.free_accelerations(0);
    r.theta_ddot = c.free_accelerations(1);
    r.phi_ddot = c.free_accelerations(2);
    r.pivot_force = vec3<T>(c.reactions(0), c.reactions(1), c.reactions(2));
    vdot.setZero(6);
    vdot.head(3) = c.free_accelerations;
    ones->setOnes(6);
    r.virtual_work_residual = virtual_work_residual(sys, c.equations, q, v, t, vdot, *ones);
  }
  {
    const free_top_fixed_axes<T> sys{A, C, mass, l, g};
    // G = l e_z (O at the origin), v_G = omega x l e_z.
    q.resize(6);
    u.resize(6);
    q << T(0), T(0), T(0), s.psi, s.theta, s.phi;
    vec3<T> n, ez;
    heavy_top<T>::axes(q.tail(3), n, ez);
    for (int i = 0; i < 3; ++i) q(i) = l * ez(i);
    const vec3<T> omega = vec3<T>(T(0), T(0), s.psi_dot) + n * s.theta_dot + ez * s.phi_dot;
    const vec3<T> vG = cross(omega, vec3<T>(ez * l));
    u << vG(0), vG(1), vG(2), s.psi_dot, s.theta_dot, s.phi_dot;
    const scratch<constrained_motion<T>, site> lag_held;
    const constrained_motion<T>& lag = *lag_held;
    lagrange_multipliers_into(sys, pivot_constraint<T>{l}, q, u, t, *lag_held);
    r.pivot_force_lagrange = vec3<T>(lag.reactions(0), lag.reactions(1), lag.reactions(2));
    r.psi_ddot_lagrange = lag.accelerations(3);
    r.theta_ddot_lagrange = lag.accelerations(4);
    r.phi_ddot_lagrange = lag.accelerations(5);
  }
  return r;
}

}  // namespace appell
