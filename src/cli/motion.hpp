// appell simulate / appell enclose: motion over time (ode/).
//
//   appell simulate SCENE --t-end T [--scalar S] [--bits N] [--order N] [--tol E] [--every DT] --out DIR
//   appell enclose  SCENE --t-end T [--scalar interval|mpfi] [--bits N] [--order N] [--tol E] [--max-width W] --out DIR
//
// simulate (point scalars): adaptive Taylor steps; DIR/trajectory.csv (t, the
// state, the scene's results, its invariants at t = 0, DT, 2 DT, ..., T),
// DIR/summary.json, DIR/drift.png (the invariants' relative drift).
// enclose (interval scalars): DIR/steps.csv (each step [t0, t1], the state at
// t1 and over the step, the results and invariants over the step; bounds as
// decimals rounded outward), DIR/summary.json (complete or not, and why),
// DIR/widths.png.  Exit 0 when the enclosure reaches T, 3 when it stops early
// (what was enclosed is still written, marked incomplete).
#pragma once

#include <optional>
#include <string>

#include "appell/io/scene.hpp"

namespace appell::cli {

struct motion_options {
  std::string command;  ///< "simulate" or "enclose"
  std::string scene;
  std::string scalar;   ///< default: double (simulate), interval (enclose)
  std::optional<unsigned> bits;
  std::string t_end, every, out;
  std::optional<int> order;
  std::optional<double> tol;
  double max_width = 1.0;
  bool quiet = false;  ///< no progress line
};

/// What a run reports back to the command (the files are written by then).
struct motion_outcome {
  int exit_status = 0;
  std::string summary;  ///< the lines printed on stdout
};

/// The run in scalar T (instantiated per standard scalar in generated units).
template <Scalar T>
motion_outcome run_motion(const scene_input& scene, const motion_options& o);

/// Parses argv[first..] into o; returns "" or the usage error (naming the flag).
std::string parse_motion_arguments(int argc, char** argv, int first, motion_options& o);

/// Validates the options, reads the scene, runs it; returns the exit status.
int motion(const motion_options& o);

}  // namespace appell::cli
