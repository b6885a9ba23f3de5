// appell horizon: the long-horizon precision study (motion.hpp).
//
// Each point scalar integrates the scene with `simulate`'s defaults (order and tolerance from its
// precision); its state at t = 0, DT, 2 DT, ... is compared with a reference at 256 bits:
//   - the model's closed form where it knows one (io/model_motion.hpp: Euler's free body in
//     Jacobi elliptic functions, the heavy top's nutation), at the very time each scalar reached
//     (its t, converted exactly), on the components it gives;
//   - any other scene: simulate in mpfr at 256 bits (its default order, 60, tolerance 2^-256, or
//     --reference-order and --reference-tol), at the same output indices.
// The error at t is max_i |x_i - ref_i| / max(1, |ref_i|).  Brouwer's law, the goal line, is the
// round-off of a careful integrator accumulating as a random walk: eps sqrt(n(t)), n(t) the
// number of steps taken by t (eps = 2^-bits).
#include <unistd.h>

#include <algorithm>
#include <boost/multiprecision/mpfr.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "appell/io/json_text.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/standard_scalars.hpp"
#include "flags.hpp"
#include "commands.hpp"
#include "write_whole.hpp"
#include "plot.hpp"
#include "motion_commands.hpp"
#include "progress.hpp"

namespace appell::cli {

namespace {

using ref_t = motion_closed_form::value;

std::string digits_text(double err) {
  if (!(err > 0)) return ">= all";
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", std::max(0.0, -std::log10(err)));
  return b;
}

}  // namespace

std::string parse_horizon_arguments(int argc, char** argv, int first, horizon_options& o) {
  command_line c;
  if (std::string why = read_command_line("horizon", argc, argv, first,
                                          {"--t-end", "--every", "--out", "--scalars", "--reference-order",
                                           "--reference-tol", "--period"},
                                          {"--quiet"}, 1, c);
      !why.empty())
    return why;
  if (std::string why = read_scene_argument(c, o.scene); !why.empty()) return why;
  o.quiet = c.has("--quiet");
  o.t_end = c.value_or("--t-end", "");
  o.every = c.value_or("--every", "");
  if (o.t_end.empty()) return "--t-end: required (the horizon, a positive decimal)";
  if (std::string why = read_out(c, o.out); !why.empty()) return why;
  if (c.has("--scalars")) {
    o.scalars.clear();
    std::stringstream ss(c.value_or("--scalars", ""));
    for (std::string s; std::getline(ss, s, ',');)
      if (!s.empty()) o.scalars.push_back(s);
    if (o.scalars.empty()) return "--scalars: expected a comma-separated list of point scalars";
  }
  if (c.has("--reference-order"))
    if (std::string why = parse_taylor_order("--reference-order", c.value_or("--reference-order", ""), o.reference.order);
        !why.empty())
      return why;
  if (c.has("--reference-tol"))
    if (std::string why = parse_step_tolerance("--reference-tol", c.value_or("--reference-tol", ""), o.reference.tol);
        !why.empty())
      return why;
  if (c.has("--period")) {
    o.period = c.value_or("--period", "");
    try {
      o.period_value = positive_decimal("--period", o.period);
    } catch (const input_error& e) {
      return e.what();
    }
  }
  return "";
}

int horizon(const horizon_options& given) {
  horizon_options o = given;  // parse_horizon_arguments has checked the required flags (scene, --t-end, --out)
  const double t_end = positive_decimal("--t-end", o.t_end);
  for (const auto& s : o.scalars) {
    const auto infos = standard_scalar_infos();
    const auto it = std::find_if(infos.begin(), infos.end(), [&](const scalar_info& i) { return i.name == s; });
    if (it == infos.end()) throw input_error("--scalars: unknown scalar '" + s + "' (known: " + standard_scalar_names() + ")");
    if (!it->built) throw input_error(left_out_scalar_message("--scalars", s));
    if (it->rigorous) throw input_error("--scalars: the study runs point scalars; " + s + " is an interval type (see enclose)");
  }
  const scene_input scene = read_scene_file(o.scene);
  const std::optional<motion_closed_form> closed = motion::closed_form_of(scene);  // the model's, where it has one
  if (closed) {  // the closed form is the reference, and it knows the period
    for (const auto& [flag, given] : {std::pair{"--reference-order", o.reference.order.has_value()},
                                      std::pair{"--reference-tol", o.reference.tol.has_value()},
                                      std::pair{"--period", !o.period.empty()}})
      if (given)
        throw input_error(std::string(flag) + ": model " + scene.model + " is judged against its " + closed->kind +
                          ", which knows its period");
  }
  const double period = closed ? static_cast<double>(closed->period) : o.period_value;  // 0: none given
  if (o.every.empty()) o.every = to_decimal(period > 0 ? std::min(period, t_end / 10) : t_end / 1000);
  const double every = positive_decimal("--every", o.every);
  if (every > t_end) throw input_error("--every: the output step " + o.every + " is larger than the horizon " + o.t_end);
  if (t_end / every > 1e6) throw input_error("--every: more than 10^6 output times; choose a larger step");

  // Each track's progress line: "horizon (dd): t = 3.1 of 10 (31%), about 2 min 5 s left".
  std::optional<progress> line;
  auto shown = [&](const std::string& what) -> std::function<void(double)> {
    line.emplace(what, o.quiet);
    return [&line, t_end](double fraction) { line->show_time(fraction, t_end); };
  };
  std::vector<motion::horizon_track> tracks;
  for (const auto& s : o.scalars)
    tracks.push_back(motion::track(scene, s, std::nullopt, o.t_end, o.every, {}, shown("horizon (" + s + ")")));
  motion::horizon_track reference;
  std::string reference_kind;
  std::vector<std::size_t> compared;  // the state's components compared
  if (closed) {
    reference_kind = closed->kind;
    compared = closed->compared;
  } else {
    if (!scalar_built<mpfr>) throw input_error(left_out_scalar_message("the reference (simulate in mpfr)", "mpfr"));
    reference = motion::track(scene, "mpfr", 256u, o.t_end, o.every, o.reference, shown("horizon (mpfr)"));
    reference_kind = "simulate in mpfr at 256 bits";
    if (o.reference.order || o.reference.tol)  // the default's text as before
      reference_kind += ", order " + std::to_string(reference.order) + ", tolerance " + to_decimal(reference.tol);
  }
  line.reset();  // the last track's progress line erased

  // errors[k][i]: scalar k at output i
  std::vector<std::vector<double>> errors(tracks.size());
  std::vector<std::vector<double>> times(tracks.size());
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const motion::horizon_track& tr = tracks[k];
    for (std::size_t i = 0; i < tr.t.size(); ++i) {
      std::vector<ref_t> truth;
      if (closed) {
        truth = closed->at(ref_t(tr.t[i]));
      } else {
        if (i >= reference.x.size()) break;
        for (const auto& v : reference.x[i]) truth.emplace_back(v);
      }
      if (compared.empty())
        for (std::size_t j = 0; j < truth.size(); ++j) compared.push_back(j);
      ref_t err = 0;
      for (std::size_t j = 0; j < truth.size(); ++j) {
        using std::abs;
        const ref_t e = abs(ref_t(tr.x[i][compared[j]]) - truth[j]) / std::max(ref_t(1), ref_t(abs(truth[j])));
        err = std::max(err, e);
      }
      errors[k].push_back(static_cast<double>(err));
      times[k].push_back(from_decimal<double>(tr.t[i]));
    }
  }

  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  std::ostringstream csv;
  csv << "t" << (period > 0 ? ",periods" : "");
  for (const auto& tr : tracks) csv << ",error_" << tr.scalar << ",brouwer_" << tr.scalar;
  csv << "\n";
  const std::size_t rows = times.empty() ? 0 : times[0].size();
  auto brouwer = [&](std::size_t k, double t) {
    const double eps = std::ldexp(1.0, -static_cast<int>(tracks[k].bits));
    const double steps = t_end > 0 ? tracks[k].steps * t / t_end : 0;
    return eps * std::sqrt(std::max(steps, 1.0));
  };
  for (std::size_t i = 0; i < rows; ++i) {
    csv << to_decimal(times[0][i]);
    if (period > 0) csv << "," << to_decimal(times[0][i] / period);
    for (std::size_t k = 0; k < tracks.size(); ++k)
      csv << "," << (i < errors[k].size() ? to_decimal(errors[k][i]) : "") << "," << to_decimal(brouwer(k, times[0][i]));
    csv << "\n";
  }
  write_whole(dir, "horizon.csv", csv.str());
  if (!closed) {  // the reference's states, in full (exact decimals of its 256-bit values), for reuse and checks
    std::string text = "t";
    for (const auto& f : motion::state_fields(scene)) text += "," + f;
    text += "\n";
    for (std::size_t i = 0; i < reference.t.size(); ++i) {
      text += reference.t[i];
      for (const auto& v : reference.x[i]) text += "," + v;
      text += "\n";
    }
    write_whole(dir, "reference.csv", text);
  }

  // The table: digits kept at 1, 10, 100, ... periods (or tenths of the horizon without a period).
  std::vector<double> marks, counts;
  const double unit = period > 0 ? period : t_end / 10;
  for (double m = 1; m * unit <= t_end * (1 + 1e-12); m *= 10) {
    marks.push_back(m * unit);
    counts.push_back(m);
  }
  std::ostringstream table;
  table << "| scalar | bits | order | steps | seconds |";
  for (std::size_t q = 0; q < marks.size(); ++q)
    table << " digits to " << (period > 0 ? to_decimal(counts[q]) + (counts[q] == 1 ? " period" : " periods") : "t = " + to_decimal(marks[q]))
          << " |";
  table << " Brouwer's digits at T |\n|---|---|---|---|---|";
  for (std::size_t q = 0; q < marks.size(); ++q) table << "---|";
  table << "---|\n";
  nlohmann::json js_tracks = nlohmann::json::array();
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    table << "| " << tracks[k].scalar << " | " << tracks[k].bits << " | " << tracks[k].order << " | " << tracks[k].steps << " | ";
    char sec[32];
    std::snprintf(sec, sizeof sec, "%.3g", tracks[k].seconds);
    table << sec << " |";
    nlohmann::json marks_js = nlohmann::json::array();
    for (double m : marks) {
      // the worst error up to the mark
      double worst = 0;
      for (std::size_t i = 0; i < errors[k].size() && times[k][i] <= m * (1 + 1e-9); ++i) worst = std::max(worst, errors[k][i]);
      table << " " << digits_text(worst) << " |";
      marks_js.push_back({{"t", m}, {"largest_error", worst}});
    }
    table << " " << digits_text(brouwer(k, t_end)) << " |\n";
    js_tracks.push_back({{"scalar", tracks[k].scalar},
                         {"bits", tracks[k].bits},
                         {"order", tracks[k].order},
                         {"steps", tracks[k].steps},
                         {"seconds", tracks[k].seconds},
                         {"largest_error_up_to", marks_js},
                         {"final_error", errors[k].empty() ? 0.0 : errors[k].back()}});
  }
  nlohmann::json summary = {{"command", "horizon"},   {"scene", o.scene},   {"model", scene.model},
                            {"t_end", o.t_end},       {"every", o.every},   {"period", period},
                            {"reference", reference_kind}, {"error", "max_i |x_i - ref_i| / max(1, |ref_i|)"},
                            {"tracks", js_tracks}};
  if (!closed) {
    summary["reference_order"] = reference.order;
    summary["reference_tol"] = reference.tol;
    summary["reference_steps"] = reference.steps;
    summary["reference_seconds"] = reference.seconds;
  }
  if (!o.period.empty()) summary["period_given"] = o.period;
  write_whole(dir, "summary.json", json_text(summary, json_style::indented));

  // The plot: each scalar's error (solid) and its Brouwer line (dashed, the same colour), with a
  // key entry saying what the dashed lines are.
  // Time on a log axis only where the samples span two decades (a log axis over one decade has a
  // single tic); the key outside on the right, clear of the axis label.
  const bool log_time = t_end / every >= 100;
  std::string script = std::string("set datafile separator ','\nset logscale y\n") +
                       (log_time ? "set logscale x\nset mxtics 10\n" : "") +
                       "set autoscale xfix\nset format y '%.0e'\nset xlabel '" +
                       (period > 0 ? std::string("time (periods)") : std::string("time")) +
                       "'\nset ylabel 'error against the 256-bit reference'\nset title " +
                       gnuplot_quoted(scene.model + ": error against time (solid); Brouwer's law, eps sqrt(steps), dashed") +
                       "\nset grid\nset key outside right top vertical Left reverse\nplot ";
  const std::string x = period > 0 ? "2" : "1";
  const int first_col = period > 0 ? 3 : 2;
  const std::string file = gnuplot_quoted((dir / "horizon.csv").string());
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const int col = first_col + 2 * static_cast<int>(k);
    script += std::string(k ? ", " : "") + file + " every ::1 using " + x + ":($" + std::to_string(col) + " > 0 ? $" +
              std::to_string(col) + " : 1/0) with lines lw 2 lc " + std::to_string(k + 1) + " title " +
              gnuplot_quoted(tracks[k].scalar) + ", '' every ::1 using " + x + ":" + std::to_string(col + 1) +
              " with lines dt 2 lw 1.5 lc " + std::to_string(k + 1) + " notitle";
  }
  script += ", NaN with lines dt 2 lw 1.5 lc rgb 'black' title \"dashed: Brouwer's law\"\n";
  const plot_outcome plot = render_png(dir / "horizon.png", script, 1000, 560);
  const std::string plotted = plot_note(plot, dir / "horizon.png");
  std::cout << "horizon " << scene.model << " to t = " << o.t_end;
  if (period > 0) std::cout << " (" << t_end / period << " periods of " << period << ")";
  std::cout << "; reference: " << reference_kind << "\n" << table.str();
  std::cout << "wrote " << (dir / "horizon.csv").string() << (closed ? "" : ", reference.csv") << ", summary.json"
            << plotted << "\n";
  return appell::exit_code(appell::exit_status::done);
}

int horizon_command(int argc, char** argv, int first) {
  horizon_options h;
  if (const std::string why = parse_horizon_arguments(argc, argv, first, h); !why.empty()) return usage_error(why);
  return guarded([&] { return horizon(h); });
}

}  // namespace appell::cli
