// appell/io/models/heavy_top.hpp -- the scene model "heavy_top": a heavy
// symmetric top on a fixed point O of its axis, no cone (the classical
// benchmark), with the pivot's force.  Schema (SCENES.md): top {A, C, mass, l}
// (A about O; A >= m l^2, C <= 2 (A - m l^2)), gravity, state {psi, theta, phi,
// psi_dot, theta_dot, phi_dot} (theta != 0).
#pragma once

#include "appell/io/model.hpp"
#include "appell/scenes/heavy_top.hpp"

namespace appell {

struct heavy_top_input : model_input {
  decimal_field A, C, mass, l, gravity;
  decimal_field psi, theta, phi, psi_dot, theta_dot, phi_dot;
};

struct heavy_top_model {
  static constexpr const char* name = "heavy_top";
  using input = heavy_top_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    T A, C, mass, l, g;
    top_on_pivot_state<T> state;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity),
            {value<T>(in.psi), value<T>(in.theta), value<T>(in.phi), value<T>(in.psi_dot), value<T>(in.theta_dot),
             value<T>(in.phi_dot)}};
  }
  template <Scalar T>
  static evaluation<T> compute(const prepared<T>& m) {
    const top_on_pivot_result<T> r = top_on_pivot_motion(m.A, m.C, m.mass, m.l, m.g, m.state);
    evaluation<T> e;
    e.results.push_back(detail::scalar_result("theta_ddot", r.theta_ddot));
    e.results.push_back(detail::scalar_result("phi_ddot", r.phi_ddot));
    e.results.push_back(detail::scalar_result("psi_ddot", r.psi_ddot));
    e.results.push_back(detail::vector_result("pivot_force", r.pivot_force));
    e.checks.push_back(detail::scalar_result("virtual_work_invariant", r.virtual_work_residual));
    e.checks.push_back(detail::vector_result("pivot_force_cotton_minus_lagrange",
                                             vec3<T>(r.pivot_force - r.pivot_force_lagrange)));
    e.checks.push_back(detail::scalar_result("theta_ddot_cotton_minus_lagrange", T(r.theta_ddot - r.theta_ddot_lagrange)));
    e.checks.push_back(detail::scalar_result("phi_ddot_cotton_minus_lagrange", T(r.phi_ddot - r.phi_ddot_lagrange)));
    e.checks.push_back(detail::scalar_result("psi_ddot_cotton_minus_lagrange", T(r.psi_ddot - r.psi_ddot_lagrange)));
    return e;
  }
};

APPELL_EXTERN_MODEL(heavy_top_model)

}  // namespace appell
