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
// registry entry are in src/models/top_on_cone.cpp; the physics is the paper's (scenes/top_on_cone.hpp).
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/models/heavy_top.hpp"  // its problem, detail::write_top_accelerations
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scenes/top_on_cone.hpp"

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 4> top_on_cone_state_table{{
    {"theta", "theta"},
    {"phi", "phi"},
    {"theta_dot", "theta_dot"},
    {"phi_dot", "phi_dot"},
}};

}  // namespace appell

namespace appell::ode {

/// Example I, the heavy top forced onto the cone psi = f(theta): x = (theta, phi, theta', phi').
template <Scalar T>
struct top_on_cone_problem {
  heavy_top<T> top;
  expression_cone<T> cone;
  static constexpr int dim = 4;
  static std::vector<std::string> state_names() { return state_names_of(top_on_cone_state_table); }

  template <class S>
  heavy_top<S> top_in() const {
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
    out.push_back({"psi", {cone.psi(x(0))}});
    out.push_back({"psi_dot", {cone.fprime(x(0)) * x(2)}});
    out.push_back({"theta_ddot", {r.theta_ddot}});
    out.push_back({"phi_ddot", {r.phi_ddot}});
    out.push_back({"psi_ddot", {r.psi_ddot}});
    out.push_back({"H", {r.H}});
  }
  /// The energy: the cone is fixed and frictionless, so its couple does no work; the top's
  /// energy is heavy_top_problem's at (psi, theta, phi, f'(theta) theta', theta', phi').
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const;
};

template <Scalar T>
template <class S>
void top_on_cone_problem<T>::invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
  const heavy_top_problem<T> free_top{top.A, top.C, top.mass, top.l, top.g};
  vector_t<S> y(6);
  y << cone.psi(x(0)), x(0), x(1), S(cone.fprime(x(0)) * x(2)), x(2), x(3);
  std::vector<named_values<S>> all;
  free_top.invariants(y, all);
  out.push_back(all.front());  // the energy (the momenta are not conserved: the cone's couple)
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
    heavy_top<T> top;
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
    detail::write_top_accelerations(out, r.theta_ddot, r.phi_ddot, r.psi_ddot);
    out.scalar(W::results, "H", "", r.H);
    out.vector(W::results, "couple", "", r.couple);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.scalar(W::checks, "cotton_minus_lagrange", "", T(r.H - r.lagrange_multiplier));
    out.scalar(W::checks, "theta_ddot_cotton_minus_lagrange", "", T(r.theta_ddot - r.theta_ddot_lagrange));
    out.scalar(W::derived, "psi", "", s.psi);
    out.scalar(W::derived, "psi_dot", "", T(m.cone.fprime(m.theta) * m.theta_dot));
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
