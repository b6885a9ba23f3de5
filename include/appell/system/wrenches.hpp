// appell/system/wrenches.hpp -- the wrenches of a system file (system_wrench_definition):
// the constraints' reactions gathered into a force at a point of one body and a couple, from
// their virtual work (Cotton sec. 5, end).
#pragma once

#include "appell/system/mechanics.hpp"

namespace appell {

/// The twist of a body at its material point P, per unit of each speed, on the
/// fixed axes (6 x n): rows 0-2 the point's velocity, rows 3-5 the angular
/// velocity, both linear in q' = W u + w (the w part, and d/dt, left out):
///   dv_P/dq'_i = dG/dq_i + sum_m da_m/dq_i e'_m x (P - G),   domega/dq'_i = sum_m da_m/dq_i e'_m.
template <Scalar T, class S>
void point_twist_jacobian_into(const compiled_system<T>& c, const typename compiled_system<T>::wrench& w, const S* v,
                               matrix_t<S>& J) {
  const int nq = c.def->vars.coordinates, n = c.def->vars.speeds;
  vec3<S> rel;
  for (int i = 0; i < 3; ++i) rel(i) = w.rel[static_cast<std::size_t>(i)].at(v);
  struct site;  // working storage borrowed (linalg/scratch.hpp)
  const scratch<std::vector<vec3<S>>, site> axes_held;
  const scratch<matrix_t<S>, site> C_held;
  detail::rotation_axes_into<T, S>(w.rotations, v, *axes_held);
  const std::vector<vec3<S>>& axes = *axes_held;
  matrix_t<S>& C = c.def->rates_as_speeds ? J : *C_held;
  C.setZero(6, nq);  // per coordinate rate
  for (int x = 0; x < 3; ++x)
    for (const auto& [i, d] : w.center[static_cast<std::size_t>(x)].dq) C(x, i) += d.at(v);
  for (std::size_t m = 0; m < w.rotations.size(); ++m) {
    const vec3<S> moved = cross(axes[m], rel);
    for (const auto& [i, d] : w.rotations[m].second.dq) {
      const S rate = d.at(v);
      for (int r = 0; r < 3; ++r) {
        C(r, i) += rate * moved(r);
        C(3 + r, i) += rate * axes[m](r);
      }
    }
  }
  if (c.def->rates_as_speeds) return;  // C is J
  J.setZero(6, n);
  for (int i = 0; i < nq; ++i)
    for (const auto& [j, wij] : c.kinematics_du[static_cast<std::size_t>(i)]) {
      const S f = wij.at(v);
      for (int r = 0; r < 6; ++r) J(r, j) += C(r, i) * f;
    }
}
template <Scalar T, class S>
matrix_t<S> point_twist_jacobian(const compiled_system<T>& c, const typename compiled_system<T>::wrench& w,
                                 const S* v) {
  matrix_t<S> J;
  point_twist_jacobian_into<T, S>(c, w, v, J);
  return J;
}

/// The normal equations of a wrench's virtual work: N = J J^T (6 x 6; 3 x 3 for a point mass's
/// force alone, J its centre's 3 rows) and J g.
template <class S>
void wrench_normal_equations_into(const matrix_t<S>& J, const vector_t<S>& g, matrix_t<S>& N, vector_t<S>& rhs) {
  const int m = static_cast<int>(J.rows());
  N.resize(m, m);
  rhs.resize(m);
  for (int r = 0; r < m; ++r) {
    for (int k = r; k < m; ++k) {
      S x = S(0);
      for (Eigen::Index j = 0; j < J.cols(); ++j) x += J(r, j) * J(k, j);
      N(r, k) = x;
      N(k, r) = x;
    }
    S y = S(0);
    for (Eigen::Index j = 0; j < J.cols(); ++j) y += J(r, j) * g(j);
    rhs(r) = y;
  }
}
template <class S>
std::pair<matrix_t<S>, vector_t<S>> wrench_normal_equations(const matrix_t<S>& J, const vector_t<S>& g) {
  matrix_t<S> N;
  vector_t<S> rhs;
  wrench_normal_equations_into(J, g, N, rhs);
  return {N, rhs};
}

template <class T>
struct constraint_wrench_result {
  vec3<T> force;   ///< on the fixed axes, applied at the wrench's point
  vec3<T> moment;  ///< about that point, on the fixed axes
  T residual;      ///< |J^T (F; M) - sum_c A_c^T Q'_c|: 0 when the wrench does the constraints' virtual work
};

/// Each wrench of the system at (q, t), from the constraints' reactions
/// (Cotton's Q'_c, one per constraint): the unique (F, M) whose virtual power
/// J_P^T F + J_w^T M is the constraints' generalized force sum_c A_c^T Q'_c
/// (the normal equations J J^T (F; M) = J g, verified for interval types).
/// S: T, or jets of T (the motion's results over a whole step).
template <Scalar T, class S = T>
void constraint_wrenches_into(const compiled_system<T>& c, const vector_t<S>& q, const S& t,
                              const vector_t<S>& reactions, std::vector<constraint_wrench_result<S>>& out) {
  out.clear();
  if (c.wrenches.empty()) return;
  const int n = c.def->vars.speeds, s = static_cast<int>(c.constraints.size());
  struct site;  // working storage borrowed (linalg/scratch.hpp)
  const scratch<vector_t<S>, site> u0, a_held, g_held, rhs_held, w_held;
  const scratch<std::vector<S>, site> x_held, values_held;
  const scratch<matrix_t<S>, site> A_held, J_held, N_held;
  u0->setZero(n);
  c.variables_into(q, *u0, t, *x_held);
  c.evaluate_into(c.constraint_tape, *x_held, *values_held);
  const std::vector<S>& values = *values_held;
  matrix_t<S>& A = *A_held;
  vector_t<S>& a = *a_held;
  A.resize(s, n), a.resize(s);
  expression_constraints<T>{&c}.template eval<S>(q, t, A, a);
  for (std::size_t k = 0; k < c.wrenches.size(); ++k) {
    const matrix_t<S>& J = *J_held;
    point_twist_jacobian_into<T, S>(c, c.wrenches[k], values.data(), *J_held);
    vector_t<S>& g = *g_held;
    g.setZero(n);
    for (int r : c.def->wrenches[k].constraints)
      for (int j = 0; j < n; ++j) g(j) += A(r, j) * reactions(r);
    wrench_normal_equations_into(J, g, *N_held, *rhs_held);
    const vector_t<S>& w = *w_held;
    solve_spd_into<site>(*N_held, *rhs_held, *w_held);
    S sq = S(0);
    for (int j = 0; j < n; ++j) {
      S e = -g(j);
      for (int r = 0; r < 6; ++r) e += J(r, j) * w(r);
      sq += sqr(e);
    }
    using std::sqrt;
    out.push_back({vec3<S>(w(0), w(1), w(2)), vec3<S>(w(3), w(4), w(5)), S(sqrt(sq))});
  }
}
template <Scalar T, class S = T>
std::vector<constraint_wrench_result<S>> constraint_wrenches(const compiled_system<T>& c, const vector_t<S>& q,
                                                             const S& t, const vector_t<S>& reactions) {
  std::vector<constraint_wrench_result<S>> out;
  constraint_wrenches_into(c, q, t, reactions, out);
  return out;
}

}  // namespace appell
