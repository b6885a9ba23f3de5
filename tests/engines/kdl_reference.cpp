// KDL (Debian liborocos-kdl-dev, libkdl-parser-dev) on a `urdf` scene of inverse dynamics, for
// `appell score` (tests/engine_score.sh):
//   kdl_reference states SCENE N SEED   the joints' q, q' and q'' at N random states (CSV)
//   kdl_reference values SCENE STATES   KDL's joint torques at those states, as `<joint>_effort`
// The robot is kdl_parser's reading of the URDF; the chain from the root link to the deepest leaf
// (the robots scored are serial chains); KDL::ChainIdSolver_RNE with the scene's gravity and no
// external wrench gives the torques (KDL's recursive Newton-Euler computes no joint wrench).
#include <kdl/chain.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

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

using engine::appell_name;
using engine::g17;

int main(int argc, char** argv) try {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (!((mode == "states" && argc == 5) || (mode == "values" && argc == 4))) {
    std::cerr << "usage: kdl_reference states SCENE N SEED | values SCENE STATES\n";
    return 2;
  }
  std::ifstream sin(argv[2]);
  const nlohmann::json scene = nlohmann::json::parse(sin);
  std::vector<std::string> joints;
  for (auto it = scene.at("state").begin(); it != scene.at("state").end(); ++it) joints.push_back(it.key());
  if (mode == "states") {  // with q'' (inverse dynamics)
    engine::print_states(joints, std::stoi(argv[3]), std::stoull(argv[4]), true);
    return 0;
  }
  std::filesystem::path file = scene.at("file").get<std::string>();
  if (file.is_relative()) file = std::filesystem::path(argv[2]).parent_path() / file;
  KDL::Tree tree;
  if (!kdl_parser::treeFromFile(file.string(), tree)) throw std::runtime_error("kdl_parser could not read " + file.string());
  // the deepest leaf
  std::string tip;
  unsigned depth = 0;
  for (const auto& [name, element] : tree.getSegments()) {
    if (!GetTreeElementChildren(element).empty()) continue;
    unsigned d = 0;
    for (auto e = tree.getSegments().find(name); e != tree.getRootSegment(); e = GetTreeElementParent(e->second)) ++d;
    if (d > depth) depth = d, tip = name;
  }
  KDL::Chain chain;
  if (!tree.getChain(tree.getRootSegment()->first, tip, chain)) throw std::runtime_error("no chain to " + tip);
  std::vector<std::string> chain_joints;
  for (unsigned i = 0; i < chain.getNrOfSegments(); ++i) {
    const KDL::Joint& j = chain.getSegment(i).getJoint();
    if (j.getType() != KDL::Joint::None) chain_joints.push_back(j.getName());
  }
  if (chain_joints.size() != joints.size()) throw std::runtime_error("the robot is not one serial chain");
  const auto& g = scene.at("gravity");
  KDL::ChainIdSolver_RNE solver(chain, KDL::Vector(std::stod(g[0].get<std::string>()), std::stod(g[1].get<std::string>()),
                                                   std::stod(g[2].get<std::string>())));
  std::ifstream in(argv[3]);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = engine::fields(line);
  std::cout << "state";
  for (const auto& j : chain_joints) std::cout << "," << appell_name(j) << "_effort";
  std::cout << "\n";
  const unsigned n = chain.getNrOfJoints();
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = engine::fields(line);
    std::map<std::string, double> q, qd, qdd;
    for (std::size_t c = 1; c < header.size() && c < f.size(); ++c) {
      const std::string& h = header[c];
      if (h.rfind("accelerations.", 0) == 0) qdd[h.substr(14)] = std::stod(f[c]);
      else if (h.size() > 6 && h.compare(h.size() - 6, 6, ".q_dot") == 0) qd[h.substr(6, h.size() - 12)] = std::stod(f[c]);
      else q[h.substr(6, h.size() - 8)] = std::stod(f[c]);
    }
    KDL::JntArray Q(n), QD(n), QDD(n), tau(n);
    for (unsigned i = 0; i < n; ++i) {
      Q(i) = q.at(chain_joints[i]);
      QD(i) = qd.at(chain_joints[i]);
      QDD(i) = qdd.at(chain_joints[i]);
    }
    KDL::Wrenches none(chain.getNrOfSegments(), KDL::Wrench::Zero());
    if (solver.CartToJnt(Q, QD, QDD, none, tau) < 0) throw std::runtime_error("ChainIdSolver_RNE failed");
    std::cout << f[0];
    for (unsigned i = 0; i < n; ++i) std::cout << "," << g17(tau(i));
    std::cout << "\n";
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "kdl_reference: " << e.what() << "\n";
  return 4;
}
