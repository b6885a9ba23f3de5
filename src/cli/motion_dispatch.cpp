// Which models move, and the motion commands' dispatch to the model's own
// motion (io/model_motion.hpp): one loop over the models CMake lists in
// APPELL_MODELS (appell_models.hpp, generated), no list of names here.  The
// runs themselves are instantiated per model and scalar in generated units
// (motion_run.hpp); this unit only declares them.
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <vector>

#include "appell_models.hpp"
#include "motion_commands.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell::cli {

#define APPELL_DETAIL_EXTERN_MOTION(Model, T, name)                                                       \
  extern template motion_outcome run_model_motion<Model, T>(const scene_input&, const motion_options&); \
  extern template horizon_track run_model_horizon_track<Model, T>(const scene_input&, const std::string&, \
                                                                  const std::string&, bool, const track_settings&);
#define APPELL_DETAIL_EXTERN_MODEL_MOTION(Model) APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_MOTION, Model)
APPELL_FOR_EACH_MODEL(APPELL_DETAIL_EXTERN_MODEL_MOTION)

namespace {

/// Calls f(std::type_identity<Model>) for the scene's model if it moves; input_error naming
/// `model` otherwise.
template <class R, class F, class... Models>
R with_moving_model(const scene_input& scene, const std::string& command, F&& f, type_list<Models...>) {
  std::optional<R> r;
  auto try_one = [&]<class Model>(std::type_identity<Model> m) {
    if constexpr (moving_model<Model>)
      if (!r && (scene.entry ? scene.entry->module : scene.model) == Model::name) r.emplace(f(m));
  };
  (try_one(std::type_identity<Models>{}), ...);
  if (!r)
    throw input_error("model: " + command + " moves the models " + moving_model_names() + "; '" + scene.model +
                      "' has no motion");
  return std::move(*r);
}

}  // namespace

std::string moving_model_names() {
  std::string names;
  auto add = [&]<class Model>(std::type_identity<Model>) {
    if constexpr (moving_model<Model>) names += (names.empty() ? "" : ", ") + std::string(Model::name);
  };
  [&]<class... Models>(type_list<Models...>) { (add(std::type_identity<Models>{}), ...); }(all_models{});
  return names;
}

template <Scalar T>
motion_outcome run_motion(const scene_input& scene, const motion_options& o) {
  if constexpr (!scalar_built<T>) throw input_error(left_out_scalar_message("--scalar", scalar_traits<T>::name));
  else return with_moving_model<motion_outcome>(
      scene, o.command, [&]<class Model>(std::type_identity<Model>) { return run_model_motion<Model, T>(scene, o); },
      all_models{});
}

template <Scalar T>
horizon_track run_horizon_track(const scene_input& scene, const std::string& t_end, const std::string& every, bool quiet,
                                const track_settings& settings) {
  if constexpr (!scalar_built<T>) throw input_error(left_out_scalar_message("--scalars", scalar_traits<T>::name));
  else return with_moving_model<horizon_track>(
      scene, "horizon",
      [&]<class Model>(std::type_identity<Model>) {
        return run_model_horizon_track<Model, T>(scene, t_end, every, quiet, settings);
      },
      all_models{});
}

std::vector<std::string> motion_state_fields(const scene_input& scene) {
  return with_moving_model<std::vector<std::string>>(
      scene, "--trajectory",
      [&]<class Model>(std::type_identity<Model>) {
        return model_motion<Model>::state_fields(scene.as<typename Model::input>());
      },
      all_models{});
}

std::optional<motion_closed_form> motion_closed_form_of(const scene_input& scene) {
  return with_moving_model<std::optional<motion_closed_form>>(
      scene, "horizon",
      [&]<class Model>(std::type_identity<Model>) -> std::optional<motion_closed_form> {
        if constexpr (requires { model_motion<Model>::closed_form(scene.as<typename Model::input>()); })
          return model_motion<Model>::closed_form(scene.as<typename Model::input>());
        else
          return std::nullopt;
      },
      all_models{});
}

#define APPELL_DETAIL_DISPATCH(ctx, T, name)                                                   \
  template motion_outcome run_motion<T>(const scene_input&, const motion_options&);           \
  template horizon_track run_horizon_track<T>(const scene_input&, const std::string&, const std::string&, bool, \
                                              const track_settings&);
APPELL_STANDARD_SCALARS(APPELL_DETAIL_DISPATCH, )

}  // namespace appell::cli
