// appell/system/tree_balls.hpp -- the tree recursions of tree.hpp for the interval scalars
// (interval, mpfi) in midpoint-radius form with norm-wise radii: enclosures whose width grows
// linearly with the tree's depth instead of geometrically.
//
// Why.  An interval vector turned by a rotation comes back wider: the box [v] turned is enclosed
// by |X| rad(v), whose rows sum up to sqrt(3) (the wrapping effect).  The recursions turn every
// link's velocity, acceleration, force and composite inertia once per joint on the way up or down
// the tree, so the widths of tree.hpp's interval recursion grow by a constant factor per link: on
// the generated chain of bench/urdf.cpp about 2.4 per link, 1e-10 wide at 8 links, 0.4 at 32, and
// at 48 the mass matrix is too wide to be proved nonsingular.  The exact rotation, however, is
// orthogonal and leaves the Euclidean length of an error unchanged.  So here every vector is a
// ball {c + e : |e|_2 <= r} (c on the bound type's grid, r a rigorous upper bound), every 3 x 3
// matrix {C + E : |E|_2 <= r}, every rotation X the set of orthogonal matrices within r of its
// centre, and
//   X (c + e) = Xc c + (X - Xc) c + X e,  |X e| = |e|:   r' = r + rX |c| + (rounding of Xc c)
//   X (C + E) X^T:                                        r' = r + rX |C|_F (2 + rX) + (rounding)
//   (a + e) x (b + d):  r' = ra |b| + |a| rb + ra rb + (rounding), and the like for + . m v I v.
// Each operation on the centres is done in the interval type on thin operands and recentred: the
// interval's radius is that operation's rounding, added to r (so the rounding errors are proved
// by the same interval arithmetic as everywhere else, and never compounded by wrapping).  Radii
// are summed and multiplied in the interval type too, upper bounds taken; the Euclidean norms of
// centres are square roots rounded up.  The results (M, b, Q; the subtree wrenches) leave as
// intervals [c - r, c + r], rounded outward.
//
// Where.  tree.hpp's componentwise intervals are tighter on shallow trees (a ball's radius is the
// same in every direction, so a small component inherits the error of a large one); the balls
// take over from prefer_balls(c)'s depth on (tests/tree_recursions.cpp measures both paths).
// Everything else (constraints, the motion's slopes and jets) is unchanged.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <vector>

#include "appell/system/tapes.hpp"

namespace appell {

namespace detail {
/// The body tape's node values at (q, u, t) into `values`, and gravity on the fixed axes: the
/// first step of both recursions' forward passes (tree.hpp's and the balls' below).
template <Scalar T, class S>
vec3<S> tree_tape_into(const compiled_system<T>& c, const vector_t<S>& q, const vector_t<S>& u, const S& t,
                       std::vector<S>& values) {
  struct site;
  const scratch<std::vector<S>, site> x_held;
  c.variables_into(q, u, t, *x_held);
  c.evaluate_into(c.body_tape, *x_held, values);
  vec3<S> g;
  for (int i = 0; i < 3; ++i) g(i) = c.gravity[static_cast<std::size_t>(i)].at(values.data());
  return g;
}
}  // namespace detail

namespace detail::balls {

template <class I>
using P = bound_t<I>;

template <class I>
I thin(const P<I>& p) {
  return scalar_traits<I>::from_bounds(p, p);
}
/// an upper bound of x's values
template <class I>
P<I> up(const I& x) {
  return upper(x);
}
template <class I>
P<I> add(const P<I>& a, const P<I>& b) {
  return up(thin<I>(a) + thin<I>(b));
}
template <class I>
P<I> mul(const P<I>& a, const P<I>& b) {
  return up(thin<I>(a) * thin<I>(b));
}
/// sqrt(x) rounded up; the interval scalar's inside its upward-rounding scope (set by the callers
/// below), the others by their interval square root.
template <class I>
P<I> sqrt_up(const P<I>& x) {
  if constexpr (std::is_same_v<I, interval>) return interval_arith::opaque(std::sqrt(interval_arith::opaque(x)));
  else return up(sqrt(thin<I>(x)));
}
/// the larger of two radii; NaN if either is NaN
template <class I>
P<I> larger(const P<I>& a, const P<I>& b) {
  return (b > a || b != b) ? b : a;
}

template <class I>
struct sball {
  P<I> c, r;
};
template <class I>
struct vball {
  vec3<P<I>> c;
  P<I> r;
};
template <class I>
struct mball {  ///< any 3 x 3 matrix within r of c in the spectral norm
  mat3<P<I>> c;
  P<I> r;
};
template <class I>
struct turn {  ///< an orthogonal matrix within r of c in the spectral norm
  mat3<P<I>> c;
  P<I> r;
};

/// y's midpoint into c, and an upper bound of |y - c| for every value of y
template <class I>
P<I> recentre(const I& y, P<I>& c) {
  c = mid(y);
  const I t = thin<I>(c);
  return larger<I>(up(y - t), up(t - y));
}
template <class I>
P<I> norm(const vec3<P<I>>& c) {
  const I x = thin<I>(c(0)), y = thin<I>(c(1)), z = thin<I>(c(2));
  return sqrt_up<I>(up(x * x + y * y + z * z));
}
/// the Frobenius norm (a bound of the spectral one)
template <class I>
P<I> norm(const mat3<P<I>>& c) {
  I s = I(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const I x = thin<I>(c(i, j));
      s += x * x;
    }
  return sqrt_up<I>(up(s));
}
/// the ball of an interval vector (the Euclidean norm of its componentwise radii)
template <class I>
vball<I> of(const vec3<I>& y) {
  vball<I> b;
  I s = I(0);
  for (int i = 0; i < 3; ++i) {
    const I r = thin<I>(recentre<I>(y(i), b.c(i)));
    s += r * r;
  }
  b.r = sqrt_up<I>(up(s));
  return b;
}
template <class I>
mball<I> of(const mat3<I>& y) {
  mball<I> b;
  I s = I(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const I r = thin<I>(recentre<I>(y(i, j), b.c(i, j)));
      s += r * r;
    }
  b.r = sqrt_up<I>(up(s));
  return b;
}
template <class I>
sball<I> of(const I& y) {
  sball<I> b;
  b.r = recentre<I>(y, b.c);
  return b;
}
/// an interval matrix known to hold an orthogonal one
template <class I>
turn<I> rotation_of(const mat3<I>& y) {
  const mball<I> b = of<I>(y);
  return turn<I>{b.c, b.r};
}
template <class I>
vec3<I> thin_vector(const vec3<P<I>>& c) {
  return vec3<I>(thin<I>(c(0)), thin<I>(c(1)), thin<I>(c(2)));
}
template <class I>
vball<I> zero() {
  return vball<I>{vec3<P<I>>(P<I>(0), P<I>(0), P<I>(0)), P<I>(0)};
}

template <class I>
vball<I> operator+(const vball<I>& a, const vball<I>& b) {
  vball<I> s = of<I>(vec3<I>(thin_vector<I>(a.c) + thin_vector<I>(b.c)));
  s.r = add<I>(s.r, add<I>(a.r, b.r));
  return s;
}
template <class I>
vball<I> operator-(const vball<I>& a, const vball<I>& b) {
  vball<I> s = of<I>(vec3<I>(thin_vector<I>(a.c) - thin_vector<I>(b.c)));
  s.r = add<I>(s.r, add<I>(a.r, b.r));
  return s;
}
template <class I>
vball<I>& operator+=(vball<I>& a, const vball<I>& b) {
  return a = a + b;
}
template <class I>
vball<I>& operator-=(vball<I>& a, const vball<I>& b) {
  return a = a - b;
}
/// the radius of a product of two balls of centres' norms na, nb and radii ra, rb
template <class I>
P<I> product_radius(const P<I>& na, const P<I>& ra, const P<I>& nb, const P<I>& rb) {
  const I ra_ = thin<I>(ra), rb_ = thin<I>(rb);
  return up(ra_ * thin<I>(nb) + thin<I>(na) * rb_ + ra_ * rb_);
}
template <class I>
mball<I> operator+(const mball<I>& a, const mball<I>& b) {
  mat3<I> y;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) y(i, j) = thin<I>(a.c(i, j)) + thin<I>(b.c(i, j));
  mball<I> s = of<I>(y);
  s.r = add<I>(s.r, add<I>(a.r, b.r));
  return s;
}
template <class I>
vball<I> operator*(const sball<I>& x, const vball<I>& v) {
  const I xc = thin<I>(x.c);
  const vec3<I> vc = thin_vector<I>(v.c);
  vball<I> s = of<I>(vec3<I>(xc * vc(0), xc * vc(1), xc * vc(2)));
  s.r = add<I>(s.r, product_radius<I>(up(abs(xc)), x.r, norm<I>(v.c), v.r));
  return s;
}
template <class I>
vball<I> cross(const vball<I>& a, const vball<I>& b) {
  vball<I> s = of<I>(vec3<I>(appell::cross(thin_vector<I>(a.c), thin_vector<I>(b.c))));
  s.r = add<I>(s.r, product_radius<I>(norm<I>(a.c), a.r, norm<I>(b.c), b.r));
  return s;
}
template <class I>
sball<I> dot(const vball<I>& a, const vball<I>& b) {
  sball<I> s = of<I>(I(appell::dot(thin_vector<I>(a.c), thin_vector<I>(b.c))));
  s.r = add<I>(s.r, product_radius<I>(norm<I>(a.c), a.r, norm<I>(b.c), b.r));
  return s;
}
template <class I>
sball<I> operator+(const sball<I>& a, const sball<I>& b) {
  sball<I> s = of<I>(I(thin<I>(a.c) + thin<I>(b.c)));
  s.r = add<I>(s.r, add<I>(a.r, b.r));
  return s;
}
/// W v for any matrix ball W
template <class I>
vball<I> operator*(const mball<I>& W, const vball<I>& v) {
  const vec3<I> vc = thin_vector<I>(v.c);
  vec3<I> y;
  for (int i = 0; i < 3; ++i)
    y(i) = thin<I>(W.c(i, 0)) * vc(0) + thin<I>(W.c(i, 1)) * vc(1) + thin<I>(W.c(i, 2)) * vc(2);
  vball<I> s = of<I>(y);
  s.r = add<I>(s.r, product_radius<I>(norm<I>(W.c), W.r, norm<I>(v.c), v.r));
  return s;
}
/// X v (transpose: X^T v) for a rotation X: v's radius carried unchanged
template <class I>
vball<I> rotate(const turn<I>& X, const vball<I>& v, bool transpose) {
  const vec3<I> vc = thin_vector<I>(v.c);
  vec3<I> y;
  for (int i = 0; i < 3; ++i) {
    const auto x = [&](int k) { return thin<I>(transpose ? X.c(k, i) : X.c(i, k)); };
    y(i) = x(0) * vc(0) + x(1) * vc(1) + x(2) * vc(2);
  }
  vball<I> s = of<I>(y);
  s.r = add<I>(s.r, add<I>(v.r, mul<I>(X.r, norm<I>(v.c))));
  return s;
}
/// X W X^T for a rotation X
template <class I>
mball<I> rotate(const turn<I>& X, const mball<I>& W) {
  mat3<I> A, B;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      A(i, j) = thin<I>(X.c(i, 0)) * thin<I>(W.c(0, j)) + thin<I>(X.c(i, 1)) * thin<I>(W.c(1, j)) +
                thin<I>(X.c(i, 2)) * thin<I>(W.c(2, j));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      B(i, j) = A(i, 0) * thin<I>(X.c(j, 0)) + A(i, 1) * thin<I>(X.c(j, 1)) + A(i, 2) * thin<I>(X.c(j, 2));
  mball<I> s = of<I>(B);
  const I rx = thin<I>(X.r);
  s.r = add<I>(s.r, up(thin<I>(W.r) + rx * thin<I>(norm<I>(W.c)) * (I(2) + rx)));
  return s;
}
/// W + m (|r|^2 1 - r r^T) + (2 r.h 1 - r h^T - h r^T): a composite inertia moved by r (h the
/// subtree's first moment, on the same axes), as tree.hpp's shift.  The perturbation bounds, from
/// the symmetric matrices' quadratic forms at unit x, x^T G(r) x = |r x x|^2 for
/// G(r) = |r|^2 1 - r r^T and x^T H x = 2 (r x x).(h x x) for H the last term:
/// |G(r + e) - G(r)| <= 2 |r| |e| + |e|^2, |G(r)| = |r|^2, and |H(r + e, h + d) - H(r, h)| <= 2 D
/// with D = |e| |h| + |r| |d| + |e| |d|.
template <class I>
mball<I> shifted(const mball<I>& W, const sball<I>& m, const vball<I>& r, const vball<I>& h) {
  const vec3<I> rc = thin_vector<I>(r.c), hc = thin_vector<I>(h.c);
  const I mc = thin<I>(m.c);
  mat3<I> y;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      I x = thin<I>(W.c(i, j));
      if (i == j) {
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        const I rhi = rc(a) * hc(a) + rc(b) * hc(b);
        x += mc * (rc(a) * rc(a) + rc(b) * rc(b)) + (rhi + rhi);
      } else {
        x -= mc * (rc(i) * rc(j)) + (rc(i) * hc(j) + hc(i) * rc(j));
      }
      y(i, j) = x;
    }
  mball<I> s = of<I>(y);
  const I nr = thin<I>(norm<I>(r.c)), nh = thin<I>(norm<I>(h.c)), er = thin<I>(r.r), eh = thin<I>(h.r);
  const I reach = nr + er;
  const I G = thin<I>(m.r) * reach * reach + abs(mc) * (I(2) * nr * er + er * er);
  const I D = er * nh + nr * eh + er * eh;
  s.r = add<I>(s.r, up(thin<I>(W.r) + G + I(2) * D));
  return s;
}
template <class I>
I interval_of(const sball<I>& b) {
  const I c = thin<I>(b.c), r = thin<I>(b.r);
  if (!(b.r >= P<I>(0)) || !is_finite(c) || !is_finite(r))
    throw certification_error("tree recursion in balls: a value is not finite");
  return scalar_traits<I>::from_bounds(lower(c - r), upper(c + r));
}
template <class I>
vec3<I> interval_of(const vball<I>& b) {
  vec3<I> y;
  for (int i = 0; i < 3; ++i) y(i) = interval_of<I>(sball<I>{b.c(i), b.r});
  return y;
}

/// One link in balls: its rotation and motion (link_state's), the passes' quantities (tree_link's).
template <class I>
struct ball_link {
  turn<I> X;                       ///< L's axes to the parent's, R0 Rot(axis, q)
  vball<I> offset;                 ///< L's origin from P's, on P's axes
  vball<I> omega, gravity;         ///< on L's axes
  vball<I> force, couple;          ///< by the actuators, on L's axes
  vball<I> axis, com;              ///< constants
  mball<I> inertia;                ///< about G, on L's axes (Rin I Rin^T)
  sball<I> m;
  vball<I> alpha, accel, f, n, fa, na;
  vball<I> h;                      ///< composite
  mball<I> Ic;                     ///< composite, about the origin
};

/// The joint's rotation R0 Rot(axis, q) as an interval matrix (one product: no wrapping), then
/// its ball.
template <class I>
turn<I> joint_rotation(const typename compiled_system<I>::link& L, const I& c, const I& s) {
  using K = system_joint_definition::kind;
  mat3<I> Rot = mat3<I>::Identity();
  if (L.type == K::revolute) {
    if (L.along >= 0) {
      const int i = (L.along + 1) % 3, j = (L.along + 2) % 3;
      const I sn = upper(L.axis(L.along)) < P<I>(0) ? I(-s) : s;
      Rot(i, i) = c, Rot(i, j) = -sn, Rot(j, i) = sn, Rot(j, j) = c;
    } else {  // c 1 + s [a]x + (1 - c) a a^T
      const vec3<I>& a = L.axis;
      const I vers = I(1) - c;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Rot(i, j) = a(i) * a(j) * vers + (i == j ? c : I(0));
      Rot(0, 1) -= a(2) * s, Rot(1, 0) += a(2) * s;
      Rot(0, 2) += a(1) * s, Rot(2, 0) -= a(1) * s;
      Rot(1, 2) -= a(0) * s, Rot(2, 1) += a(0) * s;
    }
  }
  if (L.R0_identity) return rotation_of<I>(Rot);
  mat3<I> X;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) X(i, j) = L.R0(i, 0) * Rot(0, j) + L.R0(i, 1) * Rot(1, j) + L.R0(i, 2) * Rot(2, j);
  return rotation_of<I>(X);
}

/// The body tape at (q, u, t), the links' motion (link_states_into's), then the forward pass with
/// q'' = udot (or, null, 0): each link's inertia and applied forces at its origin, not yet summed.
template <class I>
void forward(const compiled_system<I>& c, const vector_t<I>& q, const vector_t<I>& u, const I& t,
             const vector_t<I>* udot, std::vector<I>& values, std::vector<ball_link<I>>& out) {
  using K = system_joint_definition::kind;
  const vball<I> gravity = of<I>(tree_tape_into<I, I>(c, q, u, t, values));
  const I* v = values.data();
  const std::size_t n = c.links.size();
  out.resize(n);
  auto parent = [&](const typename compiled_system<I>::link& L) -> ball_link<I>* {
    return L.parent >= 0 ? &out[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)])] : nullptr;
  };
  for (std::size_t k = 0; k < n; ++k) {  // the motion: link_states_into's
    const auto& L = c.links[k];
    ball_link<I>& o = out[k];
    const ball_link<I>* p = parent(L);
    const I qk = L.coordinate >= 0 ? q(L.coordinate) : I(0), qdk = L.coordinate >= 0 ? u(L.coordinate) : I(0);
    using std::cos, std::sin;
    o.X = L.type == K::revolute ? joint_rotation<I>(L, I(cos(qk)), I(sin(qk))) : joint_rotation<I>(L, I(1), I(0));
    vec3<I> offset = L.origin;
    if (L.type == K::prismatic) offset += compiled_system<I>::times(L.R0, compiled_system<I>::scaled(L.axis, qk));
    o.offset = of<I>(offset);
    o.axis = of<I>(L.axis);
    o.com = of<I>(L.com);
    o.omega = p ? rotate(o.X, p->omega, true) : zero<I>();
    o.gravity = rotate(o.X, p ? p->gravity : gravity, true);
    if (L.type == K::revolute) o.omega += of<I>(compiled_system<I>::scaled(L.axis, qdk));
    o.force = o.couple = zero<I>();
  }
  for (std::size_t k = 0; k < n; ++k) {  // the actuators, as link_states_into
    const auto& L = c.links[k];
    if (!L.actuated()) continue;
    ball_link<I>& o = out[k];
    ball_link<I>* p = parent(L);
    const vball<I> along = of<I>(compiled_system<I>::scaled(L.axis, L.effort_at(v)));
    const vball<I> back = p ? rotate(o.X, along, false) : zero<I>();
    if (L.type == K::revolute) {
      o.couple += along;
      if (p) p->couple -= back;
    } else if (L.type == K::prismatic) {
      o.force += along;
      if (p) {
        p->force -= back;
        const vball<I> arm = (o.offset + rotate(o.X, o.com, false)) - p->com;
        p->couple -= cross(arm, back);
      }
    }
  }
  for (std::size_t k = 0; k < n; ++k) {  // accelerations and the bodies' forces
    const auto& L = c.links[k];
    ball_link<I>& o = out[k];
    const ball_link<I>* p = parent(L);
    if (p) {
      const vball<I>& r = o.offset;
      o.alpha = rotate(o.X, p->alpha, true);
      o.accel = rotate(o.X, p->accel + cross(p->alpha, r) + cross(p->omega, cross(p->omega, r)), true);
    } else {
      o.alpha = o.accel = zero<I>();
    }
    if (L.type != K::fixed) {
      const vball<I> rate = of<I>(compiled_system<I>::scaled(L.axis, u(L.coordinate)));
      vball<I> wp = o.omega;  // as tree_forward: the parent's omega for an oblique axis
      if (L.type == K::revolute && L.along < 0) wp = p ? rotate(o.X, p->omega, true) : zero<I>();
      const vball<I> spin = cross(wp, rate);
      if (L.type == K::revolute) o.alpha += spin;
      else o.accel += spin + spin;
      if (udot) {
        const vball<I> along = of<I>(compiled_system<I>::scaled(L.axis, (*udot)(L.coordinate)));
        if (L.type == K::revolute) o.alpha += along;
        else o.accel += along;
      }
    }
    const auto& b = c.bodies[static_cast<std::size_t>(L.body)];
    const I m = b.mass.at(v);
    o.m = of<I>(m);
    mat3<I> W = b.has_inertia ? b.inertia_on_body_axes(v) : mat3<I>(zero_matrix<mat3<I>>());
    if (b.has_inertia && !L.Rin_identity) {  // Rin I Rin^T, in intervals (constants: no wrapping)
      mat3<I> A, B;
      for (int j = 0; j < 3; ++j) A.col(j) = compiled_system<I>::times(L.Rin, vec3<I>(W.col(j)));
      for (int i = 0; i < 3; ++i) B.row(i) = compiled_system<I>::times(L.Rin, vec3<I>(A.row(i).transpose())).transpose();
      W = B;
    }
    o.inertia = of<I>(W);
    const vball<I> aG = o.accel + cross(o.alpha, o.com) + cross(o.omega, cross(o.omega, o.com));
    o.f = o.m * aG;
    const vball<I> nG = o.inertia * o.alpha + cross(o.omega, o.inertia * o.omega);
    o.n = nG + cross(o.com, o.f);
    o.fa = o.m * o.gravity + o.force;
    o.na = o.couple + cross(o.com, o.fa);
  }
}

/// Children first: each link's sums over its subtree, moved to its origin.
template <class I>
void backward(const compiled_system<I>& c, std::vector<ball_link<I>>& links, bool applied) {
  for (std::size_t k = links.size(); k-- > 0;) {
    const auto& L = c.links[k];
    if (L.parent < 0) continue;
    ball_link<I>& o = links[k];
    ball_link<I>& p = links[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)])];
    const vball<I> f = rotate(o.X, o.f, false);
    p.f += f;
    p.n += rotate(o.X, o.n, false) + cross(o.offset, f);
    if (!applied) continue;
    const vball<I> fa = rotate(o.X, o.fa, false);
    p.fa += fa;
    p.na += rotate(o.X, o.na, false) + cross(o.offset, fa);
  }
}

template <class I>
sball<I> joint_row(const typename compiled_system<I>::link& L, const ball_link<I>& o, const vball<I>& f,
                   const vball<I>& n) {
  return dot(o.axis, L.type == system_joint_definition::kind::revolute ? n : f);
}
}  // namespace detail::balls

/// The depth of the tree (links on the longest path from a root), from which the balls'
/// norm-wise radii enclose tighter than componentwise intervals (tests/tree_recursions.cpp).
inline constexpr int tree_balls_depth = 10;
template <Scalar T>
int tree_depth(const compiled_system<T>& c) {
  int deepest = 0;
  for (const auto& L : c.links) {  // up to the root from each link: O(N d), and nothing on the heap
    int depth = 1;
    for (int b = L.parent; b >= 0; b = c.links[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(b)])].parent)
      ++depth;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}
template <Scalar T>
bool prefer_balls(const compiled_system<T>& c) {
  return tree_depth(c) >= tree_balls_depth;
}

/// tree_equations_into in balls (the interval scalars).
template <Scalar I>
  requires(scalar_traits<I>::is_interval)
void tree_equations_in_balls(const compiled_system<I>& c, const vector_t<I>& q, const vector_t<I>& u, const I& t,
                             appell_equations<I>& e) {
  using K = system_joint_definition::kind;
  using namespace detail::balls;
  std::optional<upward_rounding> mode;  // sqrt_up's rounding, for the interval scalar
  if constexpr (std::is_same_v<I, interval>) mode.emplace();
  struct site;
  const scratch<std::vector<I>, site> values_held;
  const scratch<std::vector<ball_link<I>>, site> links_held;
  std::vector<ball_link<I>>& links = *links_held;
  forward<I>(c, q, u, t, nullptr, *values_held, links);
  backward<I>(c, links, true);
  const int n = c.def->vars.speeds;
  e.M.setZero(n, n);
  e.b.setZero(n);
  e.Q.setZero(n);
  const std::size_t N = c.links.size();
  for (std::size_t k = 0; k < N; ++k) {
    const auto& L = c.links[k];
    if (L.type == K::fixed) continue;
    e.b(L.coordinate) = interval_of<I>(joint_row<I>(L, links[k], links[k].f, links[k].n));
    e.Q(L.coordinate) = interval_of<I>(joint_row<I>(L, links[k], links[k].fa, links[k].na));
  }
  // Composite rigid bodies: each link's own (m, h = m c, I about O), then the subtrees' sums.
  for (std::size_t k = 0; k < N; ++k) {
    ball_link<I>& o = links[k];
    o.h = o.m * o.com;
    o.Ic = shifted<I>(o.inertia, o.m, o.com, zero<I>());
  }
  for (std::size_t k = N; k-- > 0;) {
    const auto& L = c.links[k];
    if (L.parent < 0) continue;
    ball_link<I>& o = links[k];
    ball_link<I>& p = links[static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(L.parent)])];
    const vball<I> h = rotate(o.X, o.h, false);
    p.Ic = shifted<I>(rotate(o.X, o.Ic) + p.Ic, o.m, o.offset, h);
    p.h += h + o.m * o.offset;
    p.m = p.m + o.m;
  }
  for (std::size_t k = 0; k < N; ++k) {
    const auto& L = c.links[k];
    if (L.type == K::fixed) continue;
    const ball_link<I>& o = links[k];
    vball<I> f, nm;
    if (L.type == K::revolute) {
      f = cross(o.axis, o.h);
      nm = o.Ic * o.axis;
    } else {
      f = o.m * o.axis;
      nm = cross(o.h, o.axis);
    }
    const int i = L.coordinate;
    e.M(i, i) = interval_of<I>(joint_row<I>(L, o, f, nm));
    std::size_t j = k;
    while (c.links[j].parent >= 0) {
      const ball_link<I>& oj = links[j];
      f = rotate(oj.X, f, false);
      nm = rotate(oj.X, nm, false) + cross(oj.offset, f);
      j = static_cast<std::size_t>(c.link_of[static_cast<std::size_t>(c.links[j].parent)]);
      const auto& Lp = c.links[j];
      if (Lp.type == K::fixed) continue;
      const I mij = interval_of<I>(joint_row<I>(Lp, links[j], f, nm));
      e.M(Lp.coordinate, i) = mij;
      e.M(i, Lp.coordinate) = mij;
    }
  }
}

/// tree_subtree_wrenches_into in balls (the interval scalars).
template <Scalar I>
  requires(scalar_traits<I>::is_interval)
void tree_subtree_wrenches_in_balls(const compiled_system<I>& c, const vector_t<I>& q, const vector_t<I>& u,
                                    const I& t, const vector_t<I>& udot, std::vector<vec3<I>>& F,
                                    std::vector<vec3<I>>& M, std::vector<I>& values) {
  using namespace detail::balls;
  std::optional<upward_rounding> mode;
  if constexpr (std::is_same_v<I, interval>) mode.emplace();
  struct site;
  const scratch<std::vector<ball_link<I>>, site> links_held;
  std::vector<ball_link<I>>& links = *links_held;
  forward<I>(c, q, u, t, &udot, values, links);
  for (auto& o : links) {
    o.f -= o.fa;
    o.n -= o.na;
  }
  backward<I>(c, links, false);
  F.resize(links.size());
  M.resize(links.size());
  for (std::size_t k = 0; k < links.size(); ++k) F[k] = interval_of<I>(links[k].f), M[k] = interval_of<I>(links[k].n);
}

}  // namespace appell
