// tests/pendulum_problem.hpp -- a test fixture, not a scene model: the simple pendulum as an
// ODE problem of the integrators (taylor.hpp, enclose.hpp), through the generic Gibbs-Appell
// path.  The classical benchmark of verified integrators; the motion suites and the benchmark
// against kv (bench/enclose_vs_kv.cpp) run it.  Its integrators are not compiled by the library:
// each program that runs it instantiates them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

namespace appell::ode {

/// The simple pendulum through the generic Gibbs-Appell path: a point mass m on a massless rod
/// of length l about a fixed point, gravity g; x = (theta, theta'), theta from the downward
/// vertical.  Not a scene model: the classical benchmark of verified integrators
/// (theta'' = -(g / l) sin theta), written as a system so that the same code path runs it.
///
/// Two descriptions of the same motion (Cotton's paper, section 3: any axes will do):
/// - on the rod's axes (the default): F turns with the rod, e1 = (cos, sin, 0) along G's path,
///   e2 = (-sin, cos, 0) along the rod towards the pivot, frame_rate = theta' e3.  G's velocity
///   on F is (l theta', 0, 0) and the weight is -m g (sin theta, cos theta, 0): Appell's
///   equations give M = m l^2 and Q = -m g l sin theta with no cancelling terms;
/// - on the fixed axes (`rod_axes = false`): v_G = l theta' (cos, sin, 0), so the path forms
///   M = m l^2 (cos^2 + sin^2) and b = -l^2 s c u^2 + l^2 s c u^2, exact at a point but whose
///   interval ranges over a wide box do not cancel (kept to measure that dependency).
template <Scalar T>
struct pendulum_problem {
  T mass, l, g;
  bool rod_axes = true;
  static constexpr int dim = 2;
  static std::vector<std::string> state_names() { return {"theta", "theta_dot"}; }

  struct system {
    T mass, l, g;
    bool rod_axes = true;
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
      body_state<S> b;
      b.mass = S(mass);
      if (rod_axes) {
        b.velocity = vec3<S>(S(l) * u(0), S(0), S(0));
        b.frame_rate = vec3<S>(S(0), S(0), u(0));
        const S w = S(mass) * S(g);
        b.force = vec3<S>(-(w * s), -(w * c), S(0));
      } else {  // G = l (sin theta, -cos theta, 0): v_G = l theta' (cos theta, sin theta, 0)
        b.velocity = vec3<S>(S(l) * c * u(0), S(l) * s * u(0), S(0));
        b.force = vec3<S>(S(0), -(S(mass) * S(g)), S(0));
      }
      out.push_back(b);
    }
  };
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const typename pendulum_problem<S>::system sys{S(mass), S(l), S(g), rod_axes};
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

/// The simple pendulum theta'' = -(g/l) sin theta released at rest from theta0 in (0, pi):
/// sin(theta/2) = k sn(K(k) - w t, k), k = sin(theta0/2), w = sqrt(g/l); theta' from the energy's sign.
template <class R>
struct pendulum_solution {
  R theta0, w;
  R modulus() const {
    using std::sin;
    return sin(theta0 / 2);
  }
  R period() const { return 4 * boost::math::ellint_1(modulus()) / w; }
  /// (theta, theta') at t.
  std::array<R, 2> at(const R& t) const {
    using std::asin;
    R cn, dn;
    const R k = modulus();
    const R sn = boost::math::jacobi_elliptic(k, boost::math::ellint_1(k) - w * t, &cn, &dn);
    // d/dt [2 asin(k sn(u))] with u = K - w t: 2 k cn dn (-w) / sqrt(1 - k^2 sn^2) = -2 k w cn (dn / dn).
    return {2 * asin(k * sn), -2 * k * w * cn};
  }
};

}  // namespace appell::ode
