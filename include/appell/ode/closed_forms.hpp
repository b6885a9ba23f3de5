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

}  // namespace appell::ode
