// The motion's library calls (motion/motion.hpp): the scalar named at run time to a type
// (with_scalar), the scene's model to its runs (one loop over the models CMake lists in
// APPELL_MODELS: appell_models.hpp, generated; no list of names here; then the models a program
// registered while it started, motion/registry.hpp), and the reports' summaries.
// The runs themselves are instantiated per model and scalar in generated units
// (motion/engine.hpp); this unit only declares them.
#include "appell/motion/motion.hpp"
#include "appell/motion/checks.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "appell/build_options.hpp"
#include "appell/motion/engine.hpp"
#include "appell/motion/registry.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/standard_scalars.hpp"
#include "appell_models.hpp"

#define APPELL_DETAIL_EXTERN_MODEL_RUNS(Model) APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_RUN, Model)
APPELL_FOR_EACH_MODEL(APPELL_DETAIL_EXTERN_MODEL_RUNS)

namespace appell::motion {

namespace {

/// The models registered while the program started (motion/registry.hpp), in their order.
std::vector<registered_motion>& registered() {
  static std::vector<registered_motion> models;
  return models;
}

/// Calls f(std::type_identity<Model>) for the scene's model if it is a built-in one that moves,
/// g(its registered motion) if it was registered; input_error naming `model` otherwise.
template <class R, class F, class G, class... Models>
R with_moving_model(const scene_input& scene, const std::string& command, F&& f, G&& g, type_list<Models...>) {
  std::optional<R> r;
  const std::string& module = scene.entry ? scene.entry->module : scene.model;
  auto try_one = [&]<class Model>(std::type_identity<Model> m) {
    if constexpr (moving_model<Model>)
      if (!r && module == Model::name) r.emplace(f(m));
  };
  (try_one(std::type_identity<Models>{}), ...);
  if (!r)
    if (const registered_motion* m = find_registered_motion(module)) r.emplace(g(*m));
  if (!r)
    throw input_error("model: " + command + " moves the models " + moving_model_names() + "; '" + scene.model +
                      "' has no motion");
  return std::move(*r);
}

/// The run `q` in the scalar its settings name, on the scene's model.
void run(const scene_input& scene, const run_request& q, const char* command) {
#ifdef APPELL_EVAL_ONLY
  (void)scene;
  (void)q;
  throw input_error(left_out_message(command));
#else
  std::string scalar = q.s->scalar;
  if (scalar.empty()) scalar = q.kind == run_kind::simulate ? "double" : "interval";
  // with_scalar refuses a scalar the build left out, without instantiating the lambda in it
  with_scalar(scalar, q.s->bits, [&]<class T>(std::type_identity<T>) {
    with_moving_model<bool>(
        scene, command,
        [&]<class Model>(std::type_identity<Model>) {
          run_model<Model, T>(scene, q);
          return true;
        },
        [&](const registered_motion& m) {
          m.run[standard_scalar_index<T>](scene, q);  // every built scalar's is compiled
          return true;
        },
        all_models{});
  });
#endif
}

void require_positive(const char* flag, const std::optional<double>& v) {
  if (v && (!(*v > 0) || !std::isfinite(*v)))
    throw input_error(std::string(flag) + ": expected a positive decimal, got '" + to_decimal(*v) + "'");
}

/// The settings a run needs, checked as the commands check their flags (a library caller, C++ or
/// Python, gets the same one-line refusal), or input_error naming the field.
void require_horizon(const settings& s) {
  if (s.t_end.empty()) throw input_error("--t-end: required (the horizon, a positive decimal)");
  (void)positive_decimal("--t-end", s.t_end);
  if (!s.every.empty()) (void)positive_decimal("--every", s.every);
  if (s.order && (*s.order < 2 || *s.order > 60))
    throw input_error("--order: expected an integer from 2 to 60, got '" + std::to_string(*s.order) + "'");
  require_positive("--tol", s.tol);
  if (s.tol && *s.tol >= 1)
    throw input_error("--tol: expected a positive decimal below 1 (a relative error per step), got '" + to_decimal(*s.tol) + "'");
  require_positive("--max-width", std::optional<double>(s.max_width));
  require_positive("--max-seconds", s.max_seconds);
  require_positive("--locate", s.locate);
  require_positive("--resolution", s.resolution);
  if (s.jobs < 0 || s.jobs > 1024) throw input_error("--jobs: expected an integer from 1 to 1024, got '" + std::to_string(s.jobs) + "'");
  if (s.mu) check_friction(*s.mu);
  if (!s.vary_field.empty()) check_range(s.vary_field, s.vary_lo, s.vary_hi);
}

}  // namespace

double positive_decimal(const std::string& flag, const std::string& text) {
  double v = 0;
  try {
    v = from_decimal<double>(text);
  } catch (const std::exception&) {
    v = 0;
  }
  if (!(v > 0) || !std::isfinite(v)) throw input_error(flag + ": expected a positive decimal, got '" + printable(text) + "'");
  return v;
}

void check_friction(const std::string& mu) {
  bool nonnegative = false;
  try {
    nonnegative = decimal_sign_of_sum({{1, mu}}) >= 0;
  } catch (const std::exception&) {
  }
  if (!nonnegative) throw input_error("--mu: expected a decimal >= 0 (every contact's friction coefficient), got '" + printable(mu) + "'");
}

void check_range(const std::string& field, const std::string& lo, const std::string& hi) {
  const std::string given = field + "=" + lo + ":" + hi;
  for (const std::string* d : {&lo, &hi}) {
    try {
      (void)decimal_sign_of_sum({{1, *d}});
    } catch (const std::exception&) {
      throw input_error("--vary: expected FIELD=lo:hi with decimal bounds, got '" + given + "'");
    }
  }
  if (decimal_sign_of_sum({{1, hi}, {-1, lo}}) <= 0)
    throw input_error("--vary: the range's lower bound must be below its upper bound, got '" + given + "'");
}

std::string run_identity::bits_text() const {
  return std::to_string(bits) + " bits" + (bits_requested ? " (" + std::to_string(bits_requested) + " requested)" : "");
}

const std::vector<std::string>& contact_columns() {
  static const std::vector<std::string> names{"contact",        "t0",
                                              "t1",             "normal_force_lo",
                                              "normal_force_hi", "tangential_force_lo",
                                              "tangential_force_hi", "required_mu_lo",
                                              "required_mu_hi", "verdict"};
  return names;
}

simulate_report simulate(const scene_input& scene, const settings& given, row_sink& rows) {
  require_horizon(given);
  settings s = given;
  if (s.every.empty()) {  // 100 outputs
    s.every = s.t_end + "e-2";
    if (s.t_end.find_first_of("eE") != std::string::npos) s.every = to_decimal(from_decimal<double>(s.t_end) / 100);
  }
  simulate_report r;
  run(scene, {run_kind::simulate, &s, &rows, &r, nullptr, nullptr}, "simulate");
  return r;
}

enclose_report enclose(const scene_input& scene, const settings& s, row_sink& rows) {
  require_horizon(s);
  enclose_report r;
  run(scene, {run_kind::enclose, &s, &rows, nullptr, &r, nullptr}, "enclose");
  return r;
}

validity_report validity(const scene_input& scene, const settings& s) {
  require_horizon(s);
  if (s.vary_field.empty()) throw input_error("--vary: required (FIELD=lo:hi, the range to split)");
  validity_report r;
  discard_rows none;
  run(scene, {run_kind::validity, &s, &none, nullptr, nullptr, &r}, "validity");
  return r;
}

horizon_track track(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits,
                    const std::string& t_end, const std::string& every, const track_settings& settings,
                    const std::function<void(double)>& progress) {
#ifdef APPELL_EVAL_ONLY
  (void)scene;
  (void)scalar;
  (void)bits;
  (void)t_end;
  (void)every;
  (void)settings;
  (void)progress;
  throw input_error(left_out_message("the motion (horizon, reference --trajectory)"));
#else
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    return with_moving_model<horizon_track>(
        scene, "horizon",
        [&]<class Model>(std::type_identity<Model>) { return run_model_track<Model, T>(scene, t_end, every, settings, progress); },
        [&](const registered_motion& m) { return m.track[standard_scalar_index<T>](scene, t_end, every, settings, progress); },
        all_models{});
  });
#endif
}

void register_motion(registered_motion m) {
  bool taken = find_registered_motion(m.module) != nullptr;
  [&]<class... Models>(type_list<Models...>) {
    ((taken = taken || (moving_model<Models> && m.module == Models::name)), ...);
  }(all_models{});
  if (taken) throw std::logic_error("register_motion: a model named " + m.module + " moves already");
  registered().push_back(std::move(m));
}

const registered_motion* find_registered_motion(const std::string& module) {
  for (const registered_motion& m : registered())
    if (m.module == module) return &m;
  return nullptr;
}

std::string moving_model_names() {
  std::string names;
  auto add = [&]<class Model>(std::type_identity<Model>) {
    if constexpr (moving_model<Model>) names += (names.empty() ? "" : ", ") + std::string(Model::name);
  };
  [&]<class... Models>(type_list<Models...>) { (add(std::type_identity<Models>{}), ...); }(all_models{});
  for (const registered_motion& m : registered()) names += (names.empty() ? "" : ", ") + m.module;
  return names;
}

std::vector<std::string> state_fields(const scene_input& scene) {
  return with_moving_model<std::vector<std::string>>(
      scene, "--trajectory",
      [&]<class Model>(std::type_identity<Model>) {
        return model_motion<Model>::state_fields(scene.as<typename Model::input>());
      },
      [&](const registered_motion& m) { return m.state_fields(scene); }, all_models{});
}

std::optional<motion_closed_form> closed_form_of(const scene_input& scene) {
  return with_moving_model<std::optional<motion_closed_form>>(
      scene, "horizon",
      [&]<class Model>(std::type_identity<Model>) -> std::optional<motion_closed_form> {
        if constexpr (requires { model_motion<Model>::closed_form(scene.as<typename Model::input>()); })
          return model_motion<Model>::closed_form(scene.as<typename Model::input>());
        else
          return std::nullopt;
      },
      [&](const registered_motion& m) { return m.closed_form(scene); }, all_models{});
}

// ---------------------------------------------------------------------------
// summary.json

namespace {

/// What every summary opens with: the command, the scene and its model, and the scalar's fields
/// as `appell eval`'s ("bits" the bits used, "bits_requested" where they differ from the bits
/// asked for).
nlohmann::json summary_head(const char* command, const std::string& scene, const run_identity& id) {
  nlohmann::json j = {{"command", command}, {"scene", scene}, {"model", id.model}, {"scalar", id.scalar}, {"bits", id.bits}};
  if (id.bits_requested) j["bits_requested"] = id.bits_requested;
  return j;
}

nlohmann::json state_object(const std::vector<std::pair<std::string, std::string>>& state) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : state) j[name] = value;
  return j;
}

}  // namespace

nlohmann::json summary(const simulate_report& r, const settings& s, const std::string& scene) {
  nlohmann::json inv = nlohmann::json::array();
  for (const auto& q : r.invariants)
    inv.push_back({{"name", q.name},
                   {"initial", q.initial},
                   {"final", q.final},
                   {q.zero_in_truth ? "max_abs_value" : "max_relative_drift", q.worst}});
  const bool complete = r.failure.empty();
  nlohmann::json j = summary_head("simulate", scene, r.id);
  j.update({{"order", r.id.order},
            {"tol", r.id.tol},
            {"t_end", s.t_end},
            {"every", s.every},
            {"complete", complete},
            {"reason", r.failure},
            {"t_reached", r.t_reached},
            {"steps", complete ? nlohmann::json(r.steps) : nlohmann::json()},
            {"seconds", r.seconds},
            {"min_step", complete ? nlohmann::json(r.min_step) : nlohmann::json()},
            {"max_step", complete ? nlohmann::json(r.max_step) : nlohmann::json()},
            {"final_state", state_object(r.final_state)},
            {"invariants", inv}});
  return j;
}

nlohmann::json summary(const enclose_report& r, const settings& s, const std::string& scene) {
  nlohmann::json contacts = nlohmann::json::object();
  for (const auto& c : r.contacts) {
    nlohmann::json j = {{"verdict", c.verdict}, {"refined_steps", c.refined}};
    if (!c.mu_text.empty()) j["mu"] = c.mu_text;
    if (c.least_normal) j["least_normal_force"] = *c.least_normal;
    j["largest_required_mu"] = c.largest_mu ? nlohmann::json(*c.largest_mu) : nlohmann::json();
    if (c.verdict == "fails") {
      j["first_failure"] = {{"from", c.holding_lo}, {"to", *c.fails_by}};
      if (!c.located.empty()) j["located"] = c.located;
    } else if (c.verdict == "undecided") {
      j["undecided_from"] = c.holding_lo;
    } else {
      j["holds_until"] = c.holding_hi;
    }
    contacts[c.name] = j;
  }
  nlohmann::json widths = nlohmann::json::object();
  for (std::size_t i = 0; i < r.value_names.size(); ++i) widths[r.value_names[i]] = r.widest_over[i];
  nlohmann::json j = summary_head("enclose", scene, r.id);
  j.update({{"order", r.id.order},
            {"tol", r.id.tol},
            {"t_end", s.t_end},
            {"complete", r.complete},
            {"reason", r.reason},
            {"t_reached", r.t_reached},
            {"steps", r.steps},
            {"rejected_steps", r.rejected},
            {"variational_steps", r.variational_steps},
            {"seconds", r.seconds},
            {"final_state", state_object(r.final_state)},
            {"final_largest_width", r.final_width},
            {"largest_width_over_a_step", widths}});
  if (!r.contacts.empty()) j["contacts"] = contacts;
  if (!r.contact_stop.empty()) j["stopped_at_contact_failure"] = true;
  return j;
}

nlohmann::json summary(const validity_report& r, const settings& s, const std::string& scene) {
  const std::vector<piece_report>& done = r.run.done;
  // The ranges of each verdict (adjacent pieces merged); why the undecided pieces stayed so, and
  // the narrowest piece width their margins suggest.
  nlohmann::json undecided_why = nlohmann::json::array();
  double suggested = 0;
  nlohmann::json ranges = {{"holds", nlohmann::json::array()}, {"fails", nlohmann::json::array()}, {"undecided", nlohmann::json::array()}};
  std::string last;
  double piece_seconds = 0;
  for (const piece_report& p : done) {
    const std::string& v = p.verdict;
    if (v == "undecided") {
      undecided_why.push_back({{"lo", p.lo}, {"hi", p.hi}, {"why", p.why}});
      if (p.suggested > 0) suggested = suggested > 0 ? std::min(suggested, p.suggested) : p.suggested;
    }
    nlohmann::json& list = ranges[v];
    if (v == last && !list.empty()) list.back()[1] = p.hi;
    else list.push_back({p.lo, p.hi});
    last = v;
    piece_seconds += p.seconds;
  }
  nlohmann::json j = summary_head("validity", scene, r.id);
  j.update({{"field", s.vary_field},
            {"range", {s.vary_lo, s.vary_hi}},
            {"t_end", s.t_end},
            {"resolution", r.resolution},
            {"pieces", done.size()},
            {"complete", r.run.stopped.empty()},
            {"reason", r.run.stopped},
            {"pieces_not_run", r.run.not_run},
            {"ranges", ranges},
            {"undecided_pieces", undecided_why},
            {"suggested_resolution", suggested > 0 ? nlohmann::json(suggested) : nlohmann::json()},
            {"threads", r.threads},
            {"processes", r.processes},
            {"seconds", r.seconds},
            {"seconds_per_piece", done.empty() ? 0.0 : piece_seconds / static_cast<double>(done.size())}});
  return j;
}

}  // namespace appell::motion
