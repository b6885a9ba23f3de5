// Scene model "heavy_top": schema and validation on exact decimals (SCENES.md), and its registry entry.
#include "appell/models/heavy_top.hpp"

#include "appell/io/validate.hpp"

namespace appell {

heavy_top_input heavy_top_model::read(object_reader& scene) {
  heavy_top_input in;
  const symmetric_top_fields top = read_symmetric_top(scene);
  in.A = top.A;
  in.C = top.C;
  in.mass = top.mass;
  in.l = top.l;
  in.gravity = scene.number("gravity");
  object_reader state = scene.object("state");
  in.psi = state.number("psi");
  in.theta = state.number("theta");
  in.phi = state.number("phi");
  in.psi_dot = state.number("psi_dot");
  in.theta_dot = state.number("theta_dot");
  in.phi_dot = state.number("phi_dot");
  state.finish();
  require_angle_in_range(state, "psi", in.psi);
  require_angle_in_range(state, "theta", in.theta);
  require_angle_in_range(state, "phi", in.phi);
  // sin(theta) = 0 only at theta = k pi; the only decimal among those is 0.
  if (decimal_sign_of_sum({{1, in.theta.text}}) == 0)
    throw input_error(state.path("theta") +
                      ": 0, the axis on the vertical, where Euler's angles are singular (psi and phi turn about the "
                      "same axis); tilt the axis or turn the frame");
  return in;
}

APPELL_DEFINE_MODEL_ENTRY(heavy_top_model)

}  // namespace appell
