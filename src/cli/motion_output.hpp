// The motion commands' output layer: the library's reports (motion/motion.hpp) turned into the
// command's files (CSV, summary.json, the plots) and its summary lines.  Scalar-free, compiled
// once (motion_output.cpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "appell/motion/motion.hpp"
#include "motion_commands.hpp"

namespace appell::cli {

/// The rows of a run as CSV text, one text per table (the lines after the header).
class csv_rows final : public motion::row_sink {
 public:
  void columns(const std::string&, const std::vector<std::string>&) override {}
  void row(const std::string& table, const std::vector<std::string>& cells) override;
  /// The table's lines ("" when it had no row).
  const std::string& text(const std::string& table) const;

 private:
  std::map<std::string, std::string> text_;
};

/// Writes DIR/trajectory.csv, summary.json and drift.png; the summary lines and exit status.
motion_outcome write_simulate(const motion::simulate_report& r, const csv_rows& rows, const motion_options& o);

/// Writes DIR/steps.csv, contacts.csv (with contacts), summary.json, widths.png and
/// contacts.png; the summary lines and exit status.
motion_outcome write_enclose(const motion::enclose_report& r, const csv_rows& rows, const motion_options& o);

/// Writes DIR/validity.csv, summary.json and validity.png; the summary lines and exit status.
motion_outcome write_validity(const motion::validity_report& r, const motion_options& o);

}  // namespace appell::cli
