// A system of the user's own, outside the paper: a bead of mass m on a
// straight frictionless wire that a motor turns about a vertical axis at the
// angle phi(t) = w t + a t^2 / 2 (accelerating).  What couple must the motor
// exert on the bead through the wire?
//
// Written once, as templated C++, on the library's API:
//   * the free system: the bead anywhere in the horizontal plane, polar
//     coordinates q = (r, phi), speeds u = (r', phi');
//   * the added frictionless constraint, rheonomic: phi' = w + a t, i.e.
//     A u = a(t) with A = [0, 1], a(t) = w + a t.
// Cotton's method (the library builds the adapted speeds) and Lagrange's
// multipliers give the motor's generalized force H on phi; the textbook answer
// is r'' = r phi'^2 and H = m (r^2 phi'' + 2 r r' phi') (the rate of change of
// the bead's angular momentum about the axis).  The program prints all three
// in double and in interval arithmetic and fails unless they agree.
#include <cstdlib>
#include <iostream>

#include "appell/reactions/lagrange.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"

using namespace appell;

template <Scalar T>
struct bead_in_plane {
  T mass;
  int speeds() const { return 2; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    using std::sin, std::cos;
    const S r = q(0), c = cos(q(1)), s = sin(q(1));
    body_state<S> bead;  // a particle: no inertia tensor, no rotation
    bead.mass = S(mass);
    bead.velocity = vec3<S>(u(0) * c - r * u(1) * s, u(0) * s + r * u(1) * c, S(0));
    out.push_back(bead);
  }
};

template <Scalar T>
struct motor_constraint {  // phi' = w + a t
  T w, a;
  int count() const { return 1; }
  template <class S>
  void eval(const vector_t<S>&, const S& t, matrix_t<S>& A, vector_t<S>& rhs) const {
    A(0, 0) = S(0);
    A(0, 1) = S(1);
    rhs(0) = S(w) + S(a) * t;
  }
};

template <Scalar T>
bool run() {
  const T m = from_decimal<T>("0.05"), w = from_decimal<T>("3"), a = from_decimal<T>("0.5");
  const T t = from_decimal<T>("2"), r = from_decimal<T>("0.4"), rd = from_decimal<T>("1.1");
  const T phid = w + a * t;
  vector_t<T> q(2), u(2);
  q << r, from_decimal<T>("0.3");
  u << rd, phid;
  const bead_in_plane<T> bead{m};
  const motor_constraint<T> motor{w, a};
  const auto cotton = cotton_reactions(bead, motor, q, u, t);
  const auto lagrange = lagrange_multipliers(bead, motor, q, u, t);
  const T r_ddot = r * phid * phid;
  const T H = m * (r * r * a + T(2) * r * rd * phid);
  std::cout << scalar_traits<T>::name << ":\n  r''   Cotton " << to_string(cotton.accelerations(0)) << "  Lagrange "
            << to_string(lagrange.accelerations(0)) << "  textbook " << to_string(r_ddot) << "\n  H     Cotton "
            << to_string(cotton.reactions(0)) << "  Lagrange " << to_string(lagrange.reactions(0)) << "  textbook "
            << to_string(H) << "\n";
  auto agree = [](const T& x, const T& y) {  // the library's admissibility predicate (scalar/policy.hpp)
    using std::abs;
    return consistent_with_zero(T(x - y), T(abs(y) + T(1)));
  };
  return agree(cotton.reactions(0), H) && agree(lagrange.reactions(0), H) && agree(cotton.accelerations(0), r_ddot) &&
         agree(lagrange.accelerations(0), r_ddot);
}

int main() {
  const bool ok = run<double>() && run<interval>();
  std::cout << (ok ? "bead on a rotating wire: Cotton, Lagrange and the textbook agree\n" : "DISAGREEMENT\n");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
