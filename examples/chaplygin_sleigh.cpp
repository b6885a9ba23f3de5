// A nonholonomic system of the user's own, outside the paper: the Chaplygin
// sleigh.  A rigid body slides on a horizontal plane on a knife edge at P that
// cannot move sideways; G lies at distance d ahead of P on the body axis.
//
// Written on the library's API:
//   * the free system: the body in the plane, q = (x_P, y_P, theta), speeds
//     u = (x_P', y_P', theta'), G = P + d (cos, sin), v_G = v_P + theta' k x (G - P);
//   * the knife edge, a nonholonomic constraint: -sin(theta) x_P' + cos(theta) y_P' = 0.
// Cotton's method (library-built adapted speeds) and Lagrange's multipliers
// give the accelerations and the knife edge's lateral force.  The textbook
// answer, with v the forward speed of P and w = theta':
//   v' = d w^2,   (I_G + m d^2) w' = -m d v w,   lateral force = m (d w' + v w).
// The program prints the three in double, interval and mpfi and fails unless
// they agree.
#include <cstdlib>
#include <iostream>

#include "appell/reactions/lagrange.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"

using namespace appell;

template <Scalar T>
struct sleigh {
  T mass, inertia_G, d;
  int speeds() const { return 3; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    using std::sin, std::cos;
    const S c = cos(q(2)), s = sin(q(2));
    body_state<S> b;
    b.mass = S(mass);
    b.velocity = vec3<S>(u(0) - S(d) * s * u(2), u(1) + S(d) * c * u(2), S(0));
    b.omega = vec3<S>(S(0), S(0), u(2));
    b.inertia(2, 2) = S(inertia_G);  // only rotation about the vertical occurs
    out.push_back(b);
  }
};

struct knife_edge {  // -sin(theta) x_P' + cos(theta) y_P' = 0
  int count() const { return 1; }
  template <class S>
  void eval(const vector_t<S>& q, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    using std::sin, std::cos;
    A(0, 0) = -sin(q(2));
    A(0, 1) = cos(q(2));
    A(0, 2) = S(0);
    a(0) = S(0);
  }
};

template <Scalar T>
bool run() {
  const T m = from_decimal<T>("3"), IG = from_decimal<T>("0.4"), d = from_decimal<T>("0.25");
  const T theta = from_decimal<T>("0.6"), v = from_decimal<T>("1.5"), w = from_decimal<T>("-2");
  using std::sin, std::cos;
  vector_t<T> q(3), u(3);
  q << from_decimal<T>("1"), from_decimal<T>("2"), theta;
  u << v * cos(theta), v * sin(theta), w;  // on the constraint
  const sleigh<T> body{m, IG, d};
  const auto cotton = cotton_reactions(body, knife_edge{}, q, u, T(0));
  const auto lagrange = lagrange_multipliers(body, knife_edge{}, q, u, T(0));
  // textbook
  const T w_dot = -m * d * v * w / (IG + m * d * d), v_dot = d * w * w;
  const T lateral = m * (d * w_dot + v * w);
  // v = x_P' cos + y_P' sin, so v' = x'' cos + y'' sin + w (-x' sin + y' cos), and the bracket is the
  // knife edge's lateral speed, 0.
  const T v_dot_cotton = cotton.accelerations(0) * cos(theta) + cotton.accelerations(1) * sin(theta);
  std::cout << scalar_traits<T>::name << ":\n  theta''  Cotton " << to_string(cotton.accelerations(2)) << "  Lagrange "
            << to_string(lagrange.accelerations(2)) << "  textbook " << to_string(w_dot) << "\n  v'       Cotton "
            << to_string(v_dot_cotton) << "  textbook " << to_string(v_dot) << "\n  lateral  Cotton "
            << to_string(cotton.reactions(0)) << "  Lagrange " << to_string(lagrange.reactions(0)) << "  textbook "
            << to_string(lateral) << "\n";
  auto agree = [](const T& x, const T& y) {  // the library's admissibility predicate (scalar/policy.hpp)
    using std::abs;
    return consistent_with_zero(T(x - y), T(abs(y) + T(1)));
  };

  return agree(cotton.accelerations(2), w_dot) && agree(lagrange.accelerations(2), w_dot) &&
         agree(v_dot_cotton, v_dot) && agree(cotton.reactions(0), lateral) && agree(lagrange.reactions(0), lateral);
}

int main() {
  mp_precision_scope scope(128);
  const bool ok = run<double>() && run<interval>() && run<mpfi>();
  std::cout << (ok ? "Chaplygin sleigh: Cotton, Lagrange and the textbook agree\n" : "DISAGREEMENT\n");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
