// DART (Debian libdart-dev, libdart-utils-urdf-dev) on a `urdf` scene's states, for `appell
// score` (tests/engine_score.sh):
//   dart_reference states SCENE N SEED   the scene's joints at N random states (CSV for `appell reference --states`)
//   dart_reference values SCENE STATES   DART's values at those states, columns named as appell's results
// The robot is DART's own reading of the URDF (DartLoader, the root fixed to the world, or on a
// free joint where the scene's base floats: engine_floating.hpp turns the coordinates); the
// scene's gravity and torques are applied; forward dynamics by DART's articulated-body
// recursion (Skeleton::computeForwardDynamics); each joint's wrench is
// -Joint::getWrenchToChildBodyNode() (torque first, then force, on the joint's frame: the child
// link's frame for a URDF), which appell's <joint>_moment and <joint>_force are (the sign: below).
// DART's headers are C++17 (CMake builds this unit so).
// not <dart/dart.hpp>: Debian 12 ships IkFast.hpp without the ikfast.h it includes
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Joint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

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


using engine::read_scene;
using engine::scene;

dart::dynamics::SkeletonPtr load(const scene& s) {
  dart::utils::DartLoader::Options options;
  options.mDefaultRootJointType =
      s.floating ? dart::utils::DartLoader::RootJointType::FLOATING : dart::utils::DartLoader::RootJointType::FIXED;
  dart::utils::DartLoader loader(options);
  const std::string bare = engine::without_geometry(s.urdf, "dart_reference");
  auto skel = loader.parseSkeleton(dart::common::Uri::createFromPath(bare));
  std::filesystem::remove(bare);
  if (!skel) throw std::runtime_error("DART could not read " + s.urdf);
  // A link without <inertial> is a frame of no mass in URDF (and in appell); DART gives it its
  // default body, 1 kg with a unit inertia: set to none here.
  // URDF's <dynamics damping friction> are not read by appell (SCENES.md, "urdf"): DART's
  // damping and Coulomb friction set to 0 (Atlas's joints have damping 0.1).
  for (std::size_t k = 0; k < skel->getNumJoints(); ++k) {
    auto* joint = skel->getJoint(k);
    for (std::size_t i = 0; i < joint->getNumDofs(); ++i) {
      joint->setDampingCoefficient(i, 0.0);
      joint->setCoulombFriction(i, 0.0);
      joint->setSpringStiffness(i, 0.0);
    }
  }
  for (const auto& name : engine::links_without_inertial(s.urdf))
    if (auto* body = skel->getBodyNode(name))
      body->setInertia(dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()));
  skel->setGravity(Eigen::Vector3d(s.gravity[0], s.gravity[1], s.gravity[2]));
  return skel;
}

/// The joints' coordinates and rates set on the skeleton; with a floating base, DART's FreeJoint
/// takes its positions (rotation vector, translation) and velocities (the body's twist on its own
/// axes, angular first), and its accelerations are that twist's derivative.
std::optional<engine::floating_base> set_state(dart::dynamics::Skeleton& skel, const scene& s,
                                               const std::map<std::string, double>& q,
                                               const std::map<std::string, double>& qd) {
  std::optional<engine::floating_base> base;
  if (s.floating) {
    base.emplace(q, qd);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = base->R;
    T.translation() = base->p;
    auto* root = skel.getRootJoint();
    root->setPositions(dart::dynamics::FreeJoint::convertToPositions(T));
    Eigen::Vector6d V;
    V << base->R.transpose() * base->omega, base->R.transpose() * base->p_dot;
    root->setVelocities(V);
  }
  for (const auto& [joint, x] : q) {
    if (s.floating && std::count(engine::base_coordinates.begin(), engine::base_coordinates.end(), joint)) continue;
    auto* jt = skel.getJoint(joint);
    if (!jt) throw std::runtime_error("no joint " + joint + " in DART's skeleton");
    jt->setPosition(0, x);
    jt->setVelocity(0, qd.at(joint));
  }
  return base;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string m = argc > 1 ? argv[1] : "";
  if (!((m == "states" && argc == 5) || (m == "values" && argc == 4) || (m == "time" && argc == 4))) {
    std::cerr << "usage: dart_reference states SCENE N SEED | values SCENE STATES | time SCENE REPS\n";
    return 2;
  }
  const std::string mode = argv[1];
  const scene s = read_scene(argv[2]);
  if (mode == "states") {
    engine::print_states(s.joints, std::stoi(argv[3]), std::stoull(argv[4]), false);
    return 0;
  }
  auto skel = load(s);
  if (mode == "time") {  // the scene's own state: forward dynamics and every joint's wrench, per call
    std::ifstream sin(argv[2]);
    const nlohmann::json j = nlohmann::json::parse(sin);
    std::map<std::string, double> q, qd;
    for (auto it = j.at("state").begin(); it != j.at("state").end(); ++it) {
      q[it.key()] = std::stod(it.value().at("q").get<std::string>());
      qd[it.key()] = std::stod(it.value().at("q_dot").get<std::string>());
    }
    set_state(*skel, s, q, qd);
    for (const auto& [name, tau] : s.torques) skel->getJoint(name)->setForce(0, tau);
    const int reps = std::stoi(argv[3]);
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) {
      skel->computeForwardDynamics();
      for (std::size_t k = 0; k < skel->getNumJoints(); ++k) sink += skel->getJoint(k)->getWrenchToChildBodyNode()[0];
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / reps;
    std::cout << "dart " << us << " us per forward dynamics and joint wrenches (" << (sink != 0) << ")\n";
    return 0;
  }
  std::ifstream in(argv[3]);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = engine::fields(line);
  // output columns: every moving joint's acceleration, then every joint's wrench
  std::cout << "state";
  for (const auto& j : s.joints) std::cout << "," << appell_name(j) << "_ddot";
  for (std::size_t k = 0; k < skel->getNumJoints(); ++k) {
    const auto* joint = skel->getJoint(k);
    if (joint->getParentBodyNode() == nullptr) continue;  // the root's weld to the world: not a URDF joint
    engine::print_wrench_columns(joint->getName());
  }
  std::cout << "\n";
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = engine::fields(line);
    std::map<std::string, double> q, qd;
    engine::read_state(header, f, q, qd);
    const std::optional<engine::floating_base> base = set_state(*skel, s, q, qd);
    for (const auto& [j, tau] : s.torques) skel->getJoint(j)->setForce(0, tau);
    skel->computeForwardDynamics();
    std::cout << f[0];
    if (base) {
      const Eigen::Vector6d A = skel->getRootJoint()->getAccelerations();
      const Eigen::Vector3d omega_b = base->R.transpose() * base->omega, v_b = base->R.transpose() * base->p_dot;
      const Eigen::Vector3d p_ddot = base->R * (A.tail<3>() + omega_b.cross(v_b));
      const Eigen::Vector3d alpha = base->R * A.head<3>();
      for (const double x : base->second_derivatives(p_ddot, alpha)) std::cout << "," << g17(x);
    }
    for (const auto& j : s.joints) {
      if (s.floating && std::count(engine::base_coordinates.begin(), engine::base_coordinates.end(), j)) continue;
      std::cout << "," << g17(skel->getJoint(j)->getAcceleration(0));
    }
    for (std::size_t k = 0; k < skel->getNumJoints(); ++k) {
      const auto* joint = skel->getJoint(k);
      if (joint->getParentBodyNode() == nullptr) continue;
      // DART 6.12 returns the opposite wrench (the child's on the parent, on the child's joint
      // frame): its moment about a joint's axis is minus the torque commanded there (SCENES.md,
      // `urdf`: every component of 200 states opposite to appell's, 10 to 16 digits).  Negated
      // here, so that the score measures the rest.
      const Eigen::Vector6d w = -joint->getWrenchToChildBodyNode();
      for (int i = 0; i < 3; ++i) std::cout << "," << g17(w[3 + i]);
      for (int i = 0; i < 3; ++i) std::cout << "," << g17(w[i]);
    }
    std::cout << "\n";
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "dart_reference: " << e.what() << "\n";
  return 4;
}
