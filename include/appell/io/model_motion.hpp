// appell/io/model_motion.hpp -- whether and how a scene model moves.
//
// A model that moves specialises model_motion<Model> in its home (models/<name>.hpp), with
//     static constexpr bool moves = true;
//     template <Scalar T> using problem = ...;    // its motion as an ODE problem (below)
//     template <Scalar T> static std::pair<problem<T>, vector_t<T>> start(const Model::prepared<T>&);
//         // the problem and its initial state, packed in the order of the state table
//     static std::vector<std::string> state_fields(const Model::input&);
//         // the scene's state fields, in the order of the motion's state (reference --trajectory):
//         // state_fields_of(<name>_state_table) for a model with a fixed state table
// and ends its home with APPELL_EXTERN_MODEL_MOTION(Model): the problem's integrators are compiled
// once per scalar, with the model (cmake/instantiate.cmake).
//
// An ODE problem is the scene's own dynamics (the functions `appell eval` runs), called on
// whatever scalar the integrator needs: T for a point step, jet<T> for Taylor coefficients,
// multi_dual<jet<T>, dim> for their Jacobian (the wrapping control of ode/enclose.hpp).  No scene
// is implemented twice: a right-hand side only arranges the scene's state into x and calls it,
// and models only what the scene requires (Euler's body is omega alone, the rolling sphere its
// centre and omega: a homogeneous sphere's orientation is not needed).
//   dim, state_names()        the state x
//   rhs<S>(x)                 x'
//   results<S>(x, out)        the scene's results along the motion (accelerations, reactions)
//   invariants<S>(x, out)     first integrals: energy where it is conserved, momenta
//   check_state(x0)           refuses a state the scene refuses (exit 2 in the CLI)
// and, where the model knows its motion in closed form for some scenes (horizon's truth),
//     static std::optional<motion_closed_form> closed_form(const Model::input&);
// The commands that move a scene (simulate, enclose, horizon, reference
// --trajectory) find the model here, through the list CMake generates from
// APPELL_MODELS (appell_models.hpp in the build tree); a model without a
// specialisation does not move, and `appell --help` says so.
#pragma once

#include <array>
#include <boost/multiprecision/mpfr.hpp>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell {

/// One component of a moving model's state table: its name in the motion's outputs (the
/// columns of simulate and enclose, the state of reference --trajectory) and the scene field its
/// initial value comes from.
struct state_component {
  const char* name;
  const char* field;
};

/// The names of a state table's components, in order.
template <std::size_t N>
std::vector<std::string> state_names_of(const std::array<state_component, N>& table) {
  std::vector<std::string> v;
  for (const state_component& c : table) v.emplace_back(c.name);
  return v;
}

/// The scene fields of a state table's components, in order.
template <std::size_t N>
std::vector<std::string> state_fields_of(const std::array<state_component, N>& table) {
  std::vector<std::string> v;
  for (const state_component& c : table) v.emplace_back(c.field);
  return v;
}

/// A scene's motion in closed form, at 256 bits (`appell horizon`'s reference): the components
/// `compared` of the scene's state (in the order of its motion's reported state) at time t.
struct motion_closed_form {
  using value = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<256>,
                                              boost::multiprecision::et_off>;
  std::string kind;                   ///< what the reference is, for the study's summary
  std::vector<std::size_t> compared;  ///< the state's components it gives
  value period = 0;                   ///< 0 when the motion has none
  std::function<std::vector<value>(const value& t)> at;
};

template <class Model>
struct model_motion {
  static constexpr bool moves = false;
};

template <class Model>
concept moving_model = model_motion<Model>::moves;

}  // namespace appell

/// At the end of a moving model's home: its problem's integrators are compiled elsewhere, once per
/// standard scalar (the model's generated units, cmake/instantiate.cmake): taylor_series in every
/// scalar, simulate in the point scalars, the slopes and enclose in the interval scalars; a use
/// of the other kind's would not link (it does not compile either).
#define APPELL_DETAIL_EXTERN_MOTION_ITEM(Model, T, name)                                     \
  APPELL_ODE_EXTERN_SERIES(::appell::model_motion<Model>::problem<T>, T)                    \
  APPELL_ODE_EXTERN_SIMULATE(::appell::model_motion<Model>::problem<T>, T)                  \
  APPELL_ODE_EXTERN_ENCLOSE(::appell::model_motion<Model>::problem<T>, T)
#define APPELL_EXTERN_MODEL_MOTION(Model) \
  namespace appell::ode {                 \
  APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_MOTION_ITEM, Model)  \
  }
/// In a moving model's generated unit: its problem's integrators in scalar T (KIND: SIMULATE for
/// a point scalar, ENCLOSE for an interval one).
#define APPELL_DEFINE_MODEL_MOTION(Model, T, KIND)                          \
  namespace appell::ode {                                                   \
  APPELL_ODE_DEFINE_SERIES(::appell::model_motion<Model>::problem<T>, T)   \
  APPELL_ODE_DEFINE_##KIND(::appell::model_motion<Model>::problem<T>, T)   \
  }
