// appell/io/models/top_on_cone.hpp -- the scene model "top_on_cone" (paper
// sec. 6, Example I).  Schema (SCENES.md): top {A, C, mass, l} (A >= m l^2,
// C <= 2 (A - m l^2)), gravity, cone (an expression in theta: psi = f(theta)),
// state {theta, phi, theta_dot, phi_dot}.
#pragma once

#include <memory>
#include <string>

#include "appell/io/model.hpp"
#include "appell/io/models/heavy_top.hpp"  // detail::write_top_accelerations
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
