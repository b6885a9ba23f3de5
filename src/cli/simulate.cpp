// `appell simulate SCENE --t-end T ... --out DIR` (motion_commands.hpp): adaptive Taylor steps in
// a point scalar (the library's motion::simulate); DIR/trajectory.csv (the state, the results and
// the invariants every DT), summary.json and drift.png (the invariants' relative drift).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "appell/errors.hpp"
#include "appell/io/json_text.hpp"
#include "appell/io/scene.hpp"
#include "appell/scalar/decimal.hpp"
#include "commands.hpp"
#include "motion_commands.hpp"
#include "motion_output.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "write_whole.hpp"

namespace appell::cli {

namespace {

motion_outcome write_simulate(const motion::simulate_report& r, const csv_rows& rows, const motion_options& o) {
  const bool complete = r.failure.empty();
  const nlohmann::json summary = motion::summary(r, o, o.scene);
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  write_whole(dir, "trajectory.csv", csv_header(r.header) + rows.text("trajectory"));
  write_whole(dir, "summary.json", json_text(summary, json_style::indented));
  std::string plotted;
  const bool moved = r.rows >= 2;  // at least one step after t = 0
  const bool drifted = std::any_of(r.invariants.begin(), r.invariants.end(), [](const auto& q) { return q.worst > 0; });
  if (!r.invariants.empty() && !moved) {
    plotted = " (no plot: the run stopped before its first step)";
  } else if (!r.invariants.empty() && !drifted) {
    plotted = " (no plot: every invariant is exactly constant along the rows)";
  } else if (!r.invariants.empty()) {
    const std::filesystem::path png = dir / "drift.png";
    std::string script = datablock("drift", r.drift) +
                         "set logscale y\nset format y '%.0e'\nset xlabel 't'\nset ylabel 'relative drift |I(t) - I(0)| / "
                         "|I(0)|, or |I(t)| where I = 0'\n"
                         "set title '" + r.id.model + ", " + r.id.scalar + ", order " + std::to_string(r.id.order) +
                         " (a drift exactly 0 is not drawn)'\nset grid\nset key below\nplot ";
    for (std::size_t q = 0; q < r.invariants.size(); ++q)
      script += std::string(q ? ", " : "") + "$drift using 1:" + std::to_string(q + 2) + " with lines title " +
                gnuplot_quoted(r.invariants[q].name + (r.invariants[q].zero_in_truth ? " (|I|, 0 in truth)" : ""));
    plotted = plot_note(render_png(png, script + "\n", 900, 500), png);
  }
  std::ostringstream out;
  out << "simulate " << r.id.model << " in " << r.id.scalar << " (" << r.id.bits_text() << "), order " << r.id.order
      << ", tol " << r.id.tol << ": ";
  if (complete) out << r.steps << " steps to t = " << o.t_end;
  else out << "stopped before t = " << o.t_end;
  out << " in " << r.seconds << " s\n";
  if (!complete) out << "  INCOMPLETE: " << r.failure << "; written up to t = " << r.t_reached << "\n";
  for (const auto& q : r.invariants) {
    if (q.zero_in_truth) out << "  " << q.name << ": 0 in truth; largest |value| " << q.worst << "\n";
    else out << "  " << q.name << ": largest relative drift " << q.worst << "\n";
  }
  out << "wrote " << (dir / "trajectory.csv").string() << ", summary.json" << plotted << "\n";
  return {complete ? appell::exit_code(appell::exit_status::done) : appell::exit_code(appell::exit_status::no_certificate), out.str()};
}

}  // namespace

int simulate(const motion_options& given) {
  motion_options o = given;
  const double horizon = checked_motion_flags(o);
  if (o.every.empty()) {
    o.every = o.t_end + "e-2";  // 100 outputs
    if (o.t_end.find_first_of("eE") != std::string::npos) o.every = to_decimal(horizon / 100);
  }
  const double every = positive_decimal("--every", o.every);
  if (every > horizon) throw input_error("--every: the output step " + o.every + " is larger than the horizon " + o.t_end);
  if (horizon / every > 1e7) throw input_error("--every: more than 10^7 output times; choose a larger step");
  const scene_input scene = read_scene_file(o.scene);
  progress line(o.command, o.quiet);  // "simulate: t = 3.1 of 10 (31%), about 2 min 5 s left"
  o.progress = [&](double fraction) { line.show_time(fraction, horizon); };
  csv_rows rows;
  const motion::simulate_report report = motion::simulate(scene, o, rows);
  line.done();
  const motion_outcome r = write_simulate(report, rows, o);
  std::cout << r.summary;
  return r.exit_status;
}

int simulate_command(int argc, char** argv, int first) { return motion_command("simulate", argc, argv, first, simulate); }

}  // namespace appell::cli
