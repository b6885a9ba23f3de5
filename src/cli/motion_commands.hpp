// appell simulate / appell enclose: motion over time (ode/).
//
//   appell simulate SCENE --t-end T [--scalar S] [--bits N] [--order N] [--tol E] [--every DT] --out DIR
//   appell enclose  SCENE --t-end T [--scalar interval|mpfi|arb] [--bits N] [--order N] [--tol E] [--max-width W] --out DIR
//
// simulate (point scalars): adaptive Taylor steps; DIR/trajectory.csv (t, the
// state, the scene's results, its invariants at t = 0, DT, 2 DT, ..., T),
// DIR/summary.json, DIR/drift.png (the invariants' relative drift).
// enclose (interval scalars): DIR/steps.csv (each step [t0, t1], the state at
// t1 and over the step, the results and invariants over the step; bounds as
// decimals rounded outward), DIR/summary.json (complete or not, and why),
// DIR/widths.png.  Exit 0 when the enclosure reaches T, 3 when it stops early
// (what was enclosed is still written, marked incomplete).
//
//   appell horizon SCENE --t-end T [--every DT] [--scalars LIST] --out DIR
//
// The long-horizon study (horizon.cpp): each point scalar's simulate against a
// reference at 256 bits (the closed form where the scene has one, Euler's body
// in Jacobi elliptic functions; otherwise simulate in mpfr at 256 bits), the
// error against time with Brouwer's law as the goal line; DIR/horizon.csv,
// DIR/summary.json, DIR/horizon.png.
// The runs are the library's (motion/motion.hpp); these commands parse, check the flags'
// combinations, call it and write its reports (simulate.cpp, enclose.cpp, validity.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"
#include "appell/motion/checks.hpp"
#include "appell/motion/motion.hpp"

namespace appell::cli {

/// A motion command's options: the library's settings, and what the command line adds.
struct motion_options : motion::settings {
  std::string command;  ///< "simulate", "enclose" or "validity"
  std::string scene;    ///< the scene file, as given
  std::string out;      ///< the output directory
  bool quiet = false;   ///< no progress line
};

/// What a run reports back to the command (the files are written by then).
struct motion_outcome {
  int exit_status = 0;
  std::string summary;  ///< the lines printed on stdout
};

/// A positive finite decimal, or input_error naming the flag (the motion library's check).
using motion::positive_decimal;

/// A Taylor order (`--order`, `--reference-order`): an integer from 2 to 60.  Returns "" or the
/// usage error naming the flag.
std::string parse_taylor_order(const std::string& flag, const std::string& text, std::optional<int>& into);

/// A relative tolerance per step (`--tol`, `--reference-tol`): a positive decimal below 1 (at 1
/// or more a step's error may be as large as the state itself).  Returns "" or the usage error.
std::string parse_step_tolerance(const std::string& flag, const std::string& text, std::optional<double>& into);

/// Parses argv[first..] into o; returns "" or the usage error (naming the flag).
std::string parse_motion_arguments(int argc, char** argv, int first, motion_options& o);

/// The checks every motion command makes, after parse_motion_arguments (which has refused a
/// missing scene, --t-end, --out, and validity's --vary): a flag of another motion command named
/// and refused (input_error), the scalar's default set (double for simulate, interval
/// otherwise).  Returns the horizon, --t-end's value.
double checked_motion_flags(motion_options& o);

/// A motion command's entry point: its command line parsed (a usage error: exit 2), then
/// run(options) under the exit-status contract (commands.hpp, guarded).
int motion_command(const char* name, int argc, char** argv, int first, int (*run)(const motion_options&));

/// `appell simulate`, `enclose`, `validity` on parsed options (simulate.cpp, enclose.cpp,
/// validity.cpp): each command's own checks, the scene read, the run, its files written and its
/// summary printed; the exit status.  validity runs on `o.pieces` where given (appell-mpi).
int simulate(const motion_options& o);
int enclose(const motion_options& o);
int validity(const motion_options& o);

/// appell horizon SCENE --t-end T [--every DT] [--scalars LIST] --out DIR: the long-horizon study.
struct horizon_options {
  std::string scene, t_end, every, out;
  std::vector<std::string> scalars{"double", "long-double", "dd", "float128"};
  bool quiet = false;
  /// --reference-order, --reference-tol: the 256-bit reference's Taylor order and tolerance
  /// (scenes without a closed form; default simulate's in mpfr at 256 bits: 60 and 2^-256).
  motion::track_settings reference;
  /// --period: the scene's period, where the model knows none (the table's marks, the plot's
  /// axis), as written (the summary echoes it) and its value
  std::string period;
  double period_value = 0;
};
std::string parse_horizon_arguments(int argc, char** argv, int first, horizon_options& o);
/// Runs the study on options from parse_horizon_arguments (which checked scene, --t-end, --out).
int horizon(const horizon_options& o);

}  // namespace appell::cli
