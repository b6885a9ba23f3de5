// proofs/eq9.hpp -- Cotton's eq. (9) as printed (paper sec. 4), written out by
// hand in the paper's symbols and nothing else: no library function, no matrix,
// no cross product.  It is the reference the proofs compare the library with.
//
// A free solid of mass M referred to axes Gxyz through its centre of gravity
// that move relative to the solid and to space.  P, Q, R: the rotation of the
// trihedron Gxyz; p, q, r: the rotation of the solid; u, v, w: the velocity of
// G (all projected on the moving axes); A, B, C, D, E, F: moments and products
// of inertia on the axes, which may vary with time, in the paper's convention
//   2T_r = A p^2 + B q^2 + C r^2 - 2D q r - 2E r p - 2F p q,
// i.e. the inertia tensor is [[A, -F, -E], [-F, B, -D], [-E, -D, C]];
//   sigma_x = dT_r/dp,  sigma_y = dT_r/dq,  sigma_z = dT_r/dr,
// and d sigma/dt differentiates A..F too.  Then (9):
//   S = M[u'(u' + Qw - Rv) + v'(v' + Ru - Pw) + w'(w' + Pv - Qu)]
//     + p'(d sigma_x/dt + Q sigma_z - R sigma_y) + q'(d sigma_y/dt + R sigma_x - P sigma_z)
//     + r'(d sigma_z/dt + P sigma_y - Q sigma_x)
//     - 1/2 [M(u'^2 + v'^2 + w'^2) + A p'^2 + B q'^2 + C r'^2 - 2D q'r' - 2E r'p' - 2F p'q']
//     + ...                                   (terms free of u', ..., r': S0, not written)
// Every written term holds an acceleration, so what is returned is exactly the
// useful part S2 + S1 (Cotton: "les termes utiles").
//
// Misprint corrected: the OCR text prints "Q omega" and "P omega" in the first
// line of (9) (u'(u' + Q omega - R v), v'(v' + R u - P omega)); omega there is
// the speed w of G, as in (21) (docs/design.md §4 lists it for (21) only; (9)
// has the same one).  Nothing else in (9) differs from a derivation: by
// Euler's theorem (6), u' P_1 + ... + r' P_6 = 2 S2 + S1 with P_1..P_6 the left
// sides of (7) and (8), which are the M[...] and p'(...) + q'(...) + r'(...)
// groups above; S2 = 1/2 [M(u'^2 + v'^2 + w'^2) + A p'^2 + ... - 2F p'q'] (the
// kinetic energy's form in the accelerations), the bracket of the last line;
// so S2 + S1 = (those groups) - S2, which is (9).
#pragma once

namespace appell::proof {

/// A state of the paper's sec. 4 solid, in the paper's symbols.
template <class T>
struct cotton_sec4_state {
  T M;                       ///< mass
  T P, Q, R;                 ///< rotation of the trihedron Gxyz
  T u, v, w;                 ///< velocity of G
  T p, q, r;                 ///< rotation of the solid
  T A, B, C, D, E, F;        ///< moments and products of inertia on the axes
  T dA, dB, dC, dD, dE, dF;  ///< their time derivatives A', ..., F' (0 when constant)
};

/// Cotton's eq. (9): the useful part of S at the accelerations
/// u' = up, v' = vp, w' = wp, p' = pp, q' = qp, r' = rp ("p" for prime).
template <class T>
T cotton_eq9(const cotton_sec4_state<T>& s, const T& up, const T& vp, const T& wp, const T& pp, const T& qp,
             const T& rp) {
  const T &M = s.M, &P = s.P, &Q = s.Q, &R = s.R;
  const T &u = s.u, &v = s.v, &w = s.w, &p = s.p, &q = s.q, &r = s.r;
  const T &A = s.A, &B = s.B, &C = s.C, &D = s.D, &E = s.E, &F = s.F;
  // sigma = grad of T_r = 1/2 (A p^2 + B q^2 + C r^2) - D q r - E r p - F p q
  const T sx = A * p - F * q - E * r;
  const T sy = B * q - D * r - F * p;
  const T sz = C * r - E * p - D * q;
  // d sigma/dt: the rates p', q', r' and the rates A', ..., F'
  const T dsx = A * pp - F * qp - E * rp + s.dA * p - s.dF * q - s.dE * r;
  const T dsy = B * qp - D * rp - F * pp + s.dB * q - s.dD * r - s.dF * p;
  const T dsz = C * rp - E * pp - D * qp + s.dC * r - s.dE * p - s.dD * q;
  const T first = M * (up * (up + Q * w - R * v) + vp * (vp + R * u - P * w) + wp * (wp + P * v - Q * u));
  const T second = pp * (dsx + Q * sz - R * sy) + qp * (dsy + R * sx - P * sz) + rp * (dsz + P * sy - Q * sx);
  const T third = M * (up * up + vp * vp + wp * wp) + A * pp * pp + B * qp * qp + C * rp * rp -
                  2 * D * qp * rp - 2 * E * rp * pp - 2 * F * pp * qp;
  return first + second - third / 2;
}

}  // namespace appell::proof
