// The IEEE 1788 test vectors (ITF1788, data/itf1788, read at run time from APPELL_ITF1788_DIR)
// run against appell's rigorous scalars `interval`, `mpfi` and `arb`.
//
// Each `op [args] = [result];` line of the .itl files whose operation appell
// implements (pos neg add sub mul div sqr sqrt exp log sin cos tan atan pown abs)
// is a case.  Bounds are read as the tightest enclosure of the literal (lower
// bound rounded down, upper bound rounded up, via MPFR's mpfr_strtofr); the
// listed result is read the same way.  The computed result must contain the
// listed one (a failure otherwise); equality of the bounds (-0 == +0) counts as
// tightest and is reported, not required.  An expected [empty] is contained in
// anything; it is tight when our function returns empty or throws
// appell::domain_error.  Decorated cases (_com _dac _def _trv _ill), [nai] and
// operations appell does not implement are counted and skipped.
// A few listed bounds are decimals that are not binary64 numbers (mpfi.itl:
// "-8.0e-17", meant as the double nearest to it, which is the exact result).
// A result that misses such a bound's outward reading but contains its
// round-to-nearest reading is counted and listed as "inexact vector literal",
// not as a failure.  APPELL_ITF1788_VERBOSE=1 lists the non-tightest cases.
//
// mpfi (and arb, the same way) runs at set_mp_precision_bits(53) (exactly 53 bits: appell's backend)
// on the cases without an empty input.  Its bounds have an
// unbounded exponent range and no subnormals, so they are first rounded
// outward into binary64 (appell::round_to_double, subnormals and overflow
// honoured) and then compared with the listed bounds: if the mpfi result
// encloses the exact result, its outward binary64 rounding encloses the listed
// tightest binary64 enclosure.  An mpfi result with a NaN bound encloses nothing.
//
// If the vectors are absent the test says so and exits with 77 (CTest: skipped).
#define BOOST_TEST_MODULE itf1788
#include <boost/test/unit_test.hpp>

#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/scalar/interval.hpp"
#include "appell/scalar/traits.hpp"
#include "appell/scalar/types.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// --- one interval literal of an .itl file ----------------------------------
struct literal {
  bool empty = false;
  double lo = 0, hi = 0;  // tightest binary64 enclosure of the literal
  // A bound that is not a binary64 number ("-8.0e-17" in mpfi.itl) is also
  // kept rounded to nearest: the value the vector's authors meant, as the C
  // compiler of the ITF1788 converters reads it.
  bool lo_exact = true, hi_exact = true;
  double lo_near = 0, hi_near = 0;
};

struct test_case {
  std::string where;  // file:line
  std::string text;   // the statement, for messages
  std::string op;
  std::vector<literal> args;
  int n = 0;  // exponent of pown
  literal expected;
  // An input bound is a decimal that is not a binary64 number ("13.1"): read
  // outward it is a one-ulp interval, so the listed result (computed for the
  // nearest double) cannot be met exactly.
  bool inexact_input = false;
};

struct corpus {
  std::vector<std::string> files;
  std::vector<test_case> cases;
  std::size_t statements = 0;
  std::size_t skipped_decorated = 0;  // decorated or [nai]
  std::size_t skipped_not_implemented = 0;
  std::map<std::string, std::size_t> not_implemented_ops;
  std::vector<std::string> parse_errors;
};

const std::set<std::string>& implemented_ops() {
  static const std::set<std::string> ops{"pos", "neg", "add", "sub", "mul", "div",
                                         "sqr", "sqrt", "exp", "log", "sin", "cos",
                                         "tan", "atan", "pown", "abs"};
  return ops;
}

std::size_t arity(const std::string& op) {
  if (op == "add" || op == "sub" || op == "mul" || op == "div") return 2;
  return 1;  // pown: one interval and an integer
}

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// A bound literal rounded to binary64 in direction rnd; nullopt if malformed.
std::optional<double> parse_bound(const std::string& token, mpfr_rnd_t rnd) {
  const std::string t = lower_case(trim(token));
  if (t.empty()) return std::nullopt;
  if (t == "infinity" || t == "+infinity" || t == "inf" || t == "+inf") return inf;
  if (t == "-infinity" || t == "-inf") return -inf;
  // Syntax check first: mpfr_strtofr must consume the whole token.
  {
    mpfr_t probe;
    mpfr_init2(probe, 53);
    char* end = nullptr;
    mpfr_strtofr(probe, t.c_str(), &end, 0, MPFR_RNDN);
    const bool whole = end == t.c_str() + t.size() && end != t.c_str();
    const bool number = mpfr_number_p(probe) != 0;
    mpfr_clear(probe);
    if (!whole || !number) return std::nullopt;
  }
  return appell::produce_double(
      [t](mpfr_ptr out, mpfr_rnd_t r) {
        return mpfr_strtofr(out, t.c_str(), nullptr, 0, r);
      },
      rnd);
}

// "[a,b]", "[a]", "[empty]", "[entire]" (no decoration).  nullopt if malformed.
std::optional<literal> parse_interval(const std::string& token) {
  if (token.size() < 2 || token.front() != '[' || token.back() != ']') return std::nullopt;
  const std::string body = lower_case(trim(token.substr(1, token.size() - 2)));
  literal r;
  if (body == "empty") {
    r.empty = true;
    return r;
  }
  if (body == "entire") {
    r.lo = -inf;
    r.hi = inf;
    return r;
  }
  const auto comma = body.find(',');
  const std::string a = comma == std::string::npos ? body : body.substr(0, comma);
  const std::string b = comma == std::string::npos ? body : body.substr(comma + 1);
  const auto lo = parse_bound(a, MPFR_RNDD);
  const auto hi = parse_bound(b, MPFR_RNDU);
  if (!lo || !hi) return std::nullopt;
  if (*lo == inf || *hi == -inf || !(*lo <= *hi)) return std::nullopt;  // not an interval
  r.lo = *lo;
  r.hi = *hi;
  r.lo_near = *parse_bound(a, MPFR_RNDN);
  r.hi_near = *parse_bound(b, MPFR_RNDN);
  r.lo_exact = *parse_bound(a, MPFR_RNDU) == r.lo;
  r.hi_exact = *parse_bound(b, MPFR_RNDD) == r.hi;
  return r;
}

// The file with comments blanked out (newlines kept, so line numbers hold).
std::string strip_comments(const std::string& s) {
  std::string out = s;
  bool in_string = false;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const char c = out[i];
    if (in_string) {
      if (c == '\\' && i + 1 < out.size()) ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
      --i;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      i += 2;
      while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
        if (out[i] != '\n') out[i] = ' ';
        ++i;
      }
      if (i < out.size()) out[i] = out[i + 1] = ' ', ++i;
    }
  }
  return out;
}

// Tokens of a statement: bracketed intervals with their decoration suffix
// ("[1.0, 2.0]_com"), quoted strings, and whitespace-separated words.
std::vector<std::string> tokenize(const std::string& s) {
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < s.size()) {
    if (std::isspace(static_cast<unsigned char>(s[i]))) {
      ++i;
      continue;
    }
    std::size_t start = i;
    if (s[i] == '[') {
      while (i < s.size() && s[i] != ']') ++i;
      if (i < s.size()) ++i;
      while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;  // suffix
    } else if (s[i] == '"') {
      ++i;
      while (i < s.size() && s[i] != '"') i += s[i] == '\\' ? 2 : 1;
      if (i < s.size()) ++i;
    } else {
      while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    tokens.push_back(s.substr(start, i - start));
  }
  return tokens;
}

bool is_decorated_or_nai(const std::string& token) {
  if (token.empty() || token.front() != '[') return false;
  if (token.back() != ']') return true;  // a suffix such as _com
  return lower_case(token).find("nai") != std::string::npos;
}

void parse_statement(corpus& c, const std::string& file, std::size_t line,
                     const std::string& statement) {
  const std::string where = file + ":" + std::to_string(line);
  const std::vector<std::string> tokens = tokenize(statement);
  if (tokens.empty()) return;
  ++c.statements;
  const std::string& op = tokens[0];
  if (!implemented_ops().count(op)) {
    ++c.skipped_not_implemented;
    ++c.not_implemented_ops[op];
    return;
  }
  const auto eq = std::find(tokens.begin(), tokens.end(), "=");
  if (eq == tokens.end()) {
    c.parse_errors.push_back(where + ": no '=' in: " + statement);
    return;
  }
  // Results end at a `signal` trailer, if any.
  auto res_end = std::find(eq + 1, tokens.end(), "signal");
  for (auto it = tokens.begin() + 1; it != res_end; ++it) {
    if (is_decorated_or_nai(*it)) {
      ++c.skipped_decorated;
      return;
    }
  }
  test_case tc;
  tc.where = where;
  tc.text = trim(statement);
  tc.op = op;
  const std::vector<std::string> args(tokens.begin() + 1, eq);
  const std::vector<std::string> results(eq + 1, res_end);
  const std::size_t want = arity(op) + (op == "pown" ? 1 : 0);
  if (args.size() != want || results.size() != 1) {
    c.parse_errors.push_back(where + ": unexpected shape: " + tc.text);
    return;
  }
  for (std::size_t k = 0; k < arity(op); ++k) {
    const auto x = parse_interval(args[k]);
    if (!x) {
      c.parse_errors.push_back(where + ": bad interval '" + args[k] + "'");
      return;
    }
    tc.args.push_back(*x);
    if (!x->empty && (!x->lo_exact || !x->hi_exact)) tc.inexact_input = true;
  }
  if (op == "pown") {
    try {
      std::size_t used = 0;
      const long n = std::stol(args[1], &used);
      if (used != args[1].size() || n < std::numeric_limits<int>::min() ||
          n > std::numeric_limits<int>::max())
        throw std::invalid_argument("exponent");
      tc.n = static_cast<int>(n);
    } catch (const std::exception&) {
      c.parse_errors.push_back(where + ": bad exponent '" + args[1] + "'");
      return;
    }
  }
  const auto r = parse_interval(results[0]);
  if (!r) {
    c.parse_errors.push_back(where + ": bad result '" + results[0] + "'");
    return;
  }
  tc.expected = *r;
  c.cases.push_back(std::move(tc));
}

void parse_file(corpus& c, const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = strip_comments(buffer.str());
  const std::string file = path.filename().string();
  std::string statement;
  std::size_t line = 1, start_line = 0;
  bool in_string = false;
  for (const char ch : text) {
    if (ch == '\n') ++line;
    if (in_string) {
      statement += ch;
      if (ch == '"') in_string = false;
      continue;
    }
    if (ch == '"') in_string = true;
    if (ch == '{' || ch == '}') {  // `testcase name {` ... `}`: not statements
      statement.clear();
      start_line = 0;
      continue;
    }
    if (ch == ';') {
      parse_statement(c, file, start_line, statement);
      statement.clear();
      start_line = 0;
      continue;
    }
    if (start_line == 0 && !std::isspace(static_cast<unsigned char>(ch))) start_line = line;
    statement += ch;
  }
  if (!trim(statement).empty())
    c.parse_errors.push_back(file + ":" + std::to_string(start_line) +
                             ": statement without ';': " + trim(statement));
}

// All the vectors, read once.  Absent vectors are a failure: they ship in data/itf1788.
const corpus& vectors() {
  static const corpus c = [] {
    const fs::path dir = APPELL_ITF1788_DIR;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      std::cout << "ITF1788 vectors not found at " << dir.string()
                << " (they ship in data/itf1788; APPELL_ITF1788_DIR names another copy)" << std::endl;
      std::exit(1);
    }
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".itl") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    corpus r;
    for (const auto& p : paths) {
      r.files.push_back(p.filename().string());
      parse_file(r, p);
    }
    return r;
  }();
  return c;
}

// --- comparing a computed result with the listed one -------------------------
struct outcome {
  bool empty = false;  // empty result, or appell::domain_error
  bool nan = false;    // a NaN bound: encloses nothing
  double lo = 0, hi = 0;
  std::string error;   // an unexpected exception
};

struct tally {
  std::size_t run = 0, contained = 0, tightest = 0, failures = 0;
  std::size_t inexact_literal = 0;  // contains the listed bounds only as read to nearest
  std::vector<std::string> inexact_lines, loose_lines;
  std::size_t skipped_empty_input = 0, skipped_not_run = 0;
  std::size_t loose_inexact_input = 0;
  std::map<std::string, std::size_t> failures_by_op, loose_by_op;
  std::vector<std::string> failure_lines;
};

std::string show(double lo, double hi) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << lo << ", " << hi << "]";
  return s.str();
}
std::string show(const literal& x) { return x.empty ? "[empty]" : show(x.lo, x.hi); }
std::string show(const outcome& o) {
  if (!o.error.empty()) return "exception: " + o.error;
  if (o.empty) return "[empty] / domain_error";
  if (o.nan) return "NaN bound " + show(o.lo, o.hi);
  return show(o.lo, o.hi);
}

void judge(tally& t, const test_case& tc, const outcome& got) {
  ++t.run;
  const literal& e = tc.expected;
  bool contained = false, tight = false;
  if (!got.error.empty()) {
    contained = false;
  } else if (e.empty) {
    contained = true;  // the empty set is a subset of anything
    tight = got.empty;
  } else if (got.empty || got.nan) {
    contained = false;
  } else {
    contained = got.lo <= e.lo && e.hi <= got.hi;
    tight = (got.lo == e.lo || (!e.lo_exact && got.lo == e.lo_near)) &&  // -0 == +0
            (got.hi == e.hi || (!e.hi_exact && got.hi == e.hi_near));
    // Not contained only because a listed bound is not a binary64 number and
    // its outward reading lies beyond the exact result: a property of the
    // vector, reported apart.
    const bool lo_ok = got.lo <= e.lo || (!e.lo_exact && got.lo <= e.lo_near);
    const bool hi_ok = e.hi <= got.hi || (!e.hi_exact && e.hi_near <= got.hi);
    if (!contained && lo_ok && hi_ok) {
      ++t.inexact_literal;
      t.inexact_lines.push_back(tc.where + ": " + tc.text + "  got " + show(got));
      if (tight) ++t.tightest;
      return;
    }
  }
  if (contained) ++t.contained;
  if (tight) ++t.tightest;
  else if (contained) {
    ++t.loose_by_op[tc.op];
    if (tc.inexact_input) ++t.loose_inexact_input;
    t.loose_lines.push_back(tc.where + ": " + tc.text + "  got " + show(got));
  }
  if (!contained) {
    ++t.failures;
    ++t.failures_by_op[tc.op];
    if (t.failure_lines.size() < 20)
      t.failure_lines.push_back(tc.where + ": " + tc.text + "  expected " + show(e) +
                                ", got " + show(got));
  }
}

std::string by_op(const std::map<std::string, std::size_t>& m) {
  std::string s;
  for (const auto& [op, n] : m) s += " " + op + ":" + std::to_string(n);
  return s.empty() ? " none" : s;
}

void report(const char* scalar, const corpus& c, const tally& t, const std::string& extra) {
  std::ostringstream s;
  s << "ITF1788 [" << scalar << "] files read: " << c.files.size()
    << ", statements: " << c.statements << ", cases run: " << t.run
    << ", contained: " << t.contained << ", tightest: " << t.tightest
    << ", containment failures: " << t.failures
    << ", inexact vector literal: " << t.inexact_literal
    << "\n  skipped: decorated/nai " << c.skipped_decorated << ", not implemented "
    << c.skipped_not_implemented << " (" << c.not_implemented_ops.size() << " operations)";
  if (t.skipped_empty_input) s << ", empty input " << t.skipped_empty_input;
  if (t.skipped_not_run) s << ", not run " << t.skipped_not_run;
  s << extra;
  for (const auto& l : t.inexact_lines)
    s << "\n  contained only in the nearest reading of a listed decimal bound: " << l;
  s << "\n  contained but not tightest, by operation:" << by_op(t.loose_by_op) << " ("
    << t.loose_inexact_input << " of them with a decimal input bound that is not a double)";
  if (std::getenv("APPELL_ITF1788_VERBOSE"))
    for (const auto& l : t.loose_lines) s << "\n  not tightest: " << l;
  if (t.failures) {
    s << "\n  failures by operation:" << by_op(t.failures_by_op);
    for (const auto& f : t.failure_lines) s << "\n  FAIL " << f;
    if (t.failures > t.failure_lines.size())
      s << "\n  ... and " << (t.failures - t.failure_lines.size()) << " more";
  }
  BOOST_TEST_MESSAGE(s.str());
}

// --- appell::interval ----------------------------------------------------------
appell::interval to_interval(const literal& x) {
  return x.empty ? appell::interval::empty() : appell::interval(x.lo, x.hi);
}

appell::interval eval(const test_case& tc) {
  const appell::interval x = to_interval(tc.args[0]);
  const std::string& op = tc.op;
  if (op == "pos") return +x;
  if (op == "neg") return -x;
  if (op == "add") return x + to_interval(tc.args[1]);
  if (op == "sub") return x - to_interval(tc.args[1]);
  if (op == "mul") return x * to_interval(tc.args[1]);
  if (op == "div") return x / to_interval(tc.args[1]);
  if (op == "sqr") return appell::sqr(x);
  if (op == "sqrt") return appell::sqrt(x);
  if (op == "exp") return appell::exp(x);
  if (op == "log") return appell::log(x);
  if (op == "sin") return appell::sin(x);
  if (op == "cos") return appell::cos(x);
  if (op == "tan") return appell::tan(x);
  if (op == "atan") return appell::atan(x);
  if (op == "pown") return appell::pown(x, tc.n);
  if (op == "abs") return appell::abs(x);
  throw std::logic_error("operation not dispatched: " + op);
}

outcome run_interval(const test_case& tc) {
  outcome o;
  try {
    const appell::interval r = eval(tc);
    if (boost::numeric::empty(r)) {
      o.empty = true;
    } else {
      o.lo = r.lower();
      o.hi = r.upper();
      o.nan = std::isnan(o.lo) || std::isnan(o.hi);
    }
  } catch (const appell::domain_error&) {
    o.empty = true;
  } catch (const std::exception& ex) {
    o.error = ex.what();
  }
  return o;
}

// --- appell::mpfi and appell::arb ------------------------------------------------------
template <class M>
M to_mp(const literal& x) {
  appell::mpfr_value lo(53), hi(53);
  mpfr_set_d(lo, x.lo, MPFR_RNDN);  // exact
  mpfr_set_d(hi, x.hi, MPFR_RNDN);
  return appell::scalar_traits<M>::from_mpfr_bounds(lo, hi);
}

template <class M>
M eval_mp(const test_case& tc) {
  using namespace boost::multiprecision;
  const M x = to_mp<M>(tc.args[0]);
  const std::string& op = tc.op;
  if (op == "pos") return x;
  if (op == "neg") return -x;
  if (op == "add") return x + to_mp<M>(tc.args[1]);
  if (op == "sub") return x - to_mp<M>(tc.args[1]);
  if (op == "mul") return x * to_mp<M>(tc.args[1]);
  if (op == "div") return x / to_mp<M>(tc.args[1]);
  if (op == "sqr") return appell::sqr(x);
  if (op == "sqrt") return sqrt(x);
  if (op == "exp") return exp(x);
  if (op == "log") return log(x);
  if (op == "sin") return sin(x);
  if (op == "cos") return cos(x);
  if (op == "tan") return tan(x);
  if (op == "atan") return atan(x);
  if (op == "pown") return appell::pown(x, tc.n);
  if (op == "abs") return abs(x);
  throw std::logic_error("operation not dispatched: " + op);
}

template <class M>
outcome run_mp(const test_case& tc) {
  outcome o;
  try {
    const M r = eval_mp<M>(tc);
    appell::mpfr_value lo, hi;
    appell::scalar_traits<M>::to_mpfr(r, lo, hi);
    if (mpfr_nan_p(lo) || mpfr_nan_p(hi)) {
      o.nan = true;
      o.lo = mpfr_get_d(lo, MPFR_RNDD);
      o.hi = mpfr_get_d(hi, MPFR_RNDU);
    } else if (mpfr_greater_p(lo, hi)) {
      o.empty = true;
    } else {
      // Outward into binary64 (subnormals, overflow to infinity honoured); the
      // comparison with the listed bounds is then exact on doubles.
      o.lo = appell::round_to_double(lo, MPFR_RNDD);
      o.hi = appell::round_to_double(hi, MPFR_RNDU);
    }
  } catch (const appell::domain_error&) {
    o.empty = true;
  } catch (const std::exception& ex) {
    o.error = ex.what();
  }
  return o;
}

template <class M>
void run_all_mp(const char* name) {
  const corpus& c = vectors();
  appell::mp_precision_scope scope(53);
  tally t;
  for (const test_case& tc : c.cases) {
    const bool empty_input =
        std::any_of(tc.args.begin(), tc.args.end(), [](const literal& x) { return x.empty; });
    if (empty_input) {
      ++t.skipped_empty_input;
      continue;
    }
    judge(t, tc, run_mp<M>(tc));
  }
  report(name, c, t, ", precision " + std::to_string(scope.bits()) + " bits");
  BOOST_TEST(t.failures == 0u);
  BOOST_TEST(t.run > 1000u);
}

}  // namespace

BOOST_AUTO_TEST_CASE(itf1788_interval) {
  const corpus& c = vectors();
  for (const auto& e : c.parse_errors) BOOST_TEST_MESSAGE("ITF1788 unparsed: " << e);
  BOOST_TEST(c.parse_errors.empty());
  tally t;
  for (const test_case& tc : c.cases) judge(t, tc, run_interval(tc));
  report("interval", c, t, "");
  BOOST_TEST(t.failures == 0u);
  BOOST_TEST(t.run > 1000u);
}

BOOST_AUTO_TEST_CASE(itf1788_mpfi) { run_all_mp<appell::mpfi>("mpfi"); }

// arb at 53 bits: a ball holds no half line, so [-inf, 3] and its images are the whole line
// (contained, never tightest); the test asks containment, as of every rigorous scalar.
BOOST_AUTO_TEST_CASE(itf1788_arb) { run_all_mp<appell::arb>("arb"); }
