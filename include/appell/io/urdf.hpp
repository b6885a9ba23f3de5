// appell/io/urdf.hpp -- robots described in URDF, read as `system` scenes.
//
// A URDF file (the ROS robot description: links with inertial data, joints between them) is
// turned into the text of a `system` scene file whose bodies are links of a tree (SCENES.md,
// "links of a tree"): every number the decimal written in the URDF, exactly.  The scene model
// "urdf" (SCENES.md) reads that text through the `system` model: one path for both; `appell
// convert` prints it.  Geometry (visual, collision, meshes) is not read: the dynamics need none.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "appell/io/files.hpp"
#include "appell/io/json.hpp"

namespace appell {

/// A URDF file's kinematic tree and inertial data, every number as its decimal text.
struct urdf_robot {
  struct inertial {
    bool given = false;
    std::array<std::string, 3> xyz{"0", "0", "0"}, rpy{"0", "0", "0"};
    std::string mass = "0";
    std::array<std::string, 6> inertia{"0", "0", "0", "0", "0", "0"};  ///< xx yy zz xy yz zx
  };
  struct link {
    std::string name;
    inertial in;
    int line = 0;
  };
  struct joint {
    std::string name, type, parent, child;  ///< type: revolute, continuous, prismatic, fixed
    std::array<std::string, 3> xyz{"0", "0", "0"}, rpy{"0", "0", "0"}, axis{"1", "0", "0"};
    int line = 0;
  };
  std::string name;
  std::vector<link> links;
  std::vector<joint> joints;  ///< each after its parent link's joint (from the root out)
  std::string root;           ///< the link no joint moves (the ground, with a fixed base)
};

/// What a URDF file may hold (the limits of scene files and of the system model).
struct urdf_limits {
  static constexpr std::size_t bytes = json_limits::bytes;
  static constexpr std::size_t links = 257;  ///< 256 joints and the root link (the system model holds 256 bodies)
};

/// Whether a URDF attribute's text is a number appell takes: at most 200 characters,
/// [+-]? (digits [. digits?] | . digits) ([eE] [+-]? 1 to 6 digits)?  (The language of the
/// regular expression the reader used before; tests/joints.cpp holds it to std::regex on random
/// texts.)
bool is_urdf_number(std::string_view s);

/// Parses URDF text; input_error naming the element (and its line) on anything it cannot take:
/// not XML, not a robot, an unknown joint type, a joint whose axis is 0, a link with two
/// parents, a loop, a name used twice, a number that is not a decimal, no joint that moves.
urdf_robot parse_urdf(const std::string& text, const std::string& file);
/// Reads a URDF file (at most urdf_limits::bytes).
urdf_robot read_urdf_file(const std::string& path);

/// The joint's name as a name of the system file (letters, digits and _; URDF names such as
/// "/j1" become "j1"), distinct over the robot and from the names in `taken` (a floating base's
/// coordinates).
std::map<std::string, std::string> urdf_joint_names(const urdf_robot& robot, const std::vector<std::string>& taken = {});

/// A floating base's six coordinates, in the order of its joints from the ground to the root link
/// (SCENES.md, "urdf"): the root frame's origin x, y, z on the fixed axes, then its orientation
/// R = Rz(yaw) Ry(pitch) Rx(roll), URDF's roll-pitch-yaw.  Singular (gimbal lock) where
/// cos(pitch) = 0: a state within floating_base_pitch_margin of it is refused by name.
inline const std::vector<std::string>& floating_base_coordinates() {
  static const std::vector<std::string> names{"base_x", "base_y", "base_z", "base_yaw", "base_pitch", "base_roll"};
  return names;
}
/// How close to +-90 degrees a floating base's pitch may come, as a bound on |cos(pitch)|: below
/// it the mass matrix's condition number (about 1/cos(pitch)^2) passes 1e12 and the roll and
/// yaw rates are no longer the orientation's coordinates anyone means.
inline constexpr double floating_base_pitch_margin = 1e-6;

/// The options of a "urdf" scene that the system file carries.
struct urdf_scene_options {
  std::array<std::string, 3> gravity{"0", "0", "-9.81"};
  std::map<std::string, std::pair<std::string, std::string>> state;  ///< joint -> (q, q_dot)
  std::map<std::string, std::string> efforts;                          ///< joint -> torque or force
  std::map<std::string, std::string> accelerations;                    ///< joint -> q_ddot (inverse dynamics)
  bool with_state = false;
  /// "base": "floating": the root link hangs from the ground by six joints of no mass
  /// (floating_base_coordinates(): three prismatic along x, y, z, three revolute about z, y, x),
  /// whose coordinates the maps above name as joints.  Otherwise the root link is the ground.
  bool floating = false;
  /// The scene's "contacts" (SCENES.md, "contacts of links"), as JSON text: written into the
  /// system file as they are (a link is named by its URDF name, which is its body's), read there.
  std::string contacts;
  /// The scene's "tables" (SCENES.md, "tables"), as JSON text: written into the system file as
  /// they are, a CSV file's path made absolute (the converted file may be read from elsewhere).
  std::string tables;
};

/// The `system` scene file (JSON text) of the robot, its base fixed to the ground (or floating:
/// urdf_scene_options::floating).
std::string urdf_to_system(const urdf_robot& robot, const urdf_scene_options& o);

/// `appell convert PATH`: the system file of a URDF file (at rest, gravity 0 0 -9.81) or of a
/// "urdf" scene (its state, gravity, torques or accelerations), checked by reading it.
std::string convert_to_system(const std::string& path);

/// The `system` file (text) of a parsed "urdf" scene (its "file" absolute, or relative to
/// scene_directory()); input_error as the scene's reader.
std::string urdf_scene_system_text(const json_value& scene);

}  // namespace appell
