// The motion's runs for one model in one scalar (motion.hpp's calls): simulate, enclose with
// the contacts' verdicts, validity's pieces, the horizon's tracks.  Included only by the units
// CMake generates per model and scalar (cmake/instantiate.cmake), each of which includes the
// models' homes first (appell_models.hpp); motion.cpp declares them and dispatches to them.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "appell/io/model_motion.hpp"
#include "appell/motion/contact_track.hpp"
#include "appell/motion/motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell::motion {

/// What one model x scalar run is asked for, and where its report goes (one of the three).
enum class run_kind { simulate, enclose, validity };
struct run_request {
  run_kind kind = run_kind::simulate;
  const settings* s = nullptr;
  row_sink* rows = nullptr;
  simulate_report* simulated = nullptr;
  enclose_report* enclosed = nullptr;
  validity_report* validated = nullptr;
};

namespace detail {

/// The run's progress: settings::progress with the fraction done, and, past settings::
/// max_seconds, ode::run_stopped (the run then reports what it reached).
class progress_gate {
 public:
  progress_gate(const settings& s, double horizon)
      : s_(s), horizon_(horizon), started_(std::chrono::steady_clock::now()) {}
  void operator()(double fraction) {
    if (s_.max_seconds && std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() >= *s_.max_seconds) {
      char why[160];
      std::snprintf(why, sizeof why, "--max-seconds %.6g reached at t = %.6g", *s_.max_seconds, fraction * horizon_);
      throw ode::run_stopped(why);
    }
    if (s_.progress) s_.progress(fraction);
  }

 private:
  const settings& s_;
  double horizon_;
  std::chrono::steady_clock::time_point started_;
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


/// The bits of the run, captured by run_model before the evaluation scope raises mpfi's
/// working precision by its guard bits: `used`, the scalar's bits (what the run reports as its
/// bits, as `appell eval` does), and `asked`, mp_precision_bits() at the same moment (the --bits
/// asked for, for runtime-precision scalars).  0: not captured.
struct run_bits_t {
  unsigned used = 0, asked = 0;
};
inline thread_local run_bits_t run_bits;

/// The run's scalar and settings, for its report (motion.hpp): "bits" the bits used and
/// "bits_requested" where --bits asked for another count, as `appell eval` reports them.
template <Scalar T>
run_identity identity_of(const scene_input& scene, int order, double tol) {
  run_identity id;
  id.model = scene.model;
  id.scalar = scalar_traits<T>::name;
  id.bits = run_bits.used ? run_bits.used : scalar_traits<T>::precision_bits();
  if constexpr (scalar_traits<T>::runtime_precision)
    if (run_bits.asked && id.bits != run_bits.asked) id.bits_requested = run_bits.asked;
  id.order = order;
  id.tol = tol;
  return id;
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
simulate_report simulate_problem(const P& prob, const vector_t<T>& x0, const scene_input& scene, const settings& o,
                                 row_sink& sink) {
  const T t_end = from_decimal<T>(o.t_end);
  const T every = from_decimal<T>(o.every);
  const int order = o.order.value_or(default_order<T>());
  const double tol = o.tol.value_or(default_tol<T>());
  std::vector<std::string> header{"t"};
  const std::vector<std::string> names = reported_names(prob);
  for (const auto& s : names) header.push_back(s);
  // The first and the last rows (the drift is measured from the first, the report ends at the
  // last); every row goes to the sink as it comes.
  std::optional<ode::sample<T>> first, last;
  long count = 0;
  // drift data: t and |I(t) - I(0)| / max(|I(0)|, 1e-300) per invariant (|I(t)| for one that is 0 in truth)
  std::ostringstream dat;
  std::vector<double> worst;
  auto take = [&](ode::sample<T> s) {
    s.x = reported(prob, s.x);
    if (!first) {
      first = s;
      column_names(s.results, "", header);
      column_names(s.invariants, "", header);
      sink.columns("trajectory", header);
      worst.assign(s.invariants.size(), 0.0);
    }
    std::vector<std::string> cells;
    cells.reserve(header.size());
    cells.push_back(to_string(s.t));
    for (std::size_t i = 0; i < names.size(); ++i) cells.push_back(to_string(s.x(static_cast<Eigen::Index>(i))));
    for (const auto* group : {&s.results, &s.invariants})
      for (const auto& g : *group)
        for (const T& v : g.values) cells.push_back(to_string(v));
    sink.row("trajectory", cells);
    ++count;
    dat << approx_double(s.t);
    for (std::size_t q = 0; q < s.invariants.size(); ++q) {
      using std::abs;
      const T i0 = first->invariants[q].values[0];
      const double d = approx_double(T(abs(T(s.invariants[q].values[0] - i0))));
      const bool absolute = first->invariants[q].zero_in_truth;
      const double rel = absolute ? std::fabs(approx_double(s.invariants[q].values[0])) : d / std::max(std::fabs(approx_double(i0)), 1e-300);
      worst[q] = std::max(worst[q], rel);
      if (rel > 0) dat << " " << rel;
      else dat << " NaN";  // exactly 0: no point on the log scale (a floor would crush it)
    }
    dat << "\n";
    last = std::move(s);
  };
  progress_gate gate(o, approx_double(t_end));
  ode::simulate_stats st;
  const auto started = std::chrono::steady_clock::now();
  std::string failure;  // why the run stopped before T (the rows up to there are still reported)
  try {
    st = ode::simulate(prob, x0, t_end, every, order, tol,
                       [&](const ode::sample<T>& s) {
                         // a result or invariant that is not finite in T ends the run there (the
                         // rows before it stand): never a number that is not one
                         for (const auto* group : {&s.results, &s.invariants})
                           for (const auto& g : *group)
                             for (const T& v : g.values) require_finite(v, g.name + " at t = " + to_string(s.t));
                         take(s);
                       },
                       [&](double f) { gate(f); });
  } catch (const std::exception& e) {
    // the motion failed on its way (the state no longer finite, a step collapse near a
    // singularity, an expression refusing its arguments) or was stopped (max_seconds): what was
    // computed stands
    const bool motion_failure = ode::motion_refusal(e) || dynamic_cast<const ode::run_stopped*>(&e);
    if (!motion_failure || !first) throw;  // a bug, or not even the initial state
    failure = e.what();
    // the integrator's counts went with its exception: the time is measured here, the steps
    // (and their sizes) are not known, null in summary.json
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  simulate_report r;
  r.id = identity_of<T>(scene, order, tol);
  r.failure = failure;
  r.header = header;
  r.rows = count;
  r.drift = dat.str();
  for (std::size_t q = 0; q < worst.size(); ++q)
    r.invariants.push_back({first->invariants[q].name, to_string(first->invariants[q].values[0]),
                            to_string(last->invariants[q].values[0]), first->invariants[q].zero_in_truth, worst[q]});
  for (std::size_t i = 0; i < names.size(); ++i) r.final_state.emplace_back(names[i], to_string(last->x(static_cast<Eigen::Index>(i))));
  r.t_reached = to_string(last->t);
  r.steps = st.steps;
  r.seconds = st.seconds;
  r.min_step = st.min_step;
  r.max_step = st.max_step;
  return r;
}

/// A sole's half-lengths in I, where the problem has soles (models/system.hpp).
template <Scalar I, class P>
std::optional<std::array<I, 2>> sole_of(const P& prob, const std::string& name) {
  if constexpr (requires { prob.sole_half_lengths(name); }) {
    if (const auto h = prob.sole_half_lengths(name)) return std::array<I, 2>{I((*h)[0]), I((*h)[1])};
  }
  return std::nullopt;
}

/// A refinement's piece (contact_track's refine and locate) enclosed from x over h: run(h') with
/// h' = h, or, where the piece's end may lie on either side of a table's breakpoint, h' = h (1 +
/// 2^-30). A step of the run that ended on a breakpoint, cut in pieces from its rounded start by
/// rounded lengths, ends its last piece on either side of it, a horizon enclose refuses (so
/// `validity` over a scene with a logged table would stop with an internal error; CHANGELOG.md);
/// a hair past it, the piece steps to the breakpoint and beyond, and a verdict over more than the
/// step holds over the step. When even that cannot run (the table ends at the
/// breakpoint) the piece is not reached, and the step stays undecided.
template <Scalar I, class P, class Run>
bool run_refinement_piece(const P& prob, const vector_t<I>& x, double h, const Run& run) {
  if constexpr (requires { prob.breakpoints(); prob.time_component(); }) {
    const int ti = prob.time_component();
    if (ti >= 0)
      for (const double b : prob.breakpoints())
        if (ode::may_straddle(I(I(b) - x(ti)), I(h))) {  // the breakpoint, from the piece's start
          try {
            return run(h * (1 + 0x1p-30));
          } catch (const input_error&) {
            return false;
          }
        }
  }
  return run(h);
}

/// The contacts a motion judges: each one's name and mu, --mu in place of the scene's (empty:
/// the model has none).
template <class P>
std::vector<std::pair<std::string, std::string>> contacts_to_judge(const P& prob, const settings& o) {
  std::vector<std::pair<std::string, std::string>> contacts;
  if constexpr (requires { prob.contacts(); }) contacts = prob.contacts();
  if (o.mu)
    for (auto& c : contacts) c.second = *o.mu;
  return contacts;
}


template <Scalar I, class P>
enclose_report enclose_problem(const P& prob, const vector_t<I>& x0, const scene_input& scene, const settings& o,
                               row_sink& sink) {
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
  std::ostringstream dat;
  long count = 0;
  bool first = true;
  double worst_end = 0;
  std::vector<std::string> group_header;
  std::vector<double> worst_over;  // per result/invariant value: largest width over a step
  std::vector<std::string> value_names;
  std::size_t result_values = 0;  // value_names: the results' first, then the invariants'
  vector_t<I> last_end = reported(prob, x0);
  progress_gate gate(o, approx_double(t_end));
  // The contacts' verdicts (contact_track.hpp), when the scene has contacts.
  std::vector<contact_track<I>> tracks;
  for (const auto& [name, mu] : contacts_to_judge(prob, o)) {
    contact_track<I> c;
    c.name = name;
    c.mu_text = mu;
    if (!mu.empty()) c.mu = from_decimal<I>(mu);
    if (o.mu) c.sole_with_own_mu = sole_of<I>(prob, name);  // --mu: the sole's cone of that mu
    tracks.push_back(std::move(c));
  }
  if (o.mu && tracks.empty()) throw input_error("--mu: the scene has no contacts to judge (SCENES.md, \"contacts\")");
  if (!tracks.empty()) sink.columns("contacts", contact_columns());
  auto contact_at = [&](const vector_t<I>& x, const std::string& name) {
    std::vector<ode::named_values<I>> r;
    try {
      prob.results(x, r);
    } catch (const std::exception&) {  // not evaluable over that box: nothing is decided there
      return contact_values<I>{I(0), I(0), false};
    }
    return find_contact(r, name);
  };
  std::string contact_stop;  // --until-contact-fails: why the run stops after this step
  vector_t<I> step_start = x0;
  std::string t_reached = "0";  // the last step's end, rounded down
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
          std::vector<std::string> columns = header;
          columns.insert(columns.end(), group_header.begin(), group_header.end());
          sink.columns("steps", columns);
          first = false;
        }
        std::vector<std::string> cells{lower_string(s.t0), upper_string(s.t1)};
        auto bounds = [&](const I& x) {
          cells.push_back(lower_string(x));
          cells.push_back(upper_string(x));
        };
        t_reached = lower_string(s.t1);
        const vector_t<I> end = reported(prob, s.end), over = reported(prob, s.over);
        for (Eigen::Index i = 0; i < n; ++i) bounds(end(i));
        for (Eigen::Index i = 0; i < n; ++i) bounds(over(i));
        std::size_t v = 0;
        double wr = 0;  // the invariants' largest width over the step (their uncertainty: constant in truth)
        auto emit_group = [&](const std::vector<ode::named_values<I>>& g, bool invariant) {
          for (const auto& nv : g)
            for (const I& x : nv.values) {
              bounds(x);
              const double w = approx_double(I(scalar_traits<I>::width(x)));
              worst_over[v] = std::max(worst_over[v], w);
              if (invariant) wr = std::max(wr, w);
              ++v;
            }
        };
        emit_group(s.results, false);
        emit_group(s.invariants, true);
        sink.row("steps", cells);
        ++count;
        const double we = ode::detail::max_width(end);
        worst_end = std::max(worst_end, we);
        dat << approx_double(s.t1) << " " << std::max(we, 1e-300) << " " << std::max(wr, 1e-300) << "\n";
        last_end = end;
        for (auto& c : tracks) {
          const contact_values<I> over = find_contact(s.results, c.name);
          const bool failed_before = c.any_fails;
          sink.row("contacts", c.step(s.t0, s.t1, step_start, s.end, over, contact_at(s.end, c.name)));
          if (o.until_contact_fails && !failed_before && c.any_fails && contact_stop.empty())
            contact_stop = "contact " + c.name + " fails (--until-contact-fails) by t = " + upper_string(*c.steps.back().fails_at);
        }
        step_start = s.end;
      },
      [&](double f) {
        if (!contact_stop.empty()) throw ode::run_stopped(contact_stop);
        gate(f);
      });
  // Undecided steps enclosed again in 8 pieces; then --locate: each failing contact's first
  // failure narrowed by enclosing again from its last holding state over shorter horizons.
  for (auto& c : tracks) {
    auto run = [&](const vector_t<I>& x, double h, const auto& on_step) {
      return run_refinement_piece<I>(prob, x, h, [&](double hp) {
        const ode::enclose_stats s2 = ode::enclose(prob, x, I(hp), order, tol, o.max_width, 2, [&](const ode::enclosed_step<I>& s) {
          on_step(s.t0, s.t1, find_contact(s.results, c.name), s.end);
        });
        c.run_failure = s2.complete ? "" : s2.reason;
        return s2.complete;
      });
    };
    auto at = [&](const vector_t<I>& x) { return contact_at(x, c.name); };
    c.refine(8, run, at);
    c.finish(x0);
    if (o.locate) c.locate(*o.locate, run, at);
  }
  // The report: every number as text, or a double for the plots.
  enclose_report r;
  r.id = identity_of<I>(scene, order, tol);
  for (const auto& c : tracks) {
    contact_report k;
    k.name = c.name;
    k.mu_text = c.mu_text;
    k.verdict = verdict_name(c.verdict());
    k.refined = c.refined;
    if (c.least_normal) k.least_normal = lower_string(*c.least_normal);
    if (c.largest_mu && !c.mu_unbounded) k.largest_mu = upper_string(*c.largest_mu);
    k.holding_lo = lower_string(c.lo);
    k.holding_hi = upper_string(c.lo);
    if (c.hi) {
      k.fails_by = upper_string(*c.hi);
      k.fails_by_t = approx_double(*c.hi);
    }
    k.located = c.located;
    r.contacts.push_back(std::move(k));
  }
  r.header = header;
  r.header.insert(r.header.end(), group_header.begin(), group_header.end());
  r.rows = count;
  r.widths = dat.str();
  r.value_names = value_names;
  r.result_values = result_values;
  r.widest_over = worst_over;
  for (std::size_t i = 0; i < names.size(); ++i) r.final_state.emplace_back(names[i], to_string(last_end(static_cast<Eigen::Index>(i))));
  r.final_width = ode::detail::max_width(last_end);
  r.contact_stop = contact_stop;
  r.complete = st.complete;
  r.reason = st.reason;
  r.t_reached = t_reached;
  r.steps = st.steps;
  r.rejected = st.rejected;
  r.variational_steps = st.variational;
  r.seconds = st.seconds;
  return r;
}

/// `appell validity`: over which range of one field do the scene's contacts hold on [0, T]?
/// Each piece of the range is enclosed whole (the field an interval: a state component of the
/// motion, or every contact's mu), so a piece's verdict holds for every value in it: `holds`
/// when every step proves every contact; `fails` when one contact's failure is proved (for every
/// value, no later than the time given); otherwise the piece is halved, down to the resolution
/// (then `undecided`). The pieces run on the threads of --jobs and, under appell-mpi, on every
/// rank (pieces.hpp): a piece is rebuilt from its path in the halving tree wherever it runs.
template <Scalar I, class P>
validity_report validity_problem(const P& prob, const vector_t<I>& x0, const scene_input& scene, const settings& o) {
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
        if constexpr (requires { prob.can_vary(o.vary_field); }) {
          known = prob.can_vary(o.vary_field);  // a system's parameters, efforts and soles (models/system.hpp)
        } else {
          const std::vector<std::string> params = prob.parameter_names();
          known = std::find(params.begin(), params.end(), o.vary_field) != params.end();
        }
        if (index < 0 && known) {
          vary_parameter = true;
          std::optional<upward_rounding> mode;
          if constexpr (scalar_traits<I>::needs_upward_rounding) mode.emplace();
          const std::string why = prob.parameter_refusal(o.vary_field, scalar_traits<I>::hull(lo0, hi0));
          if (!why.empty()) throw input_error("--vary: " + o.vary_field + " cannot vary: " + why);
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
      // Upward rounding over the whole piece, as on the thread that opened run_model's
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
        if (vary_mu || o.mu) c.sole_with_own_mu = sole_of<I>(model, name);  // the sole's cone of the piece's mu
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
      bool out_of_time = false, proved_failure = false;
      vector_t<I> step_start = x;
      const ode::enclose_stats st = ode::enclose(
          model, x, t_end, order, tol, o.max_width, 2,
          [&](const ode::enclosed_step<I>& s) {
            for (auto& c : tracks) {
              (void)c.step(s.t0, s.t1, step_start, s.end, find_contact(s.results, c.name), contact_at(s.end, c.name));
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
              return run_refinement_piece<I>(model, s0, h, [&](double hp) {
                return ode::enclose(model, s0, I(hp), order, tol, o.max_width, 2, [&](const ode::enclosed_step<I>& s) {
                         on_step(s.t0, s.t1, find_contact(s.results, c.name), s.end);
                       }).complete;
              });
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
        if (st.complete)
          for (const auto& c : tracks)
            if (const auto m = c.verdict() == contact_verdict::undecided ? c.first_undecided() : std::nullopt) {
              // The margin's enclosure holds 0: it decides once its width is below 2 |midpoint|.
              // Where that width comes from the piece's spread (it shrinks with the piece), a
              // piece |midpoint| / width times this one's width may decide; a midpoint 0 is the
              // boundary itself, which no piece decides.
              const double h = span(a, b);
              p.suggested = m->width > 0 && std::isfinite(m->width) && std::isfinite(m->mid) ? h * std::fabs(m->mid) / m->width : 0;
              std::ostringstream why;
              why << m->text << ", over a piece " << h << " wide; "
                  << (p.suggested > 0 ? "a piece about " + ode::number_text(p.suggested) +
                                            " wide may decide it, if the width comes from the piece's spread"
                                      : "no narrower piece decides it");
              p.why = why.str();
              break;
            }
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
    here.threads = std::max(1, o.jobs);
    const piece_network& net = o.pieces ? *o.pieces : here;
    if (net.serve) {  // a rank that runs the pieces it is sent (appell-mpi); the leading rank writes
      net.serve(run_piece);
      validity_report served;
      served.served = true;
      return served;
    }
    validity_report r;
    r.run = run_pieces(run_piece, net, [&](double f) {
      if (o.progress) o.progress(f);
    });
    r.id = identity_of<I>(scene, order, tol);
    r.resolution = resolution;
    r.t_end = T;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    r.threads = std::max(1, net.threads);
    r.processes = net.remote ? net.remote->workers() + 1 : 1;
    return r;
  }
}

template <Scalar T, class P>
void run_problem(const P& prob, const vector_t<T>& x0, const scene_input& scene, const run_request& q) {
  const settings& o = *q.s;
  if constexpr (scalar_traits<T>::is_interval) {
    if (q.kind == run_kind::simulate)
      throw input_error("--scalar: simulate runs point scalars (double, long-double, dd, float128, mpfr); use enclose for " +
                        std::string(scalar_traits<T>::name));
    auto run = [&](const auto& p, const vector_t<T>& x) {
      if (q.kind == run_kind::validity) *q.validated = validity_problem<T>(p, x, scene, o);
      else *q.enclosed = enclose_problem<T>(p, x, scene, o, *q.rows);
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
      // beyond: its slopes in vectors, of the state's own size (any size, any system)
      return run(prob.template with_capacity<runtime_slopes>(), vector_t<T>(x0.head(n)));
    } else {
      run(prob, x0);
    }
  } else {
    if (q.kind != run_kind::simulate)
      throw input_error("--scalar: enclose needs an interval scalar (interval, mpfi or arb), not " + std::string(scalar_traits<T>::name));
    *q.simulated = simulate_problem<T>(prob, x0, scene, o, *q.rows);
  }
}

}  // namespace detail

/// The run `q` asks for, of Model's scene in T (the model moves: io/model_motion.hpp).
template <class Model, Scalar T>
void run_model(const scene_input& scene, const run_request& q) {
  if constexpr (!moving_model<Model>) {
    throw std::logic_error("run_model: model " + scene.model + " does not move");
  } else {
    detail::run_bits = {scalar_traits<T>::precision_bits(), mp_precision_bits()};
    const evaluation_scope<T> scope;
    const auto m = Model::template prepare<T>(scene.as<typename Model::input>());
    const auto [prob, x0] = model_motion<Model>::template start<T>(m);
    detail::run_problem<T>(prob, x0, scene, q);
  }
}

/// A horizon track of Model's scene in T (motion::track).
template <class Model, Scalar T>
horizon_track run_model_track(const scene_input& scene, const std::string& t_end, const std::string& every,
                              const track_settings& settings, const std::function<void(double)>& progress) {
  horizon_track tr;
  if constexpr (scalar_traits<T>::is_interval) {
    throw input_error("--scalars: the study runs point scalars, not " + std::string(scalar_traits<T>::name));
  } else if constexpr (!moving_model<Model>) {
    throw std::logic_error("run_model_track: model " + scene.model + " does not move");
  } else {
    const evaluation_scope<T> scope;
    tr.scalar = scalar_traits<T>::name;
    tr.bits = scalar_traits<T>::precision_bits();
    tr.order = settings.order.value_or(detail::default_order<T>());
    const double tol = settings.tol.value_or(detail::default_tol<T>());
    tr.tol = tol;
    const auto m = Model::template prepare<T>(scene.as<typename Model::input>());
    const auto [prob, x0] = model_motion<Model>::template start<T>(m);
    const std::size_t n = detail::reported_names(prob).size();
    const ode::simulate_stats st = ode::simulate(
        prob, x0, from_decimal<T>(t_end), from_decimal<T>(every), tr.order, tol,
        [&](const ode::sample<T>& s) {
          tr.t.push_back(lower_string(s.t));
          std::vector<std::string> v;
          const vector_t<T> x = detail::reported(prob, s.x);
          for (std::size_t i = 0; i < n; ++i) v.push_back(lower_string(x(static_cast<Eigen::Index>(i))));
          tr.x.push_back(std::move(v));
        },
        [&](double f) {
          if (progress) progress(f);
        });
    tr.steps = st.steps;
    tr.seconds = st.seconds;
  }
  return tr;
}

/// Declares the runs of one model in every built scalar, compiled elsewhere (the generated units).
#define APPELL_DETAIL_EXTERN_RUN(Model, T, name)                                                              \
  extern template void ::appell::motion::run_model<Model, T>(const ::appell::scene_input&,                    \
                                                             const ::appell::motion::run_request&);           \
  extern template ::appell::motion::horizon_track appell::motion::run_model_track<Model, T>(                 \
      const ::appell::scene_input&, const std::string&, const std::string&, const ::appell::motion::track_settings&, \
      const std::function<void(double)>&);

}  // namespace appell::motion
