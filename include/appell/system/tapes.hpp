// appell/system/tapes.hpp -- a system file's expressions compiled to tapes, with their constants
// and the parameters' values in T (compiled_system<T>; the description: definition.hpp).
#pragma once

#include <optional>
#include <type_traits>

#include "appell/linalg/scratch.hpp"
#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/products.hpp"
#include "appell/system/definition.hpp"

namespace appell {

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
    int link_contact = -1, link_row = -1;  ///< a link contact's row (system_constraint_definition)
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
    bool point_body = false;  ///< a body without orientation (a point mass): a force alone, at its centre
    std::array<std::vector<std::pair<int, detail::compiled_term<T>>>, 3> omega_du;
    std::array<detail::compiled_term<T>, 3> direction;
    /// A link's contact (system_contact_definition::link): the link's body number, the contact
    /// frame's origin on the link's axes and its axes (surface: the sole's, turned from the
    /// link's; point: the fixed axes), the normal (point: fixed axes), the sole's half-lengths.
    int link = -1;
    bool surface = false;
    vec3<T> origin = zero_matrix<vec3<T>>(), normal = zero_matrix<vec3<T>>();
    mat3<T> sole_axes = mat3<T>::Identity();  ///< surface: the sole's axes on the link's (its columns)
    T half_x = T(0), half_y = T(0);
  };
  std::vector<contact> contacts;
  /// A link of a tree (system_joint_definition): its joint's constants in T, from the
  /// parameters' values (refresh_links); the effort on the body tape.
  struct link {
    int body = -1, parent = -1, coordinate = -1;  ///< parent: a body number, -1 the ground
    system_joint_definition::kind type = system_joint_definition::kind::fixed;
    int along = -1;
    int turn_i = 1, turn_j = 2;  ///< along >= 0: the plane it turns, (along + 1, along + 2) mod 3
    bool axis_negative = false;  ///< along >= 0: the axis is -e_along
    vec3<T> origin = zero_matrix<vec3<T>>(), axis = zero_matrix<vec3<T>>(), com = zero_matrix<vec3<T>>();
    mat3<T> R0 = mat3<T>::Identity(), Rin = mat3<T>::Identity();  ///< the joint's fixed rotation (L's axes to P's), the inertia axes' (to L's)
    bool R0_identity = true, Rin_identity = true;
    detail::compiled_term<T> effort;
    /// The effort over a range in place of the number the file gives (`appell validity --vary`
    /// of a joint's torque: system_problem::with_parameter), none otherwise.
    std::optional<T> effort_fixed;
    /// Whether an actuator acts at the joint.
    bool actuated() const { return effort || effort_fixed; }
    /// The actuator's effort, from the body tape's node values v.
    template <class S>
    S effort_at(const S* v) const {
      return effort_fixed ? detail::from_base<S>(*effort_fixed) : effort.at(v);
    }
  };
  std::vector<link> links;   ///< in the definition's link order (each after its parent)
  std::vector<int> link_of;  ///< each body's place in links; -1: not a link

  /// How many nodes of the tapes read the table `name` (0: no force, couple or effort calls it).
  int table_readers(const std::string& name) const {
    return body_tape.table_readers(name) + kinematics_tape.table_readers(name) + constraint_tape.table_readers(name);
  }
  /// Value k of the table `name` set to v on every tape that reads it (with_parameter); returns
  /// how many nodes read the table.
  int set_table_value(const std::string& name, std::size_t k, const T& v) {
    return body_tape.set_table_value(name, k, v) + kinematics_tape.set_table_value(name, k, v) +
           constraint_tape.set_table_value(name, k, v);
  }

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
        L.turn_i = (j.along + 1) % 3;
        L.turn_j = (j.along + 2) % 3;
        L.axis_negative = j.sign < 0;
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
  ///
  /// In the plain scalar (S = T: an evaluation, not a series), a revolute joint whose fixed
  /// rotation is not the identity, or whose axis is oblique, keeps X = R0 Rot(axis, q) as one
  /// matrix (`folded`, set by link_states_into): a vector turned by it costs one 3 x 3 product
  /// instead of two rotations, and in the interval scalars it is wrapped once instead of twice
  /// (each component of X w is the exact hull of its linear form over the box w).  On jets and
  /// slopes X stays factored: its entries would be series, each product a convolution.
  template <class S>
  struct link_state {
    static constexpr bool can_fold = std::is_same_v<S, T>;
    struct no_matrix {};
    vec3<S> omega, velocity, gravity;  ///< angular velocity, its origin's velocity, g: on L's axes
    vec3<S> offset;                    ///< L's origin from P's, on P's axes
    S c = S(1), s = S(0);              ///< cos q, sin q (revolute)
    vec3<S> force = vec3<S>::Zero(), couple = vec3<S>::Zero();  ///< by actuators: force at G, couple; L's axes
    bool folded = false;               ///< X below holds R0 Rot(axis, q)
    [[no_unique_address]] std::conditional_t<can_fold, mat3<S>, no_matrix> X{};
  };
  /// Whether link_states_into folds L's rotations into one matrix (link_state's note): where
  /// the fixed rotation is not the identity or the axis is oblique; in the native floating types
  /// every revolute joint (a 3 x 3 product costs them less than the elementary rotation's
  /// shuffles: measured, docs/benchmarks.md "Against the engines, in one run").
  bool folds(const link& L) const {
    return L.type == system_joint_definition::kind::revolute &&
           (std::is_floating_point_v<T> || !L.R0_identity || L.along < 0);
  }
  /// st.X = R0 Rot(axis, q) from st.c and st.s: the columns of Rot turned by R0.
  template <class S>
  void fold(const link& L, link_state<S>& st) const {
    if constexpr (link_state<S>::can_fold) {
      mat3<S>& X = st.X;
      if (L.along >= 0) {
        // Rot e_along = e_along; Rot e_i = c e_i + sn e_j, Rot e_j = -sn e_i + c e_j (rotate's)
        const int i = L.turn_i, j = L.turn_j;
        const S sn = L.axis_negative ? S(-st.s) : st.s;
        for (int r = 0; r < 3; ++r) {
          const S a = L.R0(r, i), b = L.R0(r, j);
          X(r, L.along) = L.R0(r, L.along);
          X(r, i) = st.c * a + sn * b;
          X(r, j) = st.c * b - sn * a;
        }
      } else {
        for (int k = 0; k < 3; ++k) {
          vec3<S> e = vec3<S>(S(0), S(0), S(0));
          e(k) = S(1);
          const vec3<S> col = rotate(L, st, e, false);
          X.col(k) = L.R0_identity ? col : times(L.R0, col);
        }
      }
      st.folded = true;
    }
  }
  /// w on the parent's axes to the link's (X^T w), and back (X w); X = R0 Rot(axis, q).
  template <class S>
  vec3<S> to_link(const link& L, const link_state<S>& st, const vec3<S>& w) const {
    if constexpr (link_state<S>::can_fold)
      if (st.folded) return transpose_times(st.X, w);
    vec3<S> r = L.R0_identity ? w : transpose_times(L.R0, w);
    if (L.type == system_joint_definition::kind::revolute) r = rotate(L, st, r, true);
    return r;
  }
  template <class S>
  vec3<S> to_parent(const link& L, const link_state<S>& st, const vec3<S>& w) const {
    if constexpr (link_state<S>::can_fold)
      if (st.folded) return times(st.X, w);
    vec3<S> r = L.type == system_joint_definition::kind::revolute ? rotate(L, st, w, false) : w;
    return L.R0_identity ? r : times(L.R0, r);
  }
  /// R w and R^T w, R in T (a joint's constant rotation) or in S itself (a folded rotation):
  /// with S = T every entry is taken as it is, each component one sum_of_products; for jets
  /// and slopes the entries are converted (from_base) and the sums written out.
  template <class U, class S>
  static vec3<S> times(const mat3<U>& R, const vec3<S>& w) {
    vec3<S> r;
    for (int i = 0; i < 3; ++i) {
      if constexpr (std::is_same_v<U, S>)
        r(i) = sum_of_products(R(i, 0), w(0), R(i, 1), w(1), R(i, 2), w(2));
      else
        r(i) = detail::from_base<S>(R(i, 0)) * w(0) + detail::from_base<S>(R(i, 1)) * w(1) + detail::from_base<S>(R(i, 2)) * w(2);
    }
    return r;
  }
  template <class U, class S>
  static vec3<S> transpose_times(const mat3<U>& R, const vec3<S>& w) {
    vec3<S> r;
    for (int i = 0; i < 3; ++i) {
      if constexpr (std::is_same_v<U, S>)
        r(i) = sum_of_products(R(0, i), w(0), R(1, i), w(1), R(2, i), w(2));
      else
        r(i) = detail::from_base<S>(R(0, i)) * w(0) + detail::from_base<S>(R(1, i)) * w(1) + detail::from_base<S>(R(2, i)) * w(2);
    }
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
      const int i = L.turn_i, j = L.turn_j;
      const bool negative = L.axis_negative != transpose;
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
    std::vector<link_state<S>> out;
    link_states_into(q, qd, g, v, out);
    return out;
  }
  /// The same into `out` (its storage reused: linalg/scratch.hpp).
  template <class S>
  void link_states_into(const vector_t<S>& q, const vector_t<S>& qd, const vec3<S>& g, const S* v,
                        std::vector<link_state<S>>& out) const {
    using K = system_joint_definition::kind;
    // Every field below is assigned, the storage of an earlier call reused (for MPFR and MPFI
    // numbers an assignment, not a new number).
    out.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) {
      const link& L = links[k];
      link_state<S>& st = out[k];
      const link_state<S>* p = L.parent >= 0 ? &out[static_cast<std::size_t>(link_of[static_cast<std::size_t>(L.parent)])] : nullptr;
      const S qk = L.coordinate >= 0 ? q(L.coordinate) : S(0), qdk = L.coordinate >= 0 ? qd(L.coordinate) : S(0);
      st.folded = false;
      for (int i = 0; i < 3; ++i) st.force(i) = S(0), st.couple(i) = S(0);
      if (L.type == K::revolute) {
        using std::sin, std::cos;
        st.c = cos(qk);
        st.s = sin(qk);
        if (folds(L)) fold(L, st);
      } else {
        st.c = S(1);
        st.s = S(0);
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
      if (!L.actuated()) continue;
      const S tau = L.effort_at(v);
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
      c.link_contact = k.link_contact, c.link_row = k.link_row;
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
        c.point_body = !b.is_link && !b.has_omega && b.rotations.empty();
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
      if (k.link >= 0) {
        c.link = k.link;
        c.surface = k.surface;
        for (int i = 0; i < 3; ++i) {
          c.origin(i) = from_decimal<T>(k.frame_origin[static_cast<std::size_t>(i)]);
          c.normal(i) = from_decimal<T>(k.frame_normal[static_cast<std::size_t>(i)]);
        }
        if (k.surface) {  // the sole's axes: Rz(yaw) Ry(pitch) Rx(roll), URDF's rpy, on the link's axes
          using std::cos, std::sin;
          const T r = from_decimal<T>(k.frame_rpy[0]), p = from_decimal<T>(k.frame_rpy[1]), y = from_decimal<T>(k.frame_rpy[2]);
          mat3<T> Rx = mat3<T>::Identity(), Ry = mat3<T>::Identity(), Rz = mat3<T>::Identity();
          Rx(1, 1) = cos(r), Rx(1, 2) = -sin(r), Rx(2, 1) = sin(r), Rx(2, 2) = cos(r);
          Ry(0, 0) = cos(p), Ry(0, 2) = sin(p), Ry(2, 0) = -sin(p), Ry(2, 2) = cos(p);
          Rz(0, 0) = cos(y), Rz(0, 1) = -sin(y), Rz(1, 0) = sin(y), Rz(1, 1) = cos(y);
          auto product = [](const mat3<T>& a, const mat3<T>& b) {
            mat3<T> m;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) m(i, j) = T(a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j));
            return m;
          };
          c.sole_axes = product(Rz, product(Ry, Rx));
          c.half_x = from_decimal<T>(k.half_lengths[0]);
          c.half_y = from_decimal<T>(k.half_lengths[1]);
        }
      }
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
    std::vector<S> x;
    variables_into(q, u, t, x);
    return x;
  }
  /// The same into x (its storage reused: linalg/scratch.hpp).
  template <class S>
  void variables_into(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<S>& x) const {
    const system_variables& v = def->vars;
    x.assign(static_cast<std::size_t>(v.size()), S(0));
    for (std::size_t i = 0; i < parameters.size(); ++i) x[i] = detail::from_base<S>(parameters[i]);
    for (int i = 0; i < v.coordinates; ++i) x[static_cast<std::size_t>(v.q(i))] = q(i);
    for (int j = 0; j < v.speeds && j < u.size(); ++j) x[static_cast<std::size_t>(v.u(j))] = u(j);
    x[static_cast<std::size_t>(v.t())] = t;
  }
  /// q' at the variables x (u included), the kinematics read from the node
  /// values `values` of a tape that holds them as `terms`.
  template <class S>
  vector_t<S> rates(const std::vector<S>& x, const std::vector<S>& values,
                    const std::vector<detail::compiled_term<T>>& terms) const {
    vector_t<S> qd;
    rates_into(x, values, terms, qd);
    return qd;
  }
  template <class S>
  void rates_into(const std::vector<S>& x, const std::vector<S>& values,
                  const std::vector<detail::compiled_term<T>>& terms, vector_t<S>& qd) const {
    const system_variables& v = def->vars;
    qd.resize(v.coordinates);
    for (int i = 0; i < v.coordinates; ++i)
      qd(i) = def->rates_as_speeds ? x[static_cast<std::size_t>(v.u(i))]
                                   : terms[static_cast<std::size_t>(i)].at(values.data());
  }
  /// The node values of `tape` at x.
  template <class S>
  std::vector<S> evaluate(const expression_tape<T>& tape, const std::vector<S>& x) const {
    std::vector<S> values;
    tape.eval(x.data(), values);
    return values;
  }
  /// The same into `values` (its storage reused).
  template <class S>
  void evaluate_into(const expression_tape<T>& tape, const std::vector<S>& x, std::vector<S>& values) const {
    tape.eval(x.data(), values);
  }
};

}  // namespace appell
