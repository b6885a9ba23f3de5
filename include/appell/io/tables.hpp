// appell/io/tables.hpp -- a scene's tables (SCENES.md, "tables"): functions of time given by
// values at breakpoints and joined by straight lines, such as a torque a controller logged, read
// from a list in the scene or from two columns of a CSV file beside it.
#pragma once

#include <string>
#include <vector>

#include "appell/expr/expression.hpp"
#include "appell/io/json.hpp"

namespace appell {

/// What a table may hold (bounded time and memory on any input).
struct table_limits {
  static constexpr std::size_t points = 1000000;           ///< of one table
  static constexpr std::size_t csv_bytes = 64u << 20;      ///< a CSV file: 64 MiB
};

/// A table's points as written: its times and values (decimal texts), from the scene's lists
/// {"t": [...], "value": [...]} or from a CSV file's columns {"csv": F, "t": C, "value": D}
/// (F relative to the scene's directory).  input_error naming `where` and the field otherwise.
struct table_points {
  std::vector<std::string> t, value;
};
table_points read_table_points(const json_value& v, const std::string& where);

/// The table named `name` of these points: its times rounded to the nearest doubles, which must
/// be finite and strictly increasing, at least two of them; its values exact decimals.
piecewise_linear make_table(const std::string& name, const table_points& p, const std::string& where);

}  // namespace appell
