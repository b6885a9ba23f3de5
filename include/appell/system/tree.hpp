// appell/system/tree.hpp -- a tree of links by recursion along the tree: the mass matrix by
// composite rigid bodies, the velocity-product terms and the generalized forces by a
// Newton-Euler pass, each joint's wrench by a second pass with the accelerations.
//
// The generic path (dynamics/gibbs_appell.hpp) differentiates every body's velocity with respect
// to every speed and assembles M = sum m Jv^T Jv + Jw^T I Jw: O(N^2) Jacobian columns, O(N^3)
// products for a chain.  For a tree of links (every body a link, the speeds the coordinates'
// rates) the same Appell equations M u' + b = Q come from recursions along the tree, as the
// engines compute them (Featherstone, "Rigid Body Dynamics Algorithms", ch. 5 and 6):
//
//  * forward, parents first, on each link's axes L (origin O at its joint):
//      omega, v_O                   (compiled_system::link_states_into)
//      alpha = X^T alpha_p + omega x (axis q')   + axis q''   (revolute)
//      a_O   = X^T (a_p + alpha_p x r + omega_p x (omega_p x r))
//              + 2 omega x (axis q') + axis q''                 (prismatic: the 2nd and 3rd terms)
//    with X = R0 Rot(axis, q) (L's axes to the parent's), r = O - O_p on the parent's axes;
//    q'' = 0 gives the velocity-product terms;
//  * per link, at its centre G = O + c:  a_G = a_O + alpha x c + omega x (omega x c),
//    f = m a_G, n_G = I alpha + omega x I omega on the inertia's own axes (exact I, as the
//    generic path keeps it), moment about O:  n_O = n_G + c x f;
//  * backward, children first: each link's sums over its subtree, moved to the parent's origin
//    (f_p += X f,  n_p += X n + r x X f); the joint's row of any generalized force is
//    axis . n (revolute) or axis . f (prismatic):  b from the inertia forces at q'' = 0,
//    Q from the applied ones (gravity, the actuators' pairs of link_states_into);
//  * M by composite rigid bodies: each subtree's mass m, first moment h = m c and inertia about
//    its root's origin I_O, accumulated backward (rotated by X, shifted by r); column i is the
//    momentum of subtree i moving with unit speed i, F = (axis x h, I_O axis) (revolute) or
//    (m axis, h x axis) (prismatic), read by each ancestor j's joint as it moves up the tree:
//    M_ji = S_j . F.
//
// Cost O(N d) for M (d the tree's depth) and O(N) for the rest; the same numbers as the generic
// path in exact arithmetic: tests/tree_recursions.cpp holds the two to each other (double to
// within its precision; the interval and MPFI recursions enclosing the generic path at 512 bits).
#pragma once

#include <vector>

#include "appell/system/tapes.hpp"
#include "appell/system/tree_balls.hpp"

namespace appell {

/// Whether a system's unconstrained Appell equations come from the tree's recursions: every body
/// a link, the speeds the coordinates' rates, every coordinate a joint's (constraints or not:
/// with them, Cotton's method on the tree, system/tree_constraints.hpp).
template <Scalar T>
bool tree_links_apply(const compiled_system<T>& c) {
  const system_definition& d = *c.def;
  if (!d.rates_as_speeds || c.links.empty() || c.links.size() != d.bodies.size()) return false;
  int moving = 0;
  for (const auto& L : c.links) moving += L.coordinate >= 0 ? 1 : 0;
  return moving == d.vars.coordinates && d.vars.coordinates == d.vars.speeds;
}
/// Whether a system's Appell equations come from the tree's recursions: a tree of links
/// (tree_links_apply) without constraints.
template <Scalar T>
bool tree_recursions_apply(const compiled_system<T>& c) {
  return c.def->constraints.empty() && tree_links_apply(c);
}

/// Whether the links' accelerations can come from the recursion (the joints' wrenches): the
/// speeds are the coordinates' rates, so that q'' = u'.
template <Scalar T>
bool tree_accelerations_apply(const compiled_system<T>& c) {
  return c.def->rates_as_speeds && !c.links.empty();
}

namespace detail {
/// One link's quantities of the passes, on its own axes.
template <class S>
struct tree_link {
  vec3<S> alpha, accel;   ///< angular acceleration, the origin's acceleration
  vec3<S> f, n;           ///< inertia force and its moment about the origin (subtree sums after the backward pass)
  vec3<S> fa, na;         ///< applied force and moment about the origin (likewise)
  S m;                    ///< composite: mass
  vec3<S> h;              ///< composite: first moment about the origin, m c
  mat3<S> I;              ///< composite: inertia about the origin
};

template <Scalar T, class S>
vec3<S> base_vector(const vec3<T>& a) {
  return vec3<S>(from_base<S>(a(0)), from_base<S>(a(1)), from_base<S>(a(2)));
}
/// x w, component by component (no Eigen expression of a scalar other than double).
template <class S>
vec3<S> times(const S& x, const vec3<S>& w) {
  return vec3<S>(x * w(0), x * w(1), x * w(2));
}

/// The joint's axis times x.  Where the axis is a coordinate axis (along >= 0) the product is
/// one component, the others exact zeros: the same numbers as the general form gives, for a
/// third of the products (and so for the helpers below).
template <Scalar T, class S>
vec3<S> axis_times(const typename compiled_system<T>::link& L, const S& x) {
  if (L.along >= 0) {
    vec3<S> r(S(0), S(0), S(0));
    r(L.along) = L.axis_negative ? S(-x) : x;
    return r;
  }
  return times(x, base_vector<T, S>(L.axis));
}
/// w x (axis x): with e the coordinate axis, (w x e)_i = w_j, (w x e)_j = -w_i, 0 along e.
template <Scalar T, class S>
vec3<S> cross_axis(const vec3<S>& w, const typename compiled_system<T>::link& L, const S& x) {
  if (L.along >= 0) {
    const S y = L.axis_negative ? S(-x) : x;
    vec3<S> r;
    r(L.along) = S(0);
    r(L.turn_i) = w(L.turn_j) * y;
    r(L.turn_j) = S(-(w(L.turn_i) * y));
    return r;
  }
  return cross(w, times(x, base_vector<T, S>(L.axis)));
}
/// axis x h: (e x h)_i = -h_j, (e x h)_j = h_i, 0 along e.
template <Scalar T, class S>
vec3<S> axis_cross(const typename compiled_system<T>::link& L, const vec3<S>& h) {
  if (L.along >= 0) {
    vec3<S> r;
    r(L.along) = S(0);
    r(L.turn_i) = L.axis_negative ? h(L.turn_j) : S(-h(L.turn_j));
    r(L.turn_j) = L.axis_negative ? S(-h(L.turn_i)) : h(L.turn_i);
    return r;
  }
  return cross(base_vector<T, S>(L.axis), h);
}
/// axis . v
template <Scalar T, class S>
S axis_dot(const typename compiled_system<T>::link& L, const vec3<S>& v) {
  if (L.along >= 0) return L.axis_negative ? S(-v(L.along)) : v(L.along);
  return dot(base_vector<T, S>(L.axis), v);
}

/// X W X^T for a symmetric matrix W on the link's axes, on the parent's: columns, then rows,
/// turned (by the folded X, link_state's note: its upper triangle, mirrored).
template <Scalar T, class S>
mat3<S> to_parent_matrix(const compiled_system<T>& c, const typename compiled_system<T>::link& L,
                         const typename compiled_system<T>::template link_state<S>& st, const mat3<S>& W) {
  mat3<S> A, B;
  if constexpr (compiled_system<T>::template link_state<S>::can_fold)
    if (st.folded) {
      const mat3<S>& X = st.X;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(i, j) = sum_of_products(X(i, 0), W(0, j), X(i, 1), W(1, j), X(i, 2), W(2, j));
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
          B(i, j) = sum_of_products(A(i, 0), X(j, 0), A(i, 1), X(j, 1), A(i, 2), X(j, 2));
          if (j != i) B(j, i) = B(i, j);
        }
      return B;
    }
  for (int j = 0; j < 3; ++j) A.col(j) = c.to_parent(L, st, vec3<S>(W.col(j)));
  for (int i = 0; i < 3; ++i) B.row(i) = c.to_parent(L, st, vec3<S>(A.row(i).transpose())).transpose();
  return B;
}

/// The node values of the body tape at (q, u, t), gravity and the links' motion; then the
/// forward pass (accelerations, with q'' = udot or, null, 0) and each link's inertia and applied
/// forces at its origin (not yet summed).
template <Scalar T, class S>
void tree_forward(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                  const vector_t<S>* udot, std::vector<S>& values,
                  std::vector<typename compiled_system<T>::template link_state<S>>& states,
                  std::vector<tree_link<S>>& out) {
  using K = system_joint_definition::kind;
  const vec3<S> g = tree_tape_into<T, S>(c, q, u, t, values);
  const S* v = values.data();
  c.link_states_into(q, u, g, v, states);  // q' = u
  const std::size_t n = c.links.size();
  out.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& L = c.links[k];
    const auto& st = states[k];
    tree_link<S>& o = out[k];
    if (L.parent >= 0) {
      const auto p = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)]);
      const auto& sp = states[p];
      const tree_link<S>& op = out[p];
      const vec3<S>& r = st.offset;
      o.alpha = c.to_link(L, st, op.alpha);
      o.accel = c.to_link(L, st, vec3<S>(op.accel + cross(op.alpha, r) + cross(sp.omega, cross(sp.omega, r))));
    } else {
      o.alpha = vec3<S>(S(0), S(0), S(0));
      o.accel = vec3<S>(S(0), S(0), S(0));
    }
    if (L.type != K::fixed) {
      const S qd = u(L.coordinate);
      // omega_p (on L's axes) x axis q'.  The link's own omega serves where the axis is along a
      // coordinate axis (its axis q' term adds axis x axis, exactly 0 there); an oblique axis
      // takes the parent's, turned, where intervals would carry (axis q') x (axis q') as a width.
      vec3<S> wp = st.omega;
      if (L.type == K::revolute && L.along < 0)
        wp = L.parent >= 0 ? c.to_link(L, st, states[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)])].omega)
                           : vec3<S>(S(0), S(0), S(0));
      const vec3<S> turn = cross_axis<T, S>(wp, L, qd);
      if (L.type == K::revolute) o.alpha += turn;
      else o.accel += vec3<S>(turn + turn);
      if (udot) {
        const vec3<S> along = axis_times<T, S>(L, (*udot)(L.coordinate));
        if (L.type == K::revolute) o.alpha += along;
        else o.accel += along;
      }
    }
    // The body: inertia forces at G, moved to O; applied forces likewise.
    const auto& b = c.bodies[static_cast<std::size_t>(L.body)];
    const S m = b.mass.at(v);
    const vec3<S> com = base_vector<T, S>(L.com);
    const vec3<S> aG = o.accel + cross(o.alpha, com) + cross(st.omega, cross(st.omega, com));
    o.f = times(m, aG);
    vec3<S> nG = vec3<S>(S(0), S(0), S(0));
    if (b.has_inertia) {
      const mat3<S> I = b.inertia_on_body_axes(v);
      if (L.Rin_identity) {
        nG = mat_vec(I, o.alpha) + gyroscopic(I, st.omega);
      } else {
        const vec3<S> al = compiled_system<T>::transpose_times(L.Rin, o.alpha);
        const vec3<S> w = compiled_system<T>::transpose_times(L.Rin, st.omega);
        nG = compiled_system<T>::times(L.Rin, vec3<S>(mat_vec(I, al) + gyroscopic(I, w)));
      }
    }
    o.n = nG + cross(com, o.f);
    o.fa = vec3<S>(times(m, st.gravity) + st.force);
    o.na = st.couple + cross(com, o.fa);
  }
}

/// The backward pass: each link's sums over its subtree, moved to its origin (children first).
template <Scalar T, class S>
void tree_backward(const compiled_system<T>& c,
                   const std::vector<typename compiled_system<T>::template link_state<S>>& states,
                   std::vector<tree_link<S>>& links, bool applied) {
  for (std::size_t k = links.size(); k-- > 0;) {
    const auto& L = c.links[k];
    if (L.parent < 0) continue;
    const auto p = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)]);
    const auto& st = states[k];
    const vec3<S> f = c.to_parent(L, st, links[k].f);
    links[p].f += f;
    links[p].n += vec3<S>(c.to_parent(L, st, links[k].n) + cross(st.offset, f));
    if (!applied) continue;
    const vec3<S> fa = c.to_parent(L, st, links[k].fa);
    links[p].fa += fa;
    links[p].na += vec3<S>(c.to_parent(L, st, links[k].na) + cross(st.offset, fa));
  }
}

/// A joint's row of a generalized force given as a force and moment about its origin.
template <Scalar T, class S>
S joint_row(const typename compiled_system<T>::link& L, const vec3<S>& f, const vec3<S>& n) {
  return L.type == system_joint_definition::kind::revolute ? axis_dot<T, S>(L, n) : axis_dot<T, S>(L, f);
}
}  // namespace detail

/// What the equations' pass leaves for the joints' wrenches at the same (q, u, t): the body
/// tape's values, the links' motion, and each link's subtree sums of the inertia forces at
/// q'' = 0 and of the applied forces (tree_link's f, n, fa, na after the backward pass).  The
/// wrenches at the accelerations u' are those sums plus the subtree sums of the inertia forces
/// that u' alone gives (no velocity terms): linear in each link's forces, the same numbers in
/// exact arithmetic as a second pass with u' (tree_subtree_wrenches_into).  system_motion_into
/// keeps one for system_model's evaluation, which asks for both at one state.
template <Scalar T>
struct tree_pass {
  const compiled_system<T>* system = nullptr;  ///< the system it was computed for; null: none kept
  vector_t<T> q, u;                            ///< the state it was computed at, and
  T t = T(0);
  std::vector<T> parameters;                   ///< the system's parameters then (pass_fits)
  std::vector<T> values;
  std::vector<typename compiled_system<T>::template link_state<T>> states;
  std::vector<detail::tree_link<T>> links;
};

namespace detail {
/// a and b the same number (an interval's or a ball's two bounds); NaN never the same.
template <class T>
bool same_number(const T& a, const T& b) {
  if constexpr (scalar_traits<T>::is_interval)
    return scalar_traits<T>::lower(a) == scalar_traits<T>::lower(b) && scalar_traits<T>::upper(a) == scalar_traits<T>::upper(b);
  else
    return a == b;
}
template <class V>
bool same_numbers(const V& a, const V& b) {
  if (a.size() != b.size()) return false;
  for (decltype(a.size()) i = 0; i < a.size(); ++i)
    if (!same_number(a[i], b[i])) return false;
  return true;
}
}  // namespace detail

/// Whether `pass` was kept for c at (q, u, t), c's parameters as they are now: the joints'
/// wrenches take a pass only then (any other, from another state or before a parameter changed,
/// is ignored and the second pass runs whole).
template <Scalar T>
bool pass_fits(const tree_pass<T>& p, const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u,
               const T& t) {
  return p.system == &c && detail::same_number(p.t, t) && detail::same_numbers(p.q, q) &&
         detail::same_numbers(p.u, u) && detail::same_numbers(p.parameters, c.parameters);
}

/// tree_equations_into's recursion in S's own arithmetic (componentwise for the interval scalars);
/// in the plain scalar (S = T), `keep` non-null keeps the pass (tree_pass).
template <Scalar T, class S>
void tree_equations_componentwise_into(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u,
                                       const S& t, appell_equations<S>& e, tree_pass<T>* keep = nullptr) {
  using K = system_joint_definition::kind;
  using link_state = typename compiled_system<T>::template link_state<S>;
  struct site;
  const scratch<std::vector<S>, site> values_held;
  const scratch<std::vector<link_state>, site> states_held;
  const scratch<std::vector<detail::tree_link<S>>, site> links_held;
  std::vector<S>* values_in = &*values_held;
  std::vector<link_state>* states_in = &*states_held;
  std::vector<detail::tree_link<S>>* links_in = &*links_held;
  if constexpr (std::is_same_v<S, T>)
    if (keep) {
      keep->system = nullptr;
      values_in = &keep->values, states_in = &keep->states, links_in = &keep->links;
    }
  std::vector<detail::tree_link<S>>& links = *links_in;
  const std::vector<link_state>& states = *states_in;
  detail::tree_forward<T, S>(c, q, u, t, nullptr, *values_in, *states_in, links);
  detail::tree_backward<T, S>(c, states, links, true);
  const int n = c.def->vars.speeds;
  e.M.setZero(n, n);
  e.b.setZero(n);
  e.Q.setZero(n);
  const std::size_t N = c.links.size();
  const S* v = values_in->data();
  for (std::size_t k = 0; k < N; ++k) {
    const auto& L = c.links[k];
    if (L.type == K::fixed) continue;
    e.b(L.coordinate) = detail::joint_row<T, S>(L, links[k].f, links[k].n);
    e.Q(L.coordinate) = detail::joint_row<T, S>(L, links[k].fa, links[k].na);
  }
  // Composite rigid bodies: each link's own (m, h, I about O), then the subtrees' sums.
  for (std::size_t k = 0; k < N; ++k) {
    const auto& L = c.links[k];
    const auto& b = c.bodies[static_cast<std::size_t>(L.body)];
    detail::tree_link<S>& o = links[k];
    o.m = b.mass.at(v);
    const vec3<S> com = detail::base_vector<T, S>(L.com);
    o.h = detail::times(o.m, com);
    mat3<S> I = b.has_inertia ? b.inertia_on_body_axes(v) : mat3<S>(zero_matrix<mat3<S>>());
    if (b.has_inertia && !L.Rin_identity) {  // Rin I Rin^T
      mat3<S> A, B;
      for (int j = 0; j < 3; ++j) A.col(j) = compiled_system<T>::times(L.Rin, vec3<S>(I.col(j)));
      for (int i = 0; i < 3; ++i) B.row(i) = compiled_system<T>::times(L.Rin, vec3<S>(A.row(i).transpose())).transpose();
      I = B;
    }
    // + m (|c|^2 1 - c c^T), with h = m c: h_a c_a + h_b c_b on the diagonal, -h_i c_j off it
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j) {
          const int a = (i + 1) % 3, bb = (i + 2) % 3;
          I(i, i) += o.h(a) * com(a) + o.h(bb) * com(bb);
        } else {
          I(i, j) -= o.h(i) * com(j);
        }
      }
    o.I = I;
  }
  for (std::size_t k = N; k-- > 0;) {
    const auto& L = c.links[k];
    if (L.parent < 0) continue;
    const auto p = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)]);
    const auto& st = states[k];
    const detail::tree_link<S>& o = links[k];
    const vec3<S>& r = st.offset;
    const vec3<S> h = c.to_parent(L, st, o.h);
    const mat3<S> Ir = detail::to_parent_matrix<T, S>(c, L, st, o.I);
    detail::tree_link<S>& op = links[p];
    // shift to the parent's origin: + m (|r|^2 1 - r r^T) + (2 r.h 1 - r h^T - h r^T)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        S x = Ir(i, j);
        if (i == j) {
          const int a = (i + 1) % 3, bb = (i + 2) % 3;
          // 2 r.h - 2 r_i h_i, written without the r_i h_i that would cancel only in exact arithmetic
          const S rhi = r(a) * h(a) + r(bb) * h(bb);
          x += o.m * (r(a) * r(a) + r(bb) * r(bb)) + (rhi + rhi);
        } else {
          x -= o.m * (r(i) * r(j)) + (r(i) * h(j) + h(i) * r(j));
        }
        op.I(i, j) += x;
      }
    op.h += vec3<S>(h + detail::times(o.m, r));
    op.m += o.m;
  }
  for (std::size_t k = 0; k < N; ++k) {
    const auto& L = c.links[k];
    if (L.type == K::fixed) continue;
    const detail::tree_link<S>& o = links[k];
    vec3<S> f, nm;
    if (L.type == K::revolute) {
      f = detail::axis_cross<T, S>(L, o.h);
      if (L.along >= 0) {  // I e: a column
        for (int i = 0; i < 3; ++i) nm(i) = L.axis_negative ? S(-o.I(i, L.along)) : o.I(i, L.along);
      } else {
        nm = mat_vec(o.I, detail::base_vector<T, S>(L.axis));
      }
    } else {
      f = detail::axis_times<T, S>(L, o.m);
      nm = detail::cross_axis<T, S>(o.h, L, S(1));
    }
    const int i = L.coordinate;
    e.M(i, i) = detail::joint_row<T, S>(L, f, nm);
    std::size_t j = k;
    while (c.links[j].parent >= 0) {
      const auto& Lj = c.links[j];
      const auto& st = states[j];
      f = c.to_parent(Lj, st, f);
      nm = vec3<S>(c.to_parent(Lj, st, nm) + cross(st.offset, f));
      j = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(Lj.parent)]);
      const auto& Lp = c.links[j];
      if (Lp.type == K::fixed) continue;
      const S mij = detail::joint_row<T, S>(Lp, f, nm);
      e.M(Lp.coordinate, i) = mij;
      e.M(i, Lp.coordinate) = mij;
    }
  }
  if constexpr (std::is_same_v<S, T>)
    if (keep) {
      keep->q = q, keep->u = u, keep->t = t;
      keep->parameters = c.parameters;
      keep->system = &c;
    }
}

/// Appell's equations M u' + b = Q of a tree (tree_recursions_apply) at (q, u, t), by the
/// recursions at the top of this file.  S: T, or numbers built on T (jets, slopes, duals); the
/// interval scalars on a deep tree in balls (tree_balls.hpp).
/// `keep`: tree_pass (where the recursion is componentwise; its `system` stays null otherwise).
template <Scalar T, class S>
void tree_equations_into(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                         appell_equations<S>& e, tree_pass<T>* keep = nullptr) {
  if (keep) keep->system = nullptr;
  if constexpr (std::is_same_v<S, T> && scalar_traits<T>::is_interval)
    if (prefer_balls(c)) return tree_equations_in_balls(c, q, u, t, e);
  tree_equations_componentwise_into<T, S>(c, q, u, t, e, keep);
}

/// Every link's motion from the recursion with the accelerations udot: for each link, its
/// inertia force and moment about its origin minus the applied ones, summed over its subtree,
/// on its axes (the joint's wrench before its own actuator: system/joint_wrenches.hpp).
template <Scalar T, class S>
void tree_subtree_wrenches_componentwise_into(const compiled_system<T>& c, const vector_t<S>& q,
                                              const vector_t<S>& u, const S& t, const vector_t<S>& udot,
                                              std::vector<vec3<S>>& F, std::vector<vec3<S>>& M,
                                              std::vector<S>& values) {
  using link_state = typename compiled_system<T>::template link_state<S>;
  struct site;
  const scratch<std::vector<link_state>, site> states_held;
  const scratch<std::vector<detail::tree_link<S>>, site> links_held;
  std::vector<detail::tree_link<S>>& links = *links_held;
  detail::tree_forward<T, S>(c, q, u, t, &udot, values, *states_held, links);
  for (auto& o : links) {
    o.f -= o.fa;
    o.n -= o.na;
  }
  detail::tree_backward<T, S>(c, *states_held, links, false);
  F.resize(links.size());
  M.resize(links.size());
  for (std::size_t k = 0; k < links.size(); ++k) F[k] = links[k].f, M[k] = links[k].n;
}

/// tree_subtree_wrenches_componentwise_into from a kept pass (tree_pass, at the same q, u, t:
/// pass_fits):
/// the forward pass of u' alone (alpha = X^T alpha_p + axis q'', a_O = X^T (a_p + alpha_p x r)
/// (+ axis q'' for a prismatic joint), the inertia forces m (a_O + alpha x c) and I alpha about
/// G), its backward sums, and the kept sums of the inertia forces at q'' = 0 minus the applied.
template <Scalar T>
void tree_subtree_wrenches_from_pass(const compiled_system<T>& c, const tree_pass<T>& pass, const vector_t<T>& udot,
                                     std::vector<vec3<T>>& F, std::vector<vec3<T>>& M, std::vector<T>& values) {
  using K = system_joint_definition::kind;
  struct site;
  const scratch<std::vector<detail::tree_link<T>>, site> links_held;
  std::vector<detail::tree_link<T>>& links = *links_held;
  const auto& states = pass.states;
  const std::size_t n = c.links.size();
  values = pass.values;
  const T* v = values.data();
  links.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& L = c.links[k];
    const auto& st = states[k];
    detail::tree_link<T>& o = links[k];
    if (L.parent >= 0) {
      const detail::tree_link<T>& op = links[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)])];
      o.alpha = c.to_link(L, st, op.alpha);
      o.accel = c.to_link(L, st, vec3<T>(op.accel + cross(op.alpha, st.offset)));
    } else {
      o.alpha = vec3<T>(T(0), T(0), T(0));
      o.accel = vec3<T>(T(0), T(0), T(0));
    }
    if (L.type != K::fixed) {
      const vec3<T> along = detail::axis_times<T, T>(L, udot(L.coordinate));
      if (L.type == K::revolute) o.alpha += along;
      else o.accel += along;
    }
    const auto& b = c.bodies[static_cast<std::size_t>(L.body)];
    const T m = b.mass.at(v);
    const vec3<T> com = detail::base_vector<T, T>(L.com);
    o.f = detail::times(m, vec3<T>(o.accel + cross(o.alpha, com)));
    vec3<T> nG = vec3<T>(T(0), T(0), T(0));
    if (b.has_inertia) {
      const mat3<T> I = b.inertia_on_body_axes(v);
      if (L.Rin_identity) {
        nG = mat_vec(I, o.alpha);
      } else {
        const vec3<T> al = compiled_system<T>::transpose_times(L.Rin, o.alpha);
        nG = compiled_system<T>::times(L.Rin, vec3<T>(mat_vec(I, al)));
      }
    }
    o.n = nG + cross(com, o.f);
  }
  detail::tree_backward<T, T>(c, states, links, false);
  F.resize(n);
  M.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const detail::tree_link<T>& p = pass.links[k];
    F[k] = vec3<T>(p.f - p.fa + links[k].f);
    M[k] = vec3<T>(p.n - p.na + links[k].n);
  }
}

/// tree_subtree_wrenches_componentwise_into, the interval scalars on a deep tree in balls
/// (tree_balls.hpp); from `pass` where it was kept for this system at (q, u, t) (pass_fits).
template <Scalar T, class S>
void tree_subtree_wrenches_into(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                                const vector_t<S>& udot, std::vector<vec3<S>>& F, std::vector<vec3<S>>& M,
                                std::vector<S>& values, const tree_pass<T>* pass = nullptr) {
  if constexpr (std::is_same_v<S, T>)
    if (pass && pass_fits(*pass, c, q, u, t)) return tree_subtree_wrenches_from_pass(c, *pass, udot, F, M, values);
  if constexpr (std::is_same_v<S, T> && scalar_traits<T>::is_interval)
    if (prefer_balls(c)) return tree_subtree_wrenches_in_balls(c, q, u, t, udot, F, M, values);
  tree_subtree_wrenches_componentwise_into<T, S>(c, q, u, t, udot, F, M, values);
}

}  // namespace appell
