// A scene's tables: reading their points (a list or a CSV file's columns) and checking them.
#include "appell/io/tables.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "appell/io/files.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

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
  std::filesystem::path path(file);
  if (path.is_relative() && !scene_directory().empty()) path = std::filesystem::path(scene_directory()) / path;
  const std::string text = read_text_file(path.string(), table_limits::csv_bytes, "a table's CSV file");
  table_points p;
  std::size_t line_number = 0, start = 0;
  std::vector<std::string> header;
  std::size_t ti = 0, vi = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = trim(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = split(line);
    const std::string at = path.string() + ":" + std::to_string(line_number);
    if (header.empty()) {
      header = fields;
      auto column = [&](const std::string& name, const char* key) {
        for (std::size_t i = 0; i < header.size(); ++i)
          if (header[i] == name) return i;
        throw input_error(where + "." + key + ": no column '" + printable(name) + "' in the header of " + at);
      };
      ti = column(t, "t");
      vi = column(value, "value");
      continue;
    }
    if (fields.size() != header.size())
      throw input_error(at + ": " + std::to_string(fields.size()) + " fields where the header has " +
                        std::to_string(header.size()));
    for (const std::size_t i : {ti, vi})
      if (!is_decimal_literal(fields[i]))
        throw input_error(at + ": '" + printable(fields[i]) + "' in column '" + printable(header[i]) +
                          "' is not a decimal number");
    if (p.t.size() >= table_limits::points)
      throw input_error(at + ": more than " + std::to_string(table_limits::points) + " points in one table");
    p.t.push_back(fields[ti]);
    p.value.push_back(fields[vi]);
  }
  if (header.empty()) throw input_error(path.string() + ": empty (a table's CSV file needs a header and rows)");
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
