// Scene model "top_on_cone": schema and validation on exact decimals (SCENES.md), and its registry entry.
#include "appell/io/models/top_on_cone.hpp"

#include "appell/io/validate.hpp"

namespace appell {

top_on_cone_input top_on_cone_model::read(object_reader& scene) {
  top_on_cone_input in;
  object_reader top = scene.object("top");
  in.A = top.number("A");
  in.C = top.number("C");
  in.mass = top.number("mass");
  in.l = top.number("l");
  top.finish();
  require_positive(top, "A", in.A);
  require_positive(top, "C", in.C);
  require_positive(top, "mass", in.mass);
  // A >= m l^2 and C <= 2 (A - m l^2), exactly.
  if (decimal_sign_of_polynomial({{1, {in.A.text}}, {-1, {in.mass.text, in.l.text, in.l.text}}}) < 0)
    throw input_error(top.path("A") + ": a body of revolution has A >= m l^2 (A = " + in.A.text + ", m l^2 = " +
                      in.mass.text + " * " + in.l.text + "^2)");
  if (decimal_sign_of_polynomial({{2, {in.A.text}}, {-2, {in.mass.text, in.l.text, in.l.text}}, {-1, {in.C.text}}}) < 0)
    throw input_error(top.path("C") + ": a body of revolution has C <= 2 (A - m l^2) (C = " + in.C.text + ")");
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
  // Angles beyond 2^40 rad are no physical state, and their sines cost time in
  // the exponent (MPFR, MPFI) or lose every digit (QD): refused, exactly.
  for (const auto& [key, d] : {std::pair<const char*, const decimal_field*>{"theta", &in.theta}, {"phi", &in.phi}})
    if (decimal_sign_of_sum({{1, d->text}, {-1, "1099511627776"}}) > 0 ||
        decimal_sign_of_sum({{1, d->text}, {1, "1099511627776"}}) < 0)
      throw input_error(state.path(key) + ": an angle beyond 2^40 rad, got " + printable(d->text));
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
