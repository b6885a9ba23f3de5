// appell/system/linearize.hpp -- the linearized equations of a system file
// about a steady motion (`appell linearize`; the "linearize" section of a
// system file, SCENES.md).
//
// Chosen coordinates q_l (m of them; their rates are speeds of the file), the
// rest of the state held, the coordinates that the holonomic constraints
// determine (q_d) and the speeds solved from the constraints (solve_speeds)
// following.  The accelerations of the q_l are differentiated with respect to
// q_l and q_l' by running the generic path itself (Cotton's reactions in the
// speeds adapted to the constraints, or Lagrange's multipliers for the
// cross-check) on multi_dual numbers: the derivatives are exact, and enclosed
// as rigorously as the values in interval types (no finite differences):
//   dq_d = -F_d^-1 F_l dq_l          (F = df/dq of the holonomic constraints),
//   dependent speeds: the constraints solved on duals (dual_solve.hpp),
//   u' and its derivatives: Cotton's method on duals.
// The linearized equations are written in the benchmark form of Meijaard et
// al. (2007) for a reference speed v (one of the given speeds) and gravity g
// (a parameter):
//   M q_l'' + v C1 q_l' + (g K0 + v^2 K2) q_l = f,
// where M is the mass matrix of the q_l in Cotton's free speeds (the Schur
// complement of the other free speeds: M^-1 is the block of M_aa^-1), f the
// generalized forces on the q_l, and
//   g K0 + v^2 K2 = -M d(q_l'')/dq_l,   v C1 = -M d(q_l'')/dq_l'.
// K0, K2 and C1 come from the Jacobians at v = 0 and at the state's speed v0;
// a third evaluation at 2 v0 checks that the dependence on v has that form
// (the residuals are results: they must hold 0).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "appell/derivatives/dual_solve.hpp"
#include "appell/system/polynomial.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/system/motion.hpp"

namespace appell {

/// What to linearize, scalar-free (read from the file's "linearize" section).
struct linearize_definition {
  std::vector<int> coordinates;            ///< q_l: indices of coordinates (their rates are speeds)
  std::vector<int> dependent_coordinates;  ///< q_d: determined by the holonomic constraints
  std::vector<int> holonomic_rows;         ///< the holonomic constraints, in order
  std::vector<int> free_speeds;            ///< the speeds not solved from the constraints, in order
  int speed = -1;                          ///< the reference speed v: a given (free) speed
  int gravity = -1;                        ///< the parameter g, or -1 (then g = 1)
};

enum class linearize_method { cotton, lagrange };

template <Scalar T>
struct linearized_equations {
  matrix_t<T> M, C1, K0, K2;  ///< M q'' + v C1 q' + (g K0 + v^2 K2) q = f
  T g, v0;                    ///< gravity (1 without a gravity parameter) and the state's speed
  /// Checks of the form, each must hold 0: the stiffness and damping at 2 v0
  /// minus g K0 + 4 v0^2 K2 and 2 v0 C1; the damping at rest.
  matrix_t<T> stiffness_residual, damping_residual, damping_at_rest;
};

namespace detail {

template <Scalar T>
struct motion_jacobians {
  matrix_t<T> M;    ///< the mass matrix of the q_l (Schur complement in the free speeds)
  matrix_t<T> Jq;   ///< d(q_l'')/dq_l
  matrix_t<T> Jqd;  ///< d(q_l'')/dq_l'
};

/// The Jacobians of the q_l'' at (q, u, t): u holds the given speeds (those in
/// `solved` are recomputed from the constraints).
template <linearize_method method, Scalar T>
motion_jacobians<T> motion_jacobians_at(const compiled_system<T>& c, const linearize_definition& L,
                                        const std::vector<int>& solved, const vector_t<T>& q, const vector_t<T>& u,
                                        const T& t) {
  constexpr int N = 4;  // directions per evaluation
  using D = multi_dual<T, N>;
  const int m = static_cast<int>(L.coordinates.size()), nq = static_cast<int>(q.size());
  const int n = static_cast<int>(u.size()), h = static_cast<int>(L.dependent_coordinates.size());
  const expression_system<T> sys{&c};
  const expression_constraints<T> con{&c};

  // dq_d / dq_l = -F_d^-1 F_l, from the holonomic constraints' gradients at the state.
  matrix_t<T> dependent(h, m);
  if (h > 0) {
    const vector_t<T> u0 = vector_t<T>::Zero(n);
    const std::vector<T> values = c.evaluate(c.constraint_tape, c.template variables<T>(q, u0, t));
    matrix_t<T> Fd = matrix_t<T>::Zero(h, h), Fl = matrix_t<T>::Zero(h, m);
    for (int r = 0; r < h; ++r)
      for (const auto& [i, e] : c.constraints[static_cast<std::size_t>(L.holonomic_rows[static_cast<std::size_t>(r)])].f.dq) {
        const auto d = std::find(L.dependent_coordinates.begin(), L.dependent_coordinates.end(), i);
        const auto l = std::find(L.coordinates.begin(), L.coordinates.end(), i);
        if (d != L.dependent_coordinates.end()) Fd(r, static_cast<int>(d - L.dependent_coordinates.begin())) = e.at(values.data());
        else if (l != L.coordinates.end()) Fl(r, static_cast<int>(l - L.coordinates.begin())) = e.at(values.data());
      }
    for (int j = 0; j < m; ++j) {
      const vector_t<T> col = solve(Fd, vector_t<T>(-Fl.col(j)));
      for (int r = 0; r < h; ++r) dependent(r, j) = col(r);
    }
  }

  motion_jacobians<T> J{matrix_t<T>(), matrix_t<T>(m, m), matrix_t<T>(m, m)};
  matrix_t<T> Maa;
  const bool constrained = !c.constraints.empty();
  for (int first = 0; first < 2 * m; first += N) {  // directions: q_l (0 .. m-1), then q_l' (m .. 2m-1)
    vector_t<D> qD(nq), uD(n);
    for (int i = 0; i < nq; ++i) qD(i) = D(q(i));
    for (int j = 0; j < n; ++j) uD(j) = D(u(j));
    const D tD(t);
    for (int s = 0; s < N && first + s < 2 * m; ++s) {
      const int d = first + s;
      const auto slot = static_cast<std::size_t>(s);
      if (d < m) {
        qD(L.coordinates[static_cast<std::size_t>(d)]).d[slot] = T(1);
        for (int r = 0; r < h; ++r) qD(L.dependent_coordinates[static_cast<std::size_t>(r)]).d[slot] = dependent(r, d);
      } else {
        uD(L.coordinates[static_cast<std::size_t>(d - m)]).d[slot] = T(1);
      }
    }
    if (!solved.empty()) solve_dependent_speeds(c, qD, uD, tD, solved);
    vector_t<D> acc;
    if (!constrained) {
      const appell_equations<D> eq = gibbs_appell(sys, qD, uD, tD);
      acc = eq.accelerations();
      if (first == 0) {
        Maa.resize(n, n);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) Maa(i, j) = eq.M(i, j).v;
      }
    } else if constexpr (method == linearize_method::cotton) {
      const auto change = adapt_speeds<T>(con, q, t, n, &L.free_speeds);
      appell_equations<D> adapted;
      acc = cotton_reactions(sys, change, qD, uD, tD, &adapted).accelerations;
      if (first == 0) {
        const int k = static_cast<int>(L.free_speeds.size());
        Maa.resize(k, k);
        for (int i = 0; i < k; ++i)
          for (int j = 0; j < k; ++j) Maa(i, j) = adapted.M(i, j).v;
      }
    } else {
      acc = lagrange_multipliers(sys, con, qD, uD, tD).accelerations;
    }
    for (int s = 0; s < N && first + s < 2 * m; ++s) {
      const int d = first + s;
      for (int i = 0; i < m; ++i) {
        const T& x = acc(L.coordinates[static_cast<std::size_t>(i)]).d[static_cast<std::size_t>(s)];
        if (d < m) J.Jq(i, d) = x;
        else J.Jqd(i, d - m) = x;
      }
    }
  }
  if (Maa.size() == 0) {  // Lagrange's method: the mass matrix in the free speeds, from Cotton's equations
    const auto change = adapt_speeds<T>(con, q, t, n, &L.free_speeds);
    vector_t<T> uu = u;
    if (!solved.empty()) solve_dependent_speeds(c, q, uu, t, solved);
    appell_equations<T> adapted;
    (void)cotton_reactions(sys, change, q, uu, t, &adapted);
    const int k = static_cast<int>(L.free_speeds.size());
    Maa = adapted.M.topLeftCorner(k, k);
  }
  // M = M_ll - M_lo M_oo^-1 M_ol over the free speeds (l: the q_l', o: the others).
  std::vector<int> free = L.free_speeds;
  if (!constrained) {
    free.resize(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) free[static_cast<std::size_t>(j)] = j;
  }
  std::vector<int> lpos, opos;
  for (int i = 0; i < m; ++i)
    lpos.push_back(static_cast<int>(std::find(free.begin(), free.end(), L.coordinates[static_cast<std::size_t>(i)]) -
                                    free.begin()));
  for (int j = 0; j < static_cast<int>(free.size()); ++j)
    if (std::find(lpos.begin(), lpos.end(), j) == lpos.end()) opos.push_back(j);
  J.M.resize(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) J.M(i, j) = Maa(lpos[static_cast<std::size_t>(i)], lpos[static_cast<std::size_t>(j)]);
  if (!opos.empty()) {
    const int o = static_cast<int>(opos.size());
    matrix_t<T> Moo(o, o), Mol(o, m);
    for (int a = 0; a < o; ++a) {
      for (int b = 0; b < o; ++b) Moo(a, b) = Maa(opos[static_cast<std::size_t>(a)], opos[static_cast<std::size_t>(b)]);
      for (int j = 0; j < m; ++j) Mol(a, j) = Maa(opos[static_cast<std::size_t>(a)], lpos[static_cast<std::size_t>(j)]);
    }
    for (int j = 0; j < m; ++j) {
      const vector_t<T> x = solve_spd(Moo, vector_t<T>(Mol.col(j)));
      for (int i = 0; i < m; ++i)
        for (int a = 0; a < o; ++a) J.M(i, j) -= Mol(a, i) * x(a);
    }
  }
  return J;
}

}  // namespace detail

/// The linearized equations about the steady motion at (q, u, t); u holds the
/// given speeds, u(L.speed) = v0 != 0 the reference speed.
/// method: Cotton's reactions (the library's), or Lagrange's multipliers (the cross-check).
template <linearize_method method = linearize_method::cotton, Scalar T>
linearized_equations<T> linearize(const compiled_system<T>& c, const linearize_definition& L,
                                  const std::vector<int>& solved, const vector_t<T>& q, const vector_t<T>& u,
                                  const T& t) {
  const int m = static_cast<int>(L.coordinates.size());
  linearized_equations<T> r;
  r.v0 = u(L.speed);
  r.g = L.gravity >= 0 ? c.parameters[static_cast<std::size_t>(L.gravity)] : T(1);
  auto at_speed = [&](const T& v) {
    vector_t<T> us = u;
    us(L.speed) = v;
    detail::motion_jacobians<T> J = detail::motion_jacobians_at<method>(c, L, solved, q, us, t);
    return std::pair<matrix_t<T>, matrix_t<T>>{-detail::product(J.M, J.Jq), -detail::product(J.M, J.Jqd)};
  };
  {
    const detail::motion_jacobians<T> J = detail::motion_jacobians_at<method>(c, L, solved, q, u, t);
    r.M = J.M;
    const matrix_t<T> K = -detail::product(J.M, J.Jq), C = -detail::product(J.M, J.Jqd);
    const auto [K_rest, C_rest] = at_speed(T(0));
    r.damping_at_rest = C_rest;
    const T v2 = r.v0 * r.v0;
    r.K0.resize(m, m);
    r.K2.resize(m, m);
    r.C1.resize(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        r.K0(i, j) = K_rest(i, j) / r.g;
        r.K2(i, j) = (K(i, j) - K_rest(i, j)) / v2;
        r.C1(i, j) = C(i, j) / r.v0;
      }
    const T v1 = T(2) * r.v0;
    const auto [K_twice, C_twice] = at_speed(v1);
    r.stiffness_residual = matrix_t<T>(m, m);
    r.damping_residual = matrix_t<T>(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        r.stiffness_residual(i, j) = K_twice(i, j) - (K_rest(i, j) + T(4) * v2 * r.K2(i, j));
        r.damping_residual(i, j) = C_twice(i, j) - v1 * r.C1(i, j);
      }
  }
  return r;
}

/// The linearized motion's first-order matrix at speed v, x = (q, q'):
///   x' = [0 I; -M^-1 (g K0 + v^2 K2)  -v M^-1 C1] x.
/// Minv: M^-1 (inverse_of below).  S: T, or a dual of T (v seeded).
template <Scalar T, class S>
matrix_t<S> first_order_matrix(const linearized_equations<T>& L, const matrix_t<T>& Minv, const S& v) {
  const Eigen::Index m = L.M.rows();
  matrix_t<S> A = matrix_t<S>::Zero(2 * m, 2 * m);
  for (Eigen::Index i = 0; i < m; ++i) A(i, m + i) = S(1);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) {
      S k = S(0), c = S(0);
      for (Eigen::Index a = 0; a < m; ++a) {
        k += S(Minv(i, a)) * (S(T(L.g * L.K0(a, j))) + v * v * S(L.K2(a, j)));
        c += S(Minv(i, a)) * S(L.C1(a, j));
      }
      A(m + i, j) = -k;
      A(m + i, m + j) = -(v * c);
    }
  return A;
}

/// M^-1, column by column (verified for interval types).
template <Scalar T>
matrix_t<T> inverse_of(const matrix_t<T>& M) {
  const Eigen::Index m = M.rows();
  matrix_t<T> inv(m, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    vector_t<T> e = vector_t<T>::Zero(m);
    e(j) = T(1);
    inv.col(j) = solve(M, e);
  }
  return inv;
}

/// The eigenvalues of the linearized motion at speed v, enclosed (polynomial.hpp).
template <Scalar T>
std::vector<root_enclosure<T>> eigenvalues_at(const linearized_equations<T>& L, const matrix_t<T>& Minv, const T& v) {
  return polynomial_roots(characteristic_polynomial(first_order_matrix(L, Minv, v)));
}

/// How many eigenvalues certainly have a positive real part, and whether every
/// one certainly has a negative real part (the motion is asymptotically stable).
template <Scalar T>
std::pair<int, bool> stability_of(const std::vector<root_enclosure<T>>& roots) {
  int unstable = 0;
  bool stable = true;
  for (const auto& r : roots) {
    if (certainly_positive(r.real_part)) ++unstable;
    if (!certainly_negative(r.real_part)) stable = false;
  }
  return {unstable, stable};
}

/// A speed where an eigenvalue's real part crosses 0, enclosed.
template <Scalar T>
struct critical_speed {
  enum kind_t { zero_root, imaginary_pair } kind;  ///< det K(v) = 0 (a real root through 0; capsize) or Delta = 0 (weave)
  T speed;             ///< holds the root of the criterion (interval types: certified by the signs at its ends)
  bool unique = false;  ///< the criterion is monotonic over the enclosure (interval types): exactly one root
  int unstable_below = 0, unstable_above = 0;  ///< eigenvalues certainly in the right half-plane at the grid points around it
};

namespace detail {
/// The two criteria at speed v: c_0(v) (det of the stiffness over det M) and Delta_(n-1)(v).
template <Scalar T, class S>
std::pair<S, S> crossing_criteria(const linearized_equations<T>& L, const matrix_t<T>& Minv, const S& v) {
  const std::vector<S> c = characteristic_polynomial(first_order_matrix(L, Minv, v));
  return {c[0], hurwitz_determinant(c)};
}
template <Scalar T>
int sign_of(const T& x) {
  if (certainly_positive(x)) return 1;
  if (certainly_negative(x)) return -1;
  return 0;
}
}  // namespace detail

/// The speeds in [from, to] where the real part of an eigenvalue crosses 0: sign
/// changes of the two criteria on a grid of `steps` intervals, each narrowed by
/// bisection as far as the signs are certain.  A root where a criterion only
/// touches 0, or two roots within one grid step, are not seen: the grid is the
/// search's resolution.
template <Scalar T>
std::vector<critical_speed<T>> critical_speeds(const linearized_equations<T>& L, const matrix_t<T>& Minv,
                                               const bound_t<T>& from, const bound_t<T>& to, int steps) {
  using P = bound_t<T>;
  std::vector<critical_speed<T>> out;
  auto criterion = [&](int which, const P& v) {
    const auto c = detail::crossing_criteria(L, Minv, detail::from_bound<T>(v));
    return detail::sign_of<T>(which == 0 ? c.first : c.second);
  };
  const int bits = static_cast<int>(scalar_traits<T>::precision_bits());
  for (int which = 0; which < 2; ++which) {
    P a = from;
    int sa = criterion(which, a);
    for (int k = 1; k <= steps; ++k) {
      const P b = k == steps ? to : P(from + (to - from) * P(k) / P(steps));
      const int sb = criterion(which, b);
      if (sa != 0 && sb != 0 && sa != sb) {
        // narrow [lo, hi]: lo keeps the sign sa, hi the sign sb
        P lo = a, hi = b;
        for (int it = 0; it < 4 * bits + 64; ++it) {
          const P mid = (lo + hi) / 2;
          if (!(lo < mid && mid < hi)) break;
          const int sm = criterion(which, mid);
          if (sm == sa) lo = mid;
          else if (sm == sb) hi = mid;
          else {  // undecided at mid: narrow each side to where the sign is certain
            P l1 = lo, r1 = mid, l2 = mid, r2 = hi;
            for (int j = 0; j < 4 * bits + 64; ++j) {
              const P m1 = (l1 + r1) / 2;
              if (!(l1 < m1 && m1 < r1)) break;
              (criterion(which, m1) == sa ? l1 : r1) = m1;
            }
            for (int j = 0; j < 4 * bits + 64; ++j) {
              const P m2 = (l2 + r2) / 2;
              if (!(l2 < m2 && m2 < r2)) break;
              (criterion(which, m2) == sb ? r2 : l2) = m2;
            }
            lo = l1, hi = r2;
            break;
          }
        }
        critical_speed<T> cs;
        cs.kind = which == 0 ? critical_speed<T>::zero_root : critical_speed<T>::imaginary_pair;
        if constexpr (scalar_traits<T>::is_interval) {
          cs.speed = scalar_traits<T>::from_bounds(lo, hi);
          const dual<T> vd(cs.speed, T(1));
          const auto cd = detail::crossing_criteria(L, Minv, vd);
          const T slope = which == 0 ? cd.first.d : cd.second.d;
          cs.unique = detail::sign_of<T>(slope) != 0;
        } else {
          cs.speed = P((lo + hi) / 2);
        }
        // at the grid points around it, where the real parts are away from 0
        cs.unstable_below = stability_of(eigenvalues_at(L, Minv, detail::from_bound<T>(a))).first;
        cs.unstable_above = stability_of(eigenvalues_at(L, Minv, detail::from_bound<T>(b))).first;
        out.push_back(cs);
      }
      a = b, sa = sb;
    }
  }
  std::sort(out.begin(), out.end(), [](const critical_speed<T>& x, const critical_speed<T>& y) {
    return approx_double(x.speed) < approx_double(y.speed);
  });
  return out;
}

}  // namespace appell
