// appell/io/models/euler_body.hpp -- the scene model "euler_body" (paper sec. 3).
// Schema (SCENES.md): inertia {A, B, C} (positive, triangle inequalities),
// torque [L, M, N] (default 0), state {omega: [p, q, r]}.
#pragma once

#include "appell/io/model.hpp"
#include "appell/scenes/euler_body.hpp"

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
