// A scene's tables: reading their points (a list or a CSV file's columns) and checking them.
#include "appell/io/tables.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "appell/io/csv.hpp"
#include "appell/io/files.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {
namespace {

std::vector<std::string> decimals(const json_value& v, const std::string& where) {
  if (v.type != json_value::kind::array) throw input_error(where + ": expected a list of numbers");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.items.size(); ++i)
    out.push_back(decimal_text(v.items[i], where + "[" + std::to_string(i) + "]").text);
  return out;
}

table_points from_csv(const json_value& v, const std::string& where) {
  object_reader r(v, where);
  const std::string file = r.string("csv"), t = r.string("t"), value = r.string("value");
  r.finish();
  const std::string path = scene_relative_path(file);
  const csv::csv_table table =
      csv::parse_csv(path, read_text_file(path, table_limits::csv_bytes, "a table's CSV file"), true);
  auto column = [&](const std::string& name, const char* key) {
    for (std::size_t i = 0; i < table.header.size(); ++i)
      if (csv::trim(table.header[i]) == name) return i;
    throw input_error(where + "." + key + ": no column '" + printable(name) + "' in the header of " + path);
  };
  const std::size_t ti = column(t, "t"), vi = column(value, "value");
  if (table.rows.size() > table_limits::points)
    throw input_error(path + ": more than " + std::to_string(table_limits::points) + " points in one table");
  table_points p;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const int line = table.line_of_row[r];
    for (const std::size_t c : {ti, vi}) {
      const std::string x = csv::checked_decimal(table, line, c, table.rows[r][c]);
      if (!is_decimal_literal(x))
        throw input_error(csv::where(table, line, c) + ": '" + printable(x) + "' is not a decimal number");
      (c == ti ? p.t : p.value).push_back(x);
    }
  }
  return p;
}

}  // namespace

table_points read_table_points(const json_value& v, const std::string& where) {
  if (v.type != json_value::kind::object)
    throw input_error(where + ": expected {\"t\": [...], \"value\": [...]} or {\"csv\": file, \"t\": column, \"value\": column}");
  if (v.find("csv")) return from_csv(v, where);
  object_reader r(v, where);
  table_points p{decimals(r.raw("t"), r.path("t")), decimals(r.raw("value"), r.path("value"))};
  r.finish();
  if (p.t.size() != p.value.size())
    throw input_error(where + ": " + std::to_string(p.t.size()) + " times and " + std::to_string(p.value.size()) +
                      " values (one value per time)");
  return p;
}

piecewise_linear make_table(const std::string& name, const table_points& p, const std::string& where) {
  if (p.t.size() < 2) throw input_error(where + ": a table needs at least two points");
  if (p.t.size() > table_limits::points)
    throw input_error(where + ": more than " + std::to_string(table_limits::points) + " points");
  piecewise_linear out;
  out.name = name;
  out.values = p.value;
  out.times.reserve(p.t.size());
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    errno = 0;
    const double x = std::strtod(p.t[i].c_str(), nullptr);  // correctly rounded to nearest (glibc)
    if (!std::isfinite(x) || errno == ERANGE)
      throw input_error(where + ".t[" + std::to_string(i) + "]: " + p.t[i] + " is not a finite time of a double");
    if (i > 0 && !(x > out.times.back()))
      throw input_error(where + ".t[" + std::to_string(i) + "]: " + p.t[i] +
                        " does not come after the time before it (times strictly increasing, as doubles)");
    out.times.push_back(x);
  }
  return out;
}

}  // namespace appell
