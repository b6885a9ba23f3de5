// appell extremes [--quiet] --out DIR: the stability study.  For every point of every
// sweep (src/studies/extreme_sweeps.cpp) and every scalar: the correct digits against
// mpfr at 2048 bits, the relative width of interval results, the
// error_amplification check of point results, or the refusal (exit 3 of
// `appell eval`) where no certificate exists.  Writes DIR/SWEEP.csv and
// DIR/SWEEP.png (digits against the swept parameter), and a summary on stdout.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <iostream>
#include <optional>
#include <sstream>

#include <unistd.h>

#include "appell/studies/accuracy.hpp"
#include "appell/studies/extreme_sweeps.hpp"
#include "appell/studies/scalar_runs.hpp"
#include "commands.hpp"
#include "flags.hpp"
#include "figure.hpp"
#include "progress.hpp"
#include "write_whole.hpp"
#include "plot.hpp"
#include "extremes.hpp"

namespace appell::cli {
namespace {

}  // namespace

int extremes(const extremes_options& o) {
  std::filesystem::create_directories(o.out_dir);
  const auto sweeps = studies::extreme_sweeps();
  // Every standard scalar; those of run-time precision at 113 bits (float128's).
  std::vector<std::string> scalars;
  for (const scalar_info& s : standard_scalar_infos())
    if (!s.built)
      std::cerr << "appell extremes: " << s.name << " left out of this build (scripts/build.sh -DAPPELL_SCALARS=all)\n";
    else
      scalars.push_back(s.runtime_precision ? s.name + "113" : s.name);
  std::cout << "appell extremes: correct digits (vs mpfr 2048 bits); 'R' = refused with a reason (exit 3)\n";
  std::size_t done = 0, total = 0;
  for (const auto& w : sweeps) total += w.points.size();
  progress line("appell extremes", o.quiet);
  for (const auto& w : sweeps) {
    std::ostringstream csv;  // written whole after the sweep (a temporary file, then rename)
    csv << "sweep,param,x,scalar,bits,status,correct_digits,rel_width,error_amplification,reason\n";
    std::cout << "\n" << w.what << "\n" << std::left << std::setw(22) << w.x_label;
    for (const std::string& s : scalars) std::cout << std::right << std::setw(12) << s;
    std::cout << "\n";
    std::map<std::string, std::vector<std::pair<double, double>>> series;
    for (const auto& p : w.points) {
      line.show(static_cast<double>(done) / static_cast<double>(total),
                std::to_string(done + 1) + "/" + std::to_string(total) + " points, " + w.name + " at " + p.param);
      ++done;
      const scene_input scene = read_scene(parse_json(p.json));
      std::optional<std::vector<mpfr_value>> ref;
      try {
        ref = studies::reference_values(scene, 2048);
      } catch (const std::exception&) {
        ref.reset();  // no reference: the point is singular even at 2048 bits
      }
      const std::vector<mpfr_value>* r = ref ? &*ref : nullptr;
      std::cout << std::left << std::setw(22) << figure(p.x, 4);
      for (const std::string& name : scalars) {
        const bool mp = name.size() > 3 && name.compare(name.size() - 3, 3, "113") == 0;
        // 2048 bits ~ 616 digits
        const studies::scalar_outcome out = studies::evaluate_against(
            scene, r, 616.0, mp ? name.substr(0, name.size() - 3) : name, mp ? std::optional<unsigned>(113) : std::nullopt);
        const unsigned bits = out.bits;
        csv << w.name << "," << p.param << "," << p.x << "," << name << "," << bits << "," << out.status << ","
            << figure(out.digits, 4) << "," << figure(out.rel_width) << "," << figure(out.amplification) << ",\""
            << out.why << "\"\n";
        std::cout << std::right << std::setw(12) << (out.status == "ok" ? figure(out.digits, 3) : std::string("R"));
        if (out.status == "ok" && !std::isnan(out.digits)) series[name].push_back({p.x, out.digits});
      }
      std::cout << "\n";
    }
    // plot: each scalar's digits against the sweep's parameter (data inline)
    std::string data, plot;
    int block = 0;
    for (const std::string& s : scalars) {
      std::string rows;
      for (const auto& [x, d] : series[s]) rows += figure(x, 17) + " " + figure(d, 6) + "\n";
      data += datablock("s" + std::to_string(block), rows);
      if (!series[s].empty())
        plot += std::string(plot.empty() ? "" : ", ") + "$s" + std::to_string(block) + " with linespoints lw 2 title " +
                gnuplot_quoted(s);
      ++block;
    }
    write_whole(o.out_dir, w.name + ".csv", csv.str());
    const auto png = std::filesystem::path(o.out_dir) / (w.name + ".png");
    const plot_outcome p = plot.empty() ? plot_outcome{false, "no scalar gave a value"}
                                        : render_png(png, data + "set title " + gnuplot_quoted(w.what) + "\nset xlabel " +
                                                              gnuplot_quoted(w.x_label) +
                                                              "\nset ylabel 'correct decimal digits (intervals: certified)'\nset grid\n"
                                                              "set key outside right\nplot " + plot + "\n");
    if (!p.written) std::cout << w.name << ": no plot: " << p.why << "\n";
  }
  line.done();
  std::cout << "\nwrote " << o.out_dir << "/<sweep>.csv and .png\n";
  return appell::exit_code(appell::exit_status::done);
}

int extremes_command(int argc, char** argv, int first) {
  extremes_options x;
  command_line c;
  if (std::string why = read_command_line("extremes", argc, argv, first, {"--out"}, {"--quiet"}, 0, c); !why.empty())
    return usage_error(why);
  if (std::string why = read_out(c, x.out_dir); !why.empty()) return usage_error(why);
  x.quiet = c.has("--quiet");
  return guarded([&] { return extremes(x); });
}

}  // namespace appell::cli
