// The generic path's kinematics without the heap (issue "Speed without the heap", point 1).
//
// A replaced malloc (counting_malloc.hpp) counts the heap's calls on this thread.  For system
// files of every kind (rates as speeds, quasi-velocities with kinematics, angles and matrices,
// links from a URDF, holonomic, nonholonomic and point-velocity constraints) and each of double,
// long double, dd, float128 and interval, on a thread that has evaluated once (its working
// storage borrowed and kept: linalg/scratch.hpp):
//   - the bodies' states (expression_system::bodies), in T and in multi_dual<T, 8> (the
//     derivative pass of Gibbs-Appell), into a vector that holds them already,
//   - the constraints' rows A(q, t), a(q, t) (expression_constraints::eval), in T and in
//     multi_dual<T, 8>, into matrices of their size,
//   - the change to adapted speeds u(q, v, t) (adapted_change::apply_into),
//   - the differentiated kinematics of Gibbs-Appell (differentiate_kinematics_into),
// take nothing from the heap; nor does the whole evaluation of each of these scenes, of scenes
// with wrenches and joints, of the paper's scenes through their own models, and of a generated
// system of 48 speeds and 16 constraints (32 free speeds), written over the last one
// (compute_into), and its results are the same, bit for bit, as a fresh evaluation's.
#define BOOST_TEST_MODULE allocations
#include <boost/test/unit_test.hpp>

#include "counting_malloc.hpp"
#include "built_scalars.hpp"
#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "appell/derivatives/jet.hpp"  // detail::identical
#include "appell/models/system.hpp"
#include "appell/io/scene.hpp"

using namespace appell;

namespace {

const char* const files[] = {"system_whipple_bicycle.json", "system_rolling_sphere_bowl.json",
                             "system_top_on_cone.json",     "system_euler_body.json",
                             "system_euler_body_angles.json", "system_chaplygin_sleigh.json",
                             "system_rolling_disk.json",    "system_bead_on_rotating_wire.json",
                             "urdf_kr5.json"};

scene_input scene_file(const std::string& file) { return read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/" + file); }

template <class S, class T>
vector_t<S> lifted(const vector_t<T>& x) {
  vector_t<S> r(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) r(i) = S(x(i));
  return r;
}

/// Runs f twice, the second time counted; the second call's allocations.
template <class F>
long warm_allocations(F&& f) {
  f();
  return counting_malloc::allocations_in(f);
}

template <class T>
void check_scalar(const std::string& scalar) {
  for (const char* file : files) {
    const scene_input scene = scene_file(file);
    const auto& in = scene.as<system_input>();
    const evaluation_scope<T> scope;  // interval: upward rounding, as in an evaluation
    const auto m = system_model::prepare<T>(in);
    const expression_system<T> sys{&m.sys};
    const expression_constraints<T> con{&m.sys};
    const int n = sys.speeds(), s = con.count();
    BOOST_TEST_CONTEXT(file << " in " << scalar) {
      std::vector<body_state<T>> out;
      BOOST_TEST(warm_allocations([&] {
                   out.clear();
                   sys.template bodies<T>(m.q, m.u, m.t, out);
                 }) == 0);
      using D = multi_dual<T, 8>;
      const vector_t<D> qd = lifted<D>(m.q), ud = lifted<D>(m.u);
      const D td(m.t);
      std::vector<body_state<D>> outd;
      BOOST_TEST(warm_allocations([&] {
                   outd.clear();
                   sys.template bodies<D>(qd, ud, td, outd);
                 }) == 0);
      std::vector<body_kinematics<T>> kinematics;
      BOOST_TEST(warm_allocations([&] {
                   detail::differentiate_kinematics_in_slots_into<8>(sys, m.q, m.u, m.t, kinematics);
                 }) == 0);
      if (s == 0) continue;
      matrix_t<T> A(s, n);
      vector_t<T> a(s);
      BOOST_TEST(warm_allocations([&] { con.template eval<T>(m.q, m.t, A, a); }) == 0);
      matrix_t<D> Ad(s, n);
      vector_t<D> ad(s);
      BOOST_TEST(warm_allocations([&] { con.template eval<D>(qd, td, Ad, ad); }) == 0);
      const auto change = adapt_speeds<T>(con, m.q, m.t, n);
      vector_t<T> v = vector_t<T>::Zero(n), u(n);
      for (std::size_t i = 0; i < change.free_columns.size(); ++i)
        v(static_cast<Eigen::Index>(i)) = m.u(change.free_columns[i]);
      BOOST_TEST(warm_allocations([&] { change.template apply_into<T>(m.q, v, m.t, u); }) == 0);
      // the change reproduces the state's speeds (a consistent state: v_c = A u - a = 0)
      for (int j = 0; j < n; ++j) BOOST_TEST(approx_double(u(j)) == approx_double(m.u(j)), boost::test_tools::tolerance(1e-9));
    }
  }
}

/// Scenes with wrenches and joints too (their forces are results of compute), and the paper's
/// scenes through their own models (scenes/*.hpp).
const char* const more_files[] = {"system_heavy_top.json", "system_rolling_disk_contact.json", "urdf_kr5_inverse.json",
                                  "urdf_wam.json",         "euler_body.json",  "heavy_top.json",
                                  "top_on_cone.json",      "rolling_sphere_plane.json", "rolling_sphere_bowl.json"};

/// 16 Chaplygin sleighs (data/scenes/system_chaplygin_sleigh.json), each knife edge coupled to
/// the sleigh before it (v_i = c w_(i-1)): 48 speeds, 16 nonholonomic constraints, 32 free
/// speeds; Lagrange's saddle-point system has 64 unknowns (the interval residual bound in
/// borrowed storage, beyond the stack's 12).
std::string sleighs_text(int count) {
  std::string coordinates, speeds, kinematics, bodies, constraints, solve, state;
  auto add = [](std::string& list, const std::string& item) { list += (list.empty() ? "" : ", ") + item; };
  for (int i = 0; i < count; ++i) {
    const std::string k = std::to_string(i), x = "x" + k, y = "y" + k, th = "th" + k, u = "u" + k, v = "v" + k,
                      w = "w" + k;
    add(coordinates, "\"" + x + "\", \"" + y + "\", \"" + th + "\"");
    add(speeds, "\"" + u + "\", \"" + v + "\", \"" + w + "\"");
    add(kinematics, "\"" + x + "\": \"" + u + "*cos(" + th + ") - " + v + "*sin(" + th + ")\", \"" + y + "\": \"" + u +
                        "*sin(" + th + ") + " + v + "*cos(" + th + ")\", \"" + th + "\": \"" + w + "\"");
    add(bodies, "\"sleigh" + k + "\": {\"mass\": \"m\", \"inertia\": [\"I/2\", \"I/2\", \"I\"], \"center\": [\"" + x +
                    " + a*cos(" + th + ")\", \"" + y + " + a*sin(" + th + ")\", \"0\"], \"orientation\": \"rz(" + th + ")\"}");
    add(constraints, "\"knife" + k + "\": {\"nonholonomic\": \"" + v +
                         (i == 0 ? std::string() : " - c*w" + std::to_string(i - 1)) + "\"}");
    add(solve, "\"" + v + "\"");
    add(state, "\"" + x + "\": \"0\", \"" + y + "\": \"" + k + "\", \"" + th + "\": \"0." + k + "\", \"" + u +
                   "\": \"1\", \"" + w + "\": \"" + std::to_string(2 + i % 3) + "\"");
  }
  return "{\"model\": \"system\", \"parameters\": {\"m\": \"2\", \"I\": \"0.3\", \"a\": \"0.4\", \"c\": \"0.1\"},"
         " \"coordinates\": [" + coordinates + "], \"speeds\": [" + speeds + "], \"kinematics\": {" + kinematics +
         "}, \"bodies\": {" + bodies + "}, \"constraints\": {" + constraints + "}, \"solve_speeds\": [" + solve +
         "], \"state\": {" + state + "}}";
}

/// The whole evaluation, written over the last one of the same scene (compute_into).
template <class T>
void check_compute(const std::string& scalar) {
  std::vector<std::string> all(std::begin(files), std::end(files));
  all.insert(all.end(), std::begin(more_files), std::end(more_files));
  all.push_back("16 sleighs");
  for (const std::string& file : all) {
    const scene_input scene = file == "16 sleighs" ? read_scene(parse_json(sleighs_text(16))) : scene_file(file);
    const prepared_scene<T> prepared = prepare<T>(scene);
    evaluation<T> e;
    compute_into<T>(prepared, e);
    const evaluation<T> first = e;
    const long n = warm_allocations([&] { compute_into<T>(prepared, e); });
    BOOST_TEST_CONTEXT(file << " in " << scalar) {
      BOOST_TEST(n == 0);
      if (file == "16 sleighs") BOOST_TEST(e.results.size() == 48u + 16u);  // the accelerations, the reactions
      // the same evaluation as a fresh one: names and values, in order
      BOOST_TEST_REQUIRE(e.results.size() == first.results.size());
      BOOST_TEST_REQUIRE(e.checks.size() == first.checks.size());
      for (std::size_t i = 0; i < e.results.size(); ++i) {
        BOOST_TEST(e.results[i].name == first.results[i].name);
        BOOST_TEST(e.results[i].values.size() == first.results[i].values.size());
        for (std::size_t j = 0; j < e.results[i].values.size(); ++j)
          BOOST_TEST(detail::identical(e.results[i].values[j], first.results[i].values[j]));
      }
      for (std::size_t i = 0; i < e.checks.size(); ++i) BOOST_TEST(e.checks[i].name == first.checks[i].name);
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_counter_counts) {
  // the test can fail: a vector, a string beyond the short-string buffer, an Eigen matrix
  // (each kept from the optimizer: its storage escapes into an empty asm)
  BOOST_TEST(counting_malloc::allocations_in([] {
               std::vector<double> x(100);
               asm volatile("" : : "g"(x.data()) : "memory");
             }) == 1);
  BOOST_TEST(counting_malloc::allocations_in([] {
               std::string s(100, 'x');
               asm volatile("" : : "g"(s.data()) : "memory");
             }) == 1);
  BOOST_TEST(counting_malloc::allocations_in([] {
               matrix_t<double> M(7, 7);
               asm volatile("" : : "g"(M.data()) : "memory");
             }) == 1);
}

BOOST_AUTO_TEST_CASE(kinematics_and_constraints_in_double) { check_scalar<double>("double"); }
BOOST_AUTO_TEST_CASE(kinematics_and_constraints_in_long_double, *test::needs_scalars({"long-double"})) {
  test::if_built<long double>([](auto t) { check_scalar<typename decltype(t)::type>("long-double"); });
}
BOOST_AUTO_TEST_CASE(kinematics_and_constraints_in_dd, *test::needs_scalars({"dd"})) {
  test::if_built<dd>([](auto t) { check_scalar<typename decltype(t)::type>("dd"); });
}
BOOST_AUTO_TEST_CASE(kinematics_and_constraints_in_float128, *test::needs_scalars({"float128"})) {
  test::if_built<float128>([](auto t) { check_scalar<typename decltype(t)::type>("float128"); });
}
BOOST_AUTO_TEST_CASE(kinematics_and_constraints_in_interval) { check_scalar<interval>("interval"); }

BOOST_AUTO_TEST_CASE(evaluations_in_double) { check_compute<double>("double"); }
BOOST_AUTO_TEST_CASE(evaluations_in_long_double, *test::needs_scalars({"long-double"})) {
  test::if_built<long double>([](auto t) { check_compute<typename decltype(t)::type>("long-double"); });
}
BOOST_AUTO_TEST_CASE(evaluations_in_dd, *test::needs_scalars({"dd"})) {
  test::if_built<dd>([](auto t) { check_compute<typename decltype(t)::type>("dd"); });
}
BOOST_AUTO_TEST_CASE(evaluations_in_float128, *test::needs_scalars({"float128"})) {
  test::if_built<float128>([](auto t) { check_compute<typename decltype(t)::type>("float128"); });
}
BOOST_AUTO_TEST_CASE(evaluations_in_interval) { check_compute<interval>("interval"); }
