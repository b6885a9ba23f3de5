// The flags every command shares, parsed in one place: the same flag means the same
// thing, and is refused the same way, in every command.
#pragma once

#include <optional>
#include <string>

#include "appell/io/json.hpp"  // printable

namespace appell::cli {

/// `--bits N`: digits only (no sign, space or exponent: "+64", " 64", "1e3" are refused), from
/// 2 to 100000.  Returns "" and sets `bits`, or the refusal (one line naming the flag).
inline std::string parse_bits(const std::string& v, std::optional<unsigned>& bits) {
  const std::string refusal = "--bits: expected an integer from 2 to 100000, got '" + printable(v) + "'";
  if (v.empty() || v.size() > 6 || v.find_first_not_of("0123456789") != std::string::npos) return refusal;
  const unsigned long b = std::stoul(v);
  if (b < 2 || b > 100000) return refusal;
  bits = static_cast<unsigned>(b);
  return "";
}

}  // namespace appell::cli
