// Scene model "rolling_sphere": schema and validation on exact decimals (SCENES.md), and its registry entry.
#include "appell/models/rolling_sphere.hpp"

#include "appell/io/validate.hpp"

namespace appell {

rolling_sphere_input rolling_sphere_model::read(object_reader& scene) {
  rolling_sphere_input in;
  object_reader sphere = scene.object("sphere");
  in.mass = sphere.number("mass");
  in.radius = sphere.number("radius");
  if (sphere.has("A")) in.A = sphere.number("A");
  sphere.finish();
  require_positive(sphere, "mass", in.mass);
  require_positive(sphere, "radius", in.radius);
  if (in.A) {
    require_positive(sphere, "A", *in.A);
    // A <= 2/3 M a^2: the thin spherical shell is the largest.
    if (decimal_sign_of_polynomial({{3, {in.A->text}}, {-2, {in.mass.text, in.radius.text, in.radius.text}}}) > 0)
      throw input_error(sphere.path("A") + ": a sphere has A <= 2/3 M a^2 (the thin shell), got " + in.A->text);
  }
  object_reader surface = scene.object("surface");
  const std::string type = surface.string("type");
  if (type == "plane") {
    in.surface = surface_type::plane;
  } else if (type == "sphere" || type == "cylinder") {
    in.surface = type == "sphere" ? surface_type::sphere : surface_type::cylinder;
    in.b = surface.number("radius");
    require_positive(surface, "radius", *in.b);
    const std::string side = surface.string("side");
    if (side != "outside" && side != "inside")
      throw input_error(surface.path("side") + ": expected \"outside\" or \"inside\", got \"" + side + "\"");
    in.inside = side == "inside";
    if (in.inside && decimal_sign_of_sum({{1, in.b->text}, {-1, in.radius.text}}) <= 0)
      throw input_error(surface.path("radius") + ": the sphere (radius " + in.radius.text +
                        ") does not fit inside the " + type + " (radius " + in.b->text + ")");
  } else {
    throw input_error(surface.path("type") + ": unknown surface '" + type + "' (known: plane, sphere, cylinder)");
  }
  surface.finish();
  in.gravity = scene.numbers("gravity", 3);
  const std::vector<decimal_field> zero{{"0", "0"}, {"0", "0"}, {"0", "0"}};
  in.force = scene.has("force") ? scene.numbers("force", 3) : zero;
  in.torque = scene.has("torque") ? scene.numbers("torque", 3) : zero;
  if (scene.has("project")) {
    in.project = scene.number("project");
    require_positive(scene, "project", *in.project, "a tolerance");
  }
  if (scene.has("contact")) {  // the contact with the surface judged (SCENES.md)
    object_reader contact = scene.object("contact");
    in.contact = true;
    if (contact.has("mu")) {
      const decimal_field mu = contact.number("mu");
      if (decimal_sign_of_sum({{1, mu.text}}) < 0)
        throw input_error(contact.path("mu") + ": a friction coefficient must not be negative, got " + mu.text);
      in.mu = mu.text;
    }
    contact.finish();
  }
  object_reader state = scene.object("state");
  in.center = state.numbers("center", 3);
  in.omega = state.numbers("omega", 3);
  state.finish();
  return in;
}

APPELL_DEFINE_MODEL_ENTRY(rolling_sphere_model)

}  // namespace appell
