// CSV files (appell/io/csv.hpp).
#include "appell/io/csv.hpp"

#include <cctype>
#include <stdexcept>

#include "appell/io/files.hpp"
#include "appell/io/json.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell::csv {


std::string where(const csv_table& t, int line, std::size_t column) {
  return t.path + " line " + std::to_string(line) + ", column " + std::to_string(column + 1) +
         (column < t.header.size() ? " (" + printable(t.header[column]) + ")" : std::string());
}

/// The CSV `text` read from `path` (named in the messages).
csv_table parse_csv(const std::string& path, const std::string& text, bool comments) {
  csv_table t;
  t.path = path;
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, any = false;
  int line = 1, row_line = 1;
  auto end_row = [&] {
    fields.push_back(field);
    field.clear();
    const bool blank = fields.size() == 1 && fields[0].empty() && !any;
    if (!blank) {
      if (t.header.empty()) {
        t.header = fields;
      } else {
        t.rows.push_back(fields);
        t.line_of_row.push_back(row_line);
      }
    }
    fields.clear();
    any = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (comments && c == '#' && !quoted && !any && fields.empty() &&
        field.find_first_not_of(" \t") == std::string::npos) {  // a comment line (blanks before # allowed)
      field.clear();
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      continue;  // its line break ends an empty row, which is skipped as blank
    }
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    if (c == '"') {
      quoted = true;
      any = true;
    } else if (c == ',') {
      fields.push_back(field);
      field.clear();
      any = true;
    } else if (c == '\n') {
      end_row();
      row_line = ++line;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (quoted) throw input_error(path + " line " + std::to_string(row_line) + ": a quoted field is not closed");
  if (!field.empty() || !fields.empty() || any) end_row();
  if (t.header.empty()) throw input_error(path + ": empty (expected a header line naming the columns)");
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r].size() != t.header.size())
      throw input_error(path + " line " + std::to_string(t.line_of_row[r]) + ": " + std::to_string(t.rows[r].size()) +
                        " fields, the header has " + std::to_string(t.header.size()));
  return t;
}

csv_table read_csv(const std::string& path, const char* what) {
  return parse_csv(path, read_text_file(path, states_file_bytes, what));
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// A finite decimal, checked; NaN and infinities named as such.
std::string checked_decimal(const csv_table& t, int line, std::size_t column, const std::string& raw) {
  const std::string s = trim(raw);
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string bare = !lower.empty() && (lower[0] == '-' || lower[0] == '+') ? lower.substr(1) : lower;
  if (bare == "nan" || bare == "inf" || bare == "infinity")
    throw input_error(where(t, line, column) + ": " + printable(s) + " is not a finite number");
  if (s.empty()) throw input_error(where(t, line, column) + ": empty, expected a decimal number");
  try {
    (void)decimal_sign_of_sum({{1, s}});
  } catch (const std::exception& e) {
    throw input_error(where(t, line, column) + ": '" + printable(s) + "' is not a decimal number (" + e.what() + ")");
  }
  return s;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace appell::csv
