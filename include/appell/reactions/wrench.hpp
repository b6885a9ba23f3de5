// appell/reactions/wrench.hpp -- the constraint wrench on a rigid body, from
// its virtual work (Cotton sec. 5, end; sec. 6).
//
// The forces of the added constraints do the virtual work  Q'_c . dv_c  in
// every virtual displacement of the unconstrained system (and none in the
// free speeds).  On a rigid body a couple Gamma does Gamma . dtheta, a force F
// at a point P does F . dr_P, and dtheta = J_w dv, dr_P = J_P dv.  When the
// unconstrained system is the body itself (3 speeds for a body about a fixed
// point, 6 for a free body) these equations fix the wrench:
//   J_w^T Gamma = Q'  (fixed point),    [J_P^T  J_w^T] [F; Gamma] = Q'  (free body).
#pragma once

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

/// The couple Gamma (components on the body's frame F) with J_w^T Gamma = Q'_full.
template <Scalar T>
vec3<T> constraint_couple(const body_kinematics<T>& body, const vector_t<T>& generalized_reaction) {
  if (body.Jw.cols() != 3)
    throw std::invalid_argument("constraint_couple: the unconstrained body must have 3 speeds");
  struct site;  // borrowed (linalg/scratch.hpp)
  const scratch<matrix_t<T>, site> JwT;
  const scratch<vector_t<T>, site> g;
  *JwT = body.Jw.transpose();
  solve_into<site>(*JwT, generalized_reaction, *g);
  return vec3<T>((*g)(0), (*g)(1), (*g)(2));
}

/// Force F at a point with velocity Jp u + ..., and couple Gamma: [Jp^T Jw^T][F; Gamma] = Q'_full.
template <Scalar T>
std::pair<vec3<T>, vec3<T>> constraint_wrench(const Eigen::Matrix<T, 3, Eigen::Dynamic>& Jp,
                                              const body_kinematics<T>& body,
                                              const vector_t<T>& generalized_reaction) {
  if (body.Jw.cols() != 6) throw std::invalid_argument("constraint_wrench: the unconstrained body must have 6 speeds");
  matrix_t<T> K(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) {
      K(i, j) = Jp(j, i);
      K(i, 3 + j) = body.Jw(j, i);
    }
  const vector_t<T> x = solve(K, generalized_reaction);
  return {vec3<T>(x(0), x(1), x(2)), vec3<T>(x(3), x(4), x(5))};
}

}  // namespace appell
