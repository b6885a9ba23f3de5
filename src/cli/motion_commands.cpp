// What `appell simulate`, `appell enclose` and `appell validity` share (motion_commands.hpp):
// their flags parsed into the library's settings (appell/motion/motion.hpp), the flags that
// belong to another of them refused by name, and the progress line.  Each command's own checks,
// run and files are in its file (simulate.cpp, enclose.cpp, validity.cpp).
#include "motion_commands.hpp"

#include "commands.hpp"
#include "flags.hpp"

#include "appell/motion/checks.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell::cli {

std::string parse_taylor_order(const std::string& flag, const std::string& text, std::optional<int>& into) {
  unsigned n = 0;
  if (std::string why = parse_integer(flag, text, 2, 60, n); !why.empty()) return why;
  into = static_cast<int>(n);
  return "";
}

std::string parse_step_tolerance(const std::string& flag, const std::string& text, std::optional<double>& into) {
  try {
    into = positive_decimal(flag, text);
  } catch (const input_error& e) {
    return e.what();
  }
  if (*into >= 1) return flag + ": expected a positive decimal below 1 (a relative error per step), got '" + text + "'";
  return "";
}

std::string parse_motion_arguments(int argc, char** argv, int first, motion_options& o) {
  command_line c;
  if (std::string why = read_command_line(o.command, argc, argv, first,
                                          {"--t-end", "--every", "--out", "--scalar", "--bits", "--order", "--tol",
                                           "--max-width", "--max-seconds", "--locate", "--vary", "--resolution", "--jobs",
                                           "--mu"},
                                          {"--quiet", "--until-contact-fails"}, 1, c);
      !why.empty())
    return why;
  if (std::string why = read_scene_argument(c, o.scene); !why.empty()) return why;
  if (std::string why = read_scalar(c, o.scalar, o.bits); !why.empty()) return why;
  o.quiet = c.has("--quiet");
  o.until_contact_fails = c.has("--until-contact-fails");
  o.t_end = c.value_or("--t-end", "");
  o.every = c.value_or("--every", "");
  for (const auto& [a, v] : c.values) {
    // The flag's value as a positive decimal, or why not.
    auto positive = [&](std::optional<double>& into) -> std::string {
      try {
        into = positive_decimal(a, v);
      } catch (const input_error& e) {
        return e.what();
      }
      return "";
    };
    if (a == "--order") {
      if (std::string why = parse_taylor_order(a, v, o.order); !why.empty()) return why;
    } else if (a == "--jobs") {
      unsigned n = 0;
      if (std::string why = parse_integer("--jobs", v, 1, 1024, n); !why.empty()) return why;
      o.jobs = static_cast<int>(n);
    } else if (a == "--tol") {
      if (std::string why = parse_step_tolerance(a, v, o.tol); !why.empty()) return why;
    } else if (a == "--vary") {
      const auto eq = v.find('='), colon = v.find(':', eq == std::string::npos ? 0 : eq);
      if (eq == std::string::npos || eq == 0 || colon == std::string::npos)
        return "--vary: expected FIELD=lo:hi, got '" + v + "'";
      o.vary_field = v.substr(0, eq);
      o.vary_lo = v.substr(eq + 1, colon - eq - 1);
      o.vary_hi = v.substr(colon + 1);
      try {
        motion::check_range(o.vary_field, o.vary_lo, o.vary_hi);
      } catch (const input_error& e) {
        return e.what();
      }
    } else if (a == "--mu") {
      try {
        motion::check_friction(v);
      } catch (const input_error& e) {
        return e.what();
      }
      o.mu = v;
    } else if (a == "--resolution") {
      if (std::string why = positive(o.resolution); !why.empty()) return why;
    } else if (a == "--locate") {
      if (std::string why = positive(o.locate); !why.empty()) return why;
    } else if (a == "--max-seconds") {
      if (std::string why = positive(o.max_seconds); !why.empty()) return why;
    } else if (a == "--max-width") {
      std::optional<double> width;
      if (std::string why = positive(width); !why.empty()) return why;
      o.max_width = *width;
    }
  }
  // the required flags last, in the usage's order: a wrong value is named before a missing flag
  if (o.t_end.empty()) return "--t-end: required (the horizon, a positive decimal)";
  if (o.command == "validity" && o.vary_field.empty()) return "--vary: required (FIELD=lo:hi, the range to split)";
  return read_out(c, o.out);
}

double checked_motion_flags(motion_options& o) {
  const double horizon = positive_decimal("--t-end", o.t_end);
  if (o.command != "simulate" && !o.every.empty())
    throw input_error("--every: enclose writes every step; --every applies to simulate");
  if (o.mu && o.command != "enclose" && o.command != "validity")
    throw input_error("--mu: applies to enclose and validity (every contact's friction coefficient)");
  if (o.command != "validity") {
    if (o.jobs != 0 && o.command != "enclose")
      throw input_error("--jobs: applies to enclose (its steps' threads) and validity (its pieces' threads)");
    if (!o.vary_field.empty() || o.resolution)
      throw input_error(std::string(o.resolution ? "--resolution" : "--vary") + ": applies to validity");
  }
  if (o.command == "simulate" && (o.locate || o.until_contact_fails))
    throw input_error(std::string(o.locate ? "--locate" : "--until-contact-fails") +
                      ": the contacts' verdicts over time are enclose's (simulate's point values prove nothing)");
  if (o.scalar.empty()) o.scalar = o.command == "simulate" ? "double" : "interval";
  return horizon;
}

int motion_command(const char* name, int argc, char** argv, int first, int (*run)(const motion_options&)) {
  motion_options m;
  m.command = name;
  if (const std::string why = parse_motion_arguments(argc, argv, first, m); !why.empty()) return usage_error(why);
  return guarded([&] { return run(m); });
}

}  // namespace appell::cli
