// The `appell reference` and `appell score` commands: certified reference
// values for other implementations, and the scoring of their values.
//
// reference SCENE (--states FILE | --box SPEC --n N [--seed S] [--digits D] | --trajectory T --every DT)
//           --scalar interval|mpfi|arb [--bits N]
//           [--inputs decimal|binary64] [--project TOL] --out DIR
//   Many states of one scene in one process.  FILE is CSV: a header naming the
//   fields each row replaces in the scene (a plain name is a key of the scene's
//   "state", `omega[1]` an entry of a list there; a dotted path such as
//   `top.A` starts at the scene's root), an optional first column `state` (the
//   states' names; default their row numbers).  Writes DIR/reference.csv (one
//   row per state and quantity), DIR/reference.jsonl (one line per state) and
//   DIR/manifest.json, each written whole or not at all.
// score REFERENCE_DIR OTHER.csv [--min-digits D] [--plot FILE.png]
//   OTHER.csv: a column `state` and one column per quantity, named as appell's
//   results (`pivot_force[0]`); prints per quantity how many values lie inside
//   the enclosures, their correct digits and how many are within the suggested
//   tolerance; exit 0 when every value is within tolerance (and, with
//   --min-digits D, every quantity has at least D correct digits), 1 otherwise.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "progress.hpp"

namespace appell::cli {

struct reference_options {
  std::string scene, states, out_dir;
  std::string scalar = "interval";
  std::optional<unsigned> bits;
  bool binary64_inputs = false;
  std::string project;  ///< --project TOL: the scene's "project" (states off the constraints by <= TOL, projected)
  // --box SPEC --n N [--seed S] [--digits D] instead of --states: N states drawn uniformly on the
  // grid of D decimals (default 6) in the box SPEC = "field=lo:hi,field=lo:hi,..."; the other
  // fields keep the scene's values.  Drawn from std::mt19937_64 (fixed by the C++ standard) by
  // exact integer arithmetic: the same states on every machine.
  std::string box;
  // --trajectory T --every DT instead: the states of the scene's own motion at t = 0, DT, ..., T
  // (simulate in dd, each value the double nearest to it), named t=...; models with a motion.
  std::string trajectory, every;
  std::size_t n = 0;
  std::uint64_t seed = 1;
  int digits = 6;
  bool quiet = false;  ///< --quiet: no progress line
};

/// Returns the process exit status (0: every state certified; 3: some refused, counted on stderr).
int reference(const reference_options& o);

/// One state's lines of the dataset (the same text whichever process computes them).
struct reference_state_output {
  std::string csv, jsonl;
  bool certified = false;
};
/// The same lines, held elsewhere (a process's own outputs, or the text a rank sent).
struct reference_state_text {
  std::string_view csv, jsonl;
  bool certified = false;
};

/// `appell reference` in three steps, so that a distributed run (appell-mpi) can
/// share the states out: the constructor reads and checks every input (input_error
/// for bad input: nothing is computed or written); compute(i) certifies state i;
/// write() assembles the outputs in the states' order and writes them whole.
class reference_run {
 public:
  explicit reference_run(const reference_options& o);
  std::size_t states() const;
  reference_state_output compute(std::size_t i) const;
  /// Returns the exit status (0, or 3 when some states were refused).
  int write(const std::vector<reference_state_text>& outputs, int processes) const;

 private:
  struct impl;
  std::shared_ptr<const impl> p_;
};

/// "WHAT: k/N states, R per second (P%), about ... left" (progress.hpp).
void show_states_done(progress& line, std::size_t done, std::size_t total);

/// Parses the arguments of `reference` (argv[first..]); returns "" or the usage error.
std::string parse_reference_arguments(int argc, char** argv, int first, reference_options& o);

struct score_options {
  std::string reference_dir, other, plot;
  std::optional<double> min_digits;  ///< --min-digits D: also require D correct digits in every quantity
  /// --skip NAME,...: quantities of the reference left out of the score (each a name or a pattern,
  /// `*` any run of characters, matching at least one); every other quantity of the reference
  /// missing from OTHER.csv is a failure, named
  std::vector<std::string> skip;
};

/// Returns the process exit status (0: every value within tolerance; 1: not; 2: bad input).
int score(const score_options& o);

}  // namespace appell::cli
