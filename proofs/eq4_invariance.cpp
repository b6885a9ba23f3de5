// Proof (b): the invariance of eq. (4).  P . du is minus the virtual work of
// the inertia forces, whatever the speeds: under a change u = T v + t,
// P_v = T^T P_u, i.e. M_v = T^T M_u T and b_v = T^T b_u (T, t constant), and
// P_v . dv = P_u . du for du = T dv.  Checked in exact rational arithmetic on
// the sec. 3 and sec. 4 systems with random invertible rational T, the library
// re-deriving everything for the changed speeds (with_speeds); and the
// inertia virtual work computed body by body equals P . du exactly.
#include <random>

#include "appell/dynamics/speeds.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/scalar/rational.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/dynamics/free_body.hpp"
#include "proof.hpp"

using namespace appell;
using Q = rational_q;

namespace {
std::mt19937_64 rng(4);
Q random_q(int lo, int hi, int den = 5) {
  return Q(std::uniform_int_distribution<int>(lo, hi)(rng)) / Q(std::uniform_int_distribution<int>(1, den)(rng));
}

struct constant_axes {  // sec. 4 axes with constant rate and (for this proof) constant inertia
  vec3<Q> Omega;
  mat3<Q> I;
  template <class S> vec3<S> rate(const S&) const { return vec3<S>(S(Omega(0)), S(Omega(1)), S(Omega(2))); }
  template <class S> mat3<S> inertia(const S&) const {
    mat3<S> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = S(I(i, j));
    return r;
  }
};

matrix_t<Q> random_invertible(int n) {
  for (;;) {
    matrix_t<Q> T(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) T(i, j) = random_q(-4, 4);
    if (T.fullPivLu().isInvertible()) return T;
  }
}

template <class Sys>
bool invariant(const Sys& sys, proof::verdict& v, const std::string& label) {
  const int n = sys.speeds();
  const matrix_t<Q> T = random_invertible(n);
  vector_t<Q> t(n), vv(n), vdot(n), dv(n);
  for (int i = 0; i < n; ++i) {
    t(i) = random_q(-3, 3);
    vv(i) = random_q(-6, 6);
    vdot(i) = random_q(-6, 6);
    dv(i) = random_q(-6, 6);
  }
  const vector_t<Q> u = T * vv + t, udot = T * vdot, du = T * dv, q = vector_t<Q>::Zero(n);
  const auto changed = change_speeds(sys, constant_change<Q>{T, t}, n);
  const appell_equations<Q> eu = gibbs_appell(sys, q, u, Q(0)), ev = gibbs_appell(changed, q, vv, Q(0));
  bool ok = ev.M == matrix_t<Q>(T.transpose() * eu.M * T) && ev.b == vector_t<Q>(T.transpose() * eu.b) &&
            ev.Q == vector_t<Q>(T.transpose() * eu.Q);
  v.require(ok, label + ": M_v != T^T M_u T, b_v != T^T b_u or Q_v != T^T Q_u");
  const Q pv = ev.P(vdot).dot(dv), pu = eu.P(udot).dot(du);
  v.require(pv == pu, label + ": P_v . dv = " + pv.str() + " but P_u . du = " + pu.str());
  const Q r1 = virtual_work_residual(sys, eu, q, u, Q(0), udot, du);
  const Q r2 = virtual_work_residual(changed, ev, q, vv, Q(0), vdot, dv);
  v.require(r1 == 0 && r2 == 0, label + ": inertia virtual work differs from P . du");
  return ok && pv == pu && r1 == 0 && r2 == 0;
}
}  // namespace

int main() {
  proof::verdict v(
      "Eq. (4) is invariant. For 200 random rational states of Euler's body (sec. 3) and 200 of the "
      "free body on moving axes (sec. 4), each with a random invertible rational change of speeds "
      "u = T v + t, the Appell equations the library derives in the speeds v satisfy M_v = T^T M_u T, "
      "b_v = T^T b_u, Q_v = T^T Q_u exactly; P_v . dv = P_u . du for du = T dv; and in both sets of "
      "speeds P . du equals minus the virtual work of the inertia forces computed body by body.");
  int ok3 = 0, ok4 = 0;
  for (int k = 0; k < 200; ++k) {
    const euler_system<Q> sys{{vec3<Q>(random_q(2, 9), random_q(2, 9), random_q(2, 9)),
                               vec3<Q>(random_q(-3, 3), random_q(-3, 3), random_q(-3, 3))}};
    ok3 += invariant(sys, v, "sec. 3 case " + std::to_string(k));
    mat3<Q> G;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) G(i, j) = random_q(-4, 4);
    const free_body_on_moving_axes<Q, constant_axes> fb{
        random_q(1, 9), constant_axes{vec3<Q>(random_q(-2, 2), random_q(-2, 2), random_q(-2, 2)),
                                      mat3<Q>(G.transpose() * G + mat3<Q>::Identity())},
        vec3<Q>(random_q(-3, 3), 0, 1), vec3<Q>(0, random_q(-3, 3), 2)};
    ok4 += invariant(fb, v, "sec. 4 case " + std::to_string(k));
  }
  v.note("sec. 3: " + std::to_string(ok3) + "/200 changes of speeds; sec. 4: " + std::to_string(ok4) + "/200");
  return v.finish();
}
