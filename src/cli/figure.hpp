// A measured figure for the commands' tables and CSV files.
#pragma once

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace appell::cli {

/// A measured figure for tables and CSV files: `precision` significant digits, "" for NaN.
inline std::string figure(double x, int precision = 3) {
  if (std::isnan(x)) return "";
  std::ostringstream s;
  s << std::setprecision(precision) << x;
  return s.str();
}

}  // namespace appell::cli
