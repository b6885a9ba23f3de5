// appell/io/models/rolling_sphere.hpp -- the scene model "rolling_sphere"
// (paper sec. 7, Example II).  Schema (SCENES.md): sphere {mass, radius, A?},
// surface {type: plane | sphere | cylinder, radius, side}, gravity, force?,
// torque?, state {center, omega}; the state must lie on the constraints.
#pragma once

#include <optional>

#include "appell/io/model.hpp"
#include "appell/scenes/rolling_sphere.hpp"

namespace appell {

struct rolling_sphere_input : model_input {
  decimal_field mass, radius;
  std::optional<decimal_field> A;  ///< default 2/5 M a^2 (enclosed exactly)
  surface_type surface = surface_type::plane;
  bool inside = false;
  std::optional<decimal_field> b;  ///< the surface's radius (sphere, cylinder)
  std::vector<decimal_field> gravity, force, torque, center, omega;
  /// "project": accept a state off the constraints by at most this (length for the centre,
  /// rad/s for omega . n) and use its projection onto them, enclosed in the scalar's arithmetic.
  std::optional<decimal_field> project;
  /// "contact": the contact with the surface judged (SCENES.md); mu as written ("" for none).
  bool contact = false;
  std::string mu;
};

struct rolling_sphere_model {
  static constexpr const char* name = "rolling_sphere";
  using input = rolling_sphere_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    T M, A, a;
    rolling_surface<T> surface;
    vec3<T> c, omega, F, tau;
    T on_surface, no_pivot;  ///< the constraint residuals at the state
    bool projected = false;
    T center_moved = T(0), omega_moved = T(0);  ///< the projection's steps along n (when projected)
    bool contact = false;  ///< the contact "surface" judged, with mu as written ("" for none)
    std::string mu;
    bool A_from_radius = false;  ///< A not given: 2/5 M a^2 (validity's --vary sphere.radius keeps it so)
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    using std::sqrt, std::abs;
    prepared<T> m;
    m.M = value<T>(in.mass);
    m.a = value<T>(in.radius);
    m.A = in.A ? value<T>(*in.A) : rational<T>(2, 5) * m.M * m.a * m.a;
    m.A_from_radius = !in.A;
    m.surface.type = in.surface;
    m.surface.inside = in.inside;
    if (in.b) m.surface.b = value<T>(*in.b);
    m.c = detail::vec3_from_decimals<T>(in.center);
    m.omega = detail::vec3_from_decimals<T>(in.omega);
    m.F = detail::vec3_from_decimals<T>(in.gravity) * m.M + detail::vec3_from_decimals<T>(in.force);
    m.tau = detail::vec3_from_decimals<T>(in.torque);
    m.contact = in.contact;
    m.mu = in.mu;
    // The state must lie on the constraints: centre on the surface of centres, omega . n = 0.
    T scale_c, scale_w;
    auto residuals = [&] {
      scale_w = sqrt(dot(m.omega, m.omega));
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
    };
    residuals();
    if (in.project) {
      // At most `project` off, then the nearest state on the constraints: the centre moved along
      // the surface of centres' normal, omega's normal component removed (enclosed in T).
      const T tol = value<T>(*in.project);
      if (certainly_positive(T(abs(m.on_surface) - tol)))
        throw input_error("state.center: off the surface of centres by " + to_string(m.on_surface) +
                          ", more than project = " + in.project->text);
      if (certainly_positive(T(abs(m.no_pivot) - tol)))
        throw input_error("state.omega: omega . n = " + to_string(m.no_pivot) + ", more than project = " +
                          in.project->text);
      m.projected = true;
      m.center_moved = -m.on_surface;
      m.omega_moved = -m.no_pivot;
      if (in.surface == surface_type::plane) {
        m.c(2) = m.a;
        m.omega(2) = T(0);
      } else {
        const vec3<T> radial = in.surface == surface_type::sphere ? m.c : vec3<T>(m.c(0), m.c(1), T(0));
        const T norm2 = dot(radial, radial), factor = m.surface.rho(m.a) / sqrt(norm2);
        const T along = dot(m.omega, radial) / norm2;
        for (int i = 0; i < (in.surface == surface_type::sphere ? 3 : 2); ++i) m.c(i) = radial(i) * factor;
        m.omega = vec3<T>(m.omega - radial * along);
      }
      residuals();
    }
    if (!consistent_with_zero(m.on_surface, scale_c))
      throw input_error("state.center: not on the surface of centres (residual " + to_string(m.on_surface) + ")");
    if (!consistent_with_zero(m.no_pivot, scale_w))
      throw input_error("state.omega: omega . n must be 0 (no pivoting), residual " + to_string(m.no_pivot));
    return m;
  }
  /// with_checks::no: no Lagrange multipliers and no eq. (4) (rolling_sphere_motion's `checks`).
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks checks) {
    struct site;
    const scratch<rolling_sphere_result<T>, site> r_held;  // borrowed (linalg/scratch.hpp)
    const rolling_sphere_result<T>& r = *r_held;
    rolling_sphere_motion_into(m.M, m.A, m.a, m.surface, m.c, m.omega, m.F, m.tau, checks == with_checks::yes, true,
                               *r_held);
    // With a contact judged, its verdict says whether the normal force is positive, and the
    // contacts group gives the friction coefficient it requires in friction_ratio's stead.
    if (!m.contact && !certainly_positive(r.normal_force) && !certainly_negative(r.normal_force))
      throw certification_error("friction_ratio: the normal force " + to_string(r.normal_force) +
                                " cannot be told from 0");
    using W = evaluation_writer<T>;
    W out(e);
    out.vector(W::results, "center_ddot", "", r.center_ddot);
    out.vector(W::results, "omega_dot", "", r.omega_dot);
    out.vector(W::results, "contact_force", "", r.contact_force);
    out.scalar(W::results, "normal_force", "", r.normal_force);
    out.scalar(W::results, "tangential_force", "", r.tangential_force());
    out.scalar(W::results, "pivot_couple", "", r.pivot_couple);
    if (!m.contact) {
      out.scalar(W::results, "friction_ratio", "", T(r.tangential_force() / r.normal_force));
    } else {  // the contact's results as every model names them (SCENES.md "contacts")
      const T tangential = r.tangential_force();
      out.scalar(W::results, "surface_normal_force", "", r.normal_force);
      out.vector(W::results, "surface_friction_force", "", r.friction_force());
      out.scalar(W::results, "surface_tangential_force", "", tangential);
      out.contacts().push_back(judged_contact("surface", r.normal_force, tangential, m.mu));
    }
    if (checks == with_checks::yes) {
      out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
      out.scalar(W::checks, "normal_force_cotton_minus_lagrange", "", T(r.reactions(2) - r.multipliers(2)));
      out.scalar(W::checks, "pivot_couple_cotton_minus_lagrange", "", T(r.reactions(3) - r.multipliers(3)));
      out.scalar(W::checks, "surface_residual", "", m.on_surface);
      out.scalar(W::checks, "pivot_residual", "", m.no_pivot);
    }
    out.vector(W::derived, "contact_point", "", r.contact_point);
    out.vector(W::derived, "normal", "", r.normal);
    out.vector(W::derived, "center_velocity", "", r.center_velocity);
    if (m.projected) {
      out.vector(W::derived, "center", "", m.c);
      out.vector(W::derived, "omega", "", m.omega);
      out.scalar(W::derived, "center_moved", "", m.center_moved);
      out.scalar(W::derived, "omega_moved", "", m.omega_moved);
    }
    out.finish();
  }
};

APPELL_EXTERN_MODEL(rolling_sphere_model)

}  // namespace appell
