// The heavy top on its pivot (model heavy_top) in all seven scalars against
// independent references written by hand (tests/independent/top_on_pivot.hpp), in MPFR at
// 532 bits:
//   - the accelerations from Lagrange's equations of the symmetric top
//     (T = A/2 (theta'^2 + psi'^2 sin^2) + C/2 r^2, r = phi' + psi' cos theta,
//     V = m g l cos theta, A about O):
//       A theta'' = A psi'^2 s c - C r psi' s + m g l s,
//       psi'' = (C r theta' - 2 A psi' theta' c) / (A s),   phi'' = -psi'' c + psi' theta' s  (r' = 0);
//   - the pivot force by Newton-Euler: F = m a_G + m g e3, a_G = l (omega' x e_z
//     + omega x (omega x e_z)), omega = psi' e3 + theta' n + phi' e_z,
//     omega' = psi'' e3 + theta'' n + theta' psi' e3 x n + phi'' e_z + phi' omega x e_z.
// The library uses none of it: it differentiates the free top's kinematics and
// applies Cotton's method with the pivot as three speeds (and, as its own
// check, Lagrange's multipliers on the free top on fixed axes).  A third route:
// the same top as a `system` file, a free body with the pivot as three
// holonomic constraints and the wrench "pivot" at O (Lagrange's multipliers,
// then the wrench's normal equations): the same force.
#define BOOST_TEST_MODULE heavy_top
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "independent/top_on_pivot.hpp"
#include "appell/models/heavy_top.hpp"
#include "appell/models/system.hpp"

using namespace appell;
using ref_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<160>, boost::multiprecision::et_off>;

namespace {

using reference = independent::top_on_pivot_reference<ref_t>;

ref_t d(const decimal_field& x) { return ref_t(x.text); }

template <class T>
std::pair<ref_t, ref_t> bounds(const T& x) {
  return {ref_t(lower_string(x)), ref_t(upper_string(x))};
}
template <class T>
ref_t width_of(const T& x) {
  const auto [lo, hi] = bounds(x);
  return hi - lo;
}
template <class T>
bool meet(const T& x, const T& y) {
  const auto [xl, xh] = bounds(x);
  const auto [yl, yh] = bounds(y);
  return xl <= yh && yl <= xh;
}

reference closed_form(const heavy_top_input& in) {
  return independent::top_on_pivot_by_hand(d(in.A), d(in.C), d(in.mass), d(in.l), d(in.gravity), d(in.psi), d(in.theta),
                                           d(in.psi_dot), d(in.theta_dot), d(in.phi_dot));
}

std::string decimal(std::mt19937_64& rng, double lo, double hi, int digits = 6) {
  const double x = std::uniform_real_distribution<double>(lo, hi)(rng);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

struct top_case {
  std::string A, C, m, l, g, psi, theta, phi, psi_dot, theta_dot, phi_dot;
};

std::string heavy_top_json(const top_case& k) {
  return "{\"model\": \"heavy_top\", \"top\": {\"A\": \"" + k.A + "\", \"C\": \"" + k.C + "\", \"mass\": \"" + k.m +
         "\", \"l\": \"" + k.l + "\"}, \"gravity\": \"" + k.g + "\", \"state\": {\"psi\": \"" + k.psi +
         "\", \"theta\": \"" + k.theta + "\", \"phi\": \"" + k.phi + "\", \"psi_dot\": \"" + k.psi_dot +
         "\", \"theta_dot\": \"" + k.theta_dot + "\", \"phi_dot\": \"" + k.phi_dot + "\"}}";
}

/// The same top as a system file: a free body, the pivot as three holonomic
/// constraints, x, y, z given to 100 digits and their rates from solve_speeds.
std::string system_json(const top_case& k) {
  const ref_t l(k.l), th(k.theta), ps(k.psi);
  auto text = [](const ref_t& x) { return x.str(100, std::ios_base::scientific); };
  const std::string x = text(l * sin(th) * sin(ps)), y = text(-l * sin(th) * cos(ps)), z = text(l * cos(th));
  return "{\"model\": \"system\", \"parameters\": {\"A\": \"" + k.A + "\", \"C\": \"" + k.C + "\", \"m\": \"" + k.m +
         "\", \"l\": \"" + k.l + "\", \"g\": \"" + k.g +
         "\"}, \"coordinates\": [\"x\", \"y\", \"z\", \"psi\", \"theta\", \"phi\"], \"gravity\": [\"0\", \"0\", \"-g\"],"
         " \"bodies\": {\"top\": {\"mass\": \"m\", \"inertia\": [\"A - m*l^2\", \"A - m*l^2\", \"C\"],"
         " \"center\": [\"x\", \"y\", \"z\"], \"orientation\": \"rz(psi) rx(theta) rz(phi)\"}},"
         " \"constraints\": {\"pivot_x\": {\"holonomic\": \"x - l*sin(theta)*sin(psi)\"},"
         " \"pivot_y\": {\"holonomic\": \"y + l*sin(theta)*cos(psi)\"},"
         " \"pivot_z\": {\"holonomic\": \"z - l*cos(theta)\"}},"
         " \"wrenches\": {\"pivot\": {\"body\": \"top\", \"point\": [\"0\", \"0\", \"0\"],"
         " \"constraints\": [\"pivot_x\", \"pivot_y\", \"pivot_z\"]}},"
         " \"solve_speeds\": [\"x_dot\", \"y_dot\", \"z_dot\"],"
         " \"state\": {\"x\": \"" + x + "\", \"y\": \"" + y + "\", \"z\": \"" + z + "\", \"psi\": \"" + k.psi +
         "\", \"theta\": \"" + k.theta + "\", \"phi\": \"" + k.phi + "\", \"psi_dot\": \"" + k.psi_dot +
         "\", \"theta_dot\": \"" + k.theta_dot + "\", \"phi_dot\": \"" + k.phi_dot + "\"}}";
}

std::vector<top_case> cases() {
  std::vector<top_case> out;
  std::mt19937_64 rng(13);
  for (int i = 0; i < 120; ++i) {
    top_case k;
    k.m = decimal(rng, 0.5, 2.0);
    k.l = decimal(rng, -0.2, 0.2);  // G above (l > 0) or below (l < 0) the pivot
    do {
      k.A = decimal(rng, 0.01, 0.2);
      k.C = decimal(rng, 0.001, 0.2);
    } while (decimal_sign_of_polynomial({{1, {k.A}}, {-1, {k.m, k.l, k.l}}}) < 0 ||
             decimal_sign_of_polynomial({{2, {k.A}}, {-2, {k.m, k.l, k.l}}, {-1, {k.C}}}) < 0);
    k.g = "9.81";
    k.psi = decimal(rng, -3.2, 3.2);
    k.theta = decimal(rng, 0.2, 2.9);
    k.phi = decimal(rng, -3.2, 3.2);
    k.psi_dot = decimal(rng, -5, 5);
    k.theta_dot = decimal(rng, -5, 5);
    k.phi_dot = decimal(rng, -60, 60);
    out.push_back(k);
  }
  return out;
}

std::vector<scene_input> scenes() {
  std::vector<scene_input> out;
  out.push_back(read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/heavy_top.json"));
  for (const top_case& k : cases()) out.push_back(read_scene(parse_json(heavy_top_json(k))));
  return out;
}

template <class T>
void compare(const char* what, const T& x, const ref_t& ref, const ref_t& scale, long& n) {
  if constexpr (scalar_traits<T>::is_interval) {
    mpfr_value v(600);
    mpfr_set(v, ref.backend().data(), MPFR_RNDN);
    BOOST_REQUIRE_MESSAGE(contains(x, v), scalar_traits<T>::name << " " << what << " " << to_string(x)
                                                                  << " misses " << ref.str(30));
  } else {
    const double eps = std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits()));
    const ref_t err = abs(ref_t(to_decimal(x)) - ref);
    // 256 roundings' worth of the largest term: a forward bound for this short computation.
    BOOST_REQUIRE_MESSAGE(err <= ref_t(256 * eps) * scale,
                          scalar_traits<T>::name << " " << what << " error " << err.str(5) << " > 256 eps * "
                                                 << scale.str(5));
  }
  ++n;
}

double worst_point = 0;  // largest point-type error, in eps * scale
double widest = 0;       // largest interval width, in eps * scale

template <class T>
long check_all() {
  long n = 0;
  for (const scene_input& scene : scenes()) {
    const reference R = closed_form(scene.as<heavy_top_input>());
    const evaluation<T> e = evaluate<T>(scene);
    const T values[6] = {e.result("theta_ddot").values[0],  e.result("phi_ddot").values[0],
                         e.result("psi_ddot").values[0],    e.result("pivot_force").values[0],
                         e.result("pivot_force").values[1], e.result("pivot_force").values[2]};
    const ref_t refs[6] = {R.theta_ddot, R.phi_ddot, R.psi_ddot, R.force[0], R.force[1], R.force[2]};
    const char* names[6] = {"theta_ddot", "phi_ddot", "psi_ddot", "pivot_force x", "pivot_force y", "pivot_force z"};
    const double eps = std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits()));
    for (int i = 0; i < 6; ++i) {
      compare(names[i], values[i], refs[i], R.scale, n);
      if constexpr (scalar_traits<T>::is_interval) {
        widest = std::max(widest, static_cast<double>(width_of(values[i]) / (ref_t(eps) * R.scale)));
      } else {
        worst_point = std::max(worst_point, static_cast<double>(abs(ref_t(to_decimal(values[i])) - refs[i]) /
                                                                (ref_t(eps) * R.scale)));
      }
    }
    for (const auto& check : e.checks) {  // eq. (4), and Cotton = Lagrange: 0 on every motion
      if (check.name == "error_amplification") continue;
      for (const T& x : check.values) {
        if constexpr (scalar_traits<T>::is_interval) {
          BOOST_REQUIRE_MESSAGE(possibly_zero(x), check.name << " excludes 0");
        } else {
          const ref_t residual = abs(ref_t(to_decimal(x)));
          BOOST_REQUIRE_MESSAGE(residual <= ref_t(256 * eps) * R.scale,
                                scalar_traits<T>::name << " " << check.name << " = " << residual.str(5)
                                                       << " > 256 eps * " << R.scale.str(5));
        }
      }
    }
  }
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_scalar_meets_lagrange_and_newton_euler_at_532_bits) {
  mp_precision_scope scope(256);
  const long expected = 121 * 6;  // the shipped scene and 120 random tops, 6 values each
  BOOST_TEST(check_all<double>() == expected);
  test::if_built<long double>([&]<class T>(std::type_identity<T>) { BOOST_TEST(check_all<T>() == expected); });
  test::if_built<dd>([&]<class T>(std::type_identity<T>) { BOOST_TEST(check_all<T>() == expected); });
  test::if_built<float128>([&]<class T>(std::type_identity<T>) { BOOST_TEST(check_all<T>() == expected); });
  test::if_built<mpfr>([&]<class T>(std::type_identity<T>) { BOOST_TEST(check_all<T>() == expected); });
  BOOST_TEST_MESSAGE("point types: largest error " << worst_point << " eps * scale (bound 256)");
  BOOST_TEST(check_all<interval>() == expected);
  BOOST_TEST(check_all<mpfi>() == expected);
  {
    mp_precision_scope s113(113);
    BOOST_TEST(check_all<mpfi>() == expected);
  }
  BOOST_TEST_MESSAGE("interval, mpfi at 256 and 113 bits: every value contains the reference; widest "
                     << widest << " eps * scale");
}

// The third route: the system file (free body, pivot as holonomic constraints,
// Lagrange's multipliers and the wrench at O) gives the same accelerations and
// force, at 256 bits, on the same random tops.
BOOST_AUTO_TEST_CASE(the_system_file_with_a_wrench_at_the_pivot_gives_the_same_force) {
  mp_precision_scope scope(256);
  long n = 0;
  double worst = 0;
  for (const top_case& k : cases()) {
    const evaluation<mpfi> a = evaluate<mpfi>(read_scene(parse_json(heavy_top_json(k))));
    const evaluation<mpfi> b = evaluate<mpfi>(read_scene(parse_json(system_json(k))));
    const std::pair<const char*, const char*> pairs[] = {
        {"theta_ddot", "theta_ddot"}, {"phi_ddot", "phi_ddot"}, {"psi_ddot", "psi_ddot"}};
    for (const auto& [x, y] : pairs) {
      const mpfi u = a.result(x).values[0], v = b.result(y).values[0];
      BOOST_REQUIRE_MESSAGE(meet(u, v), x << ": " << to_string(u) << " and " << to_string(v));
      worst = std::max(worst, static_cast<double>(width_of(v)));
      ++n;
    }
    for (int i = 0; i < 3; ++i) {
      const mpfi u = a.result("pivot_force").values[static_cast<std::size_t>(i)];
      const mpfi v = b.result("pivot_force").values[static_cast<std::size_t>(i)];
      BOOST_REQUIRE_MESSAGE(meet(u, v), "pivot_force " << i << ": " << to_string(u) << " and " << to_string(v));
      worst = std::max(worst, static_cast<double>(width_of(v)));
      ++n;
    }
    // The pivot exerts no moment about O.
    for (const mpfi& x : b.result("pivot_moment").values) BOOST_REQUIRE(possibly_zero(x));
  }
  BOOST_TEST(n == 120 * 6);
  BOOST_TEST(worst < 1e-60);
  BOOST_TEST_MESSAGE("system file vs heavy_top at 256 bits: " << n << " values intersect; system widths <= " << worst);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused_naming_the_field) {
  const auto refused = [](const std::string& json, const std::string& field) {
    try {
      (void)read_scene(parse_json(json));
    } catch (const input_error& e) {
      BOOST_TEST(std::string(e.what()).find(field) != std::string::npos, e.what());
      return;
    }
    BOOST_ERROR("accepted: " << json);
  };
  top_case k{"0.08", "0.02", "1.5", "0.2", "9.81", "0", "0.7", "0", "1", "0", "40"};
  top_case bad = k;
  bad.theta = "0";
  refused(heavy_top_json(bad), "state.theta");
  bad = k;
  bad.A = "0.05";  // < m l^2 = 0.06
  refused(heavy_top_json(bad), "top.A");
  bad = k;
  bad.C = "0.05";  // > 2 (A - m l^2) = 0.04
  refused(heavy_top_json(bad), "top.C");
  bad = k;
  bad.m = "-1";
  refused(heavy_top_json(bad), "top.mass");
  bad = k;
  bad.psi = "1e13";
  refused(heavy_top_json(bad), "state.psi");
}
