// Scene model "top_on_cone": schema and validation on exact decimals (SCENES.md), and its registry entry.
#include "appell/models/top_on_cone.hpp"

#include "appell/io/validate.hpp"

namespace appell {

top_on_cone_input top_on_cone_model::read(object_reader& scene) {
  top_on_cone_input in;
  const symmetric_top_fields top = read_symmetric_top(scene);
  in.A = top.A;
  in.C = top.C;
  in.mass = top.mass;
  in.l = top.l;
  in.gravity = scene.number("gravity");
  in.cone_text = scene.string("cone");
  in.f = std::make_shared<expression>(expression::parse(in.cone_text, "theta", "cone"));
  in.fprime = std::make_shared<expression>(in.f->derivative());
  in.fsecond = std::make_shared<expression>(in.fprime->derivative());
  object_reader state = scene.object("state");
  in.theta = state.number("theta");
  in.phi = state.number("phi");
  in.theta_dot = state.number("theta_dot");
  in.phi_dot = state.number("phi_dot");
  state.finish();
  require_angle_in_range(state, "theta", in.theta);
  require_angle_in_range(state, "phi", in.phi);
  // The cone at the state, once, in 256-bit interval arithmetic: a division by
  // zero (or a log/sqrt outside its domain) at the exact state is bad input for
  // every scalar, even where a 53-bit enclosure could not tell it from a tiny
  // nonzero number.
  try {
    mp_precision_scope scope(256);
    const mpfi theta = value<mpfi>(in.theta);
    const mpfi psi = in.f->eval(theta);
    if (!(certainly_nonpositive(mpfi(psi - 1099511627776.0)) && certainly_nonnegative(mpfi(psi + 1099511627776.0))))
      throw input_error("cone: psi = f(theta) = " + to_string(psi) + " at the state, beyond 2^40 rad");
    (void)in.fprime->eval(theta);
    (void)in.fsecond->eval(theta);
  } catch (const certification_error& e) {
    throw input_error(std::string(e.what()) + " (within 2^-256 of it: taken as exact)");
  }
  return in;
}

APPELL_DEFINE_MODEL_ENTRY(top_on_cone_model)

}  // namespace appell
