// Proof: eq. (21) follows from eq. (9).  For a homogeneous sphere
// (A = B = C, D = E = F = 0, constant), Cotton's acceleration energy of the
// free body on moving axes, eq. (9), becomes (with the misprints corrected,
// docs/design.md §4)
//   2S = M [u'(u' + 2Qw - 2Rv) + v'(v' + 2Ru - 2Pw) + w'(w' + 2Pv - 2Qu)]
//      + A [p'(p' + 2Qr - 2Rq) + q'(q' + 2Rp - 2Pr) + r'(r' + 2Pq - 2Qp)] + ...   (21)
// (the OCR prints p'(p + 2Qr - 2Rq), omega for w and nu for v).
// Checked in exact rational arithmetic at 300 random states (speeds and axis
// rotation P, Q, R): the printed eq. (9), written out by hand in eq9.hpp and
// specialised here to A = B = C, D = E = F = 0, A' = .. = F' = 0, the printed
// eq. (21) halved, and the S2 + S1 the library assembles for the free sphere on
// the moving axes are the same polynomial in (u', v', w', p', q', r'),
// coefficient by coefficient.
#include <random>

#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/scalar/rational.hpp"
#include "appell/dynamics/free_body.hpp"
#include "eq9.hpp"
#include "proof.hpp"

using namespace appell;
using Q = rational_q;

namespace {
std::mt19937_64 rng(21);
Q rq(long lo, long hi, long den) { return Q(std::uniform_int_distribution<long>(lo, hi)(rng), den); }

struct sphere_axes {  // constant rotation (P, Q, R), inertia A * identity
  vec3<Q> Omega;
  Q A;
  template <class S> vec3<S> rate(const S&) const { return vec3<S>(S(Omega(0)), S(Omega(1)), S(Omega(2))); }
  template <class S> mat3<S> inertia(const S&) const { return mat3<S>::Identity() * S(A); }
};

// Coefficients of a quadratic polynomial in x (6 variables), read off values.
template <class F>
std::pair<matrix_t<Q>, vector_t<Q>> coefficients(const F& p) {
  const int k = 6;
  const Q p0 = p(vector_t<Q>::Zero(k));
  matrix_t<Q> K(k, k);
  vector_t<Q> c(k), pe(k);
  for (int i = 0; i < k; ++i) {
    vector_t<Q> e = vector_t<Q>::Zero(k);
    e(i) = 1;
    pe(i) = p(e);
  }
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      vector_t<Q> e = vector_t<Q>::Zero(k);
      e(i) += 1;
      e(j) += 1;
      K(i, j) = i == j ? p(e) - 2 * pe(i) + p0 : p(e) - pe(i) - pe(j) + p0;
    }
  for (int i = 0; i < k; ++i) c(i) = pe(i) - p0 - K(i, i) / 2;
  return {K, c};
}
}  // namespace

int main() {
  proof::verdict v(
      "Eq. (21) follows from eq. (9). For a homogeneous sphere on axes turning with (P, Q, R), at 300 "
      "random rational states, eq. (9) with A = B = C and D = E = F = 0, the paper's eq. (21) (misprints "
      "corrected), and the library's S2 + S1 are the same polynomial in the accelerations, exactly.");
  int ok_count = 0;
  for (int n = 0; n < 300; ++n) {
    const Q M = rq(1, 90, 10), A = rq(1, 90, 100);
    const sphere_axes axes{vec3<Q>(rq(-50, 50, 10), rq(-50, 50, 10), rq(-50, 50, 10)), A};
    const free_body_on_moving_axes<Q, sphere_axes> sys{M, axes, vec3<Q>(0, 0, 0), vec3<Q>(0, 0, 0)};
    vector_t<Q> s(6);
    for (int i = 0; i < 6; ++i) s(i) = rq(-100, 100, 10);
    const Q P = axes.Omega(0), Qr = axes.Omega(1), R = axes.Omega(2);
    const Q u = s(0), vv = s(1), w = s(2), p = s(3), q = s(4), r = s(5);
    // The printed (9) (eq9.hpp) with A = B = C, D = E = F = 0, all constant.
    const proof::cotton_sec4_state<Q> st{M, P, Qr, R, u, vv, w, p, q, r, A, A, A, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    auto eq9 = [&](const vector_t<Q>& d) { return proof::cotton_eq9(st, d(0), d(1), d(2), d(3), d(4), d(5)); };
    auto eq21 = [&](const vector_t<Q>& d) {  // as printed, misprints corrected
      const Q two_S = M * (d(0) * (d(0) + 2 * Qr * w - 2 * R * vv) + d(1) * (d(1) + 2 * R * u - 2 * P * w) +
                           d(2) * (d(2) + 2 * P * vv - 2 * Qr * u)) +
                      A * (d(3) * (d(3) + 2 * Qr * r - 2 * R * q) + d(4) * (d(4) + 2 * R * p - 2 * P * r) +
                           d(5) * (d(5) + 2 * P * q - 2 * Qr * p));
      return two_S / 2;
    };
    const appell_equations<Q> e = gibbs_appell(sys, vector_t<Q>(vector_t<Q>::Zero(6)), s, Q(0));
    const auto [K9, c9] = coefficients(eq9);
    const auto [K21, c21] = coefficients(eq21);
    const bool ok9_lib = K9 == e.M && c9 == e.b;   // printed (9) = library's S2 + S1
    const bool ok21_9 = K21 == K9 && c21 == c9;    // printed (21) = printed (9) specialised
    const bool ok = ok9_lib && ok21_9;
    v.require(ok, "state " + std::to_string(n) + ": " +
                      (!ok9_lib ? "(9) specialised and the library's S2 + S1 differ" : "(21) and (9) specialised differ"));
    ok_count += ok;
  }
  v.note(std::to_string(ok_count) + "/300 states: (9) specialised = (21) = library, 6 + 36 coefficients each");
  return v.finish();
}
