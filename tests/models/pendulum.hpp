// tests/models/pendulum.hpp -- the home of the scene model "pendulum", a model of the tests'
// own, built exactly as docs/architecture.md's "Adding a model" says a built-in model that moves
// is built: this header, its reader (pendulum.cpp) and one line of a CMake list (tests/
// CMakeLists.txt, APPELL_TEST_MODELS). CMake generates its units, one per scalar, and its
// registration (cmake/instantiate.cmake, appell_add_models); the suite model_walkthrough reads,
// evaluates and moves its scenes through the library's calls, as a user's own model would be.
//
// Schema: pendulum {mass, length} (positive), gravity, state {theta, theta_dot}: a point mass on
// a massless rod about a fixed pivot, theta from the downward vertical.  Its physics is Appell's
// equations on the generic path (tests/pendulum_problem.hpp's system: M = m l^2,
// Q = -m g l sin theta), the rod's tension from Newton's law along the rod as the check's other
// side: T = m (g cos theta + l theta'^2), which the generic path's Lagrange multiplier of the
// pivot gives too.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/scalar/decimal.hpp"
#include "pendulum_problem.hpp"

namespace appell {

/// The state of the motion as reported: each component's name in the outputs and the scene
/// field it starts from.
inline constexpr std::array<state_component, 2> pendulum_state_table{{
    {"theta", "theta"},
    {"theta_dot", "theta_dot"},
}};

struct pendulum_input : model_input {
  decimal_field mass, length, gravity, theta, theta_dot;
};

/// theta'' by Appell's equations (the generic path) and the rod's tension.
template <Scalar T>
struct pendulum_result {
  T theta_ddot, tension;
};

template <Scalar T>
pendulum_result<T> pendulum_motion(const T& mass, const T& length, const T& g, const T& theta, const T& theta_dot) {
  const typename ode::pendulum_problem<T>::system sys{mass, length, g, true};
  vector_t<T> q(1), u(1);
  q << theta;
  u << theta_dot;
  const T theta_ddot = gibbs_appell(sys, q, u, T(0)).accelerations()(0);
  using std::cos;
  return {theta_ddot, T(mass * (g * cos(theta) + length * theta_dot * theta_dot))};
}

struct pendulum_model {
  static constexpr const char* name = "pendulum";
  using input = pendulum_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    T mass, length, g, theta, theta_dot;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {value<T>(in.mass), value<T>(in.length), value<T>(in.gravity), value<T>(in.theta), value<T>(in.theta_dot)};
  }
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const pendulum_result<T> r = pendulum_motion(m.mass, m.length, m.g, m.theta, m.theta_dot);
    using W = evaluation_writer<T>;
    W out(e);
    out.scalar(W::results, "theta_ddot", "", r.theta_ddot);
    out.scalar(W::results, "tension", "", r.tension);
    using std::sin;  // Appell's theta'' against the textbook's -(g / l) sin theta
    out.scalar(W::checks, "theta_ddot_minus_textbook", "", T(r.theta_ddot + m.g / m.length * sin(m.theta)));
    out.finish();
  }
};

APPELL_EXTERN_MODEL(pendulum_model)

template <>
struct model_motion<pendulum_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::pendulum_problem<T>;
  template <Scalar T>
  static std::pair<ode::pendulum_problem<T>, vector_t<T>> start(const pendulum_model::prepared<T>& m) {
    vector_t<T> x0(2);
    x0 << m.theta, m.theta_dot;
    return {ode::pendulum_problem<T>{m.mass, m.length, m.g}, x0};
  }
  static std::vector<std::string> state_fields(const pendulum_input&) { return state_fields_of(pendulum_state_table); }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::pendulum_model)
