// tests/independent/sphere_newton_euler.hpp -- the rolling sphere by Newton-Euler with
// contact multipliers in a fixed frame: an independent formulation (no
// trihedron, no quasi-velocities, no Appell), used by proofs/ and tests/.
//
//   M a_G = F + F_c,                      A alpha = tau + (-a n) x F_c + G_n n,
//   a_G - a alpha x n - a omega x n' = 0, alpha . n + omega . n' = 0,
// ten linear equations for a_G, alpha, the contact force F_c and the pivoting
// couple G_n; n' = +-v_G / rho (sphere), its horizontal part (cylinder), 0
// (plane), with v_G = a omega x n and rho the radius of the surface of centres.
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "appell/models/rolling_sphere.hpp"

namespace appell::independent {

template <class S>
struct sphere_contact {
  Eigen::Matrix<S, 3, 1> aG, alpha, Fc;
  S Gn;
};

/// `solve(K, rhs)` solves the 10 x 10 system in S.
template <class S, class Solve>
sphere_contact<S> sphere_newton_euler(const S& M, const S& A, const S& a, surface_type type, bool inside,
                                      const S& b, const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& w,
                                      const Eigen::Matrix<S, 3, 1>& F, const Eigen::Matrix<S, 3, 1>& tau,
                                      const Solve& solve) {
  using V = Eigen::Matrix<S, 3, 1>;
  using std::sqrt;
  auto cr = [](const V& x, const V& y) {
    return V(x(1) * y(2) - x(2) * y(1), x(2) * y(0) - x(0) * y(2), x(0) * y(1) - x(1) * y(0));
  };
  auto dt = [](const V& x, const V& y) { return S(x(0) * y(0) + x(1) * y(1) + x(2) * y(2)); };
  const S sgn = inside ? S(-1) : S(1);
  const S rho = inside ? S(b - a) : S(b + a);
  V n, ndot;
  if (type == surface_type::plane) {
    n = V(S(0), S(0), S(1));
  } else {
    const V radial = type == surface_type::sphere ? c : V(c(0), c(1), S(0));
    n = radial / sqrt(dt(radial, radial)) * sgn;
  }
  const V vG = cr(w, n) * a;
  if (type == surface_type::plane) ndot = V(S(0), S(0), S(0));
  else if (type == surface_type::sphere) ndot = vG / rho * sgn;
  else ndot = V(vG(0), vG(1), S(0)) / rho * sgn;
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> K = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>::Zero(10, 10);
  Eigen::Matrix<S, Eigen::Dynamic, 1> rhs = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(10);
  // [n]x = [[0, -n2, n1], [n2, 0, -n0], [-n1, n0, 0]]
  auto skew = [&](int row0, int col0, const S& factor) {
    K(row0 + 0, col0 + 1) += -factor * n(2);
    K(row0 + 0, col0 + 2) += factor * n(1);
    K(row0 + 1, col0 + 0) += factor * n(2);
    K(row0 + 1, col0 + 2) += -factor * n(0);
    K(row0 + 2, col0 + 0) += -factor * n(1);
    K(row0 + 2, col0 + 1) += factor * n(0);
  };
  for (int i = 0; i < 3; ++i) {
    K(i, i) = M;  // M aG - Fc = F
    K(i, 6 + i) = S(-1);
    rhs(i) = F(i);
    K(3 + i, 3 + i) = A;  // A alpha + a [n]x Fc - Gn n = tau  ((-a n) x Fc = -a [n]x Fc)
    K(3 + i, 9) = -n(i);
    rhs(3 + i) = tau(i);
    K(6 + i, i) = S(1);  // aG + a [n]x alpha = a omega x ndot
    K(9, 3 + i) = n(i);  // alpha . n = -omega . ndot
  }
  skew(3, 6, a);
  skew(6, 3, a);
  const V wn = cr(w, ndot) * a;
  for (int i = 0; i < 3; ++i) rhs(6 + i) = wn(i);
  rhs(9) = -dt(w, ndot);
  const auto x = solve(K, rhs);
  sphere_contact<S> r;
  r.aG = V(x(0), x(1), x(2));
  r.alpha = V(x(3), x(4), x(5));
  r.Fc = V(x(6), x(7), x(8));
  r.Gn = x(9);
  return r;
}

}  // namespace appell::independent
