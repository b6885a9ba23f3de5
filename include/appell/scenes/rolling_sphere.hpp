// appell/scenes/rolling_sphere.hpp -- paper sec. 7, Example II: a homogeneous
// sphere (mass M, radius a, central moment A) rolling without slipping or
// pivoting on a fixed surface.
//
// Speeds on a moving trihedron (sec. 4): G x y z with z along the normal n
// from the contact point to the centre; (u, v, w) the velocity of G and
// (p, q, r) the rotation of the sphere, on those axes, which turn with
// (P, Q, R).  The surface supplies exactly the trihedron rotation it implies
// and nothing more:
//   plane z = 0:            the axes are fixed, (P, Q, R) = 0;
//   sphere of radius b:     n = +-c/|c|, (P, Q, R) = +-(-v, u, 0)/rho + spin n;
//   cylinder of radius b:   n = +-(c_x, c_y, 0)/|..|, y along the axis,
//                           (P, Q, R) = +-(0, u/rho, 0) + spin n,
// rho = b + a outside (+), b - a inside (-): the radius of the surface of
// centres.  `spin` (default 0) turns the axes about n, which leaves the
// physics unchanged (it exists to test the paper's R terms).
// The constraints (22) read A u = 0 with rows u - a q, v + a p, w, r; Cotton's
// change (23) keeps (p, q) as the free speeds, u_1 = u - a q, v_1 = v + a p.
// The reactions (14) are the contact force at the contact point, on the axes
// (F - X, H - Y, K - Z in the paper's notation), and the pivoting couple L - N.
#pragma once

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"

namespace appell {

enum class surface_type { plane, sphere, cylinder };

template <Scalar T>
struct rolling_surface {
  surface_type type = surface_type::plane;
  bool inside = false;
  T b = T(0);     ///< radius of the sphere or cylinder
  T spin = T(0);  ///< rotation of the axes about n (0: none)

  /// Radius of the surface of centres (not used for the plane).
  T rho(const T& a) const { return inside ? b - a : b + a; }
  T sign() const { return inside ? T(-1) : T(1); }

  /// The unit normal n at centre c (fixed axes).
  vec3<T> normal(const vec3<T>& c) const {
    using std::sqrt;
    if (type == surface_type::plane) return vec3<T>(T(0), T(0), T(1));
    const vec3<T> radial = type == surface_type::sphere ? c : vec3<T>(c(0), c(1), T(0));
    return vec3<T>(radial / sqrt(dot(radial, radial)) * sign());
  }

  /// The trihedron at centre c: columns e1, e2, e3 = n, on the fixed axes.
  /// Sphere: the Householder reflection that takes e3 to +-n, made a rotation
  /// (rational when n is: the exact proofs rely on it); cylinder: e2 along the axis.
  mat3<T> frame(const vec3<T>& c) const {
    mat3<T> R = mat3<T>::Identity();
    if (type == surface_type::plane) return R;
    const vec3<T> n = normal(c);
    if (type == surface_type::cylinder) {
      const vec3<T> e2(T(0), T(0), T(1));
      R.col(0) = cross(e2, n);
      R.col(1) = e2;
      R.col(2) = n;
      return R;
    }
    const bool below = approx_double(n(2)) <= 0;  // v = e3 - n or e3 + n, whichever is long
    vec3<T> v = below ? vec3<T>(-n(0), -n(1), T(1) - n(2)) : vec3<T>(n(0), n(1), T(1) + n(2));
    const T vv = dot(v, v);
    mat3<T> H;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H(i, j) = (i == j ? T(1) : T(0)) - T(2) * v(i) * v(j) / vv;
    // H e3 = n (below) or -n; flip one column to get a rotation with third column n.
    R.col(0) = H.col(0);
    R.col(1) = below ? vec3<T>(-H.col(1)) : vec3<T>(H.col(1));
    R.col(2) = below ? vec3<T>(H.col(2)) : vec3<T>(-H.col(2));
    return R;
  }

  /// (P, Q, R) on the trihedron's own axes when G moves with velocity v (same axes).
  template <class S>
  vec3<S> frame_rate(const vec3<S>& v, const T& rho) const {
    vec3<S> w(S(0), S(0), S(spin));
    if (type == surface_type::sphere) w += vec3<S>(-v(1), v(0), S(0)) * S(sign() / rho);
    if (type == surface_type::cylinder) w += vec3<S>(S(0), v(0), S(0)) * S(sign() / rho);
    return w;
  }
};

/// The free sphere (6 speeds on the trihedron), before the rolling constraints.
template <Scalar T>
struct free_sphere {
  T mass, A, a;
  rolling_surface<T> surface;
  vec3<T> force, couple;  ///< total applied force through G (weight included) and couple, on the axes

  static constexpr int max_speeds = 6;  ///< differentiated in one pass (gibbs_appell.hpp)
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;  // the paper's parameters: dq_1 = u dt, ..., dq_6 = r dt
  }
  /// The same into qd (its storage reused).
  template <class S>
  void qdot_into(const vector_t<S>&, const vector_t<S>& u, const S&, vector_t<S>& qd) const {
    qd = u;
  }
  template <class S>
  void bodies(const vector_t<S>&, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    body_state<S> s;
    s.mass = S(mass);
    s.velocity = vec3<S>(u(0), u(1), u(2));
    s.omega = vec3<S>(u(3), u(4), u(5));
    s.frame_rate = surface.template frame_rate<S>(s.velocity, surface.rho(a));
    for (int i = 0; i < 3; ++i) {
      s.inertia(i, i) = S(A);
      s.force(i) = S(force(i));
      s.couple(i) = S(couple(i));
    }
    out.push_back(s);
  }
};

/// Rolling without slipping or pivoting, (22): u - a q = 0, v + a p = 0, w = 0, r = 0.
template <Scalar T>
struct rolling_constraint {
  T a;
  int count() const { return 4; }
  template <class S>
  void eval(const vector_t<S>&, const S&, matrix_t<S>& A, vector_t<S>& rhs) const {
    A.setZero();
    A(0, 0) = S(1);
    A(0, 4) = -S(a);
    A(1, 1) = S(1);
    A(1, 3) = S(a);
    A(2, 2) = S(1);
    A(3, 5) = S(1);
    rhs.setZero();
  }
};

template <Scalar T>
struct rolling_sphere_result {
  vec3<T> center_ddot, omega_dot, contact_force;  ///< fixed axes
  T normal_force, pivot_couple;
  T tangential_x, tangential_y;  ///< the contact force's components along e1, e2
  T tangential_force() const {
    using std::sqrt;
    return sqrt(sqr(tangential_x) + sqr(tangential_y));
  }
  /// The contact force's tangential part (the friction), fixed axes.
  vec3<T> friction_force() const { return vec3<T>(axes.col(0) * tangential_x + axes.col(1) * tangential_y); }
  vector_t<T> speeds_dot;   ///< (u', v', w', p', q', r') on the trihedron
  vector_t<T> reactions;    ///< Cotton's Q'_c: (F - X, H - Y, K - Z, L - N) on the trihedron
  vector_t<T> multipliers;  ///< Lagrange's, for comparison
  T virtual_work_residual;
  mat3<T> axes;             ///< the trihedron (columns) on the fixed axes
  vec3<T> frame_rate;       ///< (P, Q, R)
  vec3<T> normal, contact_point, center_velocity;  ///< the state the constraints imply (fixed axes)
};

/// Example II at centre c and rotation omega (fixed axes), with applied force
/// F_total (weight included) through G and couple tau, on the fixed axes.  Without
/// `checks` the Lagrange multipliers and eq. (4) are left out (multipliers empty,
/// virtual_work_residual 0): the motion over time needs neither (the model's problem, models/<name>.hpp).  Without
/// `reactions` (which needs `checks` off) the contact force and the pivoting couple are left 0 too:
/// the free speeds' columns alone are formed (cotton_free_motion), the accelerations the same bit
/// for bit; the motion's right-hand side.  Into r, whose vectors are reused; the working storage
/// is borrowed (linalg/scratch.hpp): with checks and reactions, nothing is taken from the heap
/// once warm.
template <Scalar T>
void rolling_sphere_motion_into(const T& mass, const T& A, const T& a, const rolling_surface<T>& surface,
                                const vec3<T>& c, const vec3<T>& omega, const vec3<T>& F_total, const vec3<T>& tau,
                                bool checks, bool reactions, rolling_sphere_result<T>& r) {
  if (checks && !reactions) throw std::invalid_argument("rolling_sphere_motion: the checks need the reactions");
  using std::sqrt;
  r.axes = surface.frame(c);
  const mat3<T> Rt = r.axes.transpose();
  const free_sphere<T> sys{mass, A, a, surface, mat_vec(Rt, F_total), mat_vec(Rt, tau)};
  const vec3<T> w = mat_vec(Rt, omega);
  struct site;
  const scratch<vector_t<T>, site> u_held, q_held;
  vector_t<T>&u = *u_held, &q = *q_held;
  u.resize(6);
  q.setZero(6);
  u << a * w(1), -a * w(0), T(0), w(0), w(1), T(0);  // on the constraints (22)
  const T t = T(0);
  const rolling_constraint<T> con{a};
  const scratch<adapted_change<rolling_constraint<T>>, site> change_held;
  adapt_speeds_keeping_into(con, 6, {3, 4}, *change_held);  // eq. (23): free speeds p, q
  const adapted_change<rolling_constraint<T>>& change = *change_held;
  const scratch<appell_equations<T>, site> adapted_eq;  // Cotton's speeds (p, q, u_1, v_1, w, r), for eq. (4) below
  const scratch<constrained_motion<T>, site> m_held;
  const constrained_motion<T>& m = *m_held;
  if (reactions) {
    cotton_reactions_into(sys, change, q, u, t, *m_held, &*adapted_eq);
  } else {
    m_held->accelerations = cotton_free_motion<3>(sys, change, q, u, t);
    m_held->reactions.setZero(con.count());
  }
  r.speeds_dot = m.accelerations;
  r.reactions = m.reactions;
  if (checks) {
    const scratch<constrained_motion<T>, site> lagrange;
    lagrange_multipliers_into(sys, con, q, u, t, *lagrange);
    r.multipliers = lagrange->reactions;
  } else {
    r.multipliers.resize(0);
  }
  const vec3<T> v(u(0), u(1), u(2)), wF(u(3), u(4), u(5));
  r.frame_rate = surface.template frame_rate<T>(v, surface.rho(a));
  const vec3<T> aG = vec3<T>(m.accelerations(0), m.accelerations(1), m.accelerations(2)) + cross(r.frame_rate, v);
  const vec3<T> alpha = vec3<T>(m.accelerations(3), m.accelerations(4), m.accelerations(5)) + cross(r.frame_rate, wF);
  r.center_ddot = mat_vec(r.axes, aG);
  r.omega_dot = mat_vec(r.axes, alpha);
  r.contact_force = mat_vec(r.axes, vec3<T>(m.reactions(0), m.reactions(1), m.reactions(2)));
  r.normal_force = m.reactions(2);
  r.tangential_x = m.reactions(0);
  r.tangential_y = m.reactions(1);
  r.pivot_couple = m.reactions(3);
  r.normal = vec3<T>(r.axes.col(2));
  r.contact_point = c - r.normal * a;
  r.center_velocity = mat_vec(r.axes, v);  // (a q, -a p, 0) on the trihedron: omega x a n
  r.virtual_work_residual = T(0);
  if (!checks) return;
  // eq. (4) in Cotton's speeds (p, q, u_1, v_1, w, r), with the equations cotton_reactions formed there
  const auto adapted = change_speeds(sys, detail::change_ref{&change}, 6);
  const scratch<vector_t<T>, site> vv_held, vdot_held, ones;
  vector_t<T>&vv = *vv_held, &vdot = *vdot_held;
  vv.setZero(6);
  vdot.setZero(6);
  ones->setOnes(6);
  vv(0) = w(0);
  vv(1) = w(1);
  vdot(0) = m.accelerations(3);
  vdot(1) = m.accelerations(4);
  r.virtual_work_residual = virtual_work_residual(adapted, *adapted_eq, q, vv, t, vdot, *ones);
}
/// The same returned.
template <Scalar T>
rolling_sphere_result<T> rolling_sphere_motion(const T& mass, const T& A, const T& a,
                                               const rolling_surface<T>& surface, const vec3<T>& c,
                                               const vec3<T>& omega, const vec3<T>& F_total, const vec3<T>& tau,
                                               bool checks = true, bool reactions = true) {
  rolling_sphere_result<T> r;
  rolling_sphere_motion_into(mass, A, a, surface, c, omega, F_total, tau, checks, reactions, r);
  return r;
}

}  // namespace appell
