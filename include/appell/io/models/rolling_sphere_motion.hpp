// appell/io/models/rolling_sphere_motion.hpp -- how "rolling_sphere" moves
// (io/model_motion.hpp): the centre and omega on the fixed axes (ode/problems.hpp).
#pragma once

#include <utility>

#include "appell/io/model_motion.hpp"
#include "appell/io/models/rolling_sphere.hpp"
#include "appell/ode/problems.hpp"

namespace appell {

template <>
struct model_motion<rolling_sphere_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  static std::pair<ode::rolling_sphere_problem<T>, vector_t<T>> start(const rolling_sphere_model::prepared<T>& m) {
    vector_t<T> x0(6);
    x0 << m.c(0), m.c(1), m.c(2), m.omega(0), m.omega(1), m.omega(2);
    ode::rolling_sphere_problem<T> p{m.M, m.A, m.a, m.surface, m.F, m.tau};
    p.contact = m.contact;
    p.mu = m.mu;
    p.A_from_radius = m.A_from_radius;
    return {std::move(p), x0};
  }
  static std::vector<std::string> state_fields(const rolling_sphere_input&) {
    return {"center[0]", "center[1]", "center[2]", "omega[0]", "omega[1]", "omega[2]"};
  }
};

}  // namespace appell
