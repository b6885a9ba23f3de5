// The flags every command shares, parsed in one place: the same flag means the same
// thing, and is refused the same way, in every command.
#pragma once

#include <optional>
#include <string>

#include "appell/io/json.hpp"  // printable

namespace appell::cli {

/// An integer flag's value: digits only (no sign, space or exponent: "+64", " 64", "1e3" are
/// refused), from lo to hi (hi below 10^9).  Returns "" and sets `into`, or the refusal (one line
/// naming the flag).
inline std::string parse_integer(const std::string& flag, const std::string& v, unsigned lo, unsigned hi, unsigned& into) {
  const std::string refusal = flag + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                              ", got '" + printable(v) + "'";
  if (v.empty() || v.size() > std::to_string(hi).size() || v.find_first_not_of("0123456789") != std::string::npos)
    return refusal;
  const unsigned long n = std::stoul(v);
  if (n < lo || n > hi) return refusal;
  into = static_cast<unsigned>(n);
  return "";
}

/// `--bits N`: an integer from 2 to 100000 (parse_integer).
inline std::string parse_bits(const std::string& v, std::optional<unsigned>& bits) {
  unsigned b = 0;
  if (std::string why = parse_integer("--bits", v, 2, 100000, b); !why.empty()) return why;
  bits = b;
  return "";
}

}  // namespace appell::cli
