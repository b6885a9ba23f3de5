// appell linearize SCENE [--scalar NAME] [--bits N] [--format json|text]:
// the linearized equations of a system file about the steady motion its
// "linearize" section names (SCENES.md), with the eigenvalues and the speeds
// where an eigenvalue's real part crosses 0 (system/linearize.hpp).
#pragma once

#include <optional>
#include <string>


namespace appell::cli {

struct linearize_options {
  std::string scene;
  std::string scalar = "double";
  std::optional<unsigned> bits;
  std::string format = "json";
};

/// Reads the scene and prints the report; the exit status of the one-line contract.
std::string linearize(const linearize_options& o);

}  // namespace appell::cli
