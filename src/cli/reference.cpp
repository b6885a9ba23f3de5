// `appell reference` and `appell score` (reference.hpp).
#include "reference.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "appell/io/scene.hpp"
#include "files.hpp"
#include "motion.hpp"

#ifndef APPELL_VERSION_STRING
#define APPELL_VERSION_STRING "unknown"
#endif
#ifndef APPELL_GIT_REVISION
#define APPELL_GIT_REVISION "unknown"
#endif

namespace appell::cli {
namespace {

// ---------------------------------------------------------------------------
// Files.

std::string read_whole(const std::string& path, const char* what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw input_error(path + ": is a directory, not " + what);
  std::ifstream f(path, std::ios::binary);
  if (!f) throw input_error(path + ": cannot read " + what);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// SHA-256 (FIPS 180-4) of a byte string, as 64 hex digits: the manifest's hash of the inputs.
std::string sha256(const std::string& data) {
  static const std::uint32_t k[64] = {
      0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5, 0xd807aa98,
      0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786,
      0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8,
      0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13,
      0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819,
      0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a,
      0x5b9cca4f, 0x682e6ff3, 0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
      0xc67178f2};
  std::uint32_t h[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::string m = data;
  const std::uint64_t bits = static_cast<std::uint64_t>(data.size()) * 8;
  m += static_cast<char>(0x80);
  while (m.size() % 64 != 56) m += '\0';
  for (int i = 7; i >= 0; --i) m += static_cast<char>((bits >> (8 * i)) & 0xff);
  auto rotr = [](std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); };
  for (std::size_t off = 0; off < m.size(); off += 64) {
    std::uint32_t w[64];
    for (int i = 0; i < 16; ++i)
      w[i] = (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i])) << 24) |
             (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 1])) << 16) |
             (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 2])) << 8) |
             static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 3]));
    for (int i = 16; i < 64; ++i) {
      const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
      const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
      w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], hh = h[7];
    for (int i = 0; i < 64; ++i) {
      const std::uint32_t t1 = hh + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + k[i] + w[i];
      const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
      hh = g;
      g = f;
      f = e;
      e = d + t1;
      d = c;
      c = b;
      b = a;
      a = t1 + t2;
    }
    h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e, h[5] += f, h[6] += g, h[7] += hh;
  }
  std::ostringstream out;
  for (std::uint32_t x : h) out << std::hex << std::setw(8) << std::setfill('0') << x;
  return out.str();
}

// ---------------------------------------------------------------------------
// CSV: comma-separated, fields optionally in double quotes ("" inside one is a quote).

struct csv_table {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> line_of_row;  ///< 1-based line numbers, for messages
};

std::string where(const csv_table& t, int line, std::size_t column) {
  return t.path + " line " + std::to_string(line) + ", column " + std::to_string(column + 1) +
         (column < t.header.size() ? " (" + printable(t.header[column]) + ")" : std::string());
}

csv_table read_csv(const std::string& path, const char* what) {
  csv_table t;
  t.path = path;
  const std::string text = read_whole(path, what);
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, any = false;
  int line = 1, row_line = 1;
  auto end_row = [&] {
    fields.push_back(field);
    field.clear();
    const bool blank = fields.size() == 1 && fields[0].empty() && !any;
    if (!blank) {
      if (t.header.empty()) {
        t.header = fields;
      } else {
        t.rows.push_back(fields);
        t.line_of_row.push_back(row_line);
      }
    }
    fields.clear();
    any = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    if (c == '"') {
      quoted = true;
      any = true;
    } else if (c == ',') {
      fields.push_back(field);
      field.clear();
      any = true;
    } else if (c == '\n') {
      end_row();
      row_line = ++line;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (quoted) throw input_error(path + " line " + std::to_string(row_line) + ": a quoted field is not closed");
  if (!field.empty() || !fields.empty() || any) end_row();
  if (t.header.empty()) throw input_error(path + ": empty (expected a header line naming the columns)");
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.rows[r].size() != t.header.size())
      throw input_error(path + " line " + std::to_string(t.line_of_row[r]) + ": " + std::to_string(t.rows[r].size()) +
                        " fields, the header has " + std::to_string(t.header.size()));
  return t;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// A finite decimal, checked; NaN and infinities named as such.
std::string checked_decimal(const csv_table& t, int line, std::size_t column, const std::string& raw) {
  const std::string s = trim(raw);
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string bare = !lower.empty() && (lower[0] == '-' || lower[0] == '+') ? lower.substr(1) : lower;
  if (bare == "nan" || bare == "inf" || bare == "infinity")
    throw input_error(where(t, line, column) + ": " + printable(s) + " is not a finite number");
  if (s.empty()) throw input_error(where(t, line, column) + ": empty, expected a decimal number");
  try {
    (void)decimal_sign_of_sum({{1, s}});
  } catch (const std::exception& e) {
    throw input_error(where(t, line, column) + ": '" + printable(s) + "' is not a decimal number (" + e.what() + ")");
  }
  return s;
}

/// The exact decimal value of the double nearest to the decimal s (glibc prints doubles exactly).
std::string nearest_binary64(const std::string& s, const std::string& field) {
  const double x = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(x)) throw input_error(field + ": " + printable(s) + " is beyond the range of binary64");
  char buffer[1100];
  std::snprintf(buffer, sizeof buffer, "%.800e", x);
  std::string t = buffer;
  const auto e = t.find('e');
  std::string mantissa = t.substr(0, e);
  const std::string exponent = t.substr(e);
  while (!mantissa.empty() && mantissa.back() == '0') mantissa.pop_back();
  if (!mantissa.empty() && mantissa.back() == '.') mantissa.pop_back();
  return mantissa + exponent;
}

// ---------------------------------------------------------------------------
// Scenes: a column names a field of the scene to replace.

struct field_path {
  std::vector<std::pair<std::string, int>> steps;  ///< key, and list index or -1
};

field_path parse_column(const std::string& name) {
  field_path p;
  std::string part;
  std::vector<std::string> parts;
  std::stringstream ss(name);
  while (std::getline(ss, part, '.')) parts.push_back(part);
  if (parts.size() == 1) parts.insert(parts.begin(), "state");
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

// ---------------------------------------------------------------------------
// One quantity of one state.

struct quantity {
  std::string name, lower, upper, nearest_double, rel_error_bound, tolerance;
  bool decided = false;
  bool derived = false;  ///< of the derived state (evaluation::derived), not a result
};

std::string mpfr_text(const mpfr_value& v, int digits, mpfr_rnd_t rnd) { return mpfr_to_decimal(v, digits, rnd); }

template <Scalar T>
quantity describe(const std::string& name, const T& x, const interval* x53, double scale, double amplification) {
  quantity q;
  q.name = name;
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(x, lo, hi);
  q.lower = lower_string(x);
  q.upper = upper_string(x);
  const double dlo = mpfr_get_d(lo, MPFR_RNDN), dhi = mpfr_get_d(hi, MPFR_RNDN);
  double d = dlo;
  q.decided = dlo == dhi;  // round-to-nearest is monotone: every point of [lo, hi] rounds to it
  if (!q.decided) {
    mpfr_value mid(std::max(mpfr_get_prec(lo), mpfr_get_prec(hi)) + 2);
    mpfr_add(mid, lo, hi, MPFR_RNDN);  // exact at this precision
    mpfr_div_2ui(mid, mid, 1, MPFR_RNDN);
    d = mpfr_get_d(mid, MPFR_RNDN);
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", d);
  q.nearest_double = buffer;
  // |d - exact| <= max(d - lo, hi - d), rounded up; relative to min |x| over the enclosure.
  mpfr_value e1(64), e2(64), e(64);
  mpfr_value dv(53);
  mpfr_set_d(dv, d, MPFR_RNDN);
  mpfr_sub(e1, dv, lo, MPFR_RNDU);
  mpfr_sub(e2, hi, dv, MPFR_RNDU);
  mpfr_max(e, e1, e2, MPFR_RNDU);
  if (mpfr_sgn(lo.get()) > 0 || mpfr_sgn(hi.get()) < 0) {
    mpfr_value m(64);
    if (mpfr_sgn(lo.get()) > 0) mpfr_set(m, lo, MPFR_RNDD);
    else mpfr_neg(m, hi, MPFR_RNDD);
    mpfr_div(e, e, m, MPFR_RNDU);
    q.rel_error_bound = mpfr_text(e, 3, MPFR_RNDU);
  }
  // The suggested tolerance on |engine - exact| for a double-precision engine,
  // from the problem's conditioning: 16 x error_amplification x 2^-53 x the
  // largest |component| of the same result (a vector's components are computed
  // together: a component that is 0, or small, carries the rounding of the
  // others, and of terms that cancel in another engine's formulation), and at
  // least 16 times the width of appell's own interval<double> enclosure of it.
  if (x53) {
    const double w = std::max(boost::numeric::width(*x53), std::ldexp(std::max(amplification, 1.0) * scale, -53));
    mpfr_value tol(64);
    mpfr_set_d(tol, w, MPFR_RNDU);
    mpfr_mul_ui(tol, tol, 16, MPFR_RNDU);
    q.tolerance = mpfr_text(tol, 3, MPFR_RNDU);
  } else {
    q.tolerance = "inf";  // interval<double> cannot certify this state: no double engine can be held to it
  }
  return q;
}

struct state_result {
  std::string name;
  std::vector<std::pair<std::string, std::string>> inputs;
  bool certified = false;
  std::string reason;
  double amplification = 0;
  std::vector<quantity> quantities;
};

template <Scalar T>
void certify(const scene_input& scene, state_result& r) {
  const evaluation<T> e = evaluate<T>(scene);
  std::optional<evaluation<interval>> e53;
  try {
    e53 = evaluate<interval>(scene);
  } catch (const std::exception&) {
  }
  r.amplification = error_amplification(scene);
  for (const bool derived : {false, true}) {
    const auto& group = derived ? e.derived : e.results;
    for (std::size_t i = 0; i < group.size(); ++i) {
      const auto& res = group[i];
      double scale = 0;  // the largest |component| of this result
      for (const T& v : res.values) {
        mpfr_value lo, hi;
        scalar_traits<T>::to_mpfr(v, lo, hi);
        scale = std::max({scale, std::abs(mpfr_get_d(lo, MPFR_RNDN)), std::abs(mpfr_get_d(hi, MPFR_RNDN))});
      }
      for (std::size_t j = 0; j < res.values.size(); ++j) {
        const std::string name = res.is_vector ? res.name + "[" + std::to_string(j) + "]" : res.name;
        const interval* x53 = e53 ? &(derived ? e53->derived : e53->results)[i].values[j] : nullptr;
        r.quantities.push_back(describe(name, res.values[j], x53, scale, r.amplification));
        r.quantities.back().derived = derived;
      }
    }
  }
}

std::string iso_date_utc() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

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
  const auto fields = motion_state_fields(scene);  // input_error naming model when it does not move
  const double t_end = positive_decimal("--trajectory", o.trajectory), every = positive_decimal("--every", o.every);
  if (every > t_end) throw input_error("--every: the output step " + o.every + " is larger than the horizon " + o.trajectory);
  if (t_end / every > 1e6) throw input_error("--every: more than 10^6 states; choose a larger step");
  const horizon_track tr = run_horizon_track<dd>(scene, o.trajectory, o.every, true);
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

struct reference_run::impl {
  reference_options o;
  std::string scene_text, states_text;
  json_value root;
  csv_table states;
  std::size_t first = 0;                        ///< 1 when the first column names the states
  std::vector<field_path> paths;                ///< per value column
  std::vector<std::vector<std::string>> values;  ///< per state, per value column (checked)
};

reference_run::reference_run(const reference_options& o) {
  const auto built = std::make_shared<impl>();
  impl& r = *built;
  r.o = o;
  if (o.scalar != "interval" && o.scalar != "mpfi")
    throw input_error("--scalar: reference values are certified: interval or mpfi, got '" + printable(o.scalar) + "'");
  r.scene_text = read_whole(o.scene, "the scene file");
  r.root = parse_json(r.scene_text);
  if (!o.project.empty()) {  // the scene's "project", set or replaced
    if (r.root.type != json_value::kind::object) throw input_error(o.scene + ": not a JSON object");
    json_value tol;
    tol.type = json_value::kind::string;
    tol.text = o.project;
    bool replaced = false;
    for (auto& m : r.root.members)
      if (m.key == "project") {
        m.value = tol;
        replaced = true;
      }
    if (!replaced) r.root.members.push_back({"project", tol});
  }
  const scene_input base_scene = read_scene(r.root);  // the scene itself must be valid
  if (!o.trajectory.empty()) {
    r.states = trajectory_states(o, base_scene);
    r.states_text = "trajectory " + o.trajectory + " every " + o.every;
  } else if (!o.box.empty()) {
    r.states = box_states(o);
    r.states_text = "box " + o.box + " n " + std::to_string(o.n) + " seed " + std::to_string(o.seed) + " digits " +
                    std::to_string(o.digits);
  } else {
    r.states = read_csv(o.states, "the states file");
    if (r.states.rows.empty()) throw input_error(o.states + ": no states (a header line and no rows)");
    r.states_text = read_whole(o.states, "the states file");
  }
  if (o.binary64_inputs) to_binary64(r.root, "");
  const csv_table& states = r.states;
  // Columns: `state` (names) and fields of the scene.
  if (states.header[0] == "state") r.first = 1;
  for (std::size_t c = r.first; c < states.header.size(); ++c) {
    const std::string& name = states.header[c];
    field_path p;
    try {
      p = parse_column(name);
    } catch (const input_error& e) {
      throw input_error(where(states, 1, c) + ": " + e.what());
    }
    if (!locate(r.root, p))
      throw input_error(where(states, 1, c) + ": not a number of the scene " + o.scene +
                        " (a plain name is a key of its \"state\"; a dotted path starts at its root)");
    for (std::size_t d = r.first; d < c; ++d)
      if (states.header[d] == name) throw input_error(where(states, 1, c) + ": a column named twice");
    r.paths.push_back(p);
  }
  // Every value checked before any is computed: a malformed file writes nothing.
  r.values.resize(states.rows.size());
  for (std::size_t i = 0; i < states.rows.size(); ++i)
    for (std::size_t c = r.first; c < states.header.size(); ++c) {
      std::string v = checked_decimal(states, states.line_of_row[i], c, states.rows[i][c]);
      if (o.binary64_inputs) v = nearest_binary64(v, where(states, states.line_of_row[i], c));
      r.values[i].push_back(v);
    }
  p_ = built;
}

std::string parse_reference_arguments(int argc, char** argv, int first, reference_options& r) {
  std::vector<std::string> positional;
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    const bool takes_value = a == "--states" || a == "--scalar" || a == "--bits" || a == "--inputs" || a == "--out" ||
                             a == "--box" || a == "--n" || a == "--seed" || a == "--digits" || a == "--project" ||
                             a == "--trajectory" || a == "--every";
    if (takes_value && i + 1 >= argc) return a + ": missing value";
    auto count = [](const std::string& v, std::size_t digits_max) {
      return !v.empty() && v.size() <= digits_max && v.find_first_not_of("0123456789") == std::string::npos;
    };
    if (a == "--states") r.states = argv[++i];
    else if (a == "--box") r.box = argv[++i];
    else if (a == "--trajectory") r.trajectory = argv[++i];
    else if (a == "--every") r.every = argv[++i];
    else if (a == "--project") r.project = argv[++i];
    else if (a == "--n") {
      const std::string v = argv[++i];
      if (!count(v, 8) || std::stoull(v) == 0) return "--n: expected a number of states from 1 to 10000000, got '" + v + "'";
      r.n = static_cast<std::size_t>(std::stoull(v));
    } else if (a == "--seed") {
      const std::string v = argv[++i];
      if (!count(v, 19)) return "--seed: expected a nonnegative integer, got '" + v + "'";
      r.seed = std::stoull(v);
    } else if (a == "--digits") {
      const std::string v = argv[++i];
      if (!count(v, 2) || std::stoi(v) > 12) return "--digits: expected 0 to 12, got '" + v + "'";
      r.digits = std::stoi(v);
    }
    else if (a == "--scalar") r.scalar = argv[++i];
    else if (a == "--out") r.out_dir = argv[++i];
    else if (a == "--inputs") {
      const std::string v = argv[++i];
      if (v != "decimal" && v != "binary64") return "--inputs: expected decimal or binary64, got '" + v + "'";
      r.binary64_inputs = v == "binary64";
    } else if (a == "--bits") {
      const std::string b = argv[++i];
      if (b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 6 || std::stoul(b) < 2 ||
          std::stoul(b) > 100000)
        return "--bits: expected an integer from 2 to 100000, got '" + b + "'";
      r.bits = static_cast<unsigned>(std::stoul(b));
    } else if (!a.empty() && a[0] == '-') return "reference: unknown option '" + a + "'";
    else positional.push_back(a);
  }
  if (positional.size() != 1) return "reference: expected one scene";
  if (!r.states.empty() + !r.box.empty() + !r.trajectory.empty() > 1)
    return "reference: --states, --box and --trajectory exclude each other";
  if (r.states.empty() && r.box.empty() && r.trajectory.empty())
    return "reference: --states FILE (or --box SPEC --n N) is required";
  if (!r.trajectory.empty() && r.every.empty()) return "reference: --trajectory needs --every DT";
  if (r.trajectory.empty() && !r.every.empty()) return "reference: --every goes with --trajectory";
  if (!r.box.empty() && r.n == 0) return "reference: --box needs --n N";
  if (r.box.empty() && r.n != 0) return "reference: --n goes with --box";
  if (r.out_dir.empty()) return "reference: --out DIR is required";
  r.scene = positional[0];
  return "";
}

std::size_t reference_run::states() const { return p_->states.rows.size(); }

reference_state_output reference_run::compute(std::size_t i) const {
  const impl& r = *p_;
  state_result s;
  s.name = r.first ? trim(r.states.rows[i][0]) : std::to_string(i + 1);
  json_value scene_json = r.root;
  for (std::size_t c = 0; c < r.paths.size(); ++c) {
    json_value* v = locate(scene_json, r.paths[c]);
    v->type = json_value::kind::string;
    v->text = r.values[i][c];
    s.inputs.emplace_back(r.states.header[c + r.first], r.values[i][c]);
  }
  try {
    const scene_input scene = read_scene(scene_json);
    if (r.o.scalar == "interval") {
      certify<interval>(scene, s);
    } else {
      const mp_precision_scope scope(r.o.bits.value_or(256));
      certify<mpfi>(scene, s);
    }
    s.certified = true;
  } catch (const input_error& e) {
    s.reason = std::string("refused: ") + e.what();
  } catch (const certification_error& e) {
    s.reason = std::string("cannot certify: ") + e.what();
  } catch (const domain_error& e) {
    s.reason = std::string("cannot certify: ") + e.what();
  }
  // The dataset's lines for this state: the same text whichever process computes them.
  reference_state_output out;
  out.certified = s.certified;
  std::ostringstream csv;
  nlohmann::ordered_json line;
  line["state"] = s.name;
  line["status"] = s.certified ? "certified" : "refused";
  nlohmann::ordered_json inputs = nlohmann::ordered_json::object();
  for (const auto& [k, v] : s.inputs) inputs[k] = v;
  line["inputs"] = inputs;
  if (!s.certified) {
    line["reason"] = s.reason;
    csv << csv_field(s.name) << ",,refused,,,,,,," << csv_field(s.reason) << "\n";
  } else {
    line["error_amplification"] = s.amplification;
    nlohmann::ordered_json qs = nlohmann::ordered_json::object(), ds = nlohmann::ordered_json::object();
    for (const quantity& q : s.quantities) {
      csv << csv_field(s.name) << "," << q.name << ",certified," << q.lower << "," << q.upper << "," << q.nearest_double
          << "," << (q.decided ? 1 : 0) << "," << q.rel_error_bound << "," << q.tolerance << ",\n";
      nlohmann::ordered_json j;
      j["lower"] = q.lower;
      j["upper"] = q.upper;
      j["double"] = q.nearest_double;
      j["decided"] = q.decided;
      if (!q.rel_error_bound.empty()) j["rel_error_bound"] = q.rel_error_bound;
      j["tolerance"] = q.tolerance;
      (q.derived ? ds : qs)[q.name] = j;
    }
    line["quantities"] = qs;
    if (!ds.empty()) line["derived"] = ds;
  }
  out.csv = csv.str();
  out.jsonl = line.dump() + "\n";
  return out;
}

int reference_run::write(const std::vector<reference_state_output>& outputs, int processes) const {
  const impl& r = *p_;
  const reference_options& o = r.o;
  if (outputs.size() != states()) throw std::logic_error("reference_run::write: one output per state expected");
  std::string csv = "state,quantity,status,lower,upper,double,decided,rel_error_bound,tolerance,reason\n", jsonl;
  std::size_t refused = 0;
  for (const reference_state_output& s : outputs) {
    csv += s.csv;
    jsonl += s.jsonl;
    if (!s.certified) ++refused;
  }
  const scene_input base = read_scene(r.root);
  unsigned bits = 53;
  if (o.scalar == "mpfi") {
    const mp_precision_scope scope(o.bits.value_or(256));
    bits = scalar_traits<mpfi>::precision_bits();
  }
  nlohmann::ordered_json manifest;
  manifest["appell_version"] = APPELL_VERSION_STRING;
  manifest["git_revision"] = APPELL_GIT_REVISION;
  manifest["command"] = "reference";
  manifest["scene"] = o.scene;
  manifest["model"] = base.model;
  manifest["scalar"] = o.scalar;
  manifest["bits"] = bits;
  manifest["inputs"] = o.binary64_inputs ? "binary64" : "decimal";
  if (!o.project.empty()) manifest["project"] = o.project;
  manifest["scene_sha256"] = sha256(r.scene_text);
  if (!o.trajectory.empty()) {
    manifest["trajectory"] = o.trajectory;
    manifest["every"] = o.every;
    manifest["trajectory_by"] = "simulate in dd (default order and tolerance), each value the nearest double";
  } else if (o.box.empty()) {
    manifest["states_file"] = o.states;
  } else {
    manifest["box"] = o.box;
    manifest["seed"] = o.seed;
    manifest["digits"] = o.digits;
  }
  manifest["states_sha256"] = sha256(r.states_text);
  manifest["date"] = iso_date_utc();
  manifest["processes"] = processes;
  manifest["states"] = outputs.size();
  manifest["certified"] = outputs.size() - refused;
  manifest["refused"] = refused;
  manifest["tolerance_rule"] =
      "16 x max(error_amplification x 2^-53 x the largest |component| of the same result, width of appell's "
      "interval<double> enclosure of the quantity): a bound on |engine - exact| for a double-precision engine; "
      "absolute, so it holds for quantities that are 0";

  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  write_whole(dir, "reference.csv", csv);
  write_whole(dir, "reference.jsonl", jsonl);
  write_whole(dir, "manifest.json", manifest.dump(2) + "\n");
  std::cout << "appell reference: " << outputs.size() - refused << " of " << outputs.size() << " states certified ("
            << o.scalar << ", " << bits << " bits" << (processes > 1 ? ", " + std::to_string(processes) + " processes" : "")
            << "); wrote " << (dir / "reference.csv").string() << ", reference.jsonl, manifest.json\n";
  if (refused) {
    std::cerr << "appell: " << refused << " of " << outputs.size()
              << " states refused or not certified (their reasons are in reference.csv)\n";
    return 3;
  }
  return 0;
}

progress_line::progress_line(std::string what, std::size_t total)
    : what_(std::move(what)), total_(total), start_(std::chrono::steady_clock::now()), last_(start_) {}

void progress_line::update(std::size_t done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(1)) return;
  last_ = now;
  shown_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::cerr << "\r" << what_ << ": " << done << "/" << total_ << " states, " << std::fixed << std::setprecision(0)
            << (seconds > 0 ? done / seconds : 0.0) << " per second" << std::defaultfloat << "   " << std::flush;
}

progress_line::~progress_line() {
  if (shown_) std::cerr << "\r" << std::string(70, ' ') << "\r" << std::flush;
}

int reference(const reference_options& o) {
  const reference_run run(o);
  std::vector<reference_state_output> outputs;
  outputs.reserve(run.states());
  {
    progress_line progress("appell reference", run.states());
    for (std::size_t i = 0; i < run.states(); ++i) {
      outputs.push_back(run.compute(i));
      progress.update(i + 1);
    }
  }
  return run.write(outputs, 1);
}

// ---------------------------------------------------------------------------
// score

namespace {

struct reference_value {
  mpfr_value lower{256}, upper{256}, tolerance{64};
  bool tolerance_finite = true;
};

struct quantity_score {
  std::size_t n = 0, inside = 0, within = 0;
  double worst_digits = INFINITY;
  std::string worst_state;
  std::vector<double> digits;  ///< per value, for the median
  double median = INFINITY;
  double worst_excess = 0;  ///< the largest distance / tolerance
  std::string worst_tolerance_state;
};

}  // namespace

int score(const score_options& o) {
  const std::string ref_path = (std::filesystem::path(o.reference_dir) / "reference.csv").string();
  const csv_table ref = read_csv(ref_path, "the reference dataset (reference.csv)");
  const std::vector<std::string> expected = {"state", "quantity", "status", "lower", "upper", "double",
                                             "decided", "rel_error_bound", "tolerance", "reason"};
  if (ref.header != expected) throw input_error(ref_path + " line 1: not a reference.csv written by appell reference");
  std::map<std::pair<std::string, std::string>, reference_value> values;
  std::map<std::string, int> quantity_names;
  std::map<std::string, bool> state_certified;
  for (std::size_t r = 0; r < ref.rows.size(); ++r) {
    const auto& row = ref.rows[r];
    state_certified[row[0]] = row[2] == "certified";
    if (row[2] != "certified") continue;
    reference_value v;
    decimal_to_mpfr(row[3], v.lower, MPFR_RNDD);
    decimal_to_mpfr(row[4], v.upper, MPFR_RNDU);
    if (row[8] == "inf") v.tolerance_finite = false;
    else decimal_to_mpfr(row[8], v.tolerance, MPFR_RNDU);
    values.emplace(std::make_pair(row[0], row[1]), std::move(v));
    quantity_names.emplace(row[1], static_cast<int>(quantity_names.size()));
  }
  const csv_table other = read_csv(o.other, "the values to score");
  if (other.header.empty() || other.header[0] != "state")
    throw input_error(where(other, 1, 0) + ": the first column must be `state` (the states' names in the reference)");
  for (std::size_t c = 1; c < other.header.size(); ++c)
    if (!quantity_names.count(other.header[c]))
      throw input_error(where(other, 1, c) + ": not a quantity of the reference " + o.reference_dir);
  std::vector<quantity_score> scores(other.header.size());
  std::size_t skipped = 0;
  for (std::size_t r = 0; r < other.rows.size(); ++r) {
    const int line = other.line_of_row[r];
    const std::string state = trim(other.rows[r][0]);
    const auto st = state_certified.find(state);
    if (st == state_certified.end())
      throw input_error(where(other, line, 0) + ": no state '" + printable(state) + "' in the reference");
    if (!st->second) {
      ++skipped;
      continue;
    }
    for (std::size_t c = 1; c < other.header.size(); ++c) {
      const std::string text = checked_decimal(other, line, c, other.rows[r][c]);
      const reference_value& v = values.at({state, other.header[c]});
      mpfr_value x(256);
      decimal_to_mpfr(text, x, MPFR_RNDN);
      quantity_score& s = scores[c];
      ++s.n;
      const bool inside = mpfr_cmp(v.lower, x) <= 0 && mpfr_cmp(x, v.upper) <= 0;
      if (inside) ++s.inside;
      // |x - exact| <= max(|x - lower|, |x - upper|); its distance to the enclosure is the least it can be.
      mpfr_value a(64), b(64), err(64), dist(64);
      mpfr_sub(a, x, v.lower, MPFR_RNDU);
      mpfr_abs(a, a, MPFR_RNDU);
      mpfr_sub(b, v.upper, x, MPFR_RNDU);
      mpfr_abs(b, b, MPFR_RNDU);
      mpfr_max(err, a, b, MPFR_RNDU);
      if (inside) mpfr_set_zero(dist, 1);
      else mpfr_min(dist, a, b, MPFR_RNDD);
      // correct digits: -log10(err / min |exact|), where the enclosure excludes 0
      double digits = INFINITY;
      if (mpfr_sgn(v.lower.get()) > 0 || mpfr_sgn(v.upper.get()) < 0) {
        mpfr_value m(64);
        if (mpfr_sgn(v.lower.get()) > 0) mpfr_set(m, v.lower, MPFR_RNDD);
        else mpfr_neg(m, v.upper, MPFR_RNDD);
        mpfr_div(err, err, m, MPFR_RNDU);
        digits = mpfr_zero_p(err.get()) ? INFINITY : -std::log10(mpfr_get_d(err, MPFR_RNDU));
      } else {
        digits = mpfr_zero_p(err.get()) ? INFINITY : -std::log10(mpfr_get_d(err, MPFR_RNDU));  // absolute, for values at 0
      }
      if (digits < s.worst_digits) {
        s.worst_digits = digits;
        s.worst_state = state;
      }
      s.digits.push_back(digits);
      const bool within = v.tolerance_finite ? mpfr_cmp(dist, v.tolerance) <= 0 : true;
      if (within) ++s.within;
      if (v.tolerance_finite && !within) {
        const double excess = mpfr_zero_p(v.tolerance.get()) ? INFINITY
                                                              : mpfr_get_d(dist, MPFR_RNDU) / mpfr_get_d(v.tolerance, MPFR_RNDD);
        if (excess > s.worst_excess) {
          s.worst_excess = excess;
          s.worst_tolerance_state = state;
        }
      }
    }
  }
  bool all_within = true, all_digits = true;
  std::cout << "appell score " << o.other << " against " << o.reference_dir << "\n\n";
  auto digits_text = [](double d) {
    std::ostringstream t;
    if (std::isinf(d)) t << "exact";
    else t << std::fixed << std::setprecision(1) << d;
    return t.str();
  };
  std::cout << std::left << std::setw(24) << "quantity" << std::right << std::setw(8) << "values" << std::setw(9)
            << "inside" << std::setw(13) << "within tol." << std::setw(12) << "min digits" << std::setw(15)
            << "median digits" << "  worst state\n";
  for (std::size_t c = 1; c < other.header.size(); ++c) {
    quantity_score& s = scores[c];
    all_within = all_within && s.within == s.n;
    std::sort(s.digits.begin(), s.digits.end());
    const double median = s.digits.empty() ? INFINITY
                          : s.digits.size() % 2 ? s.digits[s.digits.size() / 2]
                                                : (s.digits[s.digits.size() / 2 - 1] + s.digits[s.digits.size() / 2]) / 2;
    s.median = median;
    if (o.min_digits && median < *o.min_digits) all_digits = false;
    std::cout << std::left << std::setw(24) << other.header[c] << std::right << std::setw(8) << s.n << std::setw(9)
              << s.inside << std::setw(13) << s.within << std::setw(12) << digits_text(s.worst_digits) << std::setw(15)
              << digits_text(median) << "  " << s.worst_state
              << (s.within < s.n ? " (outside tolerance: worst " + s.worst_tolerance_state + ")" : "") << "\n";
  }
  if (skipped) std::cout << "\n" << skipped << " rows at states the reference could not certify: not scored\n";
  std::cout << "\n" << (all_within ? "every value within the suggested tolerance" : "values outside the suggested tolerance");
  if (o.min_digits)
    std::cout << "; " << (all_digits ? "every quantity has" : "not every quantity has") << " a median of at least "
              << *o.min_digits << " correct digits";
  std::cout << "\n";
  if (!o.plot.empty()) {
    const std::filesystem::path dat =
        std::filesystem::temp_directory_path() / ("appell-score-" + std::to_string(::getpid()) + ".dat");
    {
      std::ofstream f(dat);
      for (std::size_t c = 1; c < other.header.size(); ++c)
        f << c << " " << (std::isinf(scores[c].median) ? 17.0 : std::min(scores[c].median, 17.0)) << " "
          << (std::isinf(scores[c].worst_digits) ? 17.0 : std::min(scores[c].worst_digits, 17.0)) << " \""
          << other.header[c] << "\"\n";
    }
    const std::string script = "set terminal png size 900,500 noenhanced\nset output '" + o.plot +
                               "'\nset style fill solid 0.6\nset boxwidth 0.6\nset yrange [0:17.5]\n"
                               "set ylabel 'correct decimal digits'\nset key below\nset title 'appell score: " +
                               std::filesystem::path(o.other).filename().string() +
                               "'\nset xtics rotate by -30\nset grid y\nplot '" + dat.string() +
                               "' using 1:2:xtic(4) with boxes title 'median over the states', '' using 1:3 with points pt 7 ps 1.5 "
                               "title 'worst state'" +
                               (o.min_digits ? ", " + std::to_string(*o.min_digits) + " with lines dt 2 title 'required'" : "") +
                               "\n";
    bool plotted = false;
    if (FILE* gp = popen("gnuplot 2>&1", "w")) {
      std::fputs(script.c_str(), gp);
      plotted = pclose(gp) == 0 && std::filesystem::exists(o.plot);
    }
    std::filesystem::remove(dat);
    std::cout << (plotted ? "wrote " + o.plot : std::string("no plot: gnuplot not found; install gnuplot-nox")) << "\n";
  }
  return all_within && all_digits ? 0 : 1;
}

}  // namespace appell::cli
