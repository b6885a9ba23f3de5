// tests/independent/top_on_pivot.hpp -- the heavy symmetric top on its pivot, derived by hand
// for the tests (the library uses none of it: it differentiates the top's kinematics, forms
// Appell's equations and Cotton's reaction of the pivot):
//   the accelerations from Lagrange's equations of the symmetric top,
//     A theta'' = A psi'^2 s c - C r psi' s + m g l s,
//     A s psi'' = C r theta' - 2 A psi' theta' c,   r' = 0 (phi'' = -psi'' c + psi' theta' s),
//   with s = sin theta, c = cos theta, r = phi' + psi' c, and A the moment about O;
//   the pivot force by Newton-Euler: F = m a_G + m g e3, a_G = l (omega' x e_z + omega x (omega x e_z)).
// R: a high-precision real type (Boost.Multiprecision MPFR at a fixed precision).
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace appell::independent {

template <class R>
struct top_on_pivot_reference {
  R theta_ddot, phi_ddot, psi_ddot, force[3];
  R scale;  ///< magnitude of the terms that cancel (for point-type tolerances)
};

template <class R>
top_on_pivot_reference<R> top_on_pivot_by_hand(const R& A, const R& C, const R& m, const R& l, const R& g, const R& ps,
                                                const R& th, const R& psd, const R& thd, const R& phd) {
  using std::abs, std::sin, std::cos;
  const R s = sin(th), c = cos(th), sp = sin(ps), cp = cos(ps), r = phd + psd * c;
  top_on_pivot_reference<R> out;
  const R t1 = A * psd * psd * s * c, t2 = -C * r * psd * s, t3 = m * g * l * s;
  out.theta_ddot = (t1 + t2 + t3) / A;
  const R u1 = C * r * thd, u2 = -2 * A * psd * thd * c;
  out.psi_ddot = (u1 + u2) / (A * s);
  out.phi_ddot = -out.psi_ddot * c + psd * thd * s;
  using v3 = Eigen::Matrix<R, 3, 1>;
  const v3 e3(0, 0, 1), n(cp, sp, 0), ez(s * sp, -s * cp, c);
  const v3 w = e3 * psd + n * thd + ez * phd;
  const v3 wdot = e3 * out.psi_ddot + n * out.theta_ddot + e3.cross(n) * (thd * psd) + ez * out.phi_ddot +
                  w.cross(ez) * phd;
  const v3 aG = (wdot.cross(ez) + w.cross(w.cross(ez))) * l;
  const v3 F = aG * m + e3 * (m * g);
  for (int i = 0; i < 3; ++i) out.force[i] = F(i);
  out.scale = (abs(t1) + abs(t2) + abs(t3)) / A + (abs(u1) + abs(u2)) / (A * abs(s)) + abs(out.theta_ddot) +
              abs(out.psi_ddot) + abs(out.phi_ddot) + abs(psd * thd) + m * (g + abs(l) * (w.squaredNorm() + wdot.norm())) +
              1;
  return out;
}

}  // namespace appell::independent
