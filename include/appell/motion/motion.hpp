// appell's motion as a library service: simulate, enclose (with each contact's verdict and its
// located first failure), validity (a range of one field split until each piece is proved) and
// the long-horizon tracks, for a scene of any model that moves (io/model_motion.hpp), in any
// standard scalar named at run time.
//
// The boundary is scalar-free: settings in (decimals as text, so that an interval run starts
// from the enclosure of the number written, not of a double near it), rows out through a sink
// (every number an exact decimal, interval bounds rounded outward), a report back (the same
// text, and doubles where they only feed a plot or a progress line).  The runs are templates of
// the model and the scalar (motion/engine.hpp), compiled once per model and scalar in units
// CMake generates (cmake/instantiate.cmake); a caller includes this header only and links
// appell::motion.  The command line (`appell simulate`, `enclose`, `validity`, `horizon`) is a
// client of these calls; docs/motion.md shows an enclose from C++.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "appell/io/model_motion.hpp"
#include "appell/io/scene.hpp"
#include "appell/motion/pieces.hpp"

namespace appell::motion {

/// A run's settings.  Numbers that enter the arithmetic are decimals as text (t_end, every,
/// mu, the range of vary); the others are doubles (tolerances, widths, seconds).
struct settings {
  /// A standard scalar's name (standard_scalars.hpp); "": double for simulate, interval for
  /// enclose and validity.
  std::string scalar;
  std::optional<unsigned> bits;  ///< mpfr's and mpfi's precision (default 256)
  std::string t_end;             ///< the horizon T (required)
  /// simulate: the output step ("": T / 100).
  std::string every;
  std::optional<int> order;   ///< the Taylor order (default: the scalar's, from its precision)
  std::optional<double> tol;  ///< the relative error per step (default 2^-bits)
  double max_width = 1.0;     ///< enclose: the widest state enclosure a step may reach
  /// Stop cleanly after this many seconds: the run reports what it reached (incomplete).
  std::optional<double> max_seconds;
  std::optional<double> locate;      ///< enclose: narrow each contact's first failure to this width
  bool until_contact_fails = false;  ///< enclose: stop after the first step in which a contact is proved to fail
  /// validity: the range of one field (a state component of the motion, a model parameter, or
  /// "mu") split into pieces until each is proved to hold or to fail over [0, T], or is
  /// narrower than resolution (default: the range / 64).
  std::string vary_field, vary_lo, vary_hi;
  std::optional<double> resolution;
  /// enclose, validity: every contact's friction coefficient, in place of the scene's.
  std::optional<std::string> mu;
  /// validity: the threads that run its pieces (0: one).
  int jobs = 0;
  /// validity across processes (appell-mpi): the other ranks (pieces.hpp); null: this process.
  const piece_network* pieces = nullptr;
  /// Called as the run goes, with the fraction done (of [0, T], or of validity's range); it
  /// may throw ode::run_stopped to end the run there (what was reached is reported).
  std::function<void(double)> progress;
};

/// Where a run's rows go, as they come: each table's column names once, before its first row,
/// then its rows, one cell per column, every number an exact decimal (an interval's bounds
/// rounded outward).  Tables: "trajectory" (simulate: t, the state, the results and the
/// invariants at each output time), "steps" (enclose: each step [t0, t1], the state at t1 and
/// over the step, the results and invariants over the step), "contacts" (enclose: each
/// contact's forces and required mu over each step, and the step's verdict).
class row_sink {
 public:
  virtual ~row_sink() = default;
  virtual void columns(const std::string& table, const std::vector<std::string>& names) = 0;
  virtual void row(const std::string& table, const std::vector<std::string>& cells) = 0;
};

/// A sink that keeps nothing (the report alone is wanted).
class discard_rows final : public row_sink {
 public:
  void columns(const std::string&, const std::vector<std::string>&) override {}
  void row(const std::string&, const std::vector<std::string>&) override {}
};

/// What every report names: the model, the scalar and the run's settings as used.
struct run_identity {
  std::string model, scalar;
  unsigned bits = 0;            ///< the bits the scalar works in (as `appell eval` reports them)
  unsigned bits_requested = 0;  ///< the bits asked for where the scalar could not take exactly that many, else 0
  std::string bits_text() const;  ///< "114 bits" or "114 bits (113 requested)"
  int order = 0;
  double tol = 0;
};

struct simulate_report {
  run_identity id;
  std::string failure;              ///< why the run stopped before T, or "" (complete)
  std::vector<std::string> header;  ///< the trajectory table's columns
  long rows = 0;                    ///< the rows sent to the sink
  std::string drift;                ///< the drift plot's data: t and each invariant's drift, a line per row
  struct invariant {
    std::string name, initial, final;
    bool zero_in_truth = false;
    double worst = 0;  ///< the largest |I(t)| (zero in truth) or relative drift
  };
  std::vector<invariant> invariants;
  std::vector<std::pair<std::string, std::string>> final_state;
  std::string t_reached = "0";  ///< the last row's time, its exact decimal
  long steps = 0;
  double seconds = 0, min_step = 0, max_step = 0;
};

/// A contact's verdict along an enclosed motion (contact_track.hpp), as text.
struct contact_report {
  std::string name, mu_text, verdict;  ///< verdict: holds, fails, undecided
  long refined = 0;
  std::optional<std::string> least_normal;  ///< its lower bound
  std::optional<std::string> largest_mu;    ///< its upper bound; none when unbounded or never formed
  std::string holding_lo, holding_hi;       ///< the holding prefix's end, rounded down and up
  std::optional<std::string> fails_by;      ///< the earliest time failure is proved (upper bound)
  double fails_by_t = 0;                    ///< the same, for the plot
  std::string located;
};

struct enclose_report {
  run_identity id;
  std::vector<std::string> header;       ///< the steps table's columns
  long rows = 0;                         ///< the steps sent to the sink
  std::string widths;                    ///< the widths plot's data
  std::vector<std::string> value_names;  ///< the results' values, then the invariants'
  std::size_t result_values = 0;
  std::vector<double> widest_over;  ///< per value: the largest width over a step
  std::vector<std::pair<std::string, std::string>> final_state;
  double final_width = 0;
  std::vector<contact_report> contacts;
  std::string contact_stop;  ///< until_contact_fails: why the run stopped, or ""
  bool complete = false;
  std::string reason;
  std::string t_reached = "0";  ///< the last step's end, a decimal rounded down: enclosed over [0, t_reached]
  long steps = 0, rejected = 0;
  long variational_steps = 0;  ///< steps whose linear part came from the variational equation
  double seconds = 0;
};

struct validity_report {
  run_identity id;
  double resolution = 0, t_end = 0, seconds = 0;
  pieces_outcome run;
  int threads = 1, processes = 1;  ///< the leading rank's threads; the MPI processes (1 without MPI)
  /// the leading rank's threads, then one worker per other rank
  int workers() const { return threads + processes - 1; }
  /// A rank that only ran the pieces it was sent (settings::pieces with serve): nothing to report.
  bool served = false;
};

/// The columns of the "contacts" table.
const std::vector<std::string>& contact_columns();

/// The motion of the scene from 0 to T in a point scalar, rows every settings.every.  A run
/// that stops on the way (a state no longer finite, a step collapse, max_seconds, progress's
/// run_stopped) reports what it reached (failure); input_error for settings it cannot run.
simulate_report simulate(const scene_input& scene, const settings& s, row_sink& rows);
/// A rigorous enclosure of the motion over [0, T] in an interval scalar, each contact judged
/// over every step.  Incomplete (complete false, with the reason) when a step cannot be
/// enclosed narrower than max_width, or on max_seconds.
enclose_report enclose(const scene_input& scene, const settings& s, row_sink& rows);
/// The range of settings.vary_field split until each piece's contacts are proved to hold or to
/// fail over [0, T] (or the piece is narrower than the resolution).
validity_report validity(const scene_input& scene, const settings& s);

/// summary.json of `appell simulate`, `enclose` and `validity`: the report with the settings it
/// ran under, `scene` the scene's name as the caller gave it (a path).
nlohmann::json summary(const simulate_report& r, const settings& s, const std::string& scene);
nlohmann::json summary(const enclose_report& r, const settings& s, const std::string& scene);
nlohmann::json summary(const validity_report& r, const settings& s, const std::string& scene);

/// One scalar's trajectory for the long-horizon study: the states at t = 0, every, 2 every, ...
/// as exact decimals of the scalar's values (lower_string: a point's value, written in full).
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

/// The Taylor order and tolerance of a track (none: simulate's defaults for the scalar).
struct track_settings {
  std::optional<int> order;
  std::optional<double> tol;
};

/// simulate in the point scalar `scalar` (mpfr and mpfi at `bits`, default 256) from 0 to t_end
/// with outputs every `every` (decimals), at the order and tolerance of `settings`;
/// progress(fraction) as the run goes.
horizon_track track(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits,
                    const std::string& t_end, const std::string& every, const track_settings& settings = {},
                    const std::function<void(double)>& progress = {});

/// The scene fields of the model's motion state, in the order of its state (input_error naming
/// the model when it does not move).
std::vector<std::string> state_fields(const scene_input& scene);

/// The scene's motion in closed form where its model knows it (horizon's reference), else none.
std::optional<motion_closed_form> closed_form_of(const scene_input& scene);

/// The models that move, in the registry's order, separated by ", ".
std::string moving_model_names();

}  // namespace appell::motion
