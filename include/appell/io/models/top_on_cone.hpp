// appell/io/models/top_on_cone.hpp -- the scene model "top_on_cone" (paper
// sec. 6, Example I).  Schema (SCENES.md): top {A, C, mass, l} (A >= m l^2,
// C <= 2 (A - m l^2)), gravity, cone (an expression in theta: psi = f(theta)),
// state {theta, phi, theta_dot, phi_dot}.
#pragma once

#include <memory>
#include <string>

#include "appell/io/model.hpp"
#include "appell/scenes/top_on_cone.hpp"

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
  template <Scalar T>
  static evaluation<T> compute(const prepared<T>& m) {
    const top_on_cone_state<T> s{m.cone.psi(m.theta), m.theta, m.phi, m.theta_dot, m.phi_dot};
    const top_on_cone_result<T> r = top_on_cone_motion(m.top, m.cone, s);
    evaluation<T> e;
    e.results.push_back(detail::scalar_result("theta_ddot", r.theta_ddot));
    e.results.push_back(detail::scalar_result("phi_ddot", r.phi_ddot));
    e.results.push_back(detail::scalar_result("psi_ddot", r.psi_ddot));
    e.results.push_back(detail::scalar_result("H", r.H));
    e.results.push_back(detail::vector_result("couple", r.couple));
    e.checks.push_back(detail::scalar_result("virtual_work_invariant", r.virtual_work_residual));
    e.checks.push_back(detail::scalar_result("cotton_minus_lagrange", T(r.H - r.lagrange_multiplier)));
    e.checks.push_back(detail::scalar_result("theta_ddot_cotton_minus_lagrange", T(r.theta_ddot - r.theta_ddot_lagrange)));
    e.derived.push_back(detail::scalar_result("psi", s.psi));
    e.derived.push_back(detail::scalar_result("psi_dot", T(m.cone.fprime(m.theta) * m.theta_dot)));
    return e;
  }
};

APPELL_EXTERN_MODEL(top_on_cone_model)

}  // namespace appell
