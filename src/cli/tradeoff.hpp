// The `appell tradeoff` command: speed against accuracy for every scalar.
#pragma once

#include <string>

namespace appell::cli {

struct tradeoff_options {
  std::string scene;
  std::string out_dir;
  int reps = 200;
  bool quiet = false;  ///< --quiet: no progress line
};

/// Runs the measurement, writes DIR/tradeoff.csv and DIR/tradeoff.png, prints the table.
/// Returns the process exit status.
int tradeoff(const tradeoff_options& o);

}  // namespace appell::cli
