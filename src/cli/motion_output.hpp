// What the motion commands' outputs share: the rows a run sends to its sink, kept as CSV text
// per table, and the CSV header line.  Each command turns the library's report (motion/motion.hpp)
// into its files and summary lines in its own file (simulate.cpp, enclose.cpp, validity.cpp).
// Scalar-free, compiled once (motion_output.cpp).
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

/// A CSV header line: the names joined by commas, then a newline.
std::string csv_header(const std::vector<std::string>& header);

}  // namespace appell::cli
