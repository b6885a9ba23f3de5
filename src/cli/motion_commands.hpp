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
//
//   appell horizon SCENE --t-end T [--every DT] [--scalars LIST] --out DIR
//
// The long-horizon study (horizon.cpp): each point scalar's simulate against a
// reference at 256 bits (the closed form where the scene has one, Euler's body
// in Jacobi elliptic functions; otherwise simulate in mpfr at 256 bits), the
// error against time with Brouwer's law as the goal line; DIR/horizon.csv,
// DIR/summary.json, DIR/horizon.png.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "appell/io/model_motion.hpp"
#include "appell/io/scene.hpp"

namespace appell::cli {

struct piece_network;

struct motion_options {
  std::string command;  ///< "simulate" or "enclose"
  std::string scene;
  std::string scalar;   ///< default: double (simulate), interval (enclose)
  std::optional<unsigned> bits;
  std::string t_end, every, out;
  std::optional<int> order;
  std::optional<double> tol;
  double max_width = 1.0;
  std::optional<double> max_seconds;  ///< stop cleanly after this long, files written (exit 3)
  bool quiet = false;  ///< no progress line
  std::optional<double> locate;      ///< enclose: narrow each contact's first failure to this width
  bool until_contact_fails = false;  ///< enclose: stop after the first step in which a contact is proved to fail
  /// validity: the range of one field (a state component of the motion, or "mu") split into
  /// pieces until each is proved to hold or to fail over [0, T], or is narrower than resolution.
  std::string vary_field, vary_lo, vary_hi;
  std::optional<double> resolution;
  /// enclose, validity: every contact's friction coefficient, in place of the scene's (--mu).
  std::optional<std::string> mu;
  /// validity: the threads that run its pieces (--jobs; 0: one per core).
  int jobs = 0;
  /// validity under appell-mpi: the other ranks (pieces.hpp); null: this process alone.
  const piece_network* pieces = nullptr;
};

/// What a run reports back to the command (the files are written by then).
struct motion_outcome {
  int exit_status = 0;
  std::string summary;  ///< the lines printed on stdout
};

/// The run in scalar T of a scene whose model moves (io/model_motion.hpp): the model found in
/// the list CMake generates from APPELL_MODELS (motion_dispatch.cpp); input_error naming
/// `model` for one that does not move.
template <Scalar T>
motion_outcome run_motion(const scene_input& scene, const motion_options& o);
/// The same for one model, instantiated per model and scalar in generated units (motion_run.hpp).
template <class Model, Scalar T>
motion_outcome run_model_motion(const scene_input& scene, const motion_options& o);

/// One scalar's trajectory for `appell horizon`: the states at t = 0, every, 2 every, ... as
/// exact decimals of the scalar's values (lower_string: a point's value, written in full).
struct horizon_track {
  std::string scalar;
  unsigned bits = 0;
  int order = 0;
  double tol = 0;  ///< the relative tolerance per step
  std::vector<std::string> t;
  std::vector<std::vector<std::string>> x;
  long steps = 0;
  double seconds = 0;
};

/// The Taylor order and tolerance of a track (none: `simulate`'s defaults for the scalar).
struct track_settings {
  std::optional<int> order;
  std::optional<double> tol;
};

/// Runs `simulate` on the scene in scalar T from 0 to t_end with outputs every `every` (decimals),
/// at the order and tolerance of `settings` (by default simulate's for T).
template <Scalar T>
horizon_track run_horizon_track(const scene_input& scene, const std::string& t_end, const std::string& every, bool quiet,
                                const track_settings& settings = {});
template <class Model, Scalar T>
horizon_track run_model_horizon_track(const scene_input& scene, const std::string& t_end, const std::string& every,
                                      bool quiet, const track_settings& settings);

/// The scene fields of the model's motion state, in the order of its state (input_error naming
/// `model` when the model does not move).
std::vector<std::string> motion_state_fields(const scene_input& scene);

/// The scene's motion in closed form where its model knows it (horizon's reference), else none.
std::optional<motion_closed_form> motion_closed_form_of(const scene_input& scene);

/// The models that move, in the registry's order ("euler_body, heavy_top, ...").
std::string moving_model_names();

/// A positive finite decimal, or input_error naming the flag.
double positive_decimal(const std::string& flag, const std::string& text);

/// A Taylor order (`--order`, `--reference-order`): an integer from 2 to 60.  Returns "" or the
/// usage error naming the flag.
std::string parse_taylor_order(const std::string& flag, const std::string& text, std::optional<int>& into);

/// A relative tolerance per step (`--tol`, `--reference-tol`): a positive decimal below 1 (at 1
/// or more a step's error may be as large as the state itself).  Returns "" or the usage error.
std::string parse_step_tolerance(const std::string& flag, const std::string& text, std::optional<double>& into);

/// Parses argv[first..] into o; returns "" or the usage error (naming the flag).
std::string parse_motion_arguments(int argc, char** argv, int first, motion_options& o);

/// Validates the options' combinations, reads the scene, runs it; returns the exit status.  The
/// options come from parse_motion_arguments, which has refused a missing scene, --t-end, --out
/// (and validity's --vary): the one place the required flags are checked.
int motion(const motion_options& o);

/// appell horizon SCENE --t-end T [--every DT] [--scalars LIST] --out DIR: the long-horizon study.
struct horizon_options {
  std::string scene, t_end, every, out;
  std::vector<std::string> scalars{"double", "long-double", "dd", "float128"};
  bool quiet = false;
  /// --reference-order, --reference-tol: the 256-bit reference's Taylor order and tolerance
  /// (scenes without a closed form; default simulate's in mpfr at 256 bits: 60 and 2^-256).
  track_settings reference;
  /// --period: the scene's period, where the model knows none (the table's marks, the plot's
  /// axis), as written (the summary echoes it) and its value
  std::string period;
  double period_value = 0;
};
std::string parse_horizon_arguments(int argc, char** argv, int first, horizon_options& o);
/// Runs the study on options from parse_horizon_arguments (which checked scene, --t-end, --out).
int horizon(const horizon_options& o);

}  // namespace appell::cli
