// A model of the tests' own, built the way docs/architecture.md's "Adding a model" builds a
// built-in model that moves (tests/models/pendulum.hpp and .cpp, one line of APPELL_TEST_MODELS in
// tests/CMakeLists.txt): registered before main by its generated units, then read, evaluated in
// every scalar and moved through the library's calls, each result held to the pendulum's own
// mathematics in MPFR at 256 bits (theta'' = -(g / l) sin theta; the nutation-free closed form in
// Jacobi's functions, tests/pendulum_problem.hpp's pendulum_solution).
#define BOOST_TEST_MODULE model_walkthrough
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <boost/multiprecision/mpfr.hpp>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "built_scalars.hpp"
#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "appell/io/evaluation_text.hpp"
#include "appell/motion/motion.hpp"
#include "pendulum.hpp"

using namespace appell;
using truth_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<256>>;

namespace {

const std::string scene_path = APPELL_SOURCE_DIR + "/tests/models/pendulum.json";

/// The scene's own numbers: m = 1, l = 1, g = 1, theta(0) = 1, theta'(0) = 0.
const truth_t theta0(1), omega(1);

/// A row sink that keeps each table's columns and last row.
struct last_rows : motion::row_sink {
  std::vector<std::string> header, last;
  void columns(const std::string& table, const std::vector<std::string>& names) override {
    if (table == "steps" || table == "trajectory") header = names;
  }
  void row(const std::string& table, const std::vector<std::string>& cells) override {
    if (table == "steps" || table == "trajectory") last = cells;
  }
  std::string cell(const std::string& column) const {
    const auto it = std::find(header.begin(), header.end(), column);
    BOOST_TEST_REQUIRE((it != header.end()), "no column " << column);
    return last.at(static_cast<std::size_t>(it - header.begin()));
  }
};

}  // namespace

BOOST_AUTO_TEST_CASE(the_model_registers_itself_and_moves) {
  BOOST_TEST(find_model("pendulum").name == "pendulum");
  BOOST_TEST(motion::moving_model_names().find("pendulum") != std::string::npos);
  const scene_input scene = read_scene_file(scene_path);
  BOOST_TEST(motion::state_fields(scene) == (std::vector<std::string>{"theta", "theta_dot"}), boost::test_tools::per_element());
  BOOST_TEST(!motion::closed_form_of(scene).has_value());  // the home gives none
}

BOOST_AUTO_TEST_CASE(eval_holds_the_textbook_in_every_scalar) {
  const scene_input scene = read_scene_file(scene_path);
  using std::sin, std::cos;
  const truth_t theta_ddot = -sin(theta0), tension = cos(theta0);  // m (g cos theta + l theta'^2)
  for (const char* scalar : {"double", "long-double", "dd", "float128", "mpfr", "interval", "mpfi"}) {
    if (!test::built(scalar)) continue;  // left out of this build (tests/built_scalars.hpp)
    BOOST_TEST_CONTEXT(scalar) {
      const nlohmann::json doc = nlohmann::json::parse(evaluation_text(scene, scalar, std::nullopt, "json"));
      for (const auto& [name, truth] : {std::pair<const char*, const truth_t&>{"theta_ddot", theta_ddot}, {"tension", tension}}) {
        const nlohmann::json& v = doc.at("results").at(name);
        if (v.contains("lo")) {  // an enclosure: it holds the truth, and tightly
          const truth_t lo(v.at("lo").get<std::string>()), hi(v.at("hi").get<std::string>());
          BOOST_TEST((lo <= truth && truth <= hi), name << " in [" << lo << ", " << hi << "]");
          BOOST_TEST(static_cast<double>(hi - lo) < 1e-14);
        } else {  // a point value: within its precision (double's at worst)
          BOOST_TEST(static_cast<double>(abs(truth_t(v.at("value").get<std::string>()) - truth)) < 1e-15, name);
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(enclose_holds_the_closed_form_and_simulate_comes_close) {
  const scene_input scene = read_scene_file(scene_path);
  const auto exact = ode::pendulum_solution<truth_t>{theta0, omega}.at(truth_t(1));
  motion::settings s;
  s.t_end = "1";
  last_rows enclosed;
  const motion::enclose_report e = motion::enclose(scene, s, enclosed);
  BOOST_TEST_REQUIRE(e.complete, e.reason);
  BOOST_TEST(enclosed.cell("t1") == "1");
  for (int i = 0; i < 2; ++i) {
    const std::string name = i == 0 ? "theta" : "theta_dot";
    const truth_t lo(enclosed.cell(name + "_lo")), hi(enclosed.cell(name + "_hi"));
    BOOST_TEST((lo <= exact[static_cast<std::size_t>(i)] && exact[static_cast<std::size_t>(i)] <= hi),
               name << "(1) in [" << lo << ", " << hi << "]");
    BOOST_TEST(static_cast<double>(hi - lo) < 1e-9);
  }
  last_rows simulated;
  const motion::simulate_report r = motion::simulate(scene, s, simulated);
  BOOST_TEST_REQUIRE(r.failure.empty(), r.failure);
  BOOST_TEST(r.t_reached == "1");
  BOOST_TEST(static_cast<double>(abs(truth_t(simulated.cell("theta")) - exact[0])) < 1e-12);
  BOOST_TEST(static_cast<double>(abs(truth_t(simulated.cell("theta_dot")) - exact[1])) < 1e-12);
}

BOOST_AUTO_TEST_CASE(its_reader_refuses_bad_input_naming_the_field) {
  nlohmann::json j = {{"model", "pendulum"},
                      {"pendulum", {{"mass", "1"}, {"length", "0"}}},
                      {"gravity", "1"},
                      {"state", {{"theta", "1"}, {"theta_dot", "0"}}}};
  const std::string path = "model_walkthrough_bad.json";
  {
    std::ofstream(path) << j.dump();
  }
  try {
    (void)read_scene_file(path);
    BOOST_ERROR("a zero length was read");
  } catch (const input_error& e) {
    BOOST_TEST(std::string(e.what()).find("pendulum.length") != std::string::npos, e.what());
  }
  std::remove(path.c_str());
}
