// Scene validation on exact decimals (SCENES.md).
#include "appell/io/scene.hpp"

#include <fstream>
#include <limits>
#include <sstream>

namespace appell {
namespace {

/// d > 0 exactly, or input_error naming the field ("WHAT must be positive").
void require_positive(const object_reader& r, const std::string& key, const decimal_field& d,
                      const std::string& what = "") {
  if (decimal_sign_of_sum({{1, d.text}}) <= 0)
    throw input_error(r.path(key) + ": " + (what.empty() ? "" : what + " ") + "must be positive, got " + d.text);
}

euler_body_input read_euler_body(object_reader& scene) {
  euler_body_input in;
  object_reader inertia = scene.object("inertia");
  in.inertia = {inertia.number("A"), inertia.number("B"), inertia.number("C")};
  inertia.finish();
  const char* names[3] = {"A", "B", "C"};
  for (int i = 0; i < 3; ++i) require_positive(inertia, names[i], in.inertia[i], "a principal moment");
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;  // moment k must not exceed the sum of the others
    if (decimal_sign_of_sum({{1, in.inertia[i].text}, {1, in.inertia[j].text}, {-1, in.inertia[k].text}}) < 0)
      throw input_error(inertia.path(names[k]) + ": violates the triangle inequality " + names[i] +
                        " + " + names[j] + " >= " + names[k] + " (" + in.inertia[i].text + " + " +
                        in.inertia[j].text + " < " + in.inertia[k].text + ")");
  }
  if (scene.has("torque")) {
    in.torque = scene.numbers("torque", 3);
  } else {  // default 0 (an if, not ?: with a braced list, which GCC 12 flags as maybe-uninitialized)
    for (const char* field : {"torque[0]", "torque[1]", "torque[2]"}) in.torque.push_back({"0", field});
  }
  object_reader state = scene.object("state");
  in.omega = state.numbers("omega", 3);
  state.finish();
  return in;
}

top_on_cone_input read_top_on_cone(object_reader& scene) {
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
  // The cone at the state, once, in 256-bit interval arithmetic: a division by
  // zero (or a log/sqrt outside its domain) at the exact state is bad input for
  // every scalar, even where a 53-bit enclosure could not tell it from a tiny
  // nonzero number.
  try {
    mp_precision_scope scope(256);
    const mpfi theta = value<mpfi>(in.theta);
    (void)in.f->eval(theta);
    (void)in.fprime->eval(theta);
    (void)in.fsecond->eval(theta);
  } catch (const certification_error& e) {
    throw input_error(std::string(e.what()) + " (within 2^-256 of it: taken as exact)");
  }
  return in;
}

rolling_sphere_input read_rolling_sphere(object_reader& scene) {
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
  object_reader state = scene.object("state");
  in.center = state.numbers("center", 3);
  in.omega = state.numbers("omega", 3);
  state.finish();
  return in;
}

}  // namespace

scene_input read_scene(const json_value& root) {
  object_reader scene(root, "");
  scene_input out;
  out.model = scene.string("model");
  if (out.model == "euler_body") {
    out.input = read_euler_body(scene);
  } else if (out.model == "top_on_cone") {
    out.input = read_top_on_cone(scene);
  } else if (out.model == "rolling_sphere") {
    out.input = read_rolling_sphere(scene);
  } else {
    throw input_error("model: unknown model '" + out.model + "' (known: euler_body, top_on_cone, rolling_sphere)");
  }
  scene.finish();
  return out;
}

double error_amplification(const scene_input& scene) {
  try {
    const evaluation<interval> e = compute<interval>(bind<interval>(scene));
    // relative widths of the components bounded away from 0 (a result that
    // may be 0 has no relative accuracy to lose); absolute ones if all may be 0
    double widest = 0, widest_abs = 0;
    bool any_nonzero = false;
    for (const auto& r : e.results)
      for (const interval& x : r.values) {
        const double w = boost::numeric::width(x);
        widest_abs = std::max(widest_abs, w);
        if (x.lower() > 0 || x.upper() < 0) {
          any_nonzero = true;
          widest = std::max(widest, w / std::min(std::abs(x.lower()), std::abs(x.upper())));
        }
      }
    return (any_nonzero ? widest : widest_abs) / std::ldexp(1.0, -53);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

scene_input read_scene_file(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw input_error(path + ": cannot read the scene file");
  std::ostringstream text;
  text << file.rdbuf();
  return read_scene(parse_json(text.str()));
}

}  // namespace appell
