// appell/system/joint_wrenches.hpp -- the wrench each joint of a tree transmits (paper sec. 5).
//
// A link hangs from its parent by a joint: the joint's constraints remove the relative motions
// it does not allow (five for a revolute or prismatic joint, six for a fixed one).  Cotton's
// reaction of those constraints is eq. (14)-(15): with the constrained motion's accelerations,
// for each direction d a constraint removes (a rigid motion of the link and everything beyond
// it: a unit twist at the joint's origin), Q'_d = dS/dv'_d - Q_d,
//   dS/dv'_d = sum over the subtree of m a_G . v_d(G) + (I alpha + omega x I omega) . omega_d,
//   Q_d      = sum over the subtree of F . v_d(G) + Gamma . omega_d,
// the bodies' accelerations those of the motion (v'_d = 0 on it).  Over the six unit twists
// (translations along L's axes, rotations about them through its origin) these are the force and
// the moment about the origin that the parent exerts on the link through the joint, on L's axes:
// the sums over the subtree of (m a_G - F) and of (G - O) x (m a_G - F) + I alpha + omega x I omega
// - Gamma.  Each is accumulated from the link's children (shifted to its origin), so all the
// wrenches cost O(N) once the kinematics are known.  The actuator's effort belongs to the wrench
// (its component along the axis is the effort: the check below); the actuators of joints beyond
// cancel in pairs inside the subtree.
//
// Checks: along the joint's free direction the wrench's virtual power is the effort,
//   axis . moment - effort (revolute),  axis . force - effort (prismatic),
// which Appell's equation of that coordinate gives independently (its row of M u' + b - Q).
#pragma once

#include <vector>

#include "appell/system/motion.hpp"
#include "appell/system/tree.hpp"

namespace appell {

template <class T>
struct joint_wrench_result {
  vec3<T> force = zero_matrix<vec3<T>>();   ///< by the parent on the link, on the link's (joint's) axes
  vec3<T> moment = zero_matrix<vec3<T>>();  ///< about the joint's origin, on the same axes
  T effort = T(0);                          ///< the effort the wrench carries along the free direction
  T residual = T(0);                        ///< axis . (moment or force) - effort: 0
};

namespace detail {
/// The wrenches from each link's subtree sums (F, M: the inertia forces minus the applied ones,
/// about the link's origin, on its axes) and its joint's own actuator; in S (T itself, or the
/// jets of a motion: joint_wrenches_along), the system's constants in T.
template <Scalar T, class S = T>
void joint_wrenches_from_sums(const compiled_system<T>& c, const std::vector<vec3<S>>& F, const std::vector<vec3<S>>& M,
                              const std::vector<S>& values, const vector_t<S>* efforts,
                              std::vector<joint_wrench_result<S>>& out) {
  using K = system_joint_definition::kind;
  const std::size_t n = c.links.size();
  out.assign(n, joint_wrench_result<S>{});
  for (std::size_t k = 0; k < n; ++k) {
    const auto& L = c.links[k];
    // The wrench: the subtree's sums and this joint's own actuator (not in the sums: its other half
    // acts on the parent).
    joint_wrench_result<S>& w = out[k];
    w.force = F[k];
    w.moment = M[k];
    if (L.type == K::fixed) continue;
    if (efforts) {
      w.effort = (*efforts)(L.coordinate);
    } else if (L.actuated()) {
      w.effort = L.effort_at(values.data());
      const vec3<S> e = compiled_system<T>::scaled(L.axis, w.effort);
      if (L.type == K::revolute) {
        w.moment += e;
      } else {
        w.force += e;
        w.moment += cross(base_vector<T, S>(L.com), e);
      }
    }
    w.residual = dot(base_vector<T, S>(L.axis), L.type == K::revolute ? w.moment : w.force) - w.effort;
  }
}
/// The links' contacts with the ground (system_contact_definition::link) as applied wrenches:
/// each contact's reactions are its force (and a sole's couple) on its frame's axes at the
/// frame's origin P; on the link's axes f = F f_frame, about the link's origin P x f + F m_frame
/// (F: the frame's axes on the link's: the sole's, or the fixed axes turned onto the link's),
/// subtracted from the subtree sums (inertia minus applied) of the link and of every ancestor,
/// carried to each one's origin.  Without this the joints' wrenches would be those of feet in the
/// air.
template <Scalar T, class S = T>
void subtract_contact_wrenches(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& reactions,
                               std::vector<vec3<S>>& F, std::vector<vec3<S>>& M) {
  using K = system_joint_definition::kind;
  using std::cos, std::sin;
  const system_definition& d = *c.def;
  auto state_of = [&](const typename compiled_system<T>::link& L) {
    typename compiled_system<T>::template link_state<S> st;
    const S qk = L.coordinate >= 0 ? q(L.coordinate) : S(0);
    if (L.type == K::revolute) st.c = cos(qk), st.s = sin(qk);
    st.offset = base_vector<T, S>(L.origin);
    if (L.type == K::prismatic) st.offset += compiled_system<T>::times(L.R0, compiled_system<T>::scaled(L.axis, qk));
    return st;
  };
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const auto& ck = c.contacts[k];
    if (ck.link < 0) continue;
    const system_contact_definition& dk = d.contacts[k];
    vec3<S> ff, mf = zero_matrix<vec3<S>>();
    for (int i = 0; i < 3; ++i) ff(i) = reactions(dk.constraints[static_cast<std::size_t>(i)]);
    if (ck.surface)
      for (int i = 0; i < 3; ++i) mf(i) = reactions(dk.constraints[static_cast<std::size_t>(3 + i)]);
    // the frame's axes on the link's
    mat3<S> Fr;
    if (ck.surface) {
      for (int x = 0; x < 3; ++x)
        for (int i = 0; i < 3; ++i) Fr(x, i) = from_base<S>(ck.sole_axes(x, i));
    } else {  // the fixed axes on the link's: each fixed axis carried down the path to the link
      std::vector<int> path;
      for (int body = ck.link; body >= 0;) {
        const int l = c.link_of[static_cast<std::size_t>(body)];
        path.push_back(l);
        body = c.links[static_cast<std::size_t>(l)].parent;
      }
      for (int i = 0; i < 3; ++i) {
        vec3<S> e = zero_matrix<vec3<S>>();
        e(i) = S(1);
        for (auto it = path.rbegin(); it != path.rend(); ++it) {
          const auto& L = c.links[static_cast<std::size_t>(*it)];
          e = c.to_link(L, state_of(L), e);
        }
        for (int x = 0; x < 3; ++x) Fr(x, i) = e(x);
      }
    }
    vec3<S> f, m;
    for (int x = 0; x < 3; ++x) {
      f(x) = Fr(x, 0) * ff(0) + Fr(x, 1) * ff(1) + Fr(x, 2) * ff(2);
      m(x) = Fr(x, 0) * mf(0) + Fr(x, 1) * mf(1) + Fr(x, 2) * mf(2);
    }
    m = vec3<S>(m + cross(base_vector<T, S>(ck.origin), f));
    // up the tree from the link: each ancestor's sums lose the contact's wrench about its origin
    for (int body = ck.link; body >= 0;) {
      const auto l = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(body)]);
      const auto& L = c.links[l];
      F[l] -= f;
      M[l] -= m;
      if (L.parent < 0) break;
      const auto st = state_of(L);
      const vec3<S> fp = c.to_parent(L, st, f);
      m = vec3<S>(c.to_parent(L, st, m) + cross(st.offset, fp));
      f = fp;
      body = L.parent;
    }
  }
}
}  // namespace detail

/// Every link's joint wrench (in the definition's link order) at (q, u, t) with accelerations
/// udot, the bodies' accelerations from the Jacobians of the generic path (any system with
/// links: the speeds may be quasi-velocities).  efforts: the efforts when they are not part of
/// the system (inverse dynamics: the efforts Appell's equations give, per coordinate); null: the
/// links' own efforts (forward dynamics: they act in the bodies' forces, and each wrench carries
/// its joint's).
template <Scalar T>
void joint_wrenches_by_jacobians_into(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u,
                                      const T& t, const vector_t<T>& udot, const vector_t<T>* efforts,
                                      std::vector<joint_wrench_result<T>>& out,
                                      const vector_t<T>* reactions = nullptr) {
  using link = typename compiled_system<T>::link;
  const expression_system<T> sys{&c};
  // working storage borrowed (linalg/scratch.hpp)
  struct site;
  const scratch<std::vector<body_kinematics<T>>, site> kin_held;
  const scratch<std::vector<T>, site> x_held, values_held;
  const scratch<vector_t<T>, site> qd_held;
  const scratch<std::vector<typename compiled_system<T>::template link_state<T>>, site> states_held;
  const scratch<std::vector<vec3<T>>, site> F_held, M_held;
  differentiate_kinematics_into(sys, q, u, t, *kin_held);
  const std::vector<body_kinematics<T>>& kin = *kin_held;
  const std::vector<T>& values = *values_held;
  c.variables_into(q, u, t, *x_held);
  c.evaluate_into(c.body_tape, *x_held, *values_held);
  c.rates_into(*x_held, values, c.kinematics_on_body_tape, *qd_held);
  vec3<T> g;
  for (int i = 0; i < 3; ++i) g(i) = c.gravity[static_cast<std::size_t>(i)].at(values.data());
  c.link_states_into(q, *qd_held, g, values.data(), *states_held);
  const auto& states = *states_held;
  const std::size_t n = c.links.size();
  std::vector<vec3<T>>&F = *F_held, &M = *M_held;  // sum (m a - F), about L's origin
  F.assign(n, zero_matrix<vec3<T>>());
  M.assign(n, zero_matrix<vec3<T>>());
  for (std::size_t k = n; k-- > 0;) {
    const link& L = c.links[k];
    const body_kinematics<T>& B = kin[static_cast<std::size_t>(L.body)];
    const body_state<T>& s = B.state;
    vec3<T> a, al;  // a_G, alpha on the inertia's axes
    for (int r = 0; r < 3; ++r) {
      T ar = B.cv(r), alr = B.cw(r);
      for (Eigen::Index j = 0; j < udot.size(); ++j) {
        if (!structurally_zero(B.Jv(r, j))) ar += B.Jv(r, j) * udot(j);
        if (!structurally_zero(B.Jw(r, j))) alr += B.Jw(r, j) * udot(j);
      }
      a(r) = ar, al(r) = alr;
    }
    vec3<T> f, m;
    const vec3<T> Ial = mat_vec(s.inertia, al), gyro = gyroscopic(s.inertia, s.omega);
    for (int r = 0; r < 3; ++r) {
      f(r) = s.mass * a(r) - s.force(r);
      m(r) = Ial(r) + gyro(r) - s.couple(r);
    }
    if (!L.Rin_identity) {
      f = compiled_system<T>::times(L.Rin, f);
      m = compiled_system<T>::times(L.Rin, m);
    }
    F[k] += f;
    M[k] += vec3<T>(m + cross(L.com, f));
    if (L.parent < 0) continue;
    const auto p = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)]);
    const vec3<T> fp = c.to_parent(L, states[k], F[k]);
    F[p] += fp;
    M[p] += vec3<T>(c.to_parent(L, states[k], M[k]) + cross(states[k].offset, fp));
  }
  if (reactions) detail::subtract_contact_wrenches(c, q, *reactions, F, M);
  detail::joint_wrenches_from_sums(c, F, M, values, efforts, out);
}

/// Every link's joint wrench, as joint_wrenches_by_jacobians_into, the links' accelerations by
/// the recursion along the tree (system/tree.hpp) where the speeds are the coordinates' rates.
/// `pass`: the tree's pass at (q, u, t), where the caller kept one (tree_pass).
template <Scalar T>
void joint_wrenches_into(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                         const vector_t<T>& udot, const vector_t<T>* efforts,
                         std::vector<joint_wrench_result<T>>& out, const vector_t<T>* reactions = nullptr,
                         const tree_pass<T>* pass = nullptr) {
  if (!tree_accelerations_apply(c)) {
    joint_wrenches_by_jacobians_into(c, q, u, t, udot, efforts, out, reactions);
    return;
  }
  struct site;
  const scratch<std::vector<T>, site> values_held;
  const scratch<std::vector<vec3<T>>, site> F_held, M_held;
  tree_subtree_wrenches_into<T, T>(c, q, u, t, udot, *F_held, *M_held, *values_held, pass);
  if (reactions) detail::subtract_contact_wrenches(c, q, *reactions, *F_held, *M_held);
  detail::joint_wrenches_from_sums(c, *F_held, *M_held, *values_held, efforts, out);
}
/// Every link's joint wrench along a motion, in S (the jets or the intervals of a step, a
/// point's T), by the recursion along the tree: forward dynamics (each joint's own effort), the
/// accelerations udot of every speed, `reactions` those of the constraints (the links' contacts
/// with the ground act on their links) or null.  Only where tree_accelerations_apply(c).
template <Scalar T, class S>
void joint_wrenches_along(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                          const vector_t<S>& udot, const vector_t<S>* reactions, std::vector<joint_wrench_result<S>>& out) {
  std::vector<S> values;
  std::vector<vec3<S>> F, M;
  tree_subtree_wrenches_into<T, S>(c, q, u, t, udot, F, M, values);
  if (reactions) detail::subtract_contact_wrenches<T, S>(c, q, *reactions, F, M);
  detail::joint_wrenches_from_sums<T, S>(c, F, M, values, nullptr, out);
}

template <Scalar T>
std::vector<joint_wrench_result<T>> joint_wrenches(const compiled_system<T>& c, const vector_t<T>& q,
                                                   const vector_t<T>& u, const T& t, const vector_t<T>& udot,
                                                   const vector_t<T>* efforts = nullptr) {
  std::vector<joint_wrench_result<T>> out;
  joint_wrenches_into(c, q, u, t, udot, efforts, out);
  return out;
}

}  // namespace appell
