// `appell enclose SCENE --t-end T ... --out DIR` (motion_commands.hpp): a rigorous enclosure of
// the motion (the library's motion::enclose), each contact judged over every step;
// DIR/steps.csv, contacts.csv (with contacts), summary.json, and the plots motion.png,
// results.png, widths.png and contacts.png.
#include <algorithm>
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
#include "appell/ode/enclose_threads.hpp"
#include "appell/scalar/decimal.hpp"
#include "commands.hpp"
#include "motion_commands.hpp"
#include "motion_output.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "write_whole.hpp"

namespace appell::cli {

namespace {

/// DIR/contacts.png from contacts.csv's rows: per contact, the normal force over each step
/// (its bounds) and, with mu, the margin mu - required mu (or the required mu without it);
/// a margin below 0, or a normal force below 0, is a contact that fails.
plot_outcome plot_contacts(const std::filesystem::path& dir, const std::string& csv,
                           const std::vector<motion::contact_report>& contacts,
                           const std::string& title) {
  std::ostringstream dat;
  std::string force_plot, margin_plot;
  bool any_mu = false;
  double t_last = 0;  // the plot's right end: the last step's end
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const auto& c = contacts[k];
    const double mu = c.mu_text.empty() ? 0.0 : from_decimal<double>(c.mu_text);
    any_mu = any_mu || !c.mu_text.empty();
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream ls(line);
      for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
      if (f.size() < 10 || f[0] != c.name) continue;
      t_last = std::max(t_last, std::stod(f[2]));
      const double t = (std::stod(f[1]) + std::stod(f[2])) / 2;
      dat << t << " " << f[3] << " " << f[4];
      if (!f[7].empty() && !f[8].empty()) {
        const double lo = std::stod(f[7]), hi = std::stod(f[8]);
        if (c.mu_text.empty()) dat << " " << lo << " " << hi << "\n";
        else dat << " " << mu - hi << " " << mu - lo << "\n";
      } else {
        dat << " NaN NaN\n";
      }
    }
    dat << "\n\n";
    const std::string idx = std::to_string(k);
    force_plot += std::string(k ? ", " : "") + "$contacts index " + idx + " using 1:2:3 with filledcurves title " +
                  gnuplot_quoted(c.name + ": normal force (enclosure over each step)");
    margin_plot += std::string(k ? ", " : "") + "$contacts index " + idx + " using 1:4:5 with filledcurves title " +
                   gnuplot_quoted(c.name + (c.mu_text.empty() ? ": required mu" : ": mu - required mu (mu = " + c.mu_text + ")"));
  }
  // each failing contact's first failure: a line at its time, labelled at the top of the force
  // panel and at the foot of the margin panel (where the margin, still positive, leaves room)
  std::string marks, marks_low;
  for (const auto& c : contacts)
    if (c.verdict == "fails" && c.fails_by) {
      const double t = c.fails_by_t;
      const std::string line = "set arrow from " + std::to_string(t) + ", graph 0 to " + std::to_string(t) +
                               ", graph 1 nohead lc rgb 'red' dt 2\n";
      const std::string text = "set label '" + c.name + " fails by t = " + *c.fails_by + "' at " + std::to_string(t);
      // written on the side of the line where the plot has room: before it in the right half,
      // after it in the left half (an early failure's label ran off the left edge)
      const std::string side = t > 0.5 * t_last ? " right offset -0.5,0" : " left offset 0.5,0";
      marks += line + text + ", graph 0.92" + side + " tc rgb 'red'\n";
      marks_low += line + text + ", graph 0.08" + side + " tc rgb 'red'\n";
    }
  return render_png(dir / "contacts.png",
                    datablock("contacts", dat.str()) + "set multiplot layout 2,1 title " +
                        gnuplot_quoted(title + ": can the contacts hold?") +
                        "\nset grid\nset key below\nset xlabel 't'\nset ylabel 'N'\nset xzeroaxis lw 2\n" + marks + "plot " +
                        force_plot + "\nunset arrow\nunset label\n" + marks_low + "set ylabel '" +
                        (any_mu ? "mu - required mu" : "required mu") + "'\nplot " + margin_plot + "\nunset multiplot\n",
                    900, 700);
}

/// A panel per value: each step's enclosure drawn as the box [t0, t1] x [lo, hi] (steps.csv's
/// rows as they are: `columns` holds each value's name and the 1-based columns of its bounds).
/// At most 16 panels: more are named in the title and left to steps.csv.
plot_outcome plot_enclosures(const std::filesystem::path& png, const std::string& title, const std::string& rows,
                             const std::vector<std::pair<std::string, std::size_t>>& columns) {
  constexpr std::size_t most = 16;
  const std::size_t shown = std::min(columns.size(), most);
  const std::size_t across = shown <= 1 ? 1 : shown <= 4 ? 2 : shown <= 9 ? 3 : 4;
  const std::size_t down = (shown + across - 1) / across;
  std::string script = datablock("steps", rows) + "set datafile separator ','\nset multiplot layout " +
                       std::to_string(down) + "," + std::to_string(across) + " title " +
                       gnuplot_quoted(title + (columns.size() > most ? " (the first " + std::to_string(most) + " of " +
                                                                            std::to_string(columns.size()) + "; all in steps.csv)"
                                                                      : "")) +
                       "\nset grid\nunset key\nset xlabel 't' offset 0,0.5\nset style fill solid 0.5 noborder\n";
  for (std::size_t k = 0; k < shown; ++k) {
    const std::string lo = std::to_string(columns[k].second), hi = std::to_string(columns[k].second + 1);
    script += "set title " + gnuplot_quoted(columns[k].first) + " noenhanced\nplot $steps using (($1+$2)/2):(($" + lo +
              "+$" + hi + ")/2):1:2:" + lo + ":" + hi + " with boxxyerror lc rgb '#1f5fa0'\n";
  }
  const int width = across <= 2 ? 900 : 1200, height = static_cast<int>(std::max<std::size_t>(down, 1)) * 260 + 60;
  return render_png(png, script + "unset multiplot\n", width, height);
}

motion_outcome write_enclose(const motion::enclose_report& r, const csv_rows& rows, const motion_options& o) {
  std::ostringstream contact_lines;
  for (const auto& c : r.contacts) {
    contact_lines << "  contact " << c.name << ": ";
    if (c.verdict == "fails")
      contact_lines << "FAILS: the first failure lies in [" << c.holding_lo << ", " << *c.fails_by << "]"
                    << (c.located.empty() ? "" : " (" + c.located + ")");
    else if (c.verdict == "undecided")
      contact_lines << "holds up to t = " << c.holding_lo << ", undecided from there";
    else
      contact_lines << "holds up to t = " << c.holding_hi;
    if (c.least_normal) contact_lines << "; least normal force >= " << *c.least_normal;
    if (c.largest_mu) contact_lines << "; required mu <= " << *c.largest_mu;
    if (!c.mu_text.empty()) contact_lines << " (mu = " << c.mu_text << ")";
    contact_lines << "\n";
  }
  const nlohmann::json summary = motion::summary(r, o, o.scene);
  const std::string& steps = rows.text("steps");
  const std::string& contact_rows = rows.text("contacts");
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  write_whole(dir, "steps.csv", csv_header(r.header) + steps);
  if (!r.contacts.empty()) write_whole(dir, "contacts.csv", csv_header(motion::contact_columns()) + contact_rows);
  write_whole(dir, "summary.json", json_text(summary, json_style::indented));
  std::string plotted;
  if (r.rows == 0) {  // nothing to draw: say so, rather than gnuplot's complaint about an empty range
    plotted = " (no plot: the run stopped before any step)";
  } else {
  // The motion and the results (a body's reactions among them): each value's enclosure over
  // every step, from steps.csv's columns (the state over the step; the results over the step).
  // steps.csv's columns (1-based for gnuplot): t0, t1, the n state components' bounds at the step's
  // end, their bounds over the step, then each result's bounds over the step
  std::vector<std::pair<std::string, std::size_t>> state_columns, result_columns;
  const std::size_t n = r.final_state.size();
  for (std::size_t i = 0; i < n; ++i) state_columns.emplace_back(r.final_state[i].first, 3 + 2 * n + 2 * i);
  const std::size_t first_result = 2 + 4 * n;  // 0-based: after t0, t1 and the state's four bounds
  for (std::size_t k = 0; k < r.result_values && first_result + 2 * k + 1 < r.header.size(); ++k)
    result_columns.emplace_back(r.value_names[k], first_result + 2 * k + 1);
  plotted = plot_note(
      plot_enclosures(dir / "motion.png", r.id.model + ", " + r.id.scalar + ": the state over each step", steps, state_columns),
      dir / "motion.png");
  if (!result_columns.empty())
    plotted += plot_note(plot_enclosures(dir / "results.png", r.id.model + ", " + r.id.scalar + ": the results over each step",
                                         steps, result_columns),
                         dir / "results.png");
  plotted +=
      plot_note(render_png(dir / "widths.png",
                           datablock("widths", r.widths) + "set logscale y\nset format y '%.0e'\nset xlabel 't'\nset ylabel 'width'\nset title " +
                               gnuplot_quoted(r.id.model + ", " + r.id.scalar + " (" + r.id.bits_text() + "), order " +
                                              std::to_string(r.id.order)) +
                               "\nset grid\nset key below\nplot $widths using 1:2 with lines title 'state at each step end (largest "
                               "width)', '' using 1:3 with lines title 'invariants over each whole step (largest width; "
                               "constant in truth)'\n",
                           900, 500),
                dir / "widths.png");
  if (!r.contacts.empty())
    plotted += plot_note(plot_contacts(dir, contact_rows, r.contacts, r.id.model + ", " + r.id.scalar), dir / "contacts.png");
  }
  std::ostringstream out;
  out << "enclose " << r.id.model << " in " << r.id.scalar << " (" << r.id.bits_text() << "), order " << r.id.order << ": "
      << r.steps << " steps (" << r.rejected << " rejected) in " << r.seconds << " s\n";
  if (r.complete) out << "  certified up to t = " << o.t_end << "; the state's largest width there " << r.final_width << "\n";
  else if (!r.contact_stop.empty()) out << "  stopped: " << r.contact_stop << "\n";
  else out << "  INCOMPLETE: " << r.reason << "; enclosed up to t = " << r.t_reached << "\n";
  out << contact_lines.str();
  for (std::size_t i = 0; i < r.value_names.size(); ++i)
    out << "  " << r.value_names[i] << ": enclosed over every whole step; widest " << r.widest_over[i]
        << (i < r.result_values ? " (its variation over the step included)\n" : " (constant in truth)\n");
  out << "wrote " << (dir / "steps.csv").string() << (r.contacts.empty() ? "" : ", contacts.csv") << ", summary.json" << plotted
      << "\n";
  return {r.complete || !r.contact_stop.empty() ? appell::exit_code(appell::exit_status::done) : appell::exit_code(appell::exit_status::no_certificate), out.str()};
}

}  // namespace

int enclose(const motion_options& given) {
  motion_options o = given;
  const double horizon = checked_motion_flags(o);
  const scene_input scene = read_scene_file(o.scene);
  progress line(o.command, o.quiet);  // "enclose: t = 3.1 of 10 (31%), about 2 min 5 s left"
  o.progress = [&](double fraction) { line.show_time(fraction, horizon); };
  csv_rows rows;
  // --jobs: a step's slopes on a second thread (interval; the same files: ode/enclose.hpp),
  // by default where the machine has a second core.
  const int threads = o.jobs ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const ode::enclose_threads_scope steps_threads(std::min(threads, 2));
  const motion::enclose_report report = motion::enclose(scene, o, rows);
  line.done();
  const motion_outcome r = write_enclose(report, rows, o);
  std::cout << r.summary;
  return r.exit_status;
}

int enclose_command(int argc, char** argv, int first) { return motion_command("enclose", argc, argv, first, enclose); }

}  // namespace appell::cli
