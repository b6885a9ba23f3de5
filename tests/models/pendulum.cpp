// Scene model "pendulum" (tests/models/pendulum.hpp): schema and validation on exact decimals,
// and its registry entry.
#include "pendulum.hpp"

#include "appell/io/validate.hpp"

namespace appell {

pendulum_input pendulum_model::read(object_reader& scene) {
  pendulum_input in;
  object_reader p = scene.object("pendulum");
  in.mass = p.number("mass");
  in.length = p.number("length");
  p.finish();
  require_positive(p, "mass", in.mass);
  require_positive(p, "length", in.length);
  in.gravity = scene.number("gravity");
  object_reader state = scene.object("state");
  in.theta = state.number("theta");
  in.theta_dot = state.number("theta_dot");
  state.finish();
  return in;
}

APPELL_DEFINE_MODEL_ENTRY(pendulum_model)

}  // namespace appell
