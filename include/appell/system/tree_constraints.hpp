// appell/system/tree_constraints.hpp -- Cotton's method on a tree of links with constraints: the
// tree's recursions give M, b, Q in the joints' rates (system/tree.hpp), the constraints'
// rows give the adapted speeds, and the k free accelerations come from a k x k system.
//
// The constraints A(q,t) u = a(q,t) (s rows: a robot's feet held by the ground, a user's own)
// are solved, as adapted_change does (dynamics/speeds.hpp), for s bound components u_B of u in
// terms of the k = n - s free ones u_F (Cotton's v_a) and of v_c = A u - a:
//      A_B u_B = v_c + a - A_F u_F.
// Along the motion v_c = 0 and v_c' = 0, so  A u' + h = 0  with  h = d/dt (A u - a) at fixed u
// (one dual pass through the constraints, q' and t' seeded), and with
//      X = A_B^-1 A_F (s x k),  y = -A_B^-1 h (s),
// every acceleration follows from the free ones:  u'_F = v',  u'_B = y - X v',  u' = C v' + e
// (C = du/dv_a: the identity on F and -X on B; e: y on B).  Appell's equations of the
// constrained system (Cotton's eq. 12-13) are those of the tree projected on C:
//      (C^T M C) v' = C^T (Q - b - M e),
// and Cotton's reactions (eq. 14), Q'_c = dS/dv_c' - Q_c, are the tree's equations' residual
// carried to v_c: u depends on v_c through u_B only (du_B/dv_c = A_B^-1), so
//      A_B^T Q'_c = (M u' + b - Q)_B,
// the Lagrange multipliers of  M u' + b = Q + A^T lambda  (reactions/lagrange.hpp).
//
// Cost: the recursions' O(N d), then O(n s k) for C^T M C and O(k^3) for its solve, where the
// generic path (dynamics/gibbs_appell.hpp on the adapted system) differentiates every body in
// every speed: O(n^3) and more.  A standing humanoid (n = 33, s = 12) is evaluated and its
// motion enclosed at any size (the generic path's slopes stop at 12 components).
// tests/tree_recursions.cpp holds this path to the generic path's Cotton reactions (double to
// within its precision; interval and MPFI enclosing 256-bit MPFR).
#pragma once

#include <vector>

#include "appell/derivatives/dual.hpp"
#include "appell/linalg/scratch.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/system/mechanics.hpp"
#include "appell/system/tree.hpp"

namespace appell {

/// Whether a system with constraints takes the tree's recursions with Cotton's method above:
/// a tree of links in its joints' rates (tree_links_apply) with at least one constraint.
template <Scalar T>
bool tree_constraints_apply(const compiled_system<T>& c) {
  return !c.constraints.empty() && tree_links_apply(c);
}

/// What tree_cotton_into leaves besides u': the tree's equations (in the original speeds), the
/// free accelerations and, where asked, the reactions and du = C 1 (eq. (4)'s displacement).
template <class S>
struct tree_cotton_result {
  appell_equations<S> equations;  ///< M, b, Q of the tree without its constraints, at (q, u, t)
  vector_t<S> free_accelerations;  ///< v' = u'_F, in the order of the free columns
  vector_t<S> reactions;          ///< Q'_c (empty unless asked)
  vector_t<S> unit_displacement;  ///< du for dv = (1, ..., 1) in the adapted speeds (empty unless asked)
};

/// What to compute beyond v' and u'.
struct tree_cotton_asks {
  bool reactions = false;
  bool unit_displacement = false;
};

/// Cotton's method on a tree of links (tree_constraints_apply) at (q, u, t), u consistent with
/// the constraints, the free and bound columns fixed at the state (adapt_speeds): u' into udot
/// and the rest into r.  S: T, or numbers built on T (jets, slopes) for the motion.
template <Scalar T, class S>
void tree_cotton_into(const compiled_system<T>& c, const std::vector<int>& free_columns,
                      const std::vector<int>& bound_columns, const vector_t<S>& q, const vector_t<S>& u,
                      const S& t, tree_cotton_asks asks, vector_t<S>& udot, tree_cotton_result<S>& r) {
  const expression_constraints<T> con{&c};
  const expression_system<T> sys{&c};
  const int n = sys.speeds(), s = con.count(), k = n - s;
  if (static_cast<int>(free_columns.size()) != k || static_cast<int>(bound_columns.size()) != s)
    throw std::logic_error("tree_cotton_into: the free and bound columns do not split the speeds");
  tree_equations_into<T, S>(c, q, u, t, r.equations);
  const appell_equations<S>& e = r.equations;
  struct site;  // this function's pools (linalg/scratch.hpp: an Eigen object keeps one size)
  using D = dual<S>;
  const scratch<vector_t<S>, site> qd_held, y_held, g_held, rr_held;
  const scratch<vector_t<D>, site> qs_held, ad_held;
  const scratch<matrix_t<D>, site> Ad_held;
  const scratch<matrix_t<S>, site> W_held, MC_held, Mr_held;
  vector_t<S>&qd = *qd_held, &y = *y_held, &g = *g_held, &rr = *rr_held;
  vector_t<D>&qs = *qs_held, &ad = *ad_held;
  matrix_t<D>& Ad = *Ad_held;
  matrix_t<S>&W = *W_held, &MC = *MC_held, &Mr = *Mr_held;
  // A, a and h = A' u - a' in one dual pass (q' = the rates at u, t' = 1): the values are A, a.
  sys.template qdot_into<S>(q, u, t, qd);
  qs.resize(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) qs(i) = D(q(i), qd(i));
  Ad.resize(s, n), ad.resize(s);
  con.template eval<D>(qs, D(t, S(1)), Ad, ad);
  // W = [A_B | A_F | -h | 1]: eliminated in the bound columns' order (adapt_speeds chose them by
  // pivoting, largest first), exactly-zero entries skipped as adapted_change does.
  const int extra = asks.unit_displacement ? 1 : 0;
  const int cols = s + k + 1 + extra;
  W.resize(s, cols);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) W(i, j) = Ad(i, bound_columns[static_cast<std::size_t>(j)]).v;
    for (int j = 0; j < k; ++j) W(i, s + j) = Ad(i, free_columns[static_cast<std::size_t>(j)]).v;
    S h = -ad(i).d;
    for (int j = 0; j < n; ++j)
      if (!structurally_zero(Ad(i, j).d)) h += Ad(i, j).d * u(j);
    W(i, s + k) = -h;
    if (extra) W(i, s + k + 1) = S(1);
  }
  for (int p = 0; p < s; ++p)
    for (int i = p + 1; i < s; ++i) {
      if (structurally_zero(W(i, p))) continue;
      const S f = W(i, p) / W(p, p);
      for (int j = p + 1; j < cols; ++j)
        if (!structurally_zero(W(p, j))) W(i, j) -= f * W(p, j);
      W(i, p) = S(0);
    }
  for (int p = s - 1; p >= 0; --p) {  // back substitution: W's right part becomes A_B^-1 [A_F | -h | 1]
    for (int j = s; j < cols; ++j) {
      S x = W(p, j);
      for (int m = p + 1; m < s; ++m)
        if (!structurally_zero(W(p, m))) x -= W(p, m) * W(m, j);
      W(p, j) = structurally_one(W(p, p)) ? x : S(x / W(p, p));
    }
  }
  // X = W(:, s .. s+k-1), y = W(:, s+k).  e's part of the right-hand side: g = Q - b - M_:B y.
  y.resize(s);
  for (int i = 0; i < s; ++i) y(i) = W(i, s + k);
  g.resize(n);
  for (int i = 0; i < n; ++i) {
    S x = e.Q(i) - e.b(i);
    for (int m = 0; m < s; ++m) x -= e.M(i, bound_columns[static_cast<std::size_t>(m)]) * y(m);
    g(i) = x;
  }
  // MC = M C (n x k): column j is M's free column j minus its bound columns times X(:, j).
  MC.resize(n, k);
  for (int j = 0; j < k; ++j) {
    const int fj = free_columns[static_cast<std::size_t>(j)];
    for (int i = 0; i < n; ++i) {
      S x = e.M(i, fj);
      for (int m = 0; m < s; ++m)
        if (!structurally_zero(W(m, s + j))) x -= e.M(i, bound_columns[static_cast<std::size_t>(m)]) * W(m, s + j);
      MC(i, j) = x;
    }
  }
  // C^T M C (symmetric: the lower triangle formed, mirrored) and C^T g.
  Mr.resize(k, k), rr.resize(k);
  for (int i = 0; i < k; ++i) {
    const int fi = free_columns[static_cast<std::size_t>(i)];
    for (int j = 0; j <= i; ++j) {
      S x = MC(fi, j);
      for (int m = 0; m < s; ++m)
        if (!structurally_zero(W(m, s + i))) x -= W(m, s + i) * MC(bound_columns[static_cast<std::size_t>(m)], j);
      Mr(i, j) = x;
      if (j < i) Mr(j, i) = x;
    }
    S x = g(fi);
    for (int m = 0; m < s; ++m)
      if (!structurally_zero(W(m, s + i))) x -= W(m, s + i) * g(bound_columns[static_cast<std::size_t>(m)]);
    rr(i) = x;
  }
  solve_spd_into<site>(Mr, rr, r.free_accelerations);
  const vector_t<S>& v = r.free_accelerations;
  udot.resize(n);
  for (int j = 0; j < k; ++j) udot(free_columns[static_cast<std::size_t>(j)]) = v(j);
  for (int m = 0; m < s; ++m) {
    S x = y(m);
    for (int j = 0; j < k; ++j)
      if (!structurally_zero(W(m, s + j))) x -= W(m, s + j) * v(j);
    udot(bound_columns[static_cast<std::size_t>(m)]) = x;
  }
  if (asks.unit_displacement) {  // du = C 1_k + (du/dv_c) 1_s:  1 on F;  A_B^-1 1 - X 1 on B
    r.unit_displacement.resize(n);
    for (int j = 0; j < k; ++j) r.unit_displacement(free_columns[static_cast<std::size_t>(j)]) = S(1);
    for (int m = 0; m < s; ++m) {
      S x = W(m, s + k + 1);
      for (int j = 0; j < k; ++j) x -= W(m, s + j);
      r.unit_displacement(bound_columns[static_cast<std::size_t>(m)]) = x;
    }
  } else {
    r.unit_displacement.resize(0);
  }
  if (!asks.reactions) {
    r.reactions.resize(0);
    return;
  }
  // A_B^T Q'_c = (M u' + b - Q)_B, solved anew (verified for the interval scalars; the jets'
  // and slopes' own solves along the motion, as the generic path's reactions).
  const scratch<matrix_t<S>, site> AbT_held;
  const scratch<vector_t<S>, site> P_held;
  matrix_t<S>& AbT = *AbT_held;
  vector_t<S>& P = *P_held;
  AbT.resize(s, s), P.resize(s);
  for (int i = 0; i < s; ++i) {
    const int bi = bound_columns[static_cast<std::size_t>(i)];
    for (int j = 0; j < s; ++j) AbT(i, j) = Ad(j, bi).v;
    S x = e.M(bi, 0) * udot(0);
    for (int j = 1; j < n; ++j) x += e.M(bi, j) * udot(j);
    P(i) = x + e.b(bi) - e.Q(bi);
  }
  solve_into<site>(AbT, P, r.reactions);
}

}  // namespace appell
