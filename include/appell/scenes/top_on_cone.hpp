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
// top_on_cone_motion: all of Example I's method (the free accelerations, H by
//                     eq. (14), psi'', the couple from virtual work, and the
//                     checks eq. (4) and Cotton = Lagrange): the one result
//                     function that `appell eval`, the tests and the proofs call.
//
// Angles: how the coordinates give the angles' sines and cosines.  euler_angles
// (the default) takes the coordinates to be psi, theta, phi; half_angle_tangents
// takes tau = tan(angle / 2) for psi and theta, so that sin, cos and q' are
// rational in the coordinates and the shipped code runs in exact rational
// arithmetic (proofs/).  phi never enters the kinematics (the top is symmetric).
// A cone is any type with `S fprime(const S& theta_coordinate)` (also on dual
// numbers) and `T fsecond(const T& theta_coordinate)`: f'(theta) and f''(theta).
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/system.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/expr/expression.hpp"
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
}  // namespace detail

template <Scalar T, class Angles = euler_angles>
struct heavy_top {
  T A, C, mass, l, g;

  static constexpr int max_speeds = 3;  ///< differentiated in one pass (system.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S&) const {
    return detail::euler_rates_to_qdot<Angles>(q, u);
  }
  /// The body axis e_z and the line of nodes n at (psi, theta).
  template <class S>
  static void axes(const vector_t<S>& q, vec3<S>& n, vec3<S>& ez) {
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

  static constexpr int max_speeds = 3;  ///< differentiated in one pass (system.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S&) const {
    return detail::euler_rates_to_qdot<Angles>(q, u);
  }
  /// The trihedron's axes n, e_z x n, e_z as the columns of a rotation (fixed-axis components).
  template <class S>
  static mat3<S> axes(const vector_t<S>& q) {
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

/// A cone psi = f(theta) given by expressions (a scene's "cone"): f, f', f''.
template <Scalar T>
struct expression_cone {
  compiled_expression<T> f_expr, fprime_expr, fsecond_expr;
  template <class S>
  S psi(const S& theta) const {
    return f_expr.eval(theta);
  }
  template <class S>
  S fprime(const S& theta) const {
    return fprime_expr.eval(theta);
  }
  template <class S>
  S fsecond(const S& theta) const {
    return fsecond_expr.eval(theta);
  }
};

/// psi' - f'(theta) theta' = 0.
template <class Cone>
struct cone_constraint {
  const Cone* cone;
  int count() const { return 1; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    A(0, 0) = S(1);
    A(0, 1) = -cone->fprime(q(1));
    A(0, 2) = S(0);
    a(0) = S(0);
  }
};

/// Cotton's speeds (theta', phi', psi_1') -> (psi', theta', phi').
template <class Cone>
struct cone_speeds {
  const Cone* cone;
  template <class S>
  vector_t<S> apply(const vector_t<S>& q, const vector_t<S>& v, const S&) const {
    vector_t<S> u(3);
    u(0) = v(2) + cone->fprime(q(1)) * v(0);
    u(1) = v(0);
    u(2) = v(1);
    return u;
  }
};

/// The state of Example I: the coordinates (psi on the cone, theta, phi) and the free speeds.
template <Scalar T>
struct top_on_cone_state {
  T psi, theta, phi, theta_dot, phi_dot;
};

template <Scalar T>
struct top_on_cone_result {
  T theta_ddot, phi_ddot, psi_ddot;
  T H;             ///< Cotton's Q'_c (eq. 14): the couple's moment about the vertical e3
  vec3<T> couple;  ///< the constraint couple, fixed axes (from its virtual work, sec. 5)
  T virtual_work_residual;  ///< eq. (4) in Cotton's speeds: 0 on the motion
  T lagrange_multiplier;    ///< of psi' - f' theta' = 0 on the unconstrained top (fixed axes)
  T theta_ddot_lagrange;    ///< theta'' from the same saddle-point system
  cotton_result<T> cotton;  ///< Cotton's method in the paper's speeds (theta', phi', psi_1')
};

/// Example I (paper sec. 6).  Cotton (sec. 6): speeds (theta', phi', psi_1'),
/// the cone is psi_1' = 0.  The top is described on Resal's trihedron (tight
/// enclosures); the Lagrange check uses the fixed-axis description `top`, an
/// independent route.  psi need not equal f(theta) for the algebra (the
/// dynamics does not depend on psi: rotations about the vertical), but a state
/// of the scene has psi = f(theta).
namespace detail {
/// f(sys, q, v_a): the top in Cotton's speeds on the cone (theta', phi' free, the cone's speed
/// constrained), at state s.
template <Scalar T, class Angles, class Cone, class F>
auto on_cone_speeds(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s, F&& f) {
  vector_t<T> q(3);
  q << s.psi, s.theta, s.phi;
  const heavy_top_resal<T, Angles> resal{top.A, top.C, top.mass, top.l, top.g};
  const auto sys = change_speeds(resal, cone_speeds<Cone>{&cone}, 3);
  vector_t<T> v_a(2);
  v_a << s.theta_dot, s.phi_dot;
  return f(sys, q, v_a);
}
}  // namespace detail

/// Cotton's method alone (the accelerations theta'', phi'' and H): what the motion's results
/// need (ode/problems.hpp); top_on_cone_motion adds the couple and the checks.
template <Scalar T, class Angles, class Cone>
cotton_result<T> top_on_cone_cotton(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_reactions(sys, q, v_a, T(0), 1);
  });
}

/// top_on_cone_cotton's (theta'', phi'') alone, bit for bit, without H: the right-hand side of
/// the motion (ode/problems.hpp).
template <Scalar T, class Angles, class Cone>
vector_t<T> top_on_cone_accelerations(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_free_accelerations<3>(sys, q, v_a, T(0), 1);
  });
}

/// Without `couple_and_checks` only the accelerations and H are formed (couple, eq. (4) and
/// Lagrange's check left 0): the motion over time (ode/problems.hpp) encloses them over a whole
/// step, where the couple's 3 x 3 solve over the step's box need not be certifiable.
template <Scalar T, class Angles, class Cone>
top_on_cone_result<T> top_on_cone_motion(const heavy_top<T, Angles>& top, const Cone& cone,
                                         const top_on_cone_state<T>& s, bool couple_and_checks = true) {
  const T t = T(0);
  const T fp = cone.fprime(s.theta), fpp = cone.fsecond(s.theta);
  vector_t<T> q(3);
  q << s.psi, s.theta, s.phi;
  const heavy_top_resal<T, Angles> resal{top.A, top.C, top.mass, top.l, top.g};
  const auto sys = change_speeds(resal, cone_speeds<Cone>{&cone}, 3);
  top_on_cone_result<T> r;
  r.cotton = top_on_cone_cotton(top, cone, s);
  r.theta_ddot = r.cotton.free_accelerations(0);
  r.phi_ddot = r.cotton.free_accelerations(1);
  r.H = r.cotton.reactions(0);
  r.psi_ddot = fpp * s.theta_dot * s.theta_dot + fp * r.theta_ddot;  // d/dt (f'(theta) theta')
  if (!couple_and_checks) {
    r.couple = vec3<T>(T(0), T(0), T(0));
    r.virtual_work_residual = r.lagrange_multiplier = r.theta_ddot_lagrange = T(0);
    return r;
  }
  // The couple: J_w^T Gamma = (0, 0, H) in Cotton's speeds (wrench.hpp).
  vector_t<T> v(3), vdot(3), generalized(3);
  v << s.theta_dot, s.phi_dot, T(0);
  vdot << r.theta_ddot, r.phi_ddot, T(0);
  generalized << T(0), T(0), T(1);  // the couple is linear in H: solve for H = 1, scale once (H enters one product, not a cancellation)
  const auto kin = differentiate_kinematics(sys, q, v, t);
  r.couple = mat_vec(heavy_top_resal<T, Angles>::axes(q), constraint_couple(kin[0], generalized)) * r.H;  // fixed axes
  // Checks: eq. (4) and Lagrange's multiplier on the unconstrained top.
  const vector_t<T> ones = vector_t<T>::Ones(3);
  r.virtual_work_residual = virtual_work_residual(sys, r.cotton.equations, q, v, t, vdot, ones);
  vector_t<T> u(3);
  u << fp * s.theta_dot, s.theta_dot, s.phi_dot;
  const constrained_motion<T> lag = lagrange_multipliers(top, cone_constraint<Cone>{&cone}, q, u, t);
  r.lagrange_multiplier = lag.reactions(0);
  r.theta_ddot_lagrange = lag.accelerations(1);
  return r;
}

}  // namespace appell
