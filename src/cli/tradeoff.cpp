// appell tradeoff SCENE [--reps N] [--quiet] --out DIR
//
// For each scalar (mpfr, mpfi and arb at 64, 113, 256 and 1024 bits), in one run:
//  * ns_per_eval: the median over N batches of the time of one evaluation of
//    the scene's dynamics (inputs converted to the scalar once, before timing;
//    a batch holds enough evaluations to last >= 1 ms; warm-up excluded;
//    the scalars take turns, one batch each per repetition);
//  * ratio_to_double: that median over double's, from the same run;
//  * correct_digits: -log10 of the largest relative error over every result
//    component against a reference computed with mpfr at 4096 bits (4x the
//    largest precision); for interval types the error of the farther bound,
//    so the digits are certified;
//  * rel_width: the largest width / |midpoint| over the components (interval types).
#include "tradeoff.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <iomanip>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "appell/studies/accuracy.hpp"
#include "appell/studies/scalar_runs.hpp"
#include "commands.hpp"
#include "flags.hpp"
#include "figure.hpp"
#include "progress.hpp"
#include "write_whole.hpp"
#include "plot.hpp"

namespace appell::cli {
namespace {

struct row {
  std::string scalar;
  unsigned bits = 0;
  double ns = NAN, ratio = NAN, digits = NAN, rel_width = NAN;
  long batch = 0;
  std::string note;
};

// One row: the scene bound in its scalar, and a batch runner for the timing loop.
struct contestant {
  row r;
  std::function<void()> batch;  ///< runs r.batch evaluations
};

// One scalar entered: its row and its batch (studies::prepare_timing).
contestant enter(const scene_input& scene, const std::vector<mpfr_value>& ref, const std::string& scalar,
                 std::optional<unsigned> bits) {
  // 4096 bits ~ 1233 digits
  const studies::timed_scalar t = studies::prepare_timing(scene, ref, 1233.0, scalar, bits);
  contestant c;
  c.r.scalar = t.scalar;
  c.r.bits = t.bits;
  c.r.digits = t.digits;
  c.r.rel_width = t.rel_width;
  c.r.batch = t.batch;
  c.r.note = t.note;
  c.batch = t.run_batch;
  return c;
}

}  // namespace

int tradeoff(const tradeoff_options& o) {
  const scene_input scene = read_scene_file(o.scene);
  const std::vector<mpfr_value> ref = studies::reference_values(scene, 4096);
  struct job {
    std::string name;
    unsigned bits;
  };
  // Every standard scalar this build has; those of run-time precision at four precisions.
  std::vector<job> jobs;
  for (const scalar_info& s : standard_scalar_infos())
    if (!s.built)
      std::cerr << "appell tradeoff: " << s.name << " left out of this build (scripts/build.sh -DAPPELL_SCALARS=all)\n";
    else if (s.runtime_precision)
      for (unsigned b : {64u, 113u, 256u, 1024u}) jobs.push_back({s.name, b});
    else
      jobs.push_back({s.name, 0});
  std::vector<contestant> field;
  progress line("appell tradeoff", o.quiet);
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    line.show(static_cast<double>(j) / (static_cast<double>(jobs.size()) + o.reps),
              "preparing " + std::to_string(j + 1) + "/" + std::to_string(jobs.size()) + ", " + jobs[j].name +
                  (jobs[j].bits ? " " + std::to_string(jobs[j].bits) : std::string()));
    const std::optional<unsigned> bits = jobs[j].bits ? std::optional<unsigned>(jobs[j].bits) : std::nullopt;
    field.push_back(enter(scene, ref, jobs[j].name, bits));
  }
  // Round robin: each repetition times one batch of every scalar in turn, so a
  // slow spell of the machine falls on all of them and the ratios stay fair.
  using clock = std::chrono::steady_clock;
  std::vector<std::vector<double>> samples(field.size());
  for (int k = 0; k < o.reps; ++k) {
    line.show(static_cast<double>(jobs.size() + static_cast<std::size_t>(k)) / (static_cast<double>(jobs.size()) + o.reps),
              "timing, repetition " + std::to_string(k + 1) + "/" + std::to_string(o.reps));
    for (std::size_t j = 0; j < field.size(); ++j) {
      if (!field[j].batch) continue;
      const auto t0 = clock::now();
      field[j].batch();
      samples[j].push_back(std::chrono::duration<double, std::nano>(clock::now() - t0).count() / field[j].r.batch);
    }
  }
  line.done();
  std::vector<row> rows;
  for (std::size_t j = 0; j < field.size(); ++j) {
    row r = field[j].r;
    if (!samples[j].empty()) {
      std::nth_element(samples[j].begin(), samples[j].begin() + samples[j].size() / 2, samples[j].end());
      r.ns = samples[j][samples[j].size() / 2];
    }
    rows.push_back(r);
  }
  const double base = rows.front().ns;
  for (auto& r : rows) r.ratio = r.ns / base;

  std::filesystem::create_directories(o.out_dir);
  const std::filesystem::path csv = std::filesystem::path(o.out_dir) / "tradeoff.csv";
  {  // written whole or not at all (a temporary file, then rename), as every command's files
    std::ostringstream f;
    f << "scalar,bits,ns_per_eval,ratio_to_double,correct_digits,rel_width,batch,reps,note\n";
    for (const auto& r : rows)
      f << r.scalar << "," << r.bits << "," << figure(r.ns, 6) << "," << figure(r.ratio, 4) << "," << figure(r.digits, 4) << ","
        << figure(r.rel_width, 3) << "," << r.batch << "," << o.reps << ",\"" << r.note << "\"\n";
    write_whole(o.out_dir, "tradeoff.csv", f.str());
  }
  std::cout << "appell tradeoff " << o.scene << " (" << scene.model << "), median of " << o.reps
            << " batches, reference: mpfr 4096 bits\n\n";
  std::cout << std::left << std::setw(12) << "scalar" << std::right << std::setw(6) << "bits" << std::setw(14)
            << "ns/eval" << std::setw(12) << "x double" << std::setw(10) << "digits" << std::setw(12) << "rel.width"
            << "\n";
  for (const auto& r : rows) {
    std::cout << std::left << std::setw(12) << r.scalar << std::right << std::setw(6) << r.bits << std::setw(14)
              << figure(r.ns, 5) << std::setw(12) << figure(r.ratio, 3) << std::setw(10) << figure(r.digits, 3) << std::setw(12)
              << (std::isnan(r.rel_width) ? "-" : figure(r.rel_width, 2)) << (r.note.empty() ? "" : "  " + r.note) << "\n";
  }
  // The plot: correct digits against cost, both on log scales (the fixed-precision types from 13
  // to 34 digits apart, mpfr and mpfi up to 300), one key entry per row (no label over a point:
  // mpfr and mpfi at one precision lie side by side), circles for point types, squares for the
  // interval types (their digits certified) but triangles for arb (else indistinguishable from
  // mpfi's squares of the same colour), one colour per precision (a point type and the interval
  // type of about its width side by side: double and interval, mpfr 257 and mpfi 256).
  std::string rows_data, series;
  int k = 0;
  for (const auto& r : rows) {
    if (std::isnan(r.ns) || !(r.digits > 0)) continue;
    const bool rigorous = r.scalar == "interval" || r.scalar == "mpfi" || r.scalar == "arb";
    const std::string name = r.scalar + (r.scalar.rfind("mp", 0) == 0 || r.scalar == "arb" ? " " + std::to_string(r.bits) + " bits" : "") +
                             (rigorous ? " (rigorous)" : "");
    const int colour = r.scalar == "dd" ? 3 : r.bits <= 53 ? 1 : r.bits <= 65 ? 2 : r.bits <= 114 ? 4 : r.bits <= 257 ? 5 : 6;
    rows_data += figure(r.ratio, 6) + " " + figure(r.digits, 6) + "\n";
    series += std::string(k ? ", " : "") + "$rows every ::" + std::to_string(k) + "::" + std::to_string(k) +
              " using 1:2 with points pt " + (r.scalar == "arb" ? "9" : rigorous ? "5" : "7") + " ps 1.6 lc " + std::to_string(colour) + " title " +
              gnuplot_quoted(name);
    ++k;
  }
  const std::filesystem::path png = std::filesystem::path(o.out_dir) / "tradeoff.png";
  const plot_outcome plotted =
      render_png(png, datablock("rows", rows_data) + "set logscale xy\nset xlabel 'cost: time per evaluation / double'\n"
                        "set ylabel 'correct decimal digits (intervals: certified)'\nset ytics (10, 15, 20, 30, 50, 100, 200, 300)\n"
                        "set yrange [8:500]\nset title " + gnuplot_quoted("appell tradeoff: " + scene.model) +
                        "\nset grid\nset offsets graph 0.03, graph 0.1, 0, 0\nset key outside right top\nplot " + series + "\n",
                 1000, 600);
  std::cout << "\nwrote " << csv.string() << plot_note(plotted, png) << "\n";
  return appell::exit_code(appell::exit_status::done);
}

int tradeoff_command(int argc, char** argv, int first) {
  tradeoff_options t;
  command_line c;
  if (std::string why = read_command_line("tradeoff", argc, argv, first, {"--out", "--reps"}, {"--quiet"}, 1, c);
      !why.empty())
    return usage_error(why);
  if (std::string why = read_scene_argument(c, t.scene); !why.empty()) return usage_error(why);
  if (c.has("--reps")) {
    unsigned reps = 0;
    if (std::string why = parse_integer("--reps", c.value_or("--reps", ""), 1, 9999999, reps); !why.empty())
      return usage_error(why);
    t.reps = static_cast<int>(reps);
  }
  if (std::string why = read_out(c, t.out_dir); !why.empty()) return usage_error(why);
  t.quiet = c.has("--quiet");
  return guarded([&] { return tradeoff(t); });
}

}  // namespace appell::cli
