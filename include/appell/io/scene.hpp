// appell/io/scene.hpp -- scene files (SCENES.md) and their evaluation.
//
// read_scene() validates a scene once, on the exact decimals, independently of
// the scalar (so "A + B >= C" is decided exactly, not after rounding), through
// the registry of models: each model is a module (models/<model>.hpp and
// src/models/<model>.cpp) with its schema, reader and compute<T>; the
// registry is generated from CMake's APPELL_MODELS list.
// prepare<T>() converts a scene's inputs to T once; compute<T>() runs the
// model's dynamics, under the scalar's evaluation policy (scalar/policy.hpp);
// evaluate<T>() does both and adds error_amplification for point types;
// format_json() prints the `appell eval` document.  These are instantiated
// once per standard scalar (scalar/standard_scalars.hpp) in generated units.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "appell/dynamics/gibbs_appell.hpp"  // vec3
#include "appell/io/json.hpp"
#include "appell/reactions/contact.hpp"
#include "appell/reactions/wrench_cone.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/scalar/policy.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell {

/// A model's validated inputs (exact decimals), type-erased: each model
/// module derives its input struct from this.
struct model_input {
  virtual ~model_input() = default;
};

struct model_entry;

/// A validated scene: its model and inputs, independent of any scalar.
struct scene_input {
  std::string model;
  std::shared_ptr<const model_input> input;
  const model_entry* entry = nullptr;
  /// The inputs as the model's own struct (the struct its home names `input`); std::logic_error if another model's.
  template <class In>
  const In& as() const {
    const auto* p = dynamic_cast<const In*>(input.get());
    if (!p) throw std::logic_error("scene '" + model + "' does not hold the inputs asked for");
    return *p;
  }
};

template <Scalar T>
struct named_result {
  std::string name;
  std::vector<T> values;
  bool is_vector = false;
};

/// A number as appell's documents print it (io/json_text.hpp writes them): an interval's bounds
/// as decimals rounded outward ({"lo", "hi"}; "[lo, hi]" in the text format), or a point value
/// ({"value"}), each as to_string (scalar/format.hpp) gives it.
struct printed_number {
  bool interval = false;
  std::string lo, hi;  ///< an interval's bounds; a point value's decimal in lo (hi empty)
};

template <Scalar T>
printed_number printed(const T& x) {
  if constexpr (scalar_traits<T>::is_interval)
    return {true, lower_string(x), upper_string(x)};
  else
    return {false, to_string(x), ""};
}

/// A contact's verdict (reactions/contact.hpp): "holds", "fails" or "undecided", its mu as
/// written (empty: none given), and the friction coefficient it requires (none where the normal
/// force is not proved positive).  Kept out of the results, whose list must not depend on the
/// values (reference, tradeoff and the error amplification compare the scalars' results by
/// position).
struct contact_judgement {
  std::string name, verdict, mu;
  std::optional<printed_number> required_mu;
  /// A sole's centre of pressure on its axes (x, y), where the normal force is proved positive.
  std::optional<std::array<printed_number, 2>> center_of_pressure;
};

/// One contact's judgement for eval's document from its normal force, its tangential force's
/// length and its mu as written ("" for none): the verdict (judge_contact) and the friction
/// coefficient it requires, |F_t| / N, where N is proved positive.
template <Scalar T>
contact_judgement judged_contact(const std::string& name, const T& normal, const T& tangential, const std::string& mu_text) {
  std::optional<printed_number> required;
  if (certainly_positive(normal)) required = printed(T(tangential / normal));
  std::optional<T> mu;
  if (!mu_text.empty()) mu = from_decimal<T>(mu_text);
  return {name, verdict_name(judge_contact(normal, tangential, mu ? &*mu : nullptr)), mu_text, required, std::nullopt};
}

/// A sole's margins as a result (SCENES.md, "contacts of links"): with mu the 16 of its contact
/// wrench cone (friction 4, centre of pressure 4, yaw 8; reactions/wrench_cone.hpp), without mu
/// the 4 of the centre of pressure; each >= 0 exactly when that half-space holds.
template <Scalar T>
std::vector<T> sole_margin_values(const vec3<T>& force, const vec3<T>& moment, const T& X, const T& Y,
                                  const std::optional<T>& mu) {
  const wrench_cone_margins<T> w = sole_wrench_margins(force, moment, X, Y, mu ? *mu : T(0));
  if (mu) {
    const std::array<T, 16> all = all_margins(w);
    return std::vector<T>(all.begin(), all.end());
  }
  return std::vector<T>(w.pressure.begin(), w.pressure.end());
}

/// A sole's judgement: with mu its contact wrench cone (judge_sole), without mu the normal force's
/// sign and the centre of pressure in the sole; the friction it requires on the resultant and
/// its centre of pressure, where the normal force is proved positive.
template <Scalar T>
contact_judgement judged_sole(const std::string& name, const vec3<T>& force, const vec3<T>& moment, const T& X,
                              const T& Y, const std::optional<T>& mu, const std::string& mu_text) {
  contact_verdict v;
  if (mu) {
    v = judge_sole(sole_wrench_margins(force, moment, X, Y, *mu));
  } else {
    const wrench_cone_margins<T> w = sole_wrench_margins(force, moment, X, Y, T(0));
    bool all = certainly_positive(force(2)), fails = certainly_negative(force(2));
    for (const T& x : w.pressure) all = all && certainly_positive(x), fails = fails || certainly_negative(x);
    v = fails ? contact_verdict::fails : all ? contact_verdict::holds : contact_verdict::undecided;
  }
  contact_judgement j{name, verdict_name(v), mu_text, std::nullopt, std::nullopt};
  if (certainly_positive(force(2))) {
    using std::sqrt;
    j.required_mu = printed(T(sqrt(T(force(0) * force(0) + force(1) * force(1))) / force(2)));
    j.center_of_pressure = std::array<printed_number, 2>{printed(T(-moment(1) / force(2))), printed(T(moment(0) / force(2)))};
  }
  return j;
}

/// Whether an evaluation computes its checks (the identities `appell eval` prints: eq. (4), Cotton
/// against Lagrange, ...).  `no`: a caller that uses only the results and the derived state (`appell
/// reference`, error_amplification) lets a model leave out what only its checks need (the rolling
/// sphere's Lagrange multipliers and eq. (4): a fifth of a reference state's instructions).  A model
/// that takes no such flag computes them anyway (model.hpp); the results are the same either way.
enum class with_checks : bool { no = false, yes = true };

template <Scalar T>
struct evaluation {
  std::vector<named_result<T>> results;
  std::vector<named_result<T>> checks;
  /// The state the scene's inputs imply but do not give (psi = f(theta) on the cone, the
  /// sphere's contact point): echoed so that other programs need not rebuild it (may be empty).
  std::vector<named_result<T>> derived;
  /// Per contact of the scene, its verdict (SCENES.md "contacts"; may be empty).
  std::vector<contact_judgement> contacts;
  const named_result<T>& result(const std::string& name) const { return find(results, name); }
  const named_result<T>& check(const std::string& name) const { return find(checks, name); }
  const named_result<T>& derived_result(const std::string& name) const { return find(derived, name); }

 private:
  static const named_result<T>& find(const std::vector<named_result<T>>& group, const std::string& name) {
    for (const auto& r : group)
      if (r.name == name) return r;
    throw std::out_of_range("no result named " + name);
  }
};

/// A scene number in T; a value out of T's range is bad input naming the field.
template <Scalar T>
T value(const decimal_field& d) {
  try {
    return from_decimal<T>(d.text);
  } catch (const parse_error& e) {
    throw input_error(d.path + ": " + e.what());
  }
}

namespace detail {
template <Scalar T>
vec3<T> vec3_from_decimals(const std::vector<decimal_field>& d) {
  return vec3<T>(value<T>(d[0]), value<T>(d[1]), value<T>(d[2]));
}
template <Scalar T>
named_result<T> vector_result(std::string name, const vec3<T>& v) {
  return {std::move(name), {v(0), v(1), v(2)}, true};
}
template <Scalar T>
named_result<T> scalar_result(std::string name, const T& v) {
  return {std::move(name), {v}, false};
}
}  // namespace detail

/// Writes an evaluation's values over those of the evaluation it is given (compute_into: the same
/// scene evaluated again), in the order they come: each name and value into the storage of the
/// one at its place, so that an evaluation of the same scene takes nothing from the heap for
/// them.  finish() drops what the earlier evaluation had beyond.
template <Scalar T>
class evaluation_writer {
 public:
  enum group_id { results, checks, derived };
  /// Over e: its contacts' judgements cleared (they are written whole), its names and values
  /// written over in order and the rest dropped by finish().
  explicit evaluation_writer(evaluation<T>& e) : e_(e) { e_.contacts.clear(); }
  /// name + suffix = v (name and suffix concatenated in place, never as a temporary string).
  void scalar(group_id g, std::string_view name, const char* suffix, const T& v) {
    named_result<T>& r = next(g, name, suffix, false);
    r.values.resize(1);
    r.values[0] = v;
  }
  void vector(group_id g, std::string_view name, const char* suffix, const vec3<T>& v) {
    named_result<T>& r = next(g, name, suffix, true);
    r.values.resize(3);
    for (int i = 0; i < 3; ++i) r.values[static_cast<std::size_t>(i)] = v(i);
  }
  /// A list of any length (a sole's margins), printed as a vector.
  void list(group_id g, std::string_view name, const char* suffix, const std::vector<T>& v) {
    named_result<T>& r = next(g, name, suffix, true);
    r.values.assign(v.begin(), v.end());
  }
  /// The evaluation's contacts' judgements, written whole (they hold strings of the values).
  std::vector<contact_judgement>& contacts() { return e_.contacts; }
  void finish() {
    for (int g = 0; g < 3; ++g) group(static_cast<group_id>(g)).resize(written_[g]);
  }

 private:
  std::vector<named_result<T>>& group(group_id g) {
    return g == results ? e_.results : g == checks ? e_.checks : e_.derived;
  }
  named_result<T>& next(group_id g, std::string_view name, const char* suffix, bool is_vector) {
    std::vector<named_result<T>>& v = group(g);
    std::size_t& n = written_[g];
    if (n == v.size()) v.emplace_back();
    named_result<T>& r = v[n++];
    r.name.assign(name);
    r.name.append(suffix);
    r.is_vector = is_vector;
    return r;
  }
  evaluation<T>& e_;
  std::size_t written_[3] = {0, 0, 0};
};

/// A scene's inputs converted to T and checked, ready to be computed any
/// number of times (the timing loops of `tradeoff` and the benchmark).
template <Scalar T>
class prepared_scene {
 public:
  using compute_fn = void (*)(const void*, evaluation<T>&, with_checks);
  prepared_scene(std::shared_ptr<const void> state, compute_fn f) : state_(std::move(state)), compute_(f) {}
  /// The model's dynamics alone (no evaluation policy: use appell::compute).
  evaluation<T> run(with_checks checks = with_checks::yes) const {
    evaluation<T> e;
    compute_(state_.get(), e, checks);
    return e;
  }
  /// The same into e, written over an earlier evaluation of this scene (its storage reused).
  void run_into(evaluation<T>& e, with_checks checks = with_checks::yes) const { compute_(state_.get(), e, checks); }
  /// Keeps the scene's inputs alive as long as this (prepared state may point
  /// into them: a cone's compiled expressions do).
  void keep(std::shared_ptr<const model_input> inputs) { inputs_ = std::move(inputs); }

 private:
  std::shared_ptr<const void> state_;
  compute_fn compute_;
  std::shared_ptr<const model_input> inputs_;
};

template <class T>  // unconstrained: a template template argument of per_standard_scalar
using prepare_fn = prepared_scene<T> (*)(const model_input&);

/// One registered model: its name, its reader, and its prepare<T> for every standard scalar.
struct model_entry {
  std::string name;
  std::shared_ptr<const model_input> (*read)(object_reader& scene);
  per_standard_scalar<prepare_fn> prepare;
  /// The model module whose inputs the reader makes (its name; "system" for "urdf").
  std::string module;
  /// A scene whose reader opens other files (a robot's description): makes the scene's relative
  /// paths to them absolute, from `scene_directory`, so that the scene reads the same wherever it
  /// is evaluated (`reference`'s threads and processes). nullptr: the scene names no file.
  void (*anchor_files)(json_value& scene, const std::string& scene_directory) = nullptr;
  /// A front end's scene as the text of the scene it reads as (the `system` file `appell convert`
  /// prints), so that `reference --inputs binary64` rounds every number the model reads, the
  /// other file's included. nullptr: the scene's own numbers are all there is.
  std::string (*read_as_text)(const json_value& scene) = nullptr;
  /// `appell convert PATH`: a file of the front end's own kind (a robot's description) or one of
  /// its scenes, as the text of the scene appell reads it as; std::nullopt where the file is not
  /// of its kind (another converter may take it); input_error where it is but cannot be read.
  /// nullptr: the model's scenes are what they read as.
  std::optional<std::string> (*convert)(const std::string& path) = nullptr;
  /// What `convert` takes, for the usage line ("a URDF file or a \"urdf\" scene").
  const char* converts = nullptr;
  /// `appell linearize`'s report (json or text) for a model that linearizes its scenes (the
  /// model's static `linearize`); nullptr: the model has no linearization.
  std::string (*linearize)(const model_input& in, const std::string& scalar, std::optional<unsigned> bits,
                           const std::string& format) = nullptr;
};

/// Every model compiled into the library, in the order of CMake's APPELL_MODELS, then those a
/// program registered while it started (io/model_registry.hpp).
const std::vector<const model_entry*>& registered_models();
/// The model called `name`; input_error naming the field `model` otherwise.
const model_entry& find_model(const std::string& name);
/// The model a parsed scene names, or nullptr where its "model" is missing, not a string or not
/// registered (read_scene then says which).
const model_entry* scene_model(const json_value& scene);

/// Validates a parsed scene; throws input_error naming the field.
scene_input read_scene(const json_value& root);
/// Reads and validates a scene file; throws input_error.
scene_input read_scene_file(const std::string& path);

/// The scene's inputs in T (at the evaluation policy's working precision).
template <Scalar T>
prepared_scene<T> prepare(const scene_input& scene) {
  const evaluation_scope<T> scope;
  const prepare_fn<T> prepare_in_t = std::get<prepare_fn<T>>(scene.entry->prepare);
  if (!prepare_in_t) throw input_error(left_out_scalar_message("scalar", scalar_traits<T>::name));
  prepared_scene<T> p = prepare_in_t(*scene.input);
  p.keep(scene.input);
  scope.verify();  // the state's constraint residuals are results too
  return p;
}

/// The dynamics of a prepared scene, under the evaluation policy of T
/// (interval: one upward-rounding scope; mpfi: guard bits, results rounded outward).
/// A value that is not finite (an overflow, or 0/0, in T) is never returned:
/// certification_error names it (exit 3; a wider scalar may succeed).
/// compute_into writes the evaluation over `e`, an earlier evaluation of the same scene or an
/// empty one, reusing its storage (a warm evaluation of a system file takes nothing from the
/// heap for its names and values); `e` is unspecified after an exception.
namespace detail {
/// A result's component as a message names it, "name" or "name[i]" (compiled once: inlined in
/// every scalar's compute_into, GCC 12 warned of a string copy it could not bound).
std::string component_name(const std::string& name, bool is_vector, std::size_t i);
}  // namespace detail

template <Scalar T>
void compute_into(const prepared_scene<T>& scene, evaluation<T>& e, with_checks checks = with_checks::yes) {
  const evaluation_scope<T> scope;
  scene.run_into(e, checks);
  for (auto* group : {&e.results, &e.checks, &e.derived})
    for (auto& r : *group)
      for (std::size_t i = 0; i < r.values.size(); ++i) {
        scope.finish(r.values[i]);
        if (!is_finite(r.values[i]))  // the name made only for the message
          require_finite(r.values[i], detail::component_name(r.name, r.is_vector, i));
      }
}
template <Scalar T>
evaluation<T> compute(const prepared_scene<T>& scene, with_checks checks = with_checks::yes) {
  evaluation<T> e;
  compute_into(scene, e, checks);
  return e;
}

/// How much the scene amplifies rounding errors, measured: the largest relative
/// width of the results of an interval<double> evaluation, divided by 2^-53; where
/// double's range does not hold the evaluation, the same with 53-bit mpfi bounds
/// (MPFR's exponent range); infinity where neither can certify.  Point types carry
/// it in "checks" as `error_amplification`: their relative error is expected below
/// error_amplification * 2^(1 - precision) (tests/extremes.cpp holds them to 16x that).
/// Where it is infinite the check is left out (a document never holds inf):
/// the point values then carry no error estimate (SCENES.md).
double error_amplification(const scene_input& scene);

/// The scene's results in scalar T (mpfr/mpfi at the current mp precision); with_checks::no: no
/// checks (error_amplification, a check of the point types, included).
template <Scalar T>
evaluation<T> evaluate(const scene_input& scene, with_checks checks = with_checks::yes) {
  evaluation<T> e = compute<T>(prepare<T>(scene), checks);
  if constexpr (!scalar_traits<T>::is_interval) {
    if (checks == with_checks::no) return e;
    const double a = error_amplification(scene);
    if (std::isfinite(a)) e.checks.push_back(detail::scalar_result("error_amplification", T(a)));
  }
  return e;
}

/// The scalar a document was computed in, as `appell eval` names it after the model: scalar,
/// bits used (and bits_requested where a library limit made them differ), rigour.
struct scalar_identity {
  std::string name;
  int bits = 0;
  std::optional<int> bits_requested;
  bool rigorous = false;
};

template <Scalar T>
scalar_identity identity_of() {
  scalar_identity s{scalar_traits<T>::name, static_cast<int>(scalar_traits<T>::precision_bits()), std::nullopt,
                    scalar_traits<T>::is_rigorous};
  if constexpr (scalar_traits<T>::runtime_precision)
    if (scalar_traits<T>::precision_bits() != mp_precision_bits()) s.bits_requested = static_cast<int>(mp_precision_bits());
  return s;
}

/// An evaluation as its documents print it, free of the scalar.
struct printed_result {
  std::string name;
  bool is_vector = false;
  std::vector<printed_number> values;
};
struct printed_evaluation {
  std::string model;
  scalar_identity scalar;
  std::vector<printed_result> results, checks, derived;
  std::vector<contact_judgement> contacts;
};

template <Scalar T>
printed_evaluation printed(const scene_input& scene, const evaluation<T>& e) {
  auto group = [](const std::vector<named_result<T>>& items) {
    std::vector<printed_result> out;
    out.reserve(items.size());
    for (const auto& r : items) {
      printed_result p{r.name, r.is_vector, {}};
      for (const T& x : r.values) p.values.push_back(printed(x));
      out.push_back(std::move(p));
    }
    return out;
  };
  return {scene.model, identity_of<T>(), group(e.results), group(e.checks), group(e.derived), e.contacts};
}

/// The `appell eval` JSON document (SCENES.md), written by io/json_text.hpp's writer, and a
/// human-readable rendering of the same numbers (src/io/evaluation_text.cpp).
std::string format_json(const printed_evaluation& e);
std::string format_text(const printed_evaluation& e);

template <Scalar T>
std::string format_json(const scene_input& scene, const evaluation<T>& e) {
  return format_json(printed(scene, e));
}
template <Scalar T>
std::string format_text(const scene_input& scene, const evaluation<T>& e) {
  return format_text(printed(scene, e));
}

// The scene layer is instantiated once per standard scalar, in units CMake
// generates from the list (cmake/instantiate.cmake).
#define APPELL_SCENE_TEMPLATES(prefix, T)                                                  \
  prefix template prepared_scene<T> prepare<T>(const scene_input&);                        \
  prefix template void compute_into<T>(const prepared_scene<T>&, evaluation<T>&, with_checks); \
  prefix template evaluation<T> compute<T>(const prepared_scene<T>&, with_checks);         \
  prefix template evaluation<T> evaluate<T>(const scene_input&, with_checks);              \
  prefix template printed_evaluation printed<T>(const scene_input&, const evaluation<T>&);
#define APPELL_DETAIL_EXTERN_SCENE(ctx, T, name) APPELL_SCENE_TEMPLATES(extern, T)
APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_SCENE, )
#undef APPELL_DETAIL_EXTERN_SCENE

}  // namespace appell
