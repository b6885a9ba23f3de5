// appell/models/euler_body.hpp -- the home of the scene model "euler_body" (paper sec. 3).
// Schema (SCENES.md): inertia {A, B, C} (positive, triangle inequalities),
// torque [L, M, N] (default 0), state {omega: [p, q, r]}.
//
// It moves as omega = (p, q, r) on the principal axes, by Euler's equations
// (ode::euler_body_problem); without torque, some scenes in closed form (horizon's truth).
//
// Everything named after the model is here: its state table (the motion's state: each
// component's name in the outputs and the scene field it starts from), its motion as an ODE
// problem (right-hand side, results and invariants along the motion), its inputs, prepare and
// evaluation with its results' names, and model_motion (start, closed form).  Its reader and
// registry entry are in src/models/euler_body.cpp; the physics is the paper's (scenes/euler_body.hpp).
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/closed_forms.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scenes/euler_body.hpp"

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 3> euler_body_state_table{{
    {"p", "omega[0]"},
    {"q", "omega[1]"},
    {"r", "omega[2]"},
}};

}  // namespace appell

namespace appell::ode {

/// Euler's body (paper sec. 3): x = omega = (p, q, r) on the principal axes.
template <Scalar T>
struct euler_body_problem {
  euler_body<T> body;
  static constexpr int dim = 3;
  static std::vector<std::string> state_names() { return state_names_of(euler_body_state_table); }

  template <class S>
  euler_body<S> body_in() const {
    return {vec3<S>(S(body.inertia(0)), S(body.inertia(1)), S(body.inertia(2))),
            vec3<S>(S(body.torque(0)), S(body.torque(1)), S(body.torque(2)))};
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    return euler_body_equations(body_in<S>(), vec3<S>(x(0), x(1), x(2))).accelerations();
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const vector_t<S> w = rhs(x);
    out.push_back({"omega_dot", {w(0), w(1), w(2)}});
  }
  /// Without torque: the kinetic energy 1/2 omega.I omega and |I omega|^2 (Euler's two integrals).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    if (!torque_free()) return;
    S e = S(0), l2 = S(0);
    for (int i = 0; i < 3; ++i) {
      const S Ii = S(body.inertia(i));
      e += Ii * x(i) * x(i);
      l2 += Ii * Ii * x(i) * x(i);
    }
    out.push_back({"energy", {e / S(2)}});
    out.push_back({"angular_momentum_squared", {l2}});
  }
  bool torque_free() const {
    for (int i = 0; i < 3; ++i)
      if (!exactly_zero(body.torque(i))) return false;
    return true;
  }
};

}  // namespace appell::ode

namespace appell {

struct euler_body_input : model_input {
  std::vector<decimal_field> inertia;  // A, B, C
  std::vector<decimal_field> torque;   // L, M, N
  std::vector<decimal_field> omega;    // p, q, r
};

struct euler_body_model {
  static constexpr const char* name = "euler_body";
  using input = euler_body_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    euler_body<T> body;
    vec3<T> omega;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {{detail::vec3_from_decimals<T>(in.inertia), detail::vec3_from_decimals<T>(in.torque)},
            detail::vec3_from_decimals<T>(in.omega)};
  }
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const euler_body_result<T> r = euler_body_motion(m.body, m.omega);
    using W = evaluation_writer<T>;
    W out(e);
    out.vector(W::results, "omega_dot", "", r.omega_dot);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.scalar(W::checks, "power_balance", "", r.power_residual);
    out.finish();
  }
};

APPELL_EXTERN_MODEL(euler_body_model)

}  // namespace appell

namespace appell {

template <>
struct model_motion<euler_body_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::euler_body_problem<T>;
  template <Scalar T>
  static std::pair<ode::euler_body_problem<T>, vector_t<T>> start(const euler_body_model::prepared<T>& m) {
    return {ode::euler_body_problem<T>{m.body}, vector_t<T>(m.omega)};
  }
  static std::vector<std::string> state_fields(const euler_body_input&) { return state_fields_of(euler_body_state_table); }
  /// Without torque, I1 < I2 < I3 and omega(0) = (a, 0, c) with M^2 > 2 E I2: omega in Jacobi
  /// elliptic functions (ode/closed_forms.hpp).
  static std::optional<motion_closed_form> closed_form(const euler_body_input& in) {
    using R = motion_closed_form::value;
    for (const auto& f : in.torque)
      if (R(f.text) != 0) return std::nullopt;
    const R I1(in.inertia[0].text), I2(in.inertia[1].text), I3(in.inertia[2].text);
    const R a(in.omega[0].text), b(in.omega[1].text), c(in.omega[2].text);
    if (b != 0 || !ode::euler_free_body_solution<R>::applies(I1, I2, I3, a, c)) return std::nullopt;
    const ode::euler_free_body_solution<R> sol(I1, I2, I3, a, c);
    return motion_closed_form{"closed form (Jacobi elliptic functions, MPFR 256 bits)", {0, 1, 2}, sol.period(),
                              [sol](const R& t) {
                                const auto w = sol.at(t);
                                return std::vector<R>(w.begin(), w.end());
                              }};
  }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::euler_body_model)
