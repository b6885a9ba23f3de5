// appell/system/motion.hpp -- the system's motion at a state: u' by Gibbs-Appell (Cotton's
// method when there are constraints), the reactions, Lagrange's multipliers and eq. (4).
// Including it includes every phase of the model but the joint wrenches and the linearization.
#pragma once

#include "appell/system/contacts.hpp"
#include "appell/system/tree.hpp"
#include "appell/system/tree_constraints.hpp"

namespace appell {

/// Appell's equations M u' + b = Q of the system without its constraints at (q, u, t): by the
/// tree's recursions where they apply (system/tree.hpp), else by the generic path.
/// `keep`: the tree's pass for the joints' wrenches at the same state (tree_pass), where kept.
template <Scalar T, class S>
void system_equations_into(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                           appell_equations<S>& e, tree_pass<T>* keep = nullptr) {
  if (keep) keep->system = nullptr;
  if (tree_recursions_apply(c)) tree_equations_into<T, S>(c, q, u, t, e, keep);
  else gibbs_appell_into(expression_system<T>{&c}, q, u, t, e);
}
template <Scalar T, class S>
appell_equations<S> system_equations(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u,
                                     const S& t) {
  appell_equations<S> e;
  system_equations_into<T, S>(c, q, u, t, e);
  return e;
}

template <Scalar T>
struct system_motion_result {
  vector_t<T> accelerations;  ///< u'
  vector_t<T> reactions;      ///< Cotton's Q'_c, one per constraint
  vector_t<T> multipliers;    ///< Lagrange's, for comparison
  T virtual_work_residual;    ///< eq. (4), in the speeds adapted to the constraints
  /// The tree's pass at the same state, for the joints' wrenches (system_model's evaluation):
  /// kept where the system has no constraints and its recursion is componentwise.
  tree_pass<T> pass;
};

/// The system's motion at (q, u, t): u' by Gibbs-Appell (Cotton's method when
/// there are constraints), the reactions, the Lagrange multipliers and eq. (4).  Without
/// `checks` the multipliers and eq. (4) are left out (multipliers empty, virtual_work_residual
/// 0): u' and the reactions are the same numbers, bit for bit (`appell reference` prints no check).
/// system_motion_into writes over r, reusing its vectors.
template <Scalar T>
void system_motion_into(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                        bool checks, system_motion_result<T>& r) {
  const expression_system<T> sys{&c};
  const int n = sys.speeds();
  r.virtual_work_residual = T(0);
  r.pass.system = nullptr;
  // working storage borrowed (linalg/scratch.hpp); r's own reused
  struct site;  // this function's pools (linalg/scratch.hpp: an Eigen object keeps one size)
  const scratch<vector_t<T>, site> ones;
  ones->setOnes(n);
  if (c.constraints.empty()) {
    const scratch<appell_equations<T>, site> eq;
    system_equations_into<T, T>(c, q, u, t, *eq, &r.pass);
    eq->accelerations_into(r.accelerations);
    r.reactions.resize(0);  // empty already after the first evaluation of the scene: no allocation
    r.multipliers.resize(0);
    if (!checks) return;
    r.virtual_work_residual = virtual_work_residual(sys, *eq, q, u, t, r.accelerations, *ones);
    return;
  }
  const expression_constraints<T> con{&c};
  const scratch<adapted_change<expression_constraints<T>>, site> change_held;
  adapt_speeds_into<T>(con, q, t, n, *change_held);
  const adapted_change<expression_constraints<T>>& change = *change_held;
  if (tree_constraints_apply(c)) {
    // A tree of links: Cotton's method on the recursions (system/tree_constraints.hpp), at the
    // speeds the constraints give to u's free components (as the generic path below takes them).
    const scratch<vector_t<T>, site> va_held, full_held;
    const scratch<tree_cotton_result<T>, site> tc_held;
    vector_t<T>&va = *va_held, &full = *full_held;
    tree_cotton_result<T>& tc = *tc_held;
    va.setZero(n);
    for (std::size_t i = 0; i < change.free_columns.size(); ++i)
      va(static_cast<Eigen::Index>(i)) = u(change.free_columns[i]);
    change.template apply_into<T>(q, va, t, full);
    tree_cotton_into<T, T>(c, change.free_columns, change.bound_columns, q, full, t, {true, checks}, r.accelerations,
                           tc);
    r.reactions = tc.reactions;
    if (!checks) {
      r.multipliers.resize(0);
      return;
    }
    // Lagrange's saddle-point system on the same equations (the constraints' two treatments
    // compared), and eq. (4) for the adapted speeds' unit displacement, written in u.
    const scratch<constrained_motion<T>, site> lagrange;
    lagrange_multipliers_with_into(tc.equations, sys, con, q, full, t, *lagrange);
    r.multipliers = lagrange->reactions;
    r.virtual_work_residual = virtual_work_residual(sys, tc.equations, q, full, t, r.accelerations, tc.unit_displacement);
    return;
  }
  const scratch<appell_equations<T>, site> adapted_eq;
  const scratch<constrained_motion<T>, site> m_held;
  const constrained_motion<T>& m = *m_held;
  cotton_reactions_into(sys, change, q, u, t, *m_held, checks ? &*adapted_eq : nullptr);
  r.accelerations = m.accelerations;  // into r's storage
  r.reactions = m.reactions;
  if (!checks) {
    r.multipliers.resize(0);
    return;
  }
  const scratch<constrained_motion<T>, site> lagrange;
  lagrange_multipliers_into(sys, con, q, u, t, *lagrange);
  r.multipliers = lagrange->reactions;
  // eq. (4) in the adapted speeds (v_a, v_c): v = (u_free, 0), v' = (u_free', 0)
  const int k = static_cast<int>(change.free_columns.size());
  const scratch<vector_t<T>, site> v_held, vdot_held;
  vector_t<T>&v = *v_held, &vdot = *vdot_held;
  v.setZero(n), vdot.setZero(n);
  for (int i = 0; i < k; ++i) {
    v(i) = u(change.free_columns[static_cast<std::size_t>(i)]);
    vdot(i) = m.accelerations(change.free_columns[static_cast<std::size_t>(i)]);
  }
  r.virtual_work_residual = virtual_work_residual(change_speeds(sys, detail::change_ref{&change}, n), *adapted_eq, q,
                                                  v, t, vdot, *ones);
}
template <Scalar T>
system_motion_result<T> system_motion(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u,
                                      const T& t, bool checks = true) {
  system_motion_result<T> r;
  system_motion_into(c, q, u, t, checks, r);
  return r;
}

}  // namespace appell
