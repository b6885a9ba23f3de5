// appell/motion/registry.hpp -- the motion of a model added while a program starts (a model of a
// user's own or the tests', io/model_registry.hpp): its runs in every built scalar, compiled beside
// the program by CMake's appell_add_models with the model's other units, and registered before
// main.  simulate, enclose, validity, track, state_fields and closed_form_of then move its scenes
// as they move a built-in model's, which the motion library knows at compile time (appell_models.hpp).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "appell/motion/engine.hpp"

namespace appell::motion {

inline constexpr std::size_t standard_scalar_count = std::tuple_size_v<per_standard_scalar<std::type_identity_t>>;

/// A registered model's motion: what motion.cpp calls for a model it was not compiled with.
struct registered_motion {
  using run_fn = void (*)(const scene_input&, const run_request&);
  using track_fn = horizon_track (*)(const scene_input&, const std::string&, const std::string&, const track_settings&,
                                     const std::function<void(double)>&);
  std::string module;                                ///< the model's name (model_entry::module)
  std::array<run_fn, standard_scalar_count> run{};   ///< per standard scalar; null: left out of the build
  std::array<track_fn, standard_scalar_count> track{};
  std::vector<std::string> (*state_fields)(const scene_input&) = nullptr;
  std::optional<motion_closed_form> (*closed_form)(const scene_input&) = nullptr;
};

/// Adds a model's motion (before main, from one thread: the generated registration does);
/// std::logic_error if a model of that name moves already.
void register_motion(registered_motion m);
/// The registered motion of the model `module`, or null.
const registered_motion* find_registered_motion(const std::string& module);

namespace detail {
template <class Model>
std::vector<std::string> registered_state_fields(const scene_input& scene) {
  return model_motion<Model>::state_fields(scene.as<typename Model::input>());
}
template <class Model>
std::optional<motion_closed_form> registered_closed_form(const scene_input& scene) {
  if constexpr (requires { model_motion<Model>::closed_form(scene.as<typename Model::input>()); })
    return model_motion<Model>::closed_form(scene.as<typename Model::input>());
  else
    return std::nullopt;
}
}  // namespace detail

/// Model's motion as registered: the addresses of its runs in the built scalars (instantiated in
/// the model's generated units; declare them extern where this is called, APPELL_DETAIL_EXTERN_RUN).
template <class Model>
registered_motion registered_motion_of() {
  registered_motion m;
  m.module = Model::name;
  [&]<class... Ts>(type_list<Ts...>) {
    auto add = [&]<class T>(std::type_identity<T>) {
      if constexpr (scalar_built<T>) {
        m.run[standard_scalar_index<T>] = &run_model<Model, T>;
        m.track[standard_scalar_index<T>] = &run_model_track<Model, T>;
      }
    };
    (add(std::type_identity<Ts>{}), ...);
  }(standard_scalars{});
  m.state_fields = &detail::registered_state_fields<Model>;
  m.closed_form = &detail::registered_closed_form<Model>;
  return m;
}

}  // namespace appell::motion
