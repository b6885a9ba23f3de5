// A seeded mutational batch: the shipped `system` files, each mutated (a number made hostile,
// an expression made singular, a field removed or of the wrong type, a list entry dropped or
// doubled), through `appell eval` and `appell linearize` in a random scalar, with the CLI
// contract as the oracle (SCENES.md, README):
//  * the exit status is 0, 2 or 3 (4, a crash or a signal is a defect);
//  * on 2 or 3: exactly one line on stderr and nothing on stdout;
//  * on 0: a JSON document whose every number is finite: no `nan`, no `inf`, in any value.
// The batch is the one a held-out review ran (issue 35), made reproducible: the seed and the
// case count are fixed; a failing case prints its command and writes its scene file.
#define BOOST_TEST_MODULE mutations
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>
#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"

namespace {

using nlohmann::json;

const std::filesystem::path work = std::filesystem::path(APPELL_TEST_TMPDIR) / "mutations";

std::string slurp(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

struct outcome {
  int status;
  std::string out, err;
};

outcome run(const std::string& args) {
  const std::string out = (work / "stdout").string(), err = (work / "stderr").string();
  const std::string cmd = std::string(APPELL_BINARY) + " " + args + " >" + out + " 2>" + err;
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

/// Every place in the document: its JSON pointer, for the leaves, the objects and the arrays.
void places(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& leaves,
            std::vector<json::json_pointer>& objects, std::vector<json::json_pointer>& arrays) {
  if (j.is_object()) {
    objects.push_back(at);
    for (auto it = j.begin(); it != j.end(); ++it) places(it.value(), at / it.key(), leaves, objects, arrays);
  } else if (j.is_array()) {
    arrays.push_back(at);
    for (std::size_t i = 0; i < j.size(); ++i) places(j[i], at / i, leaves, objects, arrays);
  } else {
    leaves.push_back(at);
  }
}

bool looks_numeric(const json& j) {
  if (j.is_number()) return true;
  if (!j.is_string()) return false;
  static const std::regex decimal(R"([-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)");
  return std::regex_match(j.get<std::string>(), decimal);
}

const std::vector<std::string> hostile_numbers = {
    "0", "-0", "1e-999999", "-1e-999999", "1e999999", "-1e999999", "1e308", "-1e308", "4.9e-324", "1e-320",
    "-1", "1e40", "123456789012345678901234567890.5", "0.1", "1e-12", "NaN", "inf", "", "1e", "--1", "0x10"};
const std::vector<std::string> hostile_expressions = {
    "0", "1/0", "sqrt(-1)", "log(0)", "1e999999*1e999999", "1e-999999", "(((", "", "x +", "1/(1-1)",
    "sqrt(0)", "exp(1e6)", "sin(1e300)", "2^2^2^2^2", "-1e999999"};

/// One mutation of the document (the RNG decides which and where); the text of what it did.
std::string mutate(json& doc, std::mt19937_64& rng) {
  std::vector<json::json_pointer> leaves, objects, arrays;
  places(doc, json::json_pointer(), leaves, objects, arrays);
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::size_t op = pick(10);
  if (op < 5 && !leaves.empty()) {  // a leaf made hostile
    const json::json_pointer at = leaves[pick(leaves.size())];
    if (at.to_string() == "/model") return "kept /model";
    if (looks_numeric(doc[at])) doc[at] = hostile_numbers[pick(hostile_numbers.size())];
    else if (pick(2) == 0) doc[at] = hostile_expressions[pick(hostile_expressions.size())];
    else doc[at] = doc[leaves[pick(leaves.size())]];  // another leaf's text
    return "set " + at.to_string() + " = " + doc[at].dump();
  }
  if (op < 7 && objects.size() > 1) {  // a field removed
    const json::json_pointer at = objects[1 + pick(objects.size() - 1)];
    json& o = doc[at];
    if (o.empty()) return "empty object " + at.to_string();
    auto it = o.begin();
    std::advance(it, static_cast<long>(pick(o.size())));
    const std::string key = it.key();
    o.erase(key);
    return "removed " + (at / key).to_string();
  }
  if (op < 8 && !leaves.empty()) {  // a field of the wrong type
    const json::json_pointer at = leaves[pick(leaves.size())];
    const json wrong[] = {json::array(), json::object(), true, nullptr, 3.5, json::array({"1", "2"})};
    doc[at] = wrong[pick(6)];
    return "set " + at.to_string() + " = " + doc[at].dump();
  }
  if (!arrays.empty()) {  // a list entry dropped or doubled
    const json::json_pointer at = arrays[pick(arrays.size())];
    json& a = doc[at];
    if (a.empty()) return "empty list " + at.to_string();
    const std::size_t i = pick(a.size());
    if (pick(2) == 0) {
      a.erase(i);
      return "dropped " + (at / i).to_string();
    }
    a.push_back(a[i]);
    return "doubled " + (at / i).to_string();
  }
  return "nothing";
}

/// Every number the document prints (the strings under "value", "lo", "hi", "from" and "to", and
/// JSON numbers) is finite: a decimal, never nan or inf.
void finite_everywhere(const json& j, const std::string& key, std::vector<std::string>& bad) {
  static const std::regex decimal(R"([-+]?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?)");
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) finite_everywhere(it.value(), it.key(), bad);
  } else if (j.is_array()) {
    for (const auto& x : j) finite_everywhere(x, key, bad);
  } else if (j.is_string()) {
    if ((key == "value" || key == "lo" || key == "hi" || key == "from" || key == "to") &&
        !std::regex_match(j.get<std::string>(), decimal))
      bad.push_back(key + ": " + j.get<std::string>());
  } else if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    bad.push_back(key + ": " + j.dump());
  }
}

/// An exit 0's stdout: a JSON document whose every number is finite (each failure a test error
/// naming `where`).
bool json_of_finite_numbers(const std::string& out, const std::string& where) {
  json doc;
  bool parsed = true;
  try {
    doc = json::parse(out);
  } catch (const std::exception&) {
    parsed = false;
  }
  BOOST_TEST(parsed, where << ": stdout is not JSON: " << out.substr(0, 200));
  std::vector<std::string> bad;
  if (parsed) finite_everywhere(doc, "", bad);
  BOOST_TEST(bad.empty(), where << ": exit 0 with a value that is not a number: " << (bad.empty() ? "" : bad.front()));
  return parsed && bad.empty();
}

}  // namespace

BOOST_AUTO_TEST_CASE(mutated_system_files_keep_the_exit_contract) {
  std::filesystem::create_directories(work);
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(APPELL_SOURCE_DIR + "/data/scenes"))
    if (e.path().filename().string().rfind("system_", 0) == 0) scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  BOOST_REQUIRE(scenes.size() >= 10u);
  std::vector<std::string> scalars;  // those this build compiled (tests/built_scalars.hpp)
  for (const std::string s : {"double", "long-double", "dd", "float128", "mpfr --bits 80", "interval", "mpfi --bits 80"})
    if (appell::test::built(s.substr(0, s.find(' ')))) scalars.push_back(s);
  std::mt19937_64 rng(20261126);
  const int cases = 400;
  std::map<int, int> by_status;
  int linearized = 0;
  for (int c = 0; c < cases; ++c) {
    const std::filesystem::path& from = scenes[std::uniform_int_distribution<std::size_t>(0, scenes.size() - 1)(rng)];
    json doc = json::parse(slurp(from));
    std::string what;
    const int mutations = 1 + static_cast<int>(rng() % 3);
    for (int m = 0; m < mutations; ++m) what += (m ? "; " : "") + mutate(doc, rng);
    const std::filesystem::path file = work / ("case" + std::to_string(c) + ".json");
    std::ofstream(file) << doc.dump(1);
    const std::string scalar = scalars[rng() % scalars.size()];
    // linearize where the file had a linearize section (the bicycle), eval otherwise and half the time there
    const bool linearize = doc.contains("linearize") && rng() % 2 == 0;
    const std::string args = std::string(linearize ? "linearize " : "eval ") + file.string() + " --scalar " + scalar;
    linearized += linearize;
    const outcome o = run(args);
    ++by_status[o.status];
    const std::string where = from.filename().string() + " [" + what + "]: appell " + args;
    bool ok = o.status == 0 || o.status == 2 || o.status == 3;
    BOOST_TEST(ok, where << ": exit " << o.status << "; stderr: " << o.err);
    if (o.status == 2 || o.status == 3) {
      BOOST_TEST(o.out.empty(), where << ": exit " << o.status << " with stdout: " << o.out.substr(0, 200));
      BOOST_TEST(std::count(o.err.begin(), o.err.end(), '\n') == 1, where << ": stderr not one line: " << o.err);
      ok = ok && o.out.empty() && std::count(o.err.begin(), o.err.end(), '\n') == 1;
    } else if (o.status == 0) {
      ok = ok && json_of_finite_numbers(o.out, where);
    }
    if (ok) std::filesystem::remove(file);  // a failing case keeps its scene file
  }
  std::ostringstream tally;
  for (const auto& [s, n] : by_status) tally << " exit " << s << ": " << n << ";";
  BOOST_TEST_MESSAGE(cases << " mutated system files (" << linearized << " through linearize):" << tally.str());
  // The batch must exercise both sides of the contract: results and refusals.
  BOOST_TEST(by_status[0] >= 20);
  BOOST_TEST(by_status[2] >= 100);
}

namespace {

/// A URDF's text mutated: an attribute's value made hostile, an element's line removed, or an
/// element doubled; the text of what it did.
std::string mutate_urdf(std::string& text, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  std::vector<std::pair<std::size_t, std::size_t>> values;  // each attribute value's [begin, end)
  for (std::size_t at = text.find("=\""); at != std::string::npos; at = text.find("=\"", at + 2)) {
    const std::size_t end = text.find('"', at + 2);
    if (end == std::string::npos) break;
    values.emplace_back(at + 2, end);
  }
  const std::size_t op = pick(4);
  if (op < 2 && !values.empty()) {
    const auto [b, e] = values[pick(values.size())];
    const std::string was = text.substr(b, e - b);
    const std::string now = pick(3) == 0 ? hostile_numbers[pick(hostile_numbers.size())]
                                         : was + " " + hostile_numbers[pick(hostile_numbers.size())];
    text.replace(b, e - b, now);
    return "attribute '" + was + "' -> '" + now + "'";
  }
  std::vector<std::size_t> lines{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') lines.push_back(i + 1);
  const std::size_t l = 1 + pick(lines.size() - 1);
  const std::size_t b = lines[l - 1], e = lines[l];
  const std::string line = text.substr(b, e - b);
  if (op == 2) {
    text.erase(b, e - b);
    return "line removed: " + line.substr(0, 60);
  }
  text.insert(e, line);
  return "line doubled: " + line.substr(0, 60);
}

}  // namespace

// The held-out batch through every command (issue 60): the shipped scenes of every model, and
// URDF robots with their files mutated, through eval, convert, reference, simulate and enclose,
// seeded.  The contract as the oracle: exit 0, 2 or 3, within 60 s (`timeout`); on 2 one line on
// stderr, nothing on stdout and no file written; on 0 or 3 from a motion command, a summary.json
// whose `t_reached` is a decimal string; on 0 from eval or convert, a JSON document with only
// finite numbers.
BOOST_AUTO_TEST_CASE(mutated_scenes_and_robots_keep_the_contract_through_every_command) {
  std::filesystem::create_directories(work);
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(APPELL_SOURCE_DIR + "/data/scenes")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("system_", 0) != 0 && name.rfind("urdf_", 0) != 0) scenes.push_back(e.path());  // the built-in models
  }
  std::sort(scenes.begin(), scenes.end());
  BOOST_REQUIRE(scenes.size() >= 10u);
  const std::string arm_urdf = slurp(APPELL_SOURCE_DIR + "/data/urdf/appell_arm.urdf");
  json arm_scene = json::parse(slurp(APPELL_SOURCE_DIR + "/data/scenes/urdf_appell_arm.json"));
  std::mt19937_64 rng(20261203);
  const int cases = 160;
  std::map<std::string, std::map<int, int>> by_command;
  for (int c = 0; c < cases; ++c) {
    const bool robot = rng() % 3 == 0;
    const std::filesystem::path file = work / ("every" + std::to_string(c) + ".json");
    std::string what;
    if (robot) {  // the URDF mutated, the scene kept (its file pointing at the mutated URDF)
      std::string urdf = arm_urdf;
      const int n = 1 + static_cast<int>(rng() % 2);
      for (int m = 0; m < n; ++m) what += (m ? "; " : "") + mutate_urdf(urdf, rng);
      const std::filesystem::path urdf_file = work / ("every" + std::to_string(c) + ".urdf");
      std::ofstream(urdf_file) << urdf;
      json doc = arm_scene;
      doc["file"] = urdf_file.string();
      if (rng() % 2 == 0) what += "; " + mutate(doc, rng);
      std::ofstream(file) << doc.dump(1);
    } else {
      const std::filesystem::path& from = scenes[std::uniform_int_distribution<std::size_t>(0, scenes.size() - 1)(rng)];
      json doc = json::parse(slurp(from));
      const int n = 1 + static_cast<int>(rng() % 2);
      for (int m = 0; m < n; ++m) what += (m ? "; " : "") + mutate(doc, rng);
      what = from.filename().string() + " [" + what + "]";
      std::ofstream(file) << doc.dump(1);
    }
    const std::vector<std::string> commands = robot ? std::vector<std::string>{"eval", "convert", "reference", "simulate", "enclose"}
                                                    : std::vector<std::string>{"eval", "reference", "simulate", "enclose"};
    const std::string command = commands[rng() % commands.size()];
    const std::filesystem::path out = work / ("every_out" + std::to_string(c));
    std::filesystem::remove_all(out);
    std::string args = command + " " + file.string();
    if (command == "eval") args += rng() % 2 ? " --scalar interval" : " --scalar double";
    if (command == "reference") args += " --trajectory 0.1 --every 0.05 --scalar interval --quiet --out " + out.string();
    // a run's cap: 2 s (two of the 160 runs reach it: 20 of this case's 23 s when it was 10 s);
    // 10 s under the sanitizers, which slow every run several times
#ifdef APPELL_SANITIZED
    const std::string cap = " --max-seconds 10";
#else
    const std::string cap = " --max-seconds 2";
#endif
    if (command == "simulate") args += " --t-end 0.2" + cap + " --quiet --out " + out.string();
    if (command == "enclose") args += " --t-end 0.2" + cap + " --quiet --out " + out.string();
    const std::string o_path = (work / "stdout").string(), e_path = (work / "stderr").string();
    const int raw = std::system(("timeout 60 " + std::string(APPELL_BINARY) + " " + args + " >" + o_path + " 2>" + e_path).c_str());
    const outcome o{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(o_path), slurp(e_path)};
    ++by_command[command][o.status];
    const std::string where = what + ": appell " + args;
    bool ok = o.status == 0 || o.status == 2 || o.status == 3;
    BOOST_TEST(ok, where << ": exit " << o.status << " (124: no answer in 60 s); stderr: " << o.err);
    if (o.status == 2) {
      const bool one_line = std::count(o.err.begin(), o.err.end(), '\n') == 1;
      BOOST_TEST(o.out.empty(), where << ": exit 2 with stdout: " << o.out.substr(0, 200));
      BOOST_TEST(one_line, where << ": stderr not one line: " << o.err);
      BOOST_TEST(!std::filesystem::exists(out / "summary.json"), where << ": exit 2, but files were written");
      ok = ok && o.out.empty() && one_line;
    } else if ((o.status == 0 || o.status == 3) && (command == "simulate" || command == "enclose")) {
      // a run that stopped writes what it computed; one that cannot start (the initial state not
      // finite: exit 3) says why in one line, as eval does, and writes nothing
      const bool written = std::filesystem::exists(out / "summary.json");
      const bool refused_at_start =
          o.status == 3 && o.out.empty() && std::count(o.err.begin(), o.err.end(), '\n') == 1 && !std::filesystem::exists(out);
      BOOST_TEST((written || refused_at_start), where << ": exit " << o.status << " without summary.json; stderr: " << o.err);
      if (written) {
        const json s = json::parse(slurp(out / "summary.json"));
        BOOST_TEST((s.contains("t_reached") && s["t_reached"].is_string()), where << ": t_reached " << s.value("t_reached", json()).dump());
      }
    } else if (o.status == 0 && (command == "eval" || command == "convert")) {
      ok = ok && json_of_finite_numbers(o.out, where);
    }
    if (ok) std::filesystem::remove_all(out);
  }
  std::ostringstream tally;
  int accepted = 0, refused = 0;
  for (const auto& [command, statuses] : by_command) {
    tally << " " << command << ":";
    for (const auto& [s, n] : statuses) {
      tally << " exit " << s << " x" << n;
      accepted += s == 0 ? n : 0;
      refused += s == 2 ? n : 0;
    }
    tally << ";";
  }
  BOOST_TEST_MESSAGE(cases << " mutated scenes and robots through every command:" << tally.str());
  BOOST_TEST(accepted >= 15);
  BOOST_TEST(refused >= 40);
  BOOST_TEST(by_command.size() == 5u);
}
