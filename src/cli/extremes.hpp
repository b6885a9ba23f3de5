// Sweeps toward the hard regimes of the paper scenes, shared by
// `appell extremes` (the study) and tests/extremes.cpp (the guarantees).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace appell::cli {

struct sweep_point {
  std::string param;  ///< the swept parameter's value, as text
  double x;           ///< the same, as a double for plotting (e.g. log10 of it)
  std::string json;   ///< the scene
};

struct sweep {
  std::string name, what, x_label;
  std::vector<sweep_point> points;
};

/// The eight sweeps of the study.
std::vector<sweep> extreme_sweeps();

struct extremes_options {
  std::string out_dir = "data/extremes";
};

int extremes(const extremes_options& o);

}  // namespace appell::cli
