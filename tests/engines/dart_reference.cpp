// DART (Debian libdart-dev, libdart-utils-urdf-dev) on a `urdf` scene's states, for `appell
// score` (tests/engine_score.sh):
//   dart_reference states SCENE N SEED   the scene's joints at N random states (CSV for `appell reference --states`)
//   dart_reference values SCENE STATES   DART's values at those states, columns named as appell's results
// The robot is DART's own reading of the URDF (DartLoader, the root fixed to the world); the
// scene's gravity and torques are applied; forward dynamics by DART's articulated-body
// recursion (Skeleton::computeForwardDynamics); each joint's wrench is
// -Joint::getWrenchToChildBodyNode() (torque first, then force, on the joint's frame: the child
// link's frame for a URDF), which appell's <joint>_moment and <joint>_force are (the sign: below).
// DART's headers are C++17 (CMake builds this unit so).
// not <dart/dart.hpp>: Debian 12 ships IkFast.hpp without the ikfast.h it includes
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Joint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include <chrono>
#include <cstdio>
#include "engine_common.hpp"
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
  options.mDefaultRootJointType = dart::utils::DartLoader::RootJointType::FIXED;
  dart::utils::DartLoader loader(options);
  const std::string bare = engine::without_geometry(s.urdf, "dart_reference");
  auto skel = loader.parseSkeleton(dart::common::Uri::createFromPath(bare));
  std::filesystem::remove(bare);
  if (!skel) throw std::runtime_error("DART could not read " + s.urdf);
  skel->setGravity(Eigen::Vector3d(s.gravity[0], s.gravity[1], s.gravity[2]));
  return skel;
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
    for (auto it = j.at("state").begin(); it != j.at("state").end(); ++it) {
      skel->getJoint(it.key())->setPosition(0, std::stod(it.value().at("q").get<std::string>()));
      skel->getJoint(it.key())->setVelocity(0, std::stod(it.value().at("q_dot").get<std::string>()));
    }
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
    for (const auto& [joint, x] : q) {
      auto* jt = skel->getJoint(joint);
      if (!jt) throw std::runtime_error("no joint " + joint + " in DART's skeleton");
      jt->setPosition(0, x);
      jt->setVelocity(0, qd.at(joint));
    }
    for (const auto& [j, tau] : s.torques) skel->getJoint(j)->setForce(0, tau);
    skel->computeForwardDynamics();
    std::cout << f[0];
    for (const auto& j : s.joints) std::cout << "," << g17(skel->getJoint(j)->getAcceleration(0));
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
