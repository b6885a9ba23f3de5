// appell/scenes/top_on_cone.hpp -- paper sec. 6, Example I: a heavy symmetric
// top on a fixed point O of its axis, the axis forced onto the cone psi = f(theta).
//
// The top, its Euler angles z-x-z and its body: heavy_top.hpp (heavy_top, heavy_top_resal).
//
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
// Angles: euler_angles or half_angle_tangents (heavy_top.hpp).
// A cone is any type with `S fprime(const S& theta_coordinate)` (also on dual
// numbers) and `T fsecond(const T& theta_coordinate)`: f'(theta) and f''(theta).
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/expr/expression.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include "appell/scenes/heavy_top.hpp"  // the top's body: heavy_top, heavy_top_resal

namespace appell {

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
  /// The same into u (its storage reused).
  template <class S>
  void apply_into(const vector_t<S>& q, const vector_t<S>& v, const S&, vector_t<S>& u) const {
    u.resize(3);
    u(0) = v(2) + cone->fprime(q(1)) * v(0);
    u(1) = v(0);
    u(2) = v(1);
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
/// need (the model's problem, models/<name>.hpp); top_on_cone_motion adds the couple and the checks.
template <Scalar T, class Angles, class Cone>
cotton_result<T> top_on_cone_cotton(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_reactions(sys, q, v_a, T(0), 1);
  });
}

/// top_on_cone_cotton's (theta'', phi'') alone, bit for bit, without H: the right-hand side of
/// the motion (the model's problem, models/<name>.hpp).
template <Scalar T, class Angles, class Cone>
vector_t<T> top_on_cone_accelerations(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_free_accelerations<3>(sys, q, v_a, T(0), 1);
  });
}

/// Without `couple_and_checks` only the accelerations and H are formed (couple, eq. (4) and
/// Lagrange's check left 0): the motion over time (the model's problem, models/<name>.hpp) encloses them over a whole
/// step, where the couple's 3 x 3 solve over the step's box need not be certifiable.
template <Scalar T, class Angles, class Cone>
void top_on_cone_motion_into(const heavy_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s,
                             bool couple_and_checks, top_on_cone_result<T>& r) {
  const T t = T(0);
  const T fp = cone.fprime(s.theta), fpp = cone.fsecond(s.theta);
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q_held, v_a;
  vector_t<T>& q = *q_held;
  q.resize(3);
  q << s.psi, s.theta, s.phi;
  const heavy_top_resal<T, Angles> resal{top.A, top.C, top.mass, top.l, top.g};
  const auto sys = change_speeds(resal, cone_speeds<Cone>{&cone}, 3);
  v_a->resize(2);
  *v_a << s.theta_dot, s.phi_dot;
  cotton_reactions_into(sys, q, *v_a, t, 1, r.cotton);  // top_on_cone_cotton
  r.theta_ddot = r.cotton.free_accelerations(0);
  r.phi_ddot = r.cotton.free_accelerations(1);
  r.H = r.cotton.reactions(0);
  r.psi_ddot = fpp * s.theta_dot * s.theta_dot + fp * r.theta_ddot;  // d/dt (f'(theta) theta')
  if (!couple_and_checks) {
    r.couple = vec3<T>(T(0), T(0), T(0));
    r.virtual_work_residual = r.lagrange_multiplier = r.theta_ddot_lagrange = T(0);
    return;
  }
  // The couple: J_w^T Gamma = (0, 0, H) in Cotton's speeds (wrench.hpp).
  const scratch<vector_t<T>, site> v_held, vdot_held, generalized_held, u_held, ones;
  vector_t<T>&v = *v_held, &vdot = *vdot_held, &generalized = *generalized_held, &u = *u_held;
  v.resize(3), vdot.resize(3), generalized.resize(3), u.resize(3);
  v << s.theta_dot, s.phi_dot, T(0);
  vdot << r.theta_ddot, r.phi_ddot, T(0);
  generalized << T(0), T(0), T(1);  // the couple is linear in H: solve for H = 1, scale once (H enters one product, not a cancellation)
  const scratch<std::vector<body_kinematics<T>>, site> kin;
  differentiate_kinematics_into(sys, q, v, t, *kin);
  r.couple = mat_vec(heavy_top_resal<T, Angles>::axes(q), constraint_couple((*kin)[0], generalized)) * r.H;  // fixed axes
  // Checks: eq. (4) and Lagrange's multiplier on the unconstrained top.
  ones->setOnes(3);
  r.virtual_work_residual = virtual_work_residual(sys, r.cotton.equations, q, v, t, vdot, *ones);
  u << fp * s.theta_dot, s.theta_dot, s.phi_dot;
  const scratch<constrained_motion<T>, site> lag;
  lagrange_multipliers_into(top, cone_constraint<Cone>{&cone}, q, u, t, *lag);
  r.lagrange_multiplier = lag->reactions(0);
  r.theta_ddot_lagrange = lag->accelerations(1);
}
/// The same returned.
template <Scalar T, class Angles, class Cone>
top_on_cone_result<T> top_on_cone_motion(const heavy_top<T, Angles>& top, const Cone& cone,
                                         const top_on_cone_state<T>& s, bool couple_and_checks = true) {
  top_on_cone_result<T> r;
  top_on_cone_motion_into(top, cone, s, couple_and_checks, r);
  return r;
}

}  // namespace appell
