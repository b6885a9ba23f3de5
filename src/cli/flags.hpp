// The command line of every command, read in one place (flags.cpp): the same flag means the
// same thing, and is refused the same way, in every command.
//
//   read_command_line  the generic pass: flags that take a value, switches, positional arguments;
//                      refused (one line, exit 2): an unknown option, a missing value, a flag
//                      given twice, too many positional arguments
//   read_scalar        --scalar NAME [--bits N]       (eval, linearize, reference, simulate, ...)
//   read_out           --out DIR, required wherever a command writes files
//   read_format        --format json|text             (eval, linearize: what they print)
//   parse_integer, parse_bits: digits only, in a range ("+64", " 64", "1e3" are refused)
// --quiet, on every command that shows a progress line, silences it.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "appell/io/json.hpp"

namespace appell::cli {

/// One command's arguments.
struct command_line {
  std::string command;
  std::map<std::string, std::string> values;  ///< flag -> its value
  std::set<std::string> switches;             ///< the switches given
  std::vector<std::string> positional;

  bool has(const std::string& flag) const { return values.count(flag) > 0 || switches.count(flag) > 0; }
  /// The flag's value, or `fallback` when the flag was not given.
  std::string value_or(const std::string& flag, const std::string& fallback) const {
    const auto it = values.find(flag);
    return it == values.end() ? fallback : it->second;
  }
};

/// Reads argv[first..] for `command`: each of `value_flags` takes the next argument as its
/// value; each of `switches` stands alone; any other argument that begins with '-' is an unknown
/// option; the rest are positional, at most `max_positional` of them.  Returns "" or the refusal.
std::string read_command_line(const std::string& command, int argc, char** argv, int first,
                              const std::vector<std::string>& value_flags, const std::vector<std::string>& switches,
                              std::size_t max_positional, command_line& out);

/// The one scene a command takes (its one positional argument): "" or "COMMAND: no scene given".
std::string read_scene_argument(const command_line& c, std::string& scene);

/// An integer flag's value: digits only (no sign, space or exponent: "+64", " 64", "1e3" are
/// refused), from lo to hi (hi below 10^9).  Returns "" and sets `into`, or the refusal (one line
/// naming the flag).
std::string parse_integer(const std::string& flag, const std::string& v, unsigned lo, unsigned hi, unsigned& into);

/// `--bits N`: an integer from 2 to 100000 (parse_integer).
std::string parse_bits(const std::string& v, std::optional<unsigned>& bits);

/// --scalar NAME and --bits N where given (the name is checked where the scalar is chosen:
/// with_scalar, which also refuses --bits for a fixed-precision scalar).
std::string read_scalar(const command_line& c, std::string& scalar, std::optional<unsigned>& bits);

/// --out DIR, required: "" or "COMMAND: --out DIR is required".
std::string read_out(const command_line& c, std::string& out);

/// --format json|text where given.
std::string read_format(const command_line& c, std::string& format);

/// --project TOL (eval, reference): the scene's "project" set to TOL, or replaced (the scene's
/// reader checks it as it checks the member); input_error when the scene is not a JSON object.
void set_project(json_value& scene, const std::string& tol, const std::string& scene_path);

}  // namespace appell::cli
