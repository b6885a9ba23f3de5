// appell/ode/problems.hpp -- the scenes as ordinary differential equations.
//
// Each problem is the scene's own dynamics (the functions `appell eval` runs),
// called on whatever scalar the integrator needs: T for a point step, jet<T>
// for Taylor coefficients, multi_dual<jet<T>, dim> for their Jacobian (the
// wrapping control of ode/enclose.hpp).  No scene is implemented twice: the
// right-hand sides below only arrange the scene's state into x and call it.
// Each models only what the scene requires (issue 12): Euler's body is omega
// alone; the top on its pivot is its three Euler angles and their rates; the
// top on the cone theta, phi and their rates (psi = f(theta)); the rolling
// sphere its centre and omega (a homogeneous sphere's orientation is not needed).
//
//   dim, state_names()        the state x
//   rhs<S>(x)                 x'
//   results<S>(x, out)        the scene's results along the motion (accelerations, reactions)
//   invariants<S>(x, out)     first integrals: energy where it is conserved, momenta
//   check_state(x0)           refuses a state the scene refuses (exit 2 in the CLI)
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scenes/euler_body.hpp"
#include "appell/scenes/rolling_sphere.hpp"
#include "appell/scenes/top_on_cone.hpp"
#include "appell/scenes/heavy_top.hpp"

namespace appell::ode {

/// Euler's body (paper sec. 3): x = omega = (p, q, r) on the principal axes.
template <Scalar T>
struct euler_body_problem {
  euler_body<T> body;
  static constexpr int dim = 3;
  static std::vector<std::string> state_names() { return {"p", "q", "r"}; }

  template <class S>
  euler_body<S> body_in() const {
    return {vec3<S>(S(body.inertia(0)), S(body.inertia(1)), S(body.inertia(2))),
            vec3<S>(S(body.torque(0)), S(body.torque(1)), S(body.torque(2)))};
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    return euler_body_equations(body_in<S>(), vec3<S>(x(0), x(1), x(2))).accelerations();
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const vector_t<S> w = rhs(x);
    out.push_back({"omega_dot", {w(0), w(1), w(2)}});
  }
  /// Without torque: the kinetic energy 1/2 omega.I omega and |I omega|^2 (Euler's two integrals).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    if (!torque_free()) return;
    S e = S(0), l2 = S(0);
    for (int i = 0; i < 3; ++i) {
      const S Ii = S(body.inertia(i));
      e += Ii * x(i) * x(i);
      l2 += Ii * Ii * x(i) * x(i);
    }
    out.push_back({"energy", {e / S(2)}});
    out.push_back({"angular_momentum_squared", {l2}});
  }
  bool torque_free() const {
    for (int i = 0; i < 3; ++i)
      if (!exactly_zero(body.torque(i))) return false;
    return true;
  }
};

/// The heavy symmetric top on its pivot: x = (psi, theta, phi, psi', theta', phi').
template <Scalar T>
struct heavy_top_problem {
  T A, C, mass, l, g;
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() {
    return {"psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot"};
  }
  template <class S>
  static top_on_pivot_state<S> state(const vector_t<S>& x) {
    return {x(0), x(1), x(2), x(3), x(4), x(5)};
  }
  template <class S>
  cotton_result<S> cotton(const vector_t<S>& x) const {
    return top_on_pivot_cotton(S(A), S(C), S(mass), S(l), S(g), state(x));
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    // The accelerations alone (no pivot force): 4 directions differentiated instead of 7.
    const vector_t<S> a = top_on_pivot_accelerations(S(A), S(C), S(mass), S(l), S(g), state(x));
    vector_t<S> d(6);
    d << x(3), x(4), x(5), a(0), a(1), a(2);
    return d;
  }
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const cotton_result<S> c = cotton(x);
    out.push_back({"psi_ddot", {c.free_accelerations(0)}});
    out.push_back({"theta_ddot", {c.free_accelerations(1)}});
    out.push_back({"phi_ddot", {c.free_accelerations(2)}});
    out.push_back({"pivot_force", {c.reactions(0), c.reactions(1), c.reactions(2)}});
  }
  /// Energy 1/2 A (theta'^2 + psi'^2 sin^2 theta) + 1/2 C r^2 + m g l cos theta, with the spin
  /// r = phi' + psi' cos theta; the momenta about the vertical, A psi' sin^2 theta + C r cos theta,
  /// and about the axis, C r.
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    using std::sin, std::cos;
    S s, c;
    sin_cos(x(1), s, c);
    const S r = x(5) + x(3) * c;
    const S sA(A), sC(C);
    const S e = (sA * (x(4) * x(4) + x(3) * x(3) * s * s) + sC * r * r) / S(2) + S(mass) * S(g) * S(l) * c;
    out.push_back({"energy", {e}});
    out.push_back({"momentum_vertical", {sA * x(3) * s * s + sC * r * c}});
    out.push_back({"momentum_axis", {sC * r}});
  }
};

/// The heavy symmetric top on its pivot in Resal's speeds (Appell's quasi-velocities, paper
/// sec. 5): x = (psi, theta, phi, p1, p2, p3) with p = (theta', psi' sin theta, psi' cos theta + phi'),
/// the angular velocity on Resal's trihedron (n, e_z x n, e_z).  There the central inertia is the
/// constant diag(A - m l^2, A - m l^2, C) and Appell's M = diag(A, A, C): the Gibbs-Appell path
/// solves no matrix of theta over a step's box, the step's series are far tighter than in Euler
/// rates (heavy_top_problem), and the spin sits in p3 alone.  The motion of the scene heavy_top
/// (io/models/heavy_top_motion.hpp): reported() gives the scene's state (psi, theta, phi, psi',
/// theta', phi') from x, and the results and invariants are those of heavy_top_problem.
template <Scalar T>
struct heavy_top_resal_problem {
  T A, C, mass, l, g;
  static constexpr int dim = 6;
  static std::vector<std::string> state_names() { return {"psi", "theta", "phi", "p1", "p2", "p3"}; }
  static std::vector<std::string> reported_names() { return heavy_top_problem<T>::state_names(); }

  /// The top with its speeds p: q' = (p2 / sin theta, p1, p3 - p2 cos theta / sin theta).
  struct system {
    T A, C, mass, l, g;
    static constexpr int max_speeds = 3;
    int speeds() const { return 3; }
    template <class S>
    vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& p, const S&) const {
      S st, ct;
      sin_cos(q(1), st, ct);
      const S psi_dot = p(1) / st;
      vector_t<S> d(3);
      d << psi_dot, p(0), S(p(2) - psi_dot * ct);
      return d;
    }
    template <class S>
    void bodies(const vector_t<S>& q, const vector_t<S>& p, const S&, std::vector<body_state<S>>& out) const {
      S st, ct;
      sin_cos(q(1), st, ct);
      // the trihedron turns with theta' n + psi' e3; the top with p (heavy_top_resal's body)
      out.push_back(heavy_top_resal<S>{S(A), S(C), S(mass), S(l), S(g)}.body(st, ct, vec3<S>(p(0), p(1), S(p(1) * ct / st)),
                                                                              vec3<S>(p(0), p(1), p(2))));
    }
  };
  /// x from the scene's state (psi, theta, phi, psi', theta', phi').
  static vector_t<T> from_euler_rates(const vector_t<T>& y) {
    using std::sin, std::cos;
    const T st = sin(y(1)), ct = cos(y(1));
    vector_t<T> x(6);
    x << y(0), y(1), y(2), y(4), T(y(3) * st), T(y(3) * ct + y(5));
    return x;
  }
  /// The scene's state (psi, theta, phi, psi', theta', phi') from x.
  template <class S>
  static vector_t<S> reported(const vector_t<S>& x) {
    S st, ct;
    sin_cos(x(1), st, ct);
    const S psi_dot = x(4) / st;
    vector_t<S> y(6);
    y << x(0), x(1), x(2), psi_dot, x(3), S(x(5) - psi_dot * ct);
    return y;
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const typename heavy_top_resal_problem<S>::system sys{S(A), S(C), S(mass), S(l), S(g)};
    const vector_t<S> q = x.head(3), p = x.tail(3);
    const vector_t<S> qd = sys.qdot(q, p, S(0));
    const vector_t<S> a = cotton_free_accelerations<4>(sys, q, p, S(0), 0);
    vector_t<S> d(6);
    d << qd(0), qd(1), qd(2), a(0), a(1), a(2);
    return d;
  }
  /// heavy_top_problem's results at the scene's state (psi'', theta'', phi'' and the pivot force).
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    heavy_top_problem<T>{A, C, mass, l, g}.results(reported(x), out);
  }
  /// The energy 1/2 (A (p1^2 + p2^2) + C p3^2) + m g l cos theta, the momenta about the vertical,
  /// A p2 sin theta + C p3 cos theta, and about the axis, C p3 (heavy_top_problem's, in p).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    S st, ct;
    sin_cos(x(1), st, ct);
    const S sA(A), sC(C);
    out.push_back({"energy", {(sA * (x(3) * x(3) + x(4) * x(4)) + sC * x(5) * x(5)) / S(2) + S(mass) * S(g) * S(l) * ct}});
    out.push_back({"momentum_vertical", {sA * x(4) * st + sC * x(5) * ct}});
    out.push_back({"momentum_axis", {sC * x(5)}});
  }
};

/// Example I, the heavy top forced onto the cone psi = f(theta): x = (theta, phi, theta', phi').
template <Scalar T>
struct top_on_cone_problem {
  heavy_top<T> top;
  expression_cone<T> cone;
  static constexpr int dim = 4;
  static std::vector<std::string> state_names() { return {"theta", "phi", "theta_dot", "phi_dot"}; }

  template <class S>
  heavy_top<S> top_in() const {
    return {S(top.A), S(top.C), S(top.mass), S(top.l), S(top.g)};
  }
  template <class S>
  top_on_cone_state<S> state(const vector_t<S>& x) const {
    return {cone.psi(x(0)), x(0), x(1), x(2), x(3)};
  }
  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const vector_t<S> a = top_on_cone_accelerations(top_in<S>(), cone, state(x));  // without H
    vector_t<S> d(4);
    d << x(2), x(3), a(0), a(1);
    return d;
  }
  /// psi and psi' (the cone's), the accelerations and H (Cotton's reaction: the couple's moment
  /// about the vertical), as appell eval gives them.  Not the couple's three components: they
  /// come from a 3 x 3 solve whose matrix, over a whole step's box, is too wide to certify.
  template <class S>
  void results(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
    const top_on_cone_result<S> r = top_on_cone_motion(top_in<S>(), cone, state(x), false);
    out.push_back({"psi", {cone.psi(x(0))}});
    out.push_back({"psi_dot", {cone.fprime(x(0)) * x(2)}});
    out.push_back({"theta_ddot", {r.theta_ddot}});
    out.push_back({"phi_ddot", {r.phi_ddot}});
    out.push_back({"psi_ddot", {r.psi_ddot}});
    out.push_back({"H", {r.H}});
  }
  /// The energy: the cone is fixed and frictionless, so its couple does no work; the top's
  /// energy is heavy_top_problem's at (psi, theta, phi, f'(theta) theta', theta', phi').
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const;
};

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
  static std::vector<std::string> state_names() {
    return {"center_x", "center_y", "center_z", "omega_x", "omega_y", "omega_z"};
  }
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
    out.push_back({"center_ddot", {r.center_ddot(0), r.center_ddot(1), r.center_ddot(2)}});
    out.push_back({"omega_dot", {r.omega_dot(0), r.omega_dot(1), r.omega_dot(2)}});
    out.push_back({"contact_force", {r.contact_force(0), r.contact_force(1), r.contact_force(2)}});
    out.push_back({"normal_force", {r.normal_force}});
    out.push_back({"pivot_couple", {r.pivot_couple}});
    if (contact) {  // the contact's forces as every model names them (judged by the commands)
      const vec3<S> f = r.friction_force();
      out.push_back({"surface_normal_force", {r.normal_force}});
      out.push_back({"surface_friction_force", {f(0), f(1), f(2)}});
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

template <Scalar T>
template <class S>
void top_on_cone_problem<T>::invariants(const vector_t<S>& x, std::vector<named_values<S>>& out) const {
  const heavy_top_problem<T> free_top{top.A, top.C, top.mass, top.l, top.g};
  vector_t<S> y(6);
  y << cone.psi(x(0)), x(0), x(1), S(cone.fprime(x(0)) * x(2)), x(2), x(3);
  std::vector<named_values<S>> all;
  free_top.invariants(y, all);
  out.push_back(all.front());  // the energy (the momenta are not conserved: the cone's couple)
}

// The integrators of the problems above, compiled once by the library (generated units:
// cmake/instantiate.cmake) and declared here, so that every unit that can name one of these
// problems links them instead of compiling them again (docs/architecture.md, "Build time"):
// taylor_series in every scalar, simulate in the point scalars (taylor.hpp's macros), the
// slopes and enclose in the interval scalars (enclose.hpp's); a use of the other kind's would
// not link (it does not compile either).

/// The problems of the built-in models that move, in scalar T: X(problem, T) for each.
#define APPELL_ODE_BUILTIN_PROBLEMS(X, T)                                                     \
  X(::appell::ode::euler_body_problem<T>, T) X(::appell::ode::heavy_top_resal_problem<T>, T) \
  X(::appell::ode::rolling_sphere_problem<T>, T) X(::appell::ode::top_on_cone_problem<T>, T)
#define APPELL_ODE_DETAIL_EXTERN_BUILTIN(ctx, T, name)                                                   \
  APPELL_ODE_BUILTIN_PROBLEMS(APPELL_ODE_EXTERN_SERIES, T) APPELL_ODE_BUILTIN_PROBLEMS(APPELL_ODE_EXTERN_SIMULATE, T) \
  APPELL_ODE_BUILTIN_PROBLEMS(APPELL_ODE_EXTERN_ENCLOSE, T)
APPELL_STANDARD_SCALARS(APPELL_ODE_DETAIL_EXTERN_BUILTIN, )
#undef APPELL_ODE_DETAIL_EXTERN_BUILTIN

}  // namespace appell::ode
