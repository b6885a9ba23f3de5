// The motion commands' output layer: what simulate, enclose and validity found, as scalar-free
// reports (every number already text or a double), and the writers that turn a report into the
// command's files (CSV, summary.json, the plots) and its summary lines.  The runs are templated
// on the scalar and the model (motion_run.hpp, compiled per model and scalar); these writers are
// compiled once (motion_output.cpp).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "motion_commands.hpp"
#include "pieces.hpp"

namespace appell::cli {

/// What every motion report names: the run's scalar and its settings.
struct run_identity {
  std::string model, scalar;
  unsigned bits = 0;            ///< the bits the scalar works in (summary.json "bits", as eval's "bits")
  unsigned bits_requested = 0;  ///< --bits where the scalar could not take exactly that many, else 0
  std::string bits_text() const;  ///< "114 bits" or "114 bits (113 requested)"
  int order = 0;
  double tol = 0;
};

struct simulate_report {
  run_identity id;
  std::string failure;           ///< why the run stopped before T, or "" (complete)
  std::vector<std::string> header;  ///< trajectory.csv's columns
  std::string rows;              ///< trajectory.csv's lines after the header
  std::string drift;             ///< the drift plot's data: t and each invariant's drift
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

/// Writes DIR/trajectory.csv, summary.json and drift.png; the summary lines and exit status.
motion_outcome write_simulate(const simulate_report& r, const motion_options& o);

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
  std::vector<std::string> header;  ///< steps.csv's columns
  std::string rows;                 ///< steps.csv's lines after the header
  std::string widths;               ///< the widths plot's data
  std::vector<std::string> value_names;  ///< the results' values, then the invariants'
  std::size_t result_values = 0;
  std::vector<double> widest_over;  ///< per value: the largest width over a step
  std::vector<std::pair<std::string, std::string>> final_state;
  double final_width = 0;
  std::vector<contact_report> contacts;
  std::string contact_rows;  ///< contacts.csv's lines after the header
  std::string contact_stop;  ///< --until-contact-fails: why the run stopped, or ""
  bool complete = false;
  std::string reason;
  std::string t_reached = "0";  ///< the last step's end, a decimal rounded down: enclosed over [0, t_reached]
  long steps = 0, rejected = 0;
  double seconds = 0;
};

/// Writes DIR/steps.csv, contacts.csv (with contacts), summary.json, widths.png and
/// contacts.png; the summary lines and exit status.
motion_outcome write_enclose(const enclose_report& r, const motion_options& o);

struct validity_report {
  run_identity id;
  double resolution = 0, t_end = 0, seconds = 0;
  pieces_outcome run;
  int threads = 1, processes = 1;  ///< rank 0's threads; the MPI processes (1 without MPI)
  /// rank 0's threads, then one worker per other rank
  int workers() const { return threads + processes - 1; }
};

/// Writes DIR/validity.csv, summary.json and validity.png; the summary lines and exit status.
motion_outcome write_validity(const validity_report& r, const motion_options& o);

}  // namespace appell::cli
