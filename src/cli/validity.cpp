// `appell validity SCENE --vary FIELD=lo:hi --t-end T ... --out DIR` (motion_commands.hpp): over
// which range of FIELD the scene's contacts hold on [0, T] (the library's motion::validity: the
// range split into pieces, each enclosed and judged, on threads and, through appell-mpi, on
// processes); DIR/validity.csv, summary.json and validity.png.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
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

/// A double in 6 significant digits (a resolution, a width: for reading, not for reading back).
std::string short_number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

motion_outcome write_validity(const motion::validity_report& r, const motion_options& o) {
  const std::vector<motion::piece_report>& done = r.run.done;
  const nlohmann::json summary = motion::summary(r, o, o.scene);
  const nlohmann::json& ranges = summary["ranges"];
  const nlohmann::json& undecided_why = summary["undecided_pieces"];
  const double suggested = summary["suggested_resolution"].is_null() ? 0.0 : summary["suggested_resolution"].get<double>();
  // The pieces, and the plot's boxes by verdict.
  std::ostringstream csv, dat[3];
  csv << "lo,hi,verdict,holds_until,first_failure_from,first_failure_to,why,steps,seconds\n";
  auto quoted = [](const std::string& t) {  // a CSV field: in quotes, a quote doubled
    std::string q = "\"";
    for (const char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  bool some_undecidable = false;  // an undecided piece for which no width is suggested
  for (const motion::piece_report& p : done) {
    const std::string& v = p.verdict;
    csv << p.lo << "," << p.hi << "," << v << "," << p.holds_until << "," << p.fail_from << "," << p.fail_to << ","
        << (v == "undecided" ? quoted(p.why) : "") << "," << p.steps << "," << p.seconds << "\n";
    if (v == "undecided" && !(p.suggested > 0)) some_undecidable = true;
    const int k = v == "holds" ? 0 : v == "fails" ? 1 : 2;
    const double x = (p.x_lo + p.x_hi) / 2, dx = (p.x_hi - p.x_lo) / 2;
    // A failure proved at a piece's start (y0 = y1 = 0) would be a box of no height: drawn at least
    // 1% of the horizon tall, upward, it still holds the instant the key says it holds.
    const double y1 = k == 1 ? std::max(p.y1, p.y0 + 0.01 * r.t_end) : p.y1;
    dat[k] << x << " " << (p.y0 + y1) / 2 << " " << x - dx << " " << x + dx << " " << p.y0 << " " << y1 << "\n";
  }
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  write_whole(dir, "validity.csv", csv.str());
  write_whole(dir, "summary.json", json_text(summary, json_style::indented));
  std::string plotted;
  if (done.empty()) {  // nothing decided to draw: say so, rather than gnuplot's complaint about an empty range
    plotted = " (no plot: the run stopped before any piece was decided)";
  } else {
    const std::string f = "$pieces";
    const std::string data = datablock("pieces", dat[0].str() + "\n\n" + dat[1].str() + "\n\n" + dat[2].str());
    const plot_outcome p = render_png(dir / "validity.png", data + "set title " +
         gnuplot_quoted(o.scene + ": can the contacts hold on [0, " + o.t_end + "]? (" + r.id.scalar + ")") +
         "\nset xlabel " + gnuplot_quoted(o.vary_field) + "\nset autoscale xfix\nset ylabel 't'\nset yrange [0:" + std::to_string(r.t_end * 1.1) +
         "]\nset grid\nset key below\nset style fill solid 0.5\nplot " + f +
         " index 0 using 1:2:3:4:5:6 with boxxyerror lc rgb 'forest-green' title 'holds over [0, T] (proved)', " + f +
         " index 1 using 1:2:3:4:5:6 with boxxyerror lc rgb 'red' title 'fails (proved): the first failure lies within the box', " + f +
         " index 2 using 1:2:3:4:5:6 with boxxyerror lc rgb 'gray' title 'undecided at the resolution (holds below the box)'\n",
         900, 500);
    plotted = plot_note(p, dir / "validity.png");
  }
  std::ostringstream out;
  out << "validity of " << o.scene << "'s contacts on [0, " << o.t_end << "] for " << o.vary_field << " in [" << o.vary_lo
      << ", " << o.vary_hi << "] (" << r.id.scalar << ", " << r.id.bits_text() << "): " << done.size() << " pieces in "
      << r.seconds << " s on " << r.workers() << (r.workers() == 1 ? " worker" : " workers") << "\n";
  if (!r.run.stopped.empty()) out << "  INCOMPLETE: " << r.run.stopped << "; " << r.run.not_run << " piece(s) not run\n";
  for (const char* v : {"holds", "fails", "undecided"})
    for (const auto& range : ranges[v])
      out << "  " << v << " for " << o.vary_field << " in [" << range[0].get<std::string>() << ", "
          << range[1].get<std::string>() << "]\n";
  if (!undecided_why.empty()) {
    out << "  why undecided (the first piece; all in validity.csv): " << undecided_why[0]["why"].get<std::string>() << "\n";
    if (suggested > 0 && suggested < r.resolution)
      out << "  --resolution " << short_number(suggested) << " (not " << short_number(r.resolution)
          << ") may decide the undecided pieces whose margins' widths come from their spread"
          << (some_undecidable ? "; for some no resolution is suggested (their `why` in validity.csv)" : "") << "\n";
    else if (some_undecidable)
      out << "  no finer --resolution is suggested for them: their `why` in validity.csv says what holds them (a margin "
             "whose midpoint is 0, forces not evaluated, or an enclosure that stopped short)\n";
  }
  out << "wrote " << (dir / "validity.csv").string() << ", summary.json" << plotted << "\n";
  return {r.run.stopped.empty() ? appell::exit_code(appell::exit_status::done) : appell::exit_code(appell::exit_status::no_certificate), out.str()};
}

}  // namespace

int validity(const motion_options& given) {
  motion_options o = given;
  (void)checked_motion_flags(o);
  if (o.mu && o.vary_field == "mu") throw input_error("--mu: fixes mu, which --vary mu varies; give one of them");
  if (o.locate || o.until_contact_fails)
    throw input_error(std::string(o.locate ? "--locate" : "--until-contact-fails") + ": applies to enclose, not validity");
  if (o.resolution && *o.resolution >= from_decimal<double>(o.vary_hi) - from_decimal<double>(o.vary_lo))
    throw input_error("--resolution: as wide as the range or wider: nothing would be split");
  if (o.jobs == 0) o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (o.scalar != "interval" && o.scalar != "mpfi" && o.scalar != "arb")
    throw input_error("--scalar: validity proves its verdicts and needs an interval scalar (interval, mpfi or arb), not " +
                      o.scalar);
  const scene_input scene = read_scene_file(o.scene);
  progress line(o.command, o.quiet);  // the fraction of the range decided
  o.progress = [&](double fraction) { line.show_time(fraction, 1.0); };
  const motion::validity_report report = motion::validity(scene, o);
  line.done();
  if (report.served) return 0;  // a rank that ran the pieces it was sent: the leading rank writes
  const motion_outcome r = write_validity(report, o);
  std::cout << r.summary;
  return r.exit_status;
}

int validity_command(int argc, char** argv, int first) { return motion_command("validity", argc, argv, first, validity); }

}  // namespace appell::cli
