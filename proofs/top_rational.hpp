// proofs/top_rational.hpp -- the top of Example I in exact rational arithmetic,
// run through the shipped code: appell::symmetric_top and appell::top_on_cone_motion
// with the coordinates tau_psi = tan(psi/2), tau_theta = tan(theta/2)
// (appell::half_angle_tangents: sin = 2 tau / (1 + tau^2), cos = (1 - tau^2) / (1 + tau^2),
// tau' = (1 + tau^2)/2 angle'), speeds still (psi', theta', phi').  The cone is
// the shipped one, f(theta) = 0.5 theta + 0.1 sin 2 theta, whose f' = 0.5 + 0.2 (c^2 - s^2)
// and f'' = -0.8 s c are rational in tau_theta.  Nothing but + - * / appears,
// so Cotton's method and Lagrange's multipliers run without rounding.
// psi itself is not on the cone at these states (f(theta) is not rational in
// tau_theta): the dynamics does not depend on psi (rotations about the
// vertical), so psi is drawn at random instead.
#pragma once

#include "appell/scalar/rational.hpp"
#include "appell/models/top_on_cone.hpp"

namespace appell::proof {

using Q = rational_q;
using rational_top = symmetric_top<Q, half_angle_tangents>;

/// The shipped cone, f' and f'' as functions of tau_theta.
struct rational_cone {
  template <class S>
  S fprime(const S& tau) const {
    S s, c;
    half_angle_tangents::sin_cos(tau, s, c);
    return S(Q(1, 2)) + S(Q(1, 5)) * (c * c - s * s);
  }
  Q fsecond(const Q& tau) const {
    Q s, c;
    half_angle_tangents::sin_cos(tau, s, c);
    return Q(-4, 5) * s * c;
  }
};

}  // namespace appell::proof
