// appell/system/mechanics.hpp -- the compiled system as the generic path sees it
// (expression_system<T>: bodies, forces, kinematics), its constraints A(q, t) u = a(q, t)
// (expression_constraints<T>; the rows are derived in definition.hpp's header) and the
// dependent speeds solved from them (solve_speeds).
#pragma once

#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/system/tapes.hpp"

namespace appell {

namespace detail {
// Pools of working storage (linalg/scratch.hpp), one per use whose sizes differ.
struct variables_tag {};
struct kinematics_tag {};
struct body_tag {};
struct constraint_tag {};
struct cos_tag {};
struct sin_tag {};
struct rate_tag {};
struct row_tag {};
}  // namespace detail

/// The system as the generic path sees it.
template <Scalar T>
struct expression_system {
  const compiled_system<T>* c;
  int speeds() const { return c->def->vars.speeds; }
  // Working storage borrowed per call (linalg/scratch.hpp): the tapes' variables and node
  // values, the rates, the links' states; a warm thread evaluates without the heap.
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S& t) const {
    vector_t<S> qd;
    qdot_into(q, u, t, qd);
    return qd;
  }
  template <class S>
  void qdot_into(const vector_t<S>& q, const vector_t<S>& u, const S& t, vector_t<S>& qd) const {
    const scratch<std::vector<S>, detail::variables_tag> x;
    const scratch<std::vector<S>, detail::kinematics_tag> values;
    c->variables_into(q, u, t, *x);
    c->evaluate_into(c->kinematics_tape, *x, *values);
    c->rates_into(*x, *values, c->kinematics, qd);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    const scratch<std::vector<S>, detail::variables_tag> x;
    const scratch<std::vector<S>, detail::body_tag> values;
    struct site;
    const scratch<vector_t<S>, site> qd_held;
    c->variables_into(q, u, t, *x);
    c->evaluate_into(c->body_tape, *x, *values);
    c->rates_into(*x, *values, c->kinematics_on_body_tape, *qd_held);
    const vector_t<S>& qd = *qd_held;
    const S* v = values->data();
    vec3<S> g = vec3<S>::Zero();
    for (int i = 0; i < 3; ++i) g(i) = c->gravity[static_cast<std::size_t>(i)].at(v);
    const scratch<std::vector<typename compiled_system<T>::template link_state<S>>> links_held;
    auto& links = *links_held;
    if (!c->links.empty()) c->link_states_into(q, qd, g, v, links);
    for (std::size_t bi = 0; bi < c->bodies.size(); ++bi) {
      const auto& b = c->bodies[bi];
      body_state<S> s;
      if (c->link_of[bi] >= 0) {  // a link: on its inertia's axes, which turn with it
        const auto k = static_cast<std::size_t>(c->link_of[bi]);
        const auto& L = c->links[k];
        const auto& st = links[k];
        s.mass = b.mass.at(v);
        vec3<S> com;
        for (int i = 0; i < 3; ++i) com(i) = detail::from_base<S>(L.com(i));
        const vec3<S> vg = st.velocity + cross(st.omega, com);
        vec3<S> f;
        for (int i = 0; i < 3; ++i) f(i) = s.mass * st.gravity(i) + st.force(i);
        s.omega = st.omega;
        s.velocity = vg;
        s.force = f;
        s.couple = st.couple;
        if (!L.Rin_identity) {
          s.omega = compiled_system<T>::transpose_times(L.Rin, s.omega);
          s.velocity = compiled_system<T>::transpose_times(L.Rin, s.velocity);
          s.force = compiled_system<T>::transpose_times(L.Rin, s.force);
          s.couple = compiled_system<T>::transpose_times(L.Rin, s.couple);
        }
        s.frame_rate = s.omega;
        s.frame_is_body = true;
        if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
        out.push_back(s);
        continue;
      }
      s.mass = b.mass.at(v);
      for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        s.velocity(i) = b.body_axes ? b.velocity[k].at(v) : b.center[k].rate(v, qd);
        s.force(i) = b.body_axes ? b.force[k].at(v) : S(s.mass * g(i) + b.force[k].at(v));
        s.couple(i) = b.couple[k].at(v);
        if (b.has_omega) s.omega(i) = b.omega[k].at(v);
      }
      if (b.body_axes) {  // the body's own axes turn with it
        s.frame_rate = s.omega;
        s.frame_is_body = true;
      }
      if (b.has_matrix) {
        // R and R' = sum_i dR/dq_i q'_i + dR/dt; omega from the skew matrices R' R^T (fixed
        // axes, for an isotropic inertia) or R^T R' (the body's axes, turning with omega).
        mat3<S> R, Rd;
        for (int k = 0; k < 9; ++k) {
          const auto& e = b.matrix[static_cast<std::size_t>(k)];
          R(k / 3, k % 3) = e.value.at(v);
          Rd(k / 3, k % 3) = e.rate(v, qd);
        }
        auto contract = [](const mat3<S>& X, const mat3<S>& Y, bool rows, int i, int j) {  // (X Y^T)(i,j) or (X^T Y)(i,j)
          S r = S(0);
          for (int k = 0; k < 3; ++k) r += rows ? X(i, k) * Y(j, k) : X(k, i) * Y(k, j);
          return r;
        };
        if (b.isotropic) {
          s.omega = vec3<S>(contract(Rd, R, true, 2, 1), contract(Rd, R, true, 0, 2), contract(Rd, R, true, 1, 0));
        } else {
          s.omega = vec3<S>(contract(R, Rd, false, 2, 1), contract(R, Rd, false, 0, 2), contract(R, Rd, false, 1, 0));
          vec3<S> vb, fb, cb;
          for (int i = 0; i < 3; ++i) {
            vb(i) = R(0, i) * s.velocity(0) + R(1, i) * s.velocity(1) + R(2, i) * s.velocity(2);
            fb(i) = R(0, i) * s.force(0) + R(1, i) * s.force(1) + R(2, i) * s.force(2);
            cb(i) = R(0, i) * s.couple(0) + R(1, i) * s.couple(1) + R(2, i) * s.couple(2);
          }
          s.velocity = vb, s.force = fb, s.couple = cb;
          s.frame_rate = s.omega;
          s.frame_is_body = true;
        }
        if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
        out.push_back(s);
        continue;
      }
      if (b.rotations.empty()) {  // a particle, a body that does not turn, or one given by omega
        if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
        out.push_back(s);
        continue;
      }
      // The angles' sines and cosines once; their rates along q' = qd.
      const std::size_t m = b.rotations.size();
      const scratch<std::vector<S>, detail::cos_tag> c_held;
      const scratch<std::vector<S>, detail::sin_tag> sn_held;
      const scratch<std::vector<S>, detail::rate_tag> rate_held;
      std::vector<S>&c = *c_held, &sn = *sn_held, &rate = *rate_held;
      c.resize(m), sn.resize(m), rate.resize(m);
      for (std::size_t k = 0; k < m; ++k) {
        using std::sin, std::cos;
        const auto& [axis, angle] = b.rotations[k];
        rate[k] = angle.rate(v, qd);
        if (k + 1 == m && b.symmetric_last && !b.isotropic) continue;  // the spin's angle turns nothing (below)
        const S a = angle.value.at(v);
        c[k] = cos(a), sn[k] = sin(a);
      }
      auto turn = [&](std::size_t k, const vec3<S>& v, bool transpose) {  // R_k v or R_k^T v
        const int axis = b.rotations[k].first, i = (axis + 1) % 3, j = (axis + 2) % 3;
        const S sk = transpose ? S(-sn[k]) : sn[k];
        vec3<S> r = v;
        r(i) = c[k] * v(i) - sk * v(j);
        r(j) = sk * v(i) + c[k] * v(j);
        return r;
      };
      auto along = [&](std::size_t k) {  // rate_k e_(axis k)
        vec3<S> e = vec3<S>::Zero();
        e(b.rotations[k].first) = rate[k];
        return e;
      };
      if (b.isotropic) {
        // I = R I R^T = I: the fixed axes, omega = r_1 e_1 + R_1 (r_2 e_2 + R_2 (r_3 e_3 + ...)).
        vec3<S> w = along(m - 1);
        for (std::size_t k = m - 1; k-- > 0;) w = vec3<S>(turn(k, w, false) + along(k));
        s.omega = w;
        if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
        out.push_back(s);
        continue;
      }
      // The body's axes (a frame turning with omega): the inertia as given, exactly;
      // omega = R_m^T (... R_2^T (R_1^T 0 + r_1 e_1) + r_2 e_2 ...) + r_m e_m; v, force, couple turned.
      // A body symmetric about its last rotation's axis stops one rotation short: the frame
      // R_1 ... R_(m-1) turns with omega - r_m e_m and carries the same inertia (Resal's trihedron).
      const std::size_t frames = b.symmetric_last ? m - 1 : m;
      vec3<S> w = vec3<S>::Zero();
      for (std::size_t k = 0; k < frames; ++k) {
        w = vec3<S>(turn(k, w, true) + along(k));
        s.velocity = turn(k, s.velocity, true);
        s.force = turn(k, s.force, true);
        s.couple = turn(k, s.couple, true);
      }
      if (b.symmetric_last) {
        s.frame_rate = w;
        s.omega = vec3<S>(w + along(m - 1));
        if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
        out.push_back(s);
        continue;
      }
      s.omega = w;
      s.frame_rate = w;
      if (b.has_inertia) s.inertia = b.inertia_on_body_axes(v);
      out.push_back(s);
    }
  }
};

/// A link contact's rows per unit of each coordinate's rate (system_contact_definition::link):
/// 3 x nq for a point contact (the point's velocity on the fixed axes), 6 x nq for a surface
/// (the sole centre's velocity and the link's angular velocity, on the sole's axes).  From the
/// link up to the ground: r, the contact point from each ancestor's joint origin on that
/// ancestor's axes, and M, the ancestor's axes to the link's; joint j (axis a) moves the point
/// by M (a x r) and turns the link by M a per unit rate (revolute), or moves it by M a
/// (prismatic).  At the ground M turns the fixed axes onto the link's.  O(depth).
template <Scalar T, class S>
void link_contact_rows_into(const compiled_system<T>& c, const typename compiled_system<T>::contact& k,
                            const vector_t<S>& q, matrix_t<S>& J) {
  using K = system_joint_definition::kind;
  using std::cos, std::sin;
  const int nq = c.def->vars.coordinates;
  J.setZero(k.surface ? 6 : 3, nq);
  auto lift = [](const vec3<T>& x) { return vec3<S>(detail::from_base<S>(x(0)), detail::from_base<S>(x(1)), detail::from_base<S>(x(2))); };
  auto times = [](const mat3<S>& m, const vec3<S>& x) {
    vec3<S> y;
    for (int i = 0; i < 3; ++i) y(i) = m(i, 0) * x(0) + m(i, 1) * x(1) + m(i, 2) * x(2);
    return y;
  };
  auto transpose_times = [](const mat3<S>& m, const vec3<S>& x) {
    vec3<S> y;
    for (int i = 0; i < 3; ++i) y(i) = m(0, i) * x(0) + m(1, i) * x(1) + m(2, i) * x(2);
    return y;
  };
  struct site;
  const scratch<matrix_t<S>, site> cols_held;  // the velocity (rows 0-2) and angular velocity (3-5) on the link's axes
  matrix_t<S>& cols = *cols_held;
  cols.setZero(6, nq);
  vec3<S> r = lift(k.origin);
  mat3<S> M = mat3<S>::Identity();
  for (int body = k.link; body >= 0;) {
    const auto& L = c.links[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(body)])];
    typename compiled_system<T>::template link_state<S> st;
    const S qk = L.coordinate >= 0 ? q(L.coordinate) : S(0);
    if (L.type == K::revolute) st.c = cos(qk), st.s = sin(qk);
    if (L.coordinate >= 0) {
      const vec3<S> a = lift(L.axis);
      const vec3<S> w = times(M, a);
      const vec3<S> v = L.type == K::revolute ? times(M, vec3<S>(cross(a, r))) : w;
      for (int i = 0; i < 3; ++i) {
        cols(i, L.coordinate) += v(i);
        if (L.type == K::revolute) cols(3 + i, L.coordinate) += w(i);
      }
    }
    vec3<S> offset = lift(L.origin);
    if (L.type == K::prismatic) offset += compiled_system<T>::times(L.R0, compiled_system<T>::scaled(L.axis, qk));
    r = vec3<S>(c.to_parent(L, st, r) + offset);
    mat3<S> Mp;
    for (int i = 0; i < 3; ++i) {
      vec3<S> e = vec3<S>::Zero();
      e(i) = S(1);
      const vec3<S> col = times(M, c.to_link(L, st, e));
      for (int x = 0; x < 3; ++x) Mp(x, i) = col(x);
    }
    M = Mp;
    body = L.parent;
  }
  const mat3<S> F = [&] {  // the contact frame's axes on the link's: the sole's, or (point) the fixed axes
    if (!k.surface) return M;
    mat3<S> f;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f(i, j) = detail::from_base<S>(k.sole_axes(i, j));
    return f;
  }();
  for (int j = 0; j < nq; ++j) {
    const vec3<S> v = transpose_times(F, vec3<S>(cols(0, j), cols(1, j), cols(2, j)));
    for (int i = 0; i < 3; ++i) J(i, j) = v(i);
    if (!k.surface) continue;
    const vec3<S> w = transpose_times(F, vec3<S>(cols(3, j), cols(4, j), cols(5, j)));
    for (int i = 0; i < 3; ++i) J(3 + i, j) = w(i);
  }
}

/// The constraints, A(q, t) u = a(q, t), one row each (see the top of this file).
template <Scalar T>
struct expression_constraints {
  const compiled_system<T>* c;
  template <class S>
  void point_velocity_row(const typename compiled_system<T>::constraint& k, const S* v, int r, matrix_t<S>& A,
                          vector_t<S>& a) const;
  int count() const { return static_cast<int>(c->constraints.size()); }
  template <class S>
  void eval(const vector_t<S>& q, const S& t, matrix_t<S>& A, vector_t<S>& a) const {
    struct site;
    const scratch<vector_t<S>, site> u0;
    u0->setZero(c->def->vars.speeds);
    const scratch<std::vector<S>, detail::variables_tag> x;
    const scratch<std::vector<S>, detail::constraint_tag> values;
    c->variables_into(q, *u0, t, *x);
    c->evaluate_into(c->constraint_tape, *x, *values);
    const S* v = values->data();
    A.setZero();
    const scratch<matrix_t<S>, detail::row_tag> J_held;  // a link contact's rows, for its consecutive constraints
    int rows_of = -1;
    for (int r = 0; r < count(); ++r) {
      const auto& k = c->constraints[static_cast<std::size_t>(r)];
      if (k.link_contact >= 0) {  // a row of a link's contact with the fixed ground: J_row u = 0
        if (rows_of != k.link_contact) {
          link_contact_rows_into<T, S>(*c, c->contacts[static_cast<std::size_t>(k.link_contact)], q, *J_held);
          rows_of = k.link_contact;
        }
        S rhs = S(0);
        for (int i = 0; i < c->def->vars.coordinates; ++i) {
          const S ji = (*J_held)(k.link_row, i);
          if (c->def->rates_as_speeds) {
            A(r, i) += ji;
            continue;
          }
          for (const auto& [j, w] : c->kinematics_du[static_cast<std::size_t>(i)]) A(r, j) += ji * w.at(v);
          rhs += ji * c->kinematics_on_constraint_tape[static_cast<std::size_t>(i)].at(v);
        }
        a(r) = -rhs;
        continue;
      }
      if (k.body >= 0) {
        point_velocity_row(k, v, r, A, a);
        continue;
      }
      if (!k.holonomic) {
        for (const auto& [j, e] : k.du) A(r, j) = e.at(v);
        a(r) = -k.g.at(v);
        continue;
      }
      S rhs = k.f.dt.at(v);
      for (const auto& [i, e] : k.f.dq) {
        const S dfi = e.at(v);
        if (c->def->rates_as_speeds) {
          A(r, i) += dfi;
          continue;
        }
        for (const auto& [j, w] : c->kinematics_du[static_cast<std::size_t>(i)]) A(r, j) += dfi * w.at(v);
        rhs += dfi * c->kinematics_on_constraint_tape[static_cast<std::size_t>(i)].at(v);  // w_i = q'_i at u = 0
      }
      a(r) = -rhs;
    }
  }
};

namespace detail {
/// The axes e'_m = R_1 ... R_(m-1) e_(axis m) of an orientation's elementary
/// rotations, on the fixed axes (the angular velocity is sum_m a_m' e'_m).
template <Scalar T, class S>
void rotation_axes_into(const std::vector<std::pair<int, compiled_differentiated<T>>>& rotations, const S* v,
                        std::vector<vec3<S>>& axes) {
  axes.clear();
  mat3<S> R = mat3<S>::Identity();
  for (const auto& [axis, angle] : rotations) {
    axes.push_back(vec3<S>(R.col(axis)));
    using std::sin, std::cos;
    const S a0 = angle.value.at(v);
    turn_columns(R, axis, S(cos(a0)), S(sin(a0)));
  }
}
template <Scalar T, class S>
std::vector<vec3<S>> rotation_axes(const std::vector<std::pair<int, compiled_differentiated<T>>>& rotations,
                                   const S* v) {
  std::vector<vec3<S>> axes;
  rotation_axes_into<T, S>(rotations, v, axes);
  return axes;
}
}  // namespace detail

template <Scalar T>
template <class S>
void expression_constraints<T>::point_velocity_row(const typename compiled_system<T>::constraint& k, const S* v,
                                                    int r, matrix_t<S>& A, vector_t<S>& a) const {
  // v_P = sum_i c_i q'_i + c_t, linear in q' (the centre's and the angles' rates are):
  //   c_i = dG/dq_i + sum_m da_m/dq_i e'_m x (P - G),   e'_m = R_1 ... R_(m-1) e_(axis m),
  // and q' = W u + w; the row is n . c W, the right-hand side -n . (c w + c_t).
  const int nq = c->def->vars.coordinates;
  vec3<S> rel, n;
  for (int i = 0; i < 3; ++i) {
    const auto x = static_cast<std::size_t>(i);
    rel(i) = k.rel[x].at(v), n(i) = k.direction[x].at(v);
  }
  const scratch<std::vector<vec3<S>>> axes_held;
  detail::rotation_axes_into<T, S>(k.rotations, v, *axes_held);
  const std::vector<vec3<S>>& axes = *axes_held;
  // n . c_i for each coordinate, and n . c_t
  const scratch<std::vector<S>, detail::row_tag> nc_held;
  std::vector<S>& nc = *nc_held;
  nc.assign(static_cast<std::size_t>(nq), S(0));
  S nct = S(0);
  auto add = [&](int i, const S& scale, const vec3<S>& w) {  // i < 0: the t column
    const S d = scale * dot(n, w);
    if (i < 0) nct += d;
    else nc[static_cast<std::size_t>(i)] += d;
  };
  for (int x = 0; x < 3; ++x) {
    vec3<S> e = vec3<S>::Zero();
    e(x) = S(1);
    for (const auto& [i, d] : k.center[static_cast<std::size_t>(x)].dq) add(i, d.at(v), e);
    if (k.center[static_cast<std::size_t>(x)].dt) add(-1, k.center[static_cast<std::size_t>(x)].dt.at(v), e);
  }
  for (std::size_t m = 0; m < k.rotations.size(); ++m) {
    const vec3<S> w = cross(axes[m], rel);
    for (const auto& [i, d] : k.rotations[m].second.dq) add(i, d.at(v), w);
    if (k.rotations[m].second.dt) add(-1, k.rotations[m].second.dt.at(v), w);
  }
  S rhs = nct;
  for (int i = 0; i < nq; ++i) {
    const S& ci = nc[static_cast<std::size_t>(i)];
    if (c->def->rates_as_speeds) {
      A(r, i) += ci;
      continue;
    }
    for (const auto& [j, wij] : c->kinematics_du[static_cast<std::size_t>(i)]) A(r, j) += ci * wij.at(v);
    rhs += ci * c->kinematics_on_constraint_tape[static_cast<std::size_t>(i)].at(v);
  }
  for (int i = 0; i < 3; ++i)  // a moving support: n . v_P = n . v_support
    if (k.support[static_cast<std::size_t>(i)]) rhs -= n(i) * k.support[static_cast<std::size_t>(i)].at(v);
  a(r) = -rhs;
}

/// The speeds numbered in `solved` computed from the constraints at (q, t)
/// (A_b u_b = a - A_f u_f, verified for interval types), the others as given in u.
/// S: T, or multi_dual numbers of T (then the solved speeds carry their derivatives).
template <Scalar T, class S>
void solve_dependent_speeds(const compiled_system<T>& c, const vector_t<S>& q, vector_t<S>& u, const S& t,
                            const std::vector<int>& solved) {
  const int s = static_cast<int>(c.constraints.size()), n = c.def->vars.speeds;
  matrix_t<S> A(s, n);
  vector_t<S> a(s);
  expression_constraints<T>{&c}.template eval<S>(q, t, A, a);
  matrix_t<S> Ab(s, s);
  vector_t<S> rhs = a;
  for (int r = 0; r < s; ++r)
    for (int j = 0; j < n; ++j) {
      const auto at = std::find(solved.begin(), solved.end(), j);
      if (at != solved.end()) Ab(r, static_cast<Eigen::Index>(at - solved.begin())) = A(r, j);
      else rhs(r) -= A(r, j) * u(j);
    }
  const vector_t<S> ub = solve(Ab, rhs);
  for (std::size_t k = 0; k < solved.size(); ++k) u(solved[k]) = ub(static_cast<Eigen::Index>(k));
}

}  // namespace appell
