// appell/io/models/top_on_cone_motion.hpp -- how "top_on_cone" moves (io/model_motion.hpp):
// x = (theta, phi, theta', phi'), psi = f(theta) (ode/problems.hpp).
#pragma once

#include <utility>

#include "appell/io/model_motion.hpp"
#include "appell/io/models/top_on_cone.hpp"
#include "appell/ode/problems.hpp"

namespace appell {

template <>
struct model_motion<top_on_cone_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  static std::pair<ode::top_on_cone_problem<T>, vector_t<T>> start(const top_on_cone_model::prepared<T>& m) {
    vector_t<T> x0(4);
    x0 << m.theta, m.phi, m.theta_dot, m.phi_dot;
    return {ode::top_on_cone_problem<T>{m.top, m.cone}, x0};
  }
  static std::vector<std::string> state_fields(const top_on_cone_input&) {
    return {"theta", "phi", "theta_dot", "phi_dot"};
  }
};

}  // namespace appell
