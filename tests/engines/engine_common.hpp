// tests/engines/engine_common.hpp -- what the engine programs (C++17, no appell header) share:
// appell's names for URDF joints, numbers printed to 17 digits, CSV lines, the URDF without its
// geometry, and the random states of a scene's joints.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace engine {

/// appell's name for a URDF joint (SCENES.md, `urdf`: "/j1" becomes "j1").
inline std::string appell_name(const std::string& urdf) {
  std::string s;
  for (char c : urdf) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  const auto b = s.find_first_not_of('_');
  s = b == std::string::npos ? "" : s.substr(b);
  while (!s.empty() && s.back() == '_') s.pop_back();
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "joint_" + s;
  if (s.size() > 48) s.resize(48);  // cut to 48 characters (Atlas's camera frames' joints)
  for (const char* reserved : {"pi", "t", "sin", "cos", "tan", "exp", "log", "sqrt", "rx", "ry", "rz"})
    if (s == reserved) s += "_";
  return s;  // (a name taken twice gets _2, _3 in appell: no robot scored here has one)
}

inline std::string g17(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

/// The comma-separated fields of one CSV line (the states files have no quoted fields).
inline std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
  return f;
}

/// What an engine program reads of a `urdf` scene: the URDF (its path made absolute from the
/// scene's folder), gravity, the torques, and the moving joints in the scene's state order.
struct scene {
  std::string urdf;
  std::array<double, 3> gravity{};
  std::map<std::string, double> torques;
  std::vector<std::string> joints;  ///< with a floating base, its six coordinates first (base_x ... base_roll)
  bool floating = false;            ///< "base": "floating"
};

/// A floating base's six coordinates (appell's urdf.hpp, SCENES.md): x, y, z, yaw, pitch, roll.
inline const std::array<std::string, 6> base_coordinates{"base_x", "base_y", "base_z", "base_yaw", "base_pitch", "base_roll"};

inline scene read_scene(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  scene s;
  std::filesystem::path file = j.at("file").get<std::string>();
  if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
  s.urdf = file.string();
  for (int i = 0; i < 3; ++i) s.gravity[static_cast<std::size_t>(i)] = std::stod(j.at("gravity")[i].get<std::string>());
  if (j.contains("torques"))
    for (auto it = j["torques"].begin(); it != j["torques"].end(); ++it) s.torques[it.key()] = std::stod(it.value().get<std::string>());
  s.floating = j.contains("base") && j.at("base").get<std::string>() == "floating";
  if (s.floating) s.joints.assign(base_coordinates.begin(), base_coordinates.end());
  for (auto it = j.at("state").begin(); it != j.at("state").end(); ++it)
    if (!s.floating || std::find(base_coordinates.begin(), base_coordinates.end(), it.key()) == base_coordinates.end())
      s.joints.push_back(it.key());
  return s;
}

/// One line of a states file (columns state.JOINT.q and state.JOINT.q_dot after the label): q
/// and q' by joint name.
inline void read_state(const std::vector<std::string>& header, const std::vector<std::string>& f,
                       std::map<std::string, double>& q, std::map<std::string, double>& qd) {
  for (std::size_t c = 1; c < header.size() && c < f.size(); ++c) {
    const std::string& h = header[c];
    const bool rate = h.size() > 6 && h.compare(h.size() - 6, 6, ".q_dot") == 0;
    (rate ? qd : q)[h.substr(6, h.size() - 6 - (rate ? 6 : 2))] = std::stod(f[c]);
  }
}

/// The names of the URDF's links that have no <inertial> (frames: a camera's optical frame).  In
/// URDF they carry nothing; engines that give a body a default mass (DART: 1 kg and a unit
/// inertia) must be told so.
inline std::vector<std::string> links_without_inertial(const std::string& urdf_path) {
  std::ifstream in(urdf_path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> out;
  for (std::size_t at = 0; (at = text.find("<link", at)) != std::string::npos; ++at) {
    const std::size_t name = text.find("name=\"", at), gt = text.find('>', at);
    if (name == std::string::npos || gt == std::string::npos || name > gt) continue;
    const std::string n = text.substr(name + 6, text.find('"', name + 6) - name - 6);
    const bool self_closed = text[gt - 1] == '/';
    const std::size_t end = self_closed ? gt : text.find("</link>", gt);
    if (self_closed || text.substr(gt, end - gt).find("<inertial") == std::string::npos) out.push_back(n);
  }
  return out;
}

/// The CSV columns of one joint's wrench, in appell's names: force then moment, 3 components each.
inline void print_wrench_columns(const std::string& urdf_joint) {
  const std::string n = appell_name(urdf_joint);
  for (int i = 0; i < 3; ++i) std::cout << "," << n << "_force[" << i << "]";
  for (int i = 0; i < 3; ++i) std::cout << "," << n << "_moment[" << i << "]";
}

/// A copy of the URDF at `path` without <visual> and <collision> (engines fail on meshes they
/// cannot find, and the dynamics need none), `extra` inserted after <robot ...>, in the temporary
/// directory under `name`; the caller removes it.
inline std::string without_geometry(const std::string& path, const std::string& name, const std::string& extra = "") {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string tag : {"visual", "collision"})
    for (std::size_t at; (at = text.find("<" + tag)) != std::string::npos;) {
      const std::string close = "</" + tag + ">";
      std::size_t end = text.find(close, at);
      const std::size_t self = text.find("/>", at), gt = text.find('>', at);
      if (self != std::string::npos && self + 1 == gt) end = self + 2;  // <visual/>
      else if (end == std::string::npos) throw std::runtime_error(path + ": an unclosed <" + tag + ">");
      else end += close.size();
      text.erase(at, end - at);
    }
  if (!extra.empty()) text.insert(text.find('>', text.find("<robot")) + 1, extra);
  const auto out = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".urdf");
  std::ofstream(out) << text;
  return out.string();
}

/// N random states of the joints on a grid of 1e-6 (CSV for `appell reference --states`): q in
/// [-1.5, 1.5], q' in [-2, 2], and with `accelerations` q'' in [-5, 5] (inverse dynamics).
inline void print_states(const std::vector<std::string>& joints, int n, unsigned long long seed, bool accelerations) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> q(-1500000, 1500000), qd(-2000000, 2000000), qdd(-5000000, 5000000);
  std::cout << "state";
  for (const auto& j : joints) {
    std::cout << ",state." << j << ".q,state." << j << ".q_dot";
    if (accelerations) std::cout << ",accelerations." << j;
  }
  std::cout << "\n";
  for (int r = 0; r < n; ++r) {
    std::cout << "s" << r;
    for (std::size_t k = 0; k < joints.size(); ++k) {
      char b[96];
      const long x = q(rng), v = qd(rng);  // drawn in this order (function arguments have none)
      if (accelerations) std::snprintf(b, sizeof b, ",%.6f,%.6f,%.6f", x * 1e-6, v * 1e-6, qdd(rng) * 1e-6);
      else std::snprintf(b, sizeof b, ",%.6f,%.6f", x * 1e-6, v * 1e-6);
      std::cout << b;
    }
    std::cout << "\n";
  }
}

}  // namespace engine
