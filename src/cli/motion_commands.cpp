// `appell simulate`, `appell enclose` and `appell validity` (motion_commands.hpp): their flags
// parsed into the library's settings (appell/motion/motion.hpp), the runs, their files written
// through motion_output.hpp.
#include "motion_commands.hpp"

#include "commands.hpp"
#include "flags.hpp"
#include "motion_output.hpp"
#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <iostream>

#include "appell/motion/checks.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"

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

int motion(const motion_options& given) {
  motion_options o = given;  // parse_motion_arguments has checked the required flags (scene, --t-end, --out)
  const double horizon = positive_decimal("--t-end", o.t_end);
  if (o.command == "simulate") {
    if (o.every.empty()) {
      o.every = o.t_end + "e-2";  // 100 outputs
      if (o.t_end.find_first_of("eE") != std::string::npos) o.every = to_decimal(horizon / 100);
    }
    const double every = positive_decimal("--every", o.every);
    if (every > horizon) throw input_error("--every: the output step " + o.every + " is larger than the horizon " + o.t_end);
    if (horizon / every > 1e7) throw input_error("--every: more than 10^7 output times; choose a larger step");
  } else if (!o.every.empty()) {
    throw input_error("--every: enclose writes every step; --every applies to simulate");
  }
  if (o.mu && o.command != "enclose" && o.command != "validity")
    throw input_error("--mu: applies to enclose and validity (every contact's friction coefficient)");
  if (o.command == "validity") {
    if (o.mu && o.vary_field == "mu") throw input_error("--mu: fixes mu, which --vary mu varies; give one of them");
    if (o.locate || o.until_contact_fails)
      throw input_error(std::string(o.locate ? "--locate" : "--until-contact-fails") + ": applies to enclose, not validity");
    if (o.resolution && *o.resolution >= from_decimal<double>(o.vary_hi) - from_decimal<double>(o.vary_lo))
      throw input_error("--resolution: as wide as the range or wider: nothing would be split");
    if (o.jobs == 0) o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  } else if (o.jobs != 0) {
    throw input_error("--jobs: applies to validity (its pieces run on that many threads)");
  } else if (!o.vary_field.empty() || o.resolution) {
    throw input_error(std::string(o.resolution ? "--resolution" : "--vary") + ": applies to validity");
  }
  if (o.command != "enclose" && (o.locate || o.until_contact_fails))
    throw input_error(std::string(o.locate ? "--locate" : "--until-contact-fails") +
                      ": the contacts' verdicts over time are enclose's (simulate's point values prove nothing)");
  if (o.scalar.empty()) o.scalar = o.command == "simulate" ? "double" : "interval";
  if (o.command == "validity" && o.scalar != "interval" && o.scalar != "mpfi" && o.scalar != "arb")
    throw input_error("--scalar: validity proves its verdicts and needs an interval scalar (interval, mpfi or arb), not " +
                      o.scalar);
  const scene_input scene = read_scene_file(o.scene);
  // The progress line: "simulate: t = 3.1 of 10 (31%), about 2 min 5 s left" (validity: the
  // fraction of its range decided).
  const double shown_horizon = o.command == "validity" ? 1.0 : horizon;
  progress line(o.command, o.quiet);
  o.progress = [&](double fraction) { line.show_time(fraction, shown_horizon); };
  motion_outcome r;
  if (o.command == "simulate") {
    csv_rows rows;
    const motion::simulate_report report = motion::simulate(scene, o, rows);
    line.done();
    r = write_simulate(report, rows, o);
  } else if (o.command == "enclose") {
    csv_rows rows;
    const motion::enclose_report report = motion::enclose(scene, o, rows);
    line.done();
    r = write_enclose(report, rows, o);
  } else {
    const motion::validity_report report = motion::validity(scene, o);
    line.done();
    if (report.served) return 0;  // a rank that ran the pieces it was sent: the leading rank writes
    r = write_validity(report, o);
  }
  std::cout << r.summary;
  return r.exit_status;
}

namespace {
int motion_command(const char* name, int argc, char** argv, int first) {
  motion_options m;
  m.command = name;
  if (const std::string why = parse_motion_arguments(argc, argv, first, m); !why.empty()) return usage_error(why);
  return guarded([&] { return motion(m); });
}
}  // namespace

int simulate_command(int argc, char** argv, int first) { return motion_command("simulate", argc, argv, first); }
int enclose_command(int argc, char** argv, int first) { return motion_command("enclose", argc, argv, first); }
int validity_command(int argc, char** argv, int first) { return motion_command("validity", argc, argv, first); }

}  // namespace appell::cli
