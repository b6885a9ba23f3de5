// contact_track.hpp -- the verdict of an enclosed motion (motion::enclose, motion::validity) on
// each contact of a scene
// (SCENES.md "contacts"), from the enclosures of its normal force N and friction
// force F_t over every whole step (reactions/contact.hpp judges them):
//   holds      up to T: every step proves N > 0 and |F_t| < mu N;
//   fails      the first failure t* lies in [lo, hi]: every step before lo holds
//              (so t* >= lo), and failure is proved at hi (over a whole step
//              starting there, or at a step's end state); --locate TOL narrows
//              [lo, hi] by enclosing again from the state at lo with shorter
//              horizons (bisection) until hi - lo <= TOL or the enclosures no
//              longer decide;
//   undecided  from lo on no step decides and none fails.
#pragma once

#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/reactions/contact.hpp"
#include "appell/reactions/wrench_cone.hpp"
#include "appell/io/scene.hpp"  // sole_margin_values
#include "appell/scalar/format.hpp"

namespace appell::motion::detail {

/// A contact's normal force and tangential force's length in one set of results
/// (`<name>_normal_force`, `<name>_friction_force` [3]).
template <Scalar I>
struct contact_values {
  I normal, tangential;
  bool known = true;  ///< false: the results could not be evaluated there (then nothing is decided)
  /// A sole's margins (`<name>_margins`: its contact wrench cone, SCENES.md), judged with the
  /// normal force in place of the friction on the resultant; empty for a point contact.
  std::vector<I> margins = {};
  /// A sole's force (friction x, y and normal, on the sole's axes) and couple (`<name>_moment`):
  /// its margins formed again for a friction coefficient other than the scene's.
  vec3<I> force = zero_matrix<vec3<I>>(), moment = zero_matrix<vec3<I>>();
};

template <Scalar I>
contact_values<I> find_contact(const std::vector<ode::named_values<I>>& results, const std::string& name) {
  const ode::named_values<I>* n = nullptr;
  const ode::named_values<I>* f = nullptr;
  for (const auto& r : results) {
    if (r.name == name + "_normal_force") n = &r;
    if (r.name == name + "_friction_force") f = &r;
  }
  if (!n || !f || f->values.size() != 3) throw std::logic_error("contact " + name + ": its results are missing");
  using std::sqrt;
  I s = sqr(f->values[0]) + sqr(f->values[1]) + sqr(f->values[2]);
  contact_values<I> out{n->values[0], I(sqrt(s)), true};
  for (const auto& r : results) {
    if (r.name == name + "_margins") out.margins = r.values;
    if (r.name == name + "_moment" && r.values.size() == 3) out.moment = vec3<I>(r.values[0], r.values[1], r.values[2]);
  }
  out.force = vec3<I>(f->values[0], f->values[1], n->values[0]);
  return out;
}

/// An upper bound (to within rounding) of b - a, as a double: how far apart two times are.
template <Scalar I>
double span(const I& a, const I& b) {
  const I d = b - a;
  return approx_double(d) + approx_double(I(scalar_traits<I>::width(d)));
}

/// The name of a sole's margin k among `count` (SCENES.md, "contacts of links": 16 with a mu, the
/// centre of pressure's 4 without; reactions/wrench_cone.hpp forms them in this order).
inline std::string sole_margin_name(std::size_t k, std::size_t count) {
  static const char* const friction[4] = {"mu fz - fx", "mu fz + fx", "mu fz - fy", "mu fz + fy"};
  static const char* const pressure[4] = {"Y fz - tau_x", "Y fz + tau_x", "X fz - tau_y", "X fz + tau_y"};
  if (count == 4) return "centre-of-pressure margin " + std::string(pressure[k]);
  if (k < 4) return "friction margin " + std::string(friction[k]);
  if (k < 8) return "centre-of-pressure margin " + std::string(pressure[k - 4]);
  return "yaw margin " + std::to_string(k - 7) + " of 8";
}

template <Scalar I>
struct contact_track {
  std::string name, mu_text;
  std::optional<I> mu;
  /// A sole's half-lengths, set where mu is not the scene's own (--mu, validity --vary mu): its
  /// margins are then formed here with mu from its force and couple, not read from the results
  /// (which are formed with the scene's mu).
  std::optional<std::array<I, 2>> sole_with_own_mu;
  /// Each step: its times, the state at its start, and its verdicts over the step and at its end.
  struct record {
    I t0, t1;
    vector_t<I> start, end;
    contact_verdict over, at_end;
    std::optional<I> fails_at;  ///< where failure is proved in it (refinement: inside the step)
    contact_values<I> values;   ///< the contact's forces over the step
  };
  std::vector<record> steps;
  // What the steps prove (finish()):
  bool prefix_holds = true;         ///< every step holds
  I lo = I(0);                      ///< the end of the holding prefix
  vector_t<I> lo_state;             ///< the state there
  std::optional<I> hi;              ///< the earliest time at which failure is proved
  bool any_fails = false;
  std::optional<I> least_normal;    ///< the enclosure whose lower bound is least
  std::optional<I> largest_mu;      ///< required mu: the enclosure whose upper bound is largest
  bool mu_unbounded = false;        ///< a step where N > 0 is not proved (required mu has no bound)
  std::string located;              ///< how --locate ended
  std::string run_failure;          ///< why the last enclosure that run() began stopped short, or ""
  long refined = 0;                 ///< undecided steps enclosed again in pieces

  /// A sole's margins as judged here: those of the results (the scene's mu), or, where mu is not
  /// the scene's, the cone of this judgement's mu formed from the sole's force and couple (the 16
  /// margins with a mu, the centre of pressure's 4 without).
  std::vector<I> sole_margins(const contact_values<I>& v) const {
    if (!sole_with_own_mu) return v.margins;
    const auto& [X, Y] = *sole_with_own_mu;
    return sole_margin_values(v.force, v.moment, X, Y, mu);
  }

  contact_verdict verdict_of(const contact_values<I>& v) const {
    if (!v.known) return contact_verdict::undecided;
    if (!v.margins.empty()) {  // a sole: its normal force and every margin of its wrench cone
      bool all = certainly_positive(v.normal), fails = certainly_negative(v.normal);
      for (const I& x : sole_margins(v)) all = all && certainly_positive(x), fails = fails || certainly_negative(x);
      return fails ? contact_verdict::fails : all ? contact_verdict::holds : contact_verdict::undecided;
    }
    return judge_contact(v.normal, v.tangential, mu ? &*mu : nullptr);
  }

  /// One main step [t0, t1] from `start` to `end`: its values over the step and at its end.
  /// Returns the step's row of the "contacts" table (contact_columns).
  std::vector<std::string> step(const I& t0, const I& t1, const vector_t<I>& start, const vector_t<I>& end,
                                const contact_values<I>& over, const contact_values<I>& at_end) {
    const contact_verdict v = verdict_of(over);
    if (!least_normal || lower(over.normal) < lower(*least_normal)) least_normal = over.normal;
    std::string mu_lo, mu_hi;
    if (over.known && certainly_positive(over.normal)) {
      const I r = over.tangential / over.normal;
      if (!largest_mu || upper(r) > upper(*largest_mu)) largest_mu = r;
      mu_lo = lower_string(r);
      mu_hi = upper_string(r);
    } else {
      mu_unbounded = true;
    }
    std::vector<std::string> row{name,
                                 lower_string(t0),
                                 upper_string(t1),
                                 lower_string(over.normal),
                                 upper_string(over.normal),
                                 lower_string(over.tangential),
                                 upper_string(over.tangential),
                                 std::move(mu_lo),
                                 std::move(mu_hi),
                                 verdict_name(v)};
    record r{t0, t1, start, end, v, verdict_of(at_end), {}, over};
    if (v == contact_verdict::fails) r.fails_at = t0;
    else if (r.at_end == contact_verdict::fails) r.fails_at = t1;
    if (r.fails_at) any_fails = true;
    steps.push_back(std::move(r));
    return row;
  }

  /// The first undecided steps enclosed again from their start in `pieces` shorter horizons
  /// (over a shorter time a step's enclosure holds less of the motion's variation, and may
  /// decide), in order, until one proves a failure or stays undecided (the holding prefix
  /// ends there; the main steps after it still prove failures).  run(x, h, on_step) as for
  /// locate().
  template <class Run, class At>
  void refine(int pieces, const Run& run, const At& at) {
    for (record& r : steps) {
      if (r.fails_at) break;  // what follows a proved failure does not move the first one
      if (r.over == contact_verdict::holds) continue;
      ++refined;
      const double h = approx_double(I(r.t1 - r.t0)) / pieces;
      vector_t<I> x = r.start;
      I offset = r.t0;
      bool all_hold = true;
      for (int k = 0; k < pieces && !r.fails_at; ++k) {
        vector_t<I> end;
        bool hold = true;
        const bool reached = run(x, h, [&](const I& t0, const I& t1, const contact_values<I>& over, const vector_t<I>& e) {
          const contact_verdict v = verdict_of(over);
          if (v != contact_verdict::holds) hold = false;
          if (!r.fails_at && v == contact_verdict::fails) r.fails_at = I(offset + t0);
          else if (!r.fails_at && verdict_of(at(e)) == contact_verdict::fails) r.fails_at = I(offset + t1);
          end = e;
        });
        if (!reached) {
          all_hold = false;
          break;
        }
        all_hold = all_hold && hold;
        x = end;
        offset = I(offset + I(h));
      }
      if (r.fails_at) {
        any_fails = true;
        r.over = contact_verdict::fails;  // somewhere in the step
        break;
      }
      if (!all_hold) break;  // the holding prefix ends here: later steps cannot extend it
      r.over = contact_verdict::holds;
    }
  }

  /// The verdict over the run from the steps: the holding prefix, the first proved failure.
  void finish(const vector_t<I>& x0) {
    prefix_holds = true;
    any_fails = false;
    hi.reset();
    lo = I(0);
    lo_state = x0;
    for (const record& r : steps) {
      if (r.fails_at) {
        any_fails = true;
        if (!hi || upper(*r.fails_at) < upper(*hi)) hi = *r.fails_at;
      }
      if (prefix_holds && !any_fails && r.over == contact_verdict::holds) {
        lo = r.t1;
        lo_state = r.end;
      } else {
        prefix_holds = false;
      }
    }
  }
  contact_verdict verdict() const {
    if (any_fails) return contact_verdict::fails;
    return prefix_holds ? contact_verdict::holds : contact_verdict::undecided;
  }

  /// Why the verdict is undecided: the first step that neither holds nor fails, and the margin
  /// there whose enclosure holds 0 (the normal force N, or mu N - |F_t|; for a sole N or the
  /// first of its wrench cone's margins that is not proved positive, by name and place in
  /// `<name>_margins`), its midpoint and width.
  struct undecided_margin {
    std::string text;
    double mid = 0, width = 0;  ///< 0 and 0 when the forces could not be evaluated
  };
  std::optional<undecided_margin> first_undecided() const {
    for (const record& r : steps) {
      if (r.fails_at) return std::nullopt;
      if (r.over == contact_verdict::holds) continue;
      const std::string when = "contact " + name + " over [" + lower_string(r.t0) + ", " + upper_string(r.t1) + "]: ";
      if (!r.values.known) return undecided_margin{when + "its forces could not be evaluated over the step", 0, 0};
      std::string what = "the normal force N";
      I m = r.values.normal;
      if (certainly_positive(r.values.normal)) {
        if (!r.values.margins.empty()) {  // a sole: the first margin of its cone not proved positive
          const std::vector<I> all = sole_margins(r.values);
          for (std::size_t k = 0; k < all.size(); ++k)
            if (!certainly_positive(all[k])) {
              // its place in the results' <name>_margins, or, judged with a mu of the run's own
              // (--mu, validity --vary mu), in the cone formed here with that mu
              what = "the " + sole_margin_name(k, all.size()) +
                     (sole_with_own_mu ? " (margin " + std::to_string(k) + " of the sole's cone at the run's mu)"
                                       : " (" + name + "_margins[" + std::to_string(k) + "])");
              m = all[k];
              break;
            }
        } else if (mu) {
          what = "the friction margin mu N - |F_t|";
          m = I(*mu * r.values.normal - r.values.tangential);
        }
      }
      const std::string lo_text = lower_string(m), hi_text = upper_string(m);
      const double lo = std::strtod(lo_text.c_str(), nullptr), hi = std::strtod(hi_text.c_str(), nullptr);
      std::ostringstream t;
      t << when << what << " in [" << lo_text << ", " << hi_text << "] holds 0 (midpoint " << (lo + hi) / 2 << ", width "
        << hi - lo << ")";
      return undecided_margin{t.str(), (lo + hi) / 2, hi - lo};
    }
    return std::nullopt;
  }

  /// --locate: narrow [lo, hi] by enclosing again from lo's state over shorter horizons.
  /// `run(x, h, on_step)` encloses from state x for a time h (an autonomous motion: the time
  /// is carried in the state when the scene depends on it), calls on_step(t0, t1, values over
  /// the step, end state) for each step, and returns whether it reached h; `at(state)` gives the
  /// contact's values at a state.
  template <class Run, class At>
  void locate(double tol, const Run& run, const At& at) {
    if (!any_fails || !hi) return;
    double h = approx_double(I(*hi - lo)) / 2;
    int rounds = 0;
    while (span(lo, *hi) > tol && rounds++ < 400) {
      h = std::min(h, approx_double(I(*hi - lo)));
      if (!(h > 0)) break;
      bool all_hold = true;
      std::optional<I> failed;  // relative to lo
      vector_t<I> end;
      const bool reached = run(lo_state, h, [&](const I& t0, const I& t1, const contact_values<I>& over, const vector_t<I>& e) {
        const contact_verdict v = verdict_of(over);
        if (v != contact_verdict::holds) all_hold = false;
        if (v == contact_verdict::fails && !failed) failed = t0;
        else if (!failed && verdict_of(at(e)) == contact_verdict::fails) failed = t1;
        end = e;
      });
      if (reached && all_hold) {
        lo = I(lo + I(h));
        lo_state = end;
        h = approx_double(I(*hi - lo)) / 2;
      } else if (failed) {
        const I t = I(lo + *failed);
        if (upper(t) < upper(*hi)) hi = t;
        h = approx_double(I(*hi - lo)) / 2;
      } else {
        // neither proved: the enclosures over h hold the boundary, or could not step (run_failure)
        const std::string why = reached ? "" : run_failure;
        h /= 2;
        if (h < tol / 64) {
          located = "stopped at width " + ode::number_text(span(lo, *hi)) + ": " +
                    (why.empty() ? "the enclosures over steps of " + ode::number_text(h * 2) +
                                       " hold the contact's boundary (they neither prove it holds nor that it fails)"
                                 : "the enclosure could not step from the holding state (" + why + ")");
          return;
        }
      }
    }
    located = span(lo, *hi) <= tol ? "located to within " + ode::number_text(tol) : "stopped after 400 rounds";
  }
};

}  // namespace appell::motion::detail
