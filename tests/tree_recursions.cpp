// A tree's Appell equations by the recursions along the tree (system/tree.hpp: composite rigid
// bodies for M, Newton-Euler passes for b, Q and each joint's wrench) against the generic path
// (dynamics/gibbs_appell.hpp: the Jacobians of every body's velocity, differentiated on dual
// numbers, and M = sum m Jv^T Jv + Jw^T I Jw) -- two independent computations of the same numbers:
//  * random trees (branches, several roots, revolute joints about elementary and oblique axes,
//    prismatic and fixed joints, turned frames and inertia axes, efforts depending on the speeds):
//    in double the two agree to within double's precision; the interval recursion encloses the
//    generic path's value at 512 bits (MPFR), and so does the recursion in MPFI and in arb at 256 bits (componentwise and in balls),
//    for M, b, Q, the accelerations and every joint's wrench;
//  * the robots shipped (dart-doc's WAM, KR5 and Atlas, appell's arm), at random states: the same;
//  * deep chains (12 to 128 links) in balls at thin states, and over wide boxes (16 and 32 links,
//    radii 1e-9 to 1e-5): every value at the boxes' corners and random points inside contained;
//  * on Taylor series (jets: the motion's right-hand side, models/system.hpp, runs the
//    recursion on jets and slopes), every coefficient of M, b, Q by both paths agrees;
//  * constrained trees (random trees with nonholonomic constraints in q, u and t; the block and
//    arm on its sole and on a point; Atlas on both soles): Cotton's method on the recursion
//    (system/tree_constraints.hpp) against Cotton's method on the generic path: u' and the
//    reactions agree in double, the interval and MPFI recursions enclose the generic path's
//    512-bit values, and their checks (Lagrange minus Cotton, eq. (4)) hold 0;
//  * which systems take the recursion: a tree of links, not a system with quasi-velocities.
#define BOOST_TEST_MODULE tree_recursions
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "appell/derivatives/jet.hpp"
#include "appell/io/scene.hpp"
#include "appell/models/system.hpp"
#include "bounds_400.hpp"
#include "built_scalars.hpp"
#include "generated_chain.hpp"

using namespace appell;
using testing::bounds_of;
using testing::ref_t;

namespace {

std::string num(double x) {
  std::ostringstream o;  // fixed notation: the reader's decimals (no exponent)
  o.setf(std::ios::fixed);
  o.precision(12);
  o << x;
  return o.str();
}
std::string list3(double a, double b, double c) { return "[\"" + num(a) + "\", \"" + num(b) + "\", \"" + num(c) + "\"]"; }

/// A random tree of n links as a system file (SCENES.md, "links of a tree"), its state random too.
std::string random_tree(std::mt19937_64& rng, int n, int constraints = 0) {
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  std::vector<std::string> coordinates;
  std::string bodies, state;
  for (int k = 0; k < n; ++k) {
    const double pick = u01(rng);
    const std::string type = k == 0 || pick < 0.55 ? "revolute" : pick < 0.8 ? "prismatic" : "fixed";
    const std::string name = "l" + std::to_string(k);
    std::string parent;
    if (k > 0 && u01(rng) < 0.9) parent = "l" + std::to_string(std::uniform_int_distribution<int>(0, k - 1)(rng));
    // principal moments satisfying the triangle inequality, small products
    const double a = 0.02 + 0.08 * u01(rng), b = 0.02 + 0.08 * u01(rng);
    const double c = std::abs(a - b) + 0.005 + (a + b - std::abs(a - b) - 0.01) * u01(rng);
    // products of inertia or principal axes; a fixed link now and then a massless frame
    const bool products = u01(rng) < 0.7, massless = type == "fixed" && u01(rng) < 0.4;
    std::string body = "\"" + name + "\": {";
    if (!massless) {
      const double mass = 0.3 + 2 * u01(rng), xy = products ? 0.002 * sym(rng) : 0.0,
                   yz = products ? 0.002 * sym(rng) : 0.0, zx = products ? 0.002 * sym(rng) : 0.0;
      const double cx = 0.2 * sym(rng), cy = 0.2 * sym(rng), cz = 0.3 * sym(rng);
      body += "\"mass\": \"" + num(mass) + "\", \"inertia\": [\"" + num(a) + "\", \"" + num(b) + "\", \"" + num(c) +
              "\", \"" + num(xy) + "\", \"" + num(yz) + "\", \"" + num(zx) + "\"], \"inertial\": {\"xyz\": " + list3(cx, cy, cz);
      if (u01(rng) < 0.5) {
        const double r1 = sym(rng), r2 = sym(rng), r3 = sym(rng);
        body += ", \"rpy\": " + list3(r1, r2, r3);
      }
      body += "}, ";
    }
    body += "\"joint\": {\"type\": \"" + type + "\"";
    if (!parent.empty()) body += ", \"parent\": \"" + parent + "\"";
    {
      const double x = 0.3 * sym(rng), y = 0.3 * sym(rng), z = 0.4 * sym(rng);
      body += ", \"origin\": " + list3(x, y, z);
    }
    if (u01(rng) < 0.6) {
      const double r1 = 2 * sym(rng), r2 = 2 * sym(rng), r3 = 2 * sym(rng);
      body += ", \"rpy\": " + list3(r1, r2, r3);
    }
    if (type != "fixed") {
      const std::string q = "q" + std::to_string(k);
      coordinates.push_back(q);
      body += ", \"coordinate\": \"" + q + "\", \"axis\": ";
      if (u01(rng) < 0.5) {
        const int along = std::uniform_int_distribution<int>(0, 2)(rng);
        const char* v[3] = {"0", "0", "0"};
        v[along] = u01(rng) < 0.5 ? "1" : "-1";
        body += std::string("[\"") + v[0] + "\", \"" + v[1] + "\", \"" + v[2] + "\"]";
      } else {
        const double x = sym(rng), y = sym(rng), z = 0.2 + u01(rng);
        body += list3(x, y, z);
      }
      if (u01(rng) < 0.7) {
        const double e0 = sym(rng), e1 = 0.1 * u01(rng);
        body += ", \"effort\": \"" + num(e0) + " - " + num(e1) + "*" + q + "_dot\"";
      }
      const double qv = 3 * sym(rng), qd = 3 * sym(rng);
      state += std::string(state.empty() ? "" : ", ") + "\"" + q + "\": \"" + num(qv) + "\", \"" + q + "_dot\": \"" +
               num(qd) + "\"";
    }
    bodies += std::string(k ? ", " : "") + body + "}}";
  }
  std::string coords;
  for (const auto& q : coordinates) coords += std::string(coords.empty() ? "" : ", ") + "\"" + q + "\"";
  const double gx = sym(rng), gy = sym(rng), gz = -9.81 + sym(rng);
  // constraints: nonholonomic, affine in the rates, in q and t; each solves the rate of a
  // coordinate of its own (solve_speeds), so that the file's state satisfies them
  std::string more;
  constraints = std::min(constraints, static_cast<int>(coordinates.size()) - 1);
  if (constraints > 0) {
    std::string cs, solved;
    for (int c = 0; c < constraints; ++c) {
      // its own rate's coefficient in [1, 2], the other solved rates' below 0.3 (A_B diagonally
      // dominant: a full block, eliminated), every coefficient in q and t
      const std::string& own = coordinates[static_cast<std::size_t>(c)];
      std::string g = "(1.5 + 0.5*sin(" + own + " + t))*" + own + "_dot";
      for (int b = 0; b < constraints; ++b)
        if (b != c)
          g += " + " + num(0.3 * sym(rng)) + "*cos(" + coordinates[static_cast<std::size_t>(b)] + " - 2*t)*" +
               coordinates[static_cast<std::size_t>(b)] + "_dot";
      for (std::size_t j = static_cast<std::size_t>(constraints); j < coordinates.size(); ++j) {
        const std::string& q = coordinates[j];
        const std::string& other = coordinates[(j + static_cast<std::size_t>(c)) % coordinates.size()];
        g += " + " + num(sym(rng)) + "*cos(" + other + " + 0.5*t)*" + q + "_dot";
      }
      g += " - " + num(sym(rng)) + "*sin(" + own + " + t)";
      cs += std::string(c ? ", " : "") + "\"c" + std::to_string(c) + "\": {\"nonholonomic\": \"" + g + "\"}";
      solved += std::string(c ? ", " : "") + "\"" + own + "_dot\"";
      const std::string drop = "\"" + own + "_dot\": \"";  // its rate is solved, not given
      const auto at = state.find(drop);
      const auto end = state.find('"', at + drop.size());
      state.erase(at == 0 ? at : at - 2, end + 1 - (at == 0 ? at : at - 2));
      if (at == 0 && state.rfind(", ", 0) == 0) state.erase(0, 2);
    }
    more = ", \"constraints\": {" + cs + "}, \"solve_speeds\": [" + solved + "]";
  }
  return "{\"model\": \"system\", \"coordinates\": [" + coords + "], \"gravity\": " + list3(gx, gy, gz) +
         ", \"bodies\": {" + bodies + "}" + more + ", \"state\": {" + state + "}}";
}

/// What both paths give at a state: M, b, Q, u' = M^-1 (Q - b), and every joint's wrench.
template <class T>
struct both {
  appell_equations<T> eq;
  vector_t<T> udot;
  std::vector<joint_wrench_result<T>> wrenches;
};
/// The paths: the recursion as the library dispatches it (`tree`: componentwise, or in balls on a
/// deep tree for the interval scalars), the same with the joints' wrenches from the equations'
/// kept pass (`pass`: tree_pass, as system_model's evaluation takes them), the recursion in balls
/// whatever the depth (`balls`, the interval scalars), and the generic path (the Jacobians' M, b,
/// Q and joint wrenches).
enum class path { tree, pass, balls, generic };
/// One path's numbers at the state of `in` (or at q, u).
template <class T>
both<T> by_path(const system_input& in, const vector_t<double>* q, const vector_t<double>* u, path how) {
  const evaluation_scope<T> scope;
  auto m = system_model::prepare<T>(in);
  if (q) m.q = q->cast<T>(), m.u = u->cast<T>();
  both<T> r;
  const vector_t<T>* none = nullptr;
  tree_pass<T> kept;
  if (how == path::tree) tree_equations_into<T, T>(m.sys, m.q, m.u, m.t, r.eq);
  else if (how == path::pass) tree_equations_into<T, T>(m.sys, m.q, m.u, m.t, r.eq, &kept);
  else if (how == path::generic) gibbs_appell_into(expression_system<T>{&m.sys}, m.q, m.u, m.t, r.eq);
  if constexpr (scalar_traits<T>::is_interval)
    if (how == path::balls) tree_equations_in_balls(m.sys, m.q, m.u, m.t, r.eq);
  r.udot = r.eq.accelerations();
  if (how == path::tree) joint_wrenches_into(m.sys, m.q, m.u, m.t, r.udot, none, r.wrenches);
  else if (how == path::pass) {
    // kept wherever the recursion is componentwise (the interval scalars' deep trees: balls)
    bool componentwise = true;
    if constexpr (scalar_traits<T>::is_interval) componentwise = !prefer_balls(m.sys);
    BOOST_TEST((kept.system == &m.sys) == componentwise);
    if (componentwise) {  // taken at its own state only
      BOOST_TEST(pass_fits(kept, m.sys, m.q, m.u, m.t));
      vector_t<T> other = m.u;
      other(0) += T(1);
      BOOST_TEST(!pass_fits(kept, m.sys, m.q, other, m.t));
    }
    joint_wrenches_into(m.sys, m.q, m.u, m.t, r.udot, none, r.wrenches, none, &kept);
  } else if (how == path::generic) joint_wrenches_by_jacobians_into(m.sys, m.q, m.u, m.t, r.udot, none, r.wrenches);
  if constexpr (scalar_traits<T>::is_interval)
    if (how == path::balls) {
      std::vector<vec3<T>> F, M;
      std::vector<T> values;
      tree_subtree_wrenches_in_balls(m.sys, m.q, m.u, m.t, r.udot, F, M, values);
      detail::joint_wrenches_from_sums(m.sys, F, M, values, none, r.wrenches);
    }
  return r;
}
template <class T>
both<T> by_tree(const system_input& in, const vector_t<double>* q, const vector_t<double>* u) {
  return by_path<T>(in, q, u, path::tree);
}
template <class T>
both<T> by_generic(const system_input& in, const vector_t<double>* q, const vector_t<double>* u) {
  return by_path<T>(in, q, u, path::generic);
}

/// Every number of `both` in one list, named.
template <class T>
std::vector<std::pair<std::string, T>> numbers(const both<T>& x) {
  std::vector<std::pair<std::string, T>> out;
  const auto n = x.eq.b.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) out.emplace_back("M(" + std::to_string(i) + "," + std::to_string(j) + ")", x.eq.M(i, j));
    out.emplace_back("b(" + std::to_string(i) + ")", x.eq.b(i));
    out.emplace_back("Q(" + std::to_string(i) + ")", x.eq.Q(i));
    out.emplace_back("udot(" + std::to_string(i) + ")", x.udot(i));
  }
  for (std::size_t k = 0; k < x.wrenches.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      out.emplace_back("force" + std::to_string(k) + "_" + std::to_string(i), x.wrenches[k].force(i));
      out.emplace_back("moment" + std::to_string(k) + "_" + std::to_string(i), x.wrenches[k].moment(i));
    }
  return out;
}

/// The checks of one system at one state; returns the largest width of the interval recursion
/// relative to the magnitude of the number (for the message).
double check_state(const system_input& in, const std::string& what, const vector_t<double>* q = nullptr,
                   const vector_t<double>* u = nullptr) {
  const auto td = numbers(by_tree<double>(in, q, u)), gd = numbers(by_generic<double>(in, q, u));
  const auto pd = numbers(by_path<double>(in, q, u, path::pass));
  BOOST_REQUIRE(td.size() == gd.size());
  BOOST_REQUIRE(pd.size() == gd.size());
  double scale = 1;
  for (const auto& [name, x] : gd) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < td.size(); ++i) {
    BOOST_TEST(std::abs(td[i].second - gd[i].second) <= 1e-11 * scale,
               what << ": " << td[i].first << " tree " << td[i].second << ", generic " << gd[i].second);
    BOOST_TEST(std::abs(pd[i].second - gd[i].second) <= 1e-11 * scale,
               what << ": " << pd[i].first << " tree from the kept pass " << pd[i].second << ", generic " << gd[i].second);
  }
  // the truth at 512 bits (its own rounding far below the 256-bit enclosures' widths)
  const auto truth = [&] {
    const mp_precision_scope high(512);
    return numbers(by_generic<mpfr>(in, q, u));
  }();
  const mp_precision_scope precision(256);
  const auto ti = numbers(by_tree<interval>(in, q, u));
  const auto gi = numbers(by_generic<interval>(in, q, u));
  const auto tm = numbers(by_tree<mpfi>(in, q, u));
  const auto kept_i = numbers(by_path<interval>(in, q, u, path::pass));
  const auto kept_m = numbers(by_path<mpfi>(in, q, u, path::pass));
  const auto bi = numbers(by_path<interval>(in, q, u, path::balls));
  const auto bm = numbers(by_path<mpfi>(in, q, u, path::balls));
  // arb where this build compiled it (the quick tier leaves it to scripts/test.sh --full)
  std::vector<std::pair<std::string, arb>> ta, ba;
#if APPELL_TEST_HAS(arb)
  ta = numbers(by_tree<arb>(in, q, u));
  ba = numbers(by_path<arb>(in, q, u, path::balls));
  BOOST_REQUIRE(ta.size() == truth.size() && ba.size() == truth.size());
#endif
  double widest = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const ref_t x = bounds_of(truth[i].second).first;
    const auto [lo, hi] = bounds_of(ti[i].second);
    BOOST_TEST((lo <= x && x <= hi), what << ": " << ti[i].first << " = " << x << " outside [" << lo << ", " << hi << "]");
    widest = std::max(widest, double(hi - lo) / std::max(1.0, std::abs(double(x))));
    const auto [blo, bhi] = bounds_of(bi[i].second);
    BOOST_TEST((blo <= x && x <= bhi), what << ": " << bi[i].first << " (balls) = " << x << " outside [" << blo << ", " << bhi << "]");
    if (std::getenv("TREE_WIDTHS") && ti[i].first.rfind("udot", 0) == 0) {
      const auto [glo, ghi] = bounds_of(gi[i].second);
      BOOST_TEST_MESSAGE(what << " " << ti[i].first << " width: recursion " << double(hi - lo) << ", balls "
                              << double(bhi - blo) << ", Jacobians " << double(ghi - glo));
    }
    const auto kept_contains = [&](const auto& p, const char* scalar) {  // the wrenches from the kept pass
      const auto [plo, phi] = bounds_of(p[i].second);
      BOOST_TEST((plo <= x && x <= phi), what << ": " << p[i].first << " (kept pass, " << scalar << ") = " << x
                                              << " outside [" << plo << ", " << phi << "]");
    };
    kept_contains(kept_i, "interval");
    kept_contains(kept_m, "mpfi");
    const auto [pmlo, pmhi] = bounds_of(kept_m[i].second);
    BOOST_TEST(double(pmhi - pmlo) <= 1e-60 * std::max(1.0, std::abs(double(x))), what << ": " << kept_m[i].first << " (mpfi, kept pass) wide");
    const auto [bmlo, bmhi] = bounds_of(bm[i].second);
    BOOST_TEST((bmlo <= x && x <= bmhi), what << ": " << bm[i].first << " (mpfi balls) outside");
    BOOST_TEST(double(bmhi - bmlo) <= 1e-60 * std::max(1.0, std::abs(double(x))), what << ": " << bm[i].first << " (mpfi balls) wide");
    const auto [mlo, mhi] = bounds_of(tm[i].second);
    BOOST_TEST((mlo <= x && x <= mhi), what << ": " << tm[i].first << " (mpfi) " << std::setprecision(80) << x << " outside [" << mlo << ", " << mhi << "]");
    BOOST_TEST(double(mhi - mlo) <= 1e-60 * std::max(1.0, std::abs(double(x))), what << ": " << tm[i].first << " (mpfi) wide");
#if APPELL_TEST_HAS(arb)
    for (const auto* a : {&ta, &ba}) {
      const auto [alo, ahi] = bounds_of((*a)[i].second);
      const char* kind = a == &ta ? "arb" : "arb balls";
      BOOST_TEST((alo <= x && x <= ahi), what << ": " << (*a)[i].first << " (" << kind << ") outside [" << alo << ", " << ahi << "]");
      BOOST_TEST(double(ahi - alo) <= 1e-60 * std::max(1.0, std::abs(double(x))), what << ": " << (*a)[i].first << " (" << kind << ") wide");
    }
#endif
  }
  return widest;
}

/// A constrained tree at (q, u_F): u' and the reactions by Cotton's method on the recursion
/// (system/tree_constraints.hpp) or by the generic path's (cotton_reactions on the Jacobians'
/// equations), the free columns given (the same for every scalar), the bound speeds solved.
/// On the recursion also the checks eval prints: Lagrange's multipliers minus Cotton's
/// reactions and eq. (4)'s residual, named "check ...".
template <class T>
std::vector<std::pair<std::string, T>> constrained_numbers(const system_input& in, const vector_t<double>& q,
                                                           const vector_t<double>& u, const std::vector<int>& free,
                                                           const std::vector<int>& bound, bool tree) {
  const evaluation_scope<T> scope;
  auto m = system_model::prepare<T>(in);
  const int n = static_cast<int>(u.size()), k = static_cast<int>(free.size());
  const vector_t<T> qT = q.cast<T>();
  vector_t<T> v = vector_t<T>::Zero(n), full;
  for (int i = 0; i < k; ++i) v(i) = T(u(free[static_cast<std::size_t>(i)]));
  const expression_constraints<T> con{&m.sys};
  const adapted_change<expression_constraints<T>> change{con, free, bound};
  change.template apply_into<T>(qT, v, m.t, full);
  std::vector<std::pair<std::string, T>> out;
  vector_t<T> udot, reactions;
  if (tree) {
    tree_cotton_result<T> tc;
    tree_cotton_into<T, T>(m.sys, free, bound, qT, full, m.t, {true, true}, udot, tc);
    reactions = tc.reactions;
    constrained_motion<T> lagrange;
    lagrange_multipliers_with_into(tc.equations, expression_system<T>{&m.sys}, con, qT, full, m.t, lagrange);
    for (Eigen::Index i = 0; i < reactions.size(); ++i)
      out.emplace_back("check lagrange - cotton " + std::to_string(i), T(lagrange.reactions(i) - reactions(i)));
    out.emplace_back("check eq. (4)", virtual_work_residual(expression_system<T>{&m.sys}, tc.equations, qT, full, m.t, udot,
                                                            tc.unit_displacement));
  } else {
    const constrained_motion<T> c = cotton_reactions(expression_system<T>{&m.sys}, change, qT, full, m.t);
    udot = c.accelerations;
    reactions = c.reactions;
  }
  for (int i = 0; i < n; ++i) out.emplace_back("udot(" + std::to_string(i) + ")", udot(i));
  for (Eigen::Index i = 0; i < reactions.size(); ++i) out.emplace_back("reaction(" + std::to_string(i) + ")", reactions(i));
  return out;
}

/// The checks of one constrained tree at one state (the free columns chosen in double, as
/// adapt_speeds chooses them): the two paths agree in double; the interval and MPFI (256 bits)
/// recursions enclose the generic path's 512-bit values, and their checks hold 0.  Returns the
/// widest relative width in interval.
double check_constrained_state(const system_input& in, const std::string& what, const vector_t<double>& q,
                               const vector_t<double>& u) {
  std::vector<int> free, bound;
  {
    const auto m = system_model::prepare<double>(in);
    BOOST_REQUIRE(tree_constraints_apply(m.sys));
    const expression_constraints<double> con{&m.sys};
    const auto change = adapt_speeds<double>(con, q, m.t, static_cast<int>(u.size()));
    free = change.free_columns;
    bound = change.bound_columns;
  }
  const auto td = constrained_numbers<double>(in, q, u, free, bound, true);
  const auto gd = constrained_numbers<double>(in, q, u, free, bound, false);
  const std::size_t checks = td.size() - gd.size();
  double scale = 1;
  for (const auto& [name, x] : gd) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < gd.size(); ++i)
    BOOST_TEST(std::abs(td[checks + i].second - gd[i].second) <= 1e-10 * scale,
               what << ": " << gd[i].first << " tree " << td[checks + i].second << ", generic " << gd[i].second);
  const auto truth = [&] {
    const mp_precision_scope high(512);
    return constrained_numbers<mpfr>(in, q, u, free, bound, false);
  }();
  const mp_precision_scope precision(256);
  const auto ti = constrained_numbers<interval>(in, q, u, free, bound, true);
  const auto tm = constrained_numbers<mpfi>(in, q, u, free, bound, true);
  if (std::getenv("TREE_WIDTHS")) {  // the generic path's interval widths beside the recursion's
    const auto gi = constrained_numbers<interval>(in, q, u, free, bound, false);
    for (std::size_t i = 0; i < gi.size(); ++i) {
      const auto [glo, ghi] = bounds_of(gi[i].second);
      const auto [lo, hi] = bounds_of(ti[checks + i].second);
      BOOST_TEST_MESSAGE(what << " " << gi[i].first << " = " << double(glo) << " width: recursion " << double(hi - lo)
                              << ", Jacobians " << double(ghi - glo));
    }
  }
  double widest = 0;
  auto hold_zero = [&](const auto& x, const char* kind) {
    for (std::size_t i = 0; i < checks; ++i) {
      const auto [lo, hi] = bounds_of(x[i].second);
      BOOST_TEST((lo <= 0 && 0 <= hi), what << ": " << x[i].first << " (" << kind << ") [" << lo << ", " << hi << "] does not hold 0");
    }
  };
  hold_zero(ti, "interval");
  hold_zero(tm, "mpfi");
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const ref_t x = bounds_of(truth[i].second).first;
    const auto [lo, hi] = bounds_of(ti[checks + i].second);
    BOOST_TEST((lo <= x && x <= hi), what << ": " << truth[i].first << " = " << x << " outside [" << lo << ", " << hi << "]");
    widest = std::max(widest, double(hi - lo) / std::max(1.0, std::abs(double(x))));
    const auto [mlo, mhi] = bounds_of(tm[checks + i].second);
    BOOST_TEST((mlo <= x && x <= mhi), what << ": " << truth[i].first << " (mpfi) " << std::setprecision(80) << x << " outside [" << mlo << ", " << mhi << "]");
    BOOST_TEST(double(mhi - mlo) <= 1e-50 * std::max(1.0, std::abs(double(x))), what << ": " << truth[i].first << " (mpfi) wide");
  }
  return widest;
}

}  // namespace

BOOST_AUTO_TEST_CASE(constrained_trees_by_cotton_on_the_recursion_agree_with_the_generic_path) {
  // random trees with one to three nonholonomic constraints, their rows in q and t (the solved
  // rates' block a full matrix), their right-hand sides in q and t
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
  int trees = 0;
  for (int t = 0; t < 24; ++t) {
    const int n = 4 + t % 6, s = 1 + t % 3;
    const scene_input scene = read_scene(parse_json(random_tree(rng, n, s)));
    const auto& in = scene.as<system_input>();
    const auto m = system_model::prepare<double>(in);
    if (m.q.size() < s + 1) continue;  // fixed links drawn: too few coordinates
    vector_t<double> q(m.q.size()), u(m.u.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = angle(rng), u(i) = rate(rng);
    const double w = check_constrained_state(in, "tree " + std::to_string(t) + " (" + std::to_string(s) + " constraints)", q, u);
    BOOST_TEST_MESSAGE("constrained tree " << t << ": " << q.size() << " coordinates, " << s << " constraints, widest relative width in interval " << w);
    ++trees;
  }
  BOOST_TEST(trees >= 15);
  // robots held by the ground: a block and arm on its sole (6 rows) and on a point of its corner
  // (3 rows), Atlas on both soles (12 rows of 33 speeds)
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string point_scene = dir + "/appell_point_contact_" + std::to_string(::getpid()) + ".json";
  std::ofstream(point_scene)
      << "{\"model\": \"urdf\", \"file\": \"" << APPELL_SOURCE_DIR << "/data/urdf/block_arm.urdf\", \"base\": \"floating\","
         " \"gravity\": [\"0\", \"0\", \"-9.81\"], \"torques\": {\"hinge\": \"3 - 2*t\"}, \"state\": {"
         "\"base_x\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_y\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_z\": {\"q\": \"0\", \"q_dot\": \"0\"},"
         " \"base_yaw\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_pitch\": {\"q\": \"0\", \"q_dot\": \"0\"}, \"base_roll\": {\"q\": \"0\", \"q_dot\": \"0\"},"
         " \"hinge\": {\"q\": \"0\", \"q_dot\": \"0\"}},"
         " \"contacts\": {\"corner\": {\"link\": \"block\", \"type\": \"point\", \"point\": [\"0.1\", \"-0.08\", \"0\"], \"mu\": \"0.5\"}}}";
  for (const std::string& file : {APPELL_SOURCE_DIR + "/data/scenes/urdf_block_arm_push.json", point_scene,
                                  APPELL_SOURCE_DIR + "/data/scenes/urdf_atlas_standing.json"}) {
    const scene_input scene = read_scene_file(file);
    const auto& in = scene.as<system_input>();
    const auto m = system_model::prepare<double>(in);
    const bool atlas = file.find("atlas") != std::string::npos;
    const int states = atlas ? 3 : 8;
    double widest = 0;
    for (int k = 0; k < states; ++k) {
      // the base within half a radian of upright (its pitch far from the refused singularity)
      vector_t<double> q(m.q.size()), u(m.u.size());
      for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = (i < 6 ? 0.5 : 1.0) * angle(rng) / 3, u(i) = rate(rng);
      widest = std::max(widest, check_constrained_state(in, file + " state " + std::to_string(k), q, u));
    }
    BOOST_TEST_MESSAGE(file << ": " << m.sys.constraints.size() << " constraints, widest relative width in interval " << widest);
  }
  std::filesystem::remove(point_scene);
}

BOOST_AUTO_TEST_CASE(random_trees_by_recursion_agree_with_the_generic_path) {
  std::mt19937_64 rng(20261204);
  int trees = 0, prismatic = 0, fixed = 0, branched = 0;
  for (int t = 0; t < 40; ++t) {
    const int n = 2 + t % 8;
    const std::string text = random_tree(rng, n);
    const scene_input scene = read_scene(parse_json(text));
    const auto& in = scene.as<system_input>();
    {
      const auto m = system_model::prepare<double>(in);
      BOOST_REQUIRE(tree_recursions_apply(m.sys));
      BOOST_REQUIRE(tree_accelerations_apply(m.sys));  // joint_wrenches_into takes the recursion
      std::vector<int> children(m.sys.links.size(), 0);
      for (const auto& L : m.sys.links) {
        prismatic += L.type == system_joint_definition::kind::prismatic;
        fixed += L.type == system_joint_definition::kind::fixed;
        if (L.parent >= 0) ++children[static_cast<std::size_t>(m.sys.link_of[static_cast<std::size_t>(L.parent)])];
      }
      branched += *std::max_element(children.begin(), children.end()) > 1;
    }
    const double w = check_state(in, "tree " + std::to_string(t) + " (" + std::to_string(n) + " links)");
    BOOST_TEST_MESSAGE("tree " << t << ": " << n << " links, widest relative width in interval " << w);
    ++trees;
  }
  BOOST_TEST(trees == 40);
  // the trees drawn hold every kind of joint and branches
  BOOST_TEST(prismatic > 10);
  BOOST_TEST(fixed > 5);
  BOOST_TEST(branched > 10);
}

BOOST_AUTO_TEST_CASE(the_robots_by_recursion_agree_with_the_generic_path) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
  for (const char* file : {"urdf_appell_arm.json", "urdf_wam.json", "urdf_kr5.json", "urdf_atlas.json"}) {
    const scene_input scene = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/" + file);
    const auto& in = scene.as<system_input>();
    const auto m = system_model::prepare<double>(in);
    BOOST_REQUIRE(tree_recursions_apply(m.sys));
    BOOST_REQUIRE(tree_accelerations_apply(m.sys));
    // depth 5 to 9: the componentwise enclosures, 2.7 to 6.7 times tighter here than balls
    // (TREE_WIDTHS=1 prints both), serve them
    BOOST_TEST(!prefer_balls(m.sys), file << ": depth " << tree_depth(m.sys));
    const int states = std::string(file) == "urdf_atlas.json" ? 3 : 8;
    double widest = 0;
    for (int s = 0; s < states; ++s) {
      vector_t<double> q(m.q.size()), u(m.u.size());
      for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = angle(rng), u(i) = rate(rng);
      widest = std::max(widest, check_state(in, std::string(file) + " state " + std::to_string(s), &q, &u));
    }
    BOOST_TEST_MESSAGE(file << ": widest relative width in interval " << widest);
  }
}

BOOST_AUTO_TEST_CASE(deep_chains_are_certified_in_balls) {
  // The componentwise interval recursion widens by a factor per link (wrapping) and cannot prove
  // the 48-link chain's mass matrix nonsingular; in balls the widths grow with the depth, not
  // geometrically.  Chains of 12 to 128 links at random states: interval (the library's dispatch:
  // balls from tree_balls_depth on), MPFI and arb at 256 bits enclose the recursion's value at 512
  // bits (MPFR, the point recursion that the tests above hold to the generic path), and the
  // interval accelerations are certified within the relative width stated in docs/benchmarks.md.
  std::mt19937_64 rng(128);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
  for (int n : {12, 24, 48, 96, 128}) {
    const scene_input scene = read_scene_file(testing::generated_chain_scene(n, "appell_test_chain"));
    const auto& in = scene.as<system_input>();
    const auto m = system_model::prepare<double>(in);
    BOOST_REQUIRE(tree_depth(m.sys) == n);
    BOOST_REQUIRE(prefer_balls(m.sys));
    for (int s = 0; s < 2; ++s) {
      vector_t<double> q(n), u(n);
      for (int i = 0; i < n; ++i) q(i) = angle(rng), u(i) = rate(rng);
      const auto truth = [&] {
        const mp_precision_scope high(512);
        return numbers(by_tree<mpfr>(in, &q, &u));
      }();
      const auto ti = numbers(by_tree<interval>(in, &q, &u));
      const mp_precision_scope precision(256);
      const auto tm = numbers(by_tree<mpfi>(in, &q, &u));
      std::vector<std::pair<std::string, arb>> ta;  // arb where this build compiled it
#if APPELL_TEST_HAS(arb)
      ta = numbers(by_tree<arb>(in, &q, &u));
      BOOST_REQUIRE(ta.size() == truth.size());
#endif
      BOOST_REQUIRE(ti.size() == truth.size());
      double widest = 0;
      for (std::size_t i = 0; i < truth.size(); ++i) {
        const ref_t x = bounds_of(truth[i].second).first;
        const auto [lo, hi] = bounds_of(ti[i].second);
        BOOST_TEST((lo <= x && x <= hi), n << " links: " << ti[i].first << " = " << x << " outside [" << lo << ", " << hi << "]");
        const auto [mlo, mhi] = bounds_of(tm[i].second);
        BOOST_TEST((mlo <= x && x <= mhi), n << " links: " << tm[i].first << " (mpfi) outside");
#if APPELL_TEST_HAS(arb)
        const auto [alo, ahi] = bounds_of(ta[i].second);
        BOOST_TEST((alo <= x && x <= ahi), n << " links: " << ta[i].first << " (arb) outside");
#endif
        if (truth[i].first.rfind("udot", 0) == 0)
          widest = std::max(widest, double(hi - lo) / std::max(1.0, std::abs(double(x))));
      }
      double wM = 0, wb = 0, scaleM = 0, scaleb = 1;
      for (std::size_t i = 0; i < truth.size(); ++i) {
        const double x = std::abs(double(bounds_of(truth[i].second).first));
        const auto [lo, hi] = bounds_of(ti[i].second);
        if (truth[i].first[0] == 'M') scaleM = std::max(scaleM, x), wM = std::max(wM, double(hi - lo));
        if (truth[i].first[0] == 'b' || truth[i].first[0] == 'Q') scaleb = std::max(scaleb, x), wb = std::max(wb, double(hi - lo));
      }
      if (std::getenv("TREE_WIDTHS")) {
        Eigen::MatrixXd Md(n, n);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) Md(i, j) = double(bounds_of(truth[static_cast<std::size_t>(i * (n + 3) + j)].second).first);
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Md);
        BOOST_TEST_MESSAGE(n << " links: M widest " << wM / scaleM << " of max|M|, b and Q " << wb / scaleb
                              << ", cond(M) " << svd.singularValues()(0) / svd.singularValues()(n - 1));
      }
      BOOST_TEST_MESSAGE(n << " links, state " << s << ": widest relative width of the accelerations " << widest);
      BOOST_TEST(widest <= 1e-3, n << " links: accelerations " << widest << " wide");
    }
  }
}

BOOST_AUTO_TEST_CASE(balls_over_wide_boxes_hold_every_state_inside) {
  // The balls above are checked at states given as decimals (thin inputs); enclose evaluates the
  // results over a step's whole box.  Chains of 16 and 32 links, boxes of radii 1e-9 to 1e-5
  // around random states: M, b, Q, u' and every joint's wrench in balls (`interval`) contain the
  // 512-bit recursion's values at the box's two extreme corners and at random points inside.
  std::mt19937_64 rng(5702);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2), u01(0, 1);
  long checked = 0, boxes = 0, refused = 0;
  for (int n : {16, 32}) {
    const scene_input scene = read_scene_file(testing::generated_chain_scene(n, "appell_test_box_chain"));
    const auto& in = scene.as<system_input>();
    for (int s = 0; s < 6; ++s) {
      const double r = std::pow(10.0, -9 + 4 * u01(rng));
      vector_t<double> lo(2 * n), hi(2 * n);
      for (int i = 0; i < 2 * n; ++i) {
        const double c = i < n ? angle(rng) : rate(rng);
        lo(i) = c - r * u01(rng);
        hi(i) = c + r * u01(rng);
      }
      both<interval> box;
      try {
        const evaluation_scope<interval> scope;
        auto m = system_model::prepare<interval>(in);
        for (int i = 0; i < n; ++i) m.q(i) = interval(lo(i), hi(i)), m.u(i) = interval(lo(n + i), hi(n + i));
        tree_equations_in_balls(m.sys, m.q, m.u, m.t, box.eq);
        box.udot = box.eq.accelerations();
        std::vector<vec3<interval>> F, M;
        std::vector<interval> values;
        const vector_t<interval>* none = nullptr;
        tree_subtree_wrenches_in_balls(m.sys, m.q, m.u, m.t, box.udot, F, M, values);
        detail::joint_wrenches_from_sums(m.sys, F, M, values, none, box.wrenches);
      } catch (const certification_error&) {
        ++refused;  // M over the box not proved nonsingular: nothing claimed
        continue;
      }
      ++boxes;
      const auto enclosed = numbers(box);
      for (int p = 0; p < 4; ++p) {
        vector_t<double> q(n), u(n);
        for (int i = 0; i < 2 * n; ++i) {
          const double x = p == 0 ? lo(i) : p == 1 ? hi(i) : lo(i) + (hi(i) - lo(i)) * u01(rng);
          (i < n ? q(i) : u(i - n)) = std::min(std::max(x, lo(i)), hi(i));
        }
        const auto truth = [&] {
          const mp_precision_scope high(512);
          return numbers(by_tree<mpfr>(in, &q, &u));
        }();
        BOOST_REQUIRE(truth.size() == enclosed.size());
        for (std::size_t i = 0; i < truth.size(); ++i) {
          const ref_t x = bounds_of(truth[i].second).first;
          const auto [blo, bhi] = bounds_of(enclosed[i].second);
          BOOST_TEST((blo <= x && x <= bhi), n << " links, box radius " << r << ", point " << p << ": " << truth[i].first
                                                 << " = " << x << " outside [" << blo << ", " << bhi << "]");
          ++checked;
        }
      }
    }
  }
  BOOST_TEST_MESSAGE("balls over boxes: " << boxes << " boxes certified, " << refused << " refused, " << checked
                                          << " values at points inside checked");
  BOOST_TEST(boxes >= 8);
  BOOST_TEST(checked > 10000);
}

BOOST_AUTO_TEST_CASE(the_recursion_on_taylor_series_agrees_with_the_generic_path) {
  // q(t), u(t) polynomials of degree 5; both paths' M, b, Q as series to order 5
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> sym(-1, 1);
  const jet_order_scope order(5);
  for (int t = 0; t < 10; ++t) {
    const scene_input scene = read_scene(parse_json(random_tree(rng, 3 + t % 5)));
    const auto m = system_model::prepare<double>(scene.as<system_input>());
    using J = jet<double>;
    vector_t<J> q(m.q.size()), u(m.u.size());
    auto series = [&](double v) {
      std::vector<double> c{v};
      for (int k = 1; k <= 5; ++k) c.push_back(sym(rng) / k);
      return J(c);
    };
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = series(m.q(i)), u(i) = series(m.u(i));
    appell_equations<J> tree, generic;
    tree_equations_into<double, J>(m.sys, q, u, J(0.0), tree);
    gibbs_appell_into(expression_system<double>{&m.sys}, q, u, J(0.0), generic);
    const Eigen::Index n = q.size();
    int compared = 0;
    for (int k = 0; k <= 5; ++k) {
      double scale = 1;
      for (Eigen::Index i = 0; i < n; ++i) {
        scale = std::max({scale, std::abs(generic.b(i)[k]), std::abs(generic.Q(i)[k])});
        for (Eigen::Index j = 0; j < n; ++j) scale = std::max(scale, std::abs(generic.M(i, j)[k]));
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        BOOST_TEST(std::abs(tree.b(i)[k] - generic.b(i)[k]) <= 1e-10 * scale, "tree " << t << " b(" << i << ") order " << k);
        BOOST_TEST(std::abs(tree.Q(i)[k] - generic.Q(i)[k]) <= 1e-10 * scale, "tree " << t << " Q(" << i << ") order " << k);
        for (Eigen::Index j = 0; j < n; ++j)
          BOOST_TEST(std::abs(tree.M(i, j)[k] - generic.M(i, j)[k]) <= 1e-10 * scale,
                     "tree " << t << " M(" << i << "," << j << ") order " << k);
        ++compared;
      }
    }
    BOOST_TEST(compared == 6 * n);
  }
}

BOOST_AUTO_TEST_CASE(the_recursion_serves_trees_of_links_only) {
  // constraints on a tree's coordinate: the generic path (Cotton's method) serves it
  const std::string constrained =
      "{\"model\": \"system\", \"coordinates\": [\"a\", \"b\"], \"gravity\": [\"0\", \"0\", \"-9.81\"], \"bodies\": {"
      "\"l0\": {\"mass\": \"1\", \"inertia\": [\"0.1\", \"0.1\", \"0.1\", \"0\", \"0\", \"0\"], \"inertial\": {\"xyz\": [\"0.1\", \"0\", \"0\"]},"
      " \"joint\": {\"type\": \"revolute\", \"coordinate\": \"a\", \"axis\": [\"0\", \"0\", \"1\"]}},"
      "\"l1\": {\"mass\": \"1\", \"inertia\": [\"0.1\", \"0.1\", \"0.1\", \"0\", \"0\", \"0\"], \"inertial\": {\"xyz\": [\"0.1\", \"0\", \"0\"]},"
      " \"joint\": {\"type\": \"revolute\", \"parent\": \"l0\", \"coordinate\": \"b\", \"axis\": [\"0\", \"1\", \"0\"]}}},"
      " \"constraints\": {\"tied\": {\"holonomic\": \"a - b\"}},"
      " \"state\": {\"a\": \"0.2\", \"b\": \"0.2\", \"a_dot\": \"0.3\", \"b_dot\": \"0.3\"}}";
  const scene_input c = read_scene(parse_json(constrained));
  BOOST_TEST(!tree_recursions_apply(system_model::prepare<double>(c.as<system_input>()).sys));
  // ... Cotton's method on the recursion does (system/tree_constraints.hpp)
  BOOST_TEST(tree_constraints_apply(system_model::prepare<double>(c.as<system_input>()).sys));
  // a system without links
  const scene_input e = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/system_euler_body.json");
  BOOST_TEST(!tree_recursions_apply(system_model::prepare<double>(e.as<system_input>()).sys));
}
