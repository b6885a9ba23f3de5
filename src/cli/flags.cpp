// The command line of every command (flags.hpp).
#include "flags.hpp"

#include <algorithm>
#include <iostream>

#include "commands.hpp"

#include "appell/io/json.hpp"  // printable

namespace appell::cli {

std::string read_command_line(const std::string& command, int argc, char** argv, int first,
                              const std::vector<std::string>& value_flags, const std::vector<std::string>& switches,
                              std::size_t max_positional, command_line& out) {
  out.command = command;
  auto listed = [](const std::vector<std::string>& list, const std::string& a) {
    return std::find(list.begin(), list.end(), a) != list.end();
  };
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if (listed(value_flags, a)) {
      if (i + 1 >= argc) return a + ": missing value";
      if (out.values.count(a)) return a + ": given twice";
      out.values[a] = argv[++i];
    } else if (listed(switches, a)) {
      if (out.switches.count(a)) return a + ": given twice";
      out.switches.insert(a);
    } else if (!a.empty() && a[0] == '-') {
      return command + ": unknown option '" + printable(a) + "'";
    } else {
      if (out.positional.size() == max_positional)
        return command + (max_positional == 1 ? ": more than one scene given ('" : ": unexpected argument ('") +
               printable(a) + "')";
      out.positional.push_back(a);
    }
  }
  return "";
}

std::string read_scene_argument(const command_line& c, std::string& scene) {
  if (c.positional.empty()) return c.command + ": no scene given";
  scene = c.positional[0];
  return "";
}

std::string parse_integer(const std::string& flag, const std::string& v, unsigned lo, unsigned hi, unsigned& into) {
  const std::string refusal = flag + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                              ", got '" + printable(v) + "'";
  if (v.empty() || v.size() > std::to_string(hi).size() || v.find_first_not_of("0123456789") != std::string::npos)
    return refusal;
  const unsigned long n = std::stoul(v);
  if (n < lo || n > hi) return refusal;
  into = static_cast<unsigned>(n);
  return "";
}

std::string parse_bits(const std::string& v, std::optional<unsigned>& bits) {
  unsigned b = 0;
  if (std::string why = parse_integer("--bits", v, 2, 100000, b); !why.empty()) return why;
  bits = b;
  return "";
}

std::string read_scalar(const command_line& c, std::string& scalar, std::optional<unsigned>& bits) {
  if (const auto it = c.values.find("--scalar"); it != c.values.end()) {
    if (it->second.empty()) return "--scalar: empty, expected a scalar's name";
    scalar = it->second;
  }
  if (const auto it = c.values.find("--bits"); it != c.values.end()) return parse_bits(it->second, bits);
  return "";
}

std::string read_out(const command_line& c, std::string& out) {
  const auto it = c.values.find("--out");
  if (it == c.values.end()) return c.command + ": --out DIR is required";
  if (it->second.empty()) return "--out: empty, expected a directory";
  out = it->second;
  return "";
}

std::string read_format(const command_line& c, std::string& format) {
  if (const auto it = c.values.find("--format"); it != c.values.end()) {
    if (it->second != "json" && it->second != "text")
      return "--format: expected json or text, got '" + printable(it->second) + "'";
    format = it->second;
  }
  return "";
}

void set_project(json_value& scene, const std::string& tol, const std::string& scene_path) {
  if (scene.type != json_value::kind::object) throw input_error(scene_path + ": not a JSON object");
  json_value value;
  value.type = json_value::kind::string;
  value.text = tol;
  for (auto& m : scene.members)
    if (m.key == "project") {
      m.value = value;
      return;
    }
  scene.members.push_back({"project", value});
}

int usage_error(const std::string& why) {
  std::cerr << "appell: " << one_line(why) << " (appell --help lists the commands and options)\n";
  return exit_code(exit_status::bad_input);
}

int print_result(const std::string& out) {
  std::cout << out;
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "appell: internal error: could not write the result to stdout\n";
    return exit_code(exit_status::internal);
  }
  return exit_code(exit_status::done);
}

}  // namespace appell::cli
