// The motion commands' shared output pieces (motion_output.hpp): scalar-free, compiled once.
#include "motion_output.hpp"

#include <string>
#include <vector>

namespace appell::cli {

std::string csv_header(const std::vector<std::string>& header) {
  std::string line;
  for (std::size_t i = 0; i < header.size(); ++i) line += (i ? "," : "") + header[i];
  return line + "\n";
}

void csv_rows::row(const std::string& table, const std::vector<std::string>& cells) {
  std::string& t = text_[table];
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) t += ',';
    t += cells[i];
  }
  t += '\n';
}

const std::string& csv_rows::text(const std::string& table) const {
  static const std::string none;
  const auto it = text_.find(table);
  return it == text_.end() ? none : it->second;
}

}  // namespace appell::cli
