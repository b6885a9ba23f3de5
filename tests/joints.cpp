// Links of a tree (SCENES.md, "links of a tree") and robots from URDF:
//  * a tree's accelerations are those of the same system written with expressions (centres and
//    orientations composed by hand from the joints' data): the expression model's value at 256
//    bits lies in the tree's enclosures (interval, mpfi), over random states;
//  * a joint's wrench is the reaction of the released joint: the child a free body (six
//    coordinates), the joint five holonomic constraints, the wrench of their reactions (Cotton's,
//    equal to Lagrange's) by the virtual work -- the existing machinery, another path entirely;
//  * inverse dynamics gives back the torques forward dynamics took (URDF arm and the WAM);
//  * a URDF scene is its converted system file; bad URDF input is refused naming the element;
//  * the numbers a URDF file may hold are the language of a regular expression (std::regex, the
//    reader's test before it took is_urdf_number), on random texts.
#define BOOST_TEST_MODULE joints
#include <boost/test/unit_test.hpp>

#include <cstring>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <unistd.h>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "appell/models/system.hpp"
#include "appell/io/scene.hpp"
#include "appell/io/urdf.hpp"
#include "appell/motion/motion.hpp"
#include "bounds_400.hpp"

using namespace appell;
using testing::bounds_of;
using testing::ref_t;  // 400 bits

namespace {

std::string data(const std::string& f) { return std::string(APPELL_SOURCE_DIR + "/data/") + f; }

scene_input from_text(const std::string& text) { return read_scene(parse_json(text)); }

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// One link of a chain: its joint's data both ways (the tree's fields; elementary rotations for
/// the expression version).
struct chain_link {
  std::string name, joint, q;  // q: the coordinate ("" fixed)
  std::array<std::string, 3> origin, com;
  std::vector<std::pair<int, std::string>> R0, axis_turn, Rin;  // (axis, angle), left to right
  std::array<std::string, 3> rpy, axis, com_rpy;                // the tree's fields
  std::array<std::string, 3> unit_axis;                         // the axis normalized (expressions)
  std::string mass;
  std::array<std::string, 6> inertia;
  std::string effort;
};

/// A 3-vector of expressions turned by elementary rotations (applied right to left).
std::array<std::string, 3> turned(std::array<std::string, 3> v, const std::vector<std::pair<int, std::string>>& rs) {
  for (auto it = rs.rbegin(); it != rs.rend(); ++it) {
    const int k = it->first, i = (k + 1) % 3, j = (k + 2) % 3;
    const std::string c = "cos(" + it->second + ")", s = "sin(" + it->second + ")";
    std::array<std::string, 3> r = v;
    r[static_cast<std::size_t>(i)] = "(" + c + "*" + v[static_cast<std::size_t>(i)] + " - " + s + "*" + v[static_cast<std::size_t>(j)] + ")";
    r[static_cast<std::size_t>(j)] = "(" + s + "*" + v[static_cast<std::size_t>(i)] + " + " + c + "*" + v[static_cast<std::size_t>(j)] + ")";
    v = r;
  }
  return v;
}
std::string list(const std::array<std::string, 3>& v) { return "[\"" + v[0] + "\", \"" + v[1] + "\", \"" + v[2] + "\"]"; }
std::string product(const std::vector<std::pair<int, std::string>>& rs) {
  std::string s;
  for (const auto& [a, angle] : rs) s += std::string(s.empty() ? "" : " ") + "r" + "xyz"[a] + "(" + angle + ")";
  return s;
}

/// The two-link arm of the tests: a shoulder about z under a turned frame, an elbow about
/// (0, 1, 1) under a frame turned about two axes, both links' inertia axes turned or not.
std::vector<chain_link> arm() {
  chain_link a;
  a.name = "upper", a.joint = "shoulder", a.q = "q1";
  a.origin = {"0", "0", "0.1"}, a.rpy = {"0", "0", "0.5"}, a.R0 = {{2, "0.5"}};
  a.axis = {"0", "0", "1"}, a.unit_axis = a.axis, a.axis_turn = {{2, "q1"}};
  a.com = {"0.1", "0.01", "0.2"}, a.com_rpy = {"0.3", "0", "0"}, a.Rin = {{0, "0.3"}};
  a.mass = "1.2", a.inertia = {"0.02", "0.018", "0.005", "0.001", "0", "0.0005"};
  a.effort = "0.3";
  chain_link b;
  b.name = "fore", b.joint = "elbow", b.q = "q2";
  b.origin = {"0", "0.02", "0.4"}, b.rpy = {"1.5707963", "0", "0.2"}, b.R0 = {{2, "0.2"}, {0, "1.5707963"}};
  b.axis = {"0", "1", "1"}, b.unit_axis = {"0", "1/sqrt(2)", "1/sqrt(2)"}, b.axis_turn = {{0, "-pi/4"}, {2, "q2"}, {0, "pi/4"}};
  b.com = {"0.05", "0", "0.15"}, b.com_rpy = {"0", "0", "0"};
  b.mass = "0.8", b.inertia = {"0.01", "0.012", "0.004", "0", "0.0002", "0"};
  b.effort = "-0.1 - 0.05*q2_dot";
  return {a, b};
}

std::string state_text(const std::array<std::string, 4>& s) {
  return "\"state\": {\"q1\": \"" + s[0] + "\", \"q2\": \"" + s[1] + "\", \"q1_dot\": \"" + s[2] + "\", \"q2_dot\": \"" +
         s[3] + "\"}";
}

std::string tree_file(const std::vector<chain_link>& links, const std::array<std::string, 4>& state) {
  std::string s = "{\"model\": \"system\", \"coordinates\": [\"q1\", \"q2\"], \"gravity\": [\"0\", \"0\", \"-9.81\"], \"bodies\": {";
  for (std::size_t k = 0; k < links.size(); ++k) {
    const chain_link& l = links[k];
    s += std::string(k ? ", " : "") + "\"" + l.name + "\": {\"mass\": \"" + l.mass + "\", \"inertia\": [";
    for (std::size_t i = 0; i < 6; ++i) s += std::string(i ? ", " : "") + "\"" + l.inertia[i] + "\"";
    s += "], \"inertial\": {\"xyz\": " + list(l.com) + ", \"rpy\": " + list(l.com_rpy) + "}, \"joint\": {\"name\": \"" +
         l.joint + "\"" + (k ? ", \"parent\": \"" + links[k - 1].name + "\"" : "") + ", \"type\": \"revolute\", \"coordinate\": \"" +
         l.q + "\", \"origin\": " + list(l.origin) + ", \"rpy\": " + list(l.rpy) + ", \"axis\": " + list(l.axis) +
         ", \"effort\": \"" + l.effort + "\"}}";
  }
  return s + "}, " + state_text(state) + "}";
}

/// The same arm with centres and orientations written out; `released`: the first link free (six
/// coordinates: q1, e1, e2 turning it, x y z its centre), its joint to the ground five
/// constraints, with the wrench of their reactions at the joint's origin (the links beyond hang
/// from the free link's coordinates).
std::string expression_file(const std::vector<chain_link>& links, const std::array<std::string, 4>& state, bool released,
                            const std::string& released_state = "") {
  std::string bodies;
  std::vector<std::pair<int, std::string>> R;  // the link frame's rotations so far
  std::array<std::string, 3> O{"0", "0", "0"};  // its origin
  std::vector<std::array<std::string, 3>> axes;  // each joint's axis on the fixed axes
  std::string constraints, wrench;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const chain_link& l = links[k];
    const auto o = turned(l.origin, R);
    for (int i = 0; i < 3; ++i) O[static_cast<std::size_t>(i)] = "(" + O[static_cast<std::size_t>(i)] + " + " + o[static_cast<std::size_t>(i)] + ")";
    R.insert(R.end(), l.R0.begin(), l.R0.end());
    axes.push_back(turned(l.unit_axis, R));  // the axis, before the joint's own turn (which keeps it)
    const bool free = released && k == 0;
    auto joint_turn = l.axis_turn;
    if (free) joint_turn.insert(joint_turn.end(), {{0, "e1"}, {1, "e2"}});  // about axes normal to the joint's (z)
    R.insert(R.end(), joint_turn.begin(), joint_turn.end());
    auto body_R = R;
    body_R.insert(body_R.end(), l.Rin.begin(), l.Rin.end());
    const auto c = turned(l.com, R);
    std::array<std::string, 3> G;
    for (int i = 0; i < 3; ++i) G[static_cast<std::size_t>(i)] = "(" + O[static_cast<std::size_t>(i)] + " + " + c[static_cast<std::size_t>(i)] + ")";
    // the efforts: +tau axis on the link, -tau axis on its parent (couples, fixed axes)
    std::array<std::string, 3> couple;
    for (int i = 0; i < 3; ++i) {
      couple[static_cast<std::size_t>(i)] = "(" + l.effort + ")*" + axes[k][static_cast<std::size_t>(i)];
      if (k + 1 < links.size())
        couple[static_cast<std::size_t>(i)] += " - (" + links[k + 1].effort + ")*(" + "AXIS" + std::to_string(k + 1) + "_" + std::to_string(i) + ")";
    }
    std::string body = "\"" + l.name + "\": {\"mass\": \"" + l.mass + "\", \"inertia\": [";
    for (std::size_t i = 0; i < 6; ++i) body += std::string(i ? ", " : "") + "\"" + l.inertia[i] + "\"";
    body += "], \"center\": " + (free ? std::string("[\"x\", \"y\", \"z\"]") : list(G)) + ", \"orientation\": \"" + product(body_R) +
            "\", \"couple\": " + list(couple) + "}";
    bodies += (k ? ", " : "") + body;
    if (free) {  // the links beyond hang from the free link: its origin is (x, y, z) - R c
      const std::array<std::string, 3> P{"x", "y", "z"};
      const std::array<std::string, 3> jointO = O;
      for (int i = 0; i < 3; ++i)
        O[static_cast<std::size_t>(i)] = "(" + P[static_cast<std::size_t>(i)] + " - " + c[static_cast<std::size_t>(i)] + ")";
      wrench = "\"shoulder_joint\": {\"body\": \"" + l.name + "\", \"point\": " + list(jointO) +
               ", \"constraints\": [\"jx\", \"jy\", \"jz\", \"je1\", \"je2\"]}";
      for (int i = 0; i < 3; ++i)
        constraints += std::string(i ? ", " : "") + "\"j" + "xyz"[i] + "\": {\"holonomic\": \"" + "xyz"[i] + " - " + G[static_cast<std::size_t>(i)] + "\"}";
      constraints += ", \"je1\": {\"holonomic\": \"e1\"}, \"je2\": {\"holonomic\": \"e2\"}";
    }
  }
  // the parent's -tau axis of the next joint (placeholders filled now that the axes are known)
  for (std::size_t k = 1; k < axes.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const std::string key = "AXIS" + std::to_string(k) + "_" + std::to_string(i);
      for (std::size_t at; (at = bodies.find(key)) != std::string::npos;) bodies.replace(at, key.size(), axes[k][static_cast<std::size_t>(i)]);
    }
  std::string s = "{\"model\": \"system\", \"coordinates\": [\"q1\", \"q2\"" +
                  std::string(released ? ", \"e1\", \"e2\", \"x\", \"y\", \"z\"" : "") +
                  "], \"gravity\": [\"0\", \"0\", \"-9.81\"], \"bodies\": {" + bodies + "}";
  if (released) {
    s += ", \"constraints\": {" + constraints + "}, \"wrenches\": {" + wrench + "}";
    s += ", \"solve_speeds\": [\"e1_dot\", \"e2_dot\", \"x_dot\", \"y_dot\", \"z_dot\"], " + released_state + "}";
    return s;
  }
  return s + ", " + state_text(state) + "}";
}

template <class T>
std::pair<ref_t, ref_t> bounds(const evaluation<T>& e, const std::string& name, std::size_t i = 0) {
  return bounds_of(e.result(name).values[i]);
}

std::string decimal(const ref_t& x) {
  std::ostringstream o;
  o << std::setprecision(100) << x;
  return o.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_tree_gives_the_accelerations_of_the_system_written_with_expressions, *test::needs_scalars({"mpfr"})) {
#if APPELL_TEST_HAS(mpfr)  // the truth: the expressions in mpfr at 512 bits
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-4, 4);
  int checked = 0;
  for (int n = 0; n < 12; ++n) {
    std::ostringstream s[4];
    s[0] << angle(rng), s[1] << angle(rng), s[2] << rate(rng), s[3] << rate(rng);
    const std::array<std::string, 4> st{s[0].str(), s[1].str(), s[2].str(), s[3].str()};
    if (std::getenv("JOINTS_DUMP")) {
      std::ofstream(std::string(std::getenv("JOINTS_DUMP")) + "/tree.json") << tree_file(arm(), st);
      std::ofstream(std::string(std::getenv("JOINTS_DUMP")) + "/expr.json") << expression_file(arm(), st, false);
    }
    const scene_input tree = from_text(tree_file(arm(), st));
    const scene_input expr = from_text(expression_file(arm(), st, false));
    // the truth at 512 bits (its own rounding far below the 256-bit enclosure's width)
    const evaluation<mpfr> truth = [&] {
      const mp_precision_scope high(512);
      return evaluate<mpfr>(expr);
    }();
    const mp_precision_scope scope(256);
    const evaluation<mpfi> wide = evaluate<mpfi>(tree);
    const evaluation<interval> narrow = evaluate<interval>(tree);
    for (const char* name : {"q1_ddot", "q2_ddot"}) {
      const ref_t x = bounds(truth, name).first;
      for (const auto& [lo, hi] : {bounds(wide, name), bounds(narrow, name)}) {
        BOOST_TEST((lo <= x && x <= hi), name << " at state " << n << ": " << x << " outside [" << lo << ", " << hi << "]");
        BOOST_TEST(double(hi - lo) <= 1e-12 * std::max(1.0, double(abs(x))));
      }
      ++checked;
    }
    // the tree's own checks: eq. (4) and each joint's virtual work hold
    for (const char* c : {"virtual_work_invariant", "shoulder_virtual_work", "elbow_virtual_work"}) {
      const auto [lo, hi] = bounds_of(narrow.check(c).values[0]);
      BOOST_TEST((lo <= 0 && 0 <= hi), c);
    }
  }
  BOOST_TEST(checked == 24);
#endif
}

BOOST_AUTO_TEST_CASE(a_joint_wrench_is_the_reaction_of_the_released_joint) {
  // The shoulder released: the upper arm free (six coordinates), its joint to the ground five
  // constraints, the forearm hanging from it; the wrench of the constraints' reactions at the
  // joint's origin (fixed axes) against the tree's shoulder wrench (link axes) turned to the
  // fixed axes, less the actuator's couple (an applied couple in the released system).
  const mp_precision_scope scope(256);
  const ref_t pi = boost::math::constants::pi<ref_t>();
  (void)pi;
  auto rot = [](int axis, const ref_t& a, std::array<ref_t, 3> v) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const ref_t c = cos(a), s = sin(a), vi = v[static_cast<std::size_t>(i)], vj = v[static_cast<std::size_t>(j)];
    v[static_cast<std::size_t>(i)] = c * vi - s * vj;
    v[static_cast<std::size_t>(j)] = s * vi + c * vj;
    return v;
  };
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-4, 4);
  for (int n = 0; n < 6; ++n) {
    std::ostringstream s[4];
    s[0] << angle(rng), s[1] << angle(rng), s[2] << rate(rng), s[3] << rate(rng);
    const std::array<std::string, 4> st{s[0].str(), s[1].str(), s[2].str(), s[3].str()};
    const evaluation<mpfi> t = evaluate<mpfi>(from_text(tree_file(arm(), st)));
    const ref_t q1(st[0]);
    auto RL1 = [&](const std::array<ref_t, 3>& v) { return rot(2, ref_t("0.5") + q1, v); };
    const std::array<ref_t, 3> c = RL1({ref_t("0.1"), ref_t("0.01"), ref_t("0.2")});
    const std::string released_state = "\"state\": {\"q1\": \"" + st[0] + "\", \"q2\": \"" + st[1] +
                                       "\", \"e1\": \"0\", \"e2\": \"0\", \"x\": \"" + decimal(c[0]) + "\", \"y\": \"" +
                                       decimal(c[1]) + "\", \"z\": \"" + decimal(ref_t("0.1") + c[2]) + "\", \"q1_dot\": \"" +
                                       st[2] + "\", \"q2_dot\": \"" + st[3] + "\"}";
    const evaluation<mpfi> r = evaluate<mpfi>(from_text(expression_file(arm(), st, true, released_state)));
    // the same motion
    for (const char* name : {"q1_ddot", "q2_ddot"}) {
      const auto [lo, hi] = bounds(t, name);
      const auto [rlo, rhi] = bounds(r, name);
      BOOST_TEST((lo <= rhi && rlo <= hi), name << " at state " << n);
      BOOST_TEST(double(hi - lo) < 1e-60);
    }
    std::array<ref_t, 3> F, M;
    for (std::size_t i = 0; i < 3; ++i) {
      F[i] = bounds(t, "shoulder_force", i).first;
      M[i] = bounds(t, "shoulder_moment", i).first;
    }
    M[2] -= ref_t("0.3");  // the actuator's couple about z
    const std::array<ref_t, 3> Ff = RL1(F), Mf = RL1(M);
    for (std::size_t i = 0; i < 3; ++i) {
      const auto [flo, fhi] = bounds(r, "shoulder_joint_force", i);
      const auto [mlo, mhi] = bounds(r, "shoulder_joint_moment", i);
      BOOST_TEST(double(abs(Ff[i] - flo)) < 1e-50, "force " << i << " at state " << n << ": tree " << Ff[i] << ", released " << flo);
      BOOST_TEST(double(abs(Mf[i] - mlo)) < 1e-50, "moment " << i << " at state " << n << ": tree " << Mf[i] << ", released " << mlo);
      BOOST_TEST(double(fhi - flo) < 1e-50);
      BOOST_TEST(double(mhi - mlo) < 1e-50);
    }
    // the released joint's own checks: Cotton's reactions are Lagrange's; the wrench does their work
    for (const char* k : {"jx", "jy", "jz", "je1", "je2"}) {
      const auto [lo, hi] = bounds_of(r.check(std::string(k) + "_cotton_minus_lagrange").values[0]);
      BOOST_TEST((lo <= 0 && 0 <= hi));
    }
    BOOST_TEST(double(abs(Ff[2])) > 1);  // the arm's weight at least: not a wrench that is 0 both ways
  }
}

BOOST_AUTO_TEST_CASE(inverse_dynamics_gives_back_the_torques_forward_dynamics_took) {
  struct robot {
    std::string scene;
    std::vector<std::string> joints;
  };
  std::vector<robot> robots{{data("scenes/urdf_appell_arm.json"), {"waist", "shoulder", "elbow", "slide"}}};
  if (std::filesystem::exists("/usr/share/doc/dart/data/urdf/wam/wam.urdf"))
    robots.push_back({data("scenes/urdf_wam.json"), {"/j1", "/j2", "/j3", "/j4", "/j5", "/j6", "/j7"}});
  else
    BOOST_TEST_MESSAGE("dart-doc's WAM is not installed: the WAM is left out (scripts/deps.sh installs it)");
  for (const robot& rb : robots) {
    const mp_precision_scope scope(256);
    const scene_input fwd = read_scene_file(rb.scene);
    const evaluation<mpfi> f = evaluate<mpfi>(fwd);
    // the scene again, its torques replaced by the accelerations found (100 digits)
    std::string text = slurp(rb.scene);
    const auto at = text.find("\"torques\"");
    BOOST_REQUIRE(at != std::string::npos);
    const std::string torques = text.substr(at, text.rfind('}') - at);
    std::string acc = "\"accelerations\": {";
    const auto names = urdf_joint_names(read_urdf_file(rb.scene.find("wam") != std::string::npos
                                                           ? "/usr/share/doc/dart/data/urdf/wam/wam.urdf"
                                                           : data("urdf/appell_arm.urdf")));
    for (std::size_t k = 0; k < rb.joints.size(); ++k)
      acc += std::string(k ? ", " : "") + "\"" + rb.joints[k] + "\": \"" +
             decimal(bounds(f, names.at(rb.joints[k]) + "_ddot").first) + "\"";
    text.replace(at, torques.size(), acc + "}");
    const std::string dir = std::filesystem::path(rb.scene).parent_path().string();
    const std::string tmp = dir + "/.inverse_" + std::to_string(::getpid()) + ".json";
    std::ofstream(tmp) << text;
    scene_input inv;
    try {
      inv = read_scene_file(tmp);
    } catch (...) {
      std::filesystem::remove(tmp);
      throw;
    }
    std::filesystem::remove(tmp);
    const evaluation<mpfi> i = evaluate<mpfi>(inv);
    const std::string given = torques;
    for (const std::string& j : rb.joints) {
      const std::string n = names.at(j);
      const auto key = given.find("\"" + j + "\"");
      const auto q1 = given.find('"', given.find(':', key) + 1) + 1;
      const ref_t tau(given.substr(q1, given.find('"', q1) - q1));
      const auto [lo, hi] = bounds(i, n + "_effort");
      BOOST_TEST(double(abs(lo - tau)) < 1e-60, j << ": effort " << lo << ", torque given " << tau);
      BOOST_TEST(double(hi - lo) < 1e-60);
      for (std::size_t c = 0; c < 3; ++c)
        for (const char* w : {"_force", "_moment"}) {
          const auto [a, b] = bounds(f, n + w, c);
          const auto [x, y] = bounds(i, n + w, c);
          BOOST_TEST(double(abs(a - x)) < 1e-55, j << w << "[" << c << "]");
        }
      const auto [vlo, vhi] = bounds_of(i.check(n + "_virtual_work").values[0]);
      BOOST_TEST((vlo <= 0 && 0 <= vhi));
    }
  }
}

BOOST_AUTO_TEST_CASE(a_urdf_scene_is_its_converted_system_file) {
  const std::string scene = data("scenes/urdf_appell_arm.json");
  const std::string text = convert_to_system(scene);
  BOOST_TEST(text.find("\"model\": \"system\"") != std::string::npos);
  BOOST_TEST(text.find("\"1.5707963267948966\"") != std::string::npos);  // the URDF's decimal, as written
  const evaluation<interval> a = evaluate<interval>(read_scene_file(scene));
  const evaluation<interval> b = evaluate<interval>(from_text(text));
  BOOST_REQUIRE(a.results.size() == b.results.size());
  for (std::size_t k = 0; k < a.results.size(); ++k)
    for (std::size_t c = 0; c < a.results[k].values.size(); ++c) {
      BOOST_TEST(a.results[k].name == b.results[k].name);
      const auto [lo, hi] = bounds_of(a.results[k].values[c]);
      const auto [blo, bhi] = bounds_of(b.results[k].values[c]);
      BOOST_TEST((lo == blo && hi == bhi), a.results[k].name);
    }
  // every joint's wrench is reported (the fixed flange's too), every moving joint's check
  for (const char* j : {"waist", "shoulder", "elbow", "slide", "flange"}) {
    BOOST_CHECK_NO_THROW(a.result(std::string(j) + "_force"));
    BOOST_CHECK_NO_THROW(a.result(std::string(j) + "_moment"));
  }
  BOOST_CHECK_THROW(a.check("flange_virtual_work"), std::out_of_range);
}

// A URDF whose root link has mass is a floating base or a base bolted down; the file does not
// say which, so `appell convert` of the file refuses it, naming the link (issue 60, point 3: it
// welded DRC-Hubo's Body_TSY, 3.86 kg, to the ground without a word); a "urdf" scene says it.
BOOST_AUTO_TEST_CASE(convert_refuses_a_root_link_with_mass) {
  auto refusal = [](const std::string& path) {
    try {
      (void)convert_to_system(path);
    } catch (const input_error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  const std::string arm = refusal(data("urdf/appell_arm.urdf"));
  BOOST_TEST(arm.find("appell_arm.urdf:6: the root link \"base\" has mass 4.0: a floating base") != std::string::npos, arm);
  BOOST_TEST(arm.find("\"base\": \"floating\" or \"fixed\"") != std::string::npos, arm);
  const std::string hubo = "/usr/share/doc/dart/data/urdf/drchubo/drchubo.urdf";  // dart-doc (scripts/deps.sh)
  if (std::filesystem::exists(hubo)) {
    const std::string m = refusal(hubo);
    BOOST_TEST(m.find("the root link \"Body_TSY\" has mass 3.858") != std::string::npos, m);
  }
  // the scene says "base": "fixed": the root is the ground, as asked
  BOOST_CHECK_NO_THROW((void)convert_to_system(data("scenes/urdf_appell_arm.json")));
  // a root without mass (the WAM's "world") converts as before
  const std::string wam = "/usr/share/doc/dart/data/urdf/wam/wam.urdf";
  if (std::filesystem::exists(wam)) BOOST_CHECK_NO_THROW((void)convert_to_system(wam));
}

BOOST_AUTO_TEST_CASE(bad_urdf_input_is_refused_naming_the_element) {
  const std::string arm = slurp(data("urdf/appell_arm.urdf"));
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = arm;
    const auto at = s.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {"<robot><link name=\"a\"", "not XML"},
      {"<?xml version=\"1.0\"?><sdf/>", "not a URDF"},
      {replaced("type=\"prismatic\"", "type=\"helical\""), "unknown joint type \"helical\""},
      {replaced("type=\"prismatic\"", "type=\"floating\""), "floating joint is not supported"},
      {replaced("<axis xyz=\"0 0.6 0.8\"/>", "<axis xyz=\"0 0 0.0\"/>"), "name=\"elbow\">: the axis is 0"},
      {replaced("<axis xyz=\"0 0.6 0.8\"/>", "<axis xyz=\"0 0.6\"/>"), "not three numbers"},
      {replaced("value=\"1.7\"", "value=\"1.7kg\""), "not a decimal number"},
      {replaced("<child link=\"forearm\"/>", "<child link=\"turret\"/>"), "has two parents"},
      {replaced("<parent link=\"ram\"/>", "<parent link=\"nowhere\"/>"), "no link named \"nowhere\""},
      {replaced("<joint name=\"elbow\"", "<joint name=\"shoulder\""), "a second joint of this name"},
      {replaced("<mass value=\"0.35\"/>", "<mass value=\"-0.35\"/>"), "a negative mass"},
      // mass 0 with an inertia: refused, naming the link (issue 60, point 2: it was dropped)
      {replaced("<mass value=\"0.35\"/>", "<mass value=\"0.0\"/>"),
       "of link \"ram\": mass 0 with a nonzero <inertia>"},
  };
  const std::string dir = std::filesystem::temp_directory_path().string();
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string file = dir + "/appell_bad_" + std::to_string(::getpid()) + "_" + std::to_string(k) + ".urdf";
    std::ofstream(file) << cases[k].first;
    std::string message;
    try {
      (void)read_urdf_file(file);
    } catch (const input_error& e) {
      message = e.what();
    }
    std::filesystem::remove(file);
    BOOST_TEST(message.find(cases[k].second) != std::string::npos, "case " << k << ": \"" << message << "\"");
  }
  // a link without inertial data at the end of the chain: the mass matrix is singular
  {
    // the ram and the tool massless (mass and inertia 0): the slide moves nothing
    std::string s = arm;
    for (const char* m : {"<mass value=\"0.35\"/>", "<mass value=\"0.25\"/>"}) {
      const auto at = s.find(m);
      BOOST_REQUIRE(at != std::string::npos);
      s.replace(at, std::strlen(m), "<mass value=\"0\"/>");
    }
    for (const char* i : {"<inertia ixx=\"0.00009\" ixy=\"0\" ixz=\"0.000002\" iyy=\"0.0003\" iyz=\"0\" izz=\"0.00031\"/>",
                          "<inertia ixx=\"0.00011\" ixy=\"0.00001\" ixz=\"0\" iyy=\"0.00012\" iyz=\"0\" izz=\"0.00008\"/>"}) {
      const auto at = s.find(i);
      BOOST_REQUIRE(at != std::string::npos);
      s.replace(at, std::strlen(i), "<inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" iyy=\"0\" iyz=\"0\" izz=\"0\"/>");
    }
    const std::string file = dir + "/appell_massless_" + std::to_string(::getpid()) + ".urdf";
    std::ofstream(file) << s;
    const std::string scene = dir + "/appell_massless_" + std::to_string(::getpid()) + ".json";
    std::ofstream(scene) << "{\"model\": \"urdf\", \"file\": \"" << file << "\", \"gravity\": [0, 0, -9.81], \"state\": "
                         << "{\"waist\": {\"q\": 0, \"q_dot\": 0}, \"shoulder\": {\"q\": 0, \"q_dot\": 0}, "
                         << "\"elbow\": {\"q\": 0, \"q_dot\": 0}, \"slide\": {\"q\": 0, \"q_dot\": 0}}}";
    std::string message;
    try {
      (void)read_scene_file(scene);
    } catch (const input_error& e) {
      message = e.what();
    }
    std::filesystem::remove(file);
    std::filesystem::remove(scene);
    // named by the URDF's joint and its line, not the converted file's path (issue 60, point 11)
    BOOST_TEST(message.find(file + ":54: <joint name=\"slide\">: the mass matrix is singular") != std::string::npos, message);
    BOOST_TEST(message.find("bodies.") == std::string::npos, message);
  }
  // the scene: an unknown joint, a missing one, a fixed one given a state
  const std::string scene = slurp(data("scenes/urdf_appell_arm.json"));
  auto scene_with = [&](const std::string& from, const std::string& to) {
    std::string s = scene;
    const auto at = s.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    s.replace(at, from.size(), to);
    const std::string file = std::string(APPELL_SOURCE_DIR + "/data/scenes/.bad_") + std::to_string(::getpid()) + ".json";
    std::ofstream(file) << s;
    std::string message;
    try {
      (void)read_scene_file(file);
    } catch (const input_error& e) {
      message = e.what();
    }
    std::filesystem::remove(file);
    return message;
  };
  BOOST_TEST(scene_with("\"waist\": {", "\"wrist\": {").find("state.wrist: no joint of this name") != std::string::npos);
  BOOST_TEST(scene_with("\"waist\": {\"q\": \"0.4\", \"q_dot\": \"0.7\"},", "").find("state: joint \"waist\" is missing") !=
             std::string::npos);
  BOOST_TEST(scene_with("\"waist\": {", "\"flange\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"waist\": {")
                 .find("state.flange: a fixed joint") != std::string::npos);
  BOOST_TEST(scene_with("\"file\": \"../urdf/appell_arm.urdf\"", "\"file\": \"../urdf/none.urdf\"").find("cannot read the URDF file") !=
             std::string::npos);
}

BOOST_AUTO_TEST_CASE(urdf_numbers_are_the_regular_expressions_language) {
  // The reader's syntax of a number before is_urdf_number (a std::regex, 44% of the instructions a
  // state of `appell reference` on KR5): the same answer on random texts over the characters that
  // matter, of every length up to 14, and at the 200-character limit.
  const std::regex r(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]{1,6})?)");
  std::mt19937_64 rng(20261129);
  const std::string alphabet = "0123456789+-.eE x";
  const std::string digits = "0123456789";
  int accepted = 0, compared = 0;
  auto compare = [&](const std::string& text) {
    const bool expected = text.size() <= 200 && std::regex_match(text, r);
    BOOST_TEST(is_urdf_number(text) == expected, "'" << text << "'");
    accepted += expected;
    ++compared;
  };
  for (int i = 0; i < 200000; ++i) {
    std::string text;
    const auto length = rng() % 15;
    // half the texts mostly digits (the accepted ones are rare among uniform texts)
    const std::string& from = i % 2 ? alphabet : (rng() % 4 ? digits : alphabet);
    for (std::size_t k = 0; k < length; ++k) text += (i % 2 || rng() % 3) ? from[rng() % from.size()] : alphabet[rng() % alphabet.size()];
    compare(text);
  }
  for (const std::size_t n : {198, 199, 200, 201, 202}) {  // the length limit
    compare(std::string(n, '7'));
    compare("1." + std::string(n - 2, '5'));
    compare(std::string(n - 4, '3') + "e-12");
  }
  for (const char* text : {"1e123456", "1e1234567", "1e+123456", "-.5E-000001", "5.", ".", "+", "e5", "1e", "1e+"})
    compare(text);
  BOOST_TEST_MESSAGE(compared << " texts, " << accepted << " of them numbers");
  BOOST_TEST(accepted > 20000);  // both answers well represented
  BOOST_TEST(compared - accepted > 20000);
}

// ---------------------------------------------------------------------------------------------
// A floating base (SCENES.md, "urdf": "base": "floating"): the root link hangs from the ground
// by six joints of no mass (x, y, z, then yaw, pitch, roll).  A robot of one link is then a free
// rigid body, whose motion Newton's and Euler's equations give in closed form on the fixed axes,
// independently of the tree's recursions:
//   the centre of mass accelerates with g:   a_G = g;
//   Euler's equations:                       I_w alpha + omega x I_w omega = 0,
//                                            I_w = R Rin I Rin^T R^T;
//   the frame's origin O = G - R c:          O'' = g - alpha x Rc - omega x (omega x Rc);
//   the angles' rates (R = Rz(yaw) Ry(pitch) Rx(roll)):
//     omega = E (yaw', pitch', roll')',  E = [e_z, Rz e_y, Rz Ry e_x],
//     alpha = E (yaw'', pitch'', roll'')' + E' (yaw', pitch', roll')',
//     E' rates = pitch' yaw' (e_z x Rz e_y) + roll' ((yaw' e_z + pitch' Rz e_y) x Rz Ry e_x).
// Computed at 400 bits from the decimals as written; the tree's enclosures (interval, MPFI at 256
// bits) must hold it, over random bodies (mass, centre of mass, inertia with products, inertia
// axes) and random states.
namespace floating {

/// The refusal message of the scene `text` written to `path` and read, or "(accepted)".
std::string refusal_of(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  try {
    (void)read_scene_file(path);
  } catch (const input_error& e) {
    return std::string(e.what());
  }
  return std::string("(accepted)");
}

/// A floating base's six joints transmit nothing: each of their wrenches' enclosures holds 0.
void base_joints_transmit_nothing(const evaluation<interval>& e, const std::string& where) {
  for (const auto& base : floating_base_coordinates())
    for (const char* part : {"_force", "_moment"})
      for (std::size_t i = 0; i < 3; ++i) {
        const auto [lo, hi] = bounds(e, base + part, i);
        BOOST_TEST((lo <= 0 && 0 <= hi), base << part << "[" << i << "]" << where << ": [" << lo << ", " << hi << "]");
      }
}

/// Every joint's virtual-work check (axis . moment or force - effort) holds 0.
void virtual_work_checks_hold(const evaluation<interval>& e, const std::string& where) {
  for (const auto& c : e.checks)
    if (c.name.find("_virtual_work") != std::string::npos) {
      const auto [lo, hi] = bounds_of(c.values[0]);
      BOOST_TEST((lo <= 0 && 0 <= hi), c.name << where << ": [" << lo << ", " << hi << "]");
    }
}

using v3 = std::array<ref_t, 3>;
using m3 = std::array<v3, 3>;  // rows

v3 cross(const v3& a, const v3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
v3 mul(const m3& m, const v3& v) {
  v3 r;
  for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return r;
}
m3 mul(const m3& a, const m3& b) {
  m3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return r;
}
m3 transposed(const m3& a) {
  m3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[j][i];
  return r;
}
m3 elementary(int axis, const ref_t& angle) {
  const ref_t c = cos(angle), s = sin(angle);
  m3 r{v3{1, 0, 0}, v3{0, 1, 0}, v3{0, 0, 1}};
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  r[i][i] = c, r[i][j] = -s, r[j][i] = s, r[j][j] = c;
  return r;
}
m3 rpy(const ref_t& roll, const ref_t& pitch, const ref_t& yaw) {
  return mul(elementary(2, yaw), mul(elementary(1, pitch), elementary(0, roll)));
}
/// x solving m x = b (Cramer's rule: 3 x 3, exact enough at 400 bits).
v3 solve(const m3& m, const v3& b) {
  auto det = [](const m3& a) { return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                                      a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                                      a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]); };
  const ref_t d = det(m);
  v3 x;
  for (int k = 0; k < 3; ++k) {
    m3 c = m;
    for (int i = 0; i < 3; ++i) c[i][k] = b[i];
    x[k] = det(c) / d;
  }
  return x;
}

struct body {
  std::string mass;
  std::array<std::string, 3> com, com_rpy;
  std::array<std::string, 6> inertia;  // ixx iyy izz ixy iyz ixz
};
struct base_state {
  std::array<std::string, 6> q, qd;  // x y z yaw pitch roll
};

std::string fixed4(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", x);
  return b;
}

std::string urdf_of(const body& b) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n<robot name=\"brick\">\n  <link name=\"brick\">\n    <inertial>\n"
    << "      <origin xyz=\"" << b.com[0] << " " << b.com[1] << " " << b.com[2] << "\" rpy=\"" << b.com_rpy[0] << " "
    << b.com_rpy[1] << " " << b.com_rpy[2] << "\"/>\n      <mass value=\"" << b.mass << "\"/>\n"
    << "      <inertia ixx=\"" << b.inertia[0] << "\" iyy=\"" << b.inertia[1] << "\" izz=\"" << b.inertia[2]
    << "\" ixy=\"" << b.inertia[3] << "\" iyz=\"" << b.inertia[4] << "\" ixz=\"" << b.inertia[5] << "\"/>\n"
    << "    </inertial>\n  </link>\n</robot>\n";
  return o.str();
}

std::string scene_of(const std::string& urdf_path, const base_state& s, const std::array<std::string, 3>& g) {
  std::ostringstream o;
  o << "{\"model\": \"urdf\", \"file\": \"" << urdf_path << "\", \"base\": \"floating\", \"gravity\": [\"" << g[0]
    << "\", \"" << g[1] << "\", \"" << g[2] << "\"], \"state\": {";
  for (int k = 0; k < 6; ++k)
    o << (k ? ", " : "") << "\"" << floating_base_coordinates()[k] << "\": {\"q\": \"" << s.q[k] << "\", \"q_dot\": \""
      << s.qd[k] << "\"}";
  o << "}}";
  return o.str();
}

/// (x'', y'', z'', yaw'', pitch'', roll'') of the free body, from Newton's and Euler's equations.
std::array<ref_t, 6> newton_euler(const body& b, const base_state& s, const std::array<std::string, 3>& g) {
  auto r = [](const std::string& d) { return ref_t(d); };
  const ref_t yaw = r(s.q[3]), pitch = r(s.q[4]), roll = r(s.q[5]);
  const ref_t yd = r(s.qd[3]), pd = r(s.qd[4]), rd = r(s.qd[5]);
  const m3 R = rpy(roll, pitch, yaw);
  const m3 Rin = rpy(r(b.com_rpy[0]), r(b.com_rpy[1]), r(b.com_rpy[2]));
  const ref_t ixx = r(b.inertia[0]), iyy = r(b.inertia[1]), izz = r(b.inertia[2]);
  const ref_t ixy = r(b.inertia[3]), iyz = r(b.inertia[4]), ixz = r(b.inertia[5]);
  const m3 I{v3{ixx, ixy, ixz}, v3{ixy, iyy, iyz}, v3{ixz, iyz, izz}};
  const m3 Iw = mul(mul(R, Rin), mul(I, transposed(mul(R, Rin))));
  const v3 ez{0, 0, 1};
  const v3 e2 = mul(elementary(2, yaw), v3{0, 1, 0});
  const v3 e3 = mul(mul(elementary(2, yaw), elementary(1, pitch)), v3{1, 0, 0});
  v3 omega, edot;
  for (int i = 0; i < 3; ++i) omega[i] = ez[i] * yd + e2[i] * pd + e3[i] * rd;
  const v3 a1 = cross(ez, e2);
  v3 w2;
  for (int i = 0; i < 3; ++i) w2[i] = yd * ez[i] + pd * e2[i];
  const v3 a2 = cross(w2, e3);
  for (int i = 0; i < 3; ++i) edot[i] = pd * yd * a1[i] + rd * a2[i];
  const v3 h = cross(omega, mul(Iw, omega));
  v3 minus_h;
  for (int i = 0; i < 3; ++i) minus_h[i] = -h[i];
  const v3 alpha = solve(Iw, minus_h);
  const v3 c = mul(R, v3{r(b.com[0]), r(b.com[1]), r(b.com[2])});
  const v3 t1 = cross(alpha, c), t2 = cross(omega, cross(omega, c));
  std::array<ref_t, 6> out;
  for (int i = 0; i < 3; ++i) out[i] = r(g[i]) - t1[i] - t2[i];
  v3 rhs;
  for (int i = 0; i < 3; ++i) rhs[i] = alpha[i] - edot[i];
  const m3 E{v3{ez[0], e2[0], e3[0]}, v3{ez[1], e2[1], e3[1]}, v3{ez[2], e2[2], e3[2]}};
  const v3 rates = solve(E, rhs);
  for (int i = 0; i < 3; ++i) out[3 + i] = rates[i];
  return out;
}

}  // namespace floating

BOOST_AUTO_TEST_CASE(a_floating_body_moves_as_newton_and_euler_say) {
  using namespace floating;
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> u(-1, 1), principal(1.5, 2.0), product(-0.05, 0.05), mass(0.5, 20);
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_floating_brick_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene = dir + "/appell_floating_brick_" + std::to_string(::getpid()) + ".json";
  int checked = 0;
  double worst_double = 0;
  for (int n = 0; n < 40; ++n) {
    body b;
    b.mass = fixed4(mass(rng));
    for (int i = 0; i < 3; ++i) b.com[i] = fixed4(0.3 * u(rng)), b.com_rpy[i] = fixed4(3 * u(rng));
    for (int i = 0; i < 3; ++i) b.inertia[i] = fixed4(principal(rng)), b.inertia[3 + i] = fixed4(product(rng));
    base_state s;
    for (int k = 0; k < 6; ++k) s.q[k] = fixed4(k == 4 ? 1.5 * u(rng) : 3 * u(rng)), s.qd[k] = fixed4(4 * u(rng));
    const std::array<std::string, 3> g{fixed4(u(rng)), fixed4(u(rng)), fixed4(-9.81 + u(rng))};
    std::ofstream(urdf) << urdf_of(b);
    std::ofstream(scene) << scene_of(urdf, s, g);
    const std::array<ref_t, 6> truth = newton_euler(b, s, g);
    const scene_input in = read_scene_file(scene);
    const evaluation<interval> narrow = evaluate<interval>(in);
    const evaluation<double> point = evaluate<double>(in);
    const mp_precision_scope scope(256);
    const evaluation<mpfi> wide = evaluate<mpfi>(in);
    for (int k = 0; k < 6; ++k) {
      const std::string name = floating_base_coordinates()[k] + "_ddot";
      const ref_t& x = truth[k];
      for (const auto& [lo, hi] : {bounds(wide, name), bounds(narrow, name)}) {
        BOOST_TEST((lo <= x && x <= hi), name << " at body " << n << ": " << x << " outside [" << lo << ", " << hi << "]");
        BOOST_TEST(double(hi - lo) <= 1e-11 * std::max(1.0, double(abs(x))), name << " at body " << n);
      }
      const double d = std::abs(point.result(name).values[0] - double(x)) / std::max(1.0, double(abs(x)));
      worst_double = std::max(worst_double, d);
      ++checked;
    }
    // the six joints of a free base transmit nothing: each wrench's enclosure holds 0
    base_joints_transmit_nothing(narrow, " at body " + std::to_string(n));
  }
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene);
  BOOST_TEST(checked == 240);
  BOOST_TEST(worst_double <= 1e-12, "double's largest relative error " << worst_double);
  BOOST_TEST_MESSAGE("a free body: 240 accelerations enclosed; double within " << worst_double);
}

// Roll-pitch-yaw angles are singular at a pitch of +-90 degrees: a state within the margin is
// refused naming the field; the base's coordinates cannot be driven, and no URDF joint may take
// their names.
BOOST_AUTO_TEST_CASE(a_floating_base_refuses_its_singular_pitch_and_its_names_taken) {
  using namespace floating;
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_floating_refusals_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene = dir + "/appell_floating_refusals_" + std::to_string(::getpid()) + ".json";
  body b{"2", {"0", "0", "0"}, {"0", "0", "0"}, {"1", "1", "1", "0", "0", "0"}};
  std::ofstream(urdf) << urdf_of(b);
  auto refusal = [&](const std::string& text) { return refusal_of(scene, text); };
  base_state s{{"0", "0", "0", "0", "0", "0"}, {"0", "0", "0", "0", "0", "0"}};
  const std::array<std::string, 3> g{"0", "0", "-9.81"};
  BOOST_TEST(refusal(scene_of(urdf, s, g)) == "(accepted)");
  for (const char* pitch : {"1.5707963", "-1.57079632679489661923", "4.712388980384689"}) {
    s.q[4] = pitch;
    const std::string m = refusal(scene_of(urdf, s, g));
    BOOST_TEST(m.find("state.base_pitch: ") == 0, m);
    BOOST_TEST(m.find("gimbal lock") != std::string::npos, m);
  }
  s.q[4] = "1.57";  // cos = 8e-4: accepted, a regular (if ill-conditioned) state
  BOOST_TEST(refusal(scene_of(urdf, s, g)) == "(accepted)");
  s.q[4] = "0";
  std::string text = scene_of(urdf, s, g);
  text.insert(text.size() - 1, ", \"torques\": {\"base_z\": \"1\"}");
  BOOST_TEST(refusal(text).find("torques.base_z: a floating base's coordinate has no actuator") == 0, refusal(text));
  text = scene_of(urdf, s, g);
  const auto at = text.find("\"floating\"");
  BOOST_REQUIRE(at != std::string::npos);
  BOOST_TEST(refusal(text.replace(at, 10, "\"free\"")).find("base: \"fixed\" (the root link is the ground) or \"floating\"") == 0);
  // a fixed base with no joint that moves: nothing to compute
  text = scene_of(urdf, s, g);
  BOOST_TEST(refusal(text.replace(text.find("\"floating\""), 10, "\"fixed\"")).find("no joint moves") != std::string::npos);
  // a missing base coordinate is a missing joint
  text = scene_of(urdf, s, g);
  const auto from = text.find(", \"base_roll\"");
  BOOST_TEST(refusal(text.erase(from, text.find('}', from) + 1 - from)).find("state: joint \"base_roll\" is missing") == 0);
  // a URDF joint named as a base coordinate
  std::ofstream(urdf) << "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" "
                         "izz=\"1\" ixy=\"0\" iyz=\"0\" ixz=\"0\"/></inertial></link><link name=\"b\"><inertial><mass "
                         "value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" iyz=\"0\" ixz=\"0\"/></inertial>"
                         "</link><joint name=\"base_yaw\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>"
                         "<axis xyz=\"0 0 1\"/></joint></robot>";
  const std::string named = refusal(scene_of(urdf, s, g));
  BOOST_TEST(named.find("base: the URDF's joint \"base_yaw\"") == 0, named);
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene);
}

// A floating body's motion (the library's simulate and enclose): with no force but gravity, its
// centre of mass moves on the parabola G0 + V0 t + g t^2 / 2 and its angular momentum about the
// centre of mass, I_w omega on the fixed axes, keeps its initial value.  Both computed here from
// each row's state (G = O + R c, V_G = O' + omega x R c, omega = E rates), in MPFI at 256 bits
// over every enclosed step's box at its end (the truth at t1 must lie inside), and in 400 bits
// from simulate's double rows (within double's rounding).
namespace floating {

/// Keeps, per row of one table, t1 (or t) and each named column's text.
struct kept_rows final : motion::row_sink {
  std::string table;
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  explicit kept_rows(std::string t) : table(std::move(t)) {}
  void columns(const std::string& t, const std::vector<std::string>& n) override {
    if (t == table) names = n;
  }
  void row(const std::string& t, const std::vector<std::string>& cells) override {
    if (t == table) rows.push_back(cells);
  }
  std::size_t at(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    BOOST_REQUIRE(it != names.end());
    return static_cast<std::size_t>(it - names.begin());
  }
};

/// The centre of mass, its velocity and the angular momentum about it, on the fixed axes, of the
/// body b at base coordinates q and rates qd (any scalar with cos, sin: ref_t, mpfi).
template <class S>
struct free_body_state {
  std::array<S, 3> G, V, L;
};
template <class S>
free_body_state<S> momenta(const body& b, const std::array<S, 6>& q, const std::array<S, 6>& qd) {
  using a3 = std::array<S, 3>;
  using n3 = std::array<a3, 3>;
  auto mulm = [](const n3& x, const n3& y) {
    n3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r[i][j] = x[i][0] * y[0][j] + x[i][1] * y[1][j] + x[i][2] * y[2][j];
    return r;
  };
  auto mulv = [](const n3& x, const a3& v) {
    a3 r;
    for (int i = 0; i < 3; ++i) r[i] = x[i][0] * v[0] + x[i][1] * v[1] + x[i][2] * v[2];
    return r;
  };
  auto crossv = [](const a3& x, const a3& y) {
    return a3{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto elem = [](int axis, const S& angle) {
    const S c = cos(angle), s = sin(angle);
    n3 r{a3{S(1), S(0), S(0)}, a3{S(0), S(1), S(0)}, a3{S(0), S(0), S(1)}};
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    r[i][i] = c, r[i][j] = -s, r[j][i] = s, r[j][j] = c;
    return r;
  };
  auto d = [](const std::string& x) { return S(x); };
  const n3 Rz = elem(2, q[3]), RzRy = mulm(Rz, elem(1, q[4])), R = mulm(RzRy, elem(0, q[5]));
  const n3 Rin = mulm(elem(2, d(b.com_rpy[2])), mulm(elem(1, d(b.com_rpy[1])), elem(0, d(b.com_rpy[0]))));
  const n3 I{a3{d(b.inertia[0]), d(b.inertia[3]), d(b.inertia[5])}, a3{d(b.inertia[3]), d(b.inertia[1]), d(b.inertia[4])},
             a3{d(b.inertia[5]), d(b.inertia[4]), d(b.inertia[2])}};
  const n3 A = mulm(R, Rin);
  n3 At;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) At[i][j] = A[j][i];
  const n3 Iw = mulm(A, mulm(I, At));
  const a3 e2 = mulv(Rz, a3{S(0), S(1), S(0)}), e3 = mulv(RzRy, a3{S(1), S(0), S(0)});
  a3 omega;
  for (int i = 0; i < 3; ++i) omega[i] = (i == 2 ? qd[3] : S(0)) + e2[i] * qd[4] + e3[i] * qd[5];
  const a3 c = mulv(R, a3{d(b.com[0]), d(b.com[1]), d(b.com[2])});
  const a3 wc = crossv(omega, c);
  free_body_state<S> out;
  const S m = d(b.mass);
  const a3 Lw = mulv(Iw, omega);
  for (int i = 0; i < 3; ++i) out.G[i] = q[i] + c[i], out.V[i] = qd[i] + wc[i], out.L[i] = Lw[i];
  (void)m;
  return out;
}

}  // namespace floating

BOOST_AUTO_TEST_CASE(a_floating_body_keeps_its_momenta_along_its_motion) {
  using namespace floating;
  const body b{"3.5", {"0.12", "-0.07", "0.05"}, {"0.3", "-0.2", "0.9"}, {"1.6", "1.9", "1.75", "0.03", "-0.04", "0.02"}};
  base_state s{{"0.1", "-0.2", "1.0", "0.3", "-0.25", "0.4"}, {"0.5", "-0.3", "2.0", "1.1", "-0.7", "1.6"}};
  const std::array<std::string, 3> g{"0", "0", "-9.81"};
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_floating_motion_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene_path = dir + "/appell_floating_motion_" + std::to_string(::getpid()) + ".json";
  std::ofstream(urdf) << urdf_of(b);
  std::ofstream(scene_path) << scene_of(urdf, s, g);
  const scene_input scene = read_scene_file(scene_path);
  // the truth at t = 0, at 400 bits
  std::array<ref_t, 6> q0, qd0;
  for (int k = 0; k < 6; ++k) q0[k] = ref_t(s.q[k]), qd0[k] = ref_t(s.qd[k]);
  const free_body_state<ref_t> start = momenta<ref_t>(b, q0, qd0);
  auto truth_at = [&](const ref_t& t) {
    free_body_state<ref_t> x = start;
    for (int i = 0; i < 3; ++i) {
      x.G[i] = start.G[i] + start.V[i] * t + ref_t(g[i]) * t * t / 2;
      x.V[i] = start.V[i] + ref_t(g[i]) * t;
    }
    return x;
  };
  const std::vector<std::string>& bases = floating_base_coordinates();
  // enclose over [0, 1] in interval: every step's end box holds the truth
  {
    motion::settings set;
    set.t_end = "1";
    kept_rows rows("steps");
    const motion::enclose_report r = motion::enclose(scene, set, rows);
    BOOST_TEST_REQUIRE(r.complete, r.reason);
    BOOST_TEST(rows.rows.size() >= 5u);
    const mp_precision_scope scope(256);
    int held = 0;
    for (const auto& row : rows.rows) {
      std::array<mpfi, 6> q, qd;
      for (int k = 0; k < 6; ++k) {
        auto box = [&](const std::string& name) {
          return mpfi_from_bounds(mpfr(std::stod(row[rows.at(name + "_lo")])), mpfr(std::stod(row[rows.at(name + "_hi")])));
        };
        q[k] = box(bases[k]), qd[k] = box(bases[k] + "_dot");
      }
      const ref_t t1(std::stod(row[rows.at("t1")]));
      const free_body_state<mpfi> x = momenta<mpfi>(b, q, qd);
      const free_body_state<ref_t> truth = truth_at(t1);
      for (int i = 0; i < 3; ++i)
        for (const auto& [what, enc, tv] : {std::tuple{"G", x.G[i], truth.G[i]}, std::tuple{"V_G", x.V[i], truth.V[i]},
                                            std::tuple{"L", x.L[i], truth.L[i]}}) {
          const auto [lo, hi] = bounds_of(enc);
          BOOST_TEST((lo <= tv && tv <= hi), what << "[" << i << "] at t1 = " << t1 << ": " << tv << " outside [" << lo
                                                  << ", " << hi << "]");
          BOOST_TEST(double(hi - lo) < 1e-6, what << "[" << i << "] at t1 = " << t1 << " is " << double(hi - lo) << " wide");
          ++held;
        }
    }
    BOOST_TEST_MESSAGE("a free body enclosed to t = 1 in " << rows.rows.size() << " steps: " << held
                                                           << " momenta and positions hold their truth");
  }
  // simulate in double: every row within double's rounding of the truth
  {
    motion::settings set;
    set.t_end = "1";
    set.every = "0.05";
    kept_rows rows("trajectory");
    const motion::simulate_report r = motion::simulate(scene, set, rows);
    BOOST_TEST_REQUIRE(r.failure.empty(), r.failure);
    BOOST_TEST(rows.rows.size() == 21u);
    double worst = 0;
    for (const auto& row : rows.rows) {
      std::array<ref_t, 6> q, qd;
      for (int k = 0; k < 6; ++k) q[k] = ref_t(row[rows.at(bases[k])]), qd[k] = ref_t(row[rows.at(bases[k] + "_dot")]);
      const ref_t t(row[rows.at("t")]);
      const free_body_state<ref_t> x = momenta<ref_t>(b, q, qd), truth = truth_at(t);
      for (int i = 0; i < 3; ++i)
        worst = std::max({worst, double(abs(x.G[i] - truth.G[i])), double(abs(x.V[i] - truth.V[i])),
                          double(abs(x.L[i] - truth.L[i]))});
    }
    BOOST_TEST(worst < 1e-11, "simulate's largest error in G, V_G, L: " << worst);
    BOOST_TEST_MESSAGE("simulate in double: G, V_G and L within " << worst << " of their truth over 21 rows");
  }
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene_path);
}

// ---------------------------------------------------------------------------------------------
// Contacts of links (SCENES.md, "contacts of links"): a link held by the ground at a point or by
// a flat rectangular sole; the constraints' reactions are the contact's force (and the sole's
// couple) on the contact frame's axes.  Truth in closed form, derived here without the tree:
//  * a block standing on its sole with an arm hinged on top (the block held, the arm swinging
//    under a torque): the arm's hinge equation gives theta''; the whole system's momentum gives
//    the sole's wrench, F = m_a a_A - (m_b + m_a) g and, about the sole's centre O,
//    M = r_A x m_a a_A + I_yy theta'' e_y - r_B x m_b g - r_A x m_a g;  the centre of pressure
//    (-M_y / F_z, M_x / F_z), and whether the sole holds (its wrench cone) or tips;
//  * a block at rest on one corner (a point contact): it turns about the corner,
//    alpha = I_O^-1 (r x m g), and the ground pushes F = m (alpha x r) - m g.
namespace contact_truth {

using floating::v3;
using floating::m3;

struct block_and_arm {
  std::string mb = "12", hb = "0.15", mb_i[3] = {"0.09", "0.11", "0.07"};
  std::string ma = "1.5", cx = "0.08", cz = "0.25", ia[3] = {"0.012", "0.015", "0.004"};
  std::string X = "0.2", Y = "0.12", mu = "0.6";
};

std::string block_arm_urdf(const block_and_arm& b) {
  std::ostringstream o;
  o << "<robot name=\"block_arm\">\n"
    << "  <link name=\"block\"><inertial><origin xyz=\"0 0 " << b.hb << "\"/><mass value=\"" << b.mb << "\"/>"
    << "<inertia ixx=\"" << b.mb_i[0] << "\" iyy=\"" << b.mb_i[1] << "\" izz=\"" << b.mb_i[2]
    << "\" ixy=\"0\" iyz=\"0\" ixz=\"0\"/></inertial></link>\n"
    << "  <link name=\"arm\"><inertial><origin xyz=\"" << b.cx << " 0 " << b.cz << "\"/><mass value=\"" << b.ma << "\"/>"
    << "<inertia ixx=\"" << b.ia[0] << "\" iyy=\"" << b.ia[1] << "\" izz=\"" << b.ia[2]
    << "\" ixy=\"0\" iyz=\"0\" ixz=\"0\"/></inertial></link>\n"
    << "  <joint name=\"hinge\" type=\"continuous\"><parent link=\"block\"/><child link=\"arm\"/>"
    << "<origin xyz=\"0 0 0.3\"/><axis xyz=\"0 1 0\"/></joint>\n</robot>\n";
  return o.str();
}

std::string block_arm_scene(const std::string& urdf, const block_and_arm& b, const std::string& yaw, const std::string& theta,
                            const std::string& theta_dot, const std::string& tau) {
  std::ostringstream o;
  o << "{\"model\": \"urdf\", \"file\": \"" << urdf << "\", \"base\": \"floating\", \"gravity\": [\"0\", \"0\", \"-9.81\"],"
    << " \"state\": {\"base_x\": {\"q\": \"0.4\", \"q_dot\": \"0\"}, \"base_y\": {\"q\": \"-1.2\", \"q_dot\": \"0\"},"
    << " \"base_z\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_yaw\": {\"q\": \"" << yaw << "\", \"q_dot\": \"0\"},"
    << " \"base_pitch\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_roll\": {\"q\": \"0\", \"q_dot\": \"0\"},"
    << " \"hinge\": {\"q\": \"" << theta << "\", \"q_dot\": \"" << theta_dot << "\"}},"
    << " \"torques\": {\"hinge\": \"" << tau << "\"},"
    << " \"contacts\": {\"sole\": {\"link\": \"block\", \"type\": \"surface\", \"sole\": {\"center\": [\"0\", \"0\", \"0\"],"
    << " \"half_lengths\": [\"" << b.X << "\", \"" << b.Y << "\"]}, \"mu\": \"" << b.mu << "\"}}}";
  return o.str();
}

struct sole_truth {
  ref_t theta_ddot;
  v3 F, M;
};

/// The closed form above, on the block's axes (= the sole's; gravity (0, 0, -9.81) there: the
/// block stands upright, turned about z only).
sole_truth block_arm_truth(const block_and_arm& b, const std::string& theta_s, const std::string& theta_dot_s,
                           const std::string& tau_s) {
  using floating::cross;
  const ref_t mb(b.mb), hb(b.hb), ma(b.ma), cx(b.cx), cz(b.cz), iyy(b.ia[1]), g("9.81");
  const ref_t th(theta_s), thd(theta_dot_s), tau(tau_s);
  const v3 p{0, 0, ref_t("0.3")};
  const m3 Ry = floating::elementary(1, th);
  const v3 c = floating::mul(Ry, v3{cx, 0, cz});  // pivot to the arm's centre
  v3 rA;
  for (int i = 0; i < 3; ++i) rA[i] = p[i] + c[i];
  const v3 gv{0, 0, -g};
  // the hinge: (Iyy + ma |c|^2) theta'' = tau + (c x ma g)_y
  const v3 cg = cross(c, gv);
  const ref_t Ip = iyy + ma * (cx * cx + cz * cz);
  sole_truth t;
  t.theta_ddot = (tau + ma * cg[1]) / Ip;
  const v3 alpha{0, t.theta_ddot, 0}, omega{0, thd, 0};
  const v3 a1 = cross(alpha, c), a2 = cross(omega, cross(omega, c));
  v3 aA;
  for (int i = 0; i < 3; ++i) aA[i] = a1[i] + a2[i];
  for (int i = 0; i < 3; ++i) t.F[i] = ma * aA[i] - (mb + ma) * gv[i];
  v3 maA, mag, mbg;
  for (int i = 0; i < 3; ++i) maA[i] = ma * aA[i], mag[i] = ma * gv[i], mbg[i] = mb * gv[i];
  const v3 rB{0, 0, hb};
  const v3 h1 = cross(rA, maA), h2 = cross(rB, mbg), h3 = cross(rA, mag);
  for (int i = 0; i < 3; ++i) t.M[i] = h1[i] - h2[i] - h3[i] + (i == 1 ? iyy * t.theta_ddot : ref_t(0));
  return t;
}

}  // namespace contact_truth

BOOST_AUTO_TEST_CASE(a_block_on_its_sole_carries_the_wrench_newton_and_euler_give) {
  using namespace contact_truth;
  const block_and_arm b;
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_block_arm_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene = dir + "/appell_block_arm_" + std::to_string(::getpid()) + ".json";
  std::ofstream(urdf) << block_arm_urdf(b);
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-3, 3), torque(-40, 40);
  int holds = 0, fails = 0, checked = 0;
  for (int n = 0; n < 30; ++n) {
    const std::string yaw = floating::fixed4(angle(rng)), theta = floating::fixed4(angle(rng)),
                      theta_dot = floating::fixed4(rate(rng)), tau = floating::fixed4(torque(rng));
    std::ofstream(scene) << block_arm_scene(urdf, b, yaw, theta, theta_dot, tau);
    const sole_truth t = block_arm_truth(b, theta, theta_dot, tau);
    const scene_input in = read_scene_file(scene);
    const evaluation<interval> narrow = evaluate<interval>(in);
    const mp_precision_scope scope(256);
    const evaluation<mpfi> wide = evaluate<mpfi>(in);
    auto holds_truth = [&](const std::string& name, std::size_t i, const ref_t& x) {
      for (const auto& [lo, hi] : {bounds(narrow, name, i), bounds(wide, name, i)}) {
        BOOST_TEST((lo <= x && x <= hi), name << "[" << i << "] at state " << n << ": " << x << " outside [" << lo << ", " << hi << "]");
        BOOST_TEST(double(hi - lo) <= 1e-9 * std::max(1.0, double(abs(x))), name << " at state " << n);
      }
      ++checked;
    };
    holds_truth("hinge_ddot", 0, t.theta_ddot);
    for (std::size_t i = 0; i < 3; ++i) holds_truth("sole_moment", i, t.M[i]);
    // the hinge's wrench (the block on the arm, about the hinge, on the arm's axes): the arm's
    // momentum, f = m_a (a_A - g), m = c x f + I_yy theta'' e_y, turned by R_y(theta)^T
    {
      using floating::cross;
      const ref_t ma(b.ma), th(theta), thd(theta_dot);
      const m3 Ry = floating::elementary(1, th);
      const v3 c = floating::mul(Ry, v3{ref_t(b.cx), 0, ref_t(b.cz)});
      const v3 alpha{0, t.theta_ddot, 0}, omega{0, thd, 0};
      const v3 a1 = cross(alpha, c), a2 = cross(omega, cross(omega, c));
      v3 f;
      for (int i = 0; i < 3; ++i) f[i] = ma * (a1[i] + a2[i]) - (i == 2 ? ma * ref_t("-9.81") : ref_t(0));
      v3 m = cross(c, f);
      m[1] += ref_t(b.ia[1]) * t.theta_ddot;
      const v3 f_arm = floating::mul(floating::transposed(Ry), f), m_arm = floating::mul(floating::transposed(Ry), m);
      for (std::size_t i = 0; i < 3; ++i) holds_truth("hinge_force", i, f_arm[i]), holds_truth("hinge_moment", i, m_arm[i]);
    }
    // the free base's six joints transmit nothing (the ground acts on the block itself), and
    // every joint's virtual-work check holds
    floating::base_joints_transmit_nothing(narrow, " at state " + std::to_string(n));
    floating::virtual_work_checks_hold(narrow, " at state " + std::to_string(n));
    holds_truth("sole_normal_force", 0, t.F[2]);
    for (std::size_t i = 0; i < 2; ++i) holds_truth("sole_friction_force", i, t.F[i]);
    // the verdict: the wrench cone of the truth, decided here in 400 bits
    const ref_t X(b.X), Y(b.Y), mu(b.mu);
    const auto m = sole_wrench_margins(t.F, t.M, X, Y, mu);
    ref_t least = 1e300;
    for (const ref_t& x : all_margins(m)) least = std::min(least, x);
    std::string verdict;
    for (const auto& c : narrow.contacts)
      if (c.name == "sole") verdict = c.verdict;
    if (abs(least) > 1e-6) {
      BOOST_TEST(verdict == (least > 0 ? "holds" : "fails"), "state " << n << ": least margin " << least << ", verdict " << verdict);
      (least > 0 ? holds : fails) += 1;
    }
    // the centre of pressure, where the sole pushes
    if (t.F[2] > 0) {
      for (const auto& c : narrow.contacts)
        if (c.name == "sole") {
          BOOST_TEST_REQUIRE(bool(c.center_of_pressure));
          const ref_t cop_x = -t.M[1] / t.F[2];
          const auto& p = (*c.center_of_pressure)[0];
          BOOST_TEST((ref_t(p.lo) <= cop_x + 1e-30 && cop_x - 1e-30 <= ref_t(p.hi)), "centre of pressure x at state " << n);
        }
    }
  }
  BOOST_TEST(checked == 30 * 13);
  BOOST_TEST(holds >= 3);
  BOOST_TEST(fails >= 3);
  BOOST_TEST_MESSAGE("a block on its sole: " << checked << " quantities enclosed; verdicts " << holds << " holds, " << fails
                                             << " fails, each the truth's");
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene);
}

BOOST_AUTO_TEST_CASE(a_block_on_a_corner_turns_about_it_as_euler_says) {
  using namespace floating;
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_corner_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene = dir + "/appell_corner_" + std::to_string(::getpid()) + ".json";
  const body b{"7.5", {"0", "0", "0.15"}, {"0", "0", "0"}, {"0.09", "0.11", "0.07", "0.004", "-0.003", "0.002"}};
  std::ofstream(urdf) << urdf_of(b);
  int checked = 0;
  for (int n = 0; n < 20; ++n) {
    const std::array<std::string, 3> corner{fixed4(0.2 * u(rng)), fixed4(0.12 * u(rng)), "0"};
    base_state s{{fixed4(u(rng)), fixed4(u(rng)), fixed4(u(rng)), fixed4(3 * u(rng)), fixed4(1.2 * u(rng)), fixed4(3 * u(rng))},
                 {"0", "0", "0", "0", "0", "0"}};
    std::string text = scene_of(urdf, s, {"0", "0", "-9.81"});
    text.insert(text.size() - 1, ", \"contacts\": {\"corner\": {\"link\": \"brick\", \"type\": \"point\", \"point\": [\"" +
                                     corner[0] + "\", \"" + corner[1] + "\", \"0\"], \"mu\": \"0.5\"}}");
    std::ofstream(scene) << text;
    // the truth: turning about the corner from rest
    const ref_t m(b.mass);
    const m3 R = rpy(ref_t(s.q[5]), ref_t(s.q[4]), ref_t(s.q[3]));
    const m3 I{v3{ref_t(b.inertia[0]), ref_t(b.inertia[3]), ref_t(b.inertia[5])},
               v3{ref_t(b.inertia[3]), ref_t(b.inertia[1]), ref_t(b.inertia[4])},
               v3{ref_t(b.inertia[5]), ref_t(b.inertia[4]), ref_t(b.inertia[2])}};
    m3 Iw = mul(R, mul(I, transposed(R)));
    const v3 Rc = mul(R, v3{ref_t(b.com[0]), ref_t(b.com[1]), ref_t(b.com[2])});
    const v3 r = mul(R, v3{ref_t(b.com[0]) - ref_t(corner[0]), ref_t(b.com[1]) - ref_t(corner[1]), ref_t(b.com[2])});
    const ref_t rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Iw[i][j] += m * ((i == j ? rr : ref_t(0)) - r[i] * r[j]);
    const v3 gm{0, 0, -m * ref_t("9.81")};
    const v3 alpha = solve(Iw, cross(r, gm));
    const v3 aG = cross(alpha, r);
    v3 F;
    for (int i = 0; i < 3; ++i) F[i] = m * aG[i] - gm[i];
    const v3 aRc = cross(alpha, Rc);
    const ref_t yaw(s.q[3]), pitch(s.q[4]);
    const v3 e2 = mul(elementary(2, yaw), v3{0, 1, 0});
    const v3 e3 = mul(mul(elementary(2, yaw), elementary(1, pitch)), v3{1, 0, 0});
    const m3 E{v3{0, e2[0], e3[0]}, v3{0, e2[1], e3[1]}, v3{1, e2[2], e3[2]}};
    const v3 rates = solve(E, alpha);
    const std::vector<std::pair<std::string, ref_t>> truth{
        {"base_x_ddot", aG[0] - aRc[0]}, {"base_y_ddot", aG[1] - aRc[1]}, {"base_z_ddot", aG[2] - aRc[2]},
        {"base_yaw_ddot", rates[0]},     {"base_pitch_ddot", rates[1]},   {"base_roll_ddot", rates[2]},
        {"corner_normal_force", F[2]}};
    const scene_input in = read_scene_file(scene);
    const evaluation<interval> narrow = evaluate<interval>(in);
    const mp_precision_scope scope(256);
    const evaluation<mpfi> wide = evaluate<mpfi>(in);
    for (const auto& [name, x] : truth)
      for (const auto& [lo, hi] : {bounds(narrow, name), bounds(wide, name)}) {
        BOOST_TEST((lo <= x && x <= hi), name << " at state " << n << ": " << x << " outside [" << lo << ", " << hi << "]");
        BOOST_TEST(double(hi - lo) <= 1e-9 * std::max(1.0, double(abs(x))), name << " at state " << n);
        ++checked;
      }
    for (std::size_t i = 0; i < 2; ++i) {
      const auto [lo, hi] = bounds(narrow, "corner_friction_force", i);
      BOOST_TEST((lo <= F[i] && F[i] <= hi), "friction force " << i << " at state " << n);
    }
  }
  BOOST_TEST(checked == 20 * 7 * 2);
  BOOST_TEST_MESSAGE("a block on a corner: " << checked << " enclosures hold the turning about the corner");
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene);
}

// A link's contacts refused as bad input: an unknown link, a non-positive half-length, a negative
// mu, a sole's constraint dependent on another contact's (exit 2, naming the contact).
BOOST_AUTO_TEST_CASE(a_link_contact_refuses_bad_input_naming_the_field) {
  using namespace contact_truth;
  const block_and_arm b;
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_contact_refusals_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene = dir + "/appell_contact_refusals_" + std::to_string(::getpid()) + ".json";
  std::ofstream(urdf) << block_arm_urdf(b);
  const std::string good = block_arm_scene(urdf, b, "0.3", "0.5", "0.2", "1");
  auto refusal = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const auto at = text.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    return floating::refusal_of(scene, text);
  };
  BOOST_TEST(refusal("\"link\": \"block\"", "\"link\": \"block\"") == "(accepted)");
  BOOST_TEST(refusal("\"link\": \"block\"", "\"link\": \"foot\"").find("contacts.sole.link: no body named 'foot'") != std::string::npos,
             refusal("\"link\": \"block\"", "\"link\": \"foot\""));
  const std::string h = refusal("[\"0.2\", \"0.12\"]", "[\"0.2\", \"0\"]");
  BOOST_TEST(h.find("contacts.sole.sole.half_lengths[1]: a sole's half-length must be positive") != std::string::npos, h);
  const std::string mu = refusal("\"mu\": \"0.6\"", "\"mu\": \"-0.1\"");
  BOOST_TEST(mu.find("contacts.sole.mu: a friction coefficient must not be negative") != std::string::npos, mu);
  // two points of the block held: the second's row along the line between them repeats the
  // first's (the block may still turn about that line), named
  const auto from = good.find("\"contacts\"");
  BOOST_REQUIRE(from != std::string::npos);
  std::string two = good.substr(0, from) +
                    "\"contacts\": {\"toe\": {\"link\": \"block\", \"point\": [\"0.2\", \"0\", \"0\"]}, "
                    "\"heel\": {\"link\": \"block\", \"point\": [\"-0.2\", \"0\", \"0\"]}}}";
  const std::string twice = floating::refusal_of(scene, two);
  BOOST_TEST(twice.find("contacts.heel: its constraint heel_") != std::string::npos, twice);
  BOOST_TEST(twice.find("depends on the constraints before it at the state (with the contacts toe") != std::string::npos, twice);
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene);
}

// A joint's torque given as a function of time drives the motion (a defect found here: the
// motion carried t only when some other expression named it, so a link's effort "k * t" was
// evaluated at t = 0 along every step).  The arm on the block held by its sole, without gravity,
// under k t: its hinge turns as theta0 + theta0' t + k t^3 / (6 I_p), I_p the arm's inertia about
// the hinge; every enclosed step's end holds it.
BOOST_AUTO_TEST_CASE(a_torque_given_in_time_drives_the_motion) {
  using namespace contact_truth;
  const block_and_arm b;
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string urdf = dir + "/appell_ramp_" + std::to_string(::getpid()) + ".urdf";
  const std::string scene_path = dir + "/appell_ramp_" + std::to_string(::getpid()) + ".json";
  std::ofstream(urdf) << block_arm_urdf(b);
  std::string text = block_arm_scene(urdf, b, "0.2", "0.3", "-0.5", "0");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  };
  replace("[\"0\", \"0\", \"-9.81\"]", "[\"0\", \"0\", \"0\"]");
  replace("\"torques\": {\"hinge\": \"0\"}", "\"torques\": {\"hinge\": \"1.5 * t\"}");
  std::ofstream(scene_path) << text;
  const scene_input scene = read_scene_file(scene_path);
  motion::settings set;
  set.t_end = "1";
  floating::kept_rows rows("steps");
  const motion::enclose_report r = motion::enclose(scene, set, rows);
  BOOST_TEST_REQUIRE(r.complete, r.reason);
  const ref_t Ip = ref_t(b.ia[1]) + ref_t(b.ma) * (ref_t(b.cx) * ref_t(b.cx) + ref_t(b.cz) * ref_t(b.cz));
  int held = 0;
  for (const auto& row : rows.rows) {
    const ref_t t(std::stod(row[rows.at("t1")]));
    const ref_t theta = ref_t("0.3") - ref_t("0.5") * t + ref_t("1.5") * t * t * t / (6 * Ip);
    const ref_t lo(std::stod(row[rows.at("hinge_lo")])), hi(std::stod(row[rows.at("hinge_hi")]));
    BOOST_TEST((lo <= theta && theta <= hi), "hinge at t = " << t << ": " << theta << " outside [" << lo << ", " << hi << "]");
    ++held;
  }
  BOOST_TEST(held >= 3);
  BOOST_TEST_MESSAGE("a torque 1.5 t: the hinge's angle enclosed around its closed form at " << held << " steps' ends");
  std::filesystem::remove(urdf);
  std::filesystem::remove(scene_path);
}

// The README's worked example: Atlas standing on both soles with the torques
// scripts/standing_torques.py found: every acceleration enclosed within 1e-7 of 0, both soles
// proved to hold (their wrench cones), the weight shared.
BOOST_AUTO_TEST_CASE(the_readme_humanoid_stands) {
  const std::string atlas = "/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf";  // dart-doc (scripts/deps.sh)
  if (!std::filesystem::exists(atlas)) {
    BOOST_TEST_MESSAGE("dart-doc is not installed: the example's robot is missing");
    return;
  }
  const scene_input in = read_scene_file(data("scenes/urdf_atlas_standing.json"));
  const evaluation<interval> e = evaluate<interval>(in);
  int accelerations = 0;
  for (const auto& r : e.results)
    if (r.name.size() > 5 && r.name.compare(r.name.size() - 5, 5, "_ddot") == 0) {
      const auto [lo, hi] = bounds_of(r.values[0]);
      BOOST_TEST((lo > -1e-7 && hi < 1e-7), r.name << " in [" << lo << ", " << hi << "]");
      ++accelerations;
    }
  BOOST_TEST(accelerations == 33);
  // the joints' wrenches carry the ground's push: the free base's joints nothing, every joint's
  // virtual-work check 0
  floating::base_joints_transmit_nothing(e, "");
  floating::virtual_work_checks_hold(e, "");
  BOOST_TEST(e.contacts.size() == 2u);
  for (const auto& c : e.contacts) {
    BOOST_TEST(c.verdict == "holds", c.name);
    const auto [lo, hi] = bounds(e, c.name + "_normal_force");
    BOOST_TEST((lo > 700 && hi < 740), c.name << "'s normal force in [" << lo << ", " << hi << "]");
  }
}
