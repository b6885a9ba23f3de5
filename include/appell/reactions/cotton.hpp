// appell/reactions/cotton.hpp -- Cotton's reactions of added frictionless
// constraints (paper sec. 5, eqs. 11-15).
//
// In speeds v = (v_a, v_c) adapted to the s added constraints (v_c = 0):
//  1. the constrained system's S-bar is S with v_c = 0 and v_c' = 0 (12, 13);
//     its equations  M_aa v_a' + b_a = Q_a  give the k free accelerations;
//  2. the reactions are  Q'_c = (dS/dv_c')|_(12,13) - Q-bar_c
//                             = M_ca v_a' + b_c - Q_c            (14),
//     with v_a' substituted;
//  3. Q'_c . dv_c is the virtual work of the constraint forces (15).
// cotton_reactions(sys, q, v_a, t, s) takes a system whose last s speeds are
// the constrained ones; cotton_reactions(sys, con, q, u, t) takes constraints
// A(q,t) u = a(q,t) on any system and builds the adapted speeds itself
// (speeds.hpp).  With v_c = A u - a, Q'_c equals the Lagrange multipliers of
// lagrange.hpp: the library computes both and the tests compare them.
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

template <Scalar T>
struct cotton_result {
  vector_t<T> free_accelerations;  ///< v_a'
  vector_t<T> reactions;           ///< Q'_c, one per added constraint
  appell_equations<T> equations;   ///< of the unconstrained system, at v_c = 0
};

namespace detail {
/// The speeds (v_a, 0) of Cotton's method, eq. (12): v_c = 0; `who` names the caller when k + s
/// is not the system's number of speeds.
template <Scalar T, class Sys>
vector_t<T> cotton_speeds(const Sys& sys, const vector_t<T>& v_a, int s, const char* who) {
  const int k = static_cast<int>(v_a.size()), n = k + s;
  if (sys.speeds() != n) throw std::invalid_argument(std::string(who) + ": k + s differs from the system's speeds");
  vector_t<T> v = vector_t<T>::Zero(n);
  v.head(k) = v_a;
  return v;
}
}  // namespace detail

/// The last s speeds of `sys` are constrained to 0; v_a holds the other k.  Into r, whose
/// storage is reused (no allocation for point types once the sizes are known).
template <Scalar T, class Sys>
void cotton_reactions_into(const Sys& sys, const vector_t<T>& q, const vector_t<T>& v_a, const T& t, int s,
                           cotton_result<T>& r) {
  const int k = static_cast<int>(v_a.size()), n = k + s;
  if (sys.speeds() != n) throw std::invalid_argument("cotton_reactions: k + s differs from the system's speeds");
  // working storage borrowed (linalg/scratch.hpp)
  struct site;
  const scratch<vector_t<T>, site> v_held, rhs_held;
  const scratch<matrix_t<T>, site> Maa_held;
  vector_t<T>&v = *v_held, &rhs = *rhs_held;
  v.setZero(n);
  v.head(k) = v_a;
  gibbs_appell_into(sys, q, v, t, r.equations);
  const appell_equations<T>& e = r.equations;
  *Maa_held = e.M.topLeftCorner(k, k);
  rhs = e.Q.head(k) - e.b.head(k);
  solve_spd_into<site>(*Maa_held, rhs, r.free_accelerations);
  // (13) v_c' = 0, then (14): M_ca v_a' + b_c - Q_c, M_ca v_a' by detail::product's sums
  r.reactions.resize(s);
  for (int i = 0; i < s; ++i) {
    T sum = k > 0 ? T(e.M(k + i, 0) * r.free_accelerations(0)) : T(0);
    for (int j = 1; j < k; ++j) sum += e.M(k + i, j) * r.free_accelerations(j);
    r.reactions(i) = sum + e.b(k + i) - e.Q(k + i);
  }
}
template <Scalar T, class Sys>
cotton_result<T> cotton_reactions(const Sys& sys, const vector_t<T>& q, const vector_t<T>& v_a, const T& t, int s) {
  cotton_result<T> r;
  cotton_reactions_into(sys, q, v_a, t, s, r);
  return r;
}

/// cotton_reactions' free accelerations v_a' alone, the same numbers bit for bit, without the
/// reactions: only the free speeds' columns of the equations are formed (gibbs_appell_leading,
/// one evaluation on multi_dual<T, Slots>, Slots >= k + 1).  For the motion (the model's problem, models/<name>.hpp),
/// whose right-hand side needs no reaction: the heavy top on its pivot differentiates 4
/// directions instead of 7.
template <int Slots, Scalar T, class Sys>
vector_t<T> cotton_free_accelerations(const Sys& sys, const vector_t<T>& q, const vector_t<T>& v_a, const T& t, int s) {
  const int k = static_cast<int>(v_a.size());
  const vector_t<T> v = detail::cotton_speeds(sys, v_a, s, "cotton_free_accelerations");
  const appell_equations<T> e = gibbs_appell_leading<Slots>(sys, q, v, t, k);
  return solve_spd(e.M, vector_t<T>(e.Q - e.b));
}

/// Result in the original speeds u of a system with constraints A u = a.
template <Scalar T>
struct constrained_motion {
  vector_t<T> accelerations;  ///< u', consistent with the constraints
  vector_t<T> reactions;      ///< Q'_c (Cotton) or lambda (Lagrange), one per constraint
};

namespace detail {
/// u' = d/dt u(q, v, t) with v' = (v_a', 0): one dual pass through the change of speeds, into udot.
template <Scalar T, class Adapted, class Change>
void original_accelerations_into(const Adapted& adapted, const Change& change, const vector_t<T>& q,
                                 const vector_t<T>& v_a, const vector_t<T>& v_a_dot, const T& t, vector_t<T>& udot) {
  const int n = adapted.speeds(), k = static_cast<int>(v_a.size());
  // working storage borrowed (linalg/scratch.hpp)
  struct site;
  const scratch<vector_t<T>, site> v_held, vdot_held, qd_held;
  const scratch<vector_t<dual<T>>, site> qs_held, vs_held, ud_held;
  vector_t<T>&v = *v_held, &vdot = *vdot_held, &qd = *qd_held;
  v.setZero(n), vdot.setZero(n);
  v.head(k) = v_a;
  vdot.head(k) = v_a_dot;
  if constexpr (requires { adapted.template qdot_into<T>(q, v, t, qd); })
    adapted.template qdot_into<T>(q, v, t, qd);
  else
    qd = adapted.template qdot<T>(q, v, t);
  vector_t<dual<T>>&qs = *qs_held, &vs = *vs_held, &ud = *ud_held;  // detail::seeded's values
  qs.resize(q.size()), vs.resize(n);
  for (Eigen::Index i = 0; i < q.size(); ++i) qs(i) = dual<T>(q(i), qd(i));
  for (int i = 0; i < n; ++i) vs(i) = dual<T>(v(i), vdot(i));
  if constexpr (requires { change.template apply_into<dual<T>>(qs, vs, dual<T>(t, T(1)), ud); })
    change.template apply_into<dual<T>>(qs, vs, dual<T>(t, T(1)), ud);
  else
    ud = change.template apply<dual<T>>(qs, vs, dual<T>(t, T(1)));
  udot.resize(n);
  for (int i = 0; i < n; ++i) udot(i) = ud(i).d;
}
template <Scalar T, class Adapted, class Change>
vector_t<T> original_accelerations(const Adapted& adapted, const Change& change, const vector_t<T>& q,
                                   const vector_t<T>& v_a, const vector_t<T>& v_a_dot, const T& t) {
  vector_t<T> udot;
  original_accelerations_into(adapted, change, q, v_a, v_a_dot, t, udot);
  return udot;
}
/// The free speeds v_a: u's components on the change's free columns.
template <Scalar T, class Constraint>
void free_speeds_into(const adapted_change<Constraint>& change, const vector_t<T>& u, vector_t<T>& v_a) {
  const auto k = static_cast<Eigen::Index>(change.free_columns.size());
  v_a.resize(k);
  for (Eigen::Index i = 0; i < k; ++i) v_a(i) = u(change.free_columns[static_cast<std::size_t>(i)]);
}
template <Scalar T, class Constraint>
vector_t<T> free_speeds(const adapted_change<Constraint>& change, const vector_t<T>& u) {
  vector_t<T> v_a;
  free_speeds_into(change, u, v_a);
  return v_a;
}
}  // namespace detail

/// Cotton's method in given adapted speeds (adapted_change): u' in the original
/// speeds, and the reactions Q'_c.  If adapted_equations is given it receives the
/// Appell equations of change_speeds(sys, change, n) at (q, (v_a, 0), t), which
/// the method computes anyway (for checks such as eq. (4) in the adapted speeds).
template <Scalar T, class Sys, class Constraint>
void cotton_reactions_into(const Sys& sys, const adapted_change<Constraint>& change, const vector_t<T>& q,
                           const vector_t<T>& u, const T& t, constrained_motion<T>& out,
                           appell_equations<T>* adapted_equations = nullptr) {
  const int n = sys.speeds(), s = change.con.count();
  const auto adapted = change_speeds(sys, detail::change_ref{&change}, n);  // no copy of the change
  struct site;
  const scratch<vector_t<T>, site> v_a;  // borrowed (linalg/scratch.hpp)
  const scratch<cotton_result<T>, site> c;
  detail::free_speeds_into(change, u, *v_a);
  cotton_reactions_into(adapted, q, *v_a, t, s, *c);
  if (adapted_equations) *adapted_equations = c->equations;  // into its storage
  detail::original_accelerations_into(adapted, change, q, *v_a, c->free_accelerations, t, out.accelerations);
  out.reactions = c->reactions;
}
template <Scalar T, class Sys, class Constraint>
constrained_motion<T> cotton_reactions(const Sys& sys, const adapted_change<Constraint>& change,
                                       const vector_t<T>& q, const vector_t<T>& u, const T& t,
                                       appell_equations<T>* adapted_equations = nullptr) {
  constrained_motion<T> out;
  cotton_reactions_into(sys, change, q, u, t, out, adapted_equations);
  return out;
}

/// cotton_reactions' u' alone, the same numbers bit for bit, without the reactions (empty): the
/// free speeds' columns only (cotton_free_accelerations), for the motion's right-hand side.
template <int Slots, Scalar T, class Sys, class Constraint>
vector_t<T> cotton_free_motion(const Sys& sys, const adapted_change<Constraint>& change, const vector_t<T>& q,
                               const vector_t<T>& u, const T& t) {
  const int n = sys.speeds(), s = change.con.count();
  const auto adapted = change_speeds(sys, detail::change_ref{&change}, n);  // no copy of the change
  const vector_t<T> v_a = detail::free_speeds(change, u);
  const vector_t<T> free_acc = cotton_free_accelerations<Slots>(adapted, q, v_a, t, s);
  return detail::original_accelerations(adapted, change, q, v_a, free_acc, t);
}

/// Cotton's method for constraints given as A(q,t) u = a(q,t); the library
/// chooses the free speeds (speeds.hpp, adapt_speeds).
template <Scalar T, class Sys, class Constraint>
constrained_motion<T> cotton_reactions(const Sys& sys, const Constraint& con, const vector_t<T>& q,
                                       const vector_t<T>& u, const T& t) {
  return cotton_reactions(sys, adapt_speeds<T>(con, q, t, sys.speeds()), q, u, t);
}

}  // namespace appell
