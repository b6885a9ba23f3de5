// examples/planar_chain.hpp -- a planar N-link pendulum written on the public API
// (dynamics/gibbs_appell.hpp), for bench/chain.cpp and tests/generic_path.cpp: N
// uniform links of mass 1 and length 1 pinned end to end, the first to the
// ground at the origin; central inertia 1/12 about every axis; gravity 9.81
// along -y; coordinates the relative joint angles, speeds their rates.  It
// declares no max_speeds (a user's system need not).
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell::examples {

/// The chain as a user writes it: speeds(), qdot(), bodies().
template <Scalar T>
struct planar_chain {
  int n;
  T mass = T(1), length = T(1), half_length = rational<T>(1, 2), central = rational<T>(1, 12),
    g = from_decimal<T>("9.81");

  int speeds() const { return n; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    using std::sin, std::cos;
    S theta(0), w(0);
    vec3<S> joint = vec3<S>::Zero();  // velocity of link i's inboard pin
    for (int i = 0; i < n; ++i) {
      theta += q(i);
      w += u(i);
      const S s = sin(theta), c = cos(theta);
      const vec3<S> along_rate(-(s * w), c * w, S(0));  // d/dt of the link's unit vector
      body_state<S> b;
      b.mass = S(mass);
      b.omega = vec3<S>(S(0), S(0), w);
      b.velocity = joint + along_rate * S(half_length);
      for (int k = 0; k < 3; ++k) b.inertia(k, k) = S(central);
      b.force = vec3<S>(S(0), -(S(mass) * S(g)), S(0));
      out.push_back(b);
      joint += along_rate * S(length);
    }
  }
};

}  // namespace appell::examples
