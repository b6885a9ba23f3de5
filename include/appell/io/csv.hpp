// appell/io/csv.hpp -- CSV files: `appell reference`'s states and `appell score`'s values, a scene's
// tables (SCENES.md, "tables"): comma-separated, fields optionally in double quotes ("" inside
// one is a quote), a header line naming the columns.  Scalar-free.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace appell::csv {

struct csv_table {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> line_of_row;  ///< 1-based line numbers, for messages
};

/// "PATH line L, column C (NAME)": where a value is, for messages.
std::string where(const csv_table& t, int line, std::size_t column);

/// The CSV `text` read from `path` (named in the messages); input_error on a malformed table.
/// With `comments`, a line that begins with # is skipped (a scene's table files; the reference
/// commands' files have none).
csv_table parse_csv(const std::string& path, const std::string& text, bool comments = false);

/// A states or values file's limit (a CSV of --n's 10^7 states at about 100 bytes a state).
constexpr std::size_t states_file_bytes = std::size_t(1) << 30;

/// The CSV file at `path` (at most states_file_bytes), `what` naming it in messages.
csv_table read_csv(const std::string& path, const char* what);

/// `s` without the blanks and tabs around it.
std::string trim(const std::string& s);

/// A finite decimal, checked (NaN and infinities named as such); input_error naming where.
std::string checked_decimal(const csv_table& t, int line, std::size_t column, const std::string& raw);

/// `s` as one CSV field (quoted when it holds a comma, a quote or a line break).
std::string csv_field(const std::string& s);

}  // namespace appell::csv
