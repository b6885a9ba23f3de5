// tests/independent/top_lagrange.hpp -- the classical top forced onto a cone psi = f(theta),
// by Lagrange's equations with a multiplier, derived by hand for the tests (the
// library uses none of it: it differentiates the top's kinematics and applies
// Cotton's method):
//   T = A/2 (theta'^2 + psi'^2 sin^2 theta) + C/2 r^2,  r = phi' + psi' cos theta,
//   V = m g l cos theta,  constraint psi' - f'(theta) theta' = 0 (multiplier H).
// R: a high-precision real type (Boost.Multiprecision mpfr_float at a fixed
// precision); f, f', f'' at theta are given by the caller, written by hand.
#pragma once

#include <Eigen/Dense>

namespace appell::independent {

template <class R>
struct top_reference {
  R theta_ddot, phi_ddot, psi_ddot, H;
  R couple[3];
  R scale;  ///< magnitude of the terms that cancel (for point-type tolerances)
};

template <class R>
top_reference<R> top_lagrange(const R& A, const R& C, const R& m, const R& l, const R& g, const R& th,
                              const R& thd, const R& phd, const R& f, const R& fp, const R& fpp) {
  using std::abs, std::sin, std::cos;
  const R s = sin(th), c = cos(th), psd = fp * thd, r = phd + psd * c;
  const R num_terms[] = {A * psd * psd * s * c, -C * r * psd * s, m * g * l * s,
                         -fp * 2 * A * s * c * thd * psd, -fp * A * s * s * fpp * thd * thd, fp * C * r * s * thd};
  R num = 0, mag = 0;
  for (const auto& t : num_terms) {
    num += t;
    mag += abs(t);
  }
  top_reference<R> out;
  out.theta_ddot = num / (A * (1 + s * s * fp * fp));
  out.psi_ddot = fpp * thd * thd + fp * out.theta_ddot;
  out.phi_ddot = psd * thd * s - out.psi_ddot * c;  // r' = 0
  out.H = 2 * A * s * c * thd * psd + A * s * s * out.psi_ddot - C * r * s * thd;
  out.scale = mag / A + abs(A * s * s * out.psi_ddot) + abs(C * r * s * thd) + abs(2 * A * s * c * thd * psd) +
              abs(out.theta_ddot) + abs(out.phi_ddot) + abs(out.psi_ddot) + abs(psd * thd) + 1;
  // Couple: Gamma . e3 = H, Gamma . e_z = 0, Gamma . (n + f' e3) = 0 (virtual work, sec. 6).
  const R sp = sin(f), cp = cos(f);
  Eigen::Matrix<R, 3, 3> K;
  K << 0, 0, 1, s * sp, -s * cp, c, cp, sp, fp;
  Eigen::Matrix<R, 3, 1> rhs(out.H, 0, 0);
  const Eigen::Matrix<R, 3, 1> G = K.partialPivLu().solve(rhs);
  for (int i = 0; i < 3; ++i) out.couple[i] = G(i);
  return out;
}

}  // namespace appell::independent
