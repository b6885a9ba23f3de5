// The contact wrench cone of a rectangular sole (reactions/wrench_cone.hpp) against its
// definition: a wrench is in the cone exactly when forces at the sole's four corners, each in its
// friction pyramid, make it.  That is a linear feasibility problem, solved here exactly in
// rationals (GMP) by the simplex method's first phase with Bland's rule: each corner force a
// nonnegative combination of its pyramid's four edges (+-mu, +-mu, 1), 16 unknowns, 6 equations
// (the wrench).  Nothing of the closed form is used by it.
//   - wrenches made by random corner forces: the closed form says inside;
//   - random wrenches in a box: the closed form and the problem agree on every one (both sides
//     represented);
//   - along random rays from the cone's inside: the boundary point t* (where the first margin,
//     linear in t, reaches 0) is inside at t* (1 - 10^-9) and outside at t* (1 + 10^-9) by the
//     feasibility problem: the closed form's boundary is the definition's, facet by facet;
//   - in interval arithmetic, at random double wrenches near the boundary and decimal mu, X, Y:
//     `holds` only where the exact problem is feasible, `fails` only where it is not; undecided
//     only within a relative 10^-12 of the boundary.
#define BOOST_TEST_MODULE wrench_cone
#include <boost/test/unit_test.hpp>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "appell/reactions/wrench_cone.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/policy.hpp"
#include "appell/scalar/types.hpp"

using namespace appell;
using q = mpq_class;
using wrench = std::array<q, 6>;  // fx, fy, fz, tau_x, tau_y, tau_z

namespace {

struct sole {
  q X, Y, mu;
};

/// The wrench at the sole's centre made by a unit force along pyramid edge (sa mu, sb mu, 1) at
/// corner (sx X, sy Y, 0): force g and moment p x g.
wrench edge_wrench(const sole& s, int sx, int sy, int sa, int sb) {
  const q x = sx * s.X, y = sy * s.Y, gx = sa * s.mu, gy = sb * s.mu, gz = 1;
  return {gx, gy, gz, q(y * gz), q(-x * gz), q(x * gy - y * gx)};
}

/// Whether nonnegative weights of the 16 edges make w: phase one of the simplex method, exact.
bool feasible(const sole& s, const wrench& w) {
  constexpr int m = 6, nv = 16, n = nv + m;
  std::vector<std::vector<q>> t(m + 1, std::vector<q>(n + 1, q(0)));
  int col = 0;
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sa : {1, -1})
        for (int sb : {1, -1}) {
          const wrench g = edge_wrench(s, sx, sy, sa, sb);
          for (int r = 0; r < m; ++r) t[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)] = g[static_cast<std::size_t>(r)];
          ++col;
        }
  std::vector<int> basis(m);
  for (int r = 0; r < m; ++r) {
    auto& row = t[static_cast<std::size_t>(r)];
    row[n] = w[static_cast<std::size_t>(r)];
    if (row[n] < 0)
      for (auto& x : row) x = -x;
    row[static_cast<std::size_t>(nv + r)] = 1;
    basis[static_cast<std::size_t>(r)] = nv + r;
  }
  // The objective row: reduced costs of "minimize the artificials' sum", and minus its value.
  auto& obj = t[m];
  for (int j = 0; j <= n; ++j) {
    q c = j >= nv && j < n ? q(1) : q(0);
    for (int r = 0; r < m; ++r) c -= t[static_cast<std::size_t>(r)][static_cast<std::size_t>(j)];
    obj[static_cast<std::size_t>(j)] = c;
  }
  for (int iteration = 0; iteration < 10000; ++iteration) {
    int enter = -1;
    for (int j = 0; j < n && enter < 0; ++j)
      if (obj[static_cast<std::size_t>(j)] < 0) enter = j;  // Bland: the first improving column
    if (enter < 0) break;
    int leave = -1;
    q best;
    for (int r = 0; r < m; ++r) {
      const q& a = t[static_cast<std::size_t>(r)][static_cast<std::size_t>(enter)];
      if (a <= 0) continue;
      const q ratio = t[static_cast<std::size_t>(r)][n] / a;
      if (leave < 0 || ratio < best ||
          (ratio == best && basis[static_cast<std::size_t>(r)] < basis[static_cast<std::size_t>(leave)])) {
        leave = r;
        best = ratio;
      }
    }
    BOOST_REQUIRE(leave >= 0);  // phase one is bounded below by 0
    auto& pr = t[static_cast<std::size_t>(leave)];
    const q p = pr[static_cast<std::size_t>(enter)];
    for (auto& x : pr) x /= p;
    for (int r = 0; r <= m; ++r) {
      if (r == leave) continue;
      auto& row = t[static_cast<std::size_t>(r)];
      const q f = row[static_cast<std::size_t>(enter)];
      if (f == 0) continue;
      for (int j = 0; j <= n; ++j) row[static_cast<std::size_t>(j)] -= f * pr[static_cast<std::size_t>(j)];
    }
    basis[static_cast<std::size_t>(leave)] = enter;
  }
  return obj[n] == 0;  // the artificials' least sum is -obj[n]
}

/// The closed form's margins, exactly.
std::array<q, 16> margins(const sole& s, const wrench& w) {
  const std::array<q, 3> f{w[0], w[1], w[2]}, tau{w[3], w[4], w[5]};
  return all_margins(sole_wrench_margins<q>(f, tau, s.X, s.Y, s.mu));
}
bool inside(const sole& s, const wrench& w) {
  for (const q& x : margins(s, w))
    if (x < 0) return false;
  return true;
}

q random_q(std::mt19937_64& rng, long lo, long hi, long den) {
  std::uniform_int_distribution<long> d(lo * den, hi * den);
  q r(d(rng), den);
  r.canonicalize();
  return r;
}

sole random_sole(std::mt19937_64& rng) {
  // X, Y in [0.02, 0.2], mu in [0.1, 1.2] (and 0 once in a while: no friction at all)
  std::uniform_int_distribution<int> pick(0, 19);
  sole s{q(std::uniform_int_distribution<long>(2, 20)(rng), 100), q(std::uniform_int_distribution<long>(2, 20)(rng), 100),
         pick(rng) == 0 ? q(0) : q(std::uniform_int_distribution<long>(1, 12)(rng), 10)};
  s.X.canonicalize();
  s.Y.canonicalize();
  s.mu.canonicalize();
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(wrenches_made_by_corner_forces_are_inside) {
  std::mt19937_64 rng(58001);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const sole s = random_sole(rng);
    wrench w{};
    // corner forces: c in [0, 10], a and b within +-mu c
    for (int sx : {1, -1})
      for (int sy : {1, -1}) {
        const q c = random_q(rng, 0, 10, 97);
        const q a = s.mu * c * random_q(rng, -1, 1, 89), b = s.mu * c * random_q(rng, -1, 1, 83);
        const q x = sx * s.X, y = sy * s.Y;
        const std::array<q, 6> g{a, b, c, q(y * c), q(-x * c), q(x * b - y * a)};
        for (std::size_t i = 0; i < 6; ++i) w[i] += g[i];
      }
    BOOST_TEST(inside(s, w), "trial " << trial);
    BOOST_TEST(feasible(s, w), "trial " << trial);
    ++checked;
  }
  BOOST_TEST(checked == 300);
}

BOOST_AUTO_TEST_CASE(the_closed_form_and_the_definition_agree_on_random_wrenches) {
  std::mt19937_64 rng(58002);
  int in = 0, out = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const sole s = random_sole(rng);
    const q fz = random_q(rng, -1, 10, 101);
    // tangential forces up to 1.1 mu fz, the centre of pressure up to 1.1 times the half-lengths,
    // the yaw moment up to 0.6 mu (X + Y) fz: about a fifth inside
    const q reach = (s.mu + q(1, 10)) * (fz < 0 ? q(-fz) : fz);
    const q rx = (s.X + s.Y) * reach;
    wrench w{q(random_q(rng, -11, 11, 107) / 10 * reach), q(random_q(rng, -11, 11, 103) / 10 * reach), fz,
             q(random_q(rng, -11, 11, 109) / 10 * s.Y * fz), q(random_q(rng, -11, 11, 113) / 10 * s.X * fz),
             q(random_q(rng, -6, 6, 127) / 10 * rx)};
    const bool closed = inside(s, w), defined = feasible(s, w);
    BOOST_TEST(closed == defined, "trial " << trial << ": closed form " << closed << ", definition " << defined);
    (defined ? in : out) += 1;
  }
  BOOST_TEST_MESSAGE("random wrenches: " << in << " inside, " << out << " outside, all agreeing");
  BOOST_TEST(in >= 200);
  BOOST_TEST(out >= 200);
}

BOOST_AUTO_TEST_CASE(the_boundary_along_random_rays_is_the_definition_s) {
  std::mt19937_64 rng(58003);
  const q eps(1, 1000000000);
  int rays = 0;
  std::array<int, 3> facet_kind{};  // friction, pressure, yaw: which facet the ray left by
  for (int trial = 0; trial < 600; ++trial) {
    sole s = random_sole(rng);
    if (s.mu == 0) s.mu = q(1, 2);  // the cone has an inside
    const wrench w0{q(0), q(0), q(1), q(0), q(0), q(0)};  // a unit push at the centre: inside
    wrench d;
    for (std::size_t i = 0; i < 6; ++i) d[i] = random_q(rng, -1, 1, 1009);
    d[3] *= 3 * s.Y, d[4] *= 3 * s.X, d[5] *= (s.X + s.Y) * s.mu;  // directions leaving by every kind of facet
    // margin_k(w0 + t d) = m0_k + t (m1_k - m0_k): the first to reach 0
    wrench w1;
    for (std::size_t i = 0; i < 6; ++i) w1[i] = w0[i] + d[i];
    const auto m0 = margins(s, w0), m1 = margins(s, w1);
    q tstar = -1;
    int which = -1;
    for (std::size_t k = 0; k < 16; ++k) {
      BOOST_REQUIRE(m0[k] > 0);
      const q slope = m1[k] - m0[k];
      if (slope >= 0) continue;
      const q t = -m0[k] / slope;
      if (which < 0 || t < tstar) tstar = t, which = static_cast<int>(k);
    }
    if (which < 0) continue;  // the ray stays inside (a direction of the cone itself)
    auto at = [&](const q& t) {
      wrench w;
      for (std::size_t i = 0; i < 6; ++i) w[i] = w0[i] + t * d[i];
      return w;
    };
    BOOST_TEST(feasible(s, at(tstar * (1 - eps))), "trial " << trial << " facet " << which);
    BOOST_TEST(!feasible(s, at(tstar * (1 + eps))), "trial " << trial << " facet " << which);
    ++facet_kind[static_cast<std::size_t>(which < 4 ? 0 : which < 8 ? 1 : 2)];
    ++rays;
  }
  BOOST_TEST_MESSAGE("rays: " << rays << "; left by friction " << facet_kind[0] << ", centre of pressure "
                              << facet_kind[1] << ", yaw " << facet_kind[2]);
  BOOST_TEST(rays >= 500);
  for (int k : facet_kind) BOOST_TEST(k >= 20);  // every kind of facet met
}

BOOST_AUTO_TEST_CASE(interval_verdicts_never_claim_what_the_definition_denies) {
  std::mt19937_64 rng(58004);
  std::uniform_real_distribution<double> u(-1, 1);
  const evaluation_scope<interval> scope;
  // decimal parameters: their intervals hold the exact rationals the definition uses
  const sole s{q(1, 10), q(1, 20), q(7, 10)};
  const interval X = from_decimal<interval>("0.1"), Y = from_decimal<interval>("0.05"), mu = from_decimal<interval>("0.7");
  int holds = 0, fails = 0, undecided = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // near the boundary: a random ray's boundary point (in doubles), moved by up to 1e-6 relative
    std::array<double, 6> d;
    for (double& x : d) x = u(rng);
    d[3] *= 0.05, d[4] *= 0.1, d[5] *= 0.15 * 0.7;
    const wrench w0{q(0), q(0), q(1), q(0), q(0), q(0)};
    wrench w1;
    for (std::size_t i = 0; i < 6; ++i) w1[i] = w0[i] + q(d[i]);
    const auto m0 = margins(s, w0), m1 = margins(s, w1);
    double tstar = -1;
    for (std::size_t k = 0; k < 16; ++k) {
      const q slope = m1[k] - m0[k];
      if (slope >= 0) continue;
      const double t = q(-m0[k] / slope).get_d();
      if (tstar < 0 || t < tstar) tstar = t;
    }
    if (tstar < 0) continue;
    const double t = tstar * (1 + 1e-6 * u(rng));
    std::array<double, 6> wd;
    for (std::size_t i = 0; i < 6; ++i) wd[i] = (i == 2 ? 1.0 : 0.0) + t * d[i];
    wrench wq;
    for (std::size_t i = 0; i < 6; ++i) wq[i] = q(wd[i]);  // exact: the doubles themselves
    const std::array<interval, 3> f{interval(wd[0]), interval(wd[1]), interval(wd[2])},
        tau{interval(wd[3]), interval(wd[4]), interval(wd[5])};
    const contact_verdict v = judge_sole(sole_wrench_margins<interval>(f, tau, X, Y, mu));
    const bool defined = feasible(s, wq);
    if (v == contact_verdict::holds) {
      ++holds;
      BOOST_TEST(defined, "trial " << trial << ": holds, but no corner forces make it");
    } else if (v == contact_verdict::fails) {
      ++fails;
      BOOST_TEST(!defined, "trial " << trial << ": fails, but corner forces make it");
    } else {
      ++undecided;
      // undecided only within 1e-12 (relative) of the boundary
      BOOST_TEST(std::fabs(t / tstar - 1) < 1e-12, "trial " << trial << ": undecided at " << t / tstar - 1);
    }
  }
  BOOST_TEST_MESSAGE("interval verdicts near the boundary: " << holds << " holds, " << fails << " fails, " << undecided
                                                             << " undecided");
  BOOST_TEST(holds >= 1000);
  BOOST_TEST(fails >= 1000);
}
