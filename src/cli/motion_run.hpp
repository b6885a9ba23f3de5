// The body of `appell simulate` / `appell enclose` / the horizon's tracks for one
// model in one scalar: included by the generated units (CMakeLists.txt), each of
// which includes the models' motion headers first (io/model_motion.hpp).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "files.hpp"
#include "motion.hpp"
#include "plot.hpp"

#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"
#include "contact_track.hpp"
#include "pieces.hpp"

namespace appell::cli {

namespace motion_detail {

/// "\rsimulate: t = 3.1 of 10 (31%), about 2 min 5 s left" on stderr, from one second on,
/// twice a second at most (the time left: the elapsed time scaled by the fraction of the
/// horizon still to go).  With max_seconds, the call past that much time throws
/// ode::run_stopped, which the motion commands turn into an incomplete run with its files.
class progress_meter {
 public:
  progress_meter(std::string what, double horizon, bool quiet, std::optional<double> max_seconds = {})
      : what_(std::move(what)), horizon_(horizon), quiet_(quiet), max_seconds_(max_seconds),
        start_(std::chrono::steady_clock::now()), last_(start_) {}
  ~progress_meter() {
    if (shown_) std::cerr << "\n";
  }
  void operator()(double fraction) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (max_seconds_ && elapsed >= *max_seconds_) {
      char why[160];
      std::snprintf(why, sizeof why, "--max-seconds %.6g reached at t = %.6g", *max_seconds_, fraction * horizon_);
      throw ode::run_stopped(why);
    }
    if (quiet_) return;
    if (elapsed < 1 || now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    shown_ = true;
    std::string left;
    if (fraction > 0 && fraction < 1) {
      const double s = elapsed * (1 - fraction) / fraction;
      char text[64];
      if (s < 60) std::snprintf(text, sizeof text, ", about %.0f s left", s);
      else if (s < 3600) std::snprintf(text, sizeof text, ", about %.0f min %.0f s left", std::floor(s / 60), std::fmod(s, 60.0));
      else std::snprintf(text, sizeof text, ", about %.0f h %.0f min left", std::floor(s / 3600), std::floor(std::fmod(s, 3600.0) / 60));
      left = text;
    }
    char line[240];
    std::snprintf(line, sizeof line, "\r%s: t = %.6g of %.6g (%.0f%%)%s   ", what_.c_str(), fraction * horizon_, horizon_,
                  100 * fraction, left.c_str());
    std::cerr << line << std::flush;
  }

 private:
  std::string what_;
  double horizon_;
  bool quiet_;
  std::optional<double> max_seconds_;
  std::chrono::steady_clock::time_point start_, last_;
  bool shown_ = false;
};

/// The state as the scene gives it.  A problem that integrates other variables (the heavy top
/// in Resal's speeds) says so with reported(x) and reported_names(); the others report x itself,
/// named by state_names() (a padded state: its first state_names().size() components).
template <class P>
std::vector<std::string> reported_names(const P& prob) {
  if constexpr (requires { prob.reported_names(); }) return prob.reported_names();
  else return prob.state_names();
}
template <class P, class S>
vector_t<S> reported(const P& prob, const vector_t<S>& x) {
  if constexpr (requires { prob.reported(x); }) return prob.reported(x);
  else return x;
}

template <class S>
void column_names(const std::vector<ode::named_values<S>>& group, const std::string& suffix, std::vector<std::string>& out) {
  static const char* axes[] = {"_x", "_y", "_z"};
  for (const auto& g : group) {
    if (g.values.size() == 1) out.push_back(g.name + suffix);
    else
      for (std::size_t i = 0; i < g.values.size(); ++i) out.push_back(g.name + (i < 3 ? axes[i] : "_" + std::to_string(i)) + suffix);
  }
}

/// The precision asked for (--bits), recorded before the evaluation scope raises mpfi's working
/// precision by its guard bits.
inline thread_local unsigned requested_bits = 0;

/// "113 bits" or "113 bits, working precision 128".
template <Scalar T>
std::string bits_text() {
  const unsigned working = scalar_traits<T>::precision_bits();
  const unsigned asked = requested_bits ? requested_bits : working;
  return std::to_string(asked) + " bits" + (asked != working ? ", working precision " + std::to_string(working) : "");
}

template <Scalar T>
int default_order() {
  const unsigned bits = scalar_traits<T>::precision_bits();
  if constexpr (scalar_traits<T>::is_interval) {
    if (bits <= 53) return 24;
    return std::clamp(static_cast<int>(std::ceil(0.3 * bits)), 24, 60);
  } else {
    return std::clamp(static_cast<int>(std::ceil(0.35 * bits)) + 1, 12, 60);
  }
}

template <Scalar T>
double default_tol() {
  return std::ldexp(1.0, -static_cast<int>(std::min(1000u, scalar_traits<T>::precision_bits())));
}

template <Scalar T, class P>
motion_outcome simulate_problem(const P& prob, const vector_t<T>& x0, const scene_input& scene, const motion_options& o) {
  const T t_end = from_decimal<T>(o.t_end);
  const T every = from_decimal<T>(o.every);
  const int order = o.order.value_or(default_order<T>());
  const double tol = o.tol.value_or(default_tol<T>());
  std::vector<std::string> header{"t"};
  const std::vector<std::string> names = reported_names(prob);
  for (const auto& s : names) header.push_back(s);
  std::vector<ode::sample<T>> rows;
  progress_meter meter("simulate", approx_double(t_end), o.quiet, o.max_seconds);
  ode::simulate_stats st;
  const auto started = std::chrono::steady_clock::now();
  std::string failure;  // why the run stopped before T (the rows up to there are still written)
  try {
    st = ode::simulate(prob, x0, t_end, every, order, tol,
                       [&](const ode::sample<T>& s) {
                         // a result or invariant that is not finite in T ends the run there (exit 3
                         // naming it; the rows before it are written): never a number that is not one
                         for (const auto* group : {&s.results, &s.invariants})
                           for (const auto& g : *group)
                             for (const T& v : g.values) require_finite(v, g.name + " at t = " + to_string(s.t));
                         rows.push_back(s);
                         rows.back().x = reported(prob, s.x);
                       },
                       [&](double f) { meter(f); });
  } catch (const std::exception& e) {
    // the motion failed on its way (the state no longer finite, a step collapse near a
    // singularity, an expression refusing its arguments) or was stopped (--max-seconds):
    // what was computed is written
    const bool motion_failure = dynamic_cast<const certification_error*>(&e) || dynamic_cast<const domain_error*>(&e) ||
                                dynamic_cast<const std::invalid_argument*>(&e) || dynamic_cast<const ode::run_stopped*>(&e);
    if (!motion_failure || rows.empty()) throw;  // a bug, or not even the initial state
    failure = e.what();
    // the integrator's counts went with its exception: the time is measured here, the steps
    // (and their sizes) are not known, null in summary.json
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  column_names(rows.front().results, "", header);
  column_names(rows.front().invariants, "", header);
  std::ostringstream csv;
  for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
  csv << "\n";
  // drift data: t and |I(t) - I(0)| / max(|I(0)|, 1e-300) per invariant (|I(t)| for one that is 0 in truth)
  std::ostringstream dat;
  nlohmann::json inv = nlohmann::json::array();
  std::vector<double> worst(rows.front().invariants.size(), 0.0);
  for (const auto& r : rows) {
    csv << to_string(r.t);
    for (std::size_t i = 0; i < names.size(); ++i) csv << "," << to_string(r.x(static_cast<Eigen::Index>(i)));
    for (const auto& g : r.results)
      for (const T& v : g.values) csv << "," << to_string(v);
    for (const auto& g : r.invariants)
      for (const T& v : g.values) csv << "," << to_string(v);
    csv << "\n";
    dat << approx_double(r.t);
    for (std::size_t q = 0; q < r.invariants.size(); ++q) {
      using std::abs;
      const T i0 = rows.front().invariants[q].values[0];
      const double d = approx_double(T(abs(T(r.invariants[q].values[0] - i0))));
      const bool absolute = rows.front().invariants[q].zero_in_truth;
      const double rel = absolute ? std::fabs(approx_double(r.invariants[q].values[0]))
                                  : d / std::max(std::fabs(approx_double(i0)), 1e-300);
      worst[q] = std::max(worst[q], rel);
      dat << " " << std::max(rel, 1e-40);
    }
    dat << "\n";
  }
  for (std::size_t q = 0; q < worst.size(); ++q)
    inv.push_back({{"name", rows.front().invariants[q].name},
                   {"initial", to_string(rows.front().invariants[q].values[0])},
                   {"final", to_string(rows.back().invariants[q].values[0])},
                   {rows.front().invariants[q].zero_in_truth ? "max_abs_value" : "max_relative_drift", worst[q]}});
  nlohmann::json final_state = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size(); ++i) final_state[names[i]] = to_string(rows.back().x(static_cast<Eigen::Index>(i)));
  nlohmann::json summary = {{"command", "simulate"},
                            {"scene", o.scene},
                            {"model", scene.model},
                            {"scalar", scalar_traits<T>::name},
                            {"bits", requested_bits ? requested_bits : scalar_traits<T>::precision_bits()},
                            {"working_bits", scalar_traits<T>::precision_bits()},
                            {"order", order},
                            {"tol", tol},
                            {"t_end", o.t_end},
                            {"every", o.every},
                            {"complete", failure.empty()},
                            {"reason", failure},
                            {"t_reached", approx_double(rows.back().t)},
                            {"steps", failure.empty() ? nlohmann::json(st.steps) : nlohmann::json()},
                            {"seconds", st.seconds},
                            {"min_step", failure.empty() ? nlohmann::json(st.min_step) : nlohmann::json()},
                            {"max_step", failure.empty() ? nlohmann::json(st.max_step) : nlohmann::json()},
                            {"final_state", final_state},
                            {"invariants", inv}};
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  write_whole(dir, "trajectory.csv", csv.str());
  write_whole(dir, "summary.json", summary.dump(2) + "\n");
  std::string plotted;
  if (!worst.empty()) {
    const std::filesystem::path png = dir / "drift.png";
    std::string script = datablock("drift", dat.str()) + "set logscale y\nset format y '%.0e'\nset xlabel 't'\nset ylabel 'relative drift |I(t) - I(0)| / |I(0)|, or |I(t)| where I = 0'\n"
                         "set title '" + scene.model + ", " + scalar_traits<T>::name + ", order " + std::to_string(order) +
                         "'\nset grid\nset key below\nplot ";
    for (std::size_t q = 0; q < worst.size(); ++q)
      script += std::string(q ? ", " : "") + "$drift using 1:" + std::to_string(q + 2) + " with lines title " +
                gnuplot_quoted(rows.front().invariants[q].name +
                               (rows.front().invariants[q].zero_in_truth ? " (|I|, 0 in truth)" : ""));
    plotted = plot_note(render_png(png, script + "\n", 900, 500), png);
  }
  std::ostringstream out;
  out << "simulate " << scene.model << " in " << scalar_traits<T>::name << " (" << bits_text<T>() << "), order " << order
      << ", tol " << tol << ": ";
  if (failure.empty()) out << st.steps << " steps to t = " << o.t_end;
  else out << "stopped before t = " << o.t_end;
  out << " in " << st.seconds << " s\n";
  if (!failure.empty())
    out << "  INCOMPLETE: " << failure << "; written up to t = " << approx_double(rows.back().t) << "\n";
  for (const auto& j : inv) {
    if (j.contains("max_abs_value"))
      out << "  " << j["name"].get<std::string>() << ": 0 in truth; largest |value| " << j["max_abs_value"].get<double>() << "\n";
    else
      out << "  " << j["name"].get<std::string>() << ": largest relative drift " << j["max_relative_drift"].get<double>() << "\n";
  }
  out << "wrote " << (dir / "trajectory.csv").string() << ", summary.json" << plotted << "\n";
  return {failure.empty() ? 0 : 3, out.str()};
}

/// DIR/contacts.png from contacts.csv's rows: per contact, the normal force over each step
/// (its bounds) and, with mu, the margin mu - required mu (or the required mu without it);
/// a margin below 0, or a normal force below 0, is a contact that fails.
/// The contacts a motion judges: each one's name and mu, --mu in place of the scene's (empty:
/// the model has none).
template <class P>
std::vector<std::pair<std::string, std::string>> contacts_to_judge(const P& prob, const motion_options& o) {
  std::vector<std::pair<std::string, std::string>> contacts;
  if constexpr (requires { prob.contacts(); }) contacts = prob.contacts();
  if (o.mu)
    for (auto& c : contacts) c.second = *o.mu;
  return contacts;
}

template <Scalar I>
plot_outcome plot_contacts(const std::filesystem::path& dir, const std::string& csv, const std::vector<contact_track<I>>& tracks,
                   const std::string& title) {
  std::ostringstream dat;
  std::string force_plot, margin_plot;
  bool any_mu = false;
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const auto& c = tracks[k];
    const double mu = c.mu_text.empty() ? 0.0 : from_decimal<double>(c.mu_text);
    any_mu = any_mu || !c.mu_text.empty();
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream ls(line);
      for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
      if (f.size() < 10 || f[0] != c.name) continue;
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
  for (const auto& c : tracks)
    if (c.verdict() == contact_verdict::fails && c.hi) {
      const double t = approx_double(*c.hi);
      const std::string line = "set arrow from " + std::to_string(t) + ", graph 0 to " + std::to_string(t) +
                               ", graph 1 nohead lc rgb 'red' dt 2\n";
      const std::string text = "set label '" + c.name + " fails by t = " + upper_string(*c.hi) + "' at " + std::to_string(t);
      marks += line + text + ", graph 0.92 right offset -0.5,0 tc rgb 'red'\n";
      marks_low += line + text + ", graph 0.08 right offset -0.5,0 tc rgb 'red'\n";
    }
  return render_png(dir / "contacts.png",
                    datablock("contacts", dat.str()) + "set multiplot layout 2,1 title " +
                        gnuplot_quoted(title + ": can the contacts hold?") +
                        "\nset grid\nset key below\nset xlabel 't'\nset ylabel 'N'\nset xzeroaxis lw 2\n" + marks + "plot " +
                        force_plot + "\nunset arrow\nunset label\n" + marks_low + "set ylabel '" +
                        (any_mu ? "mu - required mu" : "required mu") + "'\nplot " + margin_plot + "\nunset multiplot\n",
                    900, 700);
}

template <Scalar I>
std::string bounds(const I& x) {
  return lower_string(x) + "," + upper_string(x);
}

template <Scalar I, class P>
motion_outcome enclose_problem(const P& prob, const vector_t<I>& x0, const scene_input& scene, const motion_options& o) {
  const I t_end = from_decimal<I>(o.t_end);
  const int order = o.order.value_or(default_order<I>());
  const double tol = o.tol.value_or(default_tol<I>());
  std::vector<std::string> header{"t0", "t1"};
  const std::vector<std::string> names = reported_names(prob);  // the state's components (a padded state's without the padding)
  const auto n = static_cast<Eigen::Index>(names.size());
  for (const auto& s : names) {
    header.push_back(s + "_lo");
    header.push_back(s + "_hi");
  }
  for (const auto& s : names) {
    header.push_back(s + "_over_lo");
    header.push_back(s + "_over_hi");
  }
  std::ostringstream body, dat;
  bool first = true;
  double worst_end = 0;
  std::vector<std::string> group_header;
  std::vector<double> worst_over;  // per result/invariant value: largest width over a step
  std::vector<std::string> value_names;
  std::size_t result_values = 0;  // value_names: the results' first, then the invariants'
  vector_t<I> last_end = reported(prob, x0);
  progress_meter meter("enclose", approx_double(t_end), o.quiet, o.max_seconds);
  // The contacts' verdicts (contact_track.hpp), when the scene has contacts.
  std::vector<contact_track<I>> tracks;
  for (const auto& [name, mu] : contacts_to_judge(prob, o)) {
    contact_track<I> c;
    c.name = name;
    c.mu_text = mu;
    if (!mu.empty()) c.mu = from_decimal<I>(mu);
    tracks.push_back(std::move(c));
  }
  if (o.mu && tracks.empty()) throw input_error("--mu: the scene has no contacts to judge (SCENES.md, \"contacts\")");
  auto contact_at = [&](const vector_t<I>& x, const std::string& name) {
    std::vector<ode::named_values<I>> r;
    try {
      prob.results(x, r);
    } catch (const std::exception&) {  // not evaluable over that box: nothing is decided there
      return contact_values<I>{I(0), I(0), false};
    }
    return find_contact(r, name);
  };
  std::ostringstream contact_csv, contact_dat;
  std::string contact_stop;  // --until-contact-fails: why the run stops after this step
  vector_t<I> step_start = x0;
  const ode::enclose_stats st = ode::enclose(
      prob, x0, t_end, order, tol, o.max_width, 2,
      [&](const ode::enclosed_step<I>& s) {
        if (first) {
          std::vector<std::string> names;
          column_names(s.results, "", names);
          result_values = names.size();
          column_names(s.invariants, "", names);
          value_names = names;
          for (const auto& nm : names) {
            group_header.push_back(nm + "_lo");
            group_header.push_back(nm + "_hi");
          }
          worst_over.assign(names.size(), 0.0);
          first = false;
        }
        body << lower_string(s.t0) << "," << upper_string(s.t1);
        const vector_t<I> end = reported(prob, s.end), over = reported(prob, s.over);
        for (Eigen::Index i = 0; i < n; ++i) body << "," << bounds(end(i));
        for (Eigen::Index i = 0; i < n; ++i) body << "," << bounds(over(i));
        std::size_t v = 0;
        double wr = 0;  // the invariants' largest width over the step (their uncertainty: constant in truth)
        auto emit_group = [&](const std::vector<ode::named_values<I>>& g, bool invariant) {
          for (const auto& nv : g)
            for (const I& x : nv.values) {
              body << "," << bounds(x);
              const double w = approx_double(I(scalar_traits<I>::width(x)));
              worst_over[v] = std::max(worst_over[v], w);
              if (invariant) wr = std::max(wr, w);
              ++v;
            }
        };
        emit_group(s.results, false);
        emit_group(s.invariants, true);
        body << "\n";
        const double we = ode::detail::max_width(end);
        worst_end = std::max(worst_end, we);
        dat << approx_double(s.t1) << " " << std::max(we, 1e-300) << " " << std::max(wr, 1e-300) << "\n";
        last_end = end;
        for (auto& c : tracks) {
          const contact_values<I> over = find_contact(s.results, c.name);
          const bool failed_before = c.any_fails;
          c.step(s.t0, s.t1, step_start, s.end, over, contact_at(s.end, c.name), contact_csv);
          if (o.until_contact_fails && !failed_before && c.any_fails && contact_stop.empty())
            contact_stop = "contact " + c.name + " fails (--until-contact-fails) by t = " + upper_string(*c.steps.back().fails_at);
        }
        step_start = s.end;
      },
      [&](double f) {
        if (!contact_stop.empty()) throw ode::run_stopped(contact_stop);
        meter(f);
      });
  // Undecided steps enclosed again in 8 pieces; then --locate: each failing contact's first
  // failure narrowed by enclosing again from its last holding state over shorter horizons.
  for (auto& c : tracks) {
    auto run = [&](const vector_t<I>& x, double h, const auto& on_step) {
      const ode::enclose_stats s2 = ode::enclose(prob, x, I(h), order, tol, o.max_width, 2, [&](const ode::enclosed_step<I>& s) {
        on_step(s.t0, s.t1, find_contact(s.results, c.name), s.end);
      });
      return s2.complete;
    };
    auto at = [&](const vector_t<I>& x) { return contact_at(x, c.name); };
    c.refine(8, run, at);
    c.finish(x0);
    if (o.locate) c.locate(*o.locate, run, at);
  }
  nlohmann::json contacts_json = nlohmann::json::object();
  std::ostringstream contact_lines;
  for (const auto& c : tracks) {
    nlohmann::json j = {{"verdict", verdict_name(c.verdict())}, {"refined_steps", c.refined}};
    if (!c.mu_text.empty()) j["mu"] = c.mu_text;
    if (c.least_normal) j["least_normal_force"] = lower_string(*c.least_normal);
    j["largest_required_mu"] = c.largest_mu && !c.mu_unbounded ? nlohmann::json(upper_string(*c.largest_mu)) : nlohmann::json();
    contact_lines << "  contact " << c.name << ": ";
    if (c.verdict() == contact_verdict::fails) {
      j["first_failure"] = {{"from", lower_string(c.lo)}, {"to", upper_string(*c.hi)}};
      if (!c.located.empty()) j["located"] = c.located;
      contact_lines << "FAILS: the first failure lies in [" << lower_string(c.lo) << ", " << upper_string(*c.hi) << "]"
                    << (c.located.empty() ? "" : " (" + c.located + ")");
    } else if (c.verdict() == contact_verdict::undecided) {
      j["undecided_from"] = lower_string(c.lo);
      contact_lines << "holds up to t = " << lower_string(c.lo) << ", undecided from there";
    } else {
      j["holds_until"] = upper_string(c.lo);
      contact_lines << "holds up to t = " << upper_string(c.lo);
    }
    if (c.least_normal) contact_lines << "; least normal force >= " << lower_string(*c.least_normal);
    if (c.largest_mu && !c.mu_unbounded) contact_lines << "; required mu <= " << upper_string(*c.largest_mu);
    if (!c.mu_text.empty()) contact_lines << " (mu = " << c.mu_text << ")";
    contact_lines << "\n";
    contacts_json[c.name] = j;
  }
  std::ostringstream csv;
  for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
  for (const auto& h : group_header) csv << "," << h;
  csv << "\n" << body.str();
  nlohmann::json final_state = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size(); ++i) final_state[names[i]] = to_string(last_end(static_cast<Eigen::Index>(i)));
  nlohmann::json widths = nlohmann::json::object();
  for (std::size_t i = 0; i < value_names.size(); ++i) widths[value_names[i]] = worst_over[i];
  const double final_width = ode::detail::max_width(last_end);
  nlohmann::json summary = {{"command", "enclose"},
                            {"scene", o.scene},
                            {"model", scene.model},
                            {"scalar", scalar_traits<I>::name},
                            {"bits", requested_bits ? requested_bits : scalar_traits<I>::precision_bits()},
                            {"working_bits", scalar_traits<I>::precision_bits()},
                            {"order", order},
                            {"tol", tol},
                            {"t_end", o.t_end},
                            {"complete", st.complete},
                            {"reason", st.reason},
                            {"t_reached", st.t_reached},
                            {"steps", st.steps},
                            {"rejected_steps", st.rejected},
                            {"seconds", st.seconds},
                            {"final_state", final_state},
                            {"final_largest_width", final_width},
                            {"largest_width_over_a_step", widths}};
  if (!tracks.empty()) summary["contacts"] = contacts_json;
  if (!contact_stop.empty()) summary["stopped_at_contact_failure"] = true;
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir);
  write_whole(dir, "steps.csv", csv.str());
  if (!tracks.empty())
    write_whole(dir, "contacts.csv",
                "contact,t0,t1,normal_force_lo,normal_force_hi,tangential_force_lo,tangential_force_hi,required_mu_lo,"
                "required_mu_hi,verdict\n" + contact_csv.str());
  write_whole(dir, "summary.json", summary.dump(2) + "\n");
  std::string plotted =
      plot_note(render_png(dir / "widths.png",
                           datablock("widths", dat.str()) + "set logscale y\nset format y '%.0e'\nset xlabel 't'\nset ylabel 'width'\nset title " +
                               gnuplot_quoted(scene.model + ", " + scalar_traits<I>::name + " (" + bits_text<I>() + "), order " +
                                              std::to_string(order)) +
                               "\nset grid\nset key below\nplot $widths using 1:2 with lines title 'state at each step end (largest "
                               "width)', '' using 1:3 with lines title 'invariants over each whole step (largest width; "
                               "constant in truth)'\n",
                           900, 500),
                dir / "widths.png");
  if (!tracks.empty())
    plotted += plot_note(plot_contacts(dir, contact_csv.str(), tracks, scene.model + ", " + scalar_traits<I>::name),
                         dir / "contacts.png");
  std::ostringstream out;
  out << "enclose " << scene.model << " in " << scalar_traits<I>::name << " (" << bits_text<I>() << "), order " << order << ": " << st.steps << " steps (" << st.rejected << " rejected) in " << st.seconds
      << " s\n";
  if (st.complete) out << "  certified up to t = " << o.t_end << "; the state's largest width there " << final_width << "\n";
  else if (!contact_stop.empty()) out << "  stopped: " << contact_stop << "\n";
  else out << "  INCOMPLETE: " << st.reason << "; enclosed up to t = " << st.t_reached << "\n";
  out << contact_lines.str();
  for (std::size_t i = 0; i < value_names.size(); ++i)
    out << "  " << value_names[i] << ": enclosed over every whole step; widest " << worst_over[i]
        << (i < result_values ? " (its variation over the step included)\n" : " (constant in truth)\n");
  out << "wrote " << (dir / "steps.csv").string() << (tracks.empty() ? "" : ", contacts.csv") << ", summary.json" << plotted << "\n";
  return {st.complete || !contact_stop.empty() ? 0 : 3, out.str()};
}

/// `appell validity`: over which range of one field do the scene's contacts hold on [0, T]?
/// Each piece of the range is enclosed whole (the field an interval: a state component of the
/// motion, or every contact's mu), so a piece's verdict holds for every value in it: `holds`
/// when every step proves every contact; `fails` when one contact's failure is proved (for every
/// value, no later than the time given); otherwise the piece is halved, down to the resolution
/// (then `undecided`). The pieces run on the threads of --jobs and, under appell-mpi, on every
/// rank (pieces.hpp): a piece is rebuilt from its path in the halving tree wherever it runs.
template <Scalar I, class P>
motion_outcome validity_problem(const P& prob, const vector_t<I>& x0, const scene_input& scene, const motion_options& o) {
  if constexpr (!requires { prob.contacts(); }) {
    throw input_error("validity: the model " + scene.model + " has no contacts (a system file's \"contacts\")");
  } else {
    const auto contacts = contacts_to_judge(prob, o);
    if (contacts.empty()) throw input_error("validity: the scene has no contacts to judge (SCENES.md, \"contacts\")");
    const bool vary_mu = o.vary_field == "mu";
    const std::vector<std::string> names = prob.state_names();
    const I lo0 = from_decimal<I>(o.vary_lo), hi0 = from_decimal<I>(o.vary_hi);
    int index = -1;
    bool vary_parameter = false;  // a model parameter, the problem prepared again for each piece
    if (!vary_mu) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == o.vary_field) index = static_cast<int>(i);
      if constexpr (requires { prob.with_parameter(o.vary_field, lo0, std::declval<vector_t<I>&>()); }) {
        // a model's parameter as it names them; a system file's also as parameters.NAME (its own lookup)
        bool known = false;
        if constexpr (requires { prob.parameter_variable(o.vary_field); }) {
          known = prob.parameter_variable(o.vary_field) >= 0;
        } else {
          const std::vector<std::string> params = prob.parameter_names();
          known = std::find(params.begin(), params.end(), o.vary_field) != params.end();
        }
        if (index < 0 && known) {
          vary_parameter = true;
          std::optional<upward_rounding> mode;
          if constexpr (scalar_traits<I>::needs_upward_rounding) mode.emplace();
          const std::string why = prob.parameter_refusal(o.vary_field, scalar_traits<I>::hull(lo0, hi0));
          if (!why.empty()) throw input_error("--vary: the parameter " + o.vary_field + " cannot vary: " + why);
        }
      }
      if (index < 0 && !vary_parameter) {
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        if constexpr (requires { prob.parameter_names(); })
          for (const auto& n : prob.parameter_names()) known += ", " + n;
        throw input_error("--vary: '" + o.vary_field + "' is not a component of the motion's state nor a parameter of the model (" +
                          known + ") nor mu");
      }
      if (index >= 0 && prob.constrains(index, x0))
        throw input_error("--vary: " + o.vary_field + " enters a constraint at the state (a range of it would leave the "
                          "constraint); vary a free speed or a coordinate no constraint involves");
    }
    const I t_end = from_decimal<I>(o.t_end);
    const int order = o.order.value_or(default_order<I>());
    const double tol = o.tol.value_or(default_tol<I>());
    const double total = span(lo0, hi0), resolution = o.resolution.value_or(total / 64);
    const double T = approx_double(t_end);
    const auto started = std::chrono::steady_clock::now();
    // One piece, from its path: run on any thread or rank (everything shared is read only).
    const piece_runner run_piece = [&](const std::string& path) {
      // Upward rounding over the whole piece, as on the thread that opened run_model_motion's
      // evaluation scope: a piece runs the same operations on every thread and rank (and interval
      // operations need not read or switch the mode one by one).
      std::optional<upward_rounding> mode;
      if constexpr (scalar_traits<I>::needs_upward_rounding) mode.emplace();
      I a = lo0, b = hi0;
      for (const char c : path) {  // the same halving wherever it runs: the same interval
        const I m = (a + b) / I(2);
        (c == '0' ? b : a) = m;
      }
      const I box = scalar_traits<I>::hull(a, b);
      vector_t<I> x = x0;
      if (index >= 0) x(index) = box;
      std::optional<P> varied;  // the model with the parameter over the piece, its state moved to match
      if constexpr (requires { prob.with_parameter(o.vary_field, box, x); })
        if (vary_parameter) varied.emplace(prob.with_parameter(o.vary_field, box, x));
      const P& model = varied ? *varied : prob;
      std::vector<contact_track<I>> tracks;
      for (const auto& [name, mu] : contacts) {
        contact_track<I> c;
        c.name = name;
        c.mu_text = mu;
        if (vary_mu) c.mu = box;
        else if (!mu.empty()) c.mu = from_decimal<I>(mu);
        tracks.push_back(std::move(c));
      }
      auto contact_at = [&](const vector_t<I>& s, const std::string& name) {
        std::vector<ode::named_values<I>> r;
        try {
          model.results(s, r);
        } catch (const std::exception&) {
          return contact_values<I>{I(0), I(0), false};
        }
        return find_contact(r, name);
      };
      std::ostringstream sink;
      bool out_of_time = false, proved_failure = false;
      vector_t<I> step_start = x;
      const ode::enclose_stats st = ode::enclose(
          model, x, t_end, order, tol, o.max_width, 2,
          [&](const ode::enclosed_step<I>& s) {
            for (auto& c : tracks) {
              c.step(s.t0, s.t1, step_start, s.end, find_contact(s.results, c.name), contact_at(s.end, c.name), sink);
              proved_failure = proved_failure || c.any_fails;
            }
            step_start = s.end;
          },
          [&](double) {
            if (proved_failure) throw ode::run_stopped("a contact fails");  // the piece's verdict is known
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            if (o.max_seconds && elapsed >= *o.max_seconds) {
              out_of_time = true;
              throw ode::run_stopped("--max-seconds");
            }
          });
      piece_report p;
      p.lo = lower_string(a);
      p.hi = upper_string(b);
      p.x_lo = approx_double(a);
      p.x_hi = approx_double(b);
      if (out_of_time) {
        p.verdict = "stopped";
        p.why = "--max-seconds " + ode::number_text(*o.max_seconds) + " reached";
        return p;
      }
      for (auto& c : tracks) {  // undecided steps enclosed again in 8 pieces
        c.refine(
            8,
            [&](const vector_t<I>& s0, double h, const auto& on_step) {
              return ode::enclose(model, s0, I(h), order, tol, o.max_width, 2, [&](const ode::enclosed_step<I>& s) {
                       on_step(s.t0, s.t1, find_contact(s.results, c.name), s.end);
                     }).complete;
            },
            [&](const vector_t<I>& s0) { return contact_at(s0, c.name); });
        c.finish(x);
      }
      p.steps = st.steps;
      p.seconds = st.seconds;
      contact_verdict verdict = contact_verdict::undecided;
      std::optional<I> fail_from, fail_to, holds_until;
      bool all_hold = st.complete;
      for (const auto& c : tracks) {
        if (c.verdict() == contact_verdict::fails && (!fail_to || upper(*c.hi) < upper(*fail_to))) {
          verdict = contact_verdict::fails;
          fail_from = c.lo;
          fail_to = *c.hi;
        }
        if (c.verdict() != contact_verdict::holds) all_hold = false;
        if (!holds_until || lower(c.lo) < lower(*holds_until)) holds_until = c.lo;
      }
      if (verdict != contact_verdict::fails && all_hold) verdict = contact_verdict::holds;
      p.verdict = verdict_name(verdict);
      if (verdict == contact_verdict::undecided) {
        p.why = st.complete ? "the enclosures straddle a boundary" : st.reason;
        if (span(a, b) > resolution) p.verdict = "split";
      }
      if (holds_until) p.holds_until = lower_string(*holds_until);
      if (fail_from) p.fail_from = lower_string(*fail_from);
      if (fail_to) p.fail_to = upper_string(*fail_to);
      p.y0 = fail_from ? approx_double(*fail_from) : verdict == contact_verdict::undecided && holds_until ? approx_double(*holds_until) : 0;
      p.y1 = fail_to ? approx_double(*fail_to) : T;
      return p;
    };
    piece_network here;
    here.threads = o.jobs;
    const piece_network& net = o.pieces ? *o.pieces : here;
    if (net.serve) {  // a rank that runs the pieces it is sent (appell-mpi); the leading rank writes
      net.serve(run_piece);
      return {0, ""};
    }
    progress_meter meter("validity", 1.0, o.quiet);
    const pieces_outcome run = run_pieces(run_piece, net, [&](double f) { meter(f); });
    const std::vector<piece_report>& done = run.done;
    // The pieces, and the ranges of each verdict (adjacent pieces merged).
    std::ostringstream csv, dat[3];
    csv << "lo,hi,verdict,holds_until,first_failure_from,first_failure_to,steps,seconds\n";
    nlohmann::json ranges = {{"holds", nlohmann::json::array()}, {"fails", nlohmann::json::array()}, {"undecided", nlohmann::json::array()}};
    std::string last;
    double piece_seconds = 0;
    for (const piece_report& p : done) {
      const std::string& v = p.verdict;
      csv << p.lo << "," << p.hi << "," << v << "," << p.holds_until << "," << p.fail_from << "," << p.fail_to << "," << p.steps
          << "," << p.seconds << "\n";
      nlohmann::json& list = ranges[v];
      if (v == last && !list.empty()) list.back()[1] = p.hi;
      else list.push_back({p.lo, p.hi});
      last = v;
      piece_seconds += p.seconds;
      const int k = v == "holds" ? 0 : v == "fails" ? 1 : 2;
      const double x = (p.x_lo + p.x_hi) / 2, dx = (p.x_hi - p.x_lo) / 2;
      dat[k] << x << " " << (p.y0 + p.y1) / 2 << " " << x - dx << " " << x + dx << " " << p.y0 << " " << p.y1 << "\n";
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int workers = std::max(1, net.threads) + (net.remote ? net.remote->workers() : 0);
    nlohmann::json summary = {{"command", "validity"},
                              {"scene", o.scene},
                              {"model", scene.model},
                              {"scalar", scalar_traits<I>::name},
                              {"bits", requested_bits ? requested_bits : scalar_traits<I>::precision_bits()},
                              {"field", o.vary_field},
                              {"range", {o.vary_lo, o.vary_hi}},
                              {"t_end", o.t_end},
                              {"resolution", resolution},
                              {"pieces", done.size()},
                              {"complete", run.stopped.empty()},
                              {"reason", run.stopped},
                              {"pieces_not_run", run.not_run},
                              {"ranges", ranges},
                              {"threads", std::max(1, net.threads)},
                              {"processes", net.remote ? net.remote->workers() + 1 : 1},
                              {"seconds", seconds},
                              {"seconds_per_piece", done.empty() ? 0.0 : piece_seconds / static_cast<double>(done.size())}};
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);
    write_whole(dir, "validity.csv", csv.str());
    write_whole(dir, "summary.json", summary.dump(2) + "\n");
    std::string plotted;
    {
      const std::string f = "$pieces";
      const std::string data = datablock("pieces", dat[0].str() + "\n\n" + dat[1].str() + "\n\n" + dat[2].str());
      const plot_outcome p = render_png(dir / "validity.png", data + "set title " +
           gnuplot_quoted(o.scene + ": can the contacts hold on [0, " + o.t_end + "]? (" + scalar_traits<I>::name + ")") +
           "\nset xlabel " + gnuplot_quoted(o.vary_field) + "\nset ylabel 't'\nset yrange [0:" + std::to_string(T * 1.1) +
           "]\nset grid\nset key below\nset style fill solid 0.5\nplot " + f +
           " index 0 using 1:2:3:4:5:6 with boxxyerror lc rgb 'forest-green' title 'holds over [0, T] (proved)', " + f +
           " index 1 using 1:2:3:4:5:6 with boxxyerror lc rgb 'red' title 'fails (proved): the first failure lies within the box', " + f +
           " index 2 using 1:2:3:4:5:6 with boxxyerror lc rgb 'gray' title 'undecided at the resolution (holds below the box)'\n",
           900, 500);
      plotted = plot_note(p, dir / "validity.png");
    }
    std::ostringstream out;
    out << "validity of " << o.scene << "'s contacts on [0, " << o.t_end << "] for " << o.vary_field << " in [" << o.vary_lo
        << ", " << o.vary_hi << "] (" << scalar_traits<I>::name << ", " << bits_text<I>() << "): " << done.size()
        << " pieces in " << seconds << " s on " << workers << (workers == 1 ? " worker" : " workers") << "\n";
    if (!run.stopped.empty()) out << "  INCOMPLETE: " << run.stopped << "; " << run.not_run << " piece(s) not run\n";
    for (const char* v : {"holds", "fails", "undecided"})
      for (const auto& r : ranges[v])
        out << "  " << v << " for " << o.vary_field << " in [" << r[0].get<std::string>() << ", " << r[1].get<std::string>() << "]\n";
    out << "wrote " << (dir / "validity.csv").string() << ", summary.json" << plotted << "\n";
    return {run.stopped.empty() ? 0 : 3, out.str()};
  }
}

template <Scalar T, class P>
motion_outcome run_problem(const P& prob, const vector_t<T>& x0, const scene_input& scene, const motion_options& o) {
  if constexpr (scalar_traits<T>::is_interval) {
    if (o.command != "enclose" && o.command != "validity")
      throw input_error("--scalar: simulate runs point scalars (double, long-double, dd, float128, mpfr); use enclose for " +
                        std::string(scalar_traits<T>::name));
    auto run = [&](const auto& p, const vector_t<T>& x) {
      return o.command == "validity" ? validity_problem<T>(p, x, scene, o) : enclose_problem<T>(p, x, scene, o);
    };
    if constexpr (requires { prob.template with_capacity<6>(); }) {
      // A state whose size is known at run time (a system file): its Jacobians and slopes are
      // carried in the smallest capacity that holds it, the state padded with constant zeros.
      const int n = prob.size();
      auto padded = [&](Eigen::Index d) {
        vector_t<T> x = vector_t<T>::Zero(d);
        x.head(n) = x0.head(n);
        return x;
      };
      if (n <= 6) return run(prob.template with_capacity<6>(), padded(6));
      if (n <= 12) return run(prob.template with_capacity<12>(), padded(12));
      throw input_error("enclose: the motion's state has " + std::to_string(n) +
                        " components; enclose carries at most 12 (the coordinates, the free speeds and t)");
    } else {
      return run(prob, x0);
    }
  } else {
    if (o.command != "simulate")
      throw input_error("--scalar: enclose needs an interval scalar (interval or mpfi), not " + std::string(scalar_traits<T>::name));
    return simulate_problem<T>(prob, x0, scene, o);
  }
}

}  // namespace motion_detail

/// The motion of Model's scene in T (the model moves: io/model_motion.hpp).
template <class Model, Scalar T>
motion_outcome run_model_motion(const scene_input& scene, const motion_options& o) {
  if constexpr (!moving_model<Model>) {
    throw std::logic_error("run_model_motion: model " + scene.model + " does not move");
  } else {
    motion_detail::requested_bits = scalar_traits<T>::precision_bits();
    const evaluation_scope<T> scope;
    const auto m = Model::template prepare<T>(scene.as<typename Model::input>());
    const auto [prob, x0] = model_motion<Model>::template start<T>(m);
    return motion_detail::run_problem<T>(prob, x0, scene, o);
  }
}

template <class Model, Scalar T>
horizon_track run_model_horizon_track(const scene_input& scene, const std::string& t_end, const std::string& every,
                                      bool quiet) {
  horizon_track tr;
  if constexpr (scalar_traits<T>::is_interval) {
    throw input_error("--scalars: the study runs point scalars, not " + std::string(scalar_traits<T>::name));
  } else if constexpr (!moving_model<Model>) {
    throw std::logic_error("run_model_horizon_track: model " + scene.model + " does not move");
  } else {
    const evaluation_scope<T> scope;
    tr.scalar = scalar_traits<T>::name;
    tr.bits = scalar_traits<T>::precision_bits();
    tr.order = motion_detail::default_order<T>();
    motion_detail::progress_meter meter("horizon (" + tr.scalar + ")", from_decimal<double>(t_end), quiet);
    const auto m = Model::template prepare<T>(scene.as<typename Model::input>());
    const auto [prob, x0] = model_motion<Model>::template start<T>(m);
    const std::size_t n = motion_detail::reported_names(prob).size();
    const ode::simulate_stats st = ode::simulate(
        prob, x0, from_decimal<T>(t_end), from_decimal<T>(every), tr.order, motion_detail::default_tol<T>(),
        [&](const ode::sample<T>& s) {
          tr.t.push_back(lower_string(s.t));
          std::vector<std::string> v;
          const vector_t<T> x = motion_detail::reported(prob, s.x);
          for (std::size_t i = 0; i < n; ++i) v.push_back(lower_string(x(static_cast<Eigen::Index>(i))));
          tr.x.push_back(std::move(v));
        },
        [&](double f) { meter(f); });
    tr.steps = st.steps;
    tr.seconds = st.seconds;
  }
  return tr;
}

}  // namespace appell::cli
