// appell/io/models/euler_body_motion.hpp -- how "euler_body" moves (io/model_motion.hpp):
// omega = (p, q, r) on the principal axes, Euler's equations (ode/problems.hpp).
#pragma once

#include <utility>

#include "appell/io/model_motion.hpp"
#include "appell/io/models/euler_body.hpp"
#include "appell/ode/closed_forms.hpp"
#include "appell/ode/problems.hpp"

namespace appell {

template <>
struct model_motion<euler_body_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  static std::pair<ode::euler_body_problem<T>, vector_t<T>> start(const euler_body_model::prepared<T>& m) {
    return {ode::euler_body_problem<T>{m.body}, vector_t<T>(m.omega)};
  }
  static std::vector<std::string> state_fields(const euler_body_input&) { return {"omega[0]", "omega[1]", "omega[2]"}; }
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
