// Proof (d): Example I's geometric claim (paper sec. 6).  The couple that keeps
// the axis on the cone has zero moment about the body axis e_z and about the
// axis n + f'(theta) e3 (the instantaneous axis when theta varies with phi
// fixed), so its axis is normal to the plane they span -- the plane through the
// body axis normal to the cone -- and its moment about the vertical e3 is H.
//
// The couple is computed twice: by the library (from virtual work,
// J_w^T Gamma = (0, 0, H)), and independently by Newton-Euler about the fixed
// point O,  Gamma_NE = I_O alpha + omega x I_O omega - (l e_z) x (-m g e3),  with
//   alpha = psi'' e3 + theta'' n + theta' psi' (e3 x n) + phi'' e_z + phi' (omega x e_z)
// written by hand from the Euler angles and Cotton's accelerations.
// Part 1 (exact, 400 rational states of the box): e_z . Gamma_NE = 0,
// (n + f' e3) . Gamma_NE = 0, e3 . Gamma_NE = H and Gamma_NE = Gamma_library exactly.
// Part 2 (interval, the whole box in sub-boxes): the enclosures of the two
// moments contain 0, e3 . Gamma_NE meets H and Gamma_NE meets the library's couple.
#include <random>
#include <sstream>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "proof.hpp"
#include "top_box.hpp"
#include "top_rational.hpp"
#include "appell/models/top_on_cone.hpp"

using namespace appell;
using proof::Q;

namespace {
// Newton-Euler couple about O from the state and the constrained accelerations.
template <class T>
vec3<T> newton_euler_couple(const T& A, const T& C, const T& m, const T& l, const T& g, const vec3<T>& n,
                            const vec3<T>& ez, const T& fp, const T& fpp, const T& thd, const T& phd, const T& thdd,
                            const T& phdd) {
  const vec3<T> e3(T(0), T(0), T(1));
  const T psi_dot = fp * thd, psi_ddot = fpp * thd * thd + fp * thdd;
  const vec3<T> omega = e3 * psi_dot + n * thd + ez * phd;
  const vec3<T> alpha = e3 * psi_ddot + n * thdd + cross(e3, n) * (thd * psi_dot) + ez * phdd + cross(omega, ez) * phd;
  mat3<T> IO;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) IO(i, j) = (C - A) * ez(i) * ez(j) + (i == j ? A : T(0));
  const vec3<T> weight_moment = cross(vec3<T>(ez * l), vec3<T>(T(0), T(0), -m * g));
  return vec3<T>(mat_vec(IO, alpha) + cross(omega, mat_vec(IO, omega)) - weight_moment);
}
}  // namespace

int main() {
  proof::verdict v(
      "Example I, the couple's axis. For the top and cone of data/scenes/top_on_cone.json and states "
      "with theta in [0.6, 0.8], theta' in [1.0, 1.4], phi' in [38, 42]: the constraint couple obtained from "
      "Newton-Euler about O has zero moment about the body axis e_z and about n + f'(theta) e3, its moment "
      "about e3 is Cotton's H, and it is the couple the library recovers from virtual work -- (1) exactly at "
      "400 random rational states, (2) as intersecting interval enclosures over the whole box (with phi in "
      "[0.2, 0.4]) cut into 8 x 8 x 8 x 2 sub-boxes.");
  const Q A(2, 25), C(1, 50), m(3, 2), l(1, 5), g(981, 100);
  const proof::rational_top top{A, C, m, l, g};
  std::mt19937_64 rng(6);
  auto uniform = [&](long lo, long hi, long den) { return Q(std::uniform_int_distribution<long>(lo, hi)(rng), den); };
  int exact = 0;
  for (int k = 0; k < 400; ++k) {
    const Q tau_theta = uniform(3100, 4200, 10000), tau_psi = uniform(-1000, 1000, 1000);
    const Q thd = uniform(100, 140, 100), phd = uniform(3800, 4200, 100);
    const proof::rational_cone cone;
    const top_on_cone_result<Q> r = top_on_cone_motion(top, cone, top_on_cone_state<Q>{tau_psi, tau_theta, Q(0), thd, phd});
    const Q H = r.H, fp = cone.fprime(tau_theta), fpp = cone.fsecond(tau_theta);
    const vec3<Q> lib = r.couple;
    vector_t<Q> q(3);
    q << tau_psi, tau_theta, Q(0);
    vec3<Q> n, ez;
    proof::rational_top::axes(q, n, ez);
    const vec3<Q> G = newton_euler_couple(A, C, m, l, g, n, ez, fp, fpp, thd, phd, r.theta_ddot, r.phi_ddot);
    const bool ok = dot(G, ez) == 0 && dot(G, vec3<Q>(n + vec3<Q>(0, 0, 1) * fp)) == 0 && G(2) == H && G == lib;
    v.require(ok, "state " + std::to_string(k) + ": Gamma . e_z = " + dot(G, ez).str() + ", Gamma . e3 - H = " +
                      Q(G(2) - H).str());
    exact += ok;
  }
  v.note("part 1: " + std::to_string(exact) + "/400 rational states, all four identities exact");
  const scene_input s = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/top_on_cone.json");
  const auto& in = s.as<top_on_cone_input>();
  using T = interval;
  const T Ai = value<T>(in.A), Ci = value<T>(in.C), mi = value<T>(in.mass), li = value<T>(in.l), gi = value<T>(in.gravity);
  long boxes = 0;
  proof::for_each_sub_box(8, [&](const proof::top_box_result& r) {
    const vec3<T> G = newton_euler_couple(Ai, Ci, mi, li, gi, r.n, r.ez, r.fprime, in.fsecond->eval(r.theta),
                                          r.theta_dot, r.phi_dot, r.theta_ddot, r.phi_ddot);
    std::ostringstream where;
    where << "theta " << to_string(r.theta) << " theta' " << to_string(r.theta_dot);
    v.require(possibly_zero(dot(G, r.ez)), "moment about e_z excludes 0 at " + where.str());
    v.require(possibly_zero(dot(G, vec3<T>(r.n + r.e3 * r.fprime))), "moment about n + f' e3 excludes 0 at " + where.str());
    v.require(proof::overlap(G(2), r.H), "moment about e3 misses H at " + where.str());
    for (int i = 0; i < 3; ++i) v.require(proof::overlap(G(i), r.couple(i)), "couples disjoint at " + where.str());
    ++boxes;
  });
  v.note("part 2: " + std::to_string(boxes) + " sub-boxes, all enclosures consistent");
  return v.finish();
}
