// appell enclose against the kv library (Kashiwagi; interval<double>, Taylor order 24, affine
// wrapping: odelong_maffine), both run in this process, on the same three problems, appell through
// its one code path (the scene's dynamics on jets), kv on the equations written by hand (kv takes
// no other form; bench/kv_runs.cpp):
//   Euler's body, moments (1, 2, 3), omega0 = (1, 1, 1): largest state width at T;
//   the heavy symmetric top (A = 1 about O, C = 2, m g l = 1, theta0 = 1, precession 0.5,
//   spin 5, the rest 0), as the scene moves it (in Resal's speeds, ode::heavy_top_resal_problem):
//   largest width of its state at T in Euler rates, and the largest width of its energy evaluated
//   at the steps' ends (the same interval function of each step's end box, for both);
//   the simple pendulum theta'' = -sin theta, theta0 = 1, as a one-body system on its rod's
//   turning axes (ode::pendulum_problem; the fixed axes are a diagnostic row).
// Prints one table: appell's width and time, kv's, and the ratios (width: appell / kv, below 1 is
// tighter; time: appell / kv, the goal is at most 0.5).  Every figure is measured in this run,
// appell's integration then kv's, row by row.  The two enclosures of the state at T must meet
// (both claim to hold the one true state): a pair that does not stops the run (exit 4).  A full
// run (no option, or --only diagnostics) then prints a diagnostic table: Euler's equations, the
// pendulum and the heavy top (Lagrange's equations) written by hand, as kv's problems are, through
// the same enclose (what the method does without the generic path's rounding and dependency), the
// heavy top through the generic path in Euler rates (the scene's motion before Resal's speeds;
// checked against the scene's enclosure), and the pendulum through the generic path on the fixed
// axes, each beside kv's width from the same run.
// Usage: appell_bench_enclose [--quick] [--order N] [--only PROBLEM[:T] | --only diagnostics]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "appell/ode/enclose.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "../tests/pendulum_problem.hpp"
#include "kv_runs.hpp"

using namespace appell;

namespace {

struct row {
  const char* problem;
  double t_end;
  const char* quantity;  // "state" (at T) or "energy" (at the steps' ends)
};

struct measured {
  double width = 0, energy_width = 0, seconds = 0;
  long steps = 0;
  bool complete = false;
  std::string reason;      ///< why it stopped, when incomplete
  vector_t<interval> end;  ///< the state enclosed at the last step's end (in the reported variables)
};

/// The heavy top's energy (A = 1 about O, C = 2, m g l = 1) at a state in Euler rates, as an
/// interval function of the box: the same function for appell's boxes and kv's.
interval top_energy(const vector_t<interval>& x) {
  std::vector<ode::named_values<interval>> out;
  ode::heavy_top_problem<interval>{interval(1), interval(2), interval(1), interval(1), interval(1)}.invariants(x, out);
  for (const auto& inv : out)
    if (inv.name == "energy") return inv.values[0];
  throw std::logic_error("heavy_top_problem has no invariant 'energy'");
}

vector_t<interval> box_of(const bench::kv_box& b) {
  vector_t<interval> x(static_cast<Eigen::Index>(b.lower.size()));
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = interval(b.lower[static_cast<std::size_t>(i)], b.upper[static_cast<std::size_t>(i)]);
  return x;
}

/// kv's run of a problem to T, measured once in this run and kept for the rows that print it.
struct kv_measured {
  bench::kv_run run;
  double width = 0, energy_width = 0;
};
const kv_measured& kv_of(bench::kv_problem p, double t_end, int order) {
  static std::map<std::pair<int, double>, kv_measured> done;
  const auto key = std::make_pair(static_cast<int>(p), t_end);
  auto it = done.find(key);
  if (it != done.end()) return it->second;
  kv_measured k;
  k.run = bench::run_kv(p, t_end, order, p == bench::kv_problem::heavy_top);
  k.width = ode::detail::max_width(box_of(k.run.end));
  for (const auto& b : k.run.step_ends) k.energy_width = std::max(k.energy_width, boost::numeric::width(top_energy(box_of(b))));
  return done.emplace(key, std::move(k)).first->second;
}

/// Both enclosures of the state at T hold the true state: they must meet, component by component.
void require_meet(const char* problem, double t_end, const vector_t<interval>& appell_end, const bench::kv_run& kv) {
  const vector_t<interval> k = box_of(kv.end);
  if (kv.status != 2 || appell_end.size() != k.size()) return;
  for (Eigen::Index i = 0; i < k.size(); ++i)
    if (!boost::numeric::overlap(appell_end(i), k(i))) {
      std::printf("%s, T = %g: component %ld of appell's enclosure [%.17g, %.17g] misses kv's [%.17g, %.17g]\n", problem, t_end,
                  static_cast<long>(i), lower(appell_end(i)), upper(appell_end(i)), lower(k(i)), upper(k(i)));
      std::exit(4);
    }
}

/// enclose(prob) from x0 to t_end; `report` maps a step's end box to the variables whose widths
/// are measured (identity: the problem's own state).
template <class P>
measured run(const P& prob, const vector_t<interval>& x0, double t_end, int order,
             vector_t<interval> (*report)(const vector_t<interval>&) = nullptr, bool energy_at_ends = false) {
  measured m;
  const auto start = std::chrono::steady_clock::now();
  const ode::enclose_stats st = ode::enclose(prob, x0, interval(t_end), order, std::ldexp(1.0, -53), 1.0, 2,
                                             [&](const ode::enclosed_step<interval>& s) {
                                               m.end = s.end;
                                               if (energy_at_ends)
                                                 m.energy_width = std::max(m.energy_width, boost::numeric::width(top_energy(report ? report(s.end) : s.end)));
                                             });
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report) m.end = report(m.end);
  m.width = ode::detail::max_width(m.end);
  m.steps = st.steps;
  m.complete = st.complete;
  m.reason = st.reason;
  return m;
}

/// One row of the diagnostic table.
void diagnostic_row(const char* problem, double T, double width, double kv, const measured& m) {
  std::printf("| %s | %g | %.2e | %.2e | %.2f | %.3g | %ld |%s\n", problem, T, width, kv, width / kv, m.seconds, m.steps,
              m.complete ? "" : " (INCOMPLETE)");
  std::fflush(stdout);
}

/// Diagnostic only: Euler's equations written out by hand, (B - C) q r / A, ..., as kv's
/// problem is, run through the same enclose.  The difference to the euler_body rows is the
/// generic path's own rounding (b = omega x I omega, a difference of products), not the method.
struct euler_by_hand {
  static constexpr int dim = 3;
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    vector_t<S> f(3);
    f << S(-1) * x(1) * x(2), S(2) * x(2) * x(0) / S(2), S(-1) * x(0) * x(1) / S(3);  // A, B, C = 1, 2, 3
    return f;
  }
  template <class S>
  void results(const vector_t<S>&, std::vector<ode::named_values<S>>&) const {}
  template <class S>
  void invariants(const vector_t<S>&, std::vector<ode::named_values<S>>&) const {}
};

/// Diagnostic only: the pendulum written out by hand, theta'' = -sin theta.
struct pendulum_by_hand {
  static constexpr int dim = 2;
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    using std::sin;
    vector_t<S> f(2);
    f << x(1), -sin(x(0));
    return f;
  }
  template <class S>
  void results(const vector_t<S>&, std::vector<ode::named_values<S>>&) const {}
  template <class S>
  void invariants(const vector_t<S>&, std::vector<ode::named_values<S>>&) const {}
};

/// Diagnostic only: the heavy top by Lagrange's equations in Euler angles, written out by hand
/// (A = 1 about O, C = 2, m g l = 1), as kv's problem is: with the spin r = phi' + psi' cos theta,
///   A theta'' = A psi'^2 sin cos - C r psi' sin + m g l sin,
///   psi'' = (C r theta' - 2 A psi' theta' cos) / (A sin),   phi'' = -psi'' cos + psi' theta' sin.
struct heavy_top_by_hand {
  static constexpr int dim = 6;
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    using std::sin, std::cos;
    const S s = sin(x(1)), c = cos(x(1));
    const S r = x(5) + x(3) * c;
    const S th2 = x(3) * x(3) * s * c - S(2) * r * x(3) * s + s;
    const S ps2 = (S(2) * r * x(4) - S(2) * x(3) * x(4) * c) / s;
    vector_t<S> f(6);
    f << x(3), x(4), x(5), ps2, th2, x(3) * x(4) * s - ps2 * c;
    return f;
  }
  template <class S>
  void results(const vector_t<S>&, std::vector<ode::named_values<S>>&) const {}
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<ode::named_values<S>>& out) const {
    ode::heavy_top_problem<S>{S(1), S(2), S(1), S(1), S(1)}.invariants(x, out);
  }
};

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int order = 24;
  const char* only = nullptr;  // --only PROBLEM[:T]: that row (rows) alone
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
    else if (!std::strcmp(argv[i], "--order") && i + 1 < argc) order = std::atoi(argv[++i]);
  }
  const evaluation_scope<interval> scope;
  const ode::euler_body_problem<interval> euler{{vec3<interval>(interval(1), interval(2), interval(3)), vec3<interval>::Zero()}};
  const vector_t<interval> euler0 = vector_t<interval>::Constant(3, interval(1));
  // The heavy top as the scene moves it: in Resal's speeds, its state at T reported in Euler rates
  // (ode::heavy_top_resal_problem); top_euler, the same top in Euler rates (the diagnostic rows).
  using resal_t = ode::heavy_top_resal_problem<interval>;
  const resal_t top{interval(1), interval(2), interval(1), interval(1), interval(1)};
  const ode::heavy_top_problem<interval> top_euler{interval(1), interval(2), interval(1), interval(1), interval(1)};
  vector_t<interval> top0(6);
  top0 << interval(0), interval(1), interval(0), interval(0.5), interval(0), interval(5);
  const vector_t<interval> top_resal0 = resal_t::from_euler_rates(top0);
  vector_t<interval> (*const euler_rates)(const vector_t<interval>&) = &resal_t::reported<interval>;
  const ode::pendulum_problem<interval> pendulum{interval(1), interval(1), interval(1)};
  vector_t<interval> pend0(2);
  pend0 << interval(1), interval(0);

  const row rows[] = {{"euler_body", 10, "state"}, {"euler_body", 100, "state"}, {"euler_body", 1000, "state"},
                      {"heavy_top", 10, "state"},  {"heavy_top", 10, "energy"}, {"heavy_top", 100, "state"},
                      {"pendulum", 10, "state"},   {"pendulum", 1000, "state"}};
  auto kv_problem_of = [](const char* name) {
    return !std::strcmp(name, "euler_body") ? bench::kv_problem::euler_body
           : !std::strcmp(name, "heavy_top") ? bench::kv_problem::heavy_top
                                             : bench::kv_problem::pendulum;
  };
  std::printf("appell enclose (interval<double>, order %d, generic Gibbs-Appell path on jets) against kv (odelong_maffine,\n"
              "order %d, the equations by hand), both measured in this run\n\n", order, order);
  std::printf("| problem | T | quantity | appell width | kv width | width ratio | appell s | kv s | time ratio | appell steps | kv steps |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  measured last;
  std::string last_key;
  for (const row& f : rows) {
    if (quick && f.t_end > 10) continue;
    if (only) {
      const std::string o = only, name = o.substr(0, o.find(':'));
      if (name != f.problem) continue;
      if (o.find(':') != std::string::npos && std::atof(o.c_str() + o.find(':') + 1) != f.t_end) continue;
    }
    const std::string key = std::string(f.problem) + std::to_string(f.t_end);
    if (key != last_key) {
      if (!std::strcmp(f.problem, "euler_body")) last = run(euler, euler0, f.t_end, order);
      else if (!std::strcmp(f.problem, "heavy_top")) last = run(top, top_resal0, f.t_end, order, euler_rates, true);
      else last = run(pendulum, pend0, f.t_end, order);
      last_key = key;
    }
    const kv_measured& k = kv_of(kv_problem_of(f.problem), f.t_end, order);
    if (last.complete) require_meet(f.problem, f.t_end, last.end, k.run);
    const bool energy = !std::strcmp(f.quantity, "energy");
    const double w = energy ? last.energy_width : last.width, kw = energy ? k.energy_width : k.width;
    std::printf("| %s | %g | %s | %.2e | %.2e | %.2f | %.3g | %.3g | %.2f | %ld | %ld |\n", f.problem, f.t_end,
                energy ? "energy (at the steps' ends)" : "state at T", w, kw, w / kw, last.seconds, k.run.seconds,
                last.seconds / k.run.seconds, last.steps, k.run.steps);
    std::fflush(stdout);
    if (!last.complete) std::printf("  (appell INCOMPLETE: the enclosure stopped before T: %s)\n", last.reason.c_str());
    if (k.run.status != 2) std::printf("  (kv INCOMPLETE: it stopped at t = %g)\n", k.run.t_reached);
  }
  const bool diagnostics = !quick && (!only || !std::strcmp(only, "diagnostics"));
  if (diagnostics) {
    using bench::kv_problem;
    std::printf("\nDiagnostic (not a scene): the equations written by hand, as kv's problems, through the same enclose;\n"
                "kv's width from this run\n");
    std::printf("| problem | T | appell width | kv width | width ratio | appell s | steps |\n|---|---|---|---|---|---|---|\n");
    for (double T : {10.0, 100.0, 1000.0}) {
      const measured m = run(euler_by_hand{}, euler0, T, order);
      const kv_measured& k = kv_of(kv_problem::euler_body, T, order);
      require_meet("euler_by_hand", T, m.end, k.run);
      diagnostic_row("euler_by_hand", T, m.width, k.width, m);
    }
    for (double T : {10.0, 1000.0}) {
      const measured m = run(pendulum_by_hand{}, pend0, T, order);
      const kv_measured& k = kv_of(kv_problem::pendulum, T, order);
      require_meet("pendulum_by_hand", T, m.end, k.run);
      diagnostic_row("pendulum_by_hand", T, m.width, k.width, m);
    }
    for (double T : {10.0, 100.0}) {
      const measured m = run(heavy_top_by_hand{}, top0, T, order, nullptr, true);
      const kv_measured& k = kv_of(kv_problem::heavy_top, T, order);
      require_meet("heavy_top_by_hand", T, m.end, k.run);
      diagnostic_row("heavy_top_by_hand", T, m.width, k.width, m);
      if (T == 10) diagnostic_row("heavy_top_by_hand energy", T, m.energy_width, k.energy_width, m);
    }
    for (double T : {10.0, 100.0}) {  // the heavy top in Euler rates (the scene's motion before Resal's speeds)
      const measured m = run(top_euler, top0, T, order, nullptr, true);
      if (T == 10) {  // a consistency check: the scene's own enclosure at T must meet this one
        const vector_t<interval> scene_end = run(top, top_resal0, T, order, euler_rates).end;
        for (int i = 0; i < 6; ++i)
          if (!boost::numeric::overlap(m.end(i), scene_end(i))) {
            std::printf("heavy_top_euler_rates: component %d misses the scene's enclosure\n", i);
            return 4;
          }
      }
      const kv_measured& k = kv_of(kv_problem::heavy_top, T, order);
      require_meet("heavy_top_euler_rates", T, m.end, k.run);
      diagnostic_row("heavy_top_euler_rates", T, m.width, k.width, m);
      if (T == 10) diagnostic_row("heavy_top_euler_rates energy", T, m.energy_width, k.energy_width, m);
    }
    // The same pendulum through the generic path on the fixed axes: M = m l^2 (cos^2 + sin^2).
    ode::pendulum_problem<interval> fixed = pendulum;
    fixed.rod_axes = false;
    for (double T : {10.0, 1000.0}) {
      const measured m = run(fixed, pend0, T, order);
      const kv_measured& k = kv_of(kv_problem::pendulum, T, order);
      require_meet("pendulum_fixed_axes", T, m.end, k.run);
      diagnostic_row("pendulum_fixed_axes", T, m.width, k.width, m);
    }
  }
  return 0;
}
