// The Gibbs-Appell core in floating and interval arithmetic (the exact
// versions are in proofs/): eq. (4) under random invertible changes of speeds,
// and the rigid-body constraint wrench recovered from virtual work.
#define BOOST_TEST_MODULE appell_core
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <optional>
#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/derivatives/jet.hpp"
#include "appell/dynamics/speeds.hpp"
#include "appell/io/scene.hpp"
#include "appell/dynamics/virtual_work.hpp"
#include "appell/reactions/lagrange.hpp"
#include "appell/reactions/wrench.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/models/top_on_cone.hpp"

using namespace appell;

namespace {
std::mt19937_64 rng(44);
double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

// The heavy top without constraint: a rich enough system (trigonometric kinematics, gravity).
template <class T>
symmetric_top<T> top() {
  return {from_decimal<T>("0.08"), from_decimal<T>("0.02"), from_decimal<T>("1.5"), from_decimal<T>("0.2"),
          from_decimal<T>("9.81")};
}
}  // namespace

BOOST_AUTO_TEST_CASE(P_transforms_as_T_transpose_P_under_random_changes_of_speeds) {
  int cases = 0;
  for (int c = 0; c < 200; ++c) {
    Eigen::Matrix3d Td;
    do {
      Td = Eigen::Matrix3d::Random();
    } while (std::abs(Td.determinant()) < 0.1);
    Eigen::Vector3d td = Eigen::Vector3d::Random(), vd = Eigen::Vector3d::Random() * 5, vdotd = Eigen::Vector3d::Random();
    vector_t<interval> q(3), v(3), vdot(3), tv(3);
    matrix_t<interval> T(3, 3);
    for (int i = 0; i < 3; ++i) {
      q(i) = interval(uniform(0.2, 2.5));
      v(i) = interval(vd(i));
      vdot(i) = interval(vdotd(i));
      tv(i) = interval(td(i));
      for (int j = 0; j < 3; ++j) T(i, j) = interval(Td(i, j));
    }
    const auto base = top<interval>();
    const auto changed = change_speeds(base, constant_change<interval>{T, tv}, 3);
    const vector_t<interval> u = detail::product(T, v) + tv, udot = detail::product(T, vdot);
    const auto eu = gibbs_appell(base, q, u, interval(0)), ev = gibbs_appell(changed, q, v, interval(0));
    const vector_t<interval> Pu = eu.P(udot), Pv = ev.P(vdot);
    const matrix_t<interval> TT = T.transpose();
    const vector_t<interval> TtPu = detail::product(TT, Pu);
    for (int i = 0; i < 3; ++i) BOOST_REQUIRE(possibly_zero(interval(Pv(i) - TtPu(i))));
    BOOST_REQUIRE(possibly_zero(virtual_work_residual(changed, ev, q, v, interval(0), vdot, vdot)));
    // double agrees to rounding.  The exact P_v lies in Pv(i); the double P_d
    // differs from it by rounding errors relative to the size of the terms that
    // cancel in P = M v' + b, scale_i = sum_j |M_ij v'_j| + |b_i|.  Measured on
    // these 200 cases against a float128 evaluation (u = 2^-53): |P_d - P| is at
    // most 34 u scale_i (median 2.2; relative to |P_i| at most 1.3e-13, median
    // 3.5e-16), and P_d never lay outside the interval.  Tolerance 128 u scale_i,
    // ~4x the largest error.  A relative error of 1e-12 in P_d leaves
    // [lower - tol, upper + tol] in 582 of the 600 components (the interval's own
    // width, 80-10000 u scale_i, hides the rest), so it fails the test.
    const auto ed = gibbs_appell(change_speeds(top<double>(), constant_change<double>{Td, td}, 3),
                                 Eigen::VectorXd(q.unaryExpr([](const interval& x) { return x.lower(); })),
                                 Eigen::VectorXd(vd), 0.0);
    const Eigen::VectorXd Pd = ed.P(vdotd);
    const double unit_roundoff = std::ldexp(1.0, -53);  // u
    for (int i = 0; i < 3; ++i) {
      const double scale = ed.M.row(i).cwiseAbs().dot(vdotd.cwiseAbs()) + std::abs(ed.b(i));
      const double tol = 128 * unit_roundoff * scale;
      BOOST_REQUIRE_MESSAGE(Pv(i).lower() - tol <= Pd(i) && Pd(i) <= Pv(i).upper() + tol,
                            "case " << c << ", P_" << i << ": double " << to_string(Pd(i)) << " vs interval "
                                    << to_string(Pv(i)));
    }
    ++cases;
  }
  BOOST_TEST_MESSAGE(cases << " random changes of speeds: P_v = T^T P_u enclosed");
}

namespace {
// A free rigid body (6 speeds: v_G and omega on fixed axes), to be pinned at a point.
template <Scalar T>
struct free_body {
  T mass;
  mat3<T> inertia;
  vec3<T> weight;
  int speeds() const { return 6; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>&, const vector_t<S>& u, const S&) const {
    return u;
  }
  template <class S>
  void bodies(const vector_t<S>&, const vector_t<S>& u, const S&, std::vector<body_state<S>>& out) const {
    body_state<S> b;
    b.mass = S(mass);
    b.velocity = vec3<S>(u(0), u(1), u(2));
    b.omega = vec3<S>(u(3), u(4), u(5));
    for (int i = 0; i < 3; ++i) {
      b.force(i) = S(weight(i));
      for (int j = 0; j < 3; ++j) b.inertia(i, j) = S(inertia(i, j));
    }
    out.push_back(b);
  }
};
// The point P = G + rho is fixed: v_G + omega x rho = 0 (3 constraints).
template <Scalar T>
struct pinned_at {
  vec3<T> rho;
  int count() const { return 3; }
  template <class S>
  void eval(const vector_t<S>&, const S&, matrix_t<S>& A, vector_t<S>& a) const {
    A.setZero();
    for (int i = 0; i < 3; ++i) A(i, i) = S(1);
    // omega x rho = -[rho]x omega
    A(0, 4) = S(rho(2)); A(0, 5) = -S(rho(1));
    A(1, 3) = -S(rho(2)); A(1, 5) = S(rho(0));
    A(2, 3) = S(rho(1)); A(2, 4) = -S(rho(0));
    a.setZero();
  }
};
}  // namespace

BOOST_AUTO_TEST_CASE(the_pin_reaction_is_a_force_at_the_pin_equal_to_m_aG_minus_weight) {
  using T = double;
  mat3<T> I;
  I << 0.3, 0.01, 0.02, 0.01, 0.2, 0.03, 0.02, 0.03, 0.25;
  const free_body<T> body{2.0, I, vec3<T>(0, 0, -19.62)};
  const pinned_at<T> pin{vec3<T>(0.1, -0.2, 0.3)};
  vector_t<T> q = vector_t<T>::Zero(6), u(6);
  const vec3<T> w(0.7, -1.2, 2.0);
  const vec3<T> vG = -cross(w, pin.rho);  // consistent: the pin point at rest
  u << vG(0), vG(1), vG(2), w(0), w(1), w(2);
  const auto lag = lagrange_multipliers(body, pin, q, u, 0.0);
  // Cotton: reactions in adapted speeds; the wrench from their virtual work.
  auto change = adapt_speeds<T>(pin, q, 0.0, 6);
  const auto adapted = change_speeds(body, change, 6);
  vector_t<T> v_a(3);
  for (int i = 0; i < 3; ++i) v_a(i) = u(change.free_columns[static_cast<std::size_t>(i)]);
  const auto c = cotton_reactions(adapted, q, v_a, 0.0, 3);
  vector_t<T> v(6), generalized = vector_t<T>::Zero(6);
  v << v_a, 0, 0, 0;
  generalized.tail(3) = c.reactions;
  const auto kin = differentiate_kinematics(adapted, q, v, 0.0);
  // Velocity of the pin point P: v_G + omega x rho, its J by columns.
  Eigen::Matrix<T, 3, Eigen::Dynamic> Jp(3, 6);
  for (int j = 0; j < 6; ++j) Jp.col(j) = kin[0].Jv.col(j) + cross(vec3<T>(kin[0].Jw.col(j)), pin.rho);
  const auto [F, G] = constraint_wrench(Jp, kin[0], generalized);
  // Newton: F = m a_G - weight, with a_G from the constrained accelerations.
  const vec3<T> aG(lag.accelerations(0), lag.accelerations(1), lag.accelerations(2));
  const vec3<T> expected = aG * 2.0 - body.weight;
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(F(i) == expected(i), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(G(i)) < 1e-12);  // a pin exerts no couple
    BOOST_TEST(lag.reactions(i) == F(i), boost::test_tools::tolerance(1e-12));  // multipliers = force at the pin
  }
}

// with_checks::no (io/scene.hpp): the results and the derived state are those of the evaluation
// with its checks, bit for bit, on every shipped scene (interval and double; a scene one of them
// cannot evaluate is refused the same way by both); the rolling sphere leaves its checks out
// (its Lagrange multipliers and eq. (4)), a model without the flag keeps them.
namespace {
template <class T>
bool same_group(const std::vector<named_result<T>>& a, const std::vector<named_result<T>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].name != b[i].name || a[i].values.size() != b[i].values.size()) return false;
    for (std::size_t j = 0; j < a[i].values.size(); ++j)
      if (!detail::identical(a[i].values[j], b[i].values[j])) return false;  // derivatives/jet.hpp
  }
  return true;
}
template <class T>
int compare_with_and_without_checks(const scene_input& scene, const std::string& file) {
  std::optional<evaluation<T>> with, without;
  std::string refused_with, refused_without;
  try {
    with = evaluate<T>(scene);
  } catch (const std::exception& e) {
    refused_with = e.what();
  }
  try {
    without = evaluate<T>(scene, with_checks::no);
  } catch (const std::exception& e) {
    refused_without = e.what();
  }
  BOOST_TEST_REQUIRE(with.has_value() == without.has_value(), file);
  if (!with) {
    BOOST_TEST(refused_with == refused_without, file);
    return 0;
  }
  BOOST_TEST(same_group(with->results, without->results), file << ": results");
  BOOST_TEST(same_group(with->derived, without->derived), file << ": derived");
  BOOST_TEST(!with->checks.empty(), file);
  if (scene.model == "rolling_sphere" || scene.entry->module == "system") BOOST_TEST(without->checks.empty(), file);
  if (scene.model == "euler_body") {  // no flag: its checks all there, but the point types' error_amplification
    std::vector<named_result<T>> kept;
    for (const auto& c : with->checks)
      if (c.name != "error_amplification") kept.push_back(c);
    BOOST_TEST(kept.size() + (scalar_traits<T>::is_interval ? 0 : 1) == with->checks.size(), file);
    BOOST_TEST(same_group(kept, without->checks), file);
  }
  return 1;
}
}  // namespace

BOOST_AUTO_TEST_CASE(evaluations_without_checks_give_the_same_results) {
  int scenes = 0, spheres = 0, systems = 0, compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(APPELL_SOURCE_DIR) + "/data/scenes")) {
    const std::string file = entry.path().string();
    if (entry.path().extension() != ".json") continue;
    const scene_input scene = read_scene_file(file);
    ++scenes;
    if (scene.model == "rolling_sphere") ++spheres;
    if (scene.entry->module == "system") ++systems;  // system files and URDF robots
    compared += compare_with_and_without_checks<interval>(scene, file);
    compared += compare_with_and_without_checks<double>(scene, file);
  }
  BOOST_TEST_MESSAGE(scenes << " scenes (" << spheres << " rolling spheres, " << systems << " systems or robots), " << compared
                            << " evaluations compared");
  BOOST_TEST(scenes >= 40);
  BOOST_TEST(spheres >= 5);
  BOOST_TEST(systems >= 10);
  BOOST_TEST(compared >= 70);
}
