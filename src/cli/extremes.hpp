// appell extremes: the stability study over the sweeps of appell/studies/extreme_sweeps.hpp.
#pragma once

#include <string>
#include <vector>

namespace appell::cli {

struct extremes_options {
  std::string out_dir;
  bool quiet = false;  ///< --quiet: no progress line
};

int extremes(const extremes_options& o);

}  // namespace appell::cli
