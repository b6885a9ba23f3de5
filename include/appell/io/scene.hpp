// appell/io/scene.hpp -- scene files (../shared/SCENES.md) and their evaluation.
//
// read_scene() validates a scene once, on the exact decimals, independently of
// the scalar (so "A + B >= C" is decided exactly, not after rounding).
// evaluate<T>() then runs the model in scalar T; format_json<T>() prints it.
// evaluate/format are instantiated once per standard scalar in src/instantiate/.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "appell/io/json.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/scenes/euler_body.hpp"
#include "appell/scenes/top_on_cone.hpp"
#include "appell/scenes/rolling_sphere.hpp"
#include <optional>
#include "appell/dynamics/virtual_work.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include <memory>

namespace appell {

struct euler_body_input {
  std::vector<decimal_field> inertia;  // A, B, C
  std::vector<decimal_field> torque;   // L, M, N
  std::vector<decimal_field> omega;    // p, q, r
};

struct top_on_cone_input {
  decimal_field A, C, mass, l, gravity;
  std::string cone_text;
  std::shared_ptr<const expression> f, fprime, fsecond;  ///< f, f', f'' (symbolic)
  decimal_field theta, phi, theta_dot, phi_dot;
};

struct rolling_sphere_input {
  decimal_field mass, radius;
  std::optional<decimal_field> A;  ///< default 2/5 M a^2 (enclosed exactly)
  surface_type surface = surface_type::plane;
  bool inside = false;
  std::optional<decimal_field> b;  ///< the surface's radius (sphere, cylinder)
  std::vector<decimal_field> gravity, force, torque, center, omega;
};

struct scene_input {
  std::string model;
  std::variant<euler_body_input, top_on_cone_input, rolling_sphere_input> input;
};

/// Validates a parsed scene; throws input_error naming the field.
scene_input read_scene(const json_value& root);
/// Reads and validates a scene file; throws input_error.
scene_input read_scene_file(const std::string& path);

template <Scalar T>
struct named_result {
  std::string name;
  std::vector<T> values;
  bool is_vector = false;
};

template <Scalar T>
struct evaluation {
  std::vector<named_result<T>> results;
  std::vector<named_result<T>> checks;
  const named_result<T>& result(const std::string& name) const {
    for (const auto& r : results)
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

template <Scalar T>
evaluation<T> evaluate_model(const euler_body_input& in) {
  const euler_system<T> sys{{vec3_from_decimals<T>(in.inertia), vec3_from_decimals<T>(in.torque)}};
  const vec3<T> omega = vec3_from_decimals<T>(in.omega);
  const vector_t<T> q = vector_t<T>::Zero(3), u = omega;
  const appell_equations<T> eq = gibbs_appell(sys, q, u, T(0));
  const vector_t<T> udot = eq.accelerations();
  const vec3<T> omega_dot(udot(0), udot(1), udot(2));
  evaluation<T> e;
  e.results.push_back(vector_result("omega_dot", omega_dot));
  e.checks.push_back(scalar_result("virtual_work_invariant",
                                   virtual_work_residual(sys, eq, q, u, T(0), udot, vector_t<T>(vector_t<T>::Ones(3)))));
  e.checks.push_back(scalar_result("power_balance", euler_power_residual(sys.body, omega, omega_dot)));
  return e;
}
template <Scalar T>
evaluation<T> evaluate_model(const top_on_cone_input& in) {
  const heavy_top<T> top{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)};
  const T theta = value<T>(in.theta), phi = value<T>(in.phi);
  const T theta_dot = value<T>(in.theta_dot), phi_dot = value<T>(in.phi_dot);
  const T t = T(0);
  const T f = in.f->eval(theta), fp = in.fprime->eval(theta), fpp = in.fsecond->eval(theta);
  vector_t<T> q(3);
  q << f, theta, phi;
  // Cotton (sec. 6): speeds (theta', phi', psi_1'), the cone is psi_1' = 0.
  const auto sys = change_speeds(top, cone_speeds<T>{in.fprime.get()}, 3);
  vector_t<T> v_a(2);
  v_a << theta_dot, phi_dot;
  const cotton_result<T> c = cotton_reactions(sys, q, v_a, t, 1);
  const T theta_ddot = c.free_accelerations(0), phi_ddot = c.free_accelerations(1);
  const T H = c.reactions(0);
  const T psi_ddot = fpp * theta_dot * theta_dot + fp * theta_ddot;  // d/dt (f'(theta) theta')
  // The couple: J_w^T Gamma = (0, 0, H) in Cotton's speeds (wrench.hpp).
  vector_t<T> v(3), vdot(3), generalized(3);
  v << theta_dot, phi_dot, T(0);
  vdot << theta_ddot, phi_ddot, T(0);
  generalized << T(0), T(0), H;
  const auto kin = differentiate_kinematics(sys, q, v, t);
  const vec3<T> couple = constraint_couple(kin[0], generalized);
  // Checks: eq. (4) and Lagrange's multiplier on the unconstrained top.
  vector_t<T> ones = vector_t<T>::Ones(3);
  const T vw = virtual_work_residual(sys, c.equations, q, v, t, vdot, ones);
  vector_t<T> u(3);
  u << fp * theta_dot, theta_dot, phi_dot;
  const constrained_motion<T> lag = lagrange_multipliers(top, cone_constraint<T>{in.fprime.get()}, q, u, t);
  evaluation<T> e;
  e.results.push_back(scalar_result("theta_ddot", theta_ddot));
  e.results.push_back(scalar_result("phi_ddot", phi_ddot));
  e.results.push_back(scalar_result("psi_ddot", psi_ddot));
  e.results.push_back(scalar_result("H", H));
  e.results.push_back(vector_result("couple", couple));
  e.checks.push_back(scalar_result("virtual_work_invariant", vw));
  e.checks.push_back(scalar_result("cotton_minus_lagrange", T(H - lag.reactions(0))));
  e.checks.push_back(scalar_result("theta_ddot_cotton_minus_lagrange", T(theta_ddot - lag.accelerations(1))));
  return e;
}
template <Scalar T>
evaluation<T> evaluate_model(const rolling_sphere_input& in) {
  using std::sqrt, std::abs;
  const T M = value<T>(in.mass), a = value<T>(in.radius);
  const T A = in.A ? value<T>(*in.A) : rational<T>(2, 5) * M * a * a;
  rolling_surface<T> surface;
  surface.type = in.surface;
  surface.inside = in.inside;
  if (in.b) surface.b = value<T>(*in.b);
  const vec3<T> c = vec3_from_decimals<T>(in.center), omega = vec3_from_decimals<T>(in.omega);
  const vec3<T> F = vec3_from_decimals<T>(in.gravity) * M + vec3_from_decimals<T>(in.force);
  const vec3<T> tau = vec3_from_decimals<T>(in.torque);
  // The state must lie on the constraints: centre on the surface of centres, omega . n = 0.
  T on_surface, no_pivot, scale_c, scale_w = sqrt(dot(omega, omega));
  if (in.surface == surface_type::plane) {
    on_surface = c(2) - a;
    no_pivot = omega(2);
    scale_c = abs(c(2)) + a;
  } else {
    const vec3<T> radial = in.surface == surface_type::sphere ? c : vec3<T>(c(0), c(1), T(0));
    const T norm = sqrt(dot(radial, radial));
    on_surface = norm - surface.rho(a);
    no_pivot = dot(omega, radial) / norm;
    scale_c = norm + abs(surface.rho(a));
  }
  auto admissible = [](const T& residual, const T& scale) {
    if constexpr (scalar_traits<T>::is_interval) {
      (void)scale;
      return possibly_zero(residual);
    } else {
      const T eps = T(std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits())));
      return abs(residual) <= T(64) * eps * scale;
    }
  };
  if (!admissible(on_surface, scale_c))
    throw input_error("state.center: not on the surface of centres (residual " + to_string(on_surface) + ")");
  if (!admissible(no_pivot, scale_w))
    throw input_error("state.omega: omega . n must be 0 (no pivoting), residual " + to_string(no_pivot));
  const rolling_sphere_result<T> r = rolling_sphere_motion(M, A, a, surface, c, omega, F, tau);
  if (!certainly_positive(r.normal_force) && !certainly_negative(r.normal_force))
    throw certification_error("friction_ratio: the normal force " + to_string(r.normal_force) +
                              " cannot be told from 0");
  evaluation<T> e;
  e.results.push_back(vector_result("center_ddot", r.center_ddot));
  e.results.push_back(vector_result("omega_dot", r.omega_dot));
  e.results.push_back(vector_result("contact_force", r.contact_force));
  e.results.push_back(scalar_result("normal_force", r.normal_force));
  e.results.push_back(scalar_result("tangential_force", r.tangential_force()));
  e.results.push_back(scalar_result("pivot_couple", r.pivot_couple));
  e.results.push_back(scalar_result("friction_ratio", T(r.tangential_force() / r.normal_force)));
  e.checks.push_back(scalar_result("virtual_work_invariant", r.virtual_work_residual));
  e.checks.push_back(scalar_result("normal_force_cotton_minus_lagrange", T(r.reactions(2) - r.multipliers(2))));
  e.checks.push_back(scalar_result("pivot_couple_cotton_minus_lagrange", T(r.reactions(3) - r.multipliers(3))));
  e.checks.push_back(scalar_result("surface_residual", on_surface));
  e.checks.push_back(scalar_result("pivot_residual", no_pivot));
  return e;
}
}  // namespace detail

/// The scene's results in scalar T (mpfr/mpfi at the current mp precision).
template <Scalar T>
evaluation<T> evaluate(const scene_input& scene) {
  return std::visit([](const auto& in) { return detail::evaluate_model<T>(in); }, scene.input);
}

/// The `appell eval` JSON document (SCENES.md).
template <Scalar T>
std::string format_json(const scene_input& scene, const evaluation<T>& e) {
  auto number = [](const T& x) {
    if constexpr (scalar_traits<T>::is_interval)
      return "{\"lo\": \"" + lower_string(x) + "\", \"hi\": \"" + upper_string(x) + "\"}";
    else
      return "{\"value\": \"" + to_string(x) + "\"}";
  };
  auto group = [&](const std::vector<named_result<T>>& items) {
    std::string s = "{";
    for (std::size_t i = 0; i < items.size(); ++i) {
      s += (i ? ",\n    \"" : "\n    \"") + items[i].name + "\": ";
      if (items[i].is_vector) {
        s += "[";
        for (std::size_t j = 0; j < items[i].values.size(); ++j) s += (j ? ", " : "") + number(items[i].values[j]);
        s += "]";
      } else {
        s += number(items[i].values[0]);
      }
    }
    return s + "}";
  };
  return "{\"model\": \"" + scene.model + "\", \"scalar\": \"" + scalar_traits<T>::name +
         "\", \"bits\": " + std::to_string(scalar_traits<T>::precision_bits()) +
         ", \"rigorous\": " + (scalar_traits<T>::is_rigorous ? "true" : "false") +
         ",\n  \"results\": " + group(e.results) + ",\n  \"checks\": " + group(e.checks) + "}\n";
}

/// A human-readable rendering of the same numbers.
template <Scalar T>
std::string format_text(const scene_input& scene, const evaluation<T>& e) {
  std::string s = scene.model + " in " + scalar_traits<T>::name + " (" +
                  std::to_string(scalar_traits<T>::precision_bits()) + " bits, " +
                  (scalar_traits<T>::is_rigorous ? "rigorous enclosures" : "point values") + ")\n";
  auto lines = [&](const std::vector<named_result<T>>& items, const char* heading) {
    s += heading;
    for (const auto& r : items)
      for (std::size_t j = 0; j < r.values.size(); ++j)
        s += "  " + r.name + (r.is_vector ? "[" + std::to_string(j) + "]" : "") + " = " +
             to_string(r.values[j]) + "\n";
  };
  lines(e.results, "results:\n");
  lines(e.checks, "checks (0 if consistent):\n");
  return s;
}

// Instantiated once per standard scalar in src/instantiate/*.cpp.
#define APPELL_EXTERN_SCENE(T)                                                         \
  extern template evaluation<T> evaluate<T>(const scene_input&);                       \
  extern template std::string format_json<T>(const scene_input&, const evaluation<T>&); \
  extern template std::string format_text<T>(const scene_input&, const evaluation<T>&);
APPELL_EXTERN_SCENE(double)
APPELL_EXTERN_SCENE(long double)
APPELL_EXTERN_SCENE(dd)
APPELL_EXTERN_SCENE(float128)
APPELL_EXTERN_SCENE(mpfr)
APPELL_EXTERN_SCENE(interval)
APPELL_EXTERN_SCENE(mpfi)
#undef APPELL_EXTERN_SCENE

}  // namespace appell
