// The `appell reference` and `appell score` commands: certified reference
// values for other implementations, and the scoring of their values.
//
// reference SCENE --states FILE --scalar interval|mpfi [--bits N] [--inputs decimal|binary64] --out DIR
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

#include <optional>
#include <string>

namespace appell::cli {

struct reference_options {
  std::string scene, states, out_dir;
  std::string scalar = "interval";
  std::optional<unsigned> bits;
  bool binary64_inputs = false;
};

/// Returns the process exit status (0: every state certified; 3: some refused, counted on stderr).
int reference(const reference_options& o);

struct score_options {
  std::string reference_dir, other, plot;
  std::optional<double> min_digits;  ///< --min-digits D: also require D correct digits in every quantity
};

/// Returns the process exit status (0: every value within tolerance; 1: not; 2: bad input).
int score(const score_options& o);

}  // namespace appell::cli
