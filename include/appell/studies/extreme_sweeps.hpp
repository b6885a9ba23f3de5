// appell/studies/extreme_sweeps.hpp -- the sweeps toward the hard regimes of the paper's
// scenes (singular angles, near-equal inertias, huge spins, tiny radii, masses over 24 decades):
// the points of `appell extremes` (the study, data/extremes/) and of tests/extremes.cpp (the
// guarantees).  Defined in src/studies/extreme_sweeps.cpp (library appell_studies).
#pragma once

#include <string>
#include <vector>

namespace appell::studies {

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

}  // namespace appell::studies
