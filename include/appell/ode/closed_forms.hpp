// Motions known in closed form, as independent truth for the Taylor integrator
// (tests/motion*.cpp) and for the long-horizon study (appell horizon).
// Templated over a real type R on which Boost.Math's elliptic functions run
// (mpfr_float at 256 bits in the study; mpfr_float_100 in the tests).
#pragma once

#include <array>
#include <stdexcept>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

namespace appell::ode {

/// Euler's free body with I1 < I2 < I3 and omega(0) = (a, 0, c) with M^2 > 2 E I2
/// (Landau & Lifshitz, Mechanics, sec. 37):
///   omega1 = a cn(tau, k), omega2 = b sn(tau, k), omega3 = c dn(tau, k), tau = rate t,
/// with 2E = I1 a^2 + I3 c^2, M^2 = I1^2 a^2 + I3^2 c^2, b^2 = (2E I3 - M^2) / (I2 (I3 - I2)),
/// rate^2 = (I3 - I2)(M^2 - 2E I1) / (I1 I2 I3), k^2 = (I2 - I1)(2E I3 - M^2) / ((I3 - I2)(M^2 - 2E I1)).
/// The sign of omega2's start (b > 0 here) follows from Euler's equation I2 omega2' = (I3 - I1) omega3 omega1 > 0.
template <class R>
struct euler_free_body_solution {
  R I1, I2, I3, a, c;

  static bool applies(const R& I1, const R& I2, const R& I3, const R& a, const R& c) {
    return I1 < I2 && I2 < I3 && a > 0 && c > 0 && I1 * (I1 - I2) * a * a + I3 * (I3 - I2) * c * c > 0;
  }
  euler_free_body_solution(R i1, R i2, R i3, R a0, R c0)
      : I1(std::move(i1)), I2(std::move(i2)), I3(std::move(i3)), a(std::move(a0)), c(std::move(c0)) {
    if (!applies(I1, I2, I3, a, c))
      throw std::invalid_argument("euler_free_body_solution: needs I1 < I2 < I3, omega(0) = (a, 0, c), a, c > 0, M^2 > 2 E I2");
  }
  R twice_energy() const { return I1 * a * a + I3 * c * c; }
  R momentum_squared() const { return I1 * I1 * a * a + I3 * I3 * c * c; }
  R rate() const {
    using std::sqrt;
    return sqrt((I3 - I2) * (momentum_squared() - twice_energy() * I1) / (I1 * I2 * I3));
  }
  R modulus() const {
    using std::sqrt;
    const R E2 = twice_energy(), M2 = momentum_squared();
    return sqrt((I2 - I1) * (E2 * I3 - M2) / ((I3 - I2) * (M2 - E2 * I1)));
  }
  /// The period of omega: 4 K(k) / rate.
  R period() const { return 4 * boost::math::ellint_1(modulus()) / rate(); }
  std::array<R, 3> at(const R& t) const {
    using std::sqrt;
    const R E2 = twice_energy(), M2 = momentum_squared();
    const R b = sqrt((E2 * I3 - M2) / (I2 * (I3 - I2)));
    R cn, dn;
    const R sn = boost::math::jacobi_elliptic(modulus(), rate() * t, &cn, &dn);
    return {a * cn, b * sn, c * dn};
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

/// The nutation of the heavy symmetric top on its pivot (A about the pivot, C about the axis,
/// m g l; Euler angles psi precession, theta nutation, phi spin), from its three first integrals:
/// with u = cos theta, a = C r / A (r = phi' + psi' cos theta), b = (A psi' sin^2 theta + C r cos theta) / A,
/// alpha = (A (theta'^2 + psi'^2 sin^2 theta) + 2 m g l cos theta) / A and beta = 2 m g l / A,
///   u'^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2 = beta (u - u1)(u - u2)(u - u3),
/// u1 <= u2 in [-1, 1] <= u3, and  u(t) = u1 + (u2 - u1) sn^2(lambda t + c, k),
/// k^2 = (u2 - u1) / (u3 - u1), lambda = sqrt(beta (u3 - u1)) / 2 (substituting gives
/// u'^2 = 4 lambda^2 (u2 - u1)^2 sn^2 cn^2 dn^2 = f(u)); c from u(0) and the sign of u'(0).
/// theta = acos u, theta' = -u' / sin theta.  (psi and phi need elliptic integrals of the
/// third kind: not given.)  Requires m g l > 0 and u2 > u1 (not a steady precession).
template <class R>
struct heavy_top_nutation {
  R u1, u2, u3, lambda, k, c;

  heavy_top_nutation(const R& A, const R& C, const R& mgl, const R& theta0, const R& psi_dot0, const R& theta_dot0,
                     const R& phi_dot0) {
    using std::cos, std::sin, std::sqrt, std::asin;
    const R u0 = cos(theta0), s0 = sin(theta0);
    const R r = phi_dot0 + psi_dot0 * u0;
    const R a = C * r / A, b = (A * psi_dot0 * s0 * s0 + C * r * u0) / A;
    const R alpha = (A * (theta_dot0 * theta_dot0 + psi_dot0 * psi_dot0 * s0 * s0) + 2 * mgl * u0) / A;
    const R beta = 2 * mgl / A;
    if (!(beta > 0)) throw std::invalid_argument("heavy_top_nutation: needs m g l > 0");
    // f(u) = beta u^3 + c2 u^2 + c1 u + c0
    const R c2 = -(alpha + a * a), c1 = 2 * a * b - beta, c0 = alpha - b * b;
    auto f = [&](const R& u) { return ((beta * u + c2) * u + c1) * u + c0; };
    // u3 >= 1: f(1) = -(b - a)^2 <= 0 and f grows without bound; bisection.
    R lo = 1, hi = 2;
    while (f(hi) <= 0) hi *= 2;
    for (int i = 0; i < 2000 && lo < hi; ++i) {
      const R m = (lo + hi) / 2;
      if (m <= lo || m >= hi) break;
      (f(m) > 0 ? hi : lo) = m;
    }
    u3 = hi;
    // f(u) = (u - u3)(beta u^2 + e1 u + e0)
    const R e1 = c2 + beta * u3, e0 = c1 + e1 * u3;
    const R disc = e1 * e1 - 4 * beta * e0;
    if (!(disc > 0)) throw std::invalid_argument("heavy_top_nutation: steady precession (no nutation)");
    u1 = (-e1 - sqrt(disc)) / (2 * beta);
    u2 = (-e1 + sqrt(disc)) / (2 * beta);
    k = sqrt((u2 - u1) / (u3 - u1));
    lambda = sqrt(beta * (u3 - u1)) / 2;
    // u(0) = u0: sn^2(c) = (u0 - u1) / (u2 - u1), clamped to [0, 1] against the last bits.
    R q = (u0 - u1) / (u2 - u1);
    if (q < 0) q = 0;
    if (q > 1) q = 1;
    const R F = boost::math::ellint_1(k, asin(sqrt(q)));
    // u' = -sin(theta) theta': sn^2 rises on (0, K), falls on (K, 2K).
    const R uprime = -s0 * theta_dot0;
    c = uprime >= 0 ? F : 2 * boost::math::ellint_1(k) - F;
  }
  /// The period of the nutation: 2 K(k) / lambda.
  R period() const { return 2 * boost::math::ellint_1(k) / lambda; }
  /// (theta, theta') at t.
  std::array<R, 2> at(const R& t) const {
    using std::acos, std::sin;
    R cn, dn;
    const R sn = boost::math::jacobi_elliptic(k, lambda * t + c, &cn, &dn);
    const R u = u1 + (u2 - u1) * sn * sn;
    const R uprime = 2 * lambda * (u2 - u1) * sn * cn * dn;
    const R theta = acos(u);
    return {theta, -uprime / sin(theta)};
  }
};

}  // namespace appell::ode
