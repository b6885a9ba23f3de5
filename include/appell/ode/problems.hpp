// appell/ode/problems.hpp -- the scenes as ordinary differential equations.
//
// Each problem is the scene's own dynamics (the functions `appell eval` runs),
// called on whatever scalar the integrator needs: T for a point step, jet<T>
// for Taylor coefficients, multi_dual<jet<T>, dim> for their Jacobian (the
// wrapping control of ode/enclose.hpp).  No scene is implemented twice: the
// right-hand sides below only arrange the scene's state into x and call it.
// Each models only what the scene requires (issue 12): Euler's body is omega
// alone; the top on its pivot is its three Euler angles and their rates.
//
//   dim, state_names()        the state x
//   rhs<S>(x)                 x'
//   results<S>(x, out)        the scene's results along the motion (accelerations, reactions)
//   invariants<S>(x, out)     first integrals: energy where it is conserved, momenta
//   check_state(x0)           refuses a state the scene refuses (exit 2 in the CLI)
#pragma once

#include <string>
#include <vector>

#include "appell/ode/jet.hpp"
#include "appell/scenes/euler_body.hpp"
#include "appell/scenes/top_on_pivot.hpp"

namespace appell::ode {

template <class S>
struct named_values {
  std::string name;
  std::vector<S> values;
};

/// Euler's body (paper sec. 3): x = omega = (p, q, r) on the principal axes.
template <Scalar T>
struct euler_body_problem {
  euler_body<T> body;
  static constexpr int dim = 3;
  static std::vector<std::string> state_names() { return {"p", "q", "r"}; }

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
    out.push_back({"omega_dot", {w(0), w(1), w(2)}});
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

/// The heavy symmetric top on its pivot: x = (psi, theta, phi, psi', theta', phi').
template <Scalar T>
struct heavy_top_problem {
  T A, C, mass, l, g;
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() {
    return {"psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot"};
  }
  template <class S>
  cotton_result<S> cotton(const vector_t<S>& x) const {
    return top_on_pivot_cotton(S(A), S(C), S(mass), S(l), S(g),
                               top_on_pivot_state<S>{x(0), x(1), x(2), x(3), x(4), x(5)});
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const cotton_result<S> c = cotton(x);
    vector_t<S> d(6);
    d << x(3), x(4), x(5), c.free_accelerations(0), c.free_accelerations(1), c.free_accelerations(2);
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

/// The simple pendulum through the generic Gibbs-Appell path: a point mass m on a massless rod
/// of length l about a fixed point, gravity g; x = (theta, theta'), theta from the downward
/// vertical.  Not a scene model: the classical benchmark of verified integrators
/// (theta'' = -(g / l) sin theta), written as a system so that the same code path runs it.
template <Scalar T>
struct pendulum_problem {
  T mass, l, g;
  static constexpr int dim = 2;
  static std::vector<std::string> state_names() { return {"theta", "theta_dot"}; }

  struct system {
    T mass, l, g;
    static constexpr int max_speeds = 1;
    int speeds() const { return 1; }
    template <class S>
    vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
      return u;
    }
    template <class S>
    void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
      using std::sin, std::cos;
      S s, c;
      sin_cos(q(0), s, c);
      body_state<S> b;  // G = l (sin theta, -cos theta, 0): v_G = l theta' (cos theta, sin theta, 0)
      b.mass = S(mass);
      b.velocity = vec3<S>(S(l) * c * u(0), S(l) * s * u(0), S(0));
      b.force = vec3<S>(S(0), -(S(mass) * S(g)), S(0));
      out.push_back(b);
    }
  };
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const typename pendulum_problem<S>::system sys{S(mass), S(l), S(g)};
    vector_t<S> q(1), u(1);
    q << x(0);
    u << x(1);
    const vector_t<S> a = gibbs_appell(sys, q, u, S(0)).accelerations();
    vector_t<S> d(2);
    d << x(1), a(0);
    return d;
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    out.push_back({"theta_ddot", {rhs(x)(1)}});
  }
  /// Energy m l^2 theta'^2 / 2 - m g l cos theta.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    using std::cos;
    S s, c;
    sin_cos(x(0), s, c);
    out.push_back({"energy", {S(mass) * S(l) * S(l) * x(1) * x(1) / S(2) - S(mass) * S(g) * S(l) * c}});
  }
};

}  // namespace appell::ode
