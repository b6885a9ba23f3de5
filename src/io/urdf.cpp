// URDF files read as `system` scenes (appell/io/urdf.hpp): parsed with tinyxml2 (the parser
// urdfdom uses), every number kept as the decimal text written in the file.
#include "appell/io/urdf.hpp"

#include <mpfi.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "appell/io/json_text.hpp"
#include "appell/io/tables.hpp"
#include "appell/io/model.hpp"
#include "appell/models/system.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {

bool is_urdf_number(std::string_view s) {
  // is_decimal_literal's syntax (scalar/decimal.hpp), with at most 6 exponent digits
  if (s.size() > 200 || !is_decimal_literal(s)) return false;
  const auto e = s.find_first_of("eE");
  if (e == std::string_view::npos) return true;
  std::size_t digits = s.size() - e - 1;
  if (digits > 0 && (s[e + 1] == '+' || s[e + 1] == '-')) --digits;
  return digits <= 6;
}

namespace {

/// "file:LINE: <joint name="j1">" for messages.
std::string where(const std::string& file, const tinyxml2::XMLElement* e) {
  std::string s = file + ":" + std::to_string(e->GetLineNum()) + ": <" + e->Name();
  if (const char* n = e->Attribute("name")) s += " name=\"" + printable(n) + "\"";
  return s + ">";
}


std::string attribute(const std::string& file, const tinyxml2::XMLElement* e, const char* name) {
  const char* v = e->Attribute(name);
  if (!v) throw input_error(where(file, e) + ": missing the attribute " + name);
  return v;
}

std::string number(const std::string& file, const tinyxml2::XMLElement* e, const char* name) {
  std::string v = attribute(file, e, name);
  const auto b = v.find_first_not_of(" \t\r\n"), l = v.find_last_not_of(" \t\r\n");
  v = b == std::string::npos ? "" : v.substr(b, l - b + 1);
  if (!is_urdf_number(v))
    throw input_error(where(file, e) + ": " + name + "=\"" + printable(v) + "\" is not a decimal number");
  return v;
}

/// "0.1 0 -2" (an attribute of three numbers); `fallback` when the attribute is absent.
std::array<std::string, 3> triple(const std::string& file, const tinyxml2::XMLElement* e, const char* name,
                                  const std::array<std::string, 3>& fallback) {
  const char* v = e->Attribute(name);
  if (!v) return fallback;
  std::istringstream in(v);
  std::vector<std::string> parts;
  for (std::string s; in >> s;) parts.push_back(s);
  if (parts.size() != 3)
    throw input_error(where(file, e) + ": " + name + "=\"" + printable(v) + "\" is not three numbers");
  std::array<std::string, 3> out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!is_urdf_number(parts[i]))
      throw input_error(where(file, e) + ": " + name + "=\"" + printable(v) + "\": '" + printable(parts[i]) +
                        "' is not a decimal number");
    out[i] = parts[i];
  }
  return out;
}

void read_origin(const std::string& file, const tinyxml2::XMLElement* parent, std::array<std::string, 3>& xyz,
                 std::array<std::string, 3>& rpy) {
  const tinyxml2::XMLElement* o = parent->FirstChildElement("origin");
  if (!o) return;
  if (o->NextSiblingElement("origin")) throw input_error(where(file, o->NextSiblingElement("origin")) + ": a second origin");
  xyz = triple(file, o, "xyz", xyz);
  rpy = triple(file, o, "rpy", rpy);
}

bool is_zero(const std::string& d) { return decimal_sign_of_sum({{1, d}}) == 0; }

/// A parsed JSON value written back as JSON text (a number as its decimal text, exactly).
nlohmann::ordered_json json_of(const json_value& v) {
  switch (v.type) {
    case json_value::kind::null: return nullptr;
    case json_value::kind::boolean: return v.boolean;
    case json_value::kind::number: return v.text;  // as a string: the decimal exactly as written
    case json_value::kind::string: return v.text;
    case json_value::kind::array: {
      nlohmann::ordered_json a = nlohmann::ordered_json::array();
      for (const auto& x : v.items) a.push_back(json_of(x));
      return a;
    }
    default: {
      nlohmann::ordered_json o = nlohmann::ordered_json::object();
      for (const auto& m : v.members) o[m.key] = json_of(m.value);
      return o;
    }
  }
}
std::string json_value_text(const json_value& v) { return json_of(v).dump(); }

/// Whether |cos(pitch)| > floating_base_pitch_margin is proved for the decimal `pitch` (MPFI at
/// 256 bits on the decimal's exact enclosure): false near +-90 degrees, and where undecided.
bool pitch_is_regular(const std::string& pitch) {
  const mpfr_producer exact = decimal_producer(pitch);
  mpfr_t lo, hi, margin;
  mpfi_t x;
  mpfr_inits2(256, lo, hi, margin, static_cast<mpfr_ptr>(nullptr));
  mpfi_init2(x, 256);
  exact(lo, MPFR_RNDD);
  exact(hi, MPFR_RNDU);
  mpfi_interv_fr(x, lo, hi);
  mpfi_cos(x, x);
  mpfi_abs(x, x);
  mpfr_set_d(margin, floating_base_pitch_margin, MPFR_RNDU);
  mpfi_get_left(lo, x);
  const bool regular = mpfr_cmp(lo, margin) > 0;
  mpfi_clear(x);
  mpfr_clears(lo, hi, margin, static_cast<mpfr_ptr>(nullptr));
  return regular;
}

}  // namespace

urdf_robot parse_urdf(const std::string& text, const std::string& file) {
  if (text.size() > urdf_limits::bytes)
    throw input_error(file + ": larger than the limit of " + std::to_string(urdf_limits::bytes) + " bytes");
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw input_error(file + ": not XML (" + printable(doc.ErrorStr() ? doc.ErrorStr() : "", 160) + ")");
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) throw input_error(file + ": not a URDF (no element)");
  if (std::string(root->Name()) != "robot")
    throw input_error(file + ":" + std::to_string(root->GetLineNum()) + ": not a URDF (the root element is <" +
                      printable(root->Name()) + ">, not <robot>)");
  urdf_robot robot;
  if (const char* n = root->Attribute("name")) robot.name = n;
  std::set<std::string> link_names, joint_names;
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "link") {
      urdf_robot::link l;
      l.name = attribute(file, e, "name");
      l.line = e->GetLineNum();
      if (!link_names.insert(l.name).second) throw input_error(where(file, e) + ": a second link of this name");
      if (const tinyxml2::XMLElement* in = e->FirstChildElement("inertial")) {
        if (in->NextSiblingElement("inertial")) throw input_error(where(file, e) + ": two <inertial> elements");
        l.in.given = true;
        read_origin(file, in, l.in.xyz, l.in.rpy);
        const tinyxml2::XMLElement* m = in->FirstChildElement("mass");
        if (!m) throw input_error(where(file, in) + " of link \"" + printable(l.name) + "\": missing <mass>");
        l.in.mass = number(file, m, "value");
        if (decimal_sign_of_sum({{1, l.in.mass}}) < 0)
          throw input_error(where(file, m) + " of link \"" + printable(l.name) + "\": a negative mass");
        const tinyxml2::XMLElement* i = in->FirstChildElement("inertia");
        if (!i) throw input_error(where(file, in) + " of link \"" + printable(l.name) + "\": missing <inertia>");
        const char* names[6] = {"ixx", "iyy", "izz", "ixy", "iyz", "ixz"};
        for (std::size_t k = 0; k < 6; ++k) l.in.inertia[k] = number(file, i, names[k]);
        // A massless link is a frame: it carries no inertia either.  A link of mass 0 with an
        // inertia is refused rather than read as a frame (its inertia dropped without a word) or
        // as a body with a rotational inertia and no mass, which the system model does not hold.
        if (is_zero(l.in.mass) &&
            std::any_of(l.in.inertia.begin(), l.in.inertia.end(), [](const std::string& d) { return !is_zero(d); }))
          throw input_error(where(file, m) + " of link \"" + printable(l.name) +
                            "\": mass 0 with a nonzero <inertia> (a massless link is a frame and carries no inertia: give "
                            "the link its mass, or an inertia of 0)");
      }
      robot.links.push_back(std::move(l));
      if (robot.links.size() > urdf_limits::links)
        throw input_error(where(file, e) + ": more than " + std::to_string(urdf_limits::links) + " links");
    } else if (tag == "joint") {
      urdf_robot::joint j;
      j.name = attribute(file, e, "name");
      j.line = e->GetLineNum();
      if (!joint_names.insert(j.name).second) throw input_error(where(file, e) + ": a second joint of this name");
      j.type = attribute(file, e, "type");
      if (j.type == "floating" || j.type == "planar")
        throw input_error(where(file, e) + ": a " + j.type + " joint is not supported (revolute, continuous, "
                                           "prismatic and fixed are; a floating base is a \"urdf\" scene's \"base\": \"floating\")");
      if (j.type != "revolute" && j.type != "continuous" && j.type != "prismatic" && j.type != "fixed")
        throw input_error(where(file, e) + ": unknown joint type \"" + printable(j.type) +
                          "\" (revolute, continuous, prismatic, fixed)");
      if (e->FirstChildElement("mimic"))
        throw input_error(where(file, e) + ": <mimic> is not supported (a joint that follows another is a constraint)");
      const tinyxml2::XMLElement* p = e->FirstChildElement("parent");
      const tinyxml2::XMLElement* c = e->FirstChildElement("child");
      if (!p) throw input_error(where(file, e) + ": missing <parent>");
      if (!c) throw input_error(where(file, e) + ": missing <child>");
      j.parent = attribute(file, p, "link");
      j.child = attribute(file, c, "link");
      read_origin(file, e, j.xyz, j.rpy);
      if (const tinyxml2::XMLElement* a = e->FirstChildElement("axis")) j.axis = triple(file, a, "xyz", j.axis);
      if (j.type != "fixed" && is_zero(j.axis[0]) && is_zero(j.axis[1]) && is_zero(j.axis[2]))
        throw input_error(where(file, e) + ": the axis is 0");
      robot.joints.push_back(std::move(j));
    }
  }
  if (robot.links.empty()) throw input_error(file + ": a robot without links");
  // The tree: every joint between known links, a link moved by one joint at most, one root.
  std::map<std::string, const urdf_robot::joint*> parent_of;
  for (const auto& j : robot.joints) {
    for (const std::string* l : {&j.parent, &j.child})
      if (!link_names.count(*l))
        throw input_error(file + ":" + std::to_string(j.line) + ": <joint name=\"" + printable(j.name) +
                          "\">: no link named \"" + printable(*l) + "\"");
    if (j.parent == j.child)
      throw input_error(file + ":" + std::to_string(j.line) + ": <joint name=\"" + printable(j.name) +
                        "\">: a link joined to itself (a loop)");
    const auto [it, fresh] = parent_of.emplace(j.child, &j);
    if (!fresh)
      throw input_error(file + ":" + std::to_string(j.line) + ": <joint name=\"" + printable(j.name) + "\">: link \"" +
                        printable(j.child) + "\" has two parents (joints \"" + printable(it->second->name) + "\" and \"" +
                        printable(j.name) + "\"): a loop, which URDF cannot describe as a tree");
  }
  std::vector<std::string> roots;
  for (const auto& l : robot.links)
    if (!parent_of.count(l.name)) roots.push_back(l.name);
  if (roots.empty()) throw input_error(file + ": no root link (every link has a parent: a loop)");
  if (roots.size() > 1)
    throw input_error(file + ": " + std::to_string(roots.size()) + " root links (\"" + printable(roots[0]) + "\", \"" +
                      printable(roots[1]) + "\"...): the links are not one tree");
  robot.root = roots[0];
  std::vector<urdf_robot::joint> ordered;
  std::vector<std::string> frontier{robot.root};
  while (!frontier.empty()) {
    std::vector<std::string> next;
    for (const auto& l : frontier)
      for (const auto& j : robot.joints)
        if (j.parent == l) {
          ordered.push_back(j);
          next.push_back(j.child);
        }
    frontier = std::move(next);
  }
  if (ordered.size() != robot.joints.size()) {
    for (const auto& j : robot.joints)
      if (std::none_of(ordered.begin(), ordered.end(), [&](const urdf_robot::joint& x) { return x.name == j.name; }))
        throw input_error(file + ":" + std::to_string(j.line) + ": <joint name=\"" + printable(j.name) +
                          "\">: not reached from the root link \"" + printable(robot.root) + "\" (a loop)");
  }
  robot.joints = std::move(ordered);
  return robot;
}

namespace {
/// The last URDF file parsed on this thread, kept: `appell reference` reads a "urdf" scene again for
/// every state (the same text parses to the same robot; a refused text is not kept).
struct parsed_urdf_file {
  std::string path, text;
  urdf_robot robot;
};
thread_local std::optional<parsed_urdf_file> last_urdf_file;

const parsed_urdf_file& parsed_urdf(const std::string& path) {
  std::string text = read_text_file(path, urdf_limits::bytes, "the URDF file");
  if (last_urdf_file && text == last_urdf_file->text && path == last_urdf_file->path) return *last_urdf_file;
  urdf_robot robot = parse_urdf(text, path);
  last_urdf_file = parsed_urdf_file{path, std::move(text), std::move(robot)};
  return *last_urdf_file;
}
}  // namespace

urdf_robot read_urdf_file(const std::string& path) { return parsed_urdf(path).robot; }

std::map<std::string, std::string> urdf_joint_names(const urdf_robot& robot, const std::vector<std::string>& taken) {
  static const std::set<std::string> reserved{"pi", "t", "sin", "cos", "tan", "exp", "log", "sqrt", "rx", "ry", "rz"};
  std::map<std::string, std::string> out;
  std::set<std::string> used(taken.begin(), taken.end());
  for (const auto& j : robot.joints) {
    std::string s;
    for (char ch : j.name) s += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    const auto b = s.find_first_not_of('_');
    s = b == std::string::npos ? "" : s.substr(b);
    while (!s.empty() && s.back() == '_') s.pop_back();
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "joint_" + s;
    if (s.size() > 48) s.resize(48);
    if (reserved.count(s)) s += "_";
    std::string name = s;
    for (int k = 2; used.count(name) || used.count(name + "_dot"); ++k) name = s + "_" + std::to_string(k);
    used.insert(name);
    out[j.name] = name;
  }
  return out;
}

namespace {
/// The entries of the system file's "state" member, in its order: each moving joint's coordinate
/// and its rate (the options' decimal texts, "0" for a joint the options leave out).  Both
/// writers of that member (urdf_to_system, system_state_member) take them from here.
template <class F>
void for_each_state_entry(const urdf_robot& robot, const std::map<std::string, std::string>& names,
                          const urdf_scene_options& o, F&& f) {
  if (o.floating)
    for (const auto& b : floating_base_coordinates()) {
      const auto it = o.state.find(b);
      f(b, it == o.state.end() ? std::string("0") : it->second.first);
      f(b + "_dot", it == o.state.end() ? std::string("0") : it->second.second);
    }
  for (const auto& j : robot.joints) {
    if (j.type == "fixed") continue;
    const std::string& n = names.at(j.name);
    const auto it = o.state.find(j.name);
    f(n, it == o.state.end() ? std::string("0") : it->second.first);
    f(n + "_dot", it == o.state.end() ? std::string("0") : it->second.second);
  }
}
}  // namespace

namespace {
std::vector<std::string> floating_base_taken_names(const urdf_scene_options& o) {
  return o.floating ? floating_base_coordinates() : std::vector<std::string>{};
}

/// The system file's body for a floating base's k-th joint (0 to 4: the frames of no mass between
/// the ground and the root link, which hangs from the last, base_roll).
std::string floating_base_frame(std::size_t k) { return floating_base_coordinates()[k] + "_frame"; }
}  // namespace

std::string urdf_to_system(const urdf_robot& robot, const urdf_scene_options& o) {
  using json = nlohmann::ordered_json;
  if (!o.floating &&
      std::none_of(robot.joints.begin(), robot.joints.end(), [](const urdf_robot::joint& j) { return j.type != "fixed"; }))
    throw input_error("the robot \"" + printable(robot.name) + "\": no joint moves (revolute, continuous or prismatic) "
                      "and its base is fixed: nothing to compute");
  const std::map<std::string, std::string> names = urdf_joint_names(robot, floating_base_taken_names(o));
  auto list = [](const auto& a) {
    json j = json::array();
    for (const auto& x : a) j.push_back(x);
    return j;
  };
  json doc;
  doc["model"] = "system";
  json coords = json::array();
  if (o.floating)
    for (const auto& b : floating_base_coordinates()) coords.push_back(b);
  for (const auto& j : robot.joints)
    if (j.type != "fixed") coords.push_back(names.at(j.name));
  doc["coordinates"] = coords;
  doc["gravity"] = list(o.gravity);
  json bodies = json::object();
  auto inertial_of = [&](const urdf_robot::link& l, json& body) {
    if (l.in.given && !is_zero(l.in.mass)) {
      body["mass"] = l.in.mass;
      body["inertia"] = list(l.in.inertia);
      json in = json::object();
      if (!(is_zero(l.in.xyz[0]) && is_zero(l.in.xyz[1]) && is_zero(l.in.xyz[2]))) in["xyz"] = list(l.in.xyz);
      if (!(is_zero(l.in.rpy[0]) && is_zero(l.in.rpy[1]) && is_zero(l.in.rpy[2]))) in["rpy"] = list(l.in.rpy);
      if (!in.empty()) body["inertial"] = in;
    }
  };
  if (o.floating) {
    // The six joints of a free body, from the ground out: translations along the fixed axes x,
    // y, z, then the rotations about z, y, x of URDF's rpy (R = Rz(yaw) Ry(pitch) Rx(roll)); the
    // root link hangs from the last one, its frame that joint's frame.
    const auto& bases = floating_base_coordinates();
    for (std::size_t k = 0; k < bases.size(); ++k) {
      const std::array<std::string, 3> axis = k == 0 || k == 5 ? std::array<std::string, 3>{"1", "0", "0"}
                                              : k == 1 || k == 4 ? std::array<std::string, 3>{"0", "1", "0"}
                                                                 : std::array<std::string, 3>{"0", "0", "1"};
      json body = json::object();
      if (k == 5) {
        const auto& root = *std::find_if(robot.links.begin(), robot.links.end(),
                                         [&](const urdf_robot::link& x) { return x.name == robot.root; });
        inertial_of(root, body);
      }
      json joint = json::object();
      joint["name"] = bases[k];
      if (k > 0) joint["parent"] = floating_base_frame(k - 1);
      joint["type"] = k < 3 ? "prismatic" : "revolute";
      joint["coordinate"] = bases[k];
      joint["axis"] = list(axis);
      body["joint"] = joint;
      bodies[k == 5 ? robot.root : floating_base_frame(k)] = body;
    }
  }
  for (const auto& j : robot.joints) {
    const auto& l = *std::find_if(robot.links.begin(), robot.links.end(), [&](const urdf_robot::link& x) { return x.name == j.child; });
    json body = json::object();
    inertial_of(l, body);
    json joint = json::object();
    joint["name"] = names.at(j.name);
    if (j.parent != robot.root || o.floating) joint["parent"] = j.parent;
    joint["type"] = j.type == "continuous" ? "revolute" : j.type;
    if (j.type != "fixed") joint["coordinate"] = names.at(j.name);
    joint["origin"] = list(j.xyz);
    joint["rpy"] = list(j.rpy);
    if (j.type != "fixed") {
      joint["axis"] = list(j.axis);
      if (o.efforts.count(j.name)) joint["effort"] = o.efforts.at(j.name);
    }
    body["joint"] = joint;
    bodies[l.name] = body;
  }
  doc["bodies"] = bodies;
  if (!o.contacts.empty()) doc["contacts"] = json::parse(o.contacts);
  if (!o.tables.empty()) doc["tables"] = json::parse(o.tables);
  json state = json::object();
  for_each_state_entry(robot, names, o, [&](const std::string& key, const std::string& text) { state[key] = text; });
  doc["state"] = state;
  if (!o.accelerations.empty()) {
    json acc = json::object();
    if (o.floating)
      for (const auto& b : floating_base_coordinates()) acc[b + "_ddot"] = o.accelerations.at(b);
    for (const auto& j : robot.joints)
      if (j.type != "fixed") acc[names.at(j.name) + "_ddot"] = o.accelerations.at(j.name);
    doc["accelerations"] = acc;
  }
  return json_text(doc, json_style::document);  // a file a person can read: each body on a line
}

namespace {

/// The scene model "urdf": {"model": "urdf", "file": F, "base": "fixed", "gravity": [3],
/// "state": {joint: {"q": x, "q_dot": y}}, "torques": {joint: x} | "accelerations": {joint: x}}.
/// The scene's robot (its parsed file, kept: parsed_urdf) and options, checked; `file` as written.
const parsed_urdf_file& read_urdf_scene_options(object_reader& scene, std::string& file, urdf_scene_options& o) {
  file = scene.string("file");
  const parsed_urdf_file& parsed = parsed_urdf(scene_relative_path(file));
  const urdf_robot& robot = parsed.robot;
  if (scene.has("base")) {
    const std::string base = scene.string("base");
    if (base != "fixed" && base != "floating")
      throw input_error(scene.path("base") + ": \"fixed\" (the root link is the ground) or \"floating\" (it moves "
                        "freely), not \"" + printable(base) + "\"");
    o.floating = base == "floating";
  }
  if (o.floating) {
    // The base's coordinates are named as joints are: no joint or link may take their names.
    for (const auto& j : robot.joints)
      for (const auto& b : floating_base_coordinates())
        if (j.name == b)
          throw input_error(scene.path("base") + ": the URDF's joint \"" + printable(j.name) + "\" (" + file + ":" +
                            std::to_string(j.line) + ") has the name of a floating base's coordinate (" + b + ")");
    for (const auto& l : robot.links)
      for (std::size_t k = 0; k + 1 < floating_base_coordinates().size(); ++k)
        if (l.name == floating_base_frame(k))
          throw input_error(scene.path("base") + ": the URDF's link \"" + printable(l.name) + "\" (" + file + ":" +
                            std::to_string(l.line) + ") has the name of a floating base's frame");
  } else if (std::none_of(robot.joints.begin(), robot.joints.end(), [](const urdf_robot::joint& j) { return j.type != "fixed"; })) {
    throw input_error(file + ": no joint moves (revolute, continuous or prismatic) and the base is fixed: nothing to compute");
  }
  const std::vector<decimal_field> g = scene.numbers("gravity", 3);
  for (std::size_t i = 0; i < 3; ++i) o.gravity[i] = g[i].text;
  std::set<std::string> moving;
  for (const auto& j : robot.joints)
    if (j.type != "fixed") moving.insert(j.name);
  if (o.floating) moving.insert(floating_base_coordinates().begin(), floating_base_coordinates().end());
  auto joint_of = [&](const std::string& section, const std::string& name) {
    if (o.floating && section == "torques" &&
        std::count(floating_base_coordinates().begin(), floating_base_coordinates().end(), name))
      throw input_error(section + "." + name + ": a floating base's coordinate has no actuator (its joints are free)");
    if (!moving.count(name)) {
      const bool fixed = std::any_of(robot.joints.begin(), robot.joints.end(), [&](const auto& j) { return j.name == name; });
      throw input_error(section + "." + printable(name) + ": " +
                        (fixed ? "a fixed joint (it has no coordinate)" : "no joint of this name in " + file));
    }
  };
  const json_value& state = scene.raw("state");
  if (state.type != json_value::kind::object) throw input_error(scene.path("state") + ": expected an object, joint by joint");
  for (const auto& m : state.members) {
    joint_of("state", m.key);
    object_reader r(m.value, "state." + m.key);
    const decimal_field q = r.number("q"), qd = r.number("q_dot");
    r.finish();
    o.state[m.key] = {q.text, qd.text};
  }
  if (o.floating && o.state.count("base_pitch")) {
    // Roll-pitch-yaw angles are singular where cos(pitch) = 0 (gimbal lock): refused by name
    // within floating_base_pitch_margin of it (decided at 256 bits on the decimal as written).
    if (!pitch_is_regular(o.state.at("base_pitch").first))
      throw input_error("state.base_pitch: " + o.state.at("base_pitch").first +
                        " is within 1e-6 (in cos) of +-90 degrees, where a floating base's roll-pitch-yaw angles are "
                        "singular (gimbal lock: roll and yaw turn about one axis); turn the base's frame, or the "
                        "scene's axes, so that the pitch stays away from it");
  }
  for (const auto& j : moving)
    if (!o.state.count(j)) throw input_error("state: joint \"" + printable(j) + "\" is missing (q and q_dot of every moving joint)");
  o.with_state = true;
  if (scene.has("contacts")) {
    // Passed to the system file as written; its reader checks them (SCENES.md, "contacts of links").
    const json_value& c = scene.raw("contacts");
    if (c.type != json_value::kind::object) throw input_error(scene.path("contacts") + ": expected an object, contact by contact");
    o.contacts = json_value_text(c);
  }
  if (scene.has("tables")) {
    // Checked here (read_table_points), passed to the system file with a CSV file's path absolute.
    const json_value& t = scene.raw("tables");
    if (t.type != json_value::kind::object) throw input_error(scene.path("tables") + ": expected an object, table by table");
    nlohmann::ordered_json tables = json_of(t);
    for (const auto& m : t.members) {
      (void)read_table_points(m.value, scene.path("tables") + "." + printable(m.key));
      if (const json_value* csv = m.value.find("csv")) {
        tables[m.key]["csv"] = std::filesystem::absolute(scene_relative_path(csv->text)).lexically_normal().string();
      }
    }
    o.tables = tables.dump();
  }
  if (scene.has("torques") && scene.has("accelerations"))
    throw input_error("accelerations: give the torques (forward dynamics) or the accelerations (inverse dynamics), not both");
  for (const char* section : {"torques", "accelerations"}) {
    if (!scene.has(section)) continue;
    const json_value& v = scene.raw(section);
    if (v.type != json_value::kind::object) throw input_error(scene.path(section) + ": expected an object, joint by joint");
    auto& into = std::string(section) == "torques" ? o.efforts : o.accelerations;
    for (const auto& m : v.members) {
      joint_of(section, m.key);
      // A torque may be a function of time: an expression in t (a push, a controller's ramp),
      // which the system file's reader parses as the joint's effort.
      if (std::string(section) == "torques" && m.value.type == json_value::kind::string && !is_decimal_literal(m.value.text)) {
        into[m.key] = m.value.text;
        continue;
      }
      into[m.key] = decimal_text(m.value, std::string(section) + "." + m.key).text;
    }
    if (std::string(section) == "accelerations")
      for (const auto& j : moving)
        if (!o.accelerations.count(j)) throw input_error("accelerations: joint \"" + printable(j) + "\" is missing");
  }
  return parsed;
}

std::string urdf_scene_text(object_reader& scene, std::string& file) {
  urdf_scene_options o;
  return urdf_to_system(read_urdf_scene_options(scene, file, o).robot, o);
}

/// The system file `text` read (what `appell convert` prints, appell reads); input_error
/// naming `file` and the field otherwise.
/// The system file's reading; a refusal names the URDF's joint and its line where it names a
/// link's joint of the system file (`bodies.LINK.joint...`: the joint that moves LINK).
system_input read_as_system(const json_value& doc, const std::string& file, const urdf_robot* robot) {
  object_reader r(doc, "");
  (void)r.string("model");
  try {
    system_input in = system_model::read(r);
    r.finish();
    return in;
  } catch (const input_error& e) {
    const std::string what = e.what();
    if (robot)
      for (const auto& j : robot->joints) {
        const std::string path = "bodies." + j.child + ".joint";
        const auto at = what.find(path);
        const std::size_t after = at + path.size();
        if (at != std::string::npos && (after == what.size() || what[after] == ':' || what[after] == '.'))
          throw input_error(file + ":" + std::to_string(j.line) + ": <joint name=\"" + printable(j.name) + "\">" +
                            (at == 0 ? "" : " (" + what.substr(0, at) + ")") + what.substr(after));
      }
    throw input_error(file + " (read as the system file `appell convert` prints): " + what);
  }
}

system_input read_as_system(const std::string& text, const std::string& file, const urdf_robot* robot) {
  return read_as_system(parse_json(text), file, robot);
}

/// The "state" member urdf_to_system writes (its coordinates and their rates, joint by joint, as
/// strings), as parse_json reads it back; `names` is urdf_joint_names(robot).
json_value system_state_member(const urdf_robot& robot, const std::map<std::string, std::string>& names,
                               const urdf_scene_options& o) {
  json_value state;
  state.type = json_value::kind::object;
  for_each_state_entry(robot, names, o, [&](const std::string& key, const std::string& text) {
    json_value v;
    v.type = json_value::kind::string;
    v.text = text;
    state.members.push_back({key, std::move(v)});
  });
  return state;
}

/// The system document of the last "urdf" scene read on this thread: a scene of the same URDF
/// text and the same options but the state takes it with its "state" member replaced, instead of
/// writing the system file's text and parsing it again (a third of a robot's reference state).
struct kept_system_document {
  std::string path, urdf_text;
  urdf_scene_options options;  ///< its state not compared
  json_value document;
  std::map<std::string, std::string> names;  ///< urdf_joint_names of the robot
};
thread_local std::optional<kept_system_document> last_system_document;

bool same_but_state(const urdf_scene_options& a, const urdf_scene_options& b) {
  return a.gravity == b.gravity && a.efforts == b.efforts && a.accelerations == b.accelerations &&
         a.with_state == b.with_state && a.floating == b.floating && a.contacts == b.contacts &&
         a.tables == b.tables;
}

std::shared_ptr<const model_input> read_urdf_scene(object_reader& scene) {
  std::string file;
  urdf_scene_options o;
  const parsed_urdf_file& parsed = read_urdf_scene_options(scene, file, o);
  kept_system_document* kept = last_system_document ? &*last_system_document : nullptr;
  if (kept && kept->path == parsed.path && kept->urdf_text == parsed.text && same_but_state(kept->options, o)) {
    for (auto& m : kept->document.members)
      if (m.key == "state") m.value = system_state_member(parsed.robot, kept->names, o);
    return std::make_shared<system_input>(read_as_system(kept->document, file, &parsed.robot));
  }
  json_value document = parse_json(urdf_to_system(parsed.robot, o));
  std::shared_ptr<const model_input> in = std::make_shared<system_input>(read_as_system(document, file, &parsed.robot));
  last_system_document = kept_system_document{parsed.path, parsed.text, o, std::move(document),
                                              urdf_joint_names(parsed.robot, floating_base_taken_names(o))};
  return in;
}

}  // namespace

std::string urdf_scene_system_text(const json_value& scene) {
  object_reader r(scene, "");
  (void)r.string("model");
  std::string file;
  std::string out = urdf_scene_text(r, file);
  r.finish();
  return out;
}

namespace {

// `appell convert PATH` for the urdf front end: the system file of a URDF file or of a "urdf"
// scene; std::nullopt for a scene of another model, whose name goes to `other_model`.
std::optional<std::string> convert_file(const std::string& path, std::string* other_model) {
  const std::string text = read_text_file(path, urdf_limits::bytes, "a URDF file or a \"urdf\" scene");
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '<') {  // a URDF file: at rest, standard gravity
    const urdf_robot robot = parse_urdf(text, path);
    // A root link with mass is a floating base (a humanoid's pelvis) or a base bolted down (an
    // arm's): the file does not say which.  Welding it to the ground would drop its mass and
    // print another robot, so convert asks for a "urdf" scene, where "base" says it.
    const auto root = std::find_if(robot.links.begin(), robot.links.end(),
                                   [&](const urdf_robot::link& l) { return l.name == robot.root; });
    if (root != robot.links.end() && root->in.given && !is_zero(root->in.mass))
      throw input_error(path + ":" + std::to_string(root->line) + ": the root link \"" + printable(root->name) +
                        "\" has mass " + root->in.mass +
                        ": a floating base or a base bolted down, which the file does not say; convert a \"urdf\" "
                        "scene with \"base\": \"floating\" or \"fixed\" (SCENES.md)");
    if (std::none_of(robot.joints.begin(), robot.joints.end(), [](const urdf_robot::joint& j) { return j.type != "fixed"; }))
      throw input_error(path + ": no joint moves (revolute, continuous or prismatic): nothing to compute with the base fixed");
    std::string out = urdf_to_system(robot, urdf_scene_options{});
    (void)read_as_system(out, path, &robot);
    return out;
  }
  const json_value doc = parse_json(text);
  object_reader scene(doc, "");
  const std::string model = scene.string("model");
  if (model != "urdf") {
    if (other_model) *other_model = model;
    return std::nullopt;
  }
  const scene_directory_scope scope(std::filesystem::path(path).parent_path().string());
  std::string file;
  urdf_scene_options o;
  const urdf_robot& robot = read_urdf_scene_options(scene, file, o).robot;
  std::string out = urdf_to_system(robot, o);
  scene.finish();
  (void)read_as_system(out, file, &robot);
  return out;
}

}  // namespace

std::string convert_to_system(const std::string& path) {
  std::string model;
  if (std::optional<std::string> out = convert_file(path, &model)) return std::move(*out);
  throw input_error("model: convert reads a URDF file or a \"urdf\" scene, not a '" + printable(model) + "' scene");
}

const model_entry& urdf_model_entry() {
  static const model_entry entry = [] {
    model_entry e = make_model_entry<system_model>();
    e.name = "urdf";
    e.read = &read_urdf_scene;
    e.anchor_files = [](json_value& scene, const std::string& scene_directory) {
      for (auto& m : scene.members)
        if (m.key == "file" && m.value.type == json_value::kind::string && std::filesystem::path(m.value.text).is_relative())
          m.value.text = (std::filesystem::path(scene_directory) / m.value.text).string();
    };
    e.read_as_text = &urdf_scene_system_text;
    e.convert = [](const std::string& path) { return convert_file(path, nullptr); };
    e.converts = "a URDF file or a \"urdf\" scene";
    e.linearize = nullptr;  // a robot's scene names no steady motion (SCENES.md, "linearize")
    return e;
  }();
  return entry;
}

}  // namespace appell
