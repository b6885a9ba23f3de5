// Scene model "system" (models/system.hpp): its reader, in named phases (SCENES.md in this
// repository), the 256-bit checks at the state, the projection ("project"), the report of
// `appell linearize`, and its registry entry.
//
// Everything that can be decided once is decided here, on the exact decimals:
// names (undefined, duplicate, reserved, circular parameters), what each
// expression may depend on (positions and angles on q and t; kinematics and
// nonholonomic constraints affine in u, checked on the derivatives' trees),
// and, in 256-bit interval arithmetic at the state, every expression and
// derivative defined, masses positive, inertia tensors positive semidefinite,
// the state on every constraint, and the constraints independent.  What
// 256 bits cannot tell from exact is taken as exact (as for the cone of
// Example I's built-in model); the scalar the user asks for certifies the rest.
#include "appell/models/system.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "appell/build_options.hpp"
#include "appell/io/json_text.hpp"
#include "appell/io/tables.hpp"
#include "appell/io/validate.hpp"
#include "appell/scalar/standard_scalars.hpp"

// The phases the reader calls before their definitions (below: the checks at the state, the
// projection), and what they share.
namespace appell::system_reading {

/// A short decimal of an enclosure's midpoint, for messages.
inline std::string short_text(const mpfi& x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", approx_double(x));
  return buf;
}

/// The sign of each link axis along a basis vector, and every axis not 0, at 256 bits.
void settle_link_axes(system_definition& def);

/// At the state, at 256 bits (below): everything the reader can decide there, the
/// projection ("project") applied first.  input_error naming the field otherwise.
void check_at_state(system_input& in);

/// The state replaced by its projection onto the constraints, read back into q and u at the
/// caller's precision, the moves checked against "project".
void project_state(system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u);

/// The linearization's reference motion: the state (the projected one, with "project") with
/// what "about" sets.
void set_reference_motion(linearize_input& li, const system_input& in);

}  // namespace appell::system_reading

namespace appell {
namespace system_reading {

const std::set<std::string>& reserved_names() {
  // coordinates_moved and speeds_moved: what a projected state's derived results add after the
  // coordinates' and speeds' names (models/system.hpp)
  static const std::set<std::string> r{"pi",   "t",  "sin", "cos", "tan", "exp", "log", "sqrt", "rx", "ry", "rz",
                                       "coordinates_moved", "speeds_moved"};
  return r;
}

bool is_identifier(const std::string& s) {
  if (s.empty() || s.size() > 64 || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string expression_text(const json_value& v, const std::string& path) {
  if (v.type == json_value::kind::string || v.type == json_value::kind::number) return v.text;
  throw input_error(path + ": expected an expression (a string) or a number");
}

std::vector<std::string> name_list(const json_value& v, const std::string& path) {
  if (v.type != json_value::kind::array) throw input_error(path + ": expected a list of names");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    const json_value& x = v.items[i];
    if (x.type != json_value::kind::string) throw input_error(path + "[" + std::to_string(i) + "]: expected a name");
    out.push_back(x.text);
  }
  return out;
}

const json_value& object_value(object_reader& r, const std::string& key) {
  const json_value& v = r.raw(key);
  if (v.type != json_value::kind::object) throw input_error(r.path(key) + ": expected an object");
  return v;
}

void require_at_most(std::size_t n, std::size_t limit, const std::string& what) {
  if (n > limit) throw input_error(what + ": more than " + std::to_string(limit) + " (" + std::to_string(n) + ")");
}

/// What a system file may hold (bounded time and memory on any input): more is bad input.
struct system_limits {
  static constexpr std::size_t names = 256;       ///< coordinates; speeds; bodies; constraints (each)
  static constexpr std::size_t rotations = 16;    ///< factors of one orientation
  static constexpr std::size_t operations = 200000;  ///< all expressions and derivatives, unfolded
};

class builder {
 public:
  system_definition def;
  std::size_t operations = 0;

  shared_expression count(shared_expression e) {
    operations += e->operations();
    if (operations > system_limits::operations)
      throw input_error(e->where() + ": the system's expressions and their derivatives exceed " +
                        std::to_string(system_limits::operations) + " operations (when unfolded)");
    return e;
  }
  /// An expression of the system's variables; `load`: an applied force, couple or effort, the
  /// only place a table may be called (SCENES.md, "tables").
  shared_expression parse(const std::string& text, const std::string& where, bool load = false) {
    expression_tables tables{&def.tables, def.vars.t(),
                             load ? std::string{}
                                  : "may be called in an applied force, couple or effort only (a position, a rate, a "
                                    "constraint or a parameter made of a table would have no derivative at its "
                                    "breakpoints)"};
    return count(std::make_shared<const expression>(expression::parse(text, def.names, where, tables)));
  }
  bool depends_on_range(const expression& e, int first, int last) const {
    for (int v = first; v < last; ++v)
      if (e.depends_on(v)) return true;
    return false;
  }
  bool depends_on_state(const expression& e) const { return depends_on_range(e, def.vars.parameters, def.vars.size()); }
  bool depends_on_speeds(const expression& e) const { return depends_on_range(e, def.vars.u(0), def.vars.t()); }
  shared_expression derivative(const expression& e, int variable) {
    auto d = std::make_shared<const expression>(e.derivative(variable));
    return d->is_zero() ? nullptr : count(d);
  }
  /// A function of (q, t) and its partial derivatives.
  differentiated_expression function_of_q_t(const std::string& text, const std::string& where) {
    differentiated_expression d;
    d.value = parse(text, where);
    if (depends_on_speeds(*d.value))
      throw input_error(where + ": depends on the speeds (a position, angle or holonomic constraint is a function of "
                                "the coordinates and t)");
    for (int i = 0; i < def.vars.coordinates; ++i)
      if (auto e = derivative(*d.value, def.vars.q(i))) d.dq.emplace_back(i, e);
    d.dt = derivative(*d.value, def.vars.t());
    return d;
  }
  /// A constant: parameters only.
  shared_expression constant(const std::string& text, const std::string& where) {
    auto e = parse(text, where);
    if (depends_on_state(*e)) throw input_error(where + ": must depend on the parameters only (not on q, u or t)");
    return e;
  }
  /// (j, d/du_j) of an expression affine in the speeds; input_error otherwise.
  std::vector<std::pair<int, shared_expression>> speed_coefficients(const expression& e, const std::string& where) {
    std::vector<std::pair<int, shared_expression>> out;
    for (int j = 0; j < def.vars.speeds; ++j)
      if (auto d = derivative(e, def.vars.u(j))) {
        if (depends_on_speeds(*d))
          throw input_error(where + ": not linear in the speeds (its derivative in " +
                            def.names[static_cast<std::size_t>(def.vars.u(j))] + " depends on the speeds)");
        out.emplace_back(j, d);
      }
    return out;
  }
};

/// What the reading phases share: the scene, the input being filled, the expressions' builder
/// (which holds the definition), and the names read first.
struct reading {
  object_reader& scene;
  system_input in{};
  builder b{};
  std::vector<std::string> coordinates{}, speeds{};
  std::vector<std::pair<std::string, std::string>> parameter_texts{};  ///< name, text
  std::vector<std::string> link_parents{};  ///< per body: its joint's parent as written ("" the ground)
  /// The definition read before for this scene's definition (definition_memo below); then the
  /// builder is empty and the state's phases read this one.
  std::shared_ptr<const system_definition> known{};
  const system_definition& definition() const { return known ? *known : b.def; }
};

/// "rz(psi) rx(theta) rz(phi)": elementary rotations, left to right.
std::vector<std::pair<int, std::string>> rotation_factors(const std::string& s, const std::string& where) {
  std::vector<std::pair<int, std::string>> out;
  std::size_t i = 0;
  auto skip = [&] {
    while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '*')) ++i;
  };
  skip();
  if (i == s.size()) throw input_error(where + ": empty (omit the field for a body that does not turn)");
  while (i < s.size()) {
    if (i + 2 >= s.size() || s[i] != 'r' || (s[i + 1] != 'x' && s[i + 1] != 'y' && s[i + 1] != 'z') || s[i + 2] != '(')
      throw input_error(where + ": expected rx(...), ry(...) or rz(...) at position " + std::to_string(i + 1) +
                        " of '" + printable(s) + "'");
    const int axis = s[i + 1] - 'x';
    std::size_t j = i + 3;
    int depth = 1;
    for (; j < s.size() && depth > 0; ++j) depth += s[j] == '(' ? 1 : s[j] == ')' ? -1 : 0;
    if (depth != 0) throw input_error(where + ": missing ')' in '" + printable(s) + "'");
    out.emplace_back(axis, s.substr(i + 3, j - 1 - (i + 3)));
    i = j;
    skip();
  }
  return out;
}

/// A body with its centre and orientation on the fixed axes, by name (for a point velocity, a
/// wrench): its index.
int body_on_fixed_axes(const system_definition& def, object_reader& r, const std::string& what) {
  const std::string body = r.string("body");
  const auto it = std::find_if(def.bodies.begin(), def.bodies.end(),
                               [&](const system_body_definition& x) { return x.name == body; });
  if (it == def.bodies.end()) throw input_error(r.path("body") + ": no body named '" + printable(body) + "'");
  if (it->is_link)
    throw input_error(r.path("body") + ": " + what + " needs a body given by its centre and orientation; '" + body +
                      "' is a link of a tree (its joint's wrench is a result of its own)");
  if (it->body_axes || it->has_omega)
    throw input_error(r.path("body") + ": " + what + " needs the body's centre and orientation on the fixed axes (not omega)");
  if (it->has_matrix)
    throw input_error(r.path("body") + ": " + what + " needs the body's orientation as a product of rotations (not a matrix)");
  return static_cast<int>(it - def.bodies.begin());
}

/// Three expressions in q and t (a point, a direction).
std::array<shared_expression, 3> point_of_q_t(builder& b, object_reader& r, const std::string& key) {
  std::array<shared_expression, 3> out;
  const json_value& v = r.raw(key);
  if (v.type != json_value::kind::array || v.items.size() != 3)
    throw input_error(r.path(key) + ": expected a list of 3 expressions in q and t");
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string where = r.path(key) + "[" + std::to_string(i) + "]";
    out[i] = b.parse(expression_text(v.items[i], where), where);
    if (b.depends_on_speeds(*out[i])) throw input_error(where + ": depends on the speeds (a function of q and t)");
  }
  return out;
}

/// A link's fields (SCENES.md, "links of a tree"): "joint" {name, parent, type, coordinate,
/// origin, rpy, axis, effort}, "mass" and "inertia" (optional together: a massless frame),
/// "inertial" {xyz, rpy}: its centre of mass and inertia axes on the link's axes.
void read_link(builder& b, object_reader& r, system_body_definition& body, const std::vector<std::string>& coordinates,
               std::vector<std::string>& link_parents) {
  using K = system_joint_definition::kind;
  system_definition& def = b.def;
  body.is_link = true;
  for (const char* key : {"center", "orientation", "omega", "axes", "velocity", "force", "couple"})
    if (r.has(key))
      throw input_error(r.path(key) + ": a link is placed by its joint (no \"" + key +
                        "\"; its centre of mass is \"inertial\", on its own axes)");
  auto constant3 = [&](object_reader& o, const std::string& key, bool required) {
    std::array<shared_expression, 3> out;
    if (!o.has(key)) {
      if (required) (void)o.raw(key);
      return out;
    }
    const json_value& v = o.raw(key);
    if (v.type != json_value::kind::array || v.items.size() != 3)
      throw input_error(o.path(key) + ": expected a list of 3 expressions (parameters only)");
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string where = o.path(key) + "[" + std::to_string(i) + "]";
      auto e = b.constant(expression_text(v.items[i], where), where);
      if (!e->is_zero()) out[i] = e;
    }
    return out;
  };
  if (r.has("mass")) {
    body.mass = b.constant(expression_text(r.raw("mass"), r.path("mass")), r.path("mass"));
    if (r.has("inertia")) {
      const json_value& v = r.raw("inertia");
      if (v.type != json_value::kind::array || v.items.size() != 6)
        throw input_error(r.path("inertia") + ": expected 6 components (xx yy zz xy yz zx) about the centre of mass");
      for (std::size_t i = 0; i < 6; ++i) {
        const std::string where = r.path("inertia") + "[" + std::to_string(i) + "]";
        auto e = b.constant(expression_text(v.items[i], where), where);
        if (!e->is_zero()) body.inertia[i] = e;
      }
    }
  } else if (r.has("inertia") || r.has("inertial")) {
    throw input_error(r.path(r.has("inertia") ? "inertia" : "inertial") + ": a link with inertia needs its \"mass\"");
  }
  if (r.has("inertial")) {
    object_reader in = r.object("inertial");
    body.com = constant3(in, "xyz", false);
    body.com_rpy = constant3(in, "rpy", false);
    in.finish();
  }
  system_joint_definition& j = body.joint;
  object_reader o = r.object("joint");
  j.name = o.has("name") ? o.string("name") : body.name;
  if (!is_identifier(j.name))
    throw input_error(o.path("name") + ": '" + printable(j.name) + "' is not a name (a letter or _, then letters, digits, _)");
  link_parents.resize(def.bodies.size() + 1);
  link_parents.back() = o.has("parent") ? o.string("parent") : "";
  const std::string type = o.string("type");
  if (type == "revolute") j.type = K::revolute;
  else if (type == "prismatic") j.type = K::prismatic;
  else if (type == "fixed") j.type = K::fixed;
  else throw input_error(o.path("type") + ": expected \"revolute\", \"prismatic\" or \"fixed\", got \"" + printable(type) + "\"");
  j.origin = constant3(o, "origin", false);
  j.rpy = constant3(o, "rpy", false);
  if (j.type == K::fixed) {
    for (const char* key : {"coordinate", "axis", "effort"})
      if (o.has(key)) throw input_error(o.path(key) + ": a fixed joint has no motion (no \"" + key + "\")");
  } else {
    const std::string q = o.string("coordinate");
    const auto it = std::find(coordinates.begin(), coordinates.end(), q);
    if (it == coordinates.end()) throw input_error(o.path("coordinate") + ": '" + printable(q) + "' is not a coordinate");
    j.coordinate = static_cast<int>(it - coordinates.begin());
    for (const auto& other : def.bodies)
      if (other.is_link && other.joint.coordinate == j.coordinate)
        throw input_error(o.path("coordinate") + ": '" + q + "' is already the coordinate of joint " + other.joint.name);
    j.axis = constant3(o, "axis", true);
    int written = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (j.axis[i]) ++written, j.along = static_cast<int>(i);
    if (written == 0) throw input_error(o.path("axis") + ": the axis is 0");
    if (written > 1) j.along = -1;
    if (o.has("effort")) j.effort = b.parse(expression_text(o.raw("effort"), o.path("effort")), o.path("effort"), true);
  }
  o.finish();
  r.finish();
}

/// Each link's parent found by name, and the links ordered each after its parent (a link with
/// two parents cannot be written; a loop is refused).
void order_links(system_definition& def, const std::vector<std::string>& parents) {
  const std::size_t n = def.bodies.size();
  for (std::size_t i = 0; i < n; ++i) {
    auto& body = def.bodies[i];
    if (!body.is_link || i >= parents.size() || parents[i].empty()) continue;
    const auto it = std::find_if(def.bodies.begin(), def.bodies.end(),
                                 [&](const system_body_definition& x) { return x.name == parents[i]; });
    if (it == def.bodies.end())
      throw input_error("bodies." + body.name + ".joint.parent: no body named '" + printable(parents[i]) + "'");
    if (!it->is_link)
      throw input_error("bodies." + body.name + ".joint.parent: '" + parents[i] +
                        "' is not a link (a link hangs from another link, or from the ground)");
    body.joint.parent = static_cast<int>(it - def.bodies.begin());
  }
  std::vector<int> state(n, 0);  // 0 new, 1 on the path, 2 placed
  std::function<void(int)> place = [&](int i) {
    auto& s = state[static_cast<std::size_t>(i)];
    if (s == 2) return;
    if (s == 1)
      throw input_error("bodies." + def.bodies[static_cast<std::size_t>(i)].name +
                        ".joint.parent: a loop (the link is its own ancestor)");
    s = 1;
    const int p = def.bodies[static_cast<std::size_t>(i)].joint.parent;
    if (p >= 0) place(p);
    s = 2;
    def.link_order.push_back(i);
  };
  for (std::size_t i = 0; i < n; ++i)
    if (def.bodies[i].is_link) place(static_cast<int>(i));
}

/// The names: parameters, coordinates, speeds (q_dot after the coordinates without "speeds"), t;
/// each a distinct identifier, none reserved.
void read_names(reading& R) {
  object_reader& scene = R.scene;
  system_input& in = R.in;
  system_definition& def = R.b.def;
  auto& coordinates = R.coordinates;
  auto& speeds = R.speeds;
  auto& parameter_texts = R.parameter_texts;
  // Names: parameters, coordinates, speeds, t.
  if (scene.has("parameters")) {
    const json_value& p = object_value(scene, "parameters");
    for (const auto& m : p.members)
      parameter_texts.emplace_back(m.key, expression_text(m.value, scene.path("parameters") + "." + m.key));
  }
  coordinates = name_list(scene.raw("coordinates"), scene.path("coordinates"));
  def.rates_as_speeds = !scene.has("speeds");
  if (coordinates.empty() && def.rates_as_speeds)
    throw input_error(scene.path("coordinates") + ": a system needs coordinates, or named speeds");
  if (def.rates_as_speeds) {
    for (const auto& q : coordinates) {
      speeds.push_back(q + "_dot");
      in.acceleration_names.push_back(q + "_ddot");
    }
  } else {
    speeds = name_list(scene.raw("speeds"), scene.path("speeds"));
    if (speeds.empty()) throw input_error(scene.path("speeds") + ": a system needs at least one speed");
    for (const auto& u : speeds) in.acceleration_names.push_back(u + "_dot");
  }
  require_at_most(coordinates.size(), system_limits::names, scene.path("coordinates"));
  require_at_most(speeds.size(), system_limits::names, scene.path("speeds"));
  def.vars = {static_cast<int>(parameter_texts.size()), static_cast<int>(coordinates.size()),
              static_cast<int>(speeds.size())};
  for (const auto& [name, text] : parameter_texts) def.names.push_back(name);
  def.names.insert(def.names.end(), coordinates.begin(), coordinates.end());
  def.names.insert(def.names.end(), speeds.begin(), speeds.end());
  def.names.push_back("t");
  {
    std::set<std::string> seen;
    for (int v = 0; v + 1 < def.vars.size(); ++v) {
      const std::string& n = def.names[static_cast<std::size_t>(v)];
      const std::string field = v < def.vars.parameters ? "parameters." + n
                                : v < def.vars.u(0)     ? "coordinates"
                                                        : (def.rates_as_speeds ? "coordinates" : "speeds");
      if (!is_identifier(n))
        throw input_error(field + ": '" + printable(n) + "' is not a name (a letter or _, then letters, digits, _)");
      if (reserved_names().count(n)) throw input_error(field + ": '" + n + "' is reserved");
      if (!seen.insert(n).second)
        throw input_error(field + ": the name '" + n + "' is used twice" +
                          (def.rates_as_speeds ? " (the speeds are named q_dot after the coordinates)" : ""));
    }
  }
  // Tables: functions of time, named apart from every variable (SCENES.md, "tables").
  if (scene.has("tables")) {
    const json_value& tables = object_value(scene, "tables");
    for (const auto& m : tables.members) {
      const std::string where = "tables." + printable(m.key);
      if (!is_identifier(m.key))
        throw input_error("tables: '" + printable(m.key) + "' is not a name (a letter or _, then letters, digits, _)");
      if (reserved_names().count(m.key)) throw input_error(where + ": the name is reserved");
      if (std::find(def.names.begin(), def.names.end(), m.key) != def.names.end())
        throw input_error(where + ": the name of a parameter, coordinate or speed");
      def.tables.push_back(std::make_shared<const piecewise_linear>(make_table(m.key, read_table_points(m.value, where), where)));
    }
  }
}

/// The parameters' expressions, and an order that evaluates each after those it uses (a
/// circular definition refused).
void read_parameters(reading& R) {
  builder& b = R.b;
  system_definition& def = R.b.def;
  auto& parameter_texts = R.parameter_texts;
  // Parameters: expressions of parameters, evaluated in an order that puts each after those it uses.
  for (const auto& [name, text] : parameter_texts) {
    const std::string where = "parameters." + name;
    auto e = b.parse(text, where);
    if (b.depends_on_state(*e)) throw input_error(where + ": a parameter cannot depend on q, u or t");
    def.parameters.push_back(e);
  }
  {
    const int P = def.vars.parameters;
    std::vector<int> state(static_cast<std::size_t>(P), 0);  // 0 new, 1 on the path, 2 done
    std::vector<int> path;
    std::function<void(int)> visit = [&](int p) {
      auto& s = state[static_cast<std::size_t>(p)];
      if (s == 2) return;
      if (s == 1) {
        std::string cycle;
        auto it = std::find(path.begin(), path.end(), p);
        for (; it != path.end(); ++it) cycle += def.names[static_cast<std::size_t>(*it)] + " -> ";
        throw input_error("parameters." + def.names[static_cast<std::size_t>(p)] + ": circular definition (" + cycle +
                          def.names[static_cast<std::size_t>(p)] + ")");
      }
      s = 1;
      path.push_back(p);
      for (int r = 0; r < P; ++r)
        if (def.parameters[static_cast<std::size_t>(p)]->depends_on(r)) visit(r);
      path.pop_back();
      s = 2;
      def.parameter_order.push_back(p);
    };
    for (int p = 0; p < P; ++p) visit(p);
  }
}

/// The kinematics q' = K(q, u, t), each affine in the speeds (only with named speeds).
void read_kinematics(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  auto& coordinates = R.coordinates;
  // Kinematics.
  if (!def.rates_as_speeds) {
    const json_value& k = object_value(scene, "kinematics");
    for (const auto& m : k.members)
      if (std::find(coordinates.begin(), coordinates.end(), m.key) == coordinates.end())
        throw input_error("kinematics." + printable(m.key) + ": not a coordinate");
    def.kinematics_du.resize(coordinates.size());
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
      const json_value* v = k.find(coordinates[i]);
      const std::string where = "kinematics." + coordinates[i];
      if (!v) throw input_error(where + ": missing (each coordinate's rate, as an expression in q, u and t)");
      auto e = b.parse(expression_text(*v, where), where);
      def.kinematics_du[i] = b.speed_coefficients(*e, where);
      def.kinematics.push_back(e);
    }
  } else if (scene.has("kinematics")) {
    throw input_error(scene.path("kinematics") + ": kinematics need named speeds (without \"speeds\", u = q')");
  }
}

/// Gravity: three constants.
void read_gravity(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  // Gravity.
  if (scene.has("gravity")) {
    const json_value& g = scene.raw("gravity");
    if (g.type != json_value::kind::array || g.items.size() != 3)
      throw input_error(scene.path("gravity") + ": expected a list of 3 expressions");
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string where = "gravity[" + std::to_string(i) + "]";
      def.gravity[i] = b.constant(expression_text(g.items[i], where), where);
    }
  }
}

/// The bodies: given by their centre and orientation (or omega, or on their own axes), or links
/// of a tree placed by their joints; the links ordered each after its parent.
void read_bodies(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  auto& coordinates = R.coordinates;
  auto& link_parents = R.link_parents;
  // Bodies.
  const json_value& bodies = object_value(scene, "bodies");
  if (bodies.members.empty()) throw input_error("bodies: a system needs at least one body");
  require_at_most(bodies.members.size(), system_limits::names, "bodies");
  for (const auto& m : bodies.members) {
    object_reader r(m.value, "bodies." + m.key);
    system_body_definition body;
    body.name = m.key;
    auto list3 = [&](const std::string& key, bool constant, bool load = false) {
      std::array<shared_expression, 3> out;
      const json_value& v = r.raw(key);
      if (v.type != json_value::kind::array || v.items.size() != 3)
        throw input_error(r.path(key) + ": expected a list of 3 expressions");
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string where = r.path(key) + "[" + std::to_string(i) + "]";
        const std::string text = expression_text(v.items[i], where);
        out[i] = constant ? b.constant(text, where) : b.parse(text, where, load);
      }
      return out;
    };
    if (r.has("joint")) {  // a link of a tree: placed by its joint
      read_link(b, r, body, coordinates, link_parents);
      def.bodies.push_back(std::move(body));
      continue;
    }
    body.mass = b.constant(expression_text(r.raw("mass"), r.path("mass")), r.path("mass"));
    if (r.has("inertia")) {
      const json_value& v = r.raw("inertia");
      if (v.type != json_value::kind::array || (v.items.size() != 3 && v.items.size() != 6))
        throw input_error(r.path("inertia") + ": expected 3 principal moments or 6 components (xx yy zz xy yz zx)");
      for (std::size_t i = 0; i < v.items.size(); ++i) {
        const std::string where = r.path("inertia") + "[" + std::to_string(i) + "]";
        body.inertia[i] = b.constant(expression_text(v.items[i], where), where);
      }
    }
    const bool has_orientation = r.has("orientation");
    body.has_omega = r.has("omega");
    if (r.has("axes")) {
      const std::string axes = r.string("axes");
      if (axes != "fixed" && axes != "body")
        throw input_error(r.path("axes") + ": expected \"fixed\" or \"body\", got \"" + printable(axes) + "\"");
      body.body_axes = axes == "body";
    }
    auto affine3 = [&](const std::string& key) {  // three expressions affine in the speeds
      std::array<shared_expression, 3> out = list3(key, false);
      for (std::size_t i = 0; i < 3; ++i) (void)b.speed_coefficients(*out[i], r.path(key) + "[" + std::to_string(i) + "]");
      return out;
    };
    if (body.body_axes) {
      // The paper's moving axes: omega and the centre's velocity on the body's own axes.
      if (!body.has_omega) throw input_error(r.path("omega") + ": required on the body's own axes");
      if (has_orientation || r.has("center"))
        throw input_error(r.path(has_orientation ? "orientation" : "center") +
                          ": a body on its own axes is given by its velocity and omega there, not by its position");
      if (def.gravity[0])
        throw input_error(r.path("axes") + ": gravity needs the body's orientation; on its own axes give the weight "
                                           "as a force on those axes");
      body.omega = affine3("omega");
      if (r.has("velocity")) body.velocity = affine3("velocity");
    } else {
      if (r.has("velocity"))
        throw input_error(r.path("velocity") + ": on the fixed axes the velocity follows from \"center\"");
      const json_value& c = r.raw("center");
      if (c.type != json_value::kind::array || c.items.size() != 3)
        throw input_error(r.path("center") + ": expected a list of 3 expressions in q and t");
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string where = r.path("center") + "[" + std::to_string(i) + "]";
        body.center[i] = b.function_of_q_t(expression_text(c.items[i], where), where);
      }
      if (body.has_omega) {
        if (has_orientation)
          throw input_error(r.path("omega") + ": give the orientation or omega, not both");
        const bool isotropic = !body.inertia[0] ||
                               (body.inertia[1] && body.inertia[2] && !body.inertia[3] && !body.inertia[4] &&
                                !body.inertia[5] && body.inertia[0]->to_string() == body.inertia[1]->to_string() &&
                                body.inertia[0]->to_string() == body.inertia[2]->to_string());
        if (!isotropic)
          throw input_error(r.path("omega") + ": on the fixed axes omega serves a body whose inertia is isotropic "
                                              "(three equal moments, as written); give an orientation, or use \"axes\": \"body\"");
        body.omega = affine3("omega");
      }
    }
    if (has_orientation) {
      const std::string where = r.path("orientation");
      const json_value& o = r.raw("orientation");
      if (o.type == json_value::kind::array) {  // a matrix, row by row
        if (o.items.size() != 3)
          throw input_error(where + ": expected a product of rotations or a 3 x 3 matrix (3 rows of 3 expressions)");
        for (std::size_t i = 0; i < 3; ++i) {
          const json_value& row = o.items[i];
          if (row.type != json_value::kind::array || row.items.size() != 3)
            throw input_error(where + "[" + std::to_string(i) + "]: expected a row of 3 expressions in q and t");
          for (std::size_t j = 0; j < 3; ++j) {
            const std::string at = where + "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
            body.matrix[3 * i + j] = b.function_of_q_t(expression_text(row.items[j], at), at);
          }
        }
        body.has_matrix = true;
      } else if (o.type != json_value::kind::string) {
        throw input_error(where + ": expected a product of rotations such as \"rz(psi) rx(theta) rz(phi)\", or a 3 x 3 matrix");
      }
      int n = 0;
      const auto factors = body.has_matrix ? std::vector<std::pair<int, std::string>>{} : rotation_factors(o.text, where);
      require_at_most(factors.size(), system_limits::rotations, where + ": rotations");
      for (const auto& [axis, text] : factors)
        body.rotations.emplace_back(axis, b.function_of_q_t(text, where + "[" + std::to_string(n++) + "]"));
    }
    if (r.has("force")) body.force = list3("force", false, true);
    if (r.has("couple")) body.couple = list3("couple", false, true);
    r.finish();
    def.bodies.push_back(std::move(body));
  }

  order_links(def, link_parents);
}

/// The constraints: holonomic f(q, t) = 0, nonholonomic g(q, u, t) = 0 affine in u, or a
/// point's velocity along a direction.
void read_constraints(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  auto& speeds = R.speeds;
  // Constraints.
  if (scene.has("constraints")) {
    const json_value& cs = object_value(scene, "constraints");
    require_at_most(cs.members.size(), system_limits::names, "constraints");
    for (const auto& m : cs.members) {
      object_reader r(m.value, "constraints." + m.key);
      system_constraint_definition k;
      k.name = m.key;
      if (!is_identifier(k.name))
        throw input_error("constraints: '" + printable(k.name) + "' is not a name (a letter or _, then letters, digits, _)");
      const bool h = r.has("holonomic"), nh = r.has("nonholonomic"), pv = r.has("point_velocity");
      if (int(h) + int(nh) + int(pv) != 1)
        throw input_error("constraints." + k.name +
                          ": expected one of \"holonomic\", \"nonholonomic\" or \"point_velocity\"");
      k.holonomic = h;
      if (pv) {
        // n . (v_G + omega x (P - G)) = 0 for the material point of a body at P
        object_reader p = r.object("point_velocity");
        k.body = body_on_fixed_axes(def, p, "a point velocity");
        k.point = point_of_q_t(b, p, "point");
        k.direction = point_of_q_t(b, p, "direction");
        if (p.has("support")) k.support = point_of_q_t(b, p, "support");
        p.finish();
        r.finish();
        def.constraints.push_back(std::move(k));
        continue;
      }
      const std::string where = r.path(h ? "holonomic" : "nonholonomic");
      const std::string text = expression_text(r.raw(h ? "holonomic" : "nonholonomic"), where);
      r.finish();
      if (h) {
        k.f = b.function_of_q_t(text, where);
        if (k.f.dq.empty())
          throw input_error(where + ": does not depend on the coordinates (a constraint on t alone is no constraint)");
      } else {
        k.g = b.parse(text, where);
        k.du = b.speed_coefficients(*k.g, where);
        if (k.du.empty())
          throw input_error(where + ": does not depend on the speeds (a constraint on q and t is holonomic: write it so)");
      }
      def.constraints.push_back(std::move(k));
    }
    if (def.constraints.size() >= speeds.size())
      throw input_error(scene.path("constraints") + ": " + std::to_string(def.constraints.size()) + " constraints on " +
                        std::to_string(speeds.size()) + " speeds leave nothing to move");
  }
}

/// The constraint wrenches: on a named body, reduced to a named point.
void read_wrenches(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  // Constraint wrenches: on a named body, reduced to a named point.
  if (scene.has("wrenches")) {
    const json_value& ws = object_value(scene, "wrenches");
    require_at_most(ws.members.size(), system_limits::names, "wrenches");
    for (const auto& m : ws.members) {
      object_reader r(m.value, "wrenches." + m.key);
      system_wrench_definition w;
      w.name = m.key;
      if (!is_identifier(w.name))
        throw input_error("wrenches: '" + printable(w.name) + "' is not a name (a letter or _, then letters, digits, _)");
      w.body = body_on_fixed_axes(def, r, "a wrench");
      if (def.bodies[static_cast<std::size_t>(w.body)].rotations.empty())
        throw input_error(r.path("body") + ": a wrench needs a body with an orientation (a couple on a body that "
                                           "does not turn does no work)");
      w.point = point_of_q_t(b, r, "point");
      for (const std::string& name : name_list(r.raw("constraints"), r.path("constraints"))) {
        const auto it = std::find_if(def.constraints.begin(), def.constraints.end(),
                                     [&](const system_constraint_definition& x) { return x.name == name; });
        if (it == def.constraints.end())
          throw input_error(r.path("constraints") + ": no constraint named '" + printable(name) + "'");
        const int c = static_cast<int>(it - def.constraints.begin());
        if (std::find(w.constraints.begin(), w.constraints.end(), c) != w.constraints.end())
          throw input_error(r.path("constraints") + ": '" + name + "' twice");
        w.constraints.push_back(c);
      }
      if (w.constraints.empty()) throw input_error(r.path("constraints") + ": name at least one constraint");
      r.finish();
      def.wrenches.push_back(std::move(w));
    }
  }
}

/// A contact of a link with the fixed ground (SCENES.md, "contacts of links"): its link, its
/// kind, its frame, its friction; its constraints made here, one per row, named
/// <contact>_x, _y, _z (the point's velocity along the frame's axes) and, for a sole,
/// <contact>_wx, _wy, _wz (the link's angular velocity).
void read_link_contact(reading& R, object_reader& r, system_contact_definition& k) {
  system_definition& def = R.b.def;
  const std::string link = r.string("link");
  const auto it = std::find_if(def.bodies.begin(), def.bodies.end(), [&](const system_body_definition& x) { return x.name == link; });
  if (it == def.bodies.end()) throw input_error(r.path("link") + ": no body named '" + printable(link) + "'");
  if (!it->is_link)
    throw input_error(r.path("link") + ": '" + printable(link) + "' is not a link of a tree (a body placed by its "
                      "joint); a contact of another body names its constraints (\"constraints\")");
  for (const char* other : {"constraints", "body", "direction"})
    if (r.has(other))
      throw input_error(r.path(other) + ": a link's contact makes its own constraints; leave \"" + std::string(other) + "\" out");
  k.link = static_cast<int>(it - def.bodies.begin());
  const std::string type = r.has("type") ? r.string("type") : std::string("point");
  if (type != "point" && type != "surface")
    throw input_error(r.path("type") + ": \"point\" (the link's point held: three constraints) or \"surface\" (the "
                      "link held by a flat rectangular sole: six), not \"" + printable(type) + "\"");
  k.surface = type == "surface";
  if (k.surface) {
    for (const char* other : {"point", "normal"})
      if (r.has(other))
        throw input_error(r.path(other) + ": a surface contact is placed by its \"sole\" (centre, rpy, half_lengths)");
    object_reader sole = r.object("sole");
    const std::vector<decimal_field> c = sole.numbers("center", 3);
    for (std::size_t i = 0; i < 3; ++i) k.frame_origin[i] = c[i].text;
    if (sole.has("rpy")) {
      const std::vector<decimal_field> a = sole.numbers("rpy", 3);
      for (std::size_t i = 0; i < 3; ++i) k.frame_rpy[i] = a[i].text;
    }
    const std::vector<decimal_field> h = sole.numbers("half_lengths", 2);
    for (std::size_t i = 0; i < 2; ++i) {
      if (decimal_sign_of_sum({{1, h[i].text}}) <= 0)
        throw input_error(sole.path("half_lengths") + "[" + std::to_string(i) + "]: a sole's half-length must be positive, got " +
                          h[i].text);
      k.half_lengths[i] = h[i].text;
    }
    sole.finish();
  } else {
    if (r.has("sole")) throw input_error(r.path("sole") + ": a point contact has no sole (\"type\": \"surface\" has one)");
    const std::vector<decimal_field> p = r.numbers("point", 3);
    for (std::size_t i = 0; i < 3; ++i) k.frame_origin[i] = p[i].text;
    if (r.has("normal")) {
      const std::vector<decimal_field> n = r.numbers("normal", 3);
      for (std::size_t i = 0; i < 3; ++i) k.frame_normal[i] = n[i].text;
      if (decimal_sign_of_polynomial({{1, {n[0].text, n[0].text}}, {1, {n[1].text, n[1].text}}, {1, {n[2].text, n[2].text}}}) == 0)
        throw input_error(r.path("normal") + ": the normal is 0");
    }
  }
  if (r.has("mu")) {
    const decimal_field mu = r.number("mu");
    if (decimal_sign_of_sum({{1, mu.text}}) < 0)
      throw input_error(r.path("mu") + ": a friction coefficient must not be negative, got " + mu.text);
    k.mu = mu.text;
  }
  const int contact = static_cast<int>(def.contacts.size());
  const std::vector<const char*> rows = k.surface ? std::vector<const char*>{"_x", "_y", "_z", "_wx", "_wy", "_wz"}
                                                  : std::vector<const char*>{"_x", "_y", "_z"};
  for (std::size_t row = 0; row < rows.size(); ++row) {
    system_constraint_definition c;
    c.name = k.name + rows[row];
    if (std::any_of(def.constraints.begin(), def.constraints.end(), [&](const system_constraint_definition& x) { return x.name == c.name; }))
      throw input_error("contacts." + k.name + ": its constraint " + c.name + " has the name of another constraint");
    c.holonomic = false;
    c.link_contact = contact;
    c.link_row = static_cast<int>(row);
    k.constraints.push_back(static_cast<int>(def.constraints.size()));
    def.constraints.push_back(std::move(c));
  }
  if (def.constraints.size() >= static_cast<std::size_t>(def.vars.speeds))
    throw input_error("contacts." + k.name + ": " + std::to_string(def.constraints.size()) + " constraints on " +
                      std::to_string(def.vars.speeds) + " speeds leave nothing to move");
}

/// The contacts: which constraints make one, its normal, its friction (SCENES.md "contacts").
void read_contacts(reading& R) {
  object_reader& scene = R.scene;
  builder& b = R.b;
  system_definition& def = R.b.def;
  // Contacts: which constraints make one, its normal, its friction (SCENES.md "contacts").
  if (scene.has("contacts")) {
    const json_value& cs = object_value(scene, "contacts");
    require_at_most(cs.members.size(), system_limits::names, "contacts");
    for (const auto& m : cs.members) {
      object_reader r(m.value, "contacts." + m.key);
      system_contact_definition k;
      k.name = m.key;
      if (!is_identifier(k.name))
        throw input_error("contacts: '" + printable(k.name) + "' is not a name (a letter or _, then letters, digits, _)");
      if (r.has("link")) {
        read_link_contact(R, r, k);
        r.finish();
        def.contacts.push_back(std::move(k));
        continue;
      }
      auto constraint_index = [&](const std::string& name, const std::string& where) {
        const auto it = std::find_if(def.constraints.begin(), def.constraints.end(),
                                     [&](const system_constraint_definition& x) { return x.name == name; });
        if (it == def.constraints.end()) throw input_error(where + ": no constraint named '" + printable(name) + "'");
        return static_cast<int>(it - def.constraints.begin());
      };
      for (const std::string& name : name_list(r.raw("constraints"), r.path("constraints"))) {
        const int c = constraint_index(name, r.path("constraints"));
        if (std::find(k.constraints.begin(), k.constraints.end(), c) != k.constraints.end())
          throw input_error(r.path("constraints") + ": '" + name + "' twice");
        k.constraints.push_back(c);
      }
      if (k.constraints.empty()) throw input_error(r.path("constraints") + ": name at least one constraint");
      const json_value& nv = r.raw("normal");
      if (nv.type == json_value::kind::string) {
        std::string name = nv.text;
        if (!name.empty() && name[0] == '-') {
          k.side = -1;
          name.erase(0, 1);
        }
        k.normal = constraint_index(name, r.path("normal"));
        if (std::find(k.constraints.begin(), k.constraints.end(), k.normal) == k.constraints.end())
          throw input_error(r.path("normal") + ": '" + name + "' is not one of the contact's constraints");
      } else if (nv.type == json_value::kind::array) {
        k.direction = point_of_q_t(b, r, "normal");
      } else {
        throw input_error(r.path("normal") + ": expected a constraint's name (\"-name\" for the other side) or a "
                                             "direction, 3 expressions in q and t");
      }
      if (r.has("mu")) {
        const decimal_field mu = r.number("mu");
        if (decimal_sign_of_sum({{1, mu.text}}) < 0)
          throw input_error(r.path("mu") + ": a friction coefficient must not be negative, got " + mu.text);
        k.mu = mu.text;
      }
      if (r.has("point") && !r.has("body"))
        throw input_error(r.path("body") + ": a contact's point is on a body: give the contact's body with its point");
      if (r.has("body")) {
        const std::string body = r.string("body");
        const auto it = std::find_if(def.bodies.begin(), def.bodies.end(),
                                     [&](const system_body_definition& x) { return x.name == body; });
        if (it == def.bodies.end()) throw input_error(r.path("body") + ": no body named '" + printable(body) + "'");
        if (it->is_link)
          throw input_error(r.path("body") + ": a contact needs a body given by its centre and orientation; '" +
                            printable(body) + "' is a link of a tree (its joint's wrench is a result of its own)");
        if (it->body_axes || it->has_matrix)
          throw input_error(r.path("body") + ": a contact's body needs its centre and its orientation on the fixed axes "
                                             "(rotations, or omega on the fixed axes; no orientation: a point mass)");
        k.body = static_cast<int>(it - def.bodies.begin());
        // A body without orientation (neither rotations nor omega) is a point mass: the contact
        // is at its centre, and the constraints' virtual work fixes the force alone there.
        const bool point_mass = !it->has_omega && it->rotations.empty();
        if (point_mass) {
          for (std::size_t i = 0; i < 3; ++i) k.point[i] = it->center[i].value;
          if (r.has("point")) {
            const auto given = point_of_q_t(b, r, "point");
            for (std::size_t i = 0; i < 3; ++i)
              if (given[i]->to_string() != k.point[i]->to_string())
                throw input_error(r.path("point") + ": " + printable(body) + " is a point mass (no orientation): its "
                                  "contact is at its centre; leave \"point\" out, or give the centre as written");
          }
        } else {
          if (!r.has("point"))
            throw input_error(r.path("point") + ": missing: " + printable(body) + " has an orientation, so the contact's "
                              "point on it must be given (3 expressions in q and t)");
          k.point = point_of_q_t(b, r, "point");
        }
        if (it->has_omega)
          for (std::size_t i = 0; i < 3; ++i)
            k.omega_du[i] = b.speed_coefficients(*it->omega[i], "bodies." + body + ".omega[" + std::to_string(i) + "]");
      } else {
        // every constraint a point_velocity constraint at one point of one body
        const system_constraint_definition& c0 = def.constraints[static_cast<std::size_t>(k.constraints[0])];
        for (int c : k.constraints) {
          const system_constraint_definition& ci = def.constraints[static_cast<std::size_t>(c)];
          bool same = ci.body >= 0 && ci.body == c0.body;
          for (std::size_t i = 0; same && i < 3; ++i) same = ci.point[i]->to_string() == c0.point[i]->to_string();
          if (!same)
            throw input_error(
                r.path("constraints") + ": " + ci.name +
                (ci.body < 0 ? std::string(" is ") + (ci.holonomic ? "a holonomic" : "a nonholonomic") +
                                   " constraint, not a point_velocity one"
                             : " is a point_velocity constraint at another point than " + c0.name + "'s") +
                ": give the contact's \"body\" (and its \"point\", unless the body is a point mass): the force then "
                "comes from the constraints' virtual work");
        }
      }
      r.finish();
      def.contacts.push_back(std::move(k));
    }
  }
}

/// The speeds the constraints determine (solve_speeds: one per constraint).
void read_solve_speeds(reading& R) {
  object_reader& scene = R.scene;
  system_input& in = R.in;
  system_definition& def = R.b.def;
  auto& speeds = R.speeds;
  // Speeds the constraints determine (given neither in the state nor by hand).
  if (scene.has("solve_speeds")) {
    for (const std::string& name : name_list(scene.raw("solve_speeds"), scene.path("solve_speeds"))) {
      const auto it = std::find(speeds.begin(), speeds.end(), name);
      if (it == speeds.end()) throw input_error(scene.path("solve_speeds") + ": '" + printable(name) + "' is not a speed");
      const int j = static_cast<int>(it - speeds.begin());
      if (std::find(in.solved.begin(), in.solved.end(), j) != in.solved.end())
        throw input_error(scene.path("solve_speeds") + ": '" + name + "' twice");
      in.solved.push_back(j);
    }
    if (in.solved.size() != def.constraints.size())
      throw input_error(scene.path("solve_speeds") + ": " + std::to_string(in.solved.size()) +
                        " speeds for " + std::to_string(def.constraints.size()) + " constraints (one per constraint)");
  }
}

/// The state (q, u, t), the accelerations of inverse dynamics, the projection's tolerance.
void read_state(reading& R) {
  object_reader& scene = R.scene;
  system_input& in = R.in;
  const system_definition& def = R.definition();
  auto& coordinates = R.coordinates;
  auto& speeds = R.speeds;
  // The state.
  object_reader state = scene.object("state");
  for (const auto& q : coordinates) in.q.push_back(state.number(q));
  for (std::size_t j = 0; j < speeds.size(); ++j)
    in.u.push_back(std::find(in.solved.begin(), in.solved.end(), static_cast<int>(j)) != in.solved.end()
                       ? decimal_field{"0", state.path(speeds[j])}
                       : state.number(speeds[j]));
  in.t = state.has("t") ? state.number("t") : decimal_field{"0", state.path("t")};
  state.finish();
  if (scene.has("accelerations")) {  // inverse dynamics: the efforts that give these accelerations
    const std::string where = scene.path("accelerations");
    if (!def.constraints.empty())
      throw input_error(where + ": inverse dynamics needs a system without constraints (a closed chain's efforts are "
                                "not determined by its accelerations)");
    if (!def.rates_as_speeds) throw input_error(where + ": inverse dynamics needs the coordinates' rates as speeds");
    for (int i = 0; i < def.vars.coordinates; ++i) {
      const auto owner = std::find_if(def.bodies.begin(), def.bodies.end(), [&](const system_body_definition& x) {
        return x.is_link && x.joint.coordinate == i;
      });
      if (owner == def.bodies.end())
        throw input_error(where + ": inverse dynamics needs every coordinate to be a joint's (" + coordinates[static_cast<std::size_t>(i)] +
                          " is no joint's)");
      if (owner->joint.effort)
        throw input_error("bodies." + owner->name + ".joint.effort: with \"accelerations\" the efforts are the results, "
                                                     "not given");
    }
    object_reader acc = scene.object("accelerations");
    for (const auto& name : in.acceleration_names) in.udot.push_back(acc.number(name));
    acc.finish();
    in.inverse_dynamics = true;
  }
  if (scene.has("project")) {
    in.project = scene.number("project");
    require_positive(scene, "project", *in.project, "a tolerance");
  }
}

/// The linearization (optional): only `linearize` reads it; its refusal is kept for that command
/// (linearize_refusal), not raised here.
void read_linearization(reading& R) {
  object_reader& scene = R.scene;
  system_input& in = R.in;
  const system_definition& def = R.definition();
  auto& coordinates = R.coordinates;
  auto& speeds = R.speeds;
  // The linearization (optional): about the state with "about" applied.  Only `linearize` reads
  // the section: a refusal of it is kept for that command (linearize_refusal), not raised here.
  if (scene.has("linearize")) try {
    object_reader lr = scene.object("linearize");
    linearize_input li;
    linearize_definition& L = li.def;
    auto coordinate_index = [&](const std::string& name, const std::string& where) {
      const auto it = std::find(coordinates.begin(), coordinates.end(), name);
      if (it == coordinates.end()) throw input_error(where + ": '" + printable(name) + "' is not a coordinate");
      return static_cast<int>(it - coordinates.begin());
    };
    auto is_solved = [&](int j) { return std::find(in.solved.begin(), in.solved.end(), j) != in.solved.end(); };
    if (!def.rates_as_speeds)
      throw input_error(scene.path("linearize") + ": needs the coordinates' rates as the speeds (no \"speeds\")");
    if (!def.constraints.empty() && in.solved.empty())
      throw input_error(scene.path("linearize") + ": a constrained system needs solve_speeds (the speeds that follow "
                                                  "the linearized ones)");
    for (const std::string& name : name_list(lr.raw("coordinates"), lr.path("coordinates"))) {
      const int i = coordinate_index(name, lr.path("coordinates"));
      if (std::find(L.coordinates.begin(), L.coordinates.end(), i) != L.coordinates.end())
        throw input_error(lr.path("coordinates") + ": '" + name + "' twice");
      if (is_solved(i))
        throw input_error(lr.path("coordinates") + ": " + speeds[static_cast<std::size_t>(i)] +
                          " is in solve_speeds (a linearized coordinate's rate is given)");
      L.coordinates.push_back(i);
    }
    if (L.coordinates.empty()) throw input_error(lr.path("coordinates") + ": name at least one coordinate");
    require_at_most(L.coordinates.size(), 16, lr.path("coordinates"));
    {
      const std::string name = lr.string("speed");
      const auto it = std::find(speeds.begin(), speeds.end(), name);
      if (it == speeds.end()) throw input_error(lr.path("speed") + ": '" + printable(name) + "' is not a speed");
      L.speed = static_cast<int>(it - speeds.begin());
      if (is_solved(L.speed)) throw input_error(lr.path("speed") + ": '" + name + "' is in solve_speeds (give it)");
      if (std::find(L.coordinates.begin(), L.coordinates.end(), L.speed) != L.coordinates.end())
        throw input_error(lr.path("speed") + ": '" + name + "' is the rate of a linearized coordinate");
    }
    if (lr.has("gravity")) {
      const std::string name = lr.string("gravity");
      const auto it = std::find(def.names.begin(), def.names.begin() + def.vars.parameters, name);
      if (it == def.names.begin() + def.vars.parameters)
        throw input_error(lr.path("gravity") + ": '" + printable(name) + "' is not a parameter");
      L.gravity = static_cast<int>(it - def.names.begin());
    }
    for (int j = 0; j < def.vars.speeds; ++j)
      if (!is_solved(j)) L.free_speeds.push_back(j);
    // The coordinates the holonomic constraints determine: named, or those they involve
    // besides the linearized ones.
    std::set<int> involved;
    for (std::size_t r = 0; r < def.constraints.size(); ++r) {
      const auto& k = def.constraints[r];
      if (!k.holonomic) continue;
      L.holonomic_rows.push_back(static_cast<int>(r));
      for (const auto& [i, e] : k.f.dq)
        if (std::find(L.coordinates.begin(), L.coordinates.end(), i) == L.coordinates.end()) involved.insert(i);
    }
    if (lr.has("solve_coordinates")) {
      for (const std::string& name : name_list(lr.raw("solve_coordinates"), lr.path("solve_coordinates"))) {
        const int i = coordinate_index(name, lr.path("solve_coordinates"));
        if (std::find(L.coordinates.begin(), L.coordinates.end(), i) != L.coordinates.end() ||
            std::find(L.dependent_coordinates.begin(), L.dependent_coordinates.end(), i) != L.dependent_coordinates.end())
          throw input_error(lr.path("solve_coordinates") + ": '" + name + "' is linearized or named twice");
        L.dependent_coordinates.push_back(i);
      }
    } else {
      L.dependent_coordinates.assign(involved.begin(), involved.end());
    }
    if (L.dependent_coordinates.size() != L.holonomic_rows.size())
      throw input_error(scene.path("linearize") + ": " + std::to_string(L.holonomic_rows.size()) +
                        " holonomic constraints involve " + std::to_string(L.dependent_coordinates.size()) +
                        " other coordinates: name the ones they determine in solve_coordinates");
    if (lr.has("about")) {
      object_reader about = lr.object("about");
      for (const auto& m : object_value(lr, "about").members) {
        const auto q = std::find(coordinates.begin(), coordinates.end(), m.key);
        const auto u = std::find(speeds.begin(), speeds.end(), m.key);
        if (q != coordinates.end()) li.about_q.emplace_back(static_cast<int>(q - coordinates.begin()), about.number(m.key));
        else if (u != speeds.end() && !is_solved(static_cast<int>(u - speeds.begin())))
          li.about_u.emplace_back(static_cast<int>(u - speeds.begin()), about.number(m.key));
        else
          throw input_error(about.path(m.key) + ": not a coordinate or a given speed");
      }
      about.finish();
    }
    if (lr.has("eigenvalues_at")) {
      const json_value& v = lr.raw("eigenvalues_at");
      if (v.type != json_value::kind::array) throw input_error(lr.path("eigenvalues_at") + ": expected a list of speeds");
      require_at_most(v.items.size(), 1000, lr.path("eigenvalues_at"));
      for (std::size_t i = 0; i < v.items.size(); ++i)
        li.eigenvalue_speeds.push_back(decimal_text(v.items[i], lr.path("eigenvalues_at") + "[" + std::to_string(i) + "]"));
    }
    if (lr.has("critical_speeds")) {
      object_reader cs = lr.object("critical_speeds");
      li.from = cs.number("from");
      li.to = cs.number("to");
      if (cs.has("steps")) {
        const decimal_field st = cs.number("steps");
        if (st.text.empty() || st.text.find_first_not_of("0123456789") != std::string::npos || st.text.size() > 5 ||
            std::stoi(st.text) < 1 || std::stoi(st.text) > 10000)
          throw input_error(cs.path("steps") + ": expected an integer from 1 to 10000");
        li.steps = std::stoi(st.text);
      }
      cs.finish();
    }
    lr.finish();
    set_reference_motion(li, in);
    in.linearize = std::move(li);
  } catch (const input_error& e) {
    in.linearize.reset();
    in.linearize_refusal = e.what();
  }
}

/// Every result's name distinct.
void check_result_names(reading& R) {
  system_input& in = R.in;
  const system_definition& def = R.definition();
  {  // the result names must be distinct
    std::set<std::string> results(in.acceleration_names.begin(), in.acceleration_names.end());
    for (const auto& k : def.constraints)
      if (!results.insert(k.name + "_reaction").second)
        throw input_error("constraints." + k.name + ": its result " + k.name + "_reaction has the name of another result");
    for (const auto& w : def.wrenches)
      for (const char* suffix : {"_force", "_moment"})
        if (!results.insert(w.name + suffix).second)
          throw input_error("wrenches." + w.name + ": its result " + w.name + suffix + " has the name of another result");
    for (const auto& body : def.bodies) {
      if (!body.is_link) continue;
      std::vector<std::string> suffixes{"_force", "_moment"};
      if (in.inverse_dynamics && body.joint.type != system_joint_definition::kind::fixed) suffixes.push_back("_effort");
      for (const auto& suffix : suffixes)
        if (!results.insert(body.joint.name + suffix).second)
          throw input_error("bodies." + body.name + ".joint: its result " + body.joint.name + suffix +
                            " has the name of another result");
    }
    for (const auto& k : def.contacts)
      for (const char* suffix : {"_normal_force", "_friction_force", "_tangential_force", "_required_mu", "_moment", "_margins"})
        if ((k.surface || std::string(suffix) != "_moment") && (k.surface || std::string(suffix) != "_margins") &&
            !results.insert(k.name + suffix).second)
          throw input_error("contacts." + k.name + ": its result " + k.name + suffix + " has the name of another result");
  }
}

}  // namespace system_reading

namespace {

// --- the definition read once for many states -------------------------------------------------
//
// `appell reference` reads a scene again for every state, and a system file's definition (its
// expressions parsed and differentiated, its links settled at 256 bits) was most of a robot's
// state.  The last definition read on this thread is kept with the members of the scene it was
// read from; a scene whose members other than the state's are the same JSON takes it, and only
// the state's phases run.  The same input then reads to the same system_input (its definition
// shared), the same refusals included: a definition is kept only once its whole scene was
// accepted (finish() included, which the callers run next anyway), and every member it read
// is marked read again.

/// The top-level members the state's phases read (read_state, read_linearization).
bool state_member(const std::string& key) {
  return key == "state" || key == "accelerations" || key == "project" || key == "linearize";
}

bool same_json(const json_value& a, const json_value& b) {
  if (a.type != b.type || a.boolean != b.boolean || a.text != b.text || a.items.size() != b.items.size() ||
      a.members.size() != b.members.size())
    return false;
  for (std::size_t i = 0; i < a.items.size(); ++i)
    if (!same_json(a.items[i], b.items[i])) return false;
  for (std::size_t i = 0; i < a.members.size(); ++i)
    if (a.members[i].key != b.members[i].key || !same_json(a.members[i].value, b.members[i].value)) return false;
  return true;
}

/// The scene's members but the state's, in order.
json_value definition_members(const json_value& scene) {
  json_value d;
  d.type = json_value::kind::object;
  for (const auto& m : scene.members)
    if (!state_member(m.key)) d.members.push_back(m);
  return d;
}

bool same_definition(const json_value& scene, const json_value& definition) {
  std::size_t j = 0;
  for (const auto& m : scene.members) {
    if (state_member(m.key)) continue;
    if (j == definition.members.size() || definition.members[j].key != m.key ||
        !same_json(m.value, definition.members[j].value))
      return false;
    ++j;
  }
  return j == definition.members.size();
}

struct definition_memo {
  json_value members;  ///< the scene's members but the state's
  system_input in;     ///< as the phases before the state left it
  std::vector<std::string> coordinates, speeds;
  std::vector<std::pair<std::string, std::string>> parameter_texts;
  std::vector<std::string> link_parents;
  std::shared_ptr<const system_definition> definition;  ///< settled
};

thread_local std::optional<definition_memo> last_definition;

}  // namespace

system_input system_model::read(object_reader& scene) {
  using namespace system_reading;
  reading R{scene};
  const json_value& root = scene.value();
  std::optional<definition_memo> read_now;
  if (last_definition && same_definition(root, last_definition->members)) {
    const definition_memo& m = *last_definition;
    for (const auto& member : root.members)
      if (!state_member(member.key)) (void)scene.raw(member.key);
    R.in = m.in;
    R.coordinates = m.coordinates;
    R.speeds = m.speeds;
    R.parameter_texts = m.parameter_texts;
    R.link_parents = m.link_parents;
    R.known = m.definition;
  } else {
    read_names(R);
    read_parameters(R);
    read_kinematics(R);
    read_gravity(R);
    read_bodies(R);
    read_constraints(R);
    read_wrenches(R);
    read_contacts(R);
    read_solve_speeds(R);
    read_now = definition_memo{definition_members(root), R.in, R.coordinates, R.speeds, R.parameter_texts,
                               R.link_parents, nullptr};
  }
  read_state(R);
  read_linearization(R);
  check_result_names(R);
  if (R.known) {
    R.in.def = R.known;
  } else {
    settle_link_axes(R.b.def);
    R.in.def = std::make_shared<system_definition>(std::move(R.b.def));
  }
  check_at_state(R.in);
  if (read_now) {
    scene.finish();  // what the callers check next: a definition is kept only from an accepted scene
    read_now->definition = R.in.def;
    last_definition = std::move(read_now);
  }
  return std::move(R.in);
}

APPELL_DEFINE_MODEL_ENTRY(system_model)

}  // namespace appell

// ----------------------------------------------------------------------------------------------
// Scene model "system": the checks at the state, at 256 bits (every expression and derivative
// defined, masses positive, inertia tensors positive semidefinite, orientation matrices
// rotations, a tree's mass matrix positive definite, the state on every constraint, the
// constraints independent, each wrench and contact fixed by its virtual work, the linearization's
// reference motion).  What 256 bits cannot tell from exact is taken as exact; the scalar the
// user asks for certifies the rest.  Also each link axis's sign, settled at 256 bits.
namespace appell::system_reading {

void require_in_256_bits(bool certainly_true, bool certainly_false, const std::string& what) {
  if (certainly_false) throw input_error(what);
  if (!certainly_true) throw input_error(what + " (within 2^-256: taken as exact)");
}



/// At 256 bits, at the state: the speeds move `body` in 6 independent ways (J J^T, Gaussian
/// elimination with every pivot certainly positive), so that the constraints' virtual work fixes
/// `what` (a wrench, a contact's force); and each named constraint's row is a virtual power of
/// that body alone (A_c^T in the range of J^T).  input_error naming `where` otherwise.
void check_body_fixes_force(const system_definition& d, const std::string& where, int body, const matrix_t<mpfi>& J,
                            const matrix_t<mpfi>& A, const std::vector<int>& constraints, const std::string& what) {
  const int n = d.vars.speeds, m = static_cast<int>(J.rows());  // m: 6, or 3 for a point mass (its force alone)
  const std::string& name = d.bodies[static_cast<std::size_t>(body)].name;
  matrix_t<mpfi> N = wrench_normal_equations(J, vector_t<mpfi>(vector_t<mpfi>::Zero(n))).first;
  for (int p = 0; p < m; ++p) {
    if (!certainly_positive(N(p, p)))
      throw input_error(where + ".body: the speeds move " + name + " in fewer than " + std::to_string(m) +
                        " independent ways at the state, so the constraints' virtual work does not fix " + what +
                        (m == 6 ? " (describe the body free: 6 speeds, the constraints as rows)"
                                : " (describe the point mass free: 3 speeds of its centre, the constraints as rows)"));
    for (int r = p + 1; r < m; ++r) {
      const mpfi f = N(r, p) / N(p, p);
      for (int c = p; c < m; ++c) N(r, c) -= f * N(p, c);
    }
  }
  for (int c : constraints) {
    const vector_t<mpfi> g = A.row(c).transpose();
    const auto [Nc, rhs] = wrench_normal_equations(J, g);
    const vector_t<mpfi> y = solve_spd(Nc, rhs);
    for (int j = 0; j < n; ++j) {
      mpfi e = -g(j);
      for (int r = 0; r < m; ++r) e += J(r, j) * y(r);
      if (!possibly_zero(e))
        throw input_error(where + ".constraints: " + d.constraints[static_cast<std::size_t>(c)].name +
                          " is not a constraint on " + name + " alone (its virtual work involves " +
                          d.names[static_cast<std::size_t>(d.vars.u(j))] + " beyond the body's motion)");
    }
  }
}

void settle_link_axes(system_definition& def) {
  if (def.link_order.empty()) return;
  mp_precision_scope scope(256);
  std::vector<mpfi> x(static_cast<std::size_t>(def.vars.size()), mpfi(0));
  for (int p : def.parameter_order)
    x[static_cast<std::size_t>(p)] = compiled_expression<mpfi>(*def.parameters[static_cast<std::size_t>(p)]).eval_at(x.data());
  for (auto& body : def.bodies) {
    auto& j = body.joint;
    if (!body.is_link || j.type == system_joint_definition::kind::fixed) continue;
    const std::string where = "bodies." + body.name + ".joint.axis";
    mpfi n2 = 0;
    for (const auto& e : j.axis)
      if (e) n2 += sqr(compiled_expression<mpfi>(*e).eval_at(x.data()));
    if (!certainly_positive(n2)) throw input_error(where + ": the axis is 0");
    if (j.along >= 0) {
      const mpfi a = compiled_expression<mpfi>(*j.axis[static_cast<std::size_t>(j.along)]).eval_at(x.data());
      j.sign = certainly_negative(a) ? -1 : 1;
    }
  }
}

/// The state at 256 bits, as the checks read it: the compiled system, q, u (the dependent
/// speeds solved), t, the tapes of the bodies and the constraints evaluated there, and (with
/// constraints) their rows A u = a and the constraint tape at u = 0.
struct state_at_256_bits {
  const system_definition& d;
  const compiled_system<mpfi>& sys;
  const vector_t<mpfi>& q;
  const vector_t<mpfi>& u;
  const mpfi& t;
  const std::vector<mpfi>& bv;
  const std::vector<mpfi>& cv;
  const matrix_t<mpfi>& A;
  const vector_t<mpfi>& a;
  const std::vector<mpfi>& w0;
};

/// Every body's expressions defined at the state; an orientation matrix a rotation (orthogonal,
/// determinant 1, R^T dR skew in every coordinate and t); masses positive; inertia tensors
/// positive semidefinite, principal moments within the triangle inequalities.
void check_bodies(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  for (std::size_t i = 0; i < d.bodies.size(); ++i) {
    const auto& bd = d.bodies[i];
    const auto& bc = sys.bodies[i];
    const std::string where = "bodies." + bd.name;
    for (const auto& c : bc.center) (void)c.value.at(bv.data());
    for (const auto& [axis, angle] : bc.rotations) (void)angle.value.at(bv.data());
    if (bd.has_matrix) {  // orthogonal with det 1, and R^T dR skew in every coordinate and t (to first order a rotation)
      mat3<mpfi> R;
      for (int k = 0; k < 9; ++k) R(k / 3, k % 3) = bc.matrix[static_cast<std::size_t>(k)].value.at(bv.data());
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          mpfi e = i == j ? mpfi(-1) : mpfi(0);
          for (int k = 0; k < 3; ++k) e += R(i, k) * R(j, k);
          if (!possibly_zero(e))
            throw input_error(where + ".orientation: not orthogonal at the state ((R R^T)(" + std::to_string(i) + ", " +
                              std::to_string(j) + ") - " + (i == j ? "1" : "0") + " = " + to_string(e) + ")");
        }
      const mpfi det = R(0, 0) * (R(1, 1) * R(2, 2) - R(1, 2) * R(2, 1)) - R(0, 1) * (R(1, 0) * R(2, 2) - R(1, 2) * R(2, 0)) +
                       R(0, 2) * (R(1, 0) * R(2, 1) - R(1, 1) * R(2, 0));
      if (!possibly_zero(mpfi(det - 1)))
        throw input_error(where + ".orientation: its determinant is " + to_string(det) + ", not 1 (a reflection)");
      for (int var = 0; var <= d.vars.coordinates; ++var) {  // the coordinates, then t
        mat3<mpfi> D = mat3<mpfi>::Zero();
        for (int k = 0; k < 9; ++k) {
          const auto& e = bc.matrix[static_cast<std::size_t>(k)];
          if (var == d.vars.coordinates) {
            if (e.dt) D(k / 3, k % 3) = e.dt.at(bv.data());
          } else {
            for (const auto& [i, de] : e.dq)
              if (i == var) D(k / 3, k % 3) = de.at(bv.data());
          }
        }
        for (int i = 0; i < 3; ++i)
          for (int j = i; j < 3; ++j) {
            mpfi e = 0;
            for (int k = 0; k < 3; ++k) e += R(k, i) * D(k, j) + D(k, i) * R(k, j);
            if (!possibly_zero(e))
              throw input_error(where + ".orientation: not a rotation near the state (R^T dR/d" +
                                (var == d.vars.coordinates ? std::string("t") : d.names[static_cast<std::size_t>(d.vars.q(var))]) +
                                " is not skew-symmetric)");
          }
      }
    }
    if (bd.is_link && !bd.mass) continue;  // a massless frame
    const mpfi mass = bc.mass.at(bv.data());
    require_in_256_bits(certainly_positive(mass), certainly_nonpositive(mass),
                        where + ".mass: must be positive (" + to_string(mass) + ")");
    // Inertia: positive semidefinite (every principal minor >= 0); principal moments: the triangle inequalities.
    mpfi I[6];
    for (std::size_t k = 0; k < 6; ++k) I[k] = bc.inertia[k].at(bv.data());
    const mpfi minors[] = {I[0], I[1], I[2], mpfi(I[0] * I[1] - I[3] * I[3]), mpfi(I[1] * I[2] - I[4] * I[4]),
                           mpfi(I[0] * I[2] - I[5] * I[5]),
                           mpfi(I[0] * (I[1] * I[2] - I[4] * I[4]) - I[3] * (I[3] * I[2] - I[4] * I[5]) +
                                I[5] * (I[3] * I[4] - I[1] * I[5]))};
    for (const mpfi& m : minors)
      if (certainly_negative(m))
        throw input_error(where + ".inertia: not positive semidefinite (a principal minor is " + to_string(m) + ")");
    if (bd.inertia[0] && !bd.inertia[3])
      for (int k = 0; k < 3; ++k) {
        const mpfi slack = I[(k + 1) % 3] + I[(k + 2) % 3] - I[k];
        if (certainly_negative(slack))
          throw input_error(where + ".inertia: principal moments must satisfy the triangle inequalities");
      }
  }
}

namespace {
/// The system compiled in T (at the working precision, for mpfi) for a definition, kept on this
/// thread for the next state of the same definition (a definition read once serves the states of
/// `appell reference`: system_model::read, above): the same tapes and constants, compiled once.
template <class T>
const compiled_system<T>& compiled_for(const std::shared_ptr<const system_definition>& def) {
  struct kept {
    std::weak_ptr<const system_definition> def;
    unsigned bits = 0;
    std::unique_ptr<const compiled_system<T>> sys;
  };
  thread_local kept k;
  const unsigned bits = mp_precision_bits();
  if (!k.sys || k.def.lock() != def || k.bits != bits) {
    auto sys = std::make_unique<const compiled_system<T>>(*def);
    k.sys = std::move(sys);
    k.def = def;
    k.bits = bits;
  }
  return *k.sys;
}

interval enclosure_in_doubles(const mpfi& x) {
  mpfr_value lo, hi;
  scalar_traits<mpfi>::to_mpfr(x, lo, hi);
  return interval(mpfr_get_d(lo, MPFR_RNDD), mpfr_get_d(hi, MPFR_RNDU));
}

/// Every matrix in a mass matrix's enclosure proved nonsingular (verified_solve's proof, which
/// holds where an interval Cholesky loses its pivots to the widths it accumulates, on long
/// chains).  The exact M is positive semidefinite (sum m Jv^T Jv + Jw^T I Jw, the inertias checked
/// positive semidefinite above), so nonsingular is positive definite.
template <class I>
bool proved_nonsingular(const matrix_t<I>& M) {
  try {
    (void)verified_solve(M, vector_t<I>(vector_t<I>::Ones(M.rows())));
    return true;
  } catch (const certification_error&) {
    return false;
  }
}

/// The mass matrix at the state proved positive definite in interval<double>: M's enclosure (the
/// system compiled in interval, at enclosures of the 256-bit state; a tree's by its recursion)
/// has a Cholesky factorization with every pivot certainly positive, which proves every symmetric
/// matrix in the enclosure positive definite, the exact M among them; or, where the pivots' widths
/// grow too wide (long chains), the enclosure is proved nonsingular (proved_nonsingular).  False
/// where it cannot tell (a singular or nearly singular M, or a state beyond double's range): then
/// the check at 256 bits decides and names the joint.  A tenth of the 256-bit check's work, which was half of a robot's state in
/// `appell reference` (docs/reference-values.md).
bool tree_mass_matrix_proved_in_doubles(const state_at_256_bits& at, const std::shared_ptr<const system_definition>& def) {
  try {
    const auto& [d, sys256, q256, u256, t256, bv, cv, A, a, w0] = at;
    const evaluation_scope<interval> scope;
    const compiled_system<interval>& sys = compiled_for<interval>(def);
    vector_t<interval> q(q256.size()), u(u256.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = enclosure_in_doubles(q256(i));
    for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = enclosure_in_doubles(u256(i));
    const appell_equations<interval> eq = system_equations<interval, interval>(sys, q, u, enclosure_in_doubles(t256));
    const int n = d.vars.speeds;
    matrix_t<interval> L = matrix_t<interval>::Zero(n, n);
    for (int k = 0; k < n; ++k) {
      interval pivot = eq.M(k, k);
      for (int j = 0; j < k; ++j) pivot -= sqr(L(k, j));
      if (!certainly_positive(pivot)) {
        const bool proved = proved_nonsingular(eq.M);
        scope.verify();
        return proved;
      }
      L(k, k) = sqrt(pivot);
      for (int i = k + 1; i < n; ++i) {
        interval x = eq.M(i, k);
        for (int j = 0; j < k; ++j) x -= L(i, j) * L(k, j);
        L(i, k) = x / L(k, k);
      }
    }
    scope.verify();
    return true;
  } catch (const std::exception&) {  // out of double's range, a tape undefined in doubles: 256 bits decide
    return false;
  }
}
}  // namespace

/// A tree's mass matrix positive definite (Cholesky with every pivot certainly positive): proved
/// in interval<double> where it can be, at 256 bits otherwise.
void check_tree_mass_matrix(const state_at_256_bits& at, const std::shared_ptr<const system_definition>& def) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // A tree's mass matrix positive definite: each joint moves some mass or inertia that the
  // joints before it do not (a link without inertial data at the end of a chain makes it singular).
  if (!d.link_order.empty() && !tree_mass_matrix_proved_in_doubles(at, def)) {
    const appell_equations<mpfi> eq = system_equations<mpfi, mpfi>(sys, q, u, t);
    const int n = d.vars.speeds;
    matrix_t<mpfi> L = matrix_t<mpfi>::Zero(n, n);
    for (int k = 0; k < n; ++k) {
      mpfi pivot = eq.M(k, k);
      for (int j = 0; j < k; ++j) pivot -= sqr(L(k, j));
      if (!certainly_positive(pivot)) {
        if (proved_nonsingular(eq.M)) return;  // hence positive definite (proved_nonsingular)
        std::string field = "coordinates." + d.names[static_cast<std::size_t>(d.vars.q(k < d.vars.coordinates ? k : 0))];
        for (const auto& bd : d.bodies)
          if (bd.is_link && bd.joint.coordinate == k) field = "bodies." + bd.name + ".joint";
        throw input_error(field + ": the mass matrix is singular at the state: this joint moves no mass or inertia "
                                  "that the joints before it do not move (a link without inertial data?)");
      }
      L(k, k) = sqrt(pivot);
      for (int i = k + 1; i < n; ++i) {
        mpfi x = eq.M(i, k);
        for (int j = 0; j < k; ++j) x -= L(i, j) * L(k, j);
        L(i, k) = x / L(k, k);
      }
    }
  }
}

/// What a refusal of a state off its constraints by at most 1e-6 adds (a state written to a few
/// digits): the remedy, with a tolerance to try (a thousand times the residual, as a power of
/// ten: the coordinates move by about |f| / |grad f|).
std::string projection_remedy(const mpfi& residual, bool projected) {
  if (projected) return "";
  const double r = std::max(std::fabs(std::strtod(lower_string(residual).c_str(), nullptr)),
                            std::fabs(std::strtod(upper_string(residual).c_str(), nullptr)));
  if (!(r <= 1e-6)) return "";  // off by more than digits: not a state on the constraint, given short
  double tol = 1e-30;
  if (r > 0) tol = std::max(1e-30, std::pow(10.0, std::ceil(std::log10(r)) + 3));
  char t[32];
  std::snprintf(t, sizeof t, "%.0e", tol);
  return std::string(" (a state given to a few digits is off a closed loop's constraints: \"project\": \"") + t +
         "\" in the scene, or --project " + t + " of eval and reference, moves it onto them and prints it; SCENES.md, "
         "\"project\")";
}

/// The state on every constraint, and the constraints independent.
void check_constraints_at_state(const state_at_256_bits& at, bool projected) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A_at, a, w0] = at;
  if (!d.constraints.empty()) {
    const int s = static_cast<int>(d.constraints.size()), n = d.vars.speeds;
    matrix_t<mpfi> A = A_at;  // eliminated below
    for (int r = 0; r < s; ++r) {
      const auto& k = d.constraints[static_cast<std::size_t>(r)];
      const std::string where = "state: constraint " + k.name;
      if (k.holonomic) {
        const mpfi f = sys.constraints[static_cast<std::size_t>(r)].f.value.at(cv.data());
        if (!possibly_zero(f))
          throw input_error(where + " does not hold: f(q, t) = " + to_string(f) + projection_remedy(f, projected));
      } else if (k.body >= 0) {
        // the direction was checked before the speeds were solved
      } else {
        (void)sys.constraints[static_cast<std::size_t>(r)].g.at(cv.data());
      }
      mpfi res = -a(r);
      for (int j = 0; j < n; ++j) res += A(r, j) * u(j);
      if (!possibly_zero(res))
        throw input_error(where + ": the speeds violate it (" +
                          std::string(k.holonomic ? "df/dt" : k.body >= 0 ? "n . v" : k.link_contact >= 0 ? "the link's velocity there" : "g") + " = " +
                          to_string(res) + ")" + projection_remedy(res, projected));
    }
    // Independence: elimination with a pivot that is certainly nonzero in each row.
    std::vector<bool> used(static_cast<std::size_t>(n), false);
    for (int r = 0; r < s; ++r) {
      int best = -1;
      double best_abs = 0;
      for (int j = 0; j < n; ++j)
        if (!used[static_cast<std::size_t>(j)] && !possibly_zero(A(r, j)) && std::abs(approx_double(A(r, j))) > best_abs) {
          best_abs = std::abs(approx_double(A(r, j)));
          best = j;
        }
      if (best < 0) {
        const system_constraint_definition& k = d.constraints[static_cast<std::size_t>(r)];
        if (k.link_contact >= 0) {  // a link's contact: name it, and the contacts before it
          std::string before;
          for (int c = 0; c < k.link_contact; ++c)
            if (d.contacts[static_cast<std::size_t>(c)].link >= 0) before += (before.empty() ? "" : ", ") + d.contacts[static_cast<std::size_t>(c)].name;
          throw input_error("contacts." + d.contacts[static_cast<std::size_t>(k.link_contact)].name + ": its constraint " + k.name +
                            " depends on the constraints before it at the state" +
                            (before.empty() ? std::string(" (the joints cannot move the link that way)")
                                            : " (with the contacts " + before + ": a closed chain through the ground at a singular pose)"));
        }
        throw input_error("constraints." + k.name + ": depends on the constraints before it at the state (or is 0 there)");
      }
      used[static_cast<std::size_t>(best)] = true;
      for (int r2 = r + 1; r2 < s; ++r2) {
        const mpfi f = A(r2, best) / A(r, best);
        for (int j = 0; j < n; ++j) A(r2, j) -= f * A(r, j);
      }
    }
  }
}

/// Each wrench fixed by the constraints' virtual work.
void check_wrenches_fixed(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // Each wrench fixed by its virtual work: the body moves in 6 independent ways
  // (J J^T nonsingular), and each of its constraints' rows is a virtual power of
  // that body alone (A_c^T in the range of J^T).
  if (!d.wrenches.empty()) {
    for (std::size_t k = 0; k < d.wrenches.size(); ++k) {
      const system_wrench_definition& wd = d.wrenches[k];
      const std::string where = "wrenches." + wd.name;
      const matrix_t<mpfi> J = point_twist_jacobian(sys, sys.wrenches[k], w0.data());
      check_body_fixes_force(d, where, wd.body, J, A, wd.constraints, "a wrench");
    }
  }
}

/// Each contact: its force fixed by the virtual work, a force at its point, its normal.
void check_contacts_at_state(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // Each contact: a body that moves in 6 independent ways (its force from the virtual work),
  // each constraint's force at the point a force alone, a normal that is not 0, and the
  // other constraints' forces orthogonal to a normal constraint's.
  if (!d.contacts.empty()) {
    for (std::size_t k = 0; k < d.contacts.size(); ++k) {
      const system_contact_definition& kd = d.contacts[k];
      const std::string where = "contacts." + kd.name;
      if (kd.link >= 0) continue;  // a link's contact: its rows are its frame's axes (read_link_contact)
      if (kd.body >= 0) {
        const matrix_t<mpfi> J = contact_twist_jacobian(sys, sys.contacts[k], w0.data());
        check_body_fixes_force(d, where, kd.body, J, A, kd.constraints, "the contact's force");
      }
      if (kd.normal < 0) {
        mpfi nn = 0;
        for (const auto& e : sys.contacts[k].direction) nn += sqr(e.at(w0.data()));
        if (!certainly_positive(nn)) throw input_error(where + ".normal: 0 at the state");
      }
      for (std::size_t i = 0; i < kd.constraints.size(); ++i) {  // unit reactions, one at a time
        vector_t<mpfi> unit = vector_t<mpfi>::Zero(static_cast<Eigen::Index>(d.constraints.size()));
        unit(kd.constraints[i]) = 1;
        const contact_force_result<mpfi> f = contact_forces<mpfi, mpfi>(sys, q, t, unit)[k];
        const std::string cname = d.constraints[static_cast<std::size_t>(kd.constraints[i])].name;
        for (int x = 0; x < 3; ++x)
          if (!possibly_zero(f.moment(x)))
            throw input_error(where + ".point: " + cname + " exerts a couple about the point (a contact transmits a "
                              "force at its point: leave pivoting or rolling constraints out of it)");
        if (kd.constraints[i] == kd.normal && !certainly_positive(kd.side > 0 ? f.normal : mpfi(-f.normal)))
          throw input_error(where + ".normal: " + cname + "'s force at the point is 0 at the state (no normal)");
        if (kd.normal >= 0 && kd.constraints[i] != kd.normal) {
          const mpfi along = f.normal;  // d_c . n for a unit reaction
          if (!possibly_zero(along))
            throw input_error(where + ".constraints: " + cname + " is not orthogonal to the normal " +
                              d.constraints[static_cast<std::size_t>(kd.normal)].name + " at the state (its force along "
                              "the normal per unit reaction: " + short_text(along) + ")");
        }
      }
    }
  }
}

/// The linearization's reference motion on the holonomic constraints, its speed not 0, its
/// range of speeds ordered, its gravity parameter not 0; a refusal kept for `linearize`.
void check_linearization_reference(const state_at_256_bits& at, system_input& in) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  if (in.linearize) try {  // the reference motion on the holonomic constraints; a nonzero speed; a range
    const linearize_input& li = *in.linearize;
    vector_t<mpfi> ql(d.vars.coordinates);
    for (int i = 0; i < d.vars.coordinates; ++i) ql(i) = value<mpfi>(li.q[static_cast<std::size_t>(i)]);
    const std::vector<mpfi> lv = sys.evaluate(sys.constraint_tape, sys.variables(ql, vector_t<mpfi>(vector_t<mpfi>::Zero(d.vars.speeds)), t));
    for (int r : li.def.holonomic_rows) {
      const mpfi f = sys.constraints[static_cast<std::size_t>(r)].f.value.at(lv.data());
      if (!possibly_zero(f))
        throw input_error("linearize.about: constraint " + d.constraints[static_cast<std::size_t>(r)].name +
                          " does not hold: f(q, t) = " + to_string(f));
    }
    const decimal_field& v = li.u[static_cast<std::size_t>(li.def.speed)];
    if (possibly_zero(value<mpfi>(v)))
      throw input_error(v.path + ": the reference speed must not be 0 (K2 and C1 come from the motion at that speed)");
    if (li.from && !certainly_less(value<mpfi>(*li.from), value<mpfi>(*li.to)))
      throw input_error("linearize.critical_speeds: from must be less than to");
    if (li.def.gravity >= 0 && possibly_zero(sys.parameters[static_cast<std::size_t>(li.def.gravity)]))
      throw input_error("linearize.gravity: the parameter is 0 (K0 is the stiffness per unit g)");
  } catch (const input_error& e) {
    in.linearize.reset();
    in.linearize_refusal = e.what();
  } catch (const certification_error& e) {
    in.linearize.reset();
    in.linearize_refusal = std::string(e.what()) + " (within 2^-256 of it: taken as exact)";
  }
}

void check_at_state(system_input& in) {
  const std::shared_ptr<const system_definition> shared = in.def;
  // At the state, at 256 bits.
  try {
    mp_precision_scope scope(256);
    const compiled_system<mpfi>& sys = compiled_for<mpfi>(shared);
    const system_definition& d = *shared;
    vector_t<mpfi> q(d.vars.coordinates), u(d.vars.speeds);
    for (int i = 0; i < d.vars.coordinates; ++i) q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
    for (int j = 0; j < d.vars.speeds; ++j) u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
    const mpfi t = value<mpfi>(in.t);
    if (in.project) {
      project_state(in, q, u);
      if (in.linearize) set_reference_motion(*in.linearize, in);  // from the projected state
    }
    for (std::size_t r = 0; r < d.constraints.size(); ++r) {  // point_velocity directions, before any solve
      const auto& kc = sys.constraints[r];
      if (kc.body < 0) continue;
      const std::vector<mpfi> cv0 = sys.evaluate(sys.constraint_tape, sys.variables(q, u, t));
      mpfi nn = 0;
      for (const auto& e : kc.direction) nn += sqr(e.at(cv0.data()));
      if (!certainly_positive(nn))
        throw input_error("constraints." + d.constraints[r].name + ".point_velocity.direction: 0 at the state");
    }
    if (!in.solved.empty()) {
      try {
        solve_dependent_speeds(sys, q, u, t, in.solved);
      } catch (const certification_error&) {
        throw input_error("solve_speeds: the constraints do not determine these speeds at the state (singular)");
      }
    }
    const std::vector<mpfi> x = sys.variables(q, u, t);
    (void)sys.evaluate(sys.kinematics_tape, x);
    const std::vector<mpfi> bv = sys.evaluate(sys.body_tape, x), cv = sys.evaluate(sys.constraint_tape, x);
    std::vector<body_state<mpfi>> states;
    expression_system<mpfi>{&sys}.bodies<mpfi>(q, u, t, states);
    const int n_constraints = static_cast<int>(d.constraints.size());
    matrix_t<mpfi> A(n_constraints, d.vars.speeds);
    vector_t<mpfi> a(n_constraints);
    std::vector<mpfi> w0;
    if (n_constraints > 0) {
      expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
      w0 = sys.evaluate(sys.constraint_tape, sys.variables(q, vector_t<mpfi>(vector_t<mpfi>::Zero(d.vars.speeds)), t));
    }
    const state_at_256_bits at{d, sys, q, u, t, bv, cv, A, a, w0};
    check_bodies(at);
    check_tree_mass_matrix(at, shared);
    check_constraints_at_state(at, in.project.has_value());
    check_wrenches_fixed(at);
    check_contacts_at_state(at);
    check_linearization_reference(at, in);
  } catch (const certification_error& e) {
    throw input_error(std::string(e.what()) + " (within 2^-256 of it: taken as exact)");
  }
}

}  // namespace appell::system_reading

// ----------------------------------------------------------------------------------------------
// Scene model "system": "project" (SCENES.md), the state moved onto the constraints at 400 bits
// and written back as 90-digit decimals; and the linearization's reference motion.
namespace appell::system_reading {

/// x as a 90-digit decimal (the midpoint of its enclosure).
std::string decimal_90(const mpfi& x) { return mpfi_mid(x).str(90, std::ios_base::scientific); }

/// "project" (SCENES.md): the state moved onto the constraints, at 400 bits.  The coordinates
/// move along the holonomic constraints' gradients taken at the given state,
/// q = q0 + W(q0) A_h(q0)^T lambda with f(q, t) = 0 (lambda by the chord iteration with
/// A_h A_h^T; the step shrinks by about the distance at each pass), then the speeds
/// orthogonally onto A(q, t) u = a(q, t) (unless solve_speeds computes them from the
/// constraints).  Written back as 90-digit decimals, which the checks that follow accept
/// or refuse as any state: the values certified are those of that state.
void project_at_400_bits(system_input& in) {
  // At 400 bits (constants and all): the 90-digit decimals it writes are then within 1e-90 of
  // the projection, far inside the 256-bit checks that follow.
  const system_definition& d = *in.def;
  const mp_precision_scope precision(400);
  const compiled_system<mpfi> sys(d);
  vector_t<mpfi> q(d.vars.coordinates), u(d.vars.speeds);
  for (int i = 0; i < d.vars.coordinates; ++i) q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
  for (int j = 0; j < d.vars.speeds; ++j) u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
  const mpfi t = value<mpfi>(in.t);
  const int s = static_cast<int>(d.constraints.size()), nq = d.vars.coordinates, n = d.vars.speeds;
  in.q_given = in.q;
  in.u_given = in.u;
  auto mids = [](vector_t<mpfi>& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = mpfi(mpfi_mid(v(i)));
  };
  std::vector<int> H;
  for (int r = 0; r < s; ++r)
    if (d.constraints[static_cast<std::size_t>(r)].holonomic) H.push_back(r);
  const int m = static_cast<int>(H.size());
  if (m > 0) {
    matrix_t<mpfi> A(s, n);
    vector_t<mpfi> a(s);
    expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
    matrix_t<mpfi> W(nq, n);
    if (d.rates_as_speeds) {
      W = matrix_t<mpfi>::Identity(nq, n);
    } else {  // q' = W u + w: W's columns from the kinematics at the unit speeds
      const expression_system<mpfi> es{&sys};
      vector_t<mpfi> e = vector_t<mpfi>::Zero(n);
      const vector_t<mpfi> w = es.qdot(q, e, t);
      for (int j = 0; j < n; ++j) {
        e(j) = 1;
        W.col(j) = es.qdot(q, e, t) - w;
        e(j) = 0;
      }
    }
    matrix_t<mpfi> Ah(m, n);
    for (int k = 0; k < m; ++k) Ah.row(k) = A.row(H[static_cast<std::size_t>(k)]);
    const matrix_t<mpfi> D = W * Ah.transpose();
    const matrix_t<mpfi> G = Ah * Ah.transpose();
    const vector_t<mpfi> q0 = q;
    vector_t<mpfi> lambda = vector_t<mpfi>::Zero(m);
    for (int pass = 0; pass < 100; ++pass) {
      q = q0 + D * lambda;
      mids(q);
      const std::vector<mpfi> cv = sys.evaluate(sys.constraint_tape, sys.variables(q, u, t));
      vector_t<mpfi> f(m);
      for (int k = 0; k < m; ++k) f(k) = sys.constraints[static_cast<std::size_t>(H[static_cast<std::size_t>(k)])].f.value.at(cv.data());
      vector_t<mpfi> step;
      try {
        step = solve(G, f);
      } catch (const certification_error&) {
        throw input_error("project: the holonomic constraints are dependent at the state (their gradients)");
      }
      mids(step);
      lambda -= step;
      mids(lambda);
      bool small = true;
      for (int k = 0; k < m; ++k)
        if (abs(mpfi_mid(step(k))) > mpfr("1e-110") * (1 + abs(mpfi_mid(lambda(k))))) small = false;
      if (small) break;
    }
    q = q0 + D * lambda;
    mids(q);
  }
  if (in.solved.empty() && s > 0) {  // the speeds: u - A^T (A A^T)^-1 (A u - a)
    matrix_t<mpfi> A(s, n);
    vector_t<mpfi> a(s);
    expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
    vector_t<mpfi> y;
    try {
      y = solve(matrix_t<mpfi>(A * A.transpose()), vector_t<mpfi>(A * u - a));
    } catch (const certification_error&) {
      throw input_error("project: the constraints are dependent at the state");
    }
    u -= A.transpose() * y;
    mids(u);
  }
  for (int i = 0; i < nq; ++i)
    if (!is_finite(q(i)))
      throw input_error("project: the projection onto the holonomic constraints does not converge from the state "
                        "(too far from them)");
  for (int i = 0; i < nq; ++i) in.q[static_cast<std::size_t>(i)].text = decimal_90(q(i));
  for (int j = 0; j < n; ++j)
    if (std::find(in.solved.begin(), in.solved.end(), j) == in.solved.end())
      in.u[static_cast<std::size_t>(j)].text = decimal_90(u(j));
}

/// The projected state (decimals) read back at the caller's precision, and the moves against
/// "project": refused when the coordinates or the speeds move farther than it.
void check_projection_moves(const system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u) {
  const system_definition& d = *in.def;
  const int nq = d.vars.coordinates, n = d.vars.speeds;
  const mpfi tol = value<mpfi>(*in.project);
  mpfi dq2 = 0, du2 = 0;
  for (int i = 0; i < nq; ++i) {
    q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
    dq2 += sqr(mpfi(q(i) - value<mpfi>(in.q_given[static_cast<std::size_t>(i)])));
  }
  for (int j = 0; j < n; ++j) {
    if (std::find(in.solved.begin(), in.solved.end(), j) != in.solved.end()) continue;
    u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
    du2 += sqr(mpfi(u(j) - value<mpfi>(in.u_given[static_cast<std::size_t>(j)])));
  }
  if (certainly_positive(mpfi(sqrt(dq2) - tol)))
    throw input_error("state: off the constraints; the projection moves the coordinates by about " + short_text(sqrt(dq2)) +
                      ", more than project = " + in.project->text);
  if (certainly_positive(mpfi(sqrt(du2) - tol)))
    throw input_error("state: off the constraints; the projection moves the speeds by about " + short_text(sqrt(du2)) +
                      ", more than project = " + in.project->text);
}

void project_state(system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u) {
  project_at_400_bits(in);
  check_projection_moves(in, q, u);
}

void set_reference_motion(linearize_input& li, const system_input& in) {
  li.q = in.q;
  li.u = in.u;
  for (const auto& [i, v] : li.about_q) li.q[static_cast<std::size_t>(i)] = v;
  for (const auto& [j, v] : li.about_u) li.u[static_cast<std::size_t>(j)] = v;
}

}  // namespace appell::system_reading

// ----------------------------------------------------------------------------------------------
// The report of `appell linearize` (models/system.hpp, linearization_text): linearize_scene<T>
// (computed in the library's generated units, one per scalar) as JSON (io/json_text.hpp's writer)
// or text, in the scalar named at run time.
namespace appell {

namespace {

template <Scalar T>
std::string report_in(const system_input& in, const std::string& format) {
  const linearization_report<T> report = linearize_scene<T>(in);
  const linearize_input& li = *in.linearize;
  const system_definition& d = *in.def;
  using P = bound_t<T>;
  const linearized_equations<T>& r = report.equations;
  const auto& spectra = report.spectra;
  const auto& speed_texts = report.speed_texts;
  const auto& critical = report.critical;
  const P from = report.from, to = report.to;
  const bool json = format == "json";
  auto number_of = [](const T& x) { return number_json(printed(x)); };
  auto bound_text = [&](const P& p) { return lower_string(detail::from_bound<T>(p)); };
  const auto& names = d.names;
  auto coordinate = [&](int i) { return names[static_cast<std::size_t>(d.vars.q(i))]; };
  const std::string speed_name = names[static_cast<std::size_t>(d.vars.u(li.def.speed))];
  const std::string g_name = li.def.gravity >= 0 ? names[static_cast<std::size_t>(li.def.gravity)] : "1";
  const auto m = static_cast<Eigen::Index>(li.def.coordinates.size());
  auto kind_name = [](const critical_speed<T>& cs) {
    return cs.kind == critical_speed<T>::zero_root ? "zero_root" : "imaginary_pair";
  };

  if (json) {
    using J = nlohmann::ordered_json;
    auto matrix = [&](const matrix_t<T>& X) {
      J rows = J::array();
      for (Eigen::Index i = 0; i < m; ++i) {
        J row = J::array();
        for (Eigen::Index j = 0; j < m; ++j) row.push_back(number_of(X(i, j)));
        rows.push_back(std::move(row));
      }
      return rows;
    };
    J j;
    j["model"] = "system";
    add_scalar_fields(j, identity_of<T>());
    J coordinates = J::array();
    for (Eigen::Index i = 0; i < m; ++i) coordinates.push_back(coordinate(li.def.coordinates[static_cast<std::size_t>(i)]));
    j["coordinates"] = std::move(coordinates);
    j["speed"] = speed_name;
    j["gravity"] = g_name;
    j["form"] = "M q'' + v C1 q' + (g K0 + v^2 K2) q = f";
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2}})
      j[name] = matrix(*X);
    J eigenvalues = J::array();
    for (std::size_t k = 0; k < spectra.size(); ++k) {
      const auto [unstable, stable] = stability_of(spectra[k]);
      J values = J::array();
      for (const auto& x : spectra[k]) {
        J v = {{"re", number_of(x.real_part)}, {"im", number_of(x.imaginary_part)}};
        if constexpr (scalar_traits<T>::is_interval) v["isolated"] = x.isolated;
        values.push_back(std::move(v));
      }
      eigenvalues.push_back({{"speed", speed_texts[k]}, {"stable", stable}, {"certainly_unstable", unstable}, {"values", std::move(values)}});
    }
    j["eigenvalues"] = std::move(eigenvalues);
    J found = J::array();
    for (const auto& cs : critical) {
      J c = {{"kind", kind_name(cs)}, {"speed", number_of(cs.speed)}};
      if constexpr (scalar_traits<T>::is_interval) c["unique"] = cs.unique;
      c["certainly_unstable_below"] = cs.unstable_below;
      c["certainly_unstable_above"] = cs.unstable_above;
      found.push_back(std::move(c));
    }
    j["critical_speeds"] = {{"from", bound_text(from)}, {"to", bound_text(to)}, {"steps", li.steps}, {"found", std::move(found)}};
    J checks = J::object();
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"stiffness_at_twice_the_speed", &r.stiffness_residual},
                                  {"damping_at_twice_the_speed", &r.damping_residual}, {"damping_at_rest", &r.damping_at_rest}})
      checks[name] = matrix(*X);
    j["checks"] = std::move(checks);
    return json_text(j, json_style::document);
  }
  std::ostringstream s;
  s << "linearized about " << speed_name << " = " << li.u[static_cast<std::size_t>(li.def.speed)].text << " in "
    << scalar_traits<T>::name << " (" << scalar_traits<T>::precision_bits() << " bits, "
    << (scalar_traits<T>::is_rigorous ? "rigorous enclosures" : "point values") << ")\n"
    << "M q'' + v C1 q' + (" << g_name << " K0 + v^2 K2) q = f,  q = (";
  for (Eigen::Index i = 0; i < m; ++i) s << (i ? ", " : "") << coordinate(li.def.coordinates[static_cast<std::size_t>(i)]);
  s << "), v = " << speed_name << "\n";
  for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2}})
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j) s << "  " << name << "(" << i + 1 << "," << j + 1 << ") = " << to_string((*X)(i, j)) << "\n";
  for (std::size_t k = 0; k < spectra.size(); ++k) {
    const auto [unstable, stable] = stability_of(spectra[k]);
    s << "eigenvalues at v = " << speed_texts[k] << (stable ? " (stable)" : unstable ? " (unstable)" : "") << ":\n";
    for (const auto& x : spectra[k])
      s << "  " << to_string((x.real_part)) << " + i " << to_string((x.imaginary_part)) << "\n";
  }
  s << "speeds in [" << bound_text(from) << ", " << bound_text(to) << "] where a real part crosses 0 (" << li.steps
    << " grid steps):\n";
  for (const auto& cs : critical)
    s << "  " << (cs.kind == critical_speed<T>::zero_root ? "a real eigenvalue through 0 (capsize-like)"
                                                          : "a pair +-i w on the imaginary axis (weave-like)")
      << ": v = " << to_string((cs.speed)) << (cs.unique ? " (unique)" : "") << "; unstable eigenvalues "
      << cs.unstable_below << " below, " << cs.unstable_above << " above\n";
  return s.str();
}

}  // namespace

std::string system_model::linearize(const model_input& in, const std::string& scalar, std::optional<unsigned> bits,
                                    const std::string& format) {
  return linearization_text(dynamic_cast<const system_input&>(in), scalar, bits, format);
}

std::string linearization_text(const system_input& in, const std::string& scalar, std::optional<unsigned> bits,
                              const std::string& format) {
  if (format != "json" && format != "text") throw input_error("--format: expected json or text, got '" + format + "'");
  if (!in.linearize)
    throw input_error(!in.linearize_refusal.empty() ? in.linearize_refusal
                                                    : "linearize: the scene has no \"linearize\" section (SCENES.md)");
#ifdef APPELL_EVAL_ONLY
  (void)scalar;
  (void)bits;
  throw input_error(left_out_message("linearize"));
#else
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) { return report_in<T>(in, format); });
#endif
}

}  // namespace appell
