// tests/independent/hand_derived.hpp -- the paper's scenes written out by hand: the
// accelerations and reactions in closed form, the yardstick of the generic Gibbs-Appell path
// (bench/generic.cpp times them against it).
//
// Each function takes the same inputs as the model's result function and
// returns the same results, plus one cheap check of the kind the generic path
// carries (a power balance).  Nothing here uses the library's dynamics: no
// dual numbers, no M, b, Q, no constraint elimination.  tests/generic_path.cpp
// compares every closed form with `appell eval`'s results at 256 bits (mpfi
// enclosures) and on random states, so the ratios compare equal work.
#pragma once

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/rolling_sphere.hpp"

namespace appell::independent {

// ---------------------------------------------------------------------------
// Euler's body (paper sec. 3): Euler's equations and the power balance.
template <Scalar T>
struct euler_result {
  vec3<T> omega_dot;
  T power_residual;
};
template <Scalar T>
euler_result<T> euler(const euler_body<T>& body, const vec3<T>& omega) {
  const vec3<T> wd = euler_omega_dot(body, omega);
  return {wd, euler_power_residual(body, omega, wd)};
}

// ---------------------------------------------------------------------------
// The rolling sphere (paper sec. 7) by Newton-Euler, eliminated by hand.
// Unknowns a_G, alpha, the contact force F_c at the contact point and the
// pivoting couple G_n n, with n the unit normal from the contact point to G:
//   M a_G = F + F_c,   A alpha = tau - a n x F_c + G_n n,
//   a_G = a alpha x n + a omega x n',   alpha . n = -omega . n'   (no slip, no pivot).
// Split alpha = alpha_t + alpha_n n.  Then alpha_n = -omega . n', G_n = A alpha_n - tau . n,
// and with n x (alpha_t x n) = alpha_t:
//   (A + M a^2) alpha_t = tau_t + a n x F - M a^2 n x (omega x n'),
// after which a_G and F_c follow.  n' = +-v_G / rho (sphere), its horizontal
// part (cylinder), 0 (plane); v_G = a omega x n.
template <Scalar T>
struct sphere_result {
  vec3<T> center_ddot, omega_dot, contact_force;
  T normal_force, pivot_couple, tangential_force;
  T power_residual;  ///< M v.a + A omega.alpha - F.v - tau.omega: the contact does no work
};
template <Scalar T>
sphere_result<T> rolling_sphere(const T& M, const T& A, const T& a, const rolling_surface<T>& surface,
                                const vec3<T>& c, const vec3<T>& omega, const vec3<T>& F, const vec3<T>& tau) {
  using std::sqrt;
  const vec3<T> n = surface.normal(c);
  const vec3<T> v = cross(omega, n) * a;
  vec3<T> nd = vec3<T>::Zero();
  if (surface.type == surface_type::sphere) nd = v * (surface.sign() / surface.rho(a));
  if (surface.type == surface_type::cylinder) nd = vec3<T>(v(0), v(1), T(0)) * (surface.sign() / surface.rho(a));
  const T alpha_n = -dot(omega, nd);
  const T tau_n = dot(tau, n);
  const T Ma2 = M * a * a;
  const vec3<T> alpha_t = (tau - n * tau_n + cross(n, F) * a - cross(n, cross(omega, nd)) * Ma2) / (A + Ma2);
  sphere_result<T> r;
  r.omega_dot = alpha_t + n * alpha_n;
  r.center_ddot = (cross(alpha_t, n) + cross(omega, nd)) * a;
  r.contact_force = r.center_ddot * M - F;
  r.normal_force = dot(r.contact_force, n);
  r.pivot_couple = A * alpha_n - tau_n;
  const vec3<T> Ft = r.contact_force - n * r.normal_force;
  r.tangential_force = sqrt(dot(Ft, Ft));
  r.power_residual = M * dot(v, r.center_ddot) + A * dot(omega, r.omega_dot) - dot(F, v) - dot(tau, omega);
  return r;
}

// ---------------------------------------------------------------------------
// Example I (paper sec. 6): the heavy symmetric top (A about O, C, m g l) on the
// cone psi = f(theta), by Lagrange's equations with a multiplier H:
//   T = A/2 (theta'^2 + psi'^2 sin^2) + C/2 r^2,  r = phi' + psi' cos theta,  V = m g l cos theta,
//   psi' = f' theta';  theta'' = N / (A (1 + f'^2 sin^2)), r' = 0,
// H the moment of the constraint couple about the vertical, the couple itself
// from  Gamma . e3 = H, Gamma . e_z = 0, Gamma . (n + f' e3) = 0  (its virtual
// work), solved by hand (determinant sin theta).  Check: d/dt (T + V) = 0.
template <Scalar T>
struct top_result {
  T theta_ddot, phi_ddot, psi_ddot, H;
  vec3<T> couple;
  T energy_rate;
};
/// f, f', f'' of the cone at theta, given by the caller.
template <Scalar T>
top_result<T> top_on_cone(const T& A, const T& C, const T& m, const T& l, const T& g, const T& th, const T& thd,
                          const T& phd, const T& f, const T& fp, const T& fpp) {
  T s, c, sp, cp;
  sin_cos(th, s, c);
  sin_cos(f, sp, cp);
  const T psd = fp * thd, r = phd + psd * c, mgl = m * g * l;
  const T num = A * psd * psd * s * c - C * r * psd * s + mgl * s - fp * T(2) * A * s * c * thd * psd -
                fp * A * s * s * fpp * thd * thd + fp * C * r * s * thd;
  top_result<T> o;
  o.theta_ddot = num / (A * (T(1) + s * s * fp * fp));
  o.psi_ddot = fpp * thd * thd + fp * o.theta_ddot;
  o.phi_ddot = psd * thd * s - o.psi_ddot * c;
  o.H = T(2) * A * s * c * thd * psd + A * s * s * o.psi_ddot - C * r * s * thd;
  // [s sp, -s cp; cp, sp] (G0, G1) = (-c H, -f' H), G2 = H
  o.couple = vec3<T>((-c * o.H * sp - s * cp * fp * o.H) / s, (c * cp * o.H - s * sp * fp * o.H) / s, o.H);
  o.energy_rate = A * (thd * o.theta_ddot + psd * o.psi_ddot * s * s + psd * psd * s * c * thd) - mgl * s * thd;
  return o;
}

/// Example I's cone psi = f(theta) = theta / 2 + sin(2 theta) / 10, written by hand, its
/// constants converted to T once (as the generic path's compiled expression has them): a
/// cone for top_on_cone_motion (f' on scalars and duals, f''), and all three of f, f', f''
/// from one sin_cos for the closed form.
template <Scalar T>
struct example_one_cone {
  T half = rational<T>(1, 2), tenth = rational<T>(1, 10), fifth = rational<T>(1, 5), two_fifths = rational<T>(2, 5);
  T f(const T& th) const {
    using std::sin;
    return half * th + tenth * sin(T(th * T(2)));
  }
  template <class S>
  S fprime(const S& th) const {
    using std::cos;
    return S(half) + S(fifth) * cos(S(th * S(2)));
  }
  T fsecond(const T& th) const {
    using std::sin;
    return -(two_fifths * sin(T(th * T(2))));
  }
  void all(const T& th, T& f, T& fp, T& fpp) const {
    T s2, c2;
    sin_cos(T(th * T(2)), s2, c2);
    f = th * half + s2 * tenth;
    fp = half + c2 * fifth;
    fpp = -(s2 * two_fifths);
  }
};

}  // namespace appell::independent
