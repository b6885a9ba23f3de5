// The sweeps of the stability study (appell/studies/extreme_sweeps.hpp): the scenes are data,
// data/extremes/sweeps.json, which CMake compiles into the library as text
// (generated/extreme_sweeps_data.cpp); here each sweep's placeholders become the decimals of
// their values at every k of the sweep.
#include <mpfr.h>

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "appell/scalar/format.hpp"
#include "appell/scalar/traits.hpp"
#include "appell/studies/extreme_sweeps.hpp"

namespace appell::studies {
namespace detail {
extern const char* const extreme_sweeps_json;  // data/extremes/sweeps.json
}  // namespace detail

namespace {

using json = nlohmann::ordered_json;

std::string pow10(int k) { return "1e" + std::to_string(k); }

// pi - 10^-k as a 60-digit decimal
std::string pi_minus(int k) {
  mpfr_value v(400), e(400);
  mpfr_const_pi(v, MPFR_RNDN);
  mpfr_set_ui(e, 10, MPFR_RNDN);
  mpfr_pow_si(e, e, -k, MPFR_RNDN);
  mpfr_sub(v, v, e, MPFR_RNDN);
  return mpfr_to_decimal(v, 60, MPFR_RNDN);
}

// 1 - 10^-k and 3 + 10^-k as exact decimals
std::string one_minus(int k) { return "0." + std::string(static_cast<std::size_t>(k), '9'); }
std::string three_plus(int k) { return "3." + std::string(static_cast<std::size_t>(k - 1), '0') + "1"; }

[[noreturn]] void bad_data(const std::string& what) {
  throw std::logic_error("data/extremes/sweeps.json (compiled into the library): " + what);
}

/// The decimal a placeholder stands for at k.
std::string value_at(const std::string& placeholder, int k) {
  if (placeholder == "10^-k") return pow10(-k);
  if (placeholder == "10^k") return pow10(k);
  if (placeholder == "pi-10^-k") return pi_minus(k);
  if (placeholder == "1-10^-k") return one_minus(k);
  if (placeholder == "3+10^-k") return three_plus(k);
  bad_data("unknown placeholder {" + placeholder + "}");
}

/// s with every {placeholder} replaced by its value at k.
std::string substitute(const std::string& s, int k) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t open; (open = s.find('{', from)) != std::string::npos;) {
    const std::size_t close = s.find('}', open);
    if (close == std::string::npos) bad_data("an unclosed '{' in \"" + s + "\"");
    out += s.substr(from, open - from);
    out += value_at(s.substr(open + 1, close - open - 1), k);
    from = close + 1;
  }
  return out + s.substr(from);
}

/// The scene at k: every string of it substituted, keys and order kept.
json scene_at(const json& scene, int k) {
  if (scene.is_string()) return substitute(scene.get<std::string>(), k);
  json out = scene;
  if (scene.is_object())
    for (auto& [key, value] : out.items()) value = scene_at(value, k);
  if (scene.is_array())
    for (auto& value : out) value = scene_at(value, k);
  return out;
}

}  // namespace

std::vector<sweep> extreme_sweeps() {
  const json data = json::parse(detail::extreme_sweeps_json);
  std::vector<sweep> sweeps;
  for (const json& s : data.at("sweeps")) {
    sweep w{s.at("name").get<std::string>(), s.at("what").get<std::string>(), s.at("x_label").get<std::string>(), {}};
    const std::string x = s.at("x").get<std::string>();
    if (x != "k" && x != "-k") bad_data("sweep " + w.name + ": x is \"k\" or \"-k\", not \"" + x + "\"");
    for (const json& kj : s.at("k")) {
      const int k = kj.get<int>();
      w.points.push_back({substitute(s.at("param").get<std::string>(), k), static_cast<double>(x == "k" ? k : -k),
                          scene_at(s.at("scene"), k).dump()});
    }
    sweeps.push_back(std::move(w));
  }
  return sweeps;
}

}  // namespace appell::studies
