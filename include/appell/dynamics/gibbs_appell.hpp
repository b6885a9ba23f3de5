// appell/dynamics/gibbs_appell.hpp -- Gibbs-Appell equations of a user's system.
//
// A system is described once, as templated C++ (see examples/ and models/):
//
//   struct my_system {
//     int speeds() const;                                   // k = dim u
//     template <class S> vector_t<S> qdot(q, u, t) const;   // q' = W(q,t) u + w(q,t)
//     template <class S> void bodies(q, u, t, std::vector<body_state<S>>& out) const;
//     static constexpr int max_speeds = ...;  // optional: then differentiated in one evaluation
//   };
//
// For each rigid body (or particle: zero inertia, zero omega) `bodies` gives,
// in components on a frame F of its choice that turns with angular velocity
// `frame_rate` (0 for a fixed frame): mass, central inertia tensor (it may vary
// with time, as in paper sec. 4), velocity of G and angular velocity -- both
// affine in u -- and the applied force through G and couple.
//
// The library differentiates the kinematics itself (dual.hpp): with
// v = J u + j,  a_G = J_v u' + c_v,  alpha = J_w u' + c_w, where
// c = d/dt(J u + j)|_{u fixed} + frame_rate x (J u + j).  Appell's acceleration
// energy of a body (docs/design.md §1),
//   S = 1/2 m |a_G|^2 + 1/2 alpha . I alpha + alpha . (omega x I omega) + (free of u'),
// gives S2 + S1 = 1/2 u'^T M u' + b^T u'  (S0 is never formed: Cotton sec. 2) with
//   M = sum m J_v^T J_v + J_w^T I J_w,
//   b = sum m J_v^T c_v + J_w^T (I c_w + omega x I omega),
// and Appell's equations (5), P = dS/du' = M u' + b = Q,
//   Q = sum J_v^T F + J_w^T Gamma  (virtual power of the applied forces).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "appell/derivatives/dual.hpp"
#include "appell/derivatives/dual_solve.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/linalg/scratch.hpp"
#include "appell/scalar/products.hpp"

namespace appell {

template <class S>
struct body_state {
  S mass = S(0);
  mat3<S> inertia = zero_matrix<mat3<S>>();  ///< central inertia tensor, components on F
  vec3<S> velocity = zero_matrix<vec3<S>>();  ///< of the centre of mass, on F
  vec3<S> omega = zero_matrix<vec3<S>>();     ///< angular velocity of the body, on F
  vec3<S> frame_rate = zero_matrix<vec3<S>>();  ///< angular velocity of F (0: F is fixed)
  /// F is the body's own frame (frame_rate is omega itself): frame_rate x omega is then exactly 0,
  /// not an interval cross product of omega with itself (whose width is not 0).
  bool frame_is_body = false;
  vec3<S> force = zero_matrix<vec3<S>>();     ///< applied force through G, on F
  vec3<S> couple = zero_matrix<vec3<S>>();    ///< applied couple, on F
};

template <class Sys, class T>
concept mechanical_system = requires(const Sys& s, const vector_t<T>& q, const T& t,
                                     std::vector<body_state<T>>& out) {
  { s.speeds() } -> std::convertible_to<int>;
  { s.template qdot<T>(q, q, t) } -> std::convertible_to<vector_t<T>>;
  s.template bodies<T>(q, q, t, out);
};

template <class T>
vec3<T> cross(const vec3<T>& a, const vec3<T>& b) {
  return vec3<T>(difference_of_products(a(1), b(2), a(2), b(1)), difference_of_products(a(2), b(0), a(0), b(2)),
                 difference_of_products(a(0), b(1), a(1), b(0)));
}
/// frame_rate x omega of a body (exactly 0 when the frame is the body's own).
template <class T>
vec3<T> frame_cross_omega(const body_state<T>& s) {
  if (s.frame_is_body) return vec3<T>(T(0), T(0), T(0));
  return cross(s.frame_rate, s.omega);
}
template <class T>
T dot(const vec3<T>& a, const vec3<T>& b) {
  return sum_of_products(a(0), b(0), a(1), b(1), a(2), b(2));
}
template <class T>
vec3<T> mat_vec(const mat3<T>& A, const vec3<T>& x) {  // coefficient-based (no Eigen kernels on intervals)
  vec3<T> y;
  for (int i = 0; i < 3; ++i) y(i) = sum_of_products(A(i, 0), x(0), A(i, 1), x(1), A(i, 2), x(2));
  return y;
}

/// omega x (I omega); for an inertia tensor with structurally zero products of inertia (principal
/// axes), in the factored form ((I3 - I2) w2 w3, ...): the same number in exact arithmetic, one
/// rounding fewer per component, and no difference of two nearly equal products (whose interval
/// enclosure is 3 to 6 ulps wide where the factored one is 1 to 2).
template <class T>
vec3<T> gyroscopic(const mat3<T>& I, const vec3<T>& w) {
  bool diagonal = true;
  for (int i = 0; i < 3 && diagonal; ++i)
    for (int j = 0; j < 3 && diagonal; ++j)
      if (i != j && !structurally_zero(I(i, j))) diagonal = false;
  if (diagonal)
    return vec3<T>((I(2, 2) - I(1, 1)) * (w(1) * w(2)), (I(0, 0) - I(2, 2)) * (w(2) * w(0)),
                   (I(1, 1) - I(0, 0)) * (w(0) * w(1)));
  return cross(w, mat_vec(I, w));
}

/// One body's kinematics, differentiated: J columns and the velocity-product terms.
template <class T>
struct body_kinematics {
  body_state<T> state;
  Eigen::Matrix<T, 3, Eigen::Dynamic> Jv, Jw;  ///< dv_G/du, domega/du
  vec3<T> cv, cw;                              ///< a_G = Jv u' + cv, alpha = Jw u' + cw
};

namespace detail {
template <class T>
vector_t<dual<T>> seeded(const vector_t<T>& x, const vector_t<T>* direction) {
  vector_t<dual<T>> r(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) r(i) = dual<T>(x(i), direction ? (*direction)(i) : T(0));
  return r;
}
template <class T>
vec3<T> value(const vec3<dual<T>>& x) { return vec3<T>(x(0).v, x(1).v, x(2).v); }
template <class T>
vec3<T> derivative(const vec3<dual<T>>& x) { return vec3<T>(x(0).d, x(1).d, x(2).d); }
}  // namespace detail

/// A system that bounds its number of speeds at compile time
/// (`static constexpr int max_speeds`): its kinematics are differentiated in
/// one evaluation on multi_dual numbers instead of k + 1 evaluations on duals.
template <class Sys>
concept bounded_speeds = requires { typename std::integral_constant<int, Sys::max_speeds>; };

namespace detail {
/// The values of a body evaluated on (multi_)dual numbers.
template <class T, class D>
body_state<T> values(const body_state<D>& d) {
  body_state<T> s;
  s.frame_is_body = d.frame_is_body;
  s.mass = d.mass.v;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s.inertia(i, j) = d.inertia(i, j).v;
    s.velocity(i) = d.velocity(i).v;
    s.omega(i) = d.omega(i).v;
    s.frame_rate(i) = d.frame_rate(i).v;
    s.force(i) = d.force(i).v;
    s.couple(i) = d.couple(i).v;
  }
  return s;
}
template <class T, int N>
vec3<T> derivative(const vec3<multi_dual<T, N>>& x, int slot) {
  return vec3<T>(x(0).d[slot], x(1).d[slot], x(2).d[slot]);
}

/// Evaluations on multi_dual<T, N>, each covering N of the k + 1 directions:
/// direction c < k seeds u_c (a column of J), direction k seeds q' = W u + w
/// and t' = 1 (the velocity-product terms).  Each slot's arithmetic is that of
/// the corresponding single-dual pass (differentiate_kinematics_by_columns),
/// and the values are those of the plain evaluation: the results are the same
/// numbers, bit for bit (tests/generic_path.cpp).  N >= k + 1 takes one evaluation.
/// Into `out`, whose storage is reused (a J of the same size is not allocated again).
template <int N, class T, class Sys>
void differentiate_kinematics_in_slots_into(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                                            std::vector<body_kinematics<T>>& out, int cols = -1) {
  using D = multi_dual<T, N>;
  const int k = cols < 0 ? sys.speeds() : cols;  // the columns of J differentiated: speeds 0 .. k - 1
  struct site;  // this function's pools (linalg/scratch.hpp: an Eigen object keeps one size)
  const scratch<vector_t<T>, site> qd_held;
  if constexpr (requires { sys.template qdot_into<T>(q, u, t, *qd_held); })
    sys.template qdot_into<T>(q, u, t, *qd_held);
  else
    *qd_held = sys.template qdot<T>(q, u, t);
  const vector_t<T>& qd = *qd_held;
  const scratch<std::vector<body_state<D>>, site> d_held;
  const scratch<vector_t<D>, site> qs_held, us_held;
  std::vector<body_state<D>>& d = *d_held;
  vector_t<D>&qs = *qs_held, &us = *us_held;
  qs.resize(q.size()), us.resize(u.size());
  for (int first = 0; first <= k; first += N) {  // directions first .. first + N - 1
    const bool has_c = k - first < N;              // direction k falls in this evaluation
    const auto c_slot = static_cast<std::size_t>(k - first);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      qs(i) = D(q(i));
      if (has_c) qs(i).d[c_slot] = qd(i);
    }
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      us(i) = D(u(i));
      if (i >= first && i < first + N && i < k) us(i).d[static_cast<std::size_t>(i - first)] = T(1);
    }
    D ts(t);
    if (has_c) ts.d[c_slot] = T(1);
    d.clear();
    sys.template bodies<D>(qs, us, ts, d);
    if (first == 0) {
      out.resize(d.size());
      for (std::size_t i = 0; i < d.size(); ++i) {
        out[i].state = values<T>(d[i]);
        out[i].Jv.resize(3, k);
        out[i].Jw.resize(3, k);
      }
    }
    for (std::size_t i = 0; i < d.size(); ++i) {
      body_kinematics<T>& B = out[i];
      for (int c = first; c < std::min(k, first + N); ++c) {
        B.Jv.col(c) = derivative(d[i].velocity, c - first);
        B.Jw.col(c) = derivative(d[i].omega, c - first);
      }
      if (has_c) {
        B.cv = derivative(d[i].velocity, k - first) + cross(B.state.frame_rate, B.state.velocity);
        B.cw = derivative(d[i].omega, k - first) + frame_cross_omega(B.state);
      }
    }
  }
}
template <int N, class T, class Sys>
std::vector<body_kinematics<T>> differentiate_kinematics_in_slots(const Sys& sys, const vector_t<T>& q,
                                                                  const vector_t<T>& u, const T& t, int cols = -1) {
  std::vector<body_kinematics<T>> out;
  differentiate_kinematics_in_slots_into<N>(sys, q, u, t, out, cols);
  return out;
}
}  // namespace detail

/// The k + 1 directional derivatives by k + 1 evaluations on single duals (and
/// one plain evaluation for the values): the reference the slotted evaluations
/// are tested against.
template <Scalar T, class Sys>
std::vector<body_kinematics<T>> differentiate_kinematics_by_columns(const Sys& sys, const vector_t<T>& q,
                                                                    const vector_t<T>& u, const T& t) {
  const int k = sys.speeds();
  std::vector<body_state<T>> plain;
  sys.template bodies<T>(q, u, t, plain);
  std::vector<body_kinematics<T>> out(plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    out[i].state = plain[i];
    out[i].Jv.resize(3, k);
    out[i].Jw.resize(3, k);
  }
  std::vector<body_state<dual<T>>> d;
  const vector_t<dual<T>> q0 = detail::seeded<T>(q, nullptr);
  for (int c = 0; c < k; ++c) {  // column c of J: seed u_c
    vector_t<T> e = vector_t<T>::Zero(k);
    e(c) = T(1);
    d.clear();
    sys.template bodies<dual<T>>(q0, detail::seeded<T>(u, &e), dual<T>(t), d);
    for (std::size_t i = 0; i < d.size(); ++i) {
      out[i].Jv.col(c) = detail::derivative(d[i].velocity);
      out[i].Jw.col(c) = detail::derivative(d[i].omega);
    }
  }
  // Velocity-product terms: seed q' = W u + w and t' = 1, u fixed.
  const vector_t<T> qd = sys.template qdot<T>(q, u, t);
  d.clear();
  sys.template bodies<dual<T>>(detail::seeded<T>(q, &qd), detail::seeded<T>(u, nullptr), dual<T>(t, T(1)), d);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const body_state<T>& s = plain[i];
    out[i].cv = detail::derivative(d[i].velocity) + cross(s.frame_rate, s.velocity);
    out[i].cw = detail::derivative(d[i].omega) + frame_cross_omega(s);
  }
  return out;
}

/// Kinematics of every body at (q, u, t), with J and c obtained by forward
/// differentiation: one evaluation on multi_dual<T, max_speeds + 1> for a system
/// that declares max_speeds, otherwise evaluations 8 directions at a time.
template <Scalar T, class Sys>
void differentiate_kinematics_into(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                                   std::vector<body_kinematics<T>>& out) {
  if constexpr (bounded_speeds<Sys>) {
    if (sys.speeds() > Sys::max_speeds)
      throw std::logic_error("a system has more speeds than its max_speeds (" + std::to_string(sys.speeds()) + " > " +
                             std::to_string(Sys::max_speeds) + ")");
    detail::differentiate_kinematics_in_slots_into<Sys::max_speeds + 1>(sys, q, u, t, out);
  } else {
    detail::differentiate_kinematics_in_slots_into<8>(sys, q, u, t, out);
  }
}
template <Scalar T, class Sys>
std::vector<body_kinematics<T>> differentiate_kinematics(const Sys& sys, const vector_t<T>& q,
                                                         const vector_t<T>& u, const T& t) {
  std::vector<body_kinematics<T>> out;
  differentiate_kinematics_into(sys, q, u, t, out);
  return out;
}

/// Appell's equations M u' + b = Q at one state.
template <Scalar T>
struct appell_equations {
  matrix_t<T> M;  ///< d2S/du'2, symmetric positive definite
  vector_t<T> b;  ///< the S1 terms: S1 = b . u'
  vector_t<T> Q;  ///< generalized active forces

  /// P = dS/du' = M u' + b.
  vector_t<T> P(const vector_t<T>& udot) const { return detail::product(M, udot) + b; }
  /// The useful part of the acceleration energy, S2 + S1 = 1/2 u'.M u' + b.u'.
  T S2_plus_S1(const vector_t<T>& udot) const {
    const vector_t<T> Mu = detail::product(M, udot);
    T s = T(0);
    for (Eigen::Index i = 0; i < udot.size(); ++i) s += (Mu(i) / T(2) + b(i)) * udot(i);
    return s;
  }
  /// The accelerations u' = M^-1 (Q - b) (verified for interval types).
  vector_t<T> accelerations() const { return solve_spd(M, vector_t<T>(Q - b)); }
  /// The same into udot (solve_spd_into: no allocation for point types once the sizes are known).
  void accelerations_into(vector_t<T>& udot) const {
    struct site;
    const scratch<vector_t<T>, site> rhs;
    *rhs = Q - b;  // into its storage: no temporary
    solve_spd_into<site>(M, *rhs, udot);
  }
};

/// Assembles M, b, Q from the differentiated kinematics.  A speed that does
/// not move a body (its columns of J_v and J_w exactly 0) adds exactly 0 to
/// that body's terms: it is skipped (a link of a chain moves with the speeds
/// of the joints before it only, so a chain's M costs N^3 / 6 products, not N^3 / 2).
template <Scalar T>
void assemble_into(const std::vector<body_kinematics<T>>& bodies, int k, appell_equations<T>& e) {
  e.M.setZero(k, k);  // of the same size as before: no allocation
  e.b.setZero(k);
  e.Q.setZero(k);
  struct site;
  const scratch<std::vector<int>, site> active_held;  // borrowed (linalg/scratch.hpp)
  std::vector<int>& active = *active_held;
  active.reserve(static_cast<std::size_t>(k));
  for (const auto& B : bodies) {
    active.clear();
    for (int i = 0; i < k; ++i) {
      bool moves = false;
      for (int r = 0; r < 3 && !moves; ++r) moves = !structurally_zero(B.Jv(r, i)) || !structurally_zero(B.Jw(r, i));
      if (moves) active.push_back(i);
    }
    if (active.empty()) continue;
    const body_state<T>& s = B.state;
    const vec3<T> rot_bias = mat_vec(s.inertia, B.cw) + gyroscopic(s.inertia, s.omega);  // I c_w + w x I w
    for (std::size_t ii = 0; ii < active.size(); ++ii) {
      const int i = active[ii];
      const vec3<T> jvi = B.Jv.col(i), jwi = B.Jw.col(i);
      const vec3<T> Ijwi = mat_vec(s.inertia, jwi);
      for (std::size_t jj = ii; jj < active.size(); ++jj) {
        const int j = active[jj];
        const vec3<T> jvj = B.Jv.col(j), jwj = B.Jw.col(j);
        const T mij = s.mass * dot(jvi, jvj) + dot(Ijwi, jwj);
        e.M(i, j) += mij;
        if (j != i) e.M(j, i) += mij;
      }
      e.b(i) += s.mass * dot(jvi, B.cv) + dot(jwi, rot_bias);
      e.Q(i) += dot(jvi, s.force) + dot(jwi, s.couple);
    }
  }
}
template <Scalar T>
appell_equations<T> assemble(const std::vector<body_kinematics<T>>& bodies, int k) {
  appell_equations<T> e;
  assemble_into(bodies, k, e);
  return e;
}

/// Appell's equations of a system at (q, u, t).
template <Scalar T, class Sys>
void gibbs_appell_into(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t, appell_equations<T>& e) {
  struct site;
  const scratch<std::vector<body_kinematics<T>>, site> kinematics;  // borrowed (linalg/scratch.hpp)
  differentiate_kinematics_into(sys, q, u, t, *kinematics);
  assemble_into(*kinematics, sys.speeds(), e);
}
/// The same returned (gibbs_appell_into: into matrices that are reused).
template <Scalar T, class Sys>
appell_equations<T> gibbs_appell(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t) {
  appell_equations<T> e;
  gibbs_appell_into(sys, q, u, t, e);
  return e;
}

/// The first `cols` rows and columns of Appell's equations at (q, u, t): M's leading block, and
/// b and Q's leading rows, the same numbers bit for bit as gibbs_appell's (each derivative slot
/// repeats the same operations), with only speeds 0 .. cols - 1 varied, in one evaluation on
/// multi_dual<T, Slots> when cols < Slots.  What the motion of a constrained system needs when
/// its reactions are not asked for (reactions/cotton.hpp: cotton_free_accelerations): the
/// constrained speeds' columns cost derivative slots in every quantity of the kinematics.
template <int Slots, Scalar T, class Sys>
appell_equations<T> gibbs_appell_leading(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t,
                                         int cols) {
  if (cols < 0 || cols > sys.speeds()) throw std::invalid_argument("gibbs_appell_leading: cols out of range");
  struct site;
  const scratch<std::vector<body_kinematics<T>>, site> kinematics;
  detail::differentiate_kinematics_in_slots_into<Slots>(sys, q, u, t, *kinematics, cols);
  return assemble(*kinematics, cols);
}

}  // namespace appell
