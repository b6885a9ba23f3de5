// appell/system/contacts.hpp -- the contacts of a system file (system_contact_definition):
// each contact's normal force N and tangential force F_t from the constraints' reactions, so that
// it can be judged (it holds while N > 0 and |F_t| < mu N).
#pragma once

#include "appell/system/wrenches.hpp"

namespace appell {

template <class S>
struct contact_force_result {
  S normal;           ///< N: the force's component along the normal, on the side the support pushes from
  vec3<S> tangential; ///< F_t: the rest of the force, on the fixed axes (|F_t| is the friction needed)
  vec3<S> moment;     ///< the couple about the point (0 for a point contact; checked when the file is read)
  vec3<S> unit_normal;
};

/// The twist Jacobian (6 x n) of a contact's body at its point: point_twist_jacobian
/// for a body given by rotations; for a body given by omega (affine in u),
///   dv_P/du_j = sum_i dG/dq_i dq'_i/du_j + domega/du_j x (P - G),  domega/du_j from the file.
template <Scalar T, class S>
void contact_twist_jacobian_into(const compiled_system<T>& c, const typename compiled_system<T>::contact& k,
                                 const S* v, matrix_t<S>& J) {
  if (k.point_body) {  // a point mass: the velocity of its centre alone (3 rows; no moment is fixed)
    point_twist_jacobian_into<T, S>(c, k.frame, v, J);
    J.conservativeResize(3, Eigen::NoChange);
    return;
  }
  if (!k.omega_body) return point_twist_jacobian_into<T, S>(c, k.frame, v, J);
  const int n = c.def->vars.speeds;
  vec3<S> rel;
  for (int i = 0; i < 3; ++i) rel(i) = k.frame.rel[static_cast<std::size_t>(i)].at(v);
  J.setZero(6, n);
  for (int x = 0; x < 3; ++x)
    for (const auto& [i, d] : k.frame.center[static_cast<std::size_t>(x)].dq) {
      const S g = d.at(v);
      if (c.def->rates_as_speeds) {
        J(x, i) += g;
        continue;
      }
      for (const auto& [j, wij] : c.kinematics_du[static_cast<std::size_t>(i)]) J(x, j) += g * wij.at(v);
    }
  for (int x = 0; x < 3; ++x)
    for (const auto& [j, e] : k.omega_du[static_cast<std::size_t>(x)]) J(3 + x, j) += e.at(v);
  for (int j = 0; j < n; ++j) {
    const vec3<S> w(J(3, j), J(4, j), J(5, j));
    const vec3<S> m = cross(w, rel);
    for (int r = 0; r < 3; ++r) J(r, j) += m(r);
  }
}
template <Scalar T, class S>
matrix_t<S> contact_twist_jacobian(const compiled_system<T>& c, const typename compiled_system<T>::contact& k,
                                   const S* v) {
  matrix_t<S> J;
  contact_twist_jacobian_into<T, S>(c, k, v, J);
  return J;
}

/// Each contact's force at (q, t) from the constraints' reactions (Cotton's Q'_c):
/// d_c the force of constraint c per unit of its reaction (system_contact_definition),
/// n = side d_normal / |d_normal| (or the given direction, normalized),
///   N = sum_c Q'_c d_c . n,   F_t = sum_c Q'_c (d_c - (d_c . n) n),
/// the normal constraint's own term taken as side Q' |d_normal| (no tangential part),
/// exactly, so that intervals do not widen it.  S: T, or jets of T (over a whole step).
template <Scalar T, class S = T>
void contact_forces_into(const compiled_system<T>& c, const vector_t<S>& q, const S& t, const vector_t<S>& reactions,
                         std::vector<contact_force_result<S>>& out) {
  out.clear();
  if (c.contacts.empty()) return;
  using std::sqrt;
  const int n = c.def->vars.speeds, s = static_cast<int>(c.constraints.size());
  struct site;  // working storage borrowed (linalg/scratch.hpp)
  const scratch<vector_t<S>, site> u0, a_held, g_held, rhs_held, w_held;
  const scratch<std::vector<S>, site> x_held, values_held;
  const scratch<matrix_t<S>, site> A_held, J_held, N_held;
  const scratch<std::vector<vec3<S>>, site> d_held, m_held;
  u0->setZero(n);
  c.variables_into(q, *u0, t, *x_held);
  c.evaluate_into(c.constraint_tape, *x_held, *values_held);
  const S* v = values_held->data();
  matrix_t<S>& A = *A_held;
  vector_t<S>& a = *a_held;
  bool have_A = false;
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const auto& ck = c.contacts[k];
    const system_contact_definition& dk = c.def->contacts[k];
    if (ck.link >= 0) {
      // A link's contact: its rows are the contact frame's axes, so the reactions are the force
      // (and, for a sole, the couple) on those axes at the frame's origin, exactly.
      auto lambda = [&](std::size_t i) { return S(reactions(dk.constraints[i])); };
      const vec3<S> F(lambda(0), lambda(1), lambda(2));
      contact_force_result<S> res{S(0), zero_matrix<vec3<S>>(), zero_matrix<vec3<S>>(), zero_matrix<vec3<S>>()};
      if (ck.surface) {  // the sole's axes: z its normal
        res.normal = F(2);
        res.tangential = vec3<S>(F(0), F(1), S(0));
        res.moment = vec3<S>(lambda(3), lambda(4), lambda(5));
        res.unit_normal(2) = S(1);
      } else {  // the fixed axes; the normal as given, normalized
        vec3<S> n = vec3<S>(detail::from_base<S>(ck.normal(0)), detail::from_base<S>(ck.normal(1)), detail::from_base<S>(ck.normal(2)));
        const S len = sqrt(dot(n, n));
        for (int i = 0; i < 3; ++i) n(i) = n(i) / len;
        res.normal = dot(F, n);
        for (int i = 0; i < 3; ++i) res.tangential(i) = F(i) - res.normal * n(i);
        res.unit_normal = n;
      }
      out.push_back(std::move(res));
      continue;
    }
    std::vector<vec3<S>>&d = *d_held, &m = *m_held;
    d.clear(), m.clear();
    if (ck.frame.body < 0) {
      for (int r : dk.constraints) {
        vec3<S> x;
        for (int i = 0; i < 3; ++i) x(i) = c.constraints[static_cast<std::size_t>(r)].direction[static_cast<std::size_t>(i)].at(v);
        d.push_back(x);
        m.push_back(zero_matrix<vec3<S>>());
      }
    } else {
      if (!have_A) {
        A.resize(s, n);
        a.resize(s);
        expression_constraints<T>{&c}.template eval<S>(q, t, A, a);
        have_A = true;
      }
      const matrix_t<S>& J = *J_held;
      contact_twist_jacobian_into<T, S>(c, ck, v, *J_held);
      for (int r : dk.constraints) {
        vector_t<S>& g = *g_held;
        g = A.row(r).transpose();
        wrench_normal_equations_into(J, g, *N_held, *rhs_held);
        const vector_t<S>& w = *w_held;
        solve_spd_into<site>(*N_held, *rhs_held, *w_held);
        d.push_back(vec3<S>(w(0), w(1), w(2)));
        m.push_back(J.rows() == 6 ? vec3<S>(w(3), w(4), w(5)) : zero_matrix<vec3<S>>());  // a point mass: no moment
      }
    }
    vec3<S> nv;
    std::size_t normal_at = dk.constraints.size();
    if (dk.normal >= 0) {
      normal_at = static_cast<std::size_t>(std::find(dk.constraints.begin(), dk.constraints.end(), dk.normal) - dk.constraints.begin());
      nv = d[normal_at];
    } else {
      for (int i = 0; i < 3; ++i) nv(i) = ck.direction[static_cast<std::size_t>(i)].at(v);
    }
    const S len = sqrt(dot(nv, nv));
    const S side = S(dk.side);
    vec3<S> un;
    for (int i = 0; i < 3; ++i) un(i) = nv(i) * side / len;
    contact_force_result<S> res{S(0), zero_matrix<vec3<S>>(), zero_matrix<vec3<S>>(), un};
    for (std::size_t i = 0; i < dk.constraints.size(); ++i) {
      const S lambda = reactions(dk.constraints[i]);
      for (int x = 0; x < 3; ++x) res.moment(x) += m[i](x) * lambda;
      if (i == normal_at) {
        res.normal += side * lambda * len;
        continue;
      }
      const S along = dot(d[i], un);
      res.normal += lambda * along;
      for (int x = 0; x < 3; ++x) res.tangential(x) += (d[i](x) - un(x) * along) * lambda;
    }
    out.push_back(std::move(res));
  }
}
template <Scalar T, class S = T>
std::vector<contact_force_result<S>> contact_forces(const compiled_system<T>& c, const vector_t<S>& q, const S& t,
                                                    const vector_t<S>& reactions) {
  std::vector<contact_force_result<S>> out;
  contact_forces_into(c, q, t, reactions, out);
  return out;
}

}  // namespace appell
