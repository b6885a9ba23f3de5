// appell/system/motion.hpp -- the system's motion at a state: u' by Gibbs-Appell (Cotton's
// method when there are constraints), the reactions, Lagrange's multipliers and eq. (4).
// Including it includes every phase of the model but the joint wrenches and the linearization.
#pragma once

#include "appell/system/contacts.hpp"

namespace appell {

template <Scalar T>
struct system_motion_result {
  vector_t<T> accelerations;  ///< u'
  vector_t<T> reactions;      ///< Cotton's Q'_c, one per constraint
  vector_t<T> multipliers;    ///< Lagrange's, for comparison
  T virtual_work_residual;    ///< eq. (4), in the speeds adapted to the constraints
};

/// The system's motion at (q, u, t): u' by Gibbs-Appell (Cotton's method when
/// there are constraints), the reactions, the Lagrange multipliers and eq. (4).  Without
/// `checks` the multipliers and eq. (4) are left out (multipliers empty, virtual_work_residual
/// 0): u' and the reactions are the same numbers, bit for bit (`appell reference` prints no check).
template <Scalar T>
system_motion_result<T> system_motion(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u,
                                      const T& t, bool checks = true) {
  const expression_system<T> sys{&c};
  const int n = sys.speeds();
  system_motion_result<T> r;
  r.virtual_work_residual = T(0);
  if (c.constraints.empty()) {
    const appell_equations<T> eq = gibbs_appell(sys, q, u, t);
    r.accelerations = eq.accelerations();
    if (!checks) return r;
    r.virtual_work_residual = virtual_work_residual(sys, eq, q, u, t, r.accelerations, vector_t<T>(vector_t<T>::Ones(n)));
    return r;
  }
  const expression_constraints<T> con{&c};
  const auto change = adapt_speeds<T>(con, q, t, n);
  appell_equations<T> adapted_eq;
  const constrained_motion<T> m = cotton_reactions(sys, change, q, u, t, checks ? &adapted_eq : nullptr);
  r.accelerations = m.accelerations;
  r.reactions = m.reactions;
  if (!checks) return r;
  r.multipliers = lagrange_multipliers(sys, con, q, u, t).reactions;
  // eq. (4) in the adapted speeds (v_a, v_c): v = (u_free, 0), v' = (u_free', 0)
  const int k = static_cast<int>(change.free_columns.size());
  vector_t<T> v = vector_t<T>::Zero(n), vdot = vector_t<T>::Zero(n);
  for (int i = 0; i < k; ++i) {
    v(i) = u(change.free_columns[static_cast<std::size_t>(i)]);
    vdot(i) = m.accelerations(change.free_columns[static_cast<std::size_t>(i)]);
  }
  r.virtual_work_residual = virtual_work_residual(change_speeds(sys, change, n), adapted_eq, q, v, t, vdot,
                                                  vector_t<T>(vector_t<T>::Ones(n)));
  return r;
}

}  // namespace appell
