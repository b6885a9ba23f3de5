// appell/io/model_motion.hpp -- whether and how a scene model moves.
//
// A model module that moves specialises model_motion<Model> beside its header
// (io/models/<name>_motion.hpp), with
//     static constexpr bool moves = true;
//     template <Scalar T> static std::pair<Problem, vector_t<T>> start(const Model::prepared<T>&);
//         // the motion as an ODE x' = f(x) (ode/problems.hpp: dim, state_names(), rhs, results,
//         // invariants) and its initial state
//     static std::vector<std::string> state_fields(const Model::input&);
//         // the scene's state fields, in the order of the motion's state (reference --trajectory)
// and, where the model knows its motion in closed form for some scenes (horizon's truth),
//     static std::optional<motion_closed_form> closed_form(const Model::input&);
// The commands that move a scene (simulate, enclose, horizon, reference
// --trajectory) find the model here, through the list CMake generates from
// APPELL_MODELS (appell_models.hpp in the build tree); a model without a
// specialisation does not move, and `appell --help` says so.
#pragma once

#include <boost/multiprecision/mpfr.hpp>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace appell {

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
