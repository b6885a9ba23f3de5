// appell/models/heavy_top.hpp -- the home of the scene model "heavy_top": a heavy
// symmetric top on a fixed point O of its axis, no cone (the classical
// benchmark), with the pivot's force.  Schema (SCENES.md): top {A, C, mass, l}
// (A about O; A >= m l^2, C <= 2 (A - m l^2)), gravity, state {psi, theta, phi,
// psi_dot, theta_dot, phi_dot} (theta != 0).
//
// It moves in Resal's speeds, x = (psi, theta, phi, theta', psi' sin theta, psi' cos theta + phi')
// (ode::heavy_top_resal_problem: Appell's M constant), reported as the scene's state (psi, theta,
// phi, psi', theta', phi'); the nutation in closed form (horizon's truth).
//
// Everything named after the model is here: its state table (the motion's state: each
// component's name in the outputs and the scene field it starts from), its motion as an ODE
// problem (right-hand side, results and invariants along the motion), its inputs, prepare and
// evaluation with its results' names, and model_motion (start, closed form).  Its reader and
// registry entry are in src/models/heavy_top.cpp.
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
//
// The physics.  The top's body and its Euler angles are dynamics/symmetric_top.hpp's (the top on
// a cone, models/top_on_cone.hpp, shares them); here the top on its pivot, with the pivot's force.
//
// Cotton's way (paper sec. 5, last paragraph): start from the free solid, k + s
// = 6 speeds, and add the fixed point as s = 3 constraints.  Speeds
//   v = (psi', theta', phi', w_x, w_y, w_z),
// w the velocity of the body's material point at O, on the fixed axes; the
// pivot is w = 0, the last three speeds.  The pivot force F at O does the
// virtual power F . w, so Cotton's Q'_c (eq. 14) on (w_x, w_y, w_z) is F itself,
// on the fixed axes: no wrench solve is needed.  Coordinates q = (psi, theta,
// phi, x_O, y_O, z_O) (the body's point at O; q' = v); Euler angles z-x-z as
// in symmetric_top.hpp.  The body is described on Resal's trihedron (n, e_z x n,
// e_z), which turns with psi' e3 + theta' n: there the inertia is constant,
// the spin sits in one component of omega, and the interval enclosures stay
// tight (see symmetric_top_resal); w enters through its components on that
// trihedron, R^T w.
//
// The independent check: the same top as a free body on the fixed axes, speeds
// (x_G', y_G', z_G', psi', theta', phi'), with the pivot written as the
// constraint v_O = v_G - omega x l e_z = 0 (three rows, linear in the speeds)
// and solved by Lagrange's multipliers: they are F again.  The tests add a
// third route, Newton-Euler written out in closed form (F = m a_G + m g e3).
//
// The Euler angles are singular where sin theta = 0 (the axis on the
// vertical): Appell's equations lose rank there; the model refuses theta = 0
// exactly and the scalars' error amplification reports the neighbourhood.
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
#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/symmetric_top.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {

/// The top as a free body with its point O as three speeds (Cotton's speeds):
/// symmetric_top_resal's body, with R^T w added to the velocity of G.
template <Scalar T>
struct free_top_resal {
  T A, C, mass, l, g;  ///< A: transverse moment about O; C: axial; l = OG

  static constexpr int max_speeds = 6;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& v, const S&) const {
    return v;
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& v, const S&, vector_t<S>& qd) const {
    qd = v;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& v, const S& t, std::vector<body_state<S>>& out) const {
    struct site;  // borrowed (linalg/scratch.hpp)
    const scratch<vector_t<S>, site> angles, rates;
    *angles = q.head(3);
    *rates = v.head(3);
    symmetric_top_resal<T>{A, C, mass, l, g}.bodies(*angles, *rates, t, out);
    const mat3<S> R = symmetric_top_resal<T>::axes(*angles);
    body_state<S>& b = out.back();
    for (int i = 0; i < 3; ++i)  // (R^T w)_i = column i of R . w
      b.velocity(i) += R(0, i) * v(3) + R(1, i) * v(4) + R(2, i) * v(5);
  }
};

/// The same top as a free body on the fixed axes, speeds (x_G', y_G', z_G', psi', theta', phi'):
/// heavy_top's body, with the velocity of G as three speeds of its own.
template <Scalar T>
struct free_top_fixed_axes {
  T A, C, mass, l, g;

  static constexpr int max_speeds = 6;
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    qd = u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    struct site;  // borrowed (linalg/scratch.hpp)
    const scratch<vector_t<S>, site> angles, rates;
    *angles = q.tail(3);
    *rates = u.tail(3);
    symmetric_top<T>{A, C, mass, l, g}.bodies(*angles, *rates, t, out);
    out.back().velocity = vec3<S>(u(0), u(1), u(2));
  }
};

/// v_O = v_G - omega x l e_z = 0 on free_top_fixed_axes: A u = 0 with
/// A = [I_3, -l e3 x e_z, -l n x e_z, 0] (omega = psi' e3 + theta' n + phi' e_z).
template <Scalar T>
struct pivot_constraint {
  T l;
  int count() const { return 3; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    vec3<S> n, ez;
    symmetric_top<T>::axes(q.tail(3), n, ez);
    const vec3<S> e3(S(0), S(0), S(1));
    const vec3<S> c_psi = cross(e3, ez), c_theta = cross(n, ez);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(i, j) = i == j ? S(1) : S(0);
      A(i, 3) = -(S(l) * c_psi(i));
      A(i, 4) = -(S(l) * c_theta(i));
      A(i, 5) = S(0);
      a(i) = S(0);
    }
  }
};

template <Scalar T>
struct top_on_pivot_state {
  T psi, theta, phi, psi_dot, theta_dot, phi_dot;
};

template <Scalar T>
struct top_on_pivot_result {
  T psi_ddot, theta_ddot, phi_ddot;
  vec3<T> pivot_force;            ///< Cotton's Q'_c on w: the force of the pivot on the top, fixed axes
  T virtual_work_residual;        ///< eq. (4) in Cotton's speeds: 0 on the motion
  vec3<T> pivot_force_lagrange;   ///< the multipliers of v_O = 0 on the free body on fixed axes
  T psi_ddot_lagrange, theta_ddot_lagrange, phi_ddot_lagrange;
};

namespace detail {
/// The free top's positions (Euler angles, then the pivot at the origin) and its free speeds.
template <Scalar T>
vector_t<T> pivot_positions(const top_on_pivot_state<T>& s) {
  vector_t<T> q(6);
  q << s.psi, s.theta, s.phi, T(0), T(0), T(0);
  return q;
}
template <Scalar T>
vector_t<T> pivot_free_speeds(const top_on_pivot_state<T>& s) {
  vector_t<T> v_a(3);
  v_a << s.psi_dot, s.theta_dot, s.phi_dot;
  return v_a;
}
}  // namespace detail

/// Cotton's method on the free top with the pivot as its last three speeds:
/// (psi'', theta'', phi'') and the pivot force (fixed axes).  What `appell eval`
/// reports, and what `appell simulate` / `enclose` report along the motion (their
/// right-hand side is top_on_pivot_accelerations, below).
template <Scalar T>
cotton_result<T> top_on_pivot_cotton(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                     const top_on_pivot_state<T>& s) {
  const free_top_resal<T> sys{A, C, mass, l, g};
  return cotton_reactions(sys, detail::pivot_positions(s), detail::pivot_free_speeds(s), T(0), 3);
}

/// top_on_pivot_cotton's (psi'', theta'', phi'') alone, bit for bit, without the pivot force:
/// the right-hand side of the motion (the model's problem, models/<name>.hpp), which needs no reaction.
template <Scalar T>
vector_t<T> top_on_pivot_accelerations(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                       const top_on_pivot_state<T>& s) {
  const free_top_resal<T> sys{A, C, mass, l, g};
  return cotton_free_accelerations<4>(sys, detail::pivot_positions(s), detail::pivot_free_speeds(s), T(0), 3);
}

/// The heavy top on its pivot: Cotton's method from the free body, and the
/// Lagrange multipliers of the free body on the fixed axes as the check.
template <Scalar T>
top_on_pivot_result<T> top_on_pivot_motion(const T& A, const T& C, const T& mass, const T& l, const T& g,
                                           const top_on_pivot_state<T>& s) {
  const T t = T(0);
  top_on_pivot_result<T> r;
  struct site;  // working storage borrowed (linalg/scratch.hpp): none taken from the heap once warm
  const scratch<vector_t<T>, site> q_held, u_held, v_held, vdot_held, ones;
  vector_t<T>&q = *q_held, &u = *u_held, &v = *v_held, &vdot = *vdot_held;
  {
    const free_top_resal<T> sys{A, C, mass, l, g};
    q.resize(6);
    q << s.psi, s.theta, s.phi, T(0), T(0), T(0);  // detail::pivot_positions
    v.setZero(6);
    v(0) = s.psi_dot, v(1) = s.theta_dot, v(2) = s.phi_dot;  // the free speeds, then the pivot's 0
    const scratch<cotton_result<T>, site> c_held;
    const cotton_result<T>& c = *c_held;
    const scratch<vector_t<T>, site> v_a;
    *v_a = v.head(3);  // detail::pivot_free_speeds
    cotton_reactions_into(sys, q, *v_a, t, 3, *c_held);  // top_on_pivot_cotton
    r.psi_ddot = c.free_accelerations(0);
    r.theta_ddot = c.free_accelerations(1);
    r.phi_ddot = c.free_accelerations(2);
    r.pivot_force = vec3<T>(c.reactions(0), c.reactions(1), c.reactions(2));
    vdot.setZero(6);
    vdot.head(3) = c.free_accelerations;
    ones->setOnes(6);
    r.virtual_work_residual = virtual_work_residual(sys, c.equations, q, v, t, vdot, *ones);
  }
  {
    const free_top_fixed_axes<T> sys{A, C, mass, l, g};
    // G = l e_z (O at the origin), v_G = omega x l e_z.
    q.resize(6);
    u.resize(6);
    q << T(0), T(0), T(0), s.psi, s.theta, s.phi;
    vec3<T> n, ez;
    symmetric_top<T>::axes(q.tail(3), n, ez);
    for (int i = 0; i < 3; ++i) q(i) = l * ez(i);
    const vec3<T> omega = vec3<T>(T(0), T(0), s.psi_dot) + n * s.theta_dot + ez * s.phi_dot;
    const vec3<T> vG = cross(omega, vec3<T>(ez * l));
    u << vG(0), vG(1), vG(2), s.psi_dot, s.theta_dot, s.phi_dot;
    const scratch<constrained_motion<T>, site> lag_held;
    const constrained_motion<T>& lag = *lag_held;
    lagrange_multipliers_into(sys, pivot_constraint<T>{l}, q, u, t, *lag_held);
    r.pivot_force_lagrange = vec3<T>(lag.reactions(0), lag.reactions(1), lag.reactions(2));
    r.psi_ddot_lagrange = lag.accelerations(3);
    r.theta_ddot_lagrange = lag.accelerations(4);
    r.phi_ddot_lagrange = lag.accelerations(5);
  }
  return r;
}

/// top_on_pivot_motion compiled with the model, once per standard scalar (io/model.hpp).
#define APPELL_MODEL_PHYSICS_heavy_top(EXTERN, T)                                                                 \
  EXTERN template top_on_pivot_result<T> top_on_pivot_motion<T>(const T&, const T&, const T&, const T&, const T&, \
                                                                const top_on_pivot_state<T>&);
APPELL_EXTERN_MODEL_PHYSICS(heavy_top)

}  // namespace appell

namespace appell::ode {

/// The nutation of the heavy symmetric top on its pivot (A about the pivot, C about the axis,
/// m g l; Euler angles psi precession, theta nutation, phi spin), from its three first integrals:
/// with u = cos theta, a = C r / A (r = phi' + psi' cos theta), b = (A psi' sin^2 theta + C r cos theta) / A,
/// alpha = (A (theta'^2 + psi'^2 sin^2 theta) + 2 m g l cos theta) / A and beta = 2 m g l / A,
///   u'^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2 = beta (u - u1)(u - u2)(u - u3),
/// u1 <= u2 in [-1, 1] <= u3, and  u(t) = u1 + (u2 - u1) sn^2(lambda t + c, k),
/// k^2 = (u2 - u1) / (u3 - u1), lambda = sqrt(beta (u3 - u1)) / 2 (substituting gives
/// u'^2 = 4 lambda^2 (u2 - u1)^2 sn^2 cn^2 dn^2 = f(u)); c from u(0) and the sign of u'(0).
/// theta = acos u, theta' = -u' / sin theta.  (psi and phi need elliptic integrals of the
/// third kind: not given.)  Requires m g l > 0 and u2 > u1 (not a steady precession).
template <class R>
struct heavy_top_nutation {
  R u1, u2, u3, lambda, k, c;

  heavy_top_nutation(const R& A, const R& C, const R& mgl, const R& theta0, const R& psi_dot0, const R& theta_dot0,
                     const R& phi_dot0) {
    using std::cos, std::sin, std::sqrt, std::asin;
    const R u0 = cos(theta0), s0 = sin(theta0);
    const R r = phi_dot0 + psi_dot0 * u0;
    const R a = C * r / A, b = (A * psi_dot0 * s0 * s0 + C * r * u0) / A;
    const R alpha = (A * (theta_dot0 * theta_dot0 + psi_dot0 * psi_dot0 * s0 * s0) + 2 * mgl * u0) / A;
    const R beta = 2 * mgl / A;
    if (!(beta > 0)) throw std::invalid_argument("heavy_top_nutation: needs m g l > 0");
    // f(u) = beta u^3 + c2 u^2 + c1 u + c0
    const R c2 = -(alpha + a * a), c1 = 2 * a * b - beta, c0 = alpha - b * b;
    auto f = [&](const R& u) { return ((beta * u + c2) * u + c1) * u + c0; };
    // u3 >= 1: f(1) = -(b - a)^2 <= 0 and f grows without bound; bisection.
    R lo = 1, hi = 2;
    while (f(hi) <= 0) hi *= 2;
    for (int i = 0; i < 2000 && lo < hi; ++i) {
      const R m = (lo + hi) / 2;
      if (m <= lo || m >= hi) break;
      (f(m) > 0 ? hi : lo) = m;
    }
    u3 = hi;
    // f(u) = (u - u3)(beta u^2 + e1 u + e0)
    const R e1 = c2 + beta * u3, e0 = c1 + e1 * u3;
    const R disc = e1 * e1 - 4 * beta * e0;
    if (!(disc > 0)) throw std::invalid_argument("heavy_top_nutation: steady precession (no nutation)");
    u1 = (-e1 - sqrt(disc)) / (2 * beta);
    u2 = (-e1 + sqrt(disc)) / (2 * beta);
    k = sqrt((u2 - u1) / (u3 - u1));
    lambda = sqrt(beta * (u3 - u1)) / 2;
    // u(0) = u0: sn^2(c) = (u0 - u1) / (u2 - u1), clamped to [0, 1] against the last bits.
    R q = (u0 - u1) / (u2 - u1);
    if (q < 0) q = 0;
    if (q > 1) q = 1;
    const R F = boost::math::ellint_1(k, asin(sqrt(q)));
    // u' = -sin(theta) theta': sn^2 rises on (0, K), falls on (K, 2K).
    const R uprime = -s0 * theta_dot0;
    c = uprime >= 0 ? F : 2 * boost::math::ellint_1(k) - F;
  }
  /// The period of the nutation: 2 K(k) / lambda.
  R period() const { return 2 * boost::math::ellint_1(k) / lambda; }
  /// (theta, theta') at t.
  std::array<R, 2> at(const R& t) const {
    using std::acos, std::sin;
    R cn, dn;
    const R sn = boost::math::jacobi_elliptic(k, lambda * t + c, &cn, &dn);
    const R u = u1 + (u2 - u1) * sn * sn;
    const R uprime = 2 * lambda * (u2 - u1) * sn * cn * dn;
    const R theta = acos(u);
    return {theta, -uprime / sin(theta)};
  }
};

}  // namespace appell::ode

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 6> heavy_top_state_table{{
    {"psi", "psi"},
    {"theta", "theta"},
    {"phi", "phi"},
    {"psi_dot", "psi_dot"},
    {"theta_dot", "theta_dot"},
    {"phi_dot", "phi_dot"},
}};

/// The results, in the order eval, reference and the motion's outputs give them: the angular
/// accelerations and the pivot's force on the fixed axes (a vector).
inline constexpr std::array<const char*, 4> heavy_top_result_names{"theta_ddot", "phi_ddot", "psi_ddot", "pivot_force"};

}  // namespace appell

namespace appell::ode {

/// The heavy symmetric top on its pivot: x = (psi, theta, phi, psi', theta', phi').
template <Scalar T>
struct heavy_top_problem {
  T A, C, mass, l, g;
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() { return state_names_of(heavy_top_state_table); }
  template <class S>
  static top_on_pivot_state<S> state(const vector_t<S>& x) {
    return {x(0), x(1), x(2), x(3), x(4), x(5)};
  }
  template <class S>
  cotton_result<S> cotton(const vector_t<S>& x) const {
    return top_on_pivot_cotton(S(A), S(C), S(mass), S(l), S(g), state(x));
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    // The accelerations alone (no pivot force): 4 directions differentiated instead of 7.
    const vector_t<S> a = top_on_pivot_accelerations(S(A), S(C), S(mass), S(l), S(g), state(x));
    vector_t<S> d(6);
    d << x(3), x(4), x(5), a(0), a(1), a(2);
    return d;
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const cotton_result<S> c = cotton(x);
    const auto& name = heavy_top_result_names;
    out.push_back({name[0], {c.free_accelerations(1)}});
    out.push_back({name[1], {c.free_accelerations(2)}});
    out.push_back({name[2], {c.free_accelerations(0)}});
    out.push_back({name[3], {c.reactions(0), c.reactions(1), c.reactions(2)}});
  }
  /// Energy 1/2 A (theta'^2 + psi'^2 sin^2 theta) + 1/2 C r^2 + m g l cos theta, with the spin
  /// r = phi' + psi' cos theta; the momenta about the vertical, A psi' sin^2 theta + C r cos theta,
  /// and about the axis, C r.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    S s, c;
    sin_cos(x(1), s, c);
    const S r = x(5) + x(3) * c;
    const S sA(A), sC(C);
    out.push_back({"energy", {symmetric_top_energy(A, C, mass, g, l, s, c, x(3), x(4), x(5))}});
    out.push_back({"momentum_vertical", {sA * x(3) * s * s + sC * r * c}});
    out.push_back({"momentum_axis", {sC * r}});
  }
};

/// The heavy symmetric top on its pivot in Resal's speeds (Appell's quasi-velocities, paper
/// sec. 5): x = (psi, theta, phi, p1, p2, p3) with p = (theta', psi' sin theta, psi' cos theta + phi'),
/// the angular velocity on Resal's trihedron (n, e_z x n, e_z).  There the central inertia is the
/// constant diag(A - m l^2, A - m l^2, C) and Appell's M = diag(A, A, C): the Gibbs-Appell path
/// solves no matrix of theta over a step's box, the step's series are far tighter than in Euler
/// rates (heavy_top_problem), and the spin sits in p3 alone.  The motion of the scene heavy_top
/// (model_motion<heavy_top_model> below): reported() gives the scene's state (psi, theta, phi, psi',
/// theta', phi') from x, and the results and invariants are those of heavy_top_problem.
template <Scalar T>
struct heavy_top_resal_problem {
  T A, C, mass, l, g;
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() { return {"psi", "theta", "phi", "p1", "p2", "p3"}; }
  static std::vector<std::string> reported_names() { return state_names_of(heavy_top_state_table); }

  /// The top with its speeds p: q' = (p2 / sin theta, p1, p3 - p2 cos theta / sin theta).
  struct system {
    T A, C, mass, l, g;
    static constexpr int max_speeds = 3;
    int speeds() const { return 3; }
    template <class S>
    vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& p, const S&) const {
      S st, ct;
      sin_cos(q(1), st, ct);
      const S psi_dot = p(1) / st;
      vector_t<S> d(3);
      d << psi_dot, p(0), S(p(2) - psi_dot * ct);
      return d;
    }
    template <class S>
    void bodies(const vector_t<S>& q, const vector_t<S>& p, const S&, std::vector<body_state<S>>& out) const {
      S st, ct;
      sin_cos(q(1), st, ct);
      // the trihedron turns with theta' n + psi' e3; the top with p (symmetric_top_resal's body)
      out.push_back(symmetric_top_resal<S>{S(A), S(C), S(mass), S(l), S(g)}.body(st, ct, vec3<S>(p(0), p(1), S(p(1) * ct / st)),
                                                                              vec3<S>(p(0), p(1), p(2))));
    }
  };
  /// x from the scene's state (psi, theta, phi, psi', theta', phi').
  static vector_t<T> from_euler_rates(const vector_t<T>& y) {
    using std::sin, std::cos;
    const T st = sin(y(1)), ct = cos(y(1));
    vector_t<T> x(6);
    x << y(0), y(1), y(2), y(4), T(y(3) * st), T(y(3) * ct + y(5));
    return x;
  }
  /// The scene's state (psi, theta, phi, psi', theta', phi') from x.
  template <class S>
  static vector_t<S> reported(const vector_t<S>& x) {
    S st, ct;
    sin_cos(x(1), st, ct);
    const S psi_dot = x(4) / st;
    vector_t<S> y(6);
    y << x(0), x(1), x(2), psi_dot, x(3), S(x(5) - psi_dot * ct);
    return y;
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const typename heavy_top_resal_problem<S>::system sys{S(A), S(C), S(mass), S(l), S(g)};
    const vector_t<S> q = x.head(3), p = x.tail(3);
    const vector_t<S> qd = sys.qdot(q, p, S(0));
    const vector_t<S> a = cotton_free_accelerations<4>(sys, q, p, S(0), 0);
    vector_t<S> d(6);
    d << qd(0), qd(1), qd(2), a(0), a(1), a(2);
    return d;
  }
  /// heavy_top_problem's results at the scene's state (psi'', theta'', phi'' and the pivot force).
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    heavy_top_problem<T>{A, C, mass, l, g}.results(reported(x), out);
  }
  /// The energy 1/2 (A (p1^2 + p2^2) + C p3^2) + m g l cos theta, the momenta about the vertical,
  /// A p2 sin theta + C p3 cos theta, and about the axis, C p3 (heavy_top_problem's, in p).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    S st, ct;
    sin_cos(x(1), st, ct);
    const S sA(A), sC(C);
    out.push_back({"energy", {(sA * (x(3) * x(3) + x(4) * x(4)) + sC * x(5) * x(5)) / S(2) + S(mass) * S(g) * S(l) * ct}});
    out.push_back({"momentum_vertical", {sA * x(4) * st + sC * x(5) * ct}});
    out.push_back({"momentum_axis", {sC * x(5)}});
  }
};

}  // namespace appell::ode

namespace appell {

struct heavy_top_input : model_input {
  decimal_field A, C, mass, l, gravity;
  decimal_field psi, theta, phi, psi_dot, theta_dot, phi_dot;
};

struct heavy_top_model {
  static constexpr const char* name = "heavy_top";
  using input = heavy_top_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    T A, C, mass, l, g;
    top_on_pivot_state<T> state;
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    return {value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity),
            {value<T>(in.psi), value<T>(in.theta), value<T>(in.phi), value<T>(in.psi_dot), value<T>(in.theta_dot),
             value<T>(in.phi_dot)}};
  }
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks = with_checks::yes) {
    const top_on_pivot_result<T> r = top_on_pivot_motion(m.A, m.C, m.mass, m.l, m.g, m.state);
    using W = evaluation_writer<T>;
    W out(e);
    const auto& name = heavy_top_result_names;
    out.scalar(W::results, name[0], "", r.theta_ddot);
    out.scalar(W::results, name[1], "", r.phi_ddot);
    out.scalar(W::results, name[2], "", r.psi_ddot);
    out.vector(W::results, name[3], "", r.pivot_force);
    out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
    out.vector(W::checks, "pivot_force_cotton_minus_lagrange", "", vec3<T>(r.pivot_force - r.pivot_force_lagrange));
    out.scalar(W::checks, "theta_ddot_cotton_minus_lagrange", "", T(r.theta_ddot - r.theta_ddot_lagrange));
    out.scalar(W::checks, "phi_ddot_cotton_minus_lagrange", "", T(r.phi_ddot - r.phi_ddot_lagrange));
    out.scalar(W::checks, "psi_ddot_cotton_minus_lagrange", "", T(r.psi_ddot - r.psi_ddot_lagrange));
    out.finish();
  }
};

APPELL_EXTERN_MODEL(heavy_top_model)

}  // namespace appell

namespace appell {

template <>
struct model_motion<heavy_top_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::heavy_top_resal_problem<T>;
  template <Scalar T>
  static std::pair<ode::heavy_top_resal_problem<T>, vector_t<T>> start(const heavy_top_model::prepared<T>& m) {
    vector_t<T> y(6);
    y << m.state.psi, m.state.theta, m.state.phi, m.state.psi_dot, m.state.theta_dot, m.state.phi_dot;
    return {ode::heavy_top_resal_problem<T>{m.A, m.C, m.mass, m.l, m.g}, ode::heavy_top_resal_problem<T>::from_euler_rates(y)};
  }
  static std::vector<std::string> state_fields(const heavy_top_input&) { return state_fields_of(heavy_top_state_table); }
  /// The nutation (theta, theta') in Jacobi elliptic functions (psi and phi would need elliptic
  /// integrals of the third kind); none without gravity or in steady precession.
  static std::optional<motion_closed_form> closed_form(const heavy_top_input& in) {
    using R = motion_closed_form::value;
    try {
      const ode::heavy_top_nutation<R> sol(R(in.A.text), R(in.C.text), R(in.mass.text) * R(in.gravity.text) * R(in.l.text),
                                           R(in.theta.text), R(in.psi_dot.text), R(in.theta_dot.text),
                                           R(in.phi_dot.text));
      return motion_closed_form{
          "closed form of the nutation (Jacobi elliptic functions, MPFR 256 bits; theta and theta' compared)",
          {1, 4},
          sol.period(),
          [sol](const R& t) {
            const auto w = sol.at(t);
            return std::vector<R>(w.begin(), w.end());
          }};
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // no gravity or a steady precession: the 256-bit simulate instead
    }
  }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::heavy_top_model)
