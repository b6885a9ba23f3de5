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
  template <Scalar T>
  static evaluation<T> compute(const prepared<T>& m) {
    const euler_body_result<T> r = euler_body_motion(m.body, m.omega);
    evaluation<T> e;
    e.results.push_back(detail::vector_result("omega_dot", r.omega_dot));
    e.checks.push_back(detail::scalar_result("virtual_work_invariant", r.virtual_work_residual));
    e.checks.push_back(detail::scalar_result("power_balance", r.power_residual));
    return e;
  }
};

APPELL_EXTERN_MODEL(euler_body_model)

}  // namespace appell
