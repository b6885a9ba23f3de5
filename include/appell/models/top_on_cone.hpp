// appell/models/top_on_cone.hpp -- the home of the scene model "top_on_cone" (paper
// sec. 6, Example I).  Schema (SCENES.md): top {A, C, mass, l} (A >= m l^2,
// C <= 2 (A - m l^2)), gravity, cone (an expression in theta: psi = f(theta)),
// state {theta, phi, theta_dot, phi_dot}.
//
// It moves as x = (theta, phi, theta', phi'), psi = f(theta) (ode::top_on_cone_problem).
//
// Everything named after the model is here: its state table (the motion's state: each
// component's name in the outputs and the scene field it starts from), its motion as an ODE
// problem (right-hand side, results and invariants along the motion), its inputs, prepare and
// evaluation with its results' names, and model_motion (start, closed form).  Its reader and
// registry entry are in src/models/top_on_cone.cpp.
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
//
// The physics: a heavy symmetric top on a fixed point O of its axis, the axis forced onto the
// cone psi = f(theta).  The top, its Euler angles z-x-z and its body: dynamics/symmetric_top.hpp
// (symmetric_top, symmetric_top_resal).
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
// Angles: euler_angles or half_angle_tangents (symmetric_top.hpp).
// A cone is any type with `S fprime(const S& theta_coordinate)` (also on dual
// numbers) and `T fsecond(const T& theta_coordinate)`: f'(theta) and f''(theta).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/symmetric_top.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/expr/expression.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include "appell/scalar/decimal.hpp"

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
auto on_cone_speeds(const symmetric_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s, F&& f) {
  vector_t<T> q(3);
  q << s.psi, s.theta, s.phi;
  const symmetric_top_resal<T, Angles> resal{top.A, top.C, top.mass, top.l, top.g};
  const auto sys = change_speeds(resal, cone_speeds<Cone>{&cone}, 3);
  vector_t<T> v_a(2);
  v_a << s.theta_dot, s.phi_dot;
  return f(sys, q, v_a);
}
}  // namespace detail

/// Cotton's method alone (the accelerations theta'', phi'' and H): what the motion's results
/// need (the model's problem, models/<name>.hpp); top_on_cone_motion adds the couple and the checks.
template <Scalar T, class Angles, class Cone>
cotton_result<T> top_on_cone_cotton(const symmetric_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_reactions(sys, q, v_a, T(0), 1);
  });
}

/// top_on_cone_cotton's (theta'', phi'') alone, bit for bit, without H: the right-hand side of
/// the motion (the model's problem, models/<name>.hpp).
template <Scalar T, class Angles, class Cone>
vector_t<T> top_on_cone_accelerations(const symmetric_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s) {
  return detail::on_cone_speeds(top, cone, s, [](const auto& sys, const vector_t<T>& q, const vector_t<T>& v_a) {
    return cotton_free_accelerations<3>(sys, q, v_a, T(0), 1);
  });
}

/// Without `couple_and_checks` only the accelerations and H are formed (couple, eq. (4) and
/// Lagrange's check left 0): the motion over time (the model's problem, models/<name>.hpp) encloses them over a whole
/// step, where the couple's 3 x 3 solve over the step's box need not be certifiable.
template <Scalar T, class Angles, class Cone>
void top_on_cone_motion_into(const symmetric_top<T, Angles>& top, const Cone& cone, const top_on_cone_state<T>& s,
                             bool couple_and_checks, top_on_cone_result<T>& r) {
  const T t = T(0);
  const T fp = cone.fprime(s.theta), fpp = cone.fsecond(s.theta);
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q_held, v_a;
  vector_t<T>& q = *q_held;
  q.resize(3);
  q << s.psi, s.theta, s.phi;
  const symmetric_top_resal<T, Angles> resal{top.A, top.C, top.mass, top.l, top.g};
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
  r.couple = mat_vec(symmetric_top_resal<T, Angles>::axes(q), constraint_couple((*kin)[0], generalized)) * r.H;  // fixed axes
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
top_on_cone_result<T> top_on_cone_motion(const symmetric_top<T, Angles>& top, const Cone& cone,
                                         const top_on_cone_state<T>& s, bool couple_and_checks = true) {
  top_on_cone_result<T> r;
  top_on_cone_motion_into(top, cone, s, couple_and_checks, r);
  return r;
}

/// top_on_cone_motion_into on the model's own top and cone (a scene's), compiled with the model
/// once per standard scalar (io/model.hpp).
#define APPELL_MODEL_PHYSICS_top_on_cone(EXTERN, T)                                                       \
  EXTERN template void top_on_cone_motion_into<T, euler_angles, expression_cone<T>>(                      \
      const symmetric_top<T, euler_angles>&, const expression_cone<T>&, const top_on_cone_state<T>&, bool, \
      top_on_cone_result<T>&);
APPELL_EXTERN_MODEL_PHYSICS(top_on_cone)

}  // namespace appell

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 4> top_on_cone_state_table{{
    {"theta", "theta"},
    {"phi", "phi"},
    {"theta_dot", "theta_dot"},
    {"phi_dot", "phi_dot"},
}};

/// The names eval, reference and the motion's outputs share, each written once.
struct top_on_cone_result_names {
  static constexpr const char* psi = "psi";  ///< the precession angle the cone imposes, psi = f(theta)
  static constexpr const char* psi_dot = "psi_dot";
  static constexpr const char* theta_ddot = "theta_ddot";
  static constexpr const char* phi_ddot = "phi_ddot";
  static constexpr const char* psi_ddot = "psi_ddot";
  static constexpr const char* H = "H";  ///< Cotton's reaction: the couple's component about the line of nodes
};

}  // namespace appell

namespace appell::ode {

/// Example I, the heavy top forced onto the cone psi = f(theta): x = (theta, phi, theta', phi').
template <Scalar T>
struct top_on_cone_problem {
  symmetric_top<T> top;
  expression_cone<T> cone;
  static constexpr int dim = 4;
  static std::vector<std::string> state_names() { return state_names_of(top_on_cone_state_table); }

  template <class S>
  symmetric_top<S> top_in() const {
    return {S(top.A), S(top.C), S(top.mass), S(top.l), S(top.g)};
  }
  template <class S>
  top_on_cone_state<S> state(const vector_t<S>& x) const {
    return {cone.psi(x(0)), x(0), x(1), x(2), x(3)};
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const vector_t<S> a = top_on_cone_accelerations(top_in<S>(), cone, state(x));  // without H
    vector_t<S> d(4);
    d << x(2), x(3), a(0), a(1);
    return d;
  }
  /// psi and psi' (the cone's), the accelerations and H (Cotton's reaction: the couple's moment
  /// about the vertical), as appell eval gives them.  Not the couple's three components: they
  /// come from a 3 x 3 solve whose matrix, over a whole step's box, is too wide to certify.
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const top_on_cone_result<S> r = top_on_cone_motion(top_in<S>(), cone, state(x), false);
    using name = top_on_cone_result_names;
    out.push_back({name::psi, {cone.psi(x(0))}});
    out.push_back({name::psi_dot, {cone.fprime(x(0)) * x(2)}});
    out.push_back({name::theta_ddot, {r.theta_ddot}});
    out.push_back({name::phi_ddot, {r.phi_ddot}});
    out.push_back({name::psi_ddot, {r.psi_ddot}});
    out.push_back({name::H, {r.H}});
  }
  /// The energy: the cone is fixed and frictionless, so its couple does no work; the top's
  /// energy (symmetric_top_energy) at psi' = f'(theta) theta'.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const;
};

template <Scalar T>
template <class S>
void top_on_cone_problem<T>::invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
  S st, ct;
  sin_cos(x(0), st, ct);
  // the energy alone (the momenta are not conserved: the cone's couple)
  out.push_back({"energy", {symmetric_top_energy(top.A, top.C, top.mass, top.g, top.l, st, ct, S(cone.fprime(x(0)) * x(2)), x(2), x(3))}});
}

}  // namespace appell::ode

namespace appell {

struct top_on_cone_input : model_input {
  decimal_field A, C, mass, l, gravity;
  std::string cone_text;
  std::shared_ptr<const expression> f, fprime, fsecond;  ///< f, f', f'' (symbolic)
  decimal_field theta, phi, theta_dot, phi_dot;
};

struct top_on_cone_model {
  static constexpr const char* name = "top_on_cone";
  using input = top_on_cone_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    symmetric_top<T> top;
    expression_cone<T> cone;
    T theta, phi, theta_dot, phi_dot;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)},
            {compiled_expression<T>(*in.f), compiled_expression<T>(*in.fprime), compiled_expression<T>(*in.fsecond)},
            value<T>(in.theta), value<T>(in.phi), value<T>(in.theta_dot), value<T>(in.phi_dot)};
  }
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const top_on_cone_state<T> s{m.cone.psi(m.theta), m.theta, m.phi, m.theta_dot, m.phi_dot};
    struct site;
    const scratch<top_on_cone_result<T>, site> r_held;  // borrowed (linalg/scratch.hpp)
    const top_on_cone_result<T>& r = *r_held;
    top_on_cone_motion_into(m.top, m.cone, s, true, *r_held);
    using W = evaluation_writer<T>;
    W out(e);
    using name = top_on_cone_result_names;
    out.scalar(W::results, name::theta_ddot, "", r.theta_ddot);
    out.scalar(W::results, name::phi_ddot, "", r.phi_ddot);
    out.scalar(W::results, name::psi_ddot, "", r.psi_ddot);
    out.scalar(W::results, name::H, "", r.H);
    out.vector(W::results, "couple", "", r.couple);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.scalar(W::checks, "cotton_minus_lagrange", "", T(r.H - r.lagrange_multiplier));
    out.scalar(W::checks, "theta_ddot_cotton_minus_lagrange", "", T(r.theta_ddot - r.theta_ddot_lagrange));
    out.scalar(W::derived, name::psi, "", s.psi);
    out.scalar(W::derived, name::psi_dot, "", T(m.cone.fprime(m.theta) * m.theta_dot));
    out.finish();
  }
};

APPELL_EXTERN_MODEL(top_on_cone_model)

}  // namespace appell

namespace appell {

template <>
struct model_motion<top_on_cone_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::top_on_cone_problem<T>;
  template <Scalar T>
  static std::pair<ode::top_on_cone_problem<T>, vector_t<T>> start(const top_on_cone_model::prepared<T>& m) {
    vector_t<T> x0(4);
    x0 << m.theta, m.phi, m.theta_dot, m.phi_dot;
    return {ode::top_on_cone_problem<T>{m.top, m.cone}, x0};
  }
  static std::vector<std::string> state_fields(const top_on_cone_input&) { return state_fields_of(top_on_cone_state_table); }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::top_on_cone_model)
