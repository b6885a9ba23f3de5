// A number of a scene named by a path, and the exact decimal of a double (io/scene_fields.hpp).
#include "appell/io/scene_fields.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "appell/errors.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell {

field_path parse_column(const std::string& name, bool plain_is_state) {
  field_path p;
  std::string part;
  std::vector<std::string> parts;
  std::stringstream ss(name);
  while (std::getline(ss, part, '.')) parts.push_back(part);
  if (parts.size() == 1 && plain_is_state) parts.insert(parts.begin(), "state");
  for (const std::string& q : parts) {
    const auto b = q.find('[');
    if (b == std::string::npos) {
      p.steps.emplace_back(q, -1);
      continue;
    }
    const std::string index = q.substr(b + 1, q.size() - b - 2);
    if (q.back() != ']' || index.empty() || index.size() > 4 || index.find_first_not_of("0123456789") != std::string::npos)
      throw input_error("'" + printable(name) + "' is not a field name (key, key[i] or a.b.c)");
    p.steps.emplace_back(q.substr(0, b), std::stoi(index));
  }
  return p;
}

json_value* locate(json_value& root, const field_path& p) {
  json_value* v = &root;
  for (const auto& [key, index] : p.steps) {
    if (v->type != json_value::kind::object) return nullptr;
    json_value* next = nullptr;
    for (auto& m : v->members)
      if (m.key == key) next = &m.value;
    if (!next) return nullptr;
    v = next;
    if (index >= 0) {
      if (v->type != json_value::kind::array || index >= static_cast<int>(v->items.size())) return nullptr;
      v = &v->items[static_cast<std::size_t>(index)];
    }
  }
  return v->type == json_value::kind::number || v->type == json_value::kind::string ? v : nullptr;
}

/// Every decimal of the scene (numbers, and strings that are decimals) replaced by its nearest binary64.
void to_binary64(json_value& v, const std::string& path) {
  if (v.type == json_value::kind::number || v.type == json_value::kind::string) {
    try {
      (void)decimal_sign_of_sum({{1, v.text}});
    } catch (const std::exception&) {
      return;  // not a decimal (an expression, a name): kept as written
    }
    v.text = nearest_binary64(v.text, path);
    v.type = json_value::kind::string;
  } else if (v.type == json_value::kind::array) {
    for (std::size_t i = 0; i < v.items.size(); ++i) to_binary64(v.items[i], path + "[" + std::to_string(i) + "]");
  } else if (v.type == json_value::kind::object) {
    for (auto& m : v.members)
      if (m.key != "model") to_binary64(m.value, path.empty() ? m.key : path + "." + m.key);
  }
}

/// The exact decimal value of the double nearest to the decimal s.
std::string nearest_binary64(const std::string& s, const std::string& field) {
  const double x = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(x)) throw input_error(field + ": " + printable(s) + " is beyond the range of binary64");
  return exact_decimal(x, field);
}

/// glibc prints a double exactly: 767 significant digits are the most a double has.
std::string exact_decimal(double x, const std::string& field) {
  if (!std::isfinite(x)) throw input_error(field + ": " + (std::isnan(x) ? "NaN" : "an infinity") + " is not a number of a scene");
  // x = mant * 2^exp2 with mant odd: its exact decimal has the digits of mant * 5^-exp2 (exp2 < 0)
  // or of an integer of log10(x) + 1 digits; print that many (an upper bound: the zeros beyond are
  // cut below), not a fixed 800 (a fifteenth of the time for a double near 1).
  int digits = 1;
  if (x != 0) {
    int e = 0;
    const double m = std::frexp(std::fabs(x), &e);
    auto mant = static_cast<unsigned long long>(std::ldexp(m, 53));
    int exp2 = e - 53;
    while ((mant & 1) == 0) mant >>= 1, ++exp2;
    const double log10_mant = std::log10(static_cast<double>(mant));
    digits = exp2 >= 0 ? static_cast<int>(log10_mant + exp2 * 0.30103) + 3
                       : static_cast<int>(log10_mant - exp2 * 0.69897000433601886) + 3;
  }
  char buffer[1100];
  std::snprintf(buffer, sizeof buffer, "%.*e", std::min(digits, 800), x);
  std::string t = buffer;
  const auto e = t.find('e');
  std::string mantissa = t.substr(0, e);
  const std::string exponent = t.substr(e);
  while (!mantissa.empty() && mantissa.back() == '0') mantissa.pop_back();
  if (!mantissa.empty() && mantissa.back() == '.') mantissa.pop_back();
  return mantissa + exponent;
}

}  // namespace appell
