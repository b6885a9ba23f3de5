// Proof (a): Cotton's eq. (6), u' . P = 2 S2 + S1, for the paper's sec. 3 and
// sec. 4 systems, in exact rational arithmetic.
//
// At each state three quadratic polynomials in u' are formed with no rounding:
//   S_direct:  S(u') - S(0) from the bodies (acceleration_energy.hpp), its
//              coefficients read off S at 0, e_i and e_i + e_j;
//   S_rebuilt: Cotton's rule applied to the Newton-Euler equations written by
//              hand (Euler's equations for sec. 3; (7) and (8) for sec. 4):
//              double the first-degree terms of u' . P, drop the rest;
//   S_appell:  1/2 u'.M u' + b.u' as assembled by the library;
// and for sec. 4 a fourth,
//   S_9:       Cotton's printed S, eq. (9), written out by hand in the paper's
//              symbols (eq9.hpp: M, P, Q, R, u..r, A..F and the rates A'..F'
//              of the time-varying inertia), no library function involved.
// They must be equal coefficient by coefficient: then u'.P = 2 S2 + S1
// identically in u' at that state, S0 never entered, and the printed (9) is the
// useful part of the acceleration energy.
#include <functional>
#include <random>
#include <sstream>

#include "appell/dynamics/acceleration_energy.hpp"
#include "appell/dynamics/euler_theorem.hpp"
#include "appell/scalar/rational.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/dynamics/free_body.hpp"
#include "eq9.hpp"
#include "proof.hpp"

using namespace appell;
using Q = rational_q;

namespace {

std::mt19937_64 rng(1907);
Q random_q(int lo, int hi, int den = 7) {
  return Q(std::uniform_int_distribution<int>(lo, hi)(rng)) / Q(std::uniform_int_distribution<int>(1, den)(rng));
}

// Axes of sec. 4: rate Omega0 + t Omega1; inertia varying as for a body turning
// at k = omega - Omega relative to the axes: I(t) = I_B + t ([k]x I_B - I_B [k]x).
// The rate must be this one: the library's S (gibbs_appell.hpp) never reads I'(t) --
// it holds the rigid-body relation I' = [k]x I - I [k]x implicitly -- while (8)
// and (9) take A'..F' as given (with k off by (1, 0, 0) all 200 states fail).
struct linear_axes {
  vec3<Q> Omega0, Omega1, k;
  mat3<Q> IB;
  template <class S>
  vec3<S> rate(const S& t) const {
    return vec3<S>(S(Omega0(0)) + t * S(Omega1(0)), S(Omega0(1)) + t * S(Omega1(1)), S(Omega0(2)) + t * S(Omega1(2)));
  }
  template <class S>
  mat3<S> inertia(const S& t) const {
    mat3<Q> K;
    K << 0, -k(2), k(1), k(2), 0, -k(0), -k(1), k(0), 0;
    const mat3<Q> D = K * IB - IB * K;
    mat3<S> I;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) I(i, j) = S(IB(i, j)) + t * S(D(i, j));
    return I;
  }
};

// Coefficients (K, c) of a quadratic polynomial p(x) = 1/2 x.K x + c.x + p(0) from values.
template <class F>
rebuilt_energy<Q> read_polynomial(const F& p, int k) {
  const Q p0 = p(vector_t<Q>::Zero(k));
  rebuilt_energy<Q> r{matrix_t<Q>(k, k), vector_t<Q>(k)};
  std::vector<Q> pe(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) {
    vector_t<Q> e = vector_t<Q>::Zero(k);
    e(i) = 1;
    pe[static_cast<std::size_t>(i)] = p(e);
  }
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      vector_t<Q> e = vector_t<Q>::Zero(k);
      e(i) += 1;
      e(j) += 1;
      // p(e_i + e_j) - p(e_i) - p(e_j) + p(0) = K_ij  (i != j);  for i == j: p(2 e_i) - 2 p(e_i) + p(0) = K_ii
      r.K(i, j) = i == j ? p(e) - 2 * pe[static_cast<std::size_t>(i)] + p0
                         : p(e) - pe[static_cast<std::size_t>(i)] - pe[static_cast<std::size_t>(j)] + p0;
    }
  for (int i = 0; i < k; ++i) r.c(i) = pe[static_cast<std::size_t>(i)] - p0 - r.K(i, i) / 2;
  return r;
}

template <class Sys, class NE>
bool same_three_ways(const Sys& sys, const vector_t<Q>& q, const vector_t<Q>& u, const NE& newton_euler,
                     std::string& why, const std::function<Q(const vector_t<Q>&)>& cotton_S = {}) {
  const int k = sys.speeds();
  const appell_equations<Q> e = gibbs_appell(sys, q, u, Q(0));
  const auto direct = read_polynomial([&](const vector_t<Q>& ud) { return acceleration_energy(sys, q, u, Q(0), ud); }, k);
  const auto rebuilt = rebuild_energy<Q>(newton_euler, k);
  if (cotton_S) {  // Cotton's printed S, eq. (9), must be the same polynomial too
    const auto s9 = read_polynomial(cotton_S, k);
    for (int i = 0; i < k; ++i) {
      if (s9.c(i) != e.b(i)) {
        why = "eq. (9) S1 coefficient " + std::to_string(i) + ": printed (9) " + s9.c(i).str() + ", Appell " +
              e.b(i).str();
        return false;
      }
      for (int j = 0; j < k; ++j)
        if (s9.K(i, j) != e.M(i, j)) {
          why = "eq. (9) S2 coefficient (" + std::to_string(i) + "," + std::to_string(j) + "): printed (9) " +
                s9.K(i, j).str() + ", Appell " + e.M(i, j).str();
          return false;
        }
    }
  }
  for (int i = 0; i < k; ++i) {
    if (direct.c(i) != e.b(i) || rebuilt.c(i) != e.b(i)) {
      why = "S1 coefficient " + std::to_string(i) + ": direct " + direct.c(i).str() + ", rebuilt " +
            rebuilt.c(i).str() + ", Appell " + e.b(i).str();
      return false;
    }
    for (int j = 0; j < k; ++j)
      if (direct.K(i, j) != e.M(i, j) || rebuilt.K(i, j) != e.M(i, j)) {
        why = "S2 coefficient (" + std::to_string(i) + "," + std::to_string(j) + ")";
        return false;
      }
  }
  return true;
}

}  // namespace

int main() {
  proof::verdict v(
      "Cotton's eq. (6). For Euler's body (sec. 3) and for the free body on axes moving relative to "
      "body and space with time-varying inertia (sec. 4), at each of 200 random rational states of "
      "each, the useful part S2 + S1 of Appell's acceleration energy computed from the bodies, the one "
      "rebuilt from the Newton-Euler equations by Cotton's rule (double the first-degree terms of "
      "u'.P, drop the rest), for sec. 4 also Cotton's printed S of eq. (9) written out by hand in the "
      "paper's symbols, and the library's 1/2 u'.M u' + b.u' are the same polynomial in u', "
      "coefficient by coefficient, in exact rational arithmetic; so u'.P = 2 S2 + S1 identically in u'.");
  int euler_ok = 0, free_ok = 0;
  for (int n = 0; n < 200; ++n) {
    // sec. 3: positive moments satisfying the triangle inequalities.
    Q A = random_q(1, 40), B = random_q(1, 40), C = random_q(1, 40);
    if (A + B < C || B + C < A || C + A < B) C = (A + B) / 2;
    const euler_system<Q> sys{{vec3<Q>(A, B, C), vec3<Q>(random_q(-9, 9), random_q(-9, 9), random_q(-9, 9))}};
    vector_t<Q> u(3);
    u << random_q(-20, 20), random_q(-20, 20), random_q(-20, 20);
    const vector_t<Q> q = vector_t<Q>::Zero(3);
    auto euler = [&](const vector_t<Q>& ud) {  // A p' + (C - B) q r, ... (sec. 3)
      vector_t<Q> P(3);
      P << A * ud(0) + (C - B) * u(1) * u(2), B * ud(1) + (A - C) * u(2) * u(0), C * ud(2) + (B - A) * u(0) * u(1);
      return P;
    };
    std::string why;
    const bool ok = same_three_ways(sys, q, u, euler, why);
    v.require(ok, "sec. 3 state " + std::to_string(n) + ": " + why);
    euler_ok += ok;
  }
  for (int n = 0; n < 200; ++n) {
    mat3<Q> G;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) G(i, j) = random_q(-5, 5);
    const mat3<Q> IB = G.transpose() * G + mat3<Q>::Identity();  // symmetric positive definite, products of inertia
    vector_t<Q> u(6);
    for (int i = 0; i < 6; ++i) u(i) = random_q(-10, 10);
    linear_axes axes{vec3<Q>(random_q(-3, 3), random_q(-3, 3), random_q(-3, 3)),
                     vec3<Q>(random_q(-3, 3), random_q(-3, 3), random_q(-3, 3)), vec3<Q>(), IB};
    axes.k = vec3<Q>(u(3), u(4), u(5)) - axes.Omega0;
    const free_body_on_moving_axes<Q, linear_axes> sys{random_q(1, 9), axes, vec3<Q>(1, 2, 3), vec3<Q>(-1, 0, 2)};
    const vector_t<Q> q = vector_t<Q>::Zero(6);
    auto ne = [&](const vector_t<Q>& ud) { return sys.newton_euler(u, Q(0), ud); };
    // eq. (9) as printed, at t = 0, in the paper's symbols.  A..F from the inertia
    // tensor [[A, -F, -E], [-F, B, -D], [-E, -D, C]] (products with minus signs);
    // the inertia is linear in t, so A'..F' are the same entries of the
    // t-coefficient I(1) - I(0) = [k]x I_B - I_B [k]x.
    const mat3<Q> I0 = sys.axes.inertia<Q>(Q(0)), I1 = sys.axes.inertia<Q>(Q(1));
    const mat3<Q> Id = I1 - I0;
    const bool symmetric = I0 == I0.transpose() && Id == Id.transpose();  // else no A..F describe it
    const vec3<Q> Om = sys.axes.rate<Q>(Q(0));
    const proof::cotton_sec4_state<Q> st{sys.mass, Om(0),    Om(1),    Om(2),    u(0),     u(1),     u(2),
                                         u(3),     u(4),     u(5),     I0(0, 0), I0(1, 1), I0(2, 2), -I0(1, 2),
                                         -I0(2, 0), -I0(0, 1), Id(0, 0), Id(1, 1), Id(2, 2), -Id(1, 2), -Id(2, 0),
                                         -Id(0, 1)};
    auto s9 = [&](const vector_t<Q>& ud) { return proof::cotton_eq9(st, ud(0), ud(1), ud(2), ud(3), ud(4), ud(5)); };
    std::string why = "the inertia on the axes is not symmetric";
    const bool ok = symmetric && same_three_ways(sys, q, u, ne, why, s9);
    v.require(ok, "sec. 4 state " + std::to_string(n) + ": " + why);
    free_ok += ok;
  }
  v.note("sec. 3: " + std::to_string(euler_ok) + "/200 states, 3 + 9 coefficients each, exact");
  v.note("sec. 4: " + std::to_string(free_ok) +
         "/200 states, 6 + 36 coefficients each, exact; the printed (9) among the four");
  return v.finish();
}
