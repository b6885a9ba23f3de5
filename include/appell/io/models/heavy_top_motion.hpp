// appell/io/models/heavy_top_motion.hpp -- how "heavy_top" moves (io/model_motion.hpp):
// integrated in Resal's speeds, x = (psi, theta, phi, theta', psi' sin theta, psi' cos theta + phi')
// (ode::heavy_top_resal_problem: M constant), reported as the scene's state (psi, theta, phi,
// psi', theta', phi').
#pragma once

#include <utility>

#include "appell/io/model_motion.hpp"
#include "appell/io/models/heavy_top.hpp"
#include "appell/ode/closed_forms.hpp"
#include "appell/ode/problems.hpp"

namespace appell {

template <>
struct model_motion<heavy_top_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  static std::pair<ode::heavy_top_resal_problem<T>, vector_t<T>> start(const heavy_top_model::prepared<T>& m) {
    vector_t<T> y(6);
    y << m.state.psi, m.state.theta, m.state.phi, m.state.psi_dot, m.state.theta_dot, m.state.phi_dot;
    return {ode::heavy_top_resal_problem<T>{m.A, m.C, m.mass, m.l, m.g}, ode::heavy_top_resal_problem<T>::from_euler_rates(y)};
  }
  static std::vector<std::string> state_fields(const heavy_top_input&) {
    return {"psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot"};
  }
  /// The nutation (theta, theta') in Jacobi elliptic functions (psi and phi would need elliptic
  /// integrals of the third kind); none without gravity or in steady precession.
  static std::optional<motion_closed_form> closed_form(const heavy_top_input& in) {
    using R = motion_closed_form::value;
    try {
      const ode::heavy_top_nutation<R> sol(R(in.A.text), R(in.C.text), R(in.mass.text) * R(in.gravity.text) * R(in.l.text),
                                           R(in.theta.text), R(in.psi_dot.text), R(in.theta_dot.text),
                                           R(in.phi_dot.text));
      return motion_closed_form{
          "closed form of the nutation (Jacobi elliptic functions, MPFR 256 bits; theta and theta' compared)",
          {1, 4},
          sol.period(),
          [sol](const R& t) {
            const auto w = sol.at(t);
            return std::vector<R>(w.begin(), w.end());
          }};
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // no gravity or a steady precession: the 256-bit simulate instead
    }
  }
};

}  // namespace appell
