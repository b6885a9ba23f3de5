// MuJoCo 2.2.2 (Debian libmujoco-dev) on a `urdf` scene's states, for `appell score`
// (tests/engine_score.sh):
//   mujoco_reference states SCENE N SEED   the scene's joints at N random states (CSV)
//   mujoco_reference values SCENE STATES   MuJoCo's values at those states, named as appell's results
// MuJoCo compiles the URDF itself (mj_loadXML; the geometry stripped, static bodies kept apart:
// fusestatic off); joint limits and contacts disabled (appell models neither), the scene's
// gravity and torques (qfrc_applied); a floating base on a free joint (below). Forward dynamics: mj_forward's qacc. Wrenches: cfrc_int
// after mj_rnePostConstraint, the interaction force with the parent, rotation first, on the world
// axes about the subtree centre of mass of the root (d->subtree_com[m->body_rootid[b]]): shifted
// here to the body's origin (the joint's, for a URDF) and turned onto the body's axes.
#include <mujoco/mujoco.h>

#include <chrono>
#include <cstdio>
#include "engine_common.hpp"
#include "engine_floating.hpp"
#include <algorithm>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using engine::appell_name;
using engine::g17;


}  // namespace

int main(int argc, char** argv) try {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (!((mode == "states" && argc == 5) || (mode == "values" && argc == 4) || (mode == "time" && argc == 4))) {
    std::cerr << "usage: mujoco_reference states SCENE N SEED | values SCENE STATES | time SCENE REPS\n";
    return 2;
  }
  std::ifstream sin(argv[2]);
  const nlohmann::json scene = nlohmann::json::parse(sin);
  const engine::scene es = engine::read_scene(argv[2]);
  const std::vector<std::string>& joints = es.joints;  // a floating base's six coordinates first
  if (mode == "states") {
    engine::print_states(joints, std::stoi(argv[3]), std::stoull(argv[4]), false);
    return 0;
  }
  std::filesystem::path file = scene.at("file").get<std::string>();
  if (file.is_relative()) file = std::filesystem::path(argv[2]).parent_path() / file;
  // static bodies kept apart (fusestatic off), so that every URDF link is a MuJoCo body
  // A floating base: MuJoCo's URDF reader takes a link named "world" as its world body and a
  // URDF "floating" joint as a free joint (qpos: position, unit quaternion w x y z; qvel: the
  // origin's velocity on the world's axes, the angular velocity on the body's; qacc their rates).
  std::string extra = "<mujoco><compiler fusestatic=\"false\" discardvisual=\"true\" balanceinertia=\"false\"/></mujoco>";
  if (es.floating) {
    std::string root;
    {
      // the root link: the one no joint has as its child
      std::ifstream u(file);
      const std::string text((std::istreambuf_iterator<char>(u)), std::istreambuf_iterator<char>());
      std::vector<std::string> links, children;
      for (std::size_t at = 0; (at = text.find("<link", at)) != std::string::npos; ++at) {
        const std::size_t n = text.find("name=\"", at);
        links.push_back(text.substr(n + 6, text.find('"', n + 6) - n - 6));
      }
      for (std::size_t at = 0; (at = text.find("<child", at)) != std::string::npos; ++at) {
        const std::size_t n = text.find("link=\"", at);
        children.push_back(text.substr(n + 6, text.find('"', n + 6) - n - 6));
      }
      for (const auto& l : links)
        if (std::find(children.begin(), children.end(), l) == children.end()) root = l;
    }
    extra += "<link name=\"world\"/><joint name=\"appell_free\" type=\"floating\"><parent link=\"world\"/>"
             "<child link=\"" + root + "\"/></joint>";
  }
  const std::string bare = engine::without_geometry(file.string(), "mujoco_reference", extra);
  char error[1000] = "";
  mjModel* m = mj_loadXML(bare.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(bare);
  if (!m) throw std::runtime_error(std::string("MuJoCo could not compile ") + file.string() + ": " + error);
  m->opt.disableflags |= mjDSBL_LIMIT | mjDSBL_CONTACT;
  const auto& g = scene.at("gravity");
  for (int i = 0; i < 3; ++i) m->opt.gravity[i] = std::stod(g[i].get<std::string>());
  mjData* d = mj_makeData(m);
  auto joint_id = [&](const std::string& name) {
    const int id = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if (id < 0) throw std::runtime_error("no joint " + name + " in MuJoCo's model");
    return id;
  };
  if (mode == "time") {  // the scene's own state: mj_forward and mj_rnePostConstraint, per call
    if (es.floating) throw std::runtime_error("time: a fixed base only");
    for (auto it = scene.at("state").begin(); it != scene.at("state").end(); ++it) {
      const int id = joint_id(it.key());
      d->qpos[m->jnt_qposadr[id]] = std::stod(it.value().at("q").get<std::string>());
      d->qvel[m->jnt_dofadr[id]] = std::stod(it.value().at("q_dot").get<std::string>());
    }
    if (scene.contains("torques"))
      for (auto it = scene["torques"].begin(); it != scene["torques"].end(); ++it)
        d->qfrc_applied[m->jnt_dofadr[joint_id(it.key())]] = std::stod(it.value().get<std::string>());
    const int reps = std::stoi(argv[3]);
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) {
      mj_forward(m, d);
      mj_rnePostConstraint(m, d);
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / reps;
    std::cout << "mujoco " << us << " us per mj_forward and mj_rnePostConstraint\n";
    return 0;
  }
  std::ifstream in(argv[3]);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = engine::fields(line);
  // bodies with a parent other than the world, and the URDF joint that makes each (by the child)
  std::cout << "state";
  for (const auto& j : joints) std::cout << "," << appell_name(j) << "_ddot";
  std::vector<std::pair<int, std::string>> wrenches;  // (body, joint name)
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_jntnum[b] != 1) continue;  // a fixed joint's body has no MuJoCo joint: left out
    if (m->jnt_type[m->body_jntadr[b]] == mjJNT_FREE) continue;  // the floating base's: no URDF joint
    const std::string name = mj_id2name(m, mjOBJ_JOINT, m->body_jntadr[b]);
    wrenches.emplace_back(b, name);
    engine::print_wrench_columns(name);
  }
  std::cout << "\n";
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = engine::fields(line);
    mj_resetData(m, d);
    std::map<std::string, double> q, qd;
    engine::read_state(header, f, q, qd);
    std::optional<engine::floating_base> base;
    int free_q = 0, free_v = 0;
    if (es.floating) {
      base.emplace(q, qd);
      const int id = joint_id("appell_free");
      free_q = m->jnt_qposadr[id], free_v = m->jnt_dofadr[id];
      const Eigen::Quaterniond o(base->R);
      const Eigen::Vector3d w_b = base->R.transpose() * base->omega;
      for (int i = 0; i < 3; ++i) {
        d->qpos[free_q + i] = base->p[i];
        d->qvel[free_v + i] = base->p_dot[i];
        d->qvel[free_v + 3 + i] = w_b[i];
      }
      d->qpos[free_q + 3] = o.w(), d->qpos[free_q + 4] = o.x(), d->qpos[free_q + 5] = o.y(), d->qpos[free_q + 6] = o.z();
    }
    auto is_base = [&](const std::string& j) {
      return es.floating && std::count(engine::base_coordinates.begin(), engine::base_coordinates.end(), j);
    };
    for (const auto& [j, x] : q)
      if (!is_base(j)) d->qpos[m->jnt_qposadr[joint_id(j)]] = x;
    for (const auto& [j, x] : qd)
      if (!is_base(j)) d->qvel[m->jnt_dofadr[joint_id(j)]] = x;
    if (scene.contains("torques"))
      for (auto it = scene["torques"].begin(); it != scene["torques"].end(); ++it)
        d->qfrc_applied[m->jnt_dofadr[joint_id(it.key())]] = std::stod(it.value().get<std::string>());
    mj_forward(m, d);
    mj_rnePostConstraint(m, d);
    std::cout << f[0];
    if (base) {
      const Eigen::Vector3d p_ddot(d->qacc[free_v], d->qacc[free_v + 1], d->qacc[free_v + 2]);
      const Eigen::Vector3d alpha = base->R * Eigen::Vector3d(d->qacc[free_v + 3], d->qacc[free_v + 4], d->qacc[free_v + 5]);
      for (const double x : base->second_derivatives(p_ddot, alpha)) std::cout << "," << g17(x);
    }
    for (const auto& j : joints)
      if (!is_base(j)) std::cout << "," << g17(d->qacc[m->jnt_dofadr[joint_id(j)]]);
    for (const auto& [b, name] : wrenches) {
      const mjtNum* w = d->cfrc_int + 6 * b;  // torque about c, force; world axes
      const mjtNum* c = d->subtree_com + 3 * m->body_rootid[b];
      const mjtNum* p = d->xpos + 3 * b;
      const mjtNum* R = d->xmat + 9 * b;  // body axes to world, row-major
      double M[3], F[3] = {w[3], w[4], w[5]}, r[3] = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
      M[0] = w[0] + r[1] * F[2] - r[2] * F[1];
      M[1] = w[1] + r[2] * F[0] - r[0] * F[2];
      M[2] = w[2] + r[0] * F[1] - r[1] * F[0];
      for (int i = 0; i < 3; ++i) std::cout << "," << g17(R[i] * F[0] + R[3 + i] * F[1] + R[6 + i] * F[2]);
      for (int i = 0; i < 3; ++i) std::cout << "," << g17(R[i] * M[0] + R[3 + i] * M[1] + R[6 + i] * M[2]);
    }
    std::cout << "\n";
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "mujoco_reference: " << e.what() << "\n";
  return 4;
}
