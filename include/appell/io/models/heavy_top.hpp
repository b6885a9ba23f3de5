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

namespace detail {
/// The top's angular accelerations, as the heavy top and Example I (top_on_cone) name them.
template <Scalar T>
void write_top_accelerations(evaluation_writer<T>& out, const T& theta_ddot, const T& phi_ddot, const T& psi_ddot) {
  using W = evaluation_writer<T>;
  out.scalar(W::results, "theta_ddot", "", theta_ddot);
  out.scalar(W::results, "phi_ddot", "", phi_ddot);
  out.scalar(W::results, "psi_ddot", "", psi_ddot);
}
}  // namespace detail

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
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const top_on_pivot_result<T> r = top_on_pivot_motion(m.A, m.C, m.mass, m.l, m.g, m.state);
    using W = evaluation_writer<T>;
    W out(e);
    detail::write_top_accelerations(out, r.theta_ddot, r.phi_ddot, r.psi_ddot);
    out.vector(W::results, "pivot_force", "", r.pivot_force);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.vector(W::checks, "pivot_force_cotton_minus_lagrange", "", vec3<T>(r.pivot_force - r.pivot_force_lagrange));
    out.scalar(W::checks, "theta_ddot_cotton_minus_lagrange", "", T(r.theta_ddot - r.theta_ddot_lagrange));
    out.scalar(W::checks, "phi_ddot_cotton_minus_lagrange", "", T(r.phi_ddot - r.phi_ddot_lagrange));
    out.scalar(W::checks, "psi_ddot_cotton_minus_lagrange", "", T(r.psi_ddot - r.psi_ddot_lagrange));
    out.finish();
  }
};

APPELL_EXTERN_MODEL(heavy_top_model)

}  // namespace appell
