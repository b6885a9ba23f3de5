// appell/models/rolling_sphere.hpp -- the home of the scene model "rolling_sphere"
// (paper sec. 7, Example II).  Schema (SCENES.md): sphere {mass, radius, A?},
// surface {type: plane | sphere | cylinder, radius, side}, gravity, force?,
// torque?, state {center, omega}; the state must lie on the constraints.
//
// It moves as its centre and omega on the fixed axes (ode::rolling_sphere_problem), the contact
// judged along the motion where the scene asks.
//
// Everything named after the model is here: its state table (the motion's state: each
// component's name in the outputs and the scene field it starts from), its motion as an ODE
// problem (right-hand side, results and invariants along the motion), its inputs, prepare and
// evaluation with its results' names, and model_motion (start, closed form).  Its reader and
// registry entry are in src/models/rolling_sphere.cpp.
// CMake compiles the model and its integrators once per scalar (cmake/instantiate.cmake).
//
// The physics (paper sec. 7, Example II): a homogeneous sphere (mass M, radius a, central
// moment A) rolling without slipping or pivoting on a fixed surface.
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

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/reactions/cotton.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/scalar/decimal.hpp"

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

/// rolling_sphere_motion_into compiled with the model, once per standard scalar (io/model.hpp).
#define APPELL_MODEL_PHYSICS_rolling_sphere(EXTERN, T)                                                          \
  EXTERN template void rolling_sphere_motion_into<T>(const T&, const T&, const T&, const rolling_surface<T>&,  \
                                                     const vec3<T>&, const vec3<T>&, const vec3<T>&,           \
                                                     const vec3<T>&, bool, bool, rolling_sphere_result<T>&);
APPELL_EXTERN_MODEL_PHYSICS(rolling_sphere)

}  // namespace appell

namespace appell {

/// The state of the motion as reported (simulate's and enclose's columns, reference --trajectory's
/// fields): each component's name in the outputs and the scene field it starts from.
inline constexpr std::array<state_component, 6> rolling_sphere_state_table{{
    {"center_x", "center[0]"},
    {"center_y", "center[1]"},
    {"center_z", "center[2]"},
    {"omega_x", "omega[0]"},
    {"omega_y", "omega[1]"},
    {"omega_z", "omega[2]"},
}};

/// The names eval, reference and the motion's outputs share, each written once.
struct rolling_sphere_result_names {
  static constexpr const char* center_ddot = "center_ddot";
  static constexpr const char* omega_dot = "omega_dot";
  static constexpr const char* contact_force = "contact_force";  ///< the surface's force on the sphere
  static constexpr const char* normal_force = "normal_force";
  static constexpr const char* pivot_couple = "pivot_couple";
  // a judged contact's results, as every model names them (SCENES.md, "contacts")
  static constexpr const char* surface_normal_force = "surface_normal_force";
  static constexpr const char* surface_friction_force = "surface_friction_force";
};

}  // namespace appell

namespace appell::ode {

/// Example II, the sphere rolling without slipping or pivoting: x = (centre, omega) on the fixed
/// axes; x' = (omega x a n, omega') from rolling_sphere_motion.
template <Scalar T>
struct rolling_sphere_problem {
  T mass, A, a;
  rolling_surface<T> surface;
  vec3<T> force, torque;  ///< total applied force through G (weight included) and couple, fixed axes
  bool contact = false;   ///< the contact "surface" judged (a scene's "contact"), with mu as written
  std::string mu{};
  bool A_from_radius = false;  ///< A = 2/5 M a^2 (the scene gives no A): it follows a varied radius
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() { return state_names_of(rolling_sphere_state_table); }
  /// The contacts to judge along the motion: "surface" when the scene asks, with its mu.
  std::vector<std::pair<std::string, std::string>> contacts() const {
    if (!contact) return {};
    return {{"surface", mu}};
  }
  /// Whether state component i enters a constraint at the state x (validity refuses to vary it:
  /// a range of it would leave the constraint): the centre's coordinates on the surface of
  /// centres, and omega's components along which the normal n is not 0 (omega . n = 0).
  template <class S>
  bool constrains(int i, const vector_t<S>& x) const {
    const bool plane = surface.type == surface_type::plane, sphere = surface.type == surface_type::sphere;
    if (i < 3) return plane ? i == 2 : sphere || i < 2;
    const int k = i - 3;  // n is along z (plane), c (sphere), (c_x, c_y, 0) (cylinder)
    if (plane) return k == 2;
    if (!sphere && k == 2) return false;
    return !exactly_zero(x(k));
  }
  /// The parameters `appell validity --vary` can take over a range, named by their scene fields.
  std::vector<std::string> parameter_names() const {
    if (surface.type == surface_type::plane) return {"sphere.radius"};
    return {"sphere.radius", "surface.radius"};
  }
  /// Why the parameter cannot take every value of `range` ("" when it can): the radii positive,
  /// and inside a sphere or cylinder the sphere's radius below the surface's.
  std::string parameter_refusal(const std::string& name, const T& range) const {
    const T r = name == "sphere.radius" ? range : a, b = name == "surface.radius" ? range : surface.b;
    if (!certainly_positive(r)) return "the sphere's radius must be positive over the whole range";
    if (surface.type == surface_type::plane) return "";
    if (!certainly_positive(b)) return "the surface's radius must be positive over the whole range";
    if (surface.inside && !certainly_positive(T(b - r)))
      return "inside the surface, the sphere's radius must stay below the surface's over the whole range";
    return "";
  }
  /// The same problem with the parameter `name` at `value` (an interval in validity), its state x
  /// moved to match: the centre along the normal onto the new surface of centres (so that n, the
  /// contact point's direction, omega and omega . n = 0 are kept), A = 2/5 M a^2 following a
  /// sphere's radius when the scene gives no A.
  rolling_sphere_problem with_parameter(const std::string& name, const T& value, vector_t<T>& x) const {
    using std::sqrt;
    rolling_sphere_problem p = *this;
    if (name == "sphere.radius") {
      p.a = value;
      if (A_from_radius) p.A = rational<T>(2, 5) * mass * value * value;
    } else {
      p.surface.b = value;
    }
    if (surface.type == surface_type::plane) {
      x(2) = p.a;  // the plane z = 0: the centre at height a
      return p;
    }
    const int n = surface.type == surface_type::sphere ? 3 : 2;  // the radial components
    T norm2 = T(0);
    for (int i = 0; i < n; ++i) norm2 += x(i) * x(i);
    const T factor = p.surface.rho(p.a) / sqrt(norm2);
    for (int i = 0; i < n; ++i) x(i) = T(x(i) * factor);
    return p;
  }
  template <class S>
  rolling_sphere_result<S> motion(const vector_t<S>& x, bool checks, bool reactions = true) const {
    const rolling_surface<S> surf{surface.type, surface.inside, S(surface.b), S(surface.spin)};
    const vec3<S> F(S(force(0)), S(force(1)), S(force(2))), tau(S(torque(0)), S(torque(1)), S(torque(2)));
    return rolling_sphere_motion<S>(S(mass), S(A), S(a), surf, vec3<S>(x(0), x(1), x(2)), vec3<S>(x(3), x(4), x(5)), F,
                                    tau, checks, reactions);
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const rolling_sphere_result<S> r = motion(x, false, false);  // no reaction: 3 directions, not 7
    vector_t<S> d(6);
    d << r.center_velocity(0), r.center_velocity(1), r.center_velocity(2), r.omega_dot(0), r.omega_dot(1), r.omega_dot(2);
    return d;
  }
  /// appell eval's results: the centre's acceleration, omega', the contact force, its normal
  /// component and the pivoting couple.
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const rolling_sphere_result<S> r = motion(x, false);
    using name = rolling_sphere_result_names;
    out.push_back({name::center_ddot, {r.center_ddot(0), r.center_ddot(1), r.center_ddot(2)}});
    out.push_back({name::omega_dot, {r.omega_dot(0), r.omega_dot(1), r.omega_dot(2)}});
    out.push_back({name::contact_force, {r.contact_force(0), r.contact_force(1), r.contact_force(2)}});
    out.push_back({name::normal_force, {r.normal_force}});
    out.push_back({name::pivot_couple, {r.pivot_couple}});
    if (contact) {  // the contact's forces as every model names them (judged by the commands)
      const vec3<S> f = r.friction_force();
      out.push_back({name::surface_normal_force, {r.normal_force}});
      out.push_back({name::surface_friction_force, {f(0), f(1), f(2)}});
    }
  }
  /// The energy M v^2 / 2 + A omega^2 / 2 - F . c (without a couple; the force is constant),
  /// and the two constraints, 0 along the motion: the centre on the surface of centres (|c| - rho,
  /// the cylinder's radial distance - rho, c_z - a on the plane) and omega . n.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    using std::sqrt;
    const vec3<S> c(x(0), x(1), x(2)), w(x(3), x(4), x(5));
    if (exactly_zero(torque(0)) && exactly_zero(torque(1)) && exactly_zero(torque(2))) {
      const rolling_sphere_result<S> r = motion(x, false, false);
      const vec3<S> F(S(force(0)), S(force(1)), S(force(2)));
      out.push_back({"energy", {(S(mass) * dot(r.center_velocity, r.center_velocity) + S(A) * dot(w, w)) / S(2) - dot(F, c)}});
    }
    if (surface.type == surface_type::plane) {
      out.push_back({"surface_residual", {S(c(2) - S(a))}, true});
      out.push_back({"pivot_residual", {w(2)}, true});
      return;
    }
    const vec3<S> radial = surface.type == surface_type::sphere ? c : vec3<S>(c(0), c(1), S(0));
    const S norm = sqrt(dot(radial, radial));
    out.push_back({"surface_residual", {S(norm - S(surface.rho(a)))}, true});
    out.push_back({"pivot_residual", {S(dot(w, radial) / norm)}, true});
  }
};

}  // namespace appell::ode

namespace appell {

struct rolling_sphere_input : model_input {
  decimal_field mass, radius;
  std::optional<decimal_field> A;  ///< default 2/5 M a^2 (enclosed exactly)
  surface_type surface = surface_type::plane;
  bool inside = false;
  std::optional<decimal_field> b;  ///< the surface's radius (sphere, cylinder)
  std::vector<decimal_field> gravity, force, torque, center, omega;
  /// "project": accept a state off the constraints by at most this (length for the centre,
  /// rad/s for omega . n) and use its projection onto them, enclosed in the scalar's arithmetic.
  std::optional<decimal_field> project;
  /// "contact": the contact with the surface judged (SCENES.md); mu as written ("" for none).
  bool contact = false;
  std::string mu;
};

struct rolling_sphere_model {
  static constexpr const char* name = "rolling_sphere";
  using input = rolling_sphere_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    T M, A, a;
    rolling_surface<T> surface;
    vec3<T> c, omega, F, tau;
    T on_surface, no_pivot;  ///< the constraint residuals at the state
    bool projected = false;
    T center_moved = T(0), omega_moved = T(0);  ///< the projection's steps along n (when projected)
    bool contact = false;  ///< the contact "surface" judged, with mu as written ("" for none)
    std::string mu;
    bool A_from_radius = false;  ///< A not given: 2/5 M a^2 (validity's --vary sphere.radius keeps it so)
  };
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    using std::sqrt, std::abs;
    prepared<T> m;
    m.M = value<T>(in.mass);
    m.a = value<T>(in.radius);
    m.A = in.A ? value<T>(*in.A) : rational<T>(2, 5) * m.M * m.a * m.a;
    m.A_from_radius = !in.A;
    m.surface.type = in.surface;
    m.surface.inside = in.inside;
    if (in.b) m.surface.b = value<T>(*in.b);
    m.c = detail::vec3_from_decimals<T>(in.center);
    m.omega = detail::vec3_from_decimals<T>(in.omega);
    m.F = detail::vec3_from_decimals<T>(in.gravity) * m.M + detail::vec3_from_decimals<T>(in.force);
    m.tau = detail::vec3_from_decimals<T>(in.torque);
    m.contact = in.contact;
    m.mu = in.mu;
    // The state must lie on the constraints: centre on the surface of centres, omega . n = 0.
    T scale_c, scale_w;
    auto residuals = [&] {
      scale_w = sqrt(dot(m.omega, m.omega));
      if (in.surface == surface_type::plane) {
        m.on_surface = m.c(2) - m.a;
        m.no_pivot = m.omega(2);
        scale_c = abs(m.c(2)) + m.a;
      } else {
        const vec3<T> radial = in.surface == surface_type::sphere ? m.c : vec3<T>(m.c(0), m.c(1), T(0));
        const T norm = sqrt(dot(radial, radial));
        m.on_surface = norm - m.surface.rho(m.a);
        m.no_pivot = dot(m.omega, radial) / norm;
        scale_c = norm + m.surface.b + m.a;  // rho = b -+ a may cancel: its error scales with b and a
      }
    };
    residuals();
    if (in.project) {
      // At most `project` off, then the nearest state on the constraints: the centre moved along
      // the surface of centres' normal, omega's normal component removed (enclosed in T).
      const T tol = value<T>(*in.project);
      if (certainly_positive(T(abs(m.on_surface) - tol)))
        throw input_error("state.center: off the surface of centres by " + to_string(m.on_surface) +
                          ", more than project = " + in.project->text);
      if (certainly_positive(T(abs(m.no_pivot) - tol)))
        throw input_error("state.omega: omega . n = " + to_string(m.no_pivot) + ", more than project = " +
                          in.project->text);
      m.projected = true;
      m.center_moved = -m.on_surface;
      m.omega_moved = -m.no_pivot;
      if (in.surface == surface_type::plane) {
        m.c(2) = m.a;
        m.omega(2) = T(0);
      } else {
        const vec3<T> radial = in.surface == surface_type::sphere ? m.c : vec3<T>(m.c(0), m.c(1), T(0));
        const T norm2 = dot(radial, radial), factor = m.surface.rho(m.a) / sqrt(norm2);
        const T along = dot(m.omega, radial) / norm2;
        for (int i = 0; i < (in.surface == surface_type::sphere ? 3 : 2); ++i) m.c(i) = radial(i) * factor;
        m.omega = vec3<T>(m.omega - radial * along);
      }
      residuals();
    }
    if (!consistent_with_zero(m.on_surface, scale_c))
      throw input_error("state.center: not on the surface of centres (residual " + to_string(m.on_surface) + ")");
    if (!consistent_with_zero(m.no_pivot, scale_w))
      throw input_error("state.omega: omega . n must be 0 (no pivoting), residual " + to_string(m.no_pivot));
    return m;
  }
  /// with_checks::no: no Lagrange multipliers and no eq. (4) (rolling_sphere_motion's `checks`).
  /// The evaluation written over e (appell::compute_into: its names' and values' storage reused;
  /// model_functions::compute calls it for a new evaluation too).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks checks) {
    struct site;
    const scratch<rolling_sphere_result<T>, site> r_held;  // borrowed (linalg/scratch.hpp)
    const rolling_sphere_result<T>& r = *r_held;
    rolling_sphere_motion_into(m.M, m.A, m.a, m.surface, m.c, m.omega, m.F, m.tau, checks == with_checks::yes, true,
                               *r_held);
    // With a contact judged, its verdict says whether the normal force is positive, and the
    // contacts group gives the friction coefficient it requires in friction_ratio's stead.
    if (!m.contact && !certainly_positive(r.normal_force) && !certainly_negative(r.normal_force))
      throw certification_error("friction_ratio: the normal force " + to_string(r.normal_force) +
                                " cannot be told from 0");
    using W = evaluation_writer<T>;
    W out(e);
    using name = rolling_sphere_result_names;
    out.vector(W::results, name::center_ddot, "", r.center_ddot);
    out.vector(W::results, name::omega_dot, "", r.omega_dot);
    out.vector(W::results, name::contact_force, "", r.contact_force);
    out.scalar(W::results, name::normal_force, "", r.normal_force);
    out.scalar(W::results, "tangential_force", "", r.tangential_force());
    out.scalar(W::results, name::pivot_couple, "", r.pivot_couple);
    if (!m.contact) {
      out.scalar(W::results, "friction_ratio", "", T(r.tangential_force() / r.normal_force));
    } else {  // the contact's results as every model names them (SCENES.md "contacts")
      const T tangential = r.tangential_force();
      out.scalar(W::results, name::surface_normal_force, "", r.normal_force);
      out.vector(W::results, name::surface_friction_force, "", r.friction_force());
      out.scalar(W::results, "surface_tangential_force", "", tangential);
      out.contacts().push_back(judged_contact("surface", r.normal_force, tangential, m.mu));
    }
    if (checks == with_checks::yes) {
      out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
      out.scalar(W::checks, "normal_force_cotton_minus_lagrange", "", T(r.reactions(2) - r.multipliers(2)));
      out.scalar(W::checks, "pivot_couple_cotton_minus_lagrange", "", T(r.reactions(3) - r.multipliers(3)));
      out.scalar(W::checks, "surface_residual", "", m.on_surface);
      out.scalar(W::checks, "pivot_residual", "", m.no_pivot);
    }
    out.vector(W::derived, "contact_point", "", r.contact_point);
    out.vector(W::derived, "normal", "", r.normal);
    out.vector(W::derived, "center_velocity", "", r.center_velocity);
    if (m.projected) {
      out.vector(W::derived, "center", "", m.c);
      out.vector(W::derived, "omega", "", m.omega);
      out.scalar(W::derived, "center_moved", "", m.center_moved);
      out.scalar(W::derived, "omega_moved", "", m.omega_moved);
    }
    out.finish();
  }
};

APPELL_EXTERN_MODEL(rolling_sphere_model)

}  // namespace appell

namespace appell {

template <>
struct model_motion<rolling_sphere_model> {
  static constexpr bool moves = true;
  template <Scalar T>
  using problem = ode::rolling_sphere_problem<T>;
  template <Scalar T>
  static std::pair<ode::rolling_sphere_problem<T>, vector_t<T>> start(const rolling_sphere_model::prepared<T>& m) {
    vector_t<T> x0(6);
    x0 << m.c(0), m.c(1), m.c(2), m.omega(0), m.omega(1), m.omega(2);
    ode::rolling_sphere_problem<T> p{m.M, m.A, m.a, m.surface, m.F, m.tau};
    p.contact = m.contact;
    p.mu = m.mu;
    p.A_from_radius = m.A_from_radius;
    return {std::move(p), x0};
  }
  static std::vector<std::string> state_fields(const rolling_sphere_input&) { return state_fields_of(rolling_sphere_state_table); }
};

}  // namespace appell

APPELL_EXTERN_MODEL_MOTION(::appell::rolling_sphere_model)
