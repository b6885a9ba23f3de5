// appell/reactions/wrench_cone.hpp -- can a flat rectangular sole hold?  The contact wrench cone
// of a rigid rectangular sole on a rigid support, in closed form, over any scalar.
//
// The sole: a rectangle of half-lengths X (along its x axis) and Y (along y), its normal z
// pointing out of the support into the body.  The support pushes at every point of the sole; the
// contact is modelled, as is usual for a rigid sole, by four forces at its corners
// p = (sx X, sy Y, 0), sx, sy = +-1, each in the friction pyramid of coefficient mu:
//     c >= 0,  |a| <= mu c,  |b| <= mu c        (f_corner = (a, b, c)).
// The wrench they make at the sole's centre, on the sole's axes, is
//     f = sum f_corner,   tau = sum p x f_corner = (sum y c, -sum x c, sum (x b - y a)).
// Which wrenches (f, tau) can they make?  Group the corners: C_R, C_L the normal forces on the
// sides x = +X and x = -X, C_T, C_B on y = +Y and y = -Y.  fz = C_R + C_L = C_T + C_B,
// tau_y = -X (C_R - C_L), tau_x = Y (C_T - C_B) fix all four:
//     C_R = (fz - tau_y / X) / 2,  C_L = (fz + tau_y / X) / 2,
//     C_T = (fz + tau_x / Y) / 2,  C_B = (fz - tau_x / Y) / 2,
// and the corners' normal forces exist (c >= 0) exactly when these four are >= 0 (a 2 x 2
// table with those margins).  The tangential parts: the b's sum to fy, those of the right side
// to B+ in [-mu C_R, mu C_R], of the left to fy - B+ in [-mu C_L, mu C_L]; tau_z's share
// X (2 B+ - fy) ranges over X [max(-mu C_R, fy - mu C_L) ... min(mu C_R, fy + mu C_L)] (times 2,
// less fy), that is [-mu X fz + |X fy - mu tau_y|, mu X fz - |X fy + mu tau_y|]; the a's, in
// the same way, give -Y (A_top - A_bottom) in [-mu Y fz + |Y fx - mu tau_x|,
// mu Y fz - |Y fx + mu tau_x|].  The a's and b's are independent, so the wrench is made exactly
// when
//     |fx| <= mu fz,  |fy| <= mu fz                         (friction on the resultant),
//     |tau_x| <= Y fz,  |tau_y| <= X fz                     (the centre of pressure in the sole),
//     tau_min <= tau_z <= tau_max,                          (yaw)
//       tau_min = -mu (X + Y) fz + |Y fx - mu tau_x| + |X fy - mu tau_y|,
//       tau_max =  mu (X + Y) fz - |Y fx + mu tau_x| - |X fy + mu tau_y|
// (Caron, Pham and Nakamura, ICRA 2015, reach the same set).  Each absolute value is the larger
// of two linear forms, so the set is 16 half-spaces: 4 of friction, 4 of the centre of pressure,
// 8 of yaw, each margin below a linear form in (f, tau), >= 0 inside.  fz >= 0 follows (the sum
// of two friction margins is 2 mu fz; with mu = 0, of two centre-of-pressure margins).
// tests/wrench_cone.cpp checks the set against its definition: an exact linear feasibility
// problem in rationals (the corner forces as combinations of the pyramid's edges) at random
// wrenches on both sides of the boundary.
//
// Friction: the pyramid |a|, |b| <= mu c lies inside Coulomb's circular cone of coefficient
// mu sqrt(2) and contains the one of coefficient mu; a verdict for a circular cone of coefficient
// mu_c that must not claim too much passes mu = mu_c / sqrt(2), rounded down.
//
// In an interval type every margin is a linear form evaluated in interval arithmetic, so it
// encloses the true margin of every wrench the enclosures hold; the verdict is that of
// reactions/contact.hpp: holds when every margin is certainly positive, fails when one is
// certainly negative, undecided otherwise.
#pragma once

#include <array>

#include "appell/scalar/traits.hpp"
#include "appell/reactions/contact.hpp"

namespace appell {

/// The 16 margins of a sole's contact wrench cone (see the top of this file), each >= 0 exactly
/// when the wrench satisfies that half-space: f and tau at the sole's centre on its axes, X and Y
/// its half-lengths, mu the pyramid's coefficient.  T: any type with + - * (a scalar of appell's,
/// or an exact rational).
template <class T>
struct wrench_cone_margins {
  std::array<T, 4> friction;  ///< mu fz -+ fx, mu fz -+ fy (forces)
  std::array<T, 4> pressure;  ///< Y fz -+ tau_x, X fz -+ tau_y (moments: the centre of pressure)
  std::array<T, 8> yaw;       ///< tau_z - tau_min's four forms, tau_max's four forms - tau_z (moments)
};

template <class T, class V>
wrench_cone_margins<T> sole_wrench_margins(const V& f, const V& tau, const T& X, const T& Y, const T& mu) {
  const T fx = f[0], fy = f[1], fz = f[2], tx = tau[0], ty = tau[1], tz = tau[2];
  wrench_cone_margins<T> m;
  const T mfz = mu * fz;
  m.friction = {T(mfz - fx), T(mfz + fx), T(mfz - fy), T(mfz + fy)};
  const T yfz = Y * fz, xfz = X * fz;
  m.pressure = {T(yfz - tx), T(yfz + tx), T(xfz - ty), T(xfz + ty)};
  // tau_z >= -mu (X + Y) fz + s1 (Y fx - mu tx) + s2 (X fy - mu ty) and
  // tau_z <=  mu (X + Y) fz - s1 (Y fx + mu tx) - s2 (X fy + mu ty), for s1, s2 = +-1.
  const T reach = mu * (X + Y) * fz;
  const T p1 = Y * fx - mu * tx, p2 = X * fy - mu * ty, q1 = Y * fx + mu * tx, q2 = X * fy + mu * ty;
  int k = 0;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1}) {
      const T a = s1 > 0 ? p1 : T(-p1), b = s2 > 0 ? p2 : T(-p2);
      m.yaw[static_cast<std::size_t>(k++)] = T(tz + reach - a - b);
      const T c = s1 > 0 ? q1 : T(-q1), d = s2 > 0 ? q2 : T(-q2);
      m.yaw[static_cast<std::size_t>(k++)] = T(reach - c - d - tz);
    }
  return m;
}

/// Every margin, in one list of 16.
template <class T>
std::array<T, 16> all_margins(const wrench_cone_margins<T>& m) {
  std::array<T, 16> r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = m.friction[i], r[4 + i] = m.pressure[i];
  for (std::size_t i = 0; i < 8; ++i) r[8 + i] = m.yaw[i];
  return r;
}

/// The verdict on a sole: holds when every margin is certainly positive, fails when one is
/// certainly negative, undecided otherwise (for point types: the comparisons on the values).
template <Scalar T>
contact_verdict judge_sole(const wrench_cone_margins<T>& m) {
  bool all_positive = true;
  for (const T& x : all_margins(m)) {
    if (certainly_negative(x)) return contact_verdict::fails;
    all_positive = all_positive && certainly_positive(x);
  }
  return all_positive ? contact_verdict::holds : contact_verdict::undecided;
}

}  // namespace appell
