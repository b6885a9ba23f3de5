// proofs/top_rational.hpp -- the top of Example I in exact rational arithmetic.
//
// The same mechanics as appell::heavy_top, in coordinates where every
// quantity is rational: tau_psi = tan(psi/2), tau_theta = tan(theta/2)
// (sin = 2 tau / (1 + tau^2), cos = (1 - tau^2) / (1 + tau^2), tau' = (1 + tau^2)/2 angle'),
// speeds still (psi', theta', phi').  The cone is the shipped one,
// f(theta) = 0.5 theta + 0.1 sin 2 theta, whose f' = 0.5 + 0.2 (c^2 - s^2) and
// f'' = -0.8 s c are rational in tau_theta.  Nothing but + - * / appears, so
// Cotton's method and Lagrange's multipliers run without rounding.
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include "appell/scalar/rational.hpp"

namespace appell::proof {

using Q = rational_q;

template <class S> S sin_of(const S& tau) { return S(2) * tau / (S(1) + tau * tau); }
template <class S> S cos_of(const S& tau) { return (S(1) - tau * tau) / (S(1) + tau * tau); }
template <class S> S cone_fprime(const S& tau) {
  const S s = sin_of(tau), c = cos_of(tau);
  return S(Q(1, 2)) + S(Q(1, 5)) * (c * c - s * s);
}
inline Q cone_fsecond(const Q& tau) { return Q(-4, 5) * sin_of(tau) * cos_of(tau); }

struct rational_top {
  Q A, C, mass, l, g;
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S&) const {
    vector_t<S> d(3);
    d << (S(1) + q(0) * q(0)) / S(2) * u(0), (S(1) + q(1) * q(1)) / S(2) * u(1), u(2);
    return d;
  }
  template <class S>
  static void axes(const vector_t<S>& q, vec3<S>& n, vec3<S>& ez) {
    const S sp = sin_of(q(0)), cp = cos_of(q(0)), st = sin_of(q(1)), ct = cos_of(q(1));
    n = vec3<S>(cp, sp, S(0));
    ez = vec3<S>(st * sp, -st * cp, ct);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    vec3<S> n, ez;
    axes(q, n, ez);
    body_state<S> b;
    b.mass = S(mass);
    b.omega = vec3<S>(S(0), S(0), u(0)) + n * u(1) + ez * u(2);
    b.velocity = cross(b.omega, vec3<S>(ez * S(l)));
    const S transverse = S(A) - S(mass) * S(l) * S(l);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b.inertia(i, j) = (S(C) - transverse) * ez(i) * ez(j) + (i == j ? transverse : S(0));
    b.force = vec3<S>(S(0), S(0), -S(mass) * S(g));
    out.push_back(b);
  }
};

struct rational_cone_constraint {  // psi' - f'(theta) theta' = 0
  int count() const { return 1; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    A(0, 0) = S(1);
    A(0, 1) = -cone_fprime(q(1));
    A(0, 2) = S(0);
    a(0) = S(0);
  }
};

struct rational_cone_speeds {  // (theta', phi', psi_1') -> (psi', theta', phi')
  template <class S>
  vector_t<S> apply(const vector_t<S>& q, const vector_t<S>& v, const S&) const {
    vector_t<S> u(3);
    u << v(2) + cone_fprime(q(1)) * v(0), v(0), v(1);
    return u;
  }
};

}  // namespace appell::proof
