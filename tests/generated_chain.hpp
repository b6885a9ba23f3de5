// tests/generated_chain.hpp -- the generated serial chain that the tests (tree_recursions) and the
// benchmarks (bench/urdf.cpp) share: n links, joints about z and y in turn, every frame turned
// (rpy 0.1 0 0.2, the inertia's 0.1 0 0), full inertia tensors of mass 1, written as URDF and a
// `urdf` scene in the temporary directory, read as every URDF is.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace appell::testing {

/// The chain of n links: writes <tmp>/<prefix>_<n>.urdf and its scene, and returns the scene's
/// path.  Its state: q_k = 0.(37 k mod 100), q'_k = -0.(53 k mod 100).
inline std::string generated_chain_scene(int n, const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string stem = (dir / (prefix + "_" + std::to_string(n))).string();
  {
    std::ofstream u(stem + ".urdf");
    u << "<robot name=\"chain\"><link name=\"l0\"/>";
    for (int k = 1; k <= n; ++k)
      u << "<link name=\"l" << k << "\"><inertial><origin xyz=\"0 0.01 0.15\" rpy=\"0.1 0 0\"/><mass value=\"1\"/>"
        << "<inertia ixx=\"0.008\" ixy=\"0.0001\" ixz=\"0.0002\" iyy=\"0.0085\" iyz=\"-0.0001\" izz=\"0.002\"/></inertial></link>"
        << "<joint name=\"j" << k << "\" type=\"revolute\"><parent link=\"l" << k - 1 << "\"/><child link=\"l" << k << "\"/>"
        << "<origin xyz=\"0 0 0.3\" rpy=\"0.1 0 0.2\"/><axis xyz=\"" << (k % 2 ? "0 0 1" : "0 1 0") << "\"/></joint>";
    u << "</robot>\n";
  }
  std::ofstream sc(stem + ".json");
  sc << "{\"model\": \"urdf\", \"file\": \"" << stem << ".urdf\", \"gravity\": [\"0\", \"0\", \"-9.81\"], \"state\": {";
  for (int k = 1; k <= n; ++k)
    sc << (k > 1 ? ", " : "") << "\"j" << k << "\": {\"q\": \"0." << (k * 37) % 100 << "\", \"q_dot\": \"-0." << (k * 53) % 100
       << "\"}";
  sc << "}}\n";
  return stem + ".json";
}

}  // namespace appell::testing
