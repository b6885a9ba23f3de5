// Random valid scenes through the whole of `appell eval` (JSON text, the
// readers, the models, the evaluation policy) in interval<double>, in mpfi and in arb
// (128 bits each), against independent references at 400 bits (120 digits):
//   euler_body     Euler's equations written out, A w1' = (B - C) w2 w3 + L, ...;
//   top_on_cone    Lagrange's equations with a multiplier (tests/independent/top_lagrange.hpp),
//                  random cones with hand-written f' and f'';
//   rolling_sphere Newton-Euler with contact multipliers in a fixed frame
//                  (tests/independent/sphere_newton_euler.hpp), on the five surfaces.
// Every input is an exact decimal and every state satisfies its constraints
// exactly (Pythagorean triples and quadruples put decimal centres on the
// surfaces of centres; omega = r x v is exactly normal to r).  A miss is an
// enclosure disjoint from reference +- 1e-100 (1 + |reference|) (the reference's
// own error is ~1e-118 times the terms that cancel; the enclosures tested are
// 1e-38 wide at best).  The relative widths are reported as quantiles.
//
// Count per model: test_random_scenes -- --n N (default 1000; docs/testing.md's
// figures come from N = 100000).
#define BOOST_TEST_MODULE random_scenes
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <random>

#include <filesystem>

#include "built_scalars.hpp"
#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "appell/io/scene.hpp"
#include "independent/sphere_newton_euler.hpp"
#include "independent/top_lagrange.hpp"
#include "bounds_400.hpp"

using namespace appell;
using testing::ref_t;
using testing::bounds_of;

namespace {

long scenes_per_model() {
  const auto& suite = boost::unit_test::framework::master_test_suite();
  for (int i = 1; i + 1 < suite.argc; ++i)
    if (std::string(suite.argv[i]) == "--n") return std::stol(suite.argv[i + 1]);
  return 1000;
}

std::mt19937_64 rng(15);
long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }

// k 10^-d as decimal text, sometimes in exponent form.
std::string decimal(long k, int d) {
  if (uniform(0, 3) == 0) return std::to_string(k) + "e-" + std::to_string(d);
  const bool negative = k < 0;
  std::string digits = std::to_string(negative ? -k : k);
  if (static_cast<int>(digits.size()) <= d) digits.insert(0, static_cast<std::size_t>(d + 1) - digits.size(), '0');
  std::string s = digits.substr(0, digits.size() - static_cast<std::size_t>(d));
  if (d > 0) s += "." + digits.substr(digits.size() - static_cast<std::size_t>(d));
  return (negative ? "-" : "") + s;
}
std::string random_decimal(long lo, long hi, int d) { return decimal(uniform(lo, hi), d); }
ref_t R(const std::string& decimal_text) { return ref_t(decimal_text); }
std::string q(const std::string& s) { return "\"" + s + "\""; }
std::string list3(const std::string& x, const std::string& y, const std::string& z) {
  return "[" + q(x) + ", " + q(y) + ", " + q(z) + "]";
}

struct truth {
  std::string name;
  std::vector<ref_t> values;
};
struct random_scene {
  std::string json;
  std::vector<truth> expected;
  // The same system as a "system" scene file (SCENES.md here), with the names
  // its results have there: the same references must be enclosed.
  std::string system_json;
  std::vector<truth> system_expected;
};

// --- pieces of system files ---------------------------------------------------------
std::string qlist(const std::vector<std::string>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + q(v[i]);
  return s + "]";
}
/// The entries of R = rz(psi) rx(theta) rz(phi) (body axes to fixed), as expressions.
const char* const rotation[3][3] = {
    {"cos(psi)*cos(phi) - sin(psi)*cos(theta)*sin(phi)", "-cos(psi)*sin(phi) - sin(psi)*cos(theta)*cos(phi)",
     "sin(psi)*sin(theta)"},
    {"sin(psi)*cos(phi) + cos(psi)*cos(theta)*sin(phi)", "-sin(psi)*sin(phi) + cos(psi)*cos(theta)*cos(phi)",
     "-cos(psi)*sin(theta)"},
    {"sin(theta)*sin(phi)", "sin(theta)*cos(phi)", "cos(theta)"}};
/// A decimal that is a transcendental number to 110 digits (within 1e-110 of the
/// constraint: the readers take what 256 bits cannot tell from exact as exact).
std::string digits110(const ref_t& x) { return x.str(110, std::ios_base::scientific); }
/// Euler angles z-x-z away from their singularity.
std::string random_angles(std::string& psi, std::string& theta, std::string& phi) {
  psi = random_decimal(-3000, 3000, 3), theta = random_decimal(200, 2900, 3), phi = random_decimal(-3000, 3000, 3);
  return "\"psi\": " + q(psi) + ", \"theta\": " + q(theta) + ", \"phi\": " + q(phi);
}

// --- euler_body -------------------------------------------------------------
random_scene euler_scene() {
  std::string A, B, C;
  do {
    A = random_decimal(1, 1000000, 3);
    B = random_decimal(1, 1000000, 3);
    C = random_decimal(1, 1000000, 3);
  } while (decimal_sign_of_sum({{1, A}, {1, B}, {-1, C}}) < 0 || decimal_sign_of_sum({{1, B}, {1, C}, {-1, A}}) < 0 ||
           decimal_sign_of_sum({{1, C}, {1, A}, {-1, B}}) < 0);
  const int e = static_cast<int>(uniform(0, 4));  // spins from 1e-4 to 1e2
  std::string w[3], L[3];
  for (int i = 0; i < 3; ++i) {
    w[i] = random_decimal(-1000000, 1000000, 4 + e);
    L[i] = random_decimal(-100000, 100000, 3);
  }
  random_scene s;
  s.json = "{\"model\": \"euler_body\", \"inertia\": {\"A\": " + q(A) + ", \"B\": " + q(B) + ", \"C\": " + q(C) +
           "}, \"torque\": " + list3(L[0], L[1], L[2]) + ", \"state\": {\"omega\": " + list3(w[0], w[1], w[2]) + "}}";
  const ref_t a = R(A), b = R(B), c = R(C), w1 = R(w[0]), w2 = R(w[1]), w3 = R(w[2]);
  s.expected.push_back({"omega_dot",
                        {((b - c) * w2 * w3 + R(L[0])) / a, ((c - a) * w3 * w1 + R(L[1])) / b,
                         ((a - b) * w1 * w2 + R(L[2])) / c}});
  // As a system: Euler angles, speeds (p, q, r) on the body axes, the torque turned to the fixed axes.
  std::string psi, theta, phi;
  const std::string angles = random_angles(psi, theta, phi);
  std::vector<std::string> couple;
  for (int i = 0; i < 3; ++i)
    couple.push_back("(" + std::string(rotation[i][0]) + ")*L + (" + rotation[i][1] + ")*M + (" + rotation[i][2] + ")*N");
  s.system_json =
      "{\"model\": \"system\", \"parameters\": {\"A\": " + q(A) + ", \"B\": " + q(B) + ", \"C\": " + q(C) +
      ", \"L\": " + q(L[0]) + ", \"M\": " + q(L[1]) + ", \"N\": " + q(L[2]) +
      "}, \"coordinates\": [\"psi\", \"theta\", \"phi\"], \"speeds\": [\"p\", \"q\", \"r\"], "
      "\"kinematics\": {\"psi\": \"(p*sin(phi) + q*cos(phi))/sin(theta)\", \"theta\": \"p*cos(phi) - q*sin(phi)\", "
      "\"phi\": \"r - cos(theta)*(p*sin(phi) + q*cos(phi))/sin(theta)\"}, "
      "\"bodies\": {\"body\": {\"mass\": \"1\", \"inertia\": [\"A\", \"B\", \"C\"], \"center\": [\"0\", \"0\", \"0\"], "
      "\"orientation\": \"rz(psi) rx(theta) rz(phi)\", \"couple\": " + qlist(couple) + "}}, "
      "\"state\": {" + angles + ", \"p\": " + q(w[0]) + ", \"q\": " + q(w[1]) + ", \"r\": " + q(w[2]) + "}}";
  const auto& wd = s.expected.back().values;
  s.system_expected = {{"p_dot", {wd[0]}}, {"q_dot", {wd[1]}}, {"r_dot", {wd[2]}}};
  return s;
}

// --- top_on_cone --------------------------------------------------------------
// f = q0 + q1 t + q2 sin(k t) + q3 t^2/(1+t) - q4 exp(-t), some terms absent.
random_scene top_scene() {
  std::string A, C, m = random_decimal(50, 2000, 3), l = random_decimal(20, 300, 3);
  do {
    A = random_decimal(1, 300000, 6);
    C = random_decimal(1, 300000, 6);
  } while (decimal_sign_of_polynomial({{1, {A}}, {-1, {m, l, l}}}) < 0 ||
           decimal_sign_of_polynomial({{2, {A}}, {-2, {m, l, l}}, {-1, {C}}}) < 0);
  std::string c[5];
  for (auto& x : c) x = uniform(0, 3) ? random_decimal(-1000, 1000, 3) : "0";
  const long k = uniform(1, 3);
  const std::string cone = c[0] + " + " + c[1] + "*theta + " + c[2] + "*sin(" + std::to_string(k) + "*theta) + " + c[3] +
                           "*theta^2/(1 + theta) - " + c[4] + "*exp(-theta)";
  const std::string th = random_decimal(200, 2900, 3), ph = random_decimal(-3000, 3000, 3),
                    thd = random_decimal(-3000, 3000, 3), phd = random_decimal(-50000, 50000, 3);
  random_scene s;
  s.json = "{\"model\": \"top_on_cone\", \"top\": {\"A\": " + q(A) + ", \"C\": " + q(C) + ", \"mass\": " + q(m) +
           ", \"l\": " + q(l) + "}, \"gravity\": \"9.81\", \"cone\": " + q(cone) + ", \"state\": {\"theta\": " + q(th) +
           ", \"phi\": " + q(ph) + ", \"theta_dot\": " + q(thd) + ", \"phi_dot\": " + q(phd) + "}}";
  const ref_t t = R(th), K = k, e = exp(-t), one = 1;
  const ref_t f = R(c[0]) + R(c[1]) * t + R(c[2]) * sin(K * t) + R(c[3]) * t * t / (one + t) - R(c[4]) * e;
  const ref_t fp = R(c[1]) + R(c[2]) * K * cos(K * t) + R(c[3]) * (t * t + 2 * t) / ((one + t) * (one + t)) + R(c[4]) * e;
  const ref_t fpp = -R(c[2]) * K * K * sin(K * t) + R(c[3]) * 2 / ((one + t) * (one + t) * (one + t)) - R(c[4]) * e;
  const auto r = independent::top_lagrange<ref_t>(R(A), R(C), R(m), R(l), R("9.81"), t, R(thd), R(phd), f, fp, fpp);
  s.expected = {{"theta_ddot", {r.theta_ddot}}, {"phi_ddot", {r.phi_ddot}}, {"psi_ddot", {r.psi_ddot}},
                {"H", {r.H}}, {"couple", {r.couple[0], r.couple[1], r.couple[2]}}};
  // As a system: the top's centre and orientation in Euler angles, the cone a holonomic constraint.
  s.system_json =
      "{\"model\": \"system\", \"parameters\": {\"A\": " + q(A) + ", \"C\": " + q(C) + ", \"m\": " + q(m) +
      ", \"l\": " + q(l) + ", \"g\": \"9.81\"}, \"coordinates\": [\"theta\", \"phi\", \"psi\"], "
      "\"gravity\": [\"0\", \"0\", \"-g\"], \"bodies\": {\"top\": {\"mass\": \"m\", "
      "\"inertia\": [\"A - m*l^2\", \"A - m*l^2\", \"C\"], "
      "\"center\": [\"l*sin(theta)*sin(psi)\", \"-l*sin(theta)*cos(psi)\", \"l*cos(theta)\"], "
      "\"orientation\": \"rz(psi) rx(theta) rz(phi)\"}}, "
      "\"constraints\": {\"cone\": {\"holonomic\": " + q("psi - (" + cone + ")") + "}}, "
      "\"state\": {\"theta\": " + q(th) + ", \"phi\": " + q(ph) + ", \"psi\": " + q(digits110(f)) +
      ", \"theta_dot\": " + q(thd) + ", \"phi_dot\": " + q(phd) + ", \"psi_dot\": " + q(digits110(fp * R(thd))) + "}}";
  s.system_expected = {{"theta_ddot", {r.theta_ddot}}, {"phi_ddot", {r.phi_ddot}}, {"psi_ddot", {r.psi_ddot}},
                       {"cone_reaction", {r.H}}};
  return s;
}

// --- rolling_sphere -------------------------------------------------------------
using V = Eigen::Matrix<ref_t, 3, 1>;
// surface 0: plane; 1, 2: sphere inside, outside; 3, 4: cylinder inside, outside

random_scene sphere_scene(int surface) {
  const std::string M = random_decimal(1, 500, 2), a = random_decimal(1, 300, 3);
  const bool homogeneous = uniform(0, 1);
  std::string A;
  if (!homogeneous) do {
      A = random_decimal(1, 1000000, 9);
    } while (decimal_sign_of_polynomial({{3, {A}}, {-2, {M, a, a}}}) > 0);
  long x = 0, y = 0, z = 0, r = 0;  // a Pythagorean triple or quadruple: x^2 + y^2 + z^2 = r^2
  if (surface == 1 || surface == 2) {
    long m, n, p, t;
    do {
      m = uniform(-9, 9), n = uniform(-9, 9), p = uniform(-9, 9), t = uniform(-9, 9);
    } while (m * m + n * n + p * p + t * t == 0);
    x = m * m + n * n - p * p - t * t, y = 2 * (m * t + n * p), z = 2 * (n * t - m * p), r = m * m + n * n + p * p + t * t;
  } else if (surface >= 3) {
    long m, n;
    do {
      m = uniform(-9, 9), n = uniform(-9, 9);
    } while (m * m + n * n == 0);
    x = m * m - n * n, y = 2 * m * n, r = m * m + n * n;
  }
  const bool inside = surface == 1 || surface == 3;
  std::string surface_json = "{\"type\": \"plane\"}", cx, cy, cz, b;
  long s_num;  // the centre is s (x, y, z) with s = s_num / 1000, rho = s r
  if (surface == 0) {
    cx = random_decimal(-10000, 10000, 3), cy = random_decimal(-10000, 10000, 3), cz = a;
  } else {
    ref_t rho;
    do {
      s_num = uniform(1, 3000);
      rho = ref_t(s_num * r) / 1000;
    } while (!inside && rho <= R(a));
    cx = decimal(s_num * x, 3), cy = decimal(s_num * y, 3);
    cz = surface <= 2 ? decimal(s_num * z, 3) : random_decimal(-10000, 10000, 3);
    // b = rho + a inside, rho - a outside, as exact decimal text
    const long a_thousandths = std::lround(static_cast<double>(R(a) * 1000));
    b = decimal(s_num * r + (inside ? a_thousandths : -a_thousandths), 3);
    surface_json = std::string("{\"type\": \"") + (surface <= 2 ? "sphere" : "cylinder") + "\", \"radius\": " + q(b) +
                   ", \"side\": \"" + (inside ? "inside" : "outside") + "\"}";
  }
  // omega = (x, y, z) x v: exactly normal to the surface (plane: (0, 0, 1) x v)
  const long vx = uniform(-500, 500), vy = uniform(-500, 500), vz = uniform(-500, 500);
  long nx = x, ny = y, nz = z;
  if (surface == 0) nx = 0, ny = 0, nz = 1;
  const long wx = ny * vz - nz * vy, wy = nz * vx - nx * vz, wz = nx * vy - ny * vx;
  const std::string w[3] = {decimal(wx, 2), decimal(wy, 2), decimal(wz, 2)};
  const std::string g[3] = {"0", "0", "-9.81"};
  std::string F[3] = {"0", "0", "0"}, tau[3] = {"0", "0", "0"};
  const bool loads = uniform(0, 1);
  if (loads)
    for (int i = 0; i < 3; ++i) F[i] = random_decimal(-2000, 2000, 2), tau[i] = random_decimal(-1000, 1000, 3);
  random_scene s;
  s.json = "{\"model\": \"rolling_sphere\", \"sphere\": {\"mass\": " + q(M) + ", \"radius\": " + q(a) +
           (homogeneous ? "" : ", \"A\": " + q(A)) + "}, \"surface\": " + surface_json + ", \"gravity\": " +
           list3(g[0], g[1], g[2]) + (loads ? ", \"force\": " + list3(F[0], F[1], F[2]) + ", \"torque\": " +
                                                  list3(tau[0], tau[1], tau[2])
                                            : std::string()) +
           ", \"state\": {\"center\": " + list3(cx, cy, cz) + ", \"omega\": " + list3(w[0], w[1], w[2]) + "}}";
  const ref_t Mr = R(M), ar = R(a), Ar = homogeneous ? ref_t(2) / 5 * Mr * ar * ar : R(A);
  const V c(R(cx), R(cy), R(cz)), om(R(w[0]), R(w[1]), R(w[2]));
  const V force = V(R(g[0]), R(g[1]), R(g[2])) * Mr + V(R(F[0]), R(F[1]), R(F[2]));
  const V torque(R(tau[0]), R(tau[1]), R(tau[2]));
  const surface_type type = surface == 0 ? surface_type::plane : surface <= 2 ? surface_type::sphere : surface_type::cylinder;
  const auto ne = independent::sphere_newton_euler<ref_t>(
      Mr, Ar, ar, type, inside, surface == 0 ? ref_t(0) : R(b), c, om, force, torque,
      [](const auto& K, const auto& rhs) { return K.partialPivLu().solve(rhs).eval(); });
  V n(0, 0, 1);
  if (surface != 0) n = V(ref_t(x), ref_t(y), ref_t(z)) / ref_t(r) * (inside ? -1 : 1);
  const ref_t normal = ne.Fc.dot(n);
  const ref_t tangential = sqrt((ne.Fc - normal * n).squaredNorm());
  s.expected = {{"center_ddot", {ne.aG(0), ne.aG(1), ne.aG(2)}},
                {"omega_dot", {ne.alpha(0), ne.alpha(1), ne.alpha(2)}},
                {"contact_force", {ne.Fc(0), ne.Fc(1), ne.Fc(2)}},
                {"normal_force", {normal}},
                {"tangential_force", {tangential}},
                {"pivot_couple", {ne.Gn}},
                {"friction_ratio", {tangential / normal}}};
  // As a system: the centre and Euler angles, speeds v and omega on the fixed axes,
  // rolling as v - a omega x n = 0 and omega . n = 0 with n from the coordinates.
  std::string n_expr[3] = {"0", "0", "1"};
  if (surface != 0) {
    const std::string sign = inside ? "-" : "";
    const std::string norm = surface <= 2 ? "sqrt(x^2 + y^2 + z^2)" : "sqrt(x^2 + y^2)";
    n_expr[0] = sign + "x/" + norm, n_expr[1] = sign + "y/" + norm, n_expr[2] = surface <= 2 ? sign + "z/" + norm : "0";
  }
  auto nx_ = [&](int i) { return "(" + n_expr[i] + ")"; };
  const std::string wxn[3] = {"wy*" + nx_(2) + " - wz*" + nx_(1), "wz*" + nx_(0) + " - wx*" + nx_(2),
                              "wx*" + nx_(1) + " - wy*" + nx_(0)};
  const V v = om.cross(n) * ar;  // the centre's velocity, from rolling
  std::string psi, theta, phi;
  const std::string angles = random_angles(psi, theta, phi);
  s.system_json =
      "{\"model\": \"system\", \"parameters\": {\"M\": " + q(M) + ", \"a\": " + q(a) + ", \"A\": " +
      q(homogeneous ? "2/5*M*a^2" : A) + "}, \"coordinates\": [\"x\", \"y\", \"z\", \"psi\", \"theta\", \"phi\"], "
      "\"speeds\": [\"vx\", \"vy\", \"vz\", \"wx\", \"wy\", \"wz\"], "
      "\"kinematics\": {\"x\": \"vx\", \"y\": \"vy\", \"z\": \"vz\", "
      "\"psi\": \"wz - cos(theta)*(wx*sin(psi) - wy*cos(psi))/sin(theta)\", "
      "\"theta\": \"wx*cos(psi) + wy*sin(psi)\", \"phi\": \"(wx*sin(psi) - wy*cos(psi))/sin(theta)\"}, "
      "\"gravity\": " + list3(g[0], g[1], g[2]) + ", \"bodies\": {\"sphere\": {\"mass\": \"M\", "
      "\"inertia\": [\"A\", \"A\", \"A\"], \"center\": [\"x\", \"y\", \"z\"], "
      "\"orientation\": \"rz(psi) rx(theta) rz(phi)\", \"force\": " + list3(F[0], F[1], F[2]) +
      ", \"couple\": " + list3(tau[0], tau[1], tau[2]) + "}}, \"constraints\": {"
      "\"slip_x\": {\"nonholonomic\": " + q("vx - a*(" + wxn[0] + ")") + "}, "
      "\"slip_y\": {\"nonholonomic\": " + q("vy - a*(" + wxn[1] + ")") + "}, "
      "\"slip_z\": {\"nonholonomic\": " + q("vz - a*(" + wxn[2] + ")") + "}, "
      "\"pivot\": {\"nonholonomic\": " + q("wx*" + nx_(0) + " + wy*" + nx_(1) + " + wz*" + nx_(2)) + "}}, "
      "\"state\": {\"x\": " + q(cx) + ", \"y\": " + q(cy) + ", \"z\": " + q(cz) + ", " + angles +
      ", \"vx\": " + q(digits110(v(0))) + ", \"vy\": " + q(digits110(v(1))) + ", \"vz\": " + q(digits110(v(2))) +
      ", \"wx\": " + q(w[0]) + ", \"wy\": " + q(w[1]) + ", \"wz\": " + q(w[2]) + "}}";
  s.system_expected = {{"vx_dot", {ne.aG(0)}}, {"vy_dot", {ne.aG(1)}}, {"vz_dot", {ne.aG(2)}},
                       {"wx_dot", {ne.alpha(0)}}, {"wy_dot", {ne.alpha(1)}}, {"wz_dot", {ne.alpha(2)}},
                       {"slip_x_reaction", {ne.Fc(0)}}, {"slip_y_reaction", {ne.Fc(1)}},
                       {"slip_z_reaction", {ne.Fc(2)}}, {"pivot_reaction", {ne.Gn}}};
  return s;
}

// --- checking -------------------------------------------------------------------

struct tally {
  long scenes = 0, values = 0, misses = 0, uncertified = 0, straddling_zero = 0;
  std::vector<double> relative_widths;
  std::string first_miss;
  std::map<std::string, long> refusals;  ///< why, for the scenes not certified
};

template <class T>
void check(const std::string& json, const std::vector<truth>& expected, tally& t) {
  ++t.scenes;
  std::optional<evaluation<T>> e;
  try {
    e = evaluate<T>(read_scene(parse_json(json)));
  } catch (const certification_error& e) {
    ++t.uncertified;
    std::string why = e.what();
    ++t.refusals[why.substr(0, why.find_first_of("([0123456789"))];
    return;
  }
  for (const truth& want : expected) {
    const auto& got = e->result(want.name).values;
    BOOST_REQUIRE_EQUAL(got.size(), want.values.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      ++t.values;
      const auto [lo, hi] = bounds_of(got[i]);
      const ref_t& r = want.values[i];
      const ref_t delta = ref_t("1e-100") * (1 + abs(r));
      if (hi < r - delta || lo > r + delta) {
        if (t.misses++ == 0)
          t.first_miss = want.name + "[" + std::to_string(i) + "] = " + to_string(got[i]) + " misses " + r.str(40) +
                         " in " + json;
      }
      if (lo > 0 || hi < 0) t.relative_widths.push_back(static_cast<double>((hi - lo) / std::min(abs(lo), abs(hi))));
      else ++t.straddling_zero;
    }
  }
}

std::string quantiles(std::vector<double> w) {
  if (w.empty()) return "no values";
  std::sort(w.begin(), w.end());
  auto at = [&](double p) { return w[std::min(w.size() - 1, static_cast<std::size_t>(p * static_cast<double>(w.size())))]; };
  char b[256];
  std::snprintf(b, sizeof b, "median %.2e, 90%% %.2e, 99%% %.2e, 99.9%% %.2e, max %.2e", at(0.5), at(0.9), at(0.99),
                at(0.999), w.back());
  return b;
}

/// The model's scenes, or (as_system) the same systems as "system" scene files.
void run(const std::string& model, long n, const std::function<random_scene(long)>& make, bool as_system = false) {
  tally ti, tm, ta;
  std::vector<random_scene> scenes;  // kept for arb, which runs them after (where built)
  for (long k = 0; k < n; ++k) {
    const random_scene& s = scenes.emplace_back(make(k));
    const std::string& json = as_system ? s.system_json : s.json;
    const std::vector<truth>& expected = as_system ? s.system_expected : s.expected;
    check<interval>(json, expected, ti);
    const mp_precision_scope bits(128);
    check<mpfi>(json, expected, tm);
  }
  test::if_built<arb>([&]<class T>(std::type_identity<T>) {  // one line where this build left arb out
    const mp_precision_scope bits(128);
    for (const random_scene& s : scenes)
      check<T>(as_system ? s.system_json : s.json, as_system ? s.system_expected : s.expected, ta);
  });
  for (const auto& [name, t] :
       {std::pair<const char*, const tally&>{"interval", ti}, {"mpfi 128", tm}, {"arb 128", ta}}) {
    if (&t == &ta && !scalar_built<arb>) continue;  // left out of this build (tests/built_scalars.hpp)
    BOOST_TEST_MESSAGE(model << ", " << name << ": " << t.scenes << " scenes, " << t.values << " values, " << t.misses
                             << " misses, " << t.uncertified << " not certified, " << t.straddling_zero
                             << " enclosures of 0; relative widths: " << quantiles(t.relative_widths));
    for (const auto& [why, count] : t.refusals) BOOST_TEST_MESSAGE("  not certified " << count << "x: " << why);
    BOOST_TEST(t.misses == 0, model << " " << name << ": first miss " << t.first_miss);
    BOOST_TEST(t.uncertified * 100 <= t.scenes, model << " " << name << ": " << t.uncertified << " not certified");
    BOOST_TEST(t.values > 0);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(euler_body_random_scenes_are_enclosed) { run("euler_body", scenes_per_model(), [](long) { return euler_scene(); }); }

BOOST_AUTO_TEST_CASE(top_on_cone_random_scenes_are_enclosed) { run("top_on_cone", scenes_per_model(), [](long) { return top_scene(); }); }

BOOST_AUTO_TEST_CASE(rolling_sphere_random_scenes_are_enclosed) {
  run("rolling_sphere", scenes_per_model(), [](long k) { return sphere_scene(static_cast<int>(k % 5)); });
}

// The same random systems written as "system" scene files (SCENES.md in this
// repository): the generic expression model must enclose the same references.
BOOST_AUTO_TEST_CASE(euler_body_as_system_files_are_enclosed) {
  run("system (euler_body)", scenes_per_model() / 4, [](long) { return euler_scene(); }, true);
}

BOOST_AUTO_TEST_CASE(top_on_cone_as_system_files_are_enclosed) {
  run("system (top_on_cone)", scenes_per_model() / 4, [](long) { return top_scene(); }, true);
}

BOOST_AUTO_TEST_CASE(rolling_sphere_as_system_files_are_enclosed) {
  run("system (rolling_sphere)", scenes_per_model() / 4, [](long k) { return sphere_scene(static_cast<int>(k % 5)); }, true);
}

namespace {
/// Every result and derived value of `scene` in T holds the 400-bit MPFI enclosure `truth` of
/// the same value inside its bounds (so it holds the true value: truth's bounds are rigorous).
/// Returns the values compared; a scene T cannot certify is counted in `uncertified`.
template <class T>
long encloses_its_truth(const scene_input& scene, const evaluation<mpfi>& truth, const std::string& file, long& uncertified) {
  std::optional<evaluation<T>> e;
  try {
    e = evaluate<T>(scene);
  } catch (const certification_error&) {
    ++uncertified;
    return 0;
  }
  long compared = 0;
  auto group = [&](const std::vector<named_result<T>>& got, const std::vector<named_result<mpfi>>& want, const char* what) {
    BOOST_TEST_REQUIRE(got.size() == want.size(), file << " " << what);
    for (std::size_t k = 0; k < got.size(); ++k) {
      BOOST_TEST_REQUIRE(got[k].name == want[k].name, file);
      BOOST_TEST_REQUIRE(got[k].values.size() == want[k].values.size(), file << " " << got[k].name);
      for (std::size_t i = 0; i < got[k].values.size(); ++i) {
        const auto [lo, hi] = bounds_of(got[k].values[i]);
        const auto [tlo, thi] = bounds_of(want[k].values[i]);
        BOOST_TEST((lo <= tlo && thi <= hi), file << ": " << scalar_traits<T>::name << " " << got[k].name << "[" << i << "] = ["
                                                  << lo.str(20) << ", " << hi.str(20) << "] does not hold [" << tlo.str(40)
                                                  << ", " << thi.str(40) << "]");
        ++compared;
      }
    }
  };
  group(e->results, truth.results, "results");
  group(e->derived, truth.derived, "derived");
  return compared;
}
}  // namespace

BOOST_AUTO_TEST_CASE(every_shipped_scene_is_enclosed_around_its_truth) {
  // Issue 57's "eval of every shipped scene still encloses its truth": each scene of data/scenes
  // in interval, in mpfi and in arb at 128 bits, every result and derived value holding the
  // scene's enclosure in MPFI at 400 bits (a value certified at 400 bits is within about 1e-110 of
  // the truth, so holding it holds the truth). A scene whose files this machine lacks (a URDF
  // from dart-doc) is skipped, said; one the 400-bit run cannot certify fails the test.
  long scenes = 0, skipped = 0, values = 0, uncertified = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(APPELL_SOURCE_DIR) + "/data/scenes")) {
    if (entry.path().extension() != ".json") continue;
    const std::string file = entry.path().filename().string();
    std::optional<scene_input> scene;
    try {
      scene = read_scene_file(entry.path().string());
    } catch (const std::exception& e) {
      const std::string why = e.what();
      BOOST_TEST_REQUIRE(why.find("/usr/share/doc/") != std::string::npos, file << ": " << why);  // only a missing URDF
      ++skipped;
      BOOST_TEST_MESSAGE(file << ": skipped (" << why << ")");
      continue;
    }
    std::optional<evaluation<mpfi>> truth;
    {
      const mp_precision_scope bits(400);
      truth = evaluate<mpfi>(*scene);
    }
    ++scenes;
    values += encloses_its_truth<interval>(*scene, *truth, file, uncertified);
    const mp_precision_scope bits(128);
    values += encloses_its_truth<mpfi>(*scene, *truth, file, uncertified);
    test::if_built<arb>([&]<class T>(std::type_identity<T>) { values += encloses_its_truth<T>(*scene, *truth, file, uncertified); });
  }
  BOOST_TEST_MESSAGE(scenes << " scenes (" << skipped << " skipped), " << values << " values held their 400-bit enclosures, "
                            << uncertified << " evaluations not certified");
  BOOST_TEST(scenes >= 40);
  BOOST_TEST(uncertified == 0);
}
