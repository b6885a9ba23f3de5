// Proof (c): for the top on a cone (Example I), Cotton's reaction H (eq. 14, in
// the paper's speeds theta', phi', psi_1') equals the Lagrange multiplier lambda
// of psi' - f'(theta) theta' = 0 (saddle-point system in the speeds psi', theta', phi'),
// and the two methods give the same theta''.
//
// Part 1 (exact): at 400 random rational states of the box, in the rational
// parametrisation of top_rational.hpp, the shipped top_on_cone_motion (Cotton on
// Resal's trihedron, Lagrange on the fixed axes) runs in exact arithmetic and
// the numbers are equal; its eq. (4) residual is exactly 0.  Part 2 (interval): over the whole box, cut into
// sub-boxes, the interval enclosures computed by the two methods in the
// library's own coordinates intersect on every sub-box.  Interval arithmetic
// cannot prove two functions equal; part 2 proves they are consistent
// everywhere in the box, part 1 that they are equal wherever it looked.
#include <random>
#include <sstream>

#include "proof.hpp"
#include "top_box.hpp"
#include "top_rational.hpp"

using namespace appell;
using proof::Q;

int main() {
  proof::verdict v(
      "Example I, Cotton = Lagrange. For the top and cone of data/scenes/top_on_cone.json and states "
      "with theta in [0.6, 0.8], theta' in [1.0, 1.4], phi' in [38, 42]: (1) at 400 random rational states "
      "(tan(theta/2) rational), Cotton's reaction H equals the Lagrange multiplier lambda, Cotton's "
      "theta'' equals Lagrange's and eq. (4) holds, exactly; (2) over the whole box (with phi in [0.2, 0.4]), cut into "
      "8 x 8 x 8 x 2 sub-boxes, the interval enclosures of H and lambda intersect, and so do those of theta''.");
  const proof::rational_top top{Q(2, 25), Q(1, 50), Q(3, 2), Q(1, 5), Q(981, 100)};
  std::mt19937_64 rng(1907);
  auto uniform = [&](long lo, long hi, long den) {
    return Q(std::uniform_int_distribution<long>(lo, hi)(rng), den);
  };
  int exact = 0;
  for (int n = 0; n < 400; ++n) {
    const Q tau_theta = uniform(3100, 4200, 10000), tau_psi = uniform(-1000, 1000, 1000);
    const Q thd = uniform(100, 140, 100), phd = uniform(3800, 4200, 100);
    const proof::rational_cone cone;
    const top_on_cone_result<Q> r = top_on_cone_motion(top, cone, top_on_cone_state<Q>{tau_psi, tau_theta, Q(0), thd, phd});
    const bool ok = r.H == r.lagrange_multiplier && r.theta_ddot == r.theta_ddot_lagrange && r.virtual_work_residual == 0;
    v.require(ok, "state " + std::to_string(n) + ": H = " + r.H.str() + ", lambda = " + r.lagrange_multiplier.str() +
                      ", eq. (4) residual " + r.virtual_work_residual.str());
    exact += ok;
  }
  v.note("part 1: " + std::to_string(exact) + "/400 rational states, H = lambda, theta'' equal and eq. (4) holds, exactly");
  long boxes = 0;
  double widest = 0;
  proof::for_each_sub_box(8, [&](const proof::top_box_result& r) {
    std::ostringstream where;
    where << "theta " << to_string(r.theta) << " theta' " << to_string(r.theta_dot) << " phi' " << to_string(r.phi_dot);
    v.require(proof::overlap(r.H, r.lambda), "H " + to_string(r.H) + " and lambda " + to_string(r.lambda) +
                                                 " are disjoint at " + where.str());
    v.require(proof::overlap(r.theta_ddot, r.theta_ddot_lagrange), "theta'' disjoint at " + where.str());
    widest = std::max(widest, boost::numeric::width(r.H));
    ++boxes;
  });
  std::ostringstream s;
  s << "part 2: " << boxes << " sub-boxes, enclosures intersect on all; widest enclosure of H on a sub-box "
    << widest << " (naive interval evaluation over a box: wrapping, see docs/proofs.md)";
  v.note(s.str());
  return v.finish();
}
