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

}  // namespace

BOOST_AUTO_TEST_CASE(mutated_system_files_keep_the_exit_contract) {
  std::filesystem::create_directories(work);
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(APPELL_SOURCE_DIR + "/data/scenes"))
    if (e.path().filename().string().rfind("system_", 0) == 0) scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  BOOST_REQUIRE(scenes.size() >= 10u);
  const std::vector<std::string> scalars = {"double", "long-double", "dd", "float128", "mpfr --bits 80",
                                            "interval", "mpfi --bits 80"};
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
      json out;
      bool parsed = true;
      try {
        out = json::parse(o.out);
      } catch (const std::exception& e) {
        parsed = false;
      }
      BOOST_TEST(parsed, where << ": stdout is not JSON: " << o.out.substr(0, 200));
      std::vector<std::string> bad;
      if (parsed) finite_everywhere(out, "", bad);
      BOOST_TEST(bad.empty(), where << ": exit 0 with a value that is not a number: " << (bad.empty() ? "" : bad.front()));
      ok = ok && parsed && bad.empty();
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
