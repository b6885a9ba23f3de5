// The built-in models' homes (include/appell/models/<name>.hpp): each moving model's state
// table is the one description of its motion's state.  For every shipped scene of such a model:
// the problem's state names and model_motion's scene fields are the table's, in its order, and
// start() packs the scene's state in that order (the reported state, for the heavy top integrated
// in Resal's speeds), compared with the scene file's own numbers read apart from the model.
#define BOOST_TEST_MODULE model_homes
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR (CMakeLists.txt)
#include "appell/io/scene.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"

using namespace appell;

namespace {

/// A number of a scene file (a JSON number or a decimal string), in double.
double number(const nlohmann::json& v) { return v.is_string() ? std::stod(v.get<std::string>()) : v.get<double>(); }

/// The scene state's field `field` ("psi", "omega[1]") as written in the file, in double.
double state_value(const nlohmann::json& scene, const std::string& field) {
  const auto bracket = field.find('[');
  const nlohmann::json& state = scene.at("state");
  if (bracket == std::string::npos) return number(state.at(field));
  const std::string name = field.substr(0, bracket);
  const std::size_t index = std::stoul(field.substr(bracket + 1));
  return number(state.at(name).at(index));
}

template <class Model, std::size_t N>
int check_scenes(const std::array<state_component, N>& table) {
  using motion = model_motion<Model>;
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(APPELL_SOURCE_DIR) + "/data/scenes")) {
    std::ifstream file(entry.path());
    const nlohmann::json j = nlohmann::json::parse(file);
    if (j.at("model") != Model::name || j.contains("project")) continue;  // a projected state moves
    ++scenes;
    BOOST_TEST_CONTEXT(entry.path().filename().string()) {
      const scene_input scene = read_scene_file(entry.path().string());
      const auto& in = scene.as<typename Model::input>();
      BOOST_TEST(motion::state_fields(in) == state_fields_of(table), boost::test_tools::per_element());
      const auto prepared = Model::template prepare<double>(in);
      const auto [problem, x0] = motion::template start<double>(prepared);
      using P = std::remove_cvref_t<decltype(problem)>;
      BOOST_TEST(x0.size() == P::dim);
      vector_t<double> reported = x0;
      std::vector<std::string> names;
      if constexpr (requires { P::reported(x0); }) {
        reported = P::reported(x0);
        names = P::reported_names();
      } else {
        names = P::state_names();
      }
      BOOST_TEST(names == state_names_of(table), boost::test_tools::per_element());
      BOOST_TEST(static_cast<std::size_t>(reported.size()) == N);
      for (std::size_t i = 0; i < N && i < static_cast<std::size_t>(reported.size()); ++i) {
        const double written = state_value(j, table[i].field);
        const double got = reported(static_cast<Eigen::Index>(i));
        BOOST_TEST(std::fabs(got - written) <= 1e-13 * std::max(1.0, std::fabs(written)),
                   table[i].name << ": start() gives " << got << ", the file's " << table[i].field << " is " << written);
      }
    }
  }
  return scenes;
}

}  // namespace

BOOST_AUTO_TEST_CASE(each_moving_models_state_table_is_its_motions_state) {
  BOOST_TEST(check_scenes<euler_body_model>(euler_body_state_table) >= 2);
  BOOST_TEST(check_scenes<heavy_top_model>(heavy_top_state_table) >= 1);
  BOOST_TEST(check_scenes<top_on_cone_model>(top_on_cone_state_table) >= 2);
  BOOST_TEST(check_scenes<rolling_sphere_model>(rolling_sphere_state_table) >= 4);
}
