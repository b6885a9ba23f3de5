// appell/models/euler_body.hpp -- the home of the scene model "euler_body" (paper sec. 3).
// Schema (SCENES.md): inertia {A, B, C} (positive, triangle inequalities),
// torque [L, M, N] (default 0), state {omega: [p, q, r]}.
//
// It moves as omega = (p, q, r) on the principal axes, by Euler's equations
// (ode::euler_body_problem); without torque, some scenes in closed form (horizon's truth).
//
// Everything named after the model is here: its state table (the motion's state: each
// component's name in the outputs and the scene field it starts from), its motion as an ODE
// problem (right-hand side, results and invariants along the motion), its inputs, prepare and
// evaluation with its results' names, and model_motion (start, closed form).  Its reader and
// registry entry are in src/models/euler_body.cpp.
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
//
// The physics (paper sec. 3: Euler's equations).
// A rigid body turns about a fixed point that is its centre of mass; body
// axes are principal, with moments A, B, C; speeds p, q, r are the components
// of the angular velocity on those axes; L, M, N the applied torque.
// Appell's S = 1/2 (A p'^2 + B q'^2 + C r'^2) + (C - B) q r p' + (A - C) r p q'
//            + (B - A) p q r' + ..., and dS/dp' = L etc. give
//   A p' = (B - C) q r + L,   B q' = (C - A) r p + M,   C r' = (A - B) p q + N.
// euler_omega_dot() writes them directly (the reference of the tests);
// euler_system is the same body for the generic Gibbs-Appell path:
// components on the body axes, a frame turning with omega itself, speeds
// u = (p, q, r), parameters with lambda' = p, ... (sec. 3).
// euler_body_motion() is the result function `appell eval` calls: the generic
// path, and the checks eq. (4) and the power balance.
#pragma once

#include <array>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {

template <Scalar T>
struct euler_body {
  vec3<T> inertia;  ///< principal moments A, B, C
  vec3<T> torque;   ///< L, M, N on the body axes
};

/// (p', q', r') at angular velocity omega = (p, q, r).
template <Scalar T>
vec3<T> euler_omega_dot(const euler_body<T>& body, const vec3<T>& omega) {
  const T &A = body.inertia(0), &B = body.inertia(1), &C = body.inertia(2);
  const T &p = omega(0), &q = omega(1), &r = omega(2);
  return vec3<T>(((B - C) * q * r + body.torque(0)) / A,
                 ((C - A) * r * p + body.torque(1)) / B,
                 ((A - B) * p * q + body.torque(2)) / C);
}

/// The power balance dT/dt - omega . torque = omega . (I omega') - omega . torque,
/// which vanishes on every motion (the gyroscopic couple does no work): an
/// independent check of omega', 0 (point) or an interval holding 0.
template <Scalar T>
T euler_power_residual(const euler_body<T>& body, const vec3<T>& omega, const vec3<T>& omega_dot) {
  T residual = T(0);
  for (int i = 0; i < 3; ++i)
    residual += omega(i) * (body.inertia(i) * omega_dot(i) - body.torque(i));
  return residual;
}

/// Euler's body as a system for the generic path.
template <Scalar T>
struct euler_system {
  euler_body<T> body;
  static constexpr int max_speeds = 3;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;  // lambda' = p, mu' = q, nu' = r
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    qd = u;
  }
  template <class S>
  void bodies(const vector_t<S>&, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    body_state<S> b;  // mass irrelevant: G is fixed
    b.omega = vec3<S>(u(0), u(1), u(2));
    b.frame_rate = b.omega;  // the body axes turn with the body
    b.frame_is_body = true;
    for (int i = 0; i < 3; ++i) {
      b.inertia(i, i) = S(body.inertia(i));
      b.couple(i) = S(body.torque(i));
    }
    out.push_back(b);
  }
};

template <Scalar T>
struct euler_body_result {
  vec3<T> omega_dot;        ///< (p', q', r')
  T virtual_work_residual;  ///< eq. (4): 0 on the motion
  T power_residual;         ///< omega . (I omega') - omega . torque: 0 on the motion
};

/// Appell's equations of Euler's body at angular velocity omega (the generic path):
/// what `appell eval` solves, and what `appell simulate` / `enclose` run on jets.
template <Scalar T>
appell_equations<T> euler_body_equations(const euler_body<T>& body, const vec3<T>& omega) {
  return gibbs_appell(euler_system<T>{body}, vector_t<T>(vector_t<T>::Zero(3)), vector_t<T>(omega), T(0));
}

/// Euler's body through the generic Gibbs-Appell path at angular velocity omega.
template <Scalar T>
euler_body_result<T> euler_body_motion(const euler_body<T>& body, const vec3<T>& omega) {
  const euler_system<T> sys{body};
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q, u, udot, ones;
  const scratch<appell_equations<T>, site> eq;
  q->setZero(3);
  *u = omega;
  ones->setOnes(3);
  gibbs_appell_into(sys, *q, *u, T(0), *eq);  // euler_body_equations' equations
  eq->accelerations_into(*udot);
  euler_body_result<T> r;
  r.omega_dot = vec3<T>((*udot)(0), (*udot)(1), (*udot)(2));
  r.virtual_work_residual = virtual_work_residual(sys, *eq, *q, *u, T(0), *udot, *ones);
  r.power_residual = euler_power_residual(body, omega, r.omega_dot);
  return r;
}

/// euler_body_motion compiled with the model, once per standard scalar (io/model.hpp).
#define APPELL_MODEL_PHYSICS_euler_body(EXTERN, T) \
  EXTERN template euler_body_result<T> euler_body_motion<T>(const euler_body<T>&, const vec3<T>&);
APPELL_EXTERN_MODEL_PHYSICS(euler_body)

}  // namespace appell

namespace appell::ode {

/// Euler's free body with I1 < I2 < I3 and omega(0) = (a, 0, c) with M^2 > 2 E I2
/// (Landau & Lifshitz, Mechanics, sec. 37):
///   omega1 = a cn(tau, k), omega2 = b sn(tau, k), omega3 = c dn(tau, k), tau = rate t,
/// with 2E = I1 a^2 + I3 c^2, M^2 = I1^2 a^2 + I3^2 c^2, b^2 = (2E I3 - M^2) / (I2 (I3 - I2)),
/// rate^2 = (I3 - I2)(M^2 - 2E I1) / (I1 I2 I3), k^2 = (I2 - I1)(2E I3 - M^2) / ((I3 - I2)(M^2 - 2E I1)).
/// The sign of omega2's start (b > 0 here) follows from Euler's equation I2 omega2' = (I3 - I1) omega3 omega1 > 0.
template <class R>
struct euler_free_body_solution {
  R I1, I2, I3, a, c;

  static bool applies(const R& I1, const R& I2, const R& I3, const R& a, const R& c) {
    return I1 < I2 && I2 < I3 && a > 0 && c > 0 && I1 * (I1 - I2) * a * a + I3 * (I3 - I2) * c * c > 0;
  }
  euler_free_body_solution(R i1, R i2, R i3, R a0, R c0)
      : I1(std::move(i1)), I2(std::move(i2)), I3(std::move(i3)), a(std::move(a0)), c(std::move(c0)) {
    if (!applies(I1, I2, I3, a, c))
      throw std::invalid_argument("euler_free_body_solution: needs I1 < I2 < I3, omega(0) = (a, 0, c), a, c > 0, M^2 > 2 E I2");
  }
  R twice_energy() const { return I1 * a * a + I3 * c * c; }
  R momentum_squared() const { return I1 * I1 * a * a + I3 * I3 * c * c; }
  R rate() const {
    using std::sqrt;
    return sqrt((I3 - I2) * (momentum_squared() - twice_energy() * I1) / (I1 * I2 * I3));
  }
  R modulus() const {
    using std::sqrt;
    const R E2 = twice_energy(), M2 = momentum_squared();
    return sqrt((I2 - I1) * (E2 * I3 - M2) / ((I3 - I2) * (M2 - E2 * I1)));
  }
  /// The period of omega: 4 K(k) / rate.
  R period() const { return 4 * boost::math::ellint_1(modulus()) / rate(); }
  std::array<R, 3> at(const R& t) const {
    using std::sqrt;
    const R E2 = twice_energy(), M2 = momentum_squared();
    const R b = sqrt((E2 * I3 - M2) / (I2 * (I3 - I2)));
    R cn, dn;
    const R sn = boost::math::jacobi_elliptic(modulus(), rate() * t, &cn, &dn);
    return {a * cn, b * sn, c * dn};
  }
};

}  // namespace appell::ode

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 3> euler_body_state_table{{
    {"p", "omega[0]"},
    {"q", "omega[1]"},
    {"r", "omega[2]"},
}};

/// The result, as eval, reference and the motion's outputs name it.
struct euler_body_result_names {
  static constexpr const char* omega_dot = "omega_dot";  ///< (p', q', r')
};

}  // namespace appell

namespace appell::ode {

/// Euler's body (paper sec. 3): x = omega = (p, q, r) on the principal axes.
template <Scalar T>
struct euler_body_problem {
  euler_body<T> body;
  static constexpr int dim = 3;
  static std::vector<std::string> state_names() { return state_names_of(euler_body_state_table); }

  template <class S>
  euler_body<S> body_in() const {
    return {vec3<S>(S(body.inertia(0)), S(body.inertia(1)), S(body.inertia(2))),
            vec3<S>(S(body.torque(0)), S(body.torque(1)), S(body.torque(2)))};
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    return euler_body_equations(body_in<S>(), vec3<S>(x(0), x(1), x(2))).accelerations();
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const vector_t<S> w = rhs(x);
    out.push_back({euler_body_result_names::omega_dot, {w(0), w(1), w(2)}});
  }
  /// Without torque: the kinetic energy 1/2 omega.I omega and |I omega|^2 (Euler's two integrals).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    if (!torque_free()) return;
    S e = S(0), l2 = S(0);
    for (int i = 0; i < 3; ++i) {
      const S Ii = S(body.inertia(i));
      e += Ii * x(i) * x(i);
      l2 += Ii * Ii * x(i) * x(i);
    }
    out.push_back({"energy", {e / S(2)}});
    out.push_back({"angular_momentum_squared", {l2}});
  }
  bool torque_free() const {
    for (int i = 0; i < 3; ++i)
      if (!exactly_zero(body.torque(i))) return false;
    return true;
  }
};

}  // namespace appell::ode

namespace appell {

struct euler_body_input : model_input {
  std::vector<decimal_field> inertia;  // A, B, C
  std::vector<decimal_field> torque;   // L, M, N
  std::vector<decimal_field> omega;    // p, q, r
};

struct euler_body_model {
  static constexpr const char* name = "euler_body";
  using input = euler_body_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    euler_body<T> body;
    vec3<T> omega;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {{detail::vec3_from_decimals<T>(in.inertia), detail::vec3_from_decimals<T>(in.torque)},
            detail::vec3_from_decimals<T>(in.omega)};
  }
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const euler_body_result<T> r = euler_body_motion(m.body, m.omega);
    using W = evaluation_writer<T>;
    W out(e);
    out.vector(W::results, euler_body_result_names::omega_dot, "", r.omega_dot);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.scalar(W::checks, "power_balance", "", r.power_residual);
    out.finish();
  }
};

APPELL_EXTERN_MODEL(euler_body_model)

}  // namespace appell

namespace appell {

template <>
struct model_motion<euler_body_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::euler_body_problem<T>;
  template <Scalar T>
  static std::pair<ode::euler_body_problem<T>, vector_t<T>> start(const euler_body_model::prepared<T>& m) {
    return {ode::euler_body_problem<T>{m.body}, vector_t<T>(m.omega)};
  }
  static std::vector<std::string> state_fields(const euler_body_input&) { return state_fields_of(euler_body_state_table); }
  /// Without torque, I1 < I2 < I3 and omega(0) = (a, 0, c) with M^2 > 2 E I2: omega in Jacobi
  /// elliptic functions (euler_free_body_solution above).
  static std::optional<motion_closed_form> closed_form(const euler_body_input& in) {
    using R = motion_closed_form::value;
    for (const auto& f : in.torque)
      if (R(f.text) != 0) return std::nullopt;
    const R I1(in.inertia[0].text), I2(in.inertia[1].text), I3(in.inertia[2].text);
    const R a(in.omega[0].text), b(in.omega[1].text), c(in.omega[2].text);
    if (b != 0 || !ode::euler_free_body_solution<R>::applies(I1, I2, I3, a, c)) return std::nullopt;
    const ode::euler_free_body_solution<R> sol(I1, I2, I3, a, c);
    return motion_closed_form{"closed form (Jacobi elliptic functions, MPFR 256 bits)", {0, 1, 2}, sol.period(),
                              [sol](const R& t) {
                                const auto w = sol.at(t);
                                return std::vector<R>(w.begin(), w.end());
                              }};
  }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::euler_body_model)
