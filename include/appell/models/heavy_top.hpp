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
// registry entry are in src/models/heavy_top.cpp; the physics is the paper's (scenes/heavy_top.hpp).
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/closed_forms.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scenes/heavy_top.hpp"

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
    out.push_back({"psi_ddot", {c.free_accelerations(0)}});
    out.push_back({"theta_ddot", {c.free_accelerations(1)}});
    out.push_back({"phi_ddot", {c.free_accelerations(2)}});
    out.push_back({"pivot_force", {c.reactions(0), c.reactions(1), c.reactions(2)}});
  }
  /// Energy 1/2 A (theta'^2 + psi'^2 sin^2 theta) + 1/2 C r^2 + m g l cos theta, with the spin
  /// r = phi' + psi' cos theta; the momenta about the vertical, A psi' sin^2 theta + C r cos theta,
  /// and about the axis, C r.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    using std::sin, std::cos;
    S s, c;
    sin_cos(x(1), s, c);
    const S r = x(5) + x(3) * c;
    const S sA(A), sC(C);
    const S e = (sA * (x(4) * x(4) + x(3) * x(3) * s * s) + sC * r * r) / S(2) + S(mass) * S(g) * S(l) * c;
    out.push_back({"energy", {e}});
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
      // the trihedron turns with theta' n + psi' e3; the top with p (heavy_top_resal's body)
      out.push_back(heavy_top_resal<S>{S(A), S(C), S(mass), S(l), S(g)}.body(st, ct, vec3<S>(p(0), p(1), S(p(1) * ct / st)),
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

namespace detail {
/// The top's angular accelerations, as the heavy top and Example I (top_on_cone) name them.
template <Scalar T>
void write_top_accelerations(evaluation_writer<T>& out, const T& theta_ddot, const T& phi_ddot, const T& psi_ddot) {
  using W = evaluation_writer<T>;
  out.scalar(W::results, "theta_ddot", "", theta_ddot);
  out.scalar(W::results, "phi_ddot", "", phi_ddot);
  out.scalar(W::results, "psi_ddot", "", psi_ddot);
}
}  // namespace detail

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
    detail::write_top_accelerations(out, r.theta_ddot, r.phi_ddot, r.psi_ddot);
    out.vector(W::results, "pivot_force", "", r.pivot_force);
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
