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
struct bound_euler_body {
  euler_system<T> sys;
  vec3<T> omega;
};
template <Scalar T>
bound_euler_body<T> bind_model(const euler_body_input& in) {
  return {{{vec3_from_decimals<T>(in.inertia), vec3_from_decimals<T>(in.torque)}}, vec3_from_decimals<T>(in.omega)};
}
template <Scalar T>
evaluation<T> compute_model(const bound_euler_body<T>& m) {
  const vector_t<T> q = vector_t<T>::Zero(3), u = m.omega;
  const appell_equations<T> eq = gibbs_appell(m.sys, q, u, T(0));
  const vector_t<T> udot = eq.accelerations();
  const vec3<T> omega_dot(udot(0), udot(1), udot(2));
  evaluation<T> e;
  e.results.push_back(vector_result("omega_dot", omega_dot));
  e.checks.push_back(scalar_result("virtual_work_invariant",
                                   virtual_work_residual(m.sys, eq, q, u, T(0), udot, vector_t<T>(vector_t<T>::Ones(3)))));
  e.checks.push_back(scalar_result("power_balance", euler_power_residual(m.sys.body, m.omega, omega_dot)));
  return e;
}

template <Scalar T>
struct bound_top_on_cone {
  heavy_top<T> top;
  T theta, phi, theta_dot, phi_dot;
  bound_expression<T> f, fprime, fsecond;
};
template <Scalar T>
bound_top_on_cone<T> bind_model(const top_on_cone_input& in) {
  return {{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)},
          value<T>(in.theta), value<T>(in.phi), value<T>(in.theta_dot), value<T>(in.phi_dot),
          bound_expression<T>(*in.f), bound_expression<T>(*in.fprime), bound_expression<T>(*in.fsecond)};
}
template <Scalar T>
evaluation<T> compute_model(const bound_top_on_cone<T>& m) {
  const T t = T(0);
  const T f = m.f.eval(m.theta), fp = m.fprime.eval(m.theta), fpp = m.fsecond.eval(m.theta);
  vector_t<T> q(3);
  q << f, m.theta, m.phi;
  // Cotton (sec. 6): speeds (theta', phi', psi_1'), the cone is psi_1' = 0.  The top is
  // described on Resal's trihedron (tight enclosures, top_on_cone.hpp); the Lagrange
  // check below uses the fixed-axis description, an independent route.
  const heavy_top_resal<T> resal{m.top.A, m.top.C, m.top.mass, m.top.l, m.top.g};
  const auto sys = change_speeds(resal, cone_speeds<T>{&m.fprime}, 3);
  vector_t<T> v_a(2);
  v_a << m.theta_dot, m.phi_dot;
  const cotton_result<T> c = cotton_reactions(sys, q, v_a, t, 1);
  const T theta_ddot = c.free_accelerations(0), phi_ddot = c.free_accelerations(1);
  const T H = c.reactions(0);
  const T psi_ddot = fpp * m.theta_dot * m.theta_dot + fp * theta_ddot;  // d/dt (f'(theta) theta')
  // The couple: J_w^T Gamma = (0, 0, H) in Cotton's speeds (wrench.hpp).
  vector_t<T> v(3), vdot(3), generalized(3);
  v << m.theta_dot, m.phi_dot, T(0);
  vdot << theta_ddot, phi_ddot, T(0);
  generalized << T(0), T(0), T(1);  // the couple is linear in H: solve for H = 1, scale once (H enters one product, not a cancellation)
  const auto kin = differentiate_kinematics(sys, q, v, t);
  const vec3<T> couple = mat_vec(heavy_top_resal<T>::axes(q), constraint_couple(kin[0], generalized)) * H;  // fixed axes
  // Checks: eq. (4) and Lagrange's multiplier on the unconstrained top.
  const vector_t<T> ones = vector_t<T>::Ones(3);
  const T vw = virtual_work_residual(sys, c.equations, q, v, t, vdot, ones);
  vector_t<T> u(3);
  u << fp * m.theta_dot, m.theta_dot, m.phi_dot;
  const constrained_motion<T> lag = lagrange_multipliers(m.top, cone_constraint<T>{&m.fprime}, q, u, t);
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
struct bound_rolling_sphere {
  T M, A, a;
  rolling_surface<T> surface;
  vec3<T> c, omega, F, tau;
  T on_surface, no_pivot;  ///< the constraint residuals at the state
};
template <Scalar T>
bound_rolling_sphere<T> bind_model(const rolling_sphere_input& in) {
  using std::sqrt, std::abs;
  bound_rolling_sphere<T> m;
  m.M = value<T>(in.mass);
  m.a = value<T>(in.radius);
  m.A = in.A ? value<T>(*in.A) : rational<T>(2, 5) * m.M * m.a * m.a;
  m.surface.type = in.surface;
  m.surface.inside = in.inside;
  if (in.b) m.surface.b = value<T>(*in.b);
  m.c = vec3_from_decimals<T>(in.center);
  m.omega = vec3_from_decimals<T>(in.omega);
  m.F = vec3_from_decimals<T>(in.gravity) * m.M + vec3_from_decimals<T>(in.force);
  m.tau = vec3_from_decimals<T>(in.torque);
  // The state must lie on the constraints: centre on the surface of centres, omega . n = 0.
  T scale_c, scale_w = sqrt(dot(m.omega, m.omega));
  if (in.surface == surface_type::plane) {
    m.on_surface = m.c(2) - m.a;
    m.no_pivot = m.omega(2);
    scale_c = abs(m.c(2)) + m.a;
  } else {
    const vec3<T> radial = in.surface == surface_type::sphere ? m.c : vec3<T>(m.c(0), m.c(1), T(0));
    const T norm = sqrt(dot(radial, radial));
    m.on_surface = norm - m.surface.rho(m.a);
    m.no_pivot = dot(m.omega, radial) / norm;
    scale_c = norm + m.surface.b + m.a;  // rho = b -+ a may cancel: its error scales with b and a
  }
  auto admissible = [](const T& residual, const T& scale) {
    if constexpr (scalar_traits<T>::is_interval) {
      (void)scale;
      return possibly_zero(residual);
    } else {
      const T eps = pown(T(2), 1 - static_cast<int>(scalar_traits<T>::precision_bits()));  // no double underflow at 2048 bits
      return abs(residual) <= T(64) * eps * scale;
    }
  };
  if (!admissible(m.on_surface, scale_c))
    throw input_error("state.center: not on the surface of centres (residual " + to_string(m.on_surface) + ")");
  if (!admissible(m.no_pivot, scale_w))
    throw input_error("state.omega: omega . n must be 0 (no pivoting), residual " + to_string(m.no_pivot));
  return m;
}
template <Scalar T>
evaluation<T> compute_model(const bound_rolling_sphere<T>& m) {
  const rolling_sphere_result<T> r = rolling_sphere_motion(m.M, m.A, m.a, m.surface, m.c, m.omega, m.F, m.tau);
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
  e.checks.push_back(scalar_result("surface_residual", m.on_surface));
  e.checks.push_back(scalar_result("pivot_residual", m.no_pivot));
  return e;
}
}  // namespace detail

/// A scene's inputs converted to T and checked (decimal conversions happen here, once).
template <Scalar T>
using bound_scene = std::variant<detail::bound_euler_body<T>, detail::bound_top_on_cone<T>,
                                 detail::bound_rolling_sphere<T>>;

/// mpfi works with guard bits inside (inputs enclosed and dynamics computed at
/// a higher precision, results rounded outward to p bits at the end): the
/// dependency effects of naive interval evaluation, which magnify the input
/// enclosures' width by up to ~10^3 on the paper scenes, are paid in the guard
/// bits.  At least 12 of them, and the rest of the last 64-bit limb, which costs
/// nothing (MPFR works limb by limb): 114 bits work at 128, 257 at 320.
inline unsigned mpfi_working_bits(unsigned bits) {
  constexpr unsigned least_guard = 12;
  return mp_precision_filling_limbs(bits + least_guard);
}

template <Scalar T>
bound_scene<T> bind(const scene_input& scene) {
  std::optional<mp_precision_scope> guard;
  if constexpr (std::is_same_v<T, mpfi>) guard.emplace(mpfi_working_bits(mp_precision_bits()));
  return std::visit([](const auto& in) { return bound_scene<T>(detail::bind_model<T>(in)); }, scene.input);
}

/// The dynamics of a bound scene.  Interval evaluations run in one upward-rounding scope.
template <Scalar T>
evaluation<T> compute(const bound_scene<T>& scene) {
  if constexpr (std::is_same_v<T, interval>) {
    forget_interval_function_values();
    const upward_rounding mode;
    evaluation<T> e = std::visit([](const auto& m) { return detail::compute_model<T>(m); }, scene);
    if (!mode.intact())  // the operations assumed upward rounding (interval.hpp): refuse, never return an unproved box
      throw certification_error("the rounding mode was changed during the interval evaluation");
    return e;
  } else if constexpr (std::is_same_v<T, mpfi>) {
    // Guard bits (see bind): compute at mpfi_working_bits(p), round the results outward to p.
    const unsigned bits = mp_precision_bits();
    evaluation<T> e;
    {
      const mp_precision_scope guard(mpfi_working_bits(bits));
      e = std::visit([](const auto& m) { return detail::compute_model<T>(m); }, scene);
    }
    for (auto* group : {&e.results, &e.checks})
      for (auto& r : *group)
        for (auto& x : r.values) x.backend().round_prec(static_cast<mpfr_prec_t>(bits));
    return e;
  } else {
    return std::visit([](const auto& m) { return detail::compute_model<T>(m); }, scene);
  }
}

/// How much the scene amplifies rounding errors, measured: the largest relative
/// width of the results of an interval<double> evaluation, divided by 2^-53
/// (infinity where that evaluation cannot certify).  Point types carry it in
/// "checks" as `error_amplification`: their relative error is expected below
/// error_amplification * 2^(1 - precision) (tests/extremes.cpp holds them to 16x that).
double error_amplification(const scene_input& scene);

/// The scene's results in scalar T (mpfr/mpfi at the current mp precision).
template <Scalar T>
evaluation<T> evaluate(const scene_input& scene) {
  evaluation<T> e = compute<T>(bind<T>(scene));
  if constexpr (!scalar_traits<T>::is_interval) {
    const double a = error_amplification(scene);
    e.checks.push_back(detail::scalar_result("error_amplification", T(a)));
  }
  return e;
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
  extern template bound_scene<T> bind<T>(const scene_input&);                          \
  extern template evaluation<T> compute<T>(const bound_scene<T>&);                     \
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
