// appell/scenes/expression_system.hpp -- a mechanical system described by
// expressions: the scene model "system" (SCENES.md in this repository).
//
// The description (system_definition) is scalar-free: parsed expressions in
// the variables  parameters..., q..., u..., t  (in that order), with the
// partial derivatives the dynamics need taken symbolically once, when the
// scene is read.  compiled_system<T> holds their constants and the
// parameters' values in T; expression_system<T> is then an ordinary
// mechanical system of the generic path (system.hpp):
//   q' = kinematics(q, u, t)  (u = q' when the speeds are the coordinates' rates);
//   for each body, on the fixed axes,
//     v_G   = sum_i dr_G/dq_i q'_i + dr_G/dt,
//     omega = sum_m a_m' R_1 ... R_(m-1) e_(axis m)  for the orientation
//             R = R_1(a_1) R_2(a_2) ... (elementary rotations about x, y, z
//             by angles a_m(q, t), composed left to right, body axes to fixed),
//             or, for an orientation given as a matrix R(q, t), the vector of the
//             skew matrix R' R^T (on the body's axes: of R^T R'),
//     force = mass g + F,  couple Gamma;
//   a body that turns is given to the generic path on its own axes (a frame
//   turning with omega; components R^T x, each R_m^T applied in turn, so the
//   inertia is the exact I_body and never R I_body R^T, which intervals would
//   widen), unless its inertia is a multiple of the identity as written: then
//   R I R^T = I and the fixed axes serve;
// the library differentiates these once more (multi_dual) for J and the
// velocity-product terms, as for every other system.
// The constraints (expression_constraints<T>) read A(q, t) u = a(q, t), one row each:
//   holonomic f(q, t) = 0:       A = df/dq W,  a = -(df/dq w + df/dt),
//                                with q' = W u + w (W = dq'/du, w = q'(u = 0));
//   nonholonomic g(q, u, t) = 0: A = dg/du,    a = -g(q, 0, t)   (g affine in u).
// Their reactions are Cotton's Q'_c in speeds adapted with v_c = A u - a, equal
// to the Lagrange multipliers of those rows (both are computed; the scene's
// checks carry the difference).
// A wrench (system_wrench_definition) gathers some constraints' reactions into a
// force at a point of one body and a couple, from their virtual work.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/expr/expression.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"

namespace appell {

/// Where each kind of variable sits in the expressions' variable list.
struct system_variables {
  int parameters = 0, coordinates = 0, speeds = 0;
  int q(int i) const { return parameters + i; }
  int u(int j) const { return parameters + coordinates + j; }
  int t() const { return parameters + coordinates + speeds; }
  int size() const { return t() + 1; }
};

using shared_expression = std::shared_ptr<const expression>;

/// A function of (q, t) with its partial derivatives that are not 0 as written.
struct differentiated_expression {
  shared_expression value;
  std::vector<std::pair<int, shared_expression>> dq;  ///< (i, d value / dq_i)
  shared_expression dt;                               ///< d value / dt, or null
};

/// A link's joint (SCENES.md, "links of a tree"): how the link hangs from its parent (another
/// link, or the ground).  The link's frame L is the joint's frame: on the parent's frame P,
///   L = P . (origin, Rz(yaw) Ry(pitch) Rx(roll)) . (its motion),
/// the motion a rotation by q about `axis` (revolute), a translation q axis (prismatic), or none
/// (fixed); `axis` on L's axes (the rotation leaves it in place).  URDF's conventions.
struct system_joint_definition {
  enum class kind { revolute, prismatic, fixed };
  std::string name;
  kind type = kind::fixed;
  int parent = -1;      ///< the parent link's body number; -1: the ground (the fixed axes)
  int coordinate = -1;  ///< revolute, prismatic: the coordinate the joint's motion is
  std::array<shared_expression, 3> origin, rpy, axis;  ///< constants (null: 0)
  shared_expression effort;  ///< the actuator's torque (revolute) or force (prismatic), in q, u, t; null: none
  /// The axis as written is along +-e_along (two components literally 0): its rotations are then
  /// elementary, exactly; -1: another direction (normalized, Rodrigues' formula).
  int along = -1, sign = 1;
};

struct system_body_definition {
  std::string name;
  /// A link of a tree: placed by its joint (no centre, orientation or omega); its centre of
  /// mass at `com` on the link's axes, its inertia on the axes turned by `com_rpy` from the link's.
  bool is_link = false;
  system_joint_definition joint;
  std::array<shared_expression, 3> com, com_rpy;
  shared_expression mass;
  std::array<shared_expression, 6> inertia;  ///< central, on body axes: xx yy zz xy yz zx (null: 0)
  std::array<differentiated_expression, 3> center;  ///< G on the fixed axes
  std::vector<std::pair<int, differentiated_expression>> rotations;  ///< (axis 0/1/2, angle), left to right
  /// Or the orientation as a matrix R (body axes to fixed), row by row: R(q, t) orthogonal, det 1.
  std::array<differentiated_expression, 9> matrix;
  bool has_matrix = false;
  std::array<shared_expression, 3> force, couple;  ///< force through G and couple (null: 0), on the body's axes
  /// Given instead of an orientation: the angular velocity (affine in u), on
  /// the fixed axes (an isotropic inertia: its orientation plays no part), or
  /// with body_axes on the body's own axes, with the centre's velocity there
  /// too (the paper's free body on moving axes, sec. 3 and 4).
  std::array<shared_expression, 3> omega, velocity;
  bool has_omega = false, body_axes = false;
};

struct system_constraint_definition {
  std::string name;
  bool holonomic = true;
  differentiated_expression f;                        ///< holonomic: f(q, t) = 0
  shared_expression g;                                ///< nonholonomic: g(q, u, t) = 0
  std::vector<std::pair<int, shared_expression>> du;  ///< nonholonomic: (j, dg/du_j) not 0
  /// point_velocity (nonholonomic): n . v = 0 for the material point of body
  /// number `body` at `point`, v = v_G + omega x (point - G), n = `direction`
  /// (point and direction on the fixed axes, functions of q and t).
  int body = -1;
  std::array<shared_expression, 3> point, direction;
  /// point_velocity on a moving support: the support's velocity at the point (fixed axes, a
  /// function of q and t; null: 0), so that n . (v - support) = 0.
  std::array<shared_expression, 3> support;
};

/// The wrench that some constraints exert on one body, reduced to a point of
/// it: a force F at P and a couple M (the moment about P), on the fixed axes,
/// fixed by the constraints' virtual work (Cotton sec. 5, end):
///   J_P^T F + J_w^T M = sum_c A_c^T Q'_c   for every virtual displacement,
/// J_P, J_w the velocity of the body's material point at P and its angular
/// velocity per unit of each speed.  Unique when the body moves in 6
/// independent ways (J of rank 6); a wrench when each constraint's row A_c is
/// a virtual power of that body alone (checked when the file is read).
struct system_wrench_definition {
  std::string name;
  int body = -1;
  std::array<shared_expression, 3> point;  ///< P on the fixed axes, a function of q and t
  std::vector<int> constraints;            ///< the constraints whose reactions it gathers
};

/// A contact (SCENES.md, "contacts"): the force that some constraints exert on
/// one body at one point, split into its normal component N (along the side the
/// support pushes from) and its tangential part F_t, so that the contact can be
/// judged: it holds while N > 0 and |F_t| < mu N.  The force of each constraint c
/// per unit of its reaction is d_c: a point_velocity constraint's direction, or
/// (with `body` and `point`) the force of the wrench its unit reaction exerts
/// there (system_wrench_definition), which must be a force alone (no couple
/// about the point: checked when the file is read).
struct system_contact_definition {
  std::string name;
  std::vector<int> constraints;
  /// The body and point the force acts at; -1 when every constraint is a point_velocity
  /// constraint at one point of one body (then d_c is the direction, no wrench is solved).
  int body = -1;
  std::array<shared_expression, 3> point;
  /// An omega body (SCENES.md): d omega_i / du_j, the columns of its angular velocity.
  std::array<std::vector<std::pair<int, shared_expression>>, 3> omega_du;
  int normal = -1;  ///< the constraint whose force is along the normal, or -1: `direction` gives it
  int side = 1;     ///< +1: the support pushes along d_normal (or `direction`); -1: against it
  std::array<shared_expression, 3> direction;
  std::string mu;   ///< the friction coefficient as written (a decimal), empty: none given
};

/// A whole system file's mechanics, independent of any scalar.
struct system_definition {
  system_variables vars;
  std::vector<std::string> names;              ///< every variable, in order
  std::vector<shared_expression> parameters;   ///< each parameter's value (an expression of parameters)
  std::vector<int> parameter_order;            ///< each parameter after those it uses
  bool rates_as_speeds = true;                 ///< u = q' (no kinematics given)
  std::vector<shared_expression> kinematics;   ///< q'_i(q, u, t), when not rates_as_speeds
  std::vector<std::vector<std::pair<int, shared_expression>>> kinematics_du;  ///< (j, dq'_i/du_j) not 0
  std::array<shared_expression, 3> gravity;    ///< null: none
  std::vector<system_body_definition> bodies;
  std::vector<int> link_order;  ///< the links' body numbers, each after its parent
  std::vector<system_constraint_definition> constraints;
  std::vector<system_wrench_definition> wrenches;
  std::vector<system_contact_definition> contacts;
};

namespace detail {
/// P - G for a point P of a body and its centre G (either null: 0), with the
/// terms they share cancelled (expression::difference): both are usually written
/// from the same origin (x + ...), and over a box of states the difference
/// evaluated term by term is as wide as the origin's range twice (measured on
/// the Whipple bicycle's front contact: the remainder of a 0.004 s step's a
/// priori enclosure 1e15 times wider with xP in P and in G than without).
/// P and G are kept on the tape too, where their domains are checked.
inline shared_expression offset(const shared_expression& point, const shared_expression& center) {
  if (!center) return point;
  const expression zero = expression::parse("0", center->variables(), center->where());
  const expression& p = point ? *point : zero;
  return std::make_shared<const expression>(
      expression::difference(p, *center, p.where() + " - (" + center->where() + ")"));
}

/// R <- R R_axis(a), for cos a and sin a: an elementary rotation applied on the right.
template <class M, class S>
void turn_columns(M& R, int axis, const S& ca, const S& sa) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  for (int row = 0; row < 3; ++row) {
    const S ri = R(row, i), rj = R(row, j);
    R(row, i) = ri * ca + rj * sa;
    R(row, j) = rj * ca - ri * sa;
  }
}

/// An optional expression on a tape (an empty one is 0): at(v) reads its value
/// from the node values v of one evaluation of the tape.
template <Scalar T>
struct compiled_term {
  int node = -1;
  compiled_term() = default;
  compiled_term(expression_tape<T>& tape, const shared_expression& x) {
    if (x) node = tape.add(*x);
  }
  template <class S>
  S at(const S* v) const {
    return node >= 0 ? v[node] : S(0);
  }
  explicit operator bool() const { return node >= 0; }
};
template <Scalar T>
struct compiled_differentiated {
  compiled_term<T> value, dt;
  std::vector<std::pair<int, compiled_term<T>>> dq;
  compiled_differentiated() = default;
  compiled_differentiated(expression_tape<T>& tape, const differentiated_expression& d)
      : value(tape, d.value), dt(tape, d.dt) {
    for (const auto& [i, e] : d.dq) dq.emplace_back(i, compiled_term<T>(tape, e));
  }
  /// d/dt along q' = qd:  sum_i d/dq_i qd_i + d/dt.
  template <class S>
  S rate(const S* v, const vector_t<S>& qd) const {
    S r = dt.at(v);
    for (const auto& [i, e] : dq) r += e.at(v) * qd(i);
    return r;
  }
};
}  // namespace detail

/// A system file's mechanics with its constants and parameters in T.  It
/// refers to the definition, which must outlive it.
template <Scalar T>
struct compiled_system {
  struct body {
    detail::compiled_term<T> mass;
    std::array<detail::compiled_term<T>, 6> inertia;
    std::array<detail::compiled_differentiated<T>, 3> center;
    std::vector<std::pair<int, detail::compiled_differentiated<T>>> rotations;
    std::array<detail::compiled_differentiated<T>, 9> matrix;
    std::array<detail::compiled_term<T>, 3> force, couple, omega, velocity;
    bool has_omega = false, body_axes = false, has_matrix = false;
    bool has_inertia = false;
    bool isotropic = false;  ///< inertia a multiple of the identity, as written (then R I R^T = I)
    /// Symmetric about the axis of its last elementary rotation, as written (the two other
    /// principal moments the same expression, no product of inertia): then described on the
    /// axes before that rotation (Resal's trihedron for a top or a wheel), which carry the same
    /// inertia, so that the spin angle enters no sine or cosine (bodies() below).
    bool symmetric_last = false;
    template <class S>
    mat3<S> inertia_on_body_axes(const S* x) const {
      const auto I = [&](std::size_t k) { return inertia[k].at(x); };
      mat3<S> Ib;
      Ib << I(0), I(3), I(5), I(3), I(1), I(4), I(5), I(4), I(2);
      return Ib;
    }
  };
  struct constraint {
    bool holonomic = true;
    detail::compiled_differentiated<T> f;
    detail::compiled_term<T> g;
    std::vector<std::pair<int, detail::compiled_term<T>>> du;
    int body = -1;  ///< point_velocity: the body, and its centre and angles on the constraint tape
    std::array<detail::compiled_differentiated<T>, 3> center;
    std::vector<std::pair<int, detail::compiled_differentiated<T>>> rotations;
    std::array<detail::compiled_term<T>, 3> point, direction;
    std::array<detail::compiled_term<T>, 3> rel;  ///< P - G, the terms both share cancelled (detail::offset)
    std::array<detail::compiled_term<T>, 3> support;  ///< the support's velocity at the point (0: a fixed support)
  };
  struct wrench {  ///< on the constraint tape
    int body = -1;
    std::array<detail::compiled_differentiated<T>, 3> center;
    std::vector<std::pair<int, detail::compiled_differentiated<T>>> rotations;
    std::array<detail::compiled_term<T>, 3> point;
    std::array<detail::compiled_term<T>, 3> rel;  ///< P - G, the terms both share cancelled (detail::offset)
  };
  const system_definition* def = nullptr;
  std::vector<T> parameters;  ///< values in T
  /// Three tapes, each evaluated in one pass: what bodies() needs, what qdot()
  /// needs, and what the constraints need (at u = 0).
  expression_tape<T> body_tape, kinematics_tape, constraint_tape;
  std::vector<detail::compiled_term<T>> kinematics, kinematics_on_body_tape, kinematics_on_constraint_tape;
  std::vector<std::vector<std::pair<int, detail::compiled_term<T>>>> kinematics_du;  ///< on the constraint tape
  std::array<detail::compiled_term<T>, 3> gravity;
  std::vector<body> bodies;
  std::vector<constraint> constraints;
  std::vector<wrench> wrenches;
  struct contact {  ///< on the constraint tape
    wrench frame;   ///< the body, its centre and angles, the point (frame.body < 0: the directions serve)
    bool omega_body = false;
    std::array<std::vector<std::pair<int, detail::compiled_term<T>>>, 3> omega_du;
    std::array<detail::compiled_term<T>, 3> direction;
  };
  std::vector<contact> contacts;
  /// A link of a tree (system_joint_definition): its joint's constants in T, from the
  /// parameters' values (refresh_links); the effort on the body tape.
  struct link {
    int body = -1, parent = -1, coordinate = -1;  ///< parent: a body number, -1 the ground
    system_joint_definition::kind type = system_joint_definition::kind::fixed;
    int along = -1;
    vec3<T> origin = zero_matrix<vec3<T>>(), axis = zero_matrix<vec3<T>>(), com = zero_matrix<vec3<T>>();
    mat3<T> R0 = mat3<T>::Identity(), Rin = mat3<T>::Identity();  ///< the joint's fixed rotation (L's axes to P's), the inertia axes' (to L's)
    bool R0_identity = true, Rin_identity = true;
    detail::compiled_term<T> effort;
  };
  std::vector<link> links;   ///< in the definition's link order (each after its parent)
  std::vector<int> link_of;  ///< each body's place in links; -1: not a link

  /// The links' constants from the parameters' current values (after they change: with_parameter).
  void refresh_links() {
    std::vector<T> x(static_cast<std::size_t>(def->vars.size()), T(0));
    for (std::size_t i = 0; i < parameters.size(); ++i) x[i] = parameters[i];
    auto constant = [&](const shared_expression& e) { return e ? compiled_expression<T>(*e).eval_at(x.data()) : T(0); };
    auto rpy = [&](const std::array<shared_expression, 3>& a, bool& identity) {
      // URDF: R = Rz(yaw) Ry(pitch) Rx(roll); a factor written 0 (null) is left out, exactly.
      mat3<T> R = mat3<T>::Identity();
      identity = true;
      for (int k = 2; k >= 0; --k) {
        if (!a[static_cast<std::size_t>(k)]) continue;
        identity = false;
        using std::sin, std::cos;
        const T angle = constant(a[static_cast<std::size_t>(k)]);
        detail::turn_columns(R, k, T(cos(angle)), T(sin(angle)));
      }
      return R;
    };
    for (link& L : links) {
      const system_body_definition& b = def->bodies[static_cast<std::size_t>(L.body)];
      const system_joint_definition& j = b.joint;
      for (std::size_t i = 0; i < 3; ++i) {
        L.origin(static_cast<Eigen::Index>(i)) = constant(j.origin[i]);
        L.com(static_cast<Eigen::Index>(i)) = constant(b.com[i]);
      }
      L.R0 = rpy(j.rpy, L.R0_identity);
      L.Rin = rpy(b.com_rpy, L.Rin_identity);
      L.axis = vec3<T>(T(0), T(0), T(0));
      if (j.type == system_joint_definition::kind::fixed) continue;
      if (j.along >= 0) {
        L.axis(j.along) = T(j.sign);
        continue;
      }
      using std::sqrt;
      T n2 = T(0);
      for (std::size_t i = 0; i < 3; ++i) n2 += sqr(constant(j.axis[i]));
      const T n = sqrt(n2);
      for (std::size_t i = 0; i < 3; ++i) L.axis(static_cast<Eigen::Index>(i)) = constant(j.axis[i]) / n;
    }
  }

  /// One link's motion (on its own axes) and what its actuators do to it, in S.
  template <class S>
  struct link_state {
    vec3<S> omega, velocity, gravity;  ///< angular velocity, its origin's velocity, g: on L's axes
    vec3<S> offset;                    ///< L's origin from P's, on P's axes
    S c = S(1), s = S(0);              ///< cos q, sin q (revolute)
    vec3<S> force = vec3<S>::Zero(), couple = vec3<S>::Zero();  ///< by actuators: force at G, couple; L's axes
  };
  /// w on the parent's axes to the link's (X^T w), and back (X w); X = R0 Rot(axis, q).
  template <class S>
  vec3<S> to_link(const link& L, const link_state<S>& st, const vec3<S>& w) const {
    vec3<S> r = L.R0_identity ? w : transpose_times(L.R0, w);
    if (L.type == system_joint_definition::kind::revolute) r = rotate(L, st, r, true);
    return r;
  }
  template <class S>
  vec3<S> to_parent(const link& L, const link_state<S>& st, const vec3<S>& w) const {
    vec3<S> r = L.type == system_joint_definition::kind::revolute ? rotate(L, st, w, false) : w;
    return L.R0_identity ? r : times(L.R0, r);
  }
  template <class S>
  static vec3<S> times(const mat3<T>& R, const vec3<S>& w) {
    vec3<S> r;
    for (int i = 0; i < 3; ++i)
      r(i) = detail::from_base<S>(R(i, 0)) * w(0) + detail::from_base<S>(R(i, 1)) * w(1) + detail::from_base<S>(R(i, 2)) * w(2);
    return r;
  }
  template <class S>
  static vec3<S> transpose_times(const mat3<T>& R, const vec3<S>& w) {
    vec3<S> r;
    for (int i = 0; i < 3; ++i)
      r(i) = detail::from_base<S>(R(0, i)) * w(0) + detail::from_base<S>(R(1, i)) * w(1) + detail::from_base<S>(R(2, i)) * w(2);
    return r;
  }
  template <class S>
  static vec3<S> scaled(const vec3<T>& a, const S& x) {
    return vec3<S>(detail::from_base<S>(a(0)) * x, detail::from_base<S>(a(1)) * x, detail::from_base<S>(a(2)) * x);
  }
  /// Rot(axis, q) w, or its transpose: elementary about e_along, else Rodrigues'
  /// w cos q + (a x w) sin q + a (a . w)(1 - cos q).
  template <class S>
  vec3<S> rotate(const link& L, const link_state<S>& st, const vec3<S>& w, bool transpose) const {
    if (L.along >= 0) {
      const int i = (L.along + 1) % 3, j = (L.along + 2) % 3;
      const bool negative = (L.axis(L.along) < T(0)) != transpose;
      const S sn = negative ? S(-st.s) : st.s;
      vec3<S> r = w;
      r(i) = st.c * w(i) - sn * w(j);
      r(j) = sn * w(i) + st.c * w(j);
      return r;
    }
    vec3<S> a;
    for (int k = 0; k < 3; ++k) a(k) = detail::from_base<S>(L.axis(k));
    const vec3<S> axw = cross(a, w);
    const S aw = dot(a, w), vers = S(1) - st.c;
    const S sn = transpose ? S(-st.s) : st.s;
    vec3<S> r;
    for (int k = 0; k < 3; ++k) r(k) = w(k) * st.c + axw(k) * sn + a(k) * (aw * vers);
    return r;
  }
  /// Every link's motion at the coordinates q, rates qd, gravity g (fixed axes) and the body
  /// tape's node values v (the efforts), in link order.
  template <class S>
  std::vector<link_state<S>> link_states(const vector_t<S>& q, const vector_t<S>& qd, const vec3<S>& g, const S* v) const {
    using K = system_joint_definition::kind;
    std::vector<link_state<S>> out(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) {
      const link& L = links[k];
      link_state<S>& st = out[k];
      const link_state<S>* p = L.parent >= 0 ? &out[static_cast<std::size_t>(link_of[static_cast<std::size_t>(L.parent)])] : nullptr;
      const S qk = L.coordinate >= 0 ? q(L.coordinate) : S(0), qdk = L.coordinate >= 0 ? qd(L.coordinate) : S(0);
      if (L.type == K::revolute) {
        using std::sin, std::cos;
        st.c = cos(qk);
        st.s = sin(qk);
      }
      for (int i = 0; i < 3; ++i) st.offset(i) = detail::from_base<S>(L.origin(i));
      if (L.type == K::prismatic) st.offset += times(L.R0, scaled(L.axis, qk));
      const vec3<S> wp = p ? p->omega : vec3<S>(vec3<S>::Zero()), vp = p ? p->velocity : vec3<S>(vec3<S>::Zero());
      st.omega = to_link(L, st, wp);
      st.velocity = to_link(L, st, vec3<S>(vp + cross(wp, st.offset)));
      st.gravity = to_link(L, st, p ? p->gravity : g);
      if (L.type == K::revolute) st.omega += scaled(L.axis, qdk);
      if (L.type == K::prismatic) st.velocity += scaled(L.axis, qdk);
    }
    // The actuators: +effort on the link, -effort on its parent (a couple about the axis; a force
    // along it, on the parent at the point where the link's G is, so that the pair works
    // effort * q' and nothing else).
    for (std::size_t k = 0; k < links.size(); ++k) {
      const link& L = links[k];
      if (!L.effort) continue;
      const S tau = L.effort.at(v);
      link_state<S>& st = out[k];
      link_state<S>* p = L.parent >= 0 ? &out[static_cast<std::size_t>(link_of[static_cast<std::size_t>(L.parent)])] : nullptr;
      const vec3<S> along = scaled(L.axis, tau);
      const vec3<S> back = p ? to_parent(L, st, along) : vec3<S>(vec3<S>::Zero());
      if (L.type == K::revolute) {
        st.couple += along;
        if (p) p->couple -= back;
      } else if (L.type == K::prismatic) {
        st.force += along;
        if (p) {
          p->force -= back;
          vec3<S> com_k, com_p;
          for (int i = 0; i < 3; ++i) {
            com_k(i) = detail::from_base<S>(L.com(i));
            com_p(i) = detail::from_base<S>(links[static_cast<std::size_t>(link_of[static_cast<std::size_t>(L.parent)])].com(i));
          }
          const vec3<S> arm = st.offset + to_parent(L, st, com_k) - com_p;
          p->couple -= cross(arm, back);
        }
      }
    }
    return out;
  }

  explicit compiled_system(const system_definition& d) : def(&d) {
    parameters.assign(d.parameters.size(), T(0));
    std::vector<T> x(static_cast<std::size_t>(d.vars.size()), T(0));
    for (int p : d.parameter_order) {
      const auto i = static_cast<std::size_t>(p);
      parameters[i] = compiled_expression<T>(*d.parameters[i]).eval_at(x.data());
      x[i] = parameters[i];
    }
    for (const auto& k : d.kinematics) {
      kinematics.emplace_back(kinematics_tape, k);
      kinematics_on_body_tape.emplace_back(body_tape, k);
      kinematics_on_constraint_tape.emplace_back(constraint_tape, k);
    }
    for (const auto& row : d.kinematics_du) {
      kinematics_du.emplace_back();
      for (const auto& [j, e] : row) kinematics_du.back().emplace_back(j, detail::compiled_term<T>(constraint_tape, e));
    }
    for (std::size_t i = 0; i < 3; ++i) gravity[i] = detail::compiled_term<T>(body_tape, d.gravity[i]);
    for (const auto& b : d.bodies) {
      body c;
      auto& tape = body_tape;
      c.mass = detail::compiled_term<T>(tape, b.mass);
      for (std::size_t i = 0; i < 6; ++i) c.inertia[i] = detail::compiled_term<T>(tape, b.inertia[i]);
      for (std::size_t i = 0; i < 3; ++i) {
        c.center[i] = detail::compiled_differentiated<T>(tape, b.center[i]);
        c.force[i] = detail::compiled_term<T>(tape, b.force[i]);
        c.couple[i] = detail::compiled_term<T>(tape, b.couple[i]);
        c.omega[i] = detail::compiled_term<T>(tape, b.omega[i]);
        c.velocity[i] = detail::compiled_term<T>(tape, b.velocity[i]);
      }
      for (const auto& [axis, angle] : b.rotations)
        c.rotations.emplace_back(axis, detail::compiled_differentiated<T>(tape, angle));
      c.has_matrix = b.has_matrix;
      if (b.has_matrix)
        for (std::size_t k = 0; k < 9; ++k) c.matrix[k] = detail::compiled_differentiated<T>(tape, b.matrix[k]);
      c.has_omega = b.has_omega;
      c.body_axes = b.body_axes;
      for (const auto& e : b.inertia) c.has_inertia = c.has_inertia || bool(e);
      c.isotropic = b.inertia[0] && b.inertia[1] && b.inertia[2] && !b.inertia[3] && !b.inertia[4] && !b.inertia[5] &&
                    b.inertia[0]->to_string() == b.inertia[1]->to_string() &&
                    b.inertia[0]->to_string() == b.inertia[2]->to_string();
      if (!c.isotropic && !b.rotations.empty() && !b.inertia[3] && !b.inertia[4] && !b.inertia[5]) {
        const int axis = b.rotations.back().first;
        const auto& i1 = b.inertia[static_cast<std::size_t>((axis + 1) % 3)];
        const auto& i2 = b.inertia[static_cast<std::size_t>((axis + 2) % 3)];
        c.symmetric_last = i1 && i2 && i1->to_string() == i2->to_string();
      }
      bodies.push_back(std::move(c));
    }
    for (const auto& k : d.constraints) {
      constraint c;
      c.holonomic = k.holonomic;
      if (k.holonomic) c.f = detail::compiled_differentiated<T>(constraint_tape, k.f);
      else if (k.body < 0) c.g = detail::compiled_term<T>(constraint_tape, k.g);
      for (const auto& [j, e] : k.du) c.du.emplace_back(j, detail::compiled_term<T>(constraint_tape, e));
      c.body = k.body;
      if (k.body >= 0) {
        const system_body_definition& b = d.bodies[static_cast<std::size_t>(k.body)];
        for (std::size_t i = 0; i < 3; ++i) {
          c.center[i] = detail::compiled_differentiated<T>(constraint_tape, b.center[i]);
          c.point[i] = detail::compiled_term<T>(constraint_tape, k.point[i]);
          c.rel[i] = detail::compiled_term<T>(constraint_tape, detail::offset(k.point[i], b.center[i].value));
          c.direction[i] = detail::compiled_term<T>(constraint_tape, k.direction[i]);
          c.support[i] = detail::compiled_term<T>(constraint_tape, k.support[i]);
        }
        for (const auto& [axis, angle] : b.rotations)
          c.rotations.emplace_back(axis, detail::compiled_differentiated<T>(constraint_tape, angle));
      }
      constraints.push_back(std::move(c));
    }
    for (const auto& w : d.wrenches) {
      wrench c;
      c.body = w.body;
      const system_body_definition& b = d.bodies[static_cast<std::size_t>(w.body)];
      for (std::size_t i = 0; i < 3; ++i) {
        c.center[i] = detail::compiled_differentiated<T>(constraint_tape, b.center[i]);
        c.point[i] = detail::compiled_term<T>(constraint_tape, w.point[i]);
        c.rel[i] = detail::compiled_term<T>(constraint_tape, detail::offset(w.point[i], b.center[i].value));
      }
      for (const auto& [axis, angle] : b.rotations)
        c.rotations.emplace_back(axis, detail::compiled_differentiated<T>(constraint_tape, angle));
      wrenches.push_back(std::move(c));
    }
    for (const auto& k : d.contacts) {
      contact c;
      c.frame.body = k.body;
      if (k.body >= 0) {
        const system_body_definition& b = d.bodies[static_cast<std::size_t>(k.body)];
        c.omega_body = b.has_omega;
        for (std::size_t i = 0; i < 3; ++i) {
          c.frame.center[i] = detail::compiled_differentiated<T>(constraint_tape, b.center[i]);
          c.frame.point[i] = detail::compiled_term<T>(constraint_tape, k.point[i]);
          c.frame.rel[i] = detail::compiled_term<T>(constraint_tape, detail::offset(k.point[i], b.center[i].value));
          for (const auto& [j, e] : k.omega_du[i]) c.omega_du[i].emplace_back(j, detail::compiled_term<T>(constraint_tape, e));
        }
        for (const auto& [axis, angle] : b.rotations)
          c.frame.rotations.emplace_back(axis, detail::compiled_differentiated<T>(constraint_tape, angle));
      }
      for (std::size_t i = 0; i < 3; ++i) c.direction[i] = detail::compiled_term<T>(constraint_tape, k.direction[i]);
      contacts.push_back(std::move(c));
    }
    link_of.assign(d.bodies.size(), -1);
    for (int b : d.link_order) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(b)].joint;
      link L;
      L.body = b;
      L.parent = j.parent;
      L.coordinate = j.coordinate;
      L.type = j.type;
      L.along = j.along;
      L.effort = detail::compiled_term<T>(body_tape, j.effort);
      link_of[static_cast<std::size_t>(b)] = static_cast<int>(links.size());
      links.push_back(std::move(L));
    }
    refresh_links();
  }

  /// The variable list at (q, u, t), parameters first.
  template <class S>
  std::vector<S> variables(const vector_t<S>& q, const vector_t<S>& u, const S& t) const {
    const system_variables& v = def->vars;
    std::vector<S> x(static_cast<std::size_t>(v.size()), S(0));
    for (std::size_t i = 0; i < parameters.size(); ++i) x[i] = detail::from_base<S>(parameters[i]);
    for (int i = 0; i < v.coordinates; ++i) x[static_cast<std::size_t>(v.q(i))] = q(i);
    for (int j = 0; j < v.speeds && j < u.size(); ++j) x[static_cast<std::size_t>(v.u(j))] = u(j);
    x[static_cast<std::size_t>(v.t())] = t;
    return x;
  }
  /// q' at the variables x (u included), the kinematics read from the node
  /// values `values` of a tape that holds them as `terms`.
  template <class S>
  vector_t<S> rates(const std::vector<S>& x, const std::vector<S>& values,
                    const std::vector<detail::compiled_term<T>>& terms) const {
    const system_variables& v = def->vars;
    vector_t<S> qd(v.coordinates);
    for (int i = 0; i < v.coordinates; ++i)
      qd(i) = def->rates_as_speeds ? x[static_cast<std::size_t>(v.u(i))]
                                   : terms[static_cast<std::size_t>(i)].at(values.data());
    return qd;
  }
  /// The node values of `tape` at x.
  template <class S>
  std::vector<S> evaluate(const expression_tape<T>& tape, const std::vector<S>& x) const {
    std::vector<S> values;
    tape.eval(x.data(), values);
    return values;
  }
};

/// The system as the generic path sees it.
template <Scalar T>
struct expression_system {
  const compiled_system<T>* c;
  int speeds() const { return c->def->vars.speeds; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S& t) const {
    const std::vector<S> x = c->template variables<S>(q, u, t);
    return c->rates(x, c->evaluate(c->kinematics_tape, x), c->kinematics);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    const std::vector<S> x = c->template variables<S>(q, u, t);
    const std::vector<S> values = c->evaluate(c->body_tape, x);
    const vector_t<S> qd = c->rates(x, values, c->kinematics_on_body_tape);
    const S* v = values.data();
    vec3<S> g = vec3<S>::Zero();
    for (int i = 0; i < 3; ++i) g(i) = c->gravity[static_cast<std::size_t>(i)].at(v);
    std::vector<typename compiled_system<T>::template link_state<S>> links;
    if (!c->links.empty()) links = c->link_states(q, qd, g, v);
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
      std::vector<S> c(m), sn(m), rate(m);
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
    const vector_t<S> u0 = vector_t<S>::Zero(c->def->vars.speeds);
    const std::vector<S> x = c->template variables<S>(q, u0, t);
    const std::vector<S> values = c->evaluate(c->constraint_tape, x);
    const S* v = values.data();
    A.setZero();
    for (int r = 0; r < count(); ++r) {
      const auto& k = c->constraints[static_cast<std::size_t>(r)];
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
std::vector<vec3<S>> rotation_axes(const std::vector<std::pair<int, compiled_differentiated<T>>>& rotations,
                                   const S* v) {
  std::vector<vec3<S>> axes;
  mat3<S> R = mat3<S>::Identity();
  for (const auto& [axis, angle] : rotations) {
    axes.push_back(vec3<S>(R.col(axis)));
    using std::sin, std::cos;
    const S a0 = angle.value.at(v);
    turn_columns(R, axis, S(cos(a0)), S(sin(a0)));
  }
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
  const std::vector<vec3<S>> axes = detail::rotation_axes<T, S>(k.rotations, v);
  // n . c_i for each coordinate, and n . c_t
  std::vector<S> nc(static_cast<std::size_t>(nq), S(0));
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

/// The twist of a body at its material point P, per unit of each speed, on the
/// fixed axes (6 x n): rows 0-2 the point's velocity, rows 3-5 the angular
/// velocity, both linear in q' = W u + w (the w part, and d/dt, left out):
///   dv_P/dq'_i = dG/dq_i + sum_m da_m/dq_i e'_m x (P - G),   domega/dq'_i = sum_m da_m/dq_i e'_m.
template <Scalar T, class S>
matrix_t<S> point_twist_jacobian(const compiled_system<T>& c, const typename compiled_system<T>::wrench& w,
                                 const S* v) {
  const int nq = c.def->vars.coordinates, n = c.def->vars.speeds;
  vec3<S> rel;
  for (int i = 0; i < 3; ++i) rel(i) = w.rel[static_cast<std::size_t>(i)].at(v);
  const std::vector<vec3<S>> axes = detail::rotation_axes<T, S>(w.rotations, v);
  matrix_t<S> C = matrix_t<S>::Zero(6, nq);  // per coordinate rate
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
  if (c.def->rates_as_speeds) return C;
  matrix_t<S> J = matrix_t<S>::Zero(6, n);
  for (int i = 0; i < nq; ++i)
    for (const auto& [j, wij] : c.kinematics_du[static_cast<std::size_t>(i)]) {
      const S f = wij.at(v);
      for (int r = 0; r < 6; ++r) J(r, j) += C(r, i) * f;
    }
  return J;
}

/// The normal equations of a wrench's virtual work: N = J J^T (6 x 6) and J g.
template <class S>
std::pair<matrix_t<S>, vector_t<S>> wrench_normal_equations(const matrix_t<S>& J, const vector_t<S>& g) {
  matrix_t<S> N(6, 6);
  vector_t<S> rhs(6);
  for (int r = 0; r < 6; ++r) {
    for (int k = r; k < 6; ++k) {
      S x = S(0);
      for (Eigen::Index j = 0; j < J.cols(); ++j) x += J(r, j) * J(k, j);
      N(r, k) = x;
      N(k, r) = x;
    }
    S y = S(0);
    for (Eigen::Index j = 0; j < J.cols(); ++j) y += J(r, j) * g(j);
    rhs(r) = y;
  }
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
std::vector<constraint_wrench_result<S>> constraint_wrenches(const compiled_system<T>& c, const vector_t<S>& q,
                                                             const S& t, const vector_t<S>& reactions) {
  std::vector<constraint_wrench_result<S>> out;
  if (c.wrenches.empty()) return out;
  const int n = c.def->vars.speeds, s = static_cast<int>(c.constraints.size());
  const vector_t<S> u0 = vector_t<S>::Zero(n);
  const std::vector<S> values = c.evaluate(c.constraint_tape, c.template variables<S>(q, u0, t));
  matrix_t<S> A(s, n);
  vector_t<S> a(s);
  expression_constraints<T>{&c}.template eval<S>(q, t, A, a);
  for (std::size_t k = 0; k < c.wrenches.size(); ++k) {
    const matrix_t<S> J = point_twist_jacobian<T, S>(c, c.wrenches[k], values.data());
    vector_t<S> g = vector_t<S>::Zero(n);
    for (int r : c.def->wrenches[k].constraints)
      for (int j = 0; j < n; ++j) g(j) += A(r, j) * reactions(r);
    const auto [N, rhs] = wrench_normal_equations(J, g);
    const vector_t<S> w = solve_spd(N, rhs);
    S sq = S(0);
    for (int j = 0; j < n; ++j) {
      S e = -g(j);
      for (int r = 0; r < 6; ++r) e += J(r, j) * w(r);
      sq += sqr(e);
    }
    using std::sqrt;
    out.push_back({vec3<S>(w(0), w(1), w(2)), vec3<S>(w(3), w(4), w(5)), S(sqrt(sq))});
  }
  return out;
}

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
matrix_t<S> contact_twist_jacobian(const compiled_system<T>& c, const typename compiled_system<T>::contact& k,
                                   const S* v) {
  if (!k.omega_body) return point_twist_jacobian<T, S>(c, k.frame, v);
  const int n = c.def->vars.speeds;
  vec3<S> rel;
  for (int i = 0; i < 3; ++i) rel(i) = k.frame.rel[static_cast<std::size_t>(i)].at(v);
  matrix_t<S> J = matrix_t<S>::Zero(6, n);
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
  return J;
}

/// Each contact's force at (q, t) from the constraints' reactions (Cotton's Q'_c):
/// d_c the force of constraint c per unit of its reaction (system_contact_definition),
/// n = side d_normal / |d_normal| (or the given direction, normalized),
///   N = sum_c Q'_c d_c . n,   F_t = sum_c Q'_c (d_c - (d_c . n) n),
/// the normal constraint's own term taken as side Q' |d_normal| (no tangential part),
/// exactly, so that intervals do not widen it.  S: T, or jets of T (over a whole step).
template <Scalar T, class S = T>
std::vector<contact_force_result<S>> contact_forces(const compiled_system<T>& c, const vector_t<S>& q, const S& t,
                                                    const vector_t<S>& reactions) {
  std::vector<contact_force_result<S>> out;
  if (c.contacts.empty()) return out;
  using std::sqrt;
  const int n = c.def->vars.speeds, s = static_cast<int>(c.constraints.size());
  const vector_t<S> u0 = vector_t<S>::Zero(n);
  const std::vector<S> values = c.evaluate(c.constraint_tape, c.template variables<S>(q, u0, t));
  const S* v = values.data();
  matrix_t<S> A;
  vector_t<S> a;
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const auto& ck = c.contacts[k];
    const system_contact_definition& dk = c.def->contacts[k];
    std::vector<vec3<S>> d, m;
    if (ck.frame.body < 0) {
      for (int r : dk.constraints) {
        vec3<S> x;
        for (int i = 0; i < 3; ++i) x(i) = c.constraints[static_cast<std::size_t>(r)].direction[static_cast<std::size_t>(i)].at(v);
        d.push_back(x);
        m.push_back(zero_matrix<vec3<S>>());
      }
    } else {
      if (A.size() == 0) {
        A.resize(s, n);
        a.resize(s);
        expression_constraints<T>{&c}.template eval<S>(q, t, A, a);
      }
      const matrix_t<S> J = contact_twist_jacobian<T, S>(c, ck, v);
      for (int r : dk.constraints) {
        const vector_t<S> g = A.row(r).transpose();
        const auto [N, rhs] = wrench_normal_equations(J, g);
        const vector_t<S> w = solve_spd(N, rhs);
        d.push_back(vec3<S>(w(0), w(1), w(2)));
        m.push_back(vec3<S>(w(3), w(4), w(5)));
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
  return out;
}

template <Scalar T>
struct system_motion_result {
  vector_t<T> accelerations;  ///< u'
  vector_t<T> reactions;      ///< Cotton's Q'_c, one per constraint
  vector_t<T> multipliers;    ///< Lagrange's, for comparison
  T virtual_work_residual;    ///< eq. (4), in the speeds adapted to the constraints
};

/// The system's motion at (q, u, t): u' by Gibbs-Appell (Cotton's method when
/// there are constraints), the reactions, the Lagrange multipliers and eq. (4).
template <Scalar T>
system_motion_result<T> system_motion(const compiled_system<T>& c, const vector_t<T>& q, const vector_t<T>& u,
                                      const T& t) {
  const expression_system<T> sys{&c};
  const int n = sys.speeds();
  system_motion_result<T> r;
  if (c.constraints.empty()) {
    const appell_equations<T> eq = gibbs_appell(sys, q, u, t);
    r.accelerations = eq.accelerations();
    r.virtual_work_residual = virtual_work_residual(sys, eq, q, u, t, r.accelerations, vector_t<T>(vector_t<T>::Ones(n)));
    return r;
  }
  const expression_constraints<T> con{&c};
  const auto change = adapt_speeds<T>(con, q, t, n);
  appell_equations<T> adapted_eq;
  const constrained_motion<T> m = cotton_reactions(sys, change, q, u, t, &adapted_eq);
  r.accelerations = m.accelerations;
  r.reactions = m.reactions;
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
