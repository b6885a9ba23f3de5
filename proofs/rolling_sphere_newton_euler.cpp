// Proof: for the rolling sphere (Example II), the reactions from Cotton's
// method -- the contact force at the contact point and the pivoting couple,
// eq. (14) in the speeds (p, q, u_1, v_1, w, r) of eq. (23) -- equal the contact
// force and couple of the Newton-Euler equations with contact multipliers in a
// fixed frame (tests/independent/sphere_newton_euler.hpp), and so do the accelerations; for each
// surface type (plane; sphere outside, inside; cylinder outside, inside).
// Part 1 (exact): at 200 random rational consistent states per surface (centres
// on the surface of centres at rational points, omega . n = 0), both run in
// exact rational arithmetic and the numbers are equal.  Part 2 (interval): over
// a box of consistent states per surface, cut into sub-boxes, the interval
// enclosures of the two intersect on every sub-box.
#include <random>
#include <sstream>

#include "appell/scalar/rational.hpp"
#include "proof.hpp"
#include "../tests/independent/sphere_newton_euler.hpp"

using namespace appell;
using Q = rational_q;

namespace {
std::mt19937_64 rng(1907);
Q rq(long lo, long hi, long den) { return Q(std::uniform_int_distribution<long>(lo, hi)(rng), den); }

struct surface_case {
  surface_type type;
  bool inside;
  const char* name;
};
const surface_case cases[] = {{surface_type::plane, false, "plane"},
                              {surface_type::sphere, false, "outside a sphere"},
                              {surface_type::sphere, true, "inside a sphere"},
                              {surface_type::cylinder, false, "outside a cylinder"},
                              {surface_type::cylinder, true, "inside a cylinder"}};

// A rational (or interval) unit normal m from parameters (u, t), and the centre.
template <class S>
void place(surface_type type, const S& rho, const S& a, const S& u, const S& t, const S& z, vec3<S>& c, vec3<S>& m) {
  if (type == surface_type::plane) {
    m = vec3<S>(S(0), S(0), S(1));
    c = vec3<S>(u, t, a);
  } else if (type == surface_type::sphere) {
    const S d = S(1) + u * u + t * t;
    m = vec3<S>(S(2) * u / d, S(2) * t / d, (S(1) - u * u - t * t) / d);
    c = m * rho;
  } else {
    const S e = S(1) + u * u;
    m = vec3<S>((S(1) - u * u) / e, S(2) * u / e, S(0));
    c = m * rho + vec3<S>(S(0), S(0), z);
  }
}

template <class S>
auto solver() {
  return [](const matrix_t<S>& K, const vector_t<S>& rhs) { return solve(K, rhs); };
}
}  // namespace

int main() {
  proof::verdict v(
      "Example II, Cotton = Newton-Euler. For a sphere rolling without slipping or pivoting on a plane, "
      "outside and inside a sphere, outside and inside a cylinder: (1) at 200 random rational consistent "
      "states per surface, the contact force and pivoting couple from Cotton's reactions (eq. 14 in the "
      "speeds of eq. 23), and the accelerations, equal those of the Newton-Euler equations with contact "
      "multipliers in a fixed frame, exactly; (2) over a box of consistent states per surface "
      "(surface parameters in [0.1, 0.3] x [0.2, 0.4], omega of components in [1, 2] projected on the "
      "tangent plane), cut into 8 x 8 sub-boxes, their interval enclosures intersect.");
  for (const auto& sc : cases) {
    int exact = 0;
    for (int k = 0; k < 200; ++k) {
      const Q M = rq(1, 50, 10), a = rq(1, 30, 100), b = a + rq(1, 200, 100);
      const Q A = rq(1, 100, 100) * Q(2, 3) * M * a * a, rho = sc.inside ? b - a : b + a;
      vec3<Q> c, m;
      place<Q>(sc.type, rho, a, rq(-300, 300, 100), rq(-300, 300, 100), rq(-100, 100, 10), c, m);
      const vec3<Q> w0(rq(-200, 200, 10), rq(-200, 200, 10), rq(-200, 200, 10));
      const vec3<Q> w = w0 - m * dot(w0, m);
      const vec3<Q> F(rq(-50, 50, 10), rq(-50, 50, 10), rq(-150, 50, 10)), tau(rq(-10, 10, 100), 0, rq(-10, 10, 100));
      const rolling_surface<Q> surface{sc.type, sc.inside, b, Q(0)};
      const auto lib = rolling_sphere_motion(M, A, a, surface, c, w, F, tau);
      const auto ne = independent::sphere_newton_euler<Q>(M, A, a, sc.type, sc.inside, b, c, w, F, tau, solver<Q>());
      const bool ok = lib.contact_force == ne.Fc && lib.pivot_couple == ne.Gn && lib.center_ddot == ne.aG &&
                      lib.omega_dot == ne.alpha;
      v.require(ok, std::string(sc.name) + " state " + std::to_string(k) + ": contact force or couple differ");
      exact += ok;
    }
    v.note(std::string(sc.name) + ": " + std::to_string(exact) + "/200 rational states equal exactly");
  }
  using T = interval;
  for (const auto& sc : cases) {
    const T M = from_decimal<T>("2"), a = from_decimal<T>("0.1"), b = from_decimal<T>("1");
    const T A = rational<T>(2, 5) * M * a * a, rho = sc.inside ? b - a : b + a;
    const rolling_surface<T> surface{sc.type, sc.inside, b, T(0)};
    const vec3<T> F(T(0.5), T(-0.3), T(-19.62)), tau(T(0), T(0.01), T(0));
    long boxes = 0;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const T u(0.1 + 0.025 * i, 0.1 + 0.025 * (i + 1)), t(0.2 + 0.025 * j, 0.2 + 0.025 * (j + 1));
        vec3<T> c, m;
        place<T>(sc.type, rho, a, u, t, T(0.3), c, m);
        const vec3<T> w0(T(1, 2), T(1, 2), T(1, 2));
        const vec3<T> w = w0 - m * dot(w0, m);
        const auto lib = rolling_sphere_motion(M, A, a, surface, c, w, F, tau);
        const auto ne = independent::sphere_newton_euler<T>(M, A, a, sc.type, sc.inside, b, c, w, F, tau, solver<T>());
        auto meet = [](const T& x, const T& y) { return x.lower() <= y.upper() && y.lower() <= x.upper(); };
        bool ok = meet(lib.pivot_couple, ne.Gn);
        for (int d = 0; d < 3; ++d) ok = ok && meet(lib.contact_force(d), ne.Fc(d)) && meet(lib.center_ddot(d), ne.aG(d));
        std::ostringstream where;
        where << sc.name << " sub-box " << i << "," << j;
        v.require(ok, where.str() + ": enclosures disjoint");
        ++boxes;
      }
    v.note(std::string(sc.name) + ": " + std::to_string(boxes) + " sub-boxes, enclosures intersect");
  }
  return v.finish();
}
