// The states of `appell reference` (states.hpp).
#include "states.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "appell/scalar/decimal.hpp"
#include "motion_commands.hpp"

namespace appell::cli {

/// A decimal with at most `digits` decimals as an integer count of 10^-digits; input_error otherwise.
long long scaled_decimal(const std::string& text, int digits, const std::string& field) {
  std::size_t i = 0;
  const bool negative = !text.empty() && (text[0] == '-' || text[0] == '+') ? text[i++] == '-' : false;
  std::string whole, fraction;
  bool dot = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '.' && !dot) dot = true;
    else if (c >= '0' && c <= '9') (dot ? fraction : whole) += c;
    else throw input_error(field + ": '" + printable(text) + "' is not a plain decimal (digits, one point, a sign)");
  }
  if (whole.empty() && fraction.empty()) throw input_error(field + ": '" + printable(text) + "' is not a number");
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  if (static_cast<int>(fraction.size()) > digits)
    throw input_error(field + ": '" + printable(text) + "' has more than --digits " + std::to_string(digits) + " decimals");
  fraction.resize(static_cast<std::size_t>(digits), '0');
  const std::string all = whole + fraction;
  const std::size_t first = std::min(all.find_first_not_of('0'), all.size());
  if (all.size() - first > 17) throw input_error(field + ": '" + printable(text) + "' is too large for the box's grid");
  const long long v = all.size() == first ? 0 : std::stoll(all.substr(first));
  return negative ? -v : v;
}

std::string unscaled_decimal(long long v, int digits) {
  std::string t = std::to_string(v < 0 ? -v : v);
  if (static_cast<int>(t.size()) <= digits) t.insert(0, static_cast<std::size_t>(digits + 1) - t.size(), '0');
  if (digits > 0) t.insert(t.size() - static_cast<std::size_t>(digits), ".");
  return (v < 0 ? "-" : "") + t;
}

/// An integer uniform on [0, range] from mt19937_64's raw outputs (rejection: no implementation-defined distribution).
std::uint64_t uniform_up_to(std::mt19937_64& rng, std::uint64_t range) {
  if (range == UINT64_MAX) return rng();
  const std::uint64_t span = range + 1, limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t x;
  do x = rng();
  while (x >= limit);
  return x % span;
}

/// The states of --trajectory T --every DT: the scene's motion by simulate in dd, each value
/// the double nearest to it (what an engine in binary64 would be given), as a states table.
csv_table trajectory_states(const reference_options& o, const scene_input& scene) {
  const auto fields = motion::state_fields(scene);  // input_error naming model when it does not move
  const double t_end = positive_decimal("--trajectory", o.trajectory), every = positive_decimal("--every", o.every);
  if (every > t_end) throw input_error("--every: the output step " + o.every + " is larger than the horizon " + o.trajectory);
  if (t_end / every > 1e6) throw input_error("--every: more than 10^6 states; choose a larger step");
  const motion::horizon_track tr = motion::track(scene, "dd", std::nullopt, o.trajectory, o.every);
  csv_table t;
  t.path = "--trajectory";
  t.header.push_back("state");
  for (const auto& f : fields) t.header.push_back(f);
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    std::vector<std::string> row{"t=" + to_decimal(from_decimal<double>(tr.t[i]))};
    for (const auto& v : tr.x[i]) row.push_back(to_decimal(from_decimal<double>(v)));
    t.rows.push_back(std::move(row));
    t.line_of_row.push_back(static_cast<int>(i) + 2);
  }
  return t;
}

/// The states of --box SPEC --n N --seed S --digits D, as a table like a states file's.
csv_table box_states(const reference_options& o) {
  csv_table t;
  t.path = "--box";
  if (o.n == 0 || o.n > 10000000) throw input_error("--n: expected a number of states from 1 to 10000000");
  if (o.digits < 0 || o.digits > 12) throw input_error("--digits: expected 0 to 12");
  struct range {
    long long lo, hi;
  };
  std::vector<range> ranges;
  t.header.push_back("state");
  std::stringstream spec(o.box);
  std::string item;
  while (std::getline(spec, item, ',')) {
    const auto eq = item.find('='), colon = item.find(':', eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || colon == std::string::npos || eq == 0)
      throw input_error("--box: '" + printable(item) + "' is not field=lo:hi");
    const std::string field = trim(item.substr(0, eq));
    const std::string where_field = "--box " + field;
    const long long lo = scaled_decimal(trim(item.substr(eq + 1, colon - eq - 1)), o.digits, where_field + " (lower end)");
    const long long hi = scaled_decimal(trim(item.substr(colon + 1)), o.digits, where_field + " (upper end)");
    if (hi < lo) throw input_error(where_field + ": the lower end exceeds the upper end");
    t.header.push_back(field);
    ranges.push_back({lo, hi});
  }
  if (ranges.empty()) throw input_error("--box: no field=lo:hi given");
  std::mt19937_64 rng(o.seed);
  for (std::size_t i = 0; i < o.n; ++i) {
    std::vector<std::string> row{"b" + std::to_string(i)};
    for (const range& r : ranges)
      row.push_back(unscaled_decimal(r.lo + static_cast<long long>(uniform_up_to(rng, static_cast<std::uint64_t>(r.hi - r.lo))),
                                     o.digits));
    t.rows.push_back(row);
    t.line_of_row.push_back(static_cast<int>(i) + 1);
  }
  return t;
}

}  // namespace appell::cli
