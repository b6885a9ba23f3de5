#include "motion.hpp"

#include "flags.hpp"

#include <cmath>
#include <iostream>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell::cli {

double positive_decimal(const std::string& flag, const std::string& text) {
  double v = 0;
  try {
    v = from_decimal<double>(text);
  } catch (const std::exception&) {
    throw input_error(flag + ": expected a positive decimal, got '" + text + "'");
  }
  if (!(v > 0) || !std::isfinite(v)) throw input_error(flag + ": expected a positive decimal, got '" + text + "'");
  return v;
}

std::string parse_common_argument(const std::string& a, std::string& scene, bool& quiet) {
  if (a == "--quiet") quiet = true;
  else if (!a.empty() && a[0] == '-') return "unknown option " + a;
  else if (scene.empty()) scene = a;
  else return "unexpected argument '" + a + "'";
  return "";
}

std::string parse_motion_arguments(int argc, char** argv, int first, motion_options& o) {
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& into) {
      if (i + 1 >= argc) return false;
      into = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--t-end" || a == "--every" || a == "--out" || a == "--scalar" || a == "--bits" || a == "--order" ||
        a == "--tol" || a == "--max-width" || a == "--max-seconds") {
      if (!value(v)) return a + ": missing value";
      if (a == "--t-end") o.t_end = v;
      else if (a == "--every") o.every = v;
      else if (a == "--out") o.out = v;
      else if (a == "--scalar") o.scalar = v;
      else if (a == "--bits") {
        if (std::string why = parse_bits(v, o.bits); !why.empty()) return why;
      } else if (a == "--order") {
        try {
          std::size_t used = 0;
          const long n = std::stol(v, &used);
          if (used != v.size() || n < 2 || n > 60) return "--order: expected an integer from 2 to 60, got '" + v + "'";
          o.order = static_cast<int>(n);
        } catch (const std::exception&) {
          return "--order: expected an integer from 2 to 60, got '" + v + "'";
        }
      } else if (a == "--tol") {
        try {
          o.tol = positive_decimal("--tol", v);
        } catch (const input_error& e) {
          return e.what();
        }
        // A relative tolerance of 1 or more lets a step's error be as large as the state itself.
        if (*o.tol >= 1) return "--tol: expected a positive decimal below 1 (a relative error per step), got '" + v + "'";
      } else if (a == "--max-seconds") {
        try {
          o.max_seconds = positive_decimal("--max-seconds", v);
        } catch (const input_error& e) {
          return e.what();
        }
      } else {
        try {
          o.max_width = positive_decimal("--max-width", v);
        } catch (const input_error& e) {
          return e.what();
        }
      }
    } else if (const std::string e = parse_common_argument(a, o.scene, o.quiet); !e.empty()) {
      return e;
    }
  }
  return "";
}

int motion(const motion_options& given) {
  motion_options o = given;
  if (o.scene.empty()) throw input_error(o.command + ": SCENE is required");
  if (o.t_end.empty()) throw input_error("--t-end: required (the horizon, a positive decimal)");
  if (o.out.empty()) throw input_error("--out: required (the directory to write)");
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
  if (o.scalar.empty()) o.scalar = o.command == "simulate" ? "double" : "interval";
  const scene_input scene = read_scene_file(o.scene);
  const motion_outcome r = with_scalar(o.scalar, o.bits, [&]<class T>(std::type_identity<T>) { return run_motion<T>(scene, o); });
  std::cout << r.summary;
  return r.exit_status;
}

}  // namespace appell::cli
