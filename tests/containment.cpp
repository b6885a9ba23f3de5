// Containment: every interval result encloses the exact value.
// For interval (53-bit bounds), mpfi and arb at 64 and 200 bits, on random thin
// (point) arguments and on wide random intervals, each operation's result must
// contain f at every sample of its arguments, evaluated by MPFR at 320 bits:
// the endpoints, random interior points and, for sin/cos/tan, every multiple
// of pi/2 inside (where extrema and poles hide).  Zero misses allowed.
#define BOOST_TEST_MODULE containment
#include <boost/test/unit_test.hpp>

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/scalar/arb_access.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/scalar/products.hpp"

using namespace appell;

namespace {

constexpr mpfr_prec_t ref_prec = 320;

using ref_unary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

struct rng_t {
  std::mt19937_64 engine{20261121};
  gmp_randstate_t gmp;
  rng_t() {
    gmp_randinit_default(gmp);
    gmp_randseed_ui(gmp, 1907);
  }
  ~rng_t() { gmp_randclear(gmp); }
  double uniform() { return std::uniform_real_distribution<double>(0, 1)(engine); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(engine); }
};

// A random number with `prec` random bits, magnitude about 2^[emin, emax].
void random_number(rng_t& rng, mpfr_prec_t prec, int emin, int emax, bool positive, mpfr_value& out) {
  mpfr_set_prec(out, prec);
  mpfr_urandomb(out, rng.gmp);
  mpfr_mul_2si(out, out, rng.integer(emin, emax), MPFR_RNDN);
  if (!positive && rng.integer(0, 1)) mpfr_neg(out, out, MPFR_RNDN);
}

struct domain {
  int emin, emax;
  bool positive;  // arguments > 0 (sqrt, log)
};

template <class I>
I make(const mpfr_value& lo, const mpfr_value& hi) {
  return scalar_traits<I>::from_mpfr_bounds(lo, hi);
}

// Random argument: thin or wide, with bounds representable in I.
template <class I>
I random_argument(rng_t& rng, const domain& d, bool wide, mpfr_prec_t prec) {
  mpfr_value a, w;
  random_number(rng, prec, d.emin, d.emax, d.positive, a);
  if (!wide) return make<I>(a, a);
  random_number(rng, prec, -12, std::max(d.emax, 3), true, w);
  mpfr_value b(prec);
  mpfr_add(b, a, w, MPFR_RNDU);
  return make<I>(a, b);
}

// Samples of an argument at ref_prec: endpoints and random interior points.
template <class I>
std::vector<mpfr_value> samples(rng_t& rng, const I& x, bool with_half_pi_multiples) {
  mpfr_value lo, hi;
  scalar_traits<I>::to_mpfr(x, lo, hi);
  std::vector<mpfr_value> s;
  auto push = [&](mpfr_srcptr v) {
    mpfr_value c(ref_prec);
    mpfr_set(c, v, MPFR_RNDN);
    s.push_back(c);
  };
  push(lo);
  push(hi);
  if (mpfr_equal_p(lo, hi)) return s;
  for (int k = 0; k < 3; ++k) {
    mpfr_value t(ref_prec), v(ref_prec);
    mpfr_set_d(t, rng.uniform(), MPFR_RNDN);
    mpfr_sub(v, hi, lo, MPFR_RNDN);
    mpfr_mul(v, v, t, MPFR_RNDN);
    mpfr_add(v, v, lo, MPFR_RNDN);
    if (mpfr_less_p(v, lo)) mpfr_set(v, lo, MPFR_RNDN);
    if (mpfr_greater_p(v, hi)) mpfr_set(v, hi, MPFR_RNDN);
    s.push_back(v);
  }
  if (with_half_pi_multiples) {
    // k pi/2 in [lo, hi], at most 8 of them.
    mpfr_value half_pi(ref_prec), k(ref_prec), v(ref_prec);
    mpfr_const_pi(half_pi, MPFR_RNDN);
    mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
    mpfr_div(k, lo, half_pi, MPFR_RNDN);
    mpfr_ceil(k, k);
    for (int i = 0; i < 8; ++i) {
      mpfr_mul(v, k, half_pi, MPFR_RNDN);
      if (mpfr_greater_p(v, hi)) break;
      if (!mpfr_less_p(v, lo)) s.push_back(v);
      mpfr_add_ui(k, k, 1, MPFR_RNDN);
    }
  }
  return s;
}

struct tally {
  long cases = 0, samples = 0, misses = 0;
  std::vector<std::string> first_misses;
};

template <class I>
void check(tally& t, const I& result, mpfr_srcptr exact, const std::string& what) {
  ++t.samples;
  if (!contains(result, exact)) {
    ++t.misses;
    if (t.first_misses.size() < 10) {
      mpfr_value e(ref_prec);
      mpfr_set(e, exact, MPFR_RNDN);
      t.first_misses.push_back(what + " -> " + to_string(result) + " misses " +
                               mpfr_to_decimal(e, 40, MPFR_RNDN));
    }
  }
}

struct unary_op {
  std::string name;
  ref_unary ref;
  domain dom;
  bool trig;
};

template <class I>
I apply(const std::string& name, const I& x, int n) {
  using std::sqrt, std::sin, std::cos, std::tan, std::atan, std::exp, std::log;
  if (name == "sqrt") return sqrt(x);
  if (name == "sin") return sin(x);
  if (name == "cos") return cos(x);
  if (name == "tan") return tan(x);
  if (name == "atan") return atan(x);
  if (name == "exp") return exp(x);
  if (name == "log") return log(x);
  if (name == "pown") return appell::pown(x, n);
  throw std::logic_error(name);
}

template <class I>
void run_unary(tally& t, rng_t& rng, mpfr_prec_t prec, int n_thin, int n_wide) {
  const std::vector<unary_op> ops = {
      {"sqrt", mpfr_sqrt, {-30, 30, true}, false}, {"sin", mpfr_sin, {-40, 12, false}, true},
      {"cos", mpfr_cos, {-40, 12, false}, true},   {"tan", mpfr_tan, {-40, 8, false}, true},
      {"atan", mpfr_atan, {-30, 30, false}, false}, {"exp", mpfr_exp, {-20, 9, false}, false},
      {"log", mpfr_log, {-30, 30, true}, false},   {"pown", nullptr, {-8, 8, false}, false}};
  for (const auto& op : ops) {
    for (int c = 0; c < n_thin + n_wide; ++c) {
      const bool wide = c >= n_thin;
      const I x = random_argument<I>(rng, op.dom, wide, prec);
      int n = 0;
      while (n == 0) n = rng.integer(-6, 7);
      I y;
      try {
        y = apply(op.name, x, n);
      } catch (const domain_error&) {
        continue;  // only for arguments outside the domain (none are generated)
      }
      ++t.cases;
      for (const auto& s : samples(rng, x, op.trig)) {
        mpfr_value r(ref_prec);
        if (op.name == "pown") {
          if (n < 0 && mpfr_zero_p(s)) continue;
          mpfr_pow_si(r, s, n, MPFR_RNDN);
        } else {
          op.ref(r, s, MPFR_RNDN);
        }
        // A point outside the function's domain has no value to enclose (IEEE 1788: the
        // function is restricted to its domain).  Only arb's arguments reach such points: a
        // wide ball's lower end, its 30-bit radius rounded up, lies a little below a positive
        // interval's lower bound (the sqrt and log of [1e-6, 835] are asked of [-1.4e-6, 835]).
        if (mpfr_nan_p(r)) continue;
        check(t, y, r, op.name + (op.name == "pown" ? std::to_string(n) : "") + to_string(x));
      }
    }
  }
}

template <class I>
void run_binary(tally& t, rng_t& rng, mpfr_prec_t prec, int n_thin, int n_wide) {
  const domain dom{-30, 30, false};
  for (const char op : {'+', '-', '*', '/'}) {
    for (int c = 0; c < n_thin + n_wide; ++c) {
      const bool wide = c >= n_thin;
      const I x = random_argument<I>(rng, dom, wide, prec);
      const I y = random_argument<I>(rng, dom, wide, prec);
      const I z = op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : x / y;
      ++t.cases;
      const auto sx = samples(rng, x, false), sy = samples(rng, y, false);
      for (std::size_t i = 0; i < sx.size(); ++i) {
        for (std::size_t j = 0; j < sy.size(); ++j) {
          if (i != j && i > 1 && j > 1) continue;  // endpoints x endpoints, interior paired
          mpfr_value r(ref_prec);
          if (op == '/' && mpfr_zero_p(sy[j])) continue;
          if (op == '+') mpfr_add(r, sx[i], sy[j], MPFR_RNDN);
          if (op == '-') mpfr_sub(r, sx[i], sy[j], MPFR_RNDN);
          if (op == '*') mpfr_mul(r, sx[i], sy[j], MPFR_RNDN);
          if (op == '/') mpfr_div(r, sx[i], sy[j], MPFR_RNDN);
          check(t, z, r, std::string(1, op) + " " + to_string(x) + " " + to_string(y));
        }
      }
    }
  }
}

template <class I>
void run_all(const std::string& label, mpfr_prec_t prec) {
  rng_t rng;
  tally t;
  run_unary<I>(t, rng, prec, 2500, 1500);
  run_binary<I>(t, rng, prec, 2500, 1500);
  BOOST_TEST_MESSAGE(label << ": " << t.cases << " cases, " << t.samples
                           << " samples checked against MPFR at 320 bits, " << t.misses << " misses");
  for (const auto& m : t.first_misses) BOOST_TEST_MESSAGE("  MISS " << m);
  BOOST_TEST(t.misses == 0);
  BOOST_TEST(t.cases >= 40000);
}

// sum_of_products (3 terms) and difference_of_products (2), the kernels of the trees' 3 x 3 and
// cross products (products.hpp: interval in SSE pairs, arb in one arb_dot): the exact range over
// the operands' box is [min, max] of the values at its vertices (the function is affine in each
// operand), each computed exactly (products of two numbers of at most 200 bits, each below 2^42 in
// magnitude, and sums of three of them fit in 1200 bits); the result must contain every one. One
// case in 16 has an exact zero among the operands (arb: a subtracted zero midpoint is skipped).
template <class I>
void run_products(tally& t, rng_t& rng, mpfr_prec_t prec, int n) {
  const domain dom{-30, 30, false};
  for (int c = 0; c < n; ++c) {
    const bool diff = c % 4 >= 2;
    const int m = diff ? 2 : 3;
    I a[3], b[3];
    for (int k = 0; k < m; ++k) {
      a[k] = random_argument<I>(rng, dom, c % 2 == 1 && rng.integer(0, 1) == 1, prec);
      b[k] = random_argument<I>(rng, dom, c % 2 == 1 && rng.integer(0, 1) == 1, prec);
      if (rng.integer(0, 15) == 0) a[k] = I(0);
    }
    const I r = diff ? difference_of_products(a[0], b[0], a[1], b[1]) : sum_of_products(a[0], b[0], a[1], b[1], a[2], b[2]);
    ++t.cases;
    mpfr_value lo[2][3], hi[2][3];
    for (int k = 0; k < m; ++k) {
      scalar_traits<I>::to_mpfr(a[k], lo[0][k], hi[0][k]);
      scalar_traits<I>::to_mpfr(b[k], lo[1][k], hi[1][k]);
    }
    for (int v = 0; v < 1 << (2 * m); ++v) {
      mpfr_value sum(1200), p(1200);
      mpfr_set_zero(sum, 1);
      for (int k = 0; k < m; ++k) {
        mpfr_mul(p, (v >> (2 * k) & 1) ? hi[0][k] : lo[0][k], (v >> (2 * k + 1) & 1) ? hi[1][k] : lo[1][k], MPFR_RNDN);
        if (diff && k == 1) mpfr_sub(sum, sum, p, MPFR_RNDN);
        else mpfr_add(sum, sum, p, MPFR_RNDN);
      }
      check(t, r, sum, std::string(diff ? "a0 b0 - a1 b1 " : "a0 b0 + a1 b1 + a2 b2 ") + to_string(a[0]) + " " + to_string(b[0]));
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(sums_of_products_contain_their_exact_range) {
  for (const mpfr_prec_t bits : {53, 64, 200}) {
    rng_t rng;
    tally t;
    if (bits == 53) {
      run_products<interval>(t, rng, 53, 4000);
    } else {
      const mp_precision_scope scope(static_cast<unsigned>(bits));
      run_products<arb>(t, rng, bits, 4000);
    }
    BOOST_TEST_MESSAGE((bits == 53 ? "interval" : "arb " + std::to_string(bits)) << ": " << t.cases << " sums of products, "
                                                                                  << t.samples << " vertices checked, " << t.misses << " misses");
    for (const auto& miss : t.first_misses) BOOST_TEST_MESSAGE("  MISS " << miss);
    BOOST_TEST(t.misses == 0);
    BOOST_TEST(t.samples >= 100000);
  }
  // x x + y y + z z with each square one value twice (arb takes Arb's square there, as the
  // expression does, and keeps its part >= 0): each square is >= 0, and the sum holds the values
  // at each operand's ends and at 0 where it holds 0.
  rng_t rng;
  tally t;
  const mp_precision_scope scope(113);
  for (int c = 0; c < 2000; ++c) {
    arb x[3];
    mpfr_value lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = random_argument<arb>(rng, domain{-30, 30, false}, c % 2 == 1, 113);
      scalar_traits<arb>::to_mpfr(x[k], lo[k], hi[k]);
    }
    const arb r = sum_of_products(x[0], x[0], x[1], x[1], x[2], x[2]);
    for (int k = 0; k < 3; ++k)  // a square's part >= 0 (arb_backend.cpp; a sum of such balls may reach below)
      BOOST_TEST_REQUIRE(scalar_traits<arb>::lower(arb(x[k] * x[k])) >= 0, to_string(x[k]));
    ++t.cases;
    for (int v = 0; v < 27; ++v) {
      mpfr_value sum(1200), p(1200), at(1200);
      mpfr_set_zero(sum, 1);
      bool point = true;  // 0 taken only where the operand holds it
      for (int k = 0, w = v; k < 3; ++k, w /= 3)
        if (w % 3 == 2 && !(mpfr_cmp_si(lo[k], 0) <= 0 && mpfr_cmp_si(hi[k], 0) >= 0)) point = false;
      if (!point) continue;
      for (int k = 0, w = v; k < 3; ++k, w /= 3) {
        if (w % 3 == 2) mpfr_set_zero(at, 1);
        else mpfr_set(at, w % 3 == 1 ? hi[k] : lo[k], MPFR_RNDN);
        mpfr_sqr(p, at, MPFR_RNDN);
        mpfr_add(sum, sum, p, MPFR_RNDN);
      }
      check(t, r, sum, "x x + y y + z z " + to_string(x[0]));
    }
  }
  BOOST_TEST_MESSAGE("arb 113, squares: " << t.cases << " sums, " << t.samples << " points, " << t.misses << " misses");
  BOOST_TEST(t.misses == 0);
}

BOOST_AUTO_TEST_CASE(interval_sums_of_products_are_the_operations_one_by_one) {
  // The fused kernels claim the bounds of the operations done one by one (interval.hpp): the
  // same bits on random operands, and on operands with infinite bounds, empty ones and exact
  // zeros (which take the operations one by one).
  rng_t rng;
  const domain dom{-30, 30, false};
  const double inf = std::numeric_limits<double>::infinity();
  // huge finite bounds: products and sums that round up to +inf in one lane
  const interval specials[] = {interval(-inf, 1.5), interval(0.0, inf), interval(-inf, inf), interval::empty(), interval(0.0),
                               interval(-0.0, 0.0), interval(-2.0, 0.0), interval(1e200, 1e300), interval(-1e300, -1e250)};
  std::optional<upward_rounding> up;  // the first half inside a scope, the second switching per operation
  up.emplace();
  long same = 0, cases = 0;
  for (int c = 0; c < 20000; ++c) {
    if (c == 10000) up.reset();
    interval a[3], b[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = random_argument<interval>(rng, dom, rng.integer(0, 1) == 1, 53);
      b[k] = random_argument<interval>(rng, dom, rng.integer(0, 1) == 1, 53);
      if (rng.integer(0, 15) == 0) a[k] = specials[rng.integer(0, 8)];
      if (rng.integer(0, 15) == 0) b[k] = specials[rng.integer(0, 8)];
    }
    const interval s = sum_of_products(a[0], b[0], a[1], b[1], a[2], b[2]), s1 = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const interval d = difference_of_products(a[0], b[0], a[1], b[1]), d1 = a[0] * b[0] - a[1] * b[1];
    auto bits = [](const interval& x, const interval& y) {
      return (std::isnan(x.lower()) && std::isnan(y.lower())) ||
             (std::memcmp(&x, &y, sizeof x) == 0);
    };
    cases += 2;
    same += bits(s, s1) + bits(d, d1);
    if (!bits(s, s1)) BOOST_TEST_MESSAGE("sum " << to_string(s) << " != " << to_string(s1));
    if (!bits(d, d1)) BOOST_TEST_MESSAGE("difference " << to_string(d) << " != " << to_string(d1));
  }
  BOOST_TEST(same == cases);
}

BOOST_AUTO_TEST_CASE(interval_jet_product_sums_are_the_operations_one_by_one) {
  // The jets' inner loop (jet.hpp, detail::product_sum<interval>) adds each product to s as a
  // pair of bounds; it claims the bits of s += x y and s -= x y: checked on random accumulations
  // of 1 to 25 terms (the jets' orders), with the special operands above (infinite, empty, zero,
  // signed zero, huge), inside an upward-rounding scope (the fast path) and outside (the
  // expression itself).
  rng_t rng;
  const domain dom{-30, 30, false};
  const double inf = std::numeric_limits<double>::infinity();
  const interval specials[] = {interval(-inf, 1.5), interval(0.0, inf), interval(-inf, inf), interval::empty(), interval(0.0),
                               interval(-0.0, 0.0), interval(-0.0), interval(-2.0, 0.0), interval(1e200, 1e300),
                               interval(-1e300, -1e250), interval(0.0, 3.0)};
  constexpr int n_specials = static_cast<int>(sizeof specials / sizeof specials[0]);
  auto bits = [](const interval& x, const interval& y) {
    return (std::isnan(x.lower()) && std::isnan(y.lower())) || (std::memcmp(&x, &y, sizeof x) == 0);
  };
  std::optional<upward_rounding> up;
  up.emplace();
  long same = 0, cases = 0;
  for (int c = 0; c < 20000; ++c) {
    if (c == 10000) up.reset();
    interval s = rng.integer(0, 3) == 0 ? random_argument<interval>(rng, dom, true, 53) : interval(0);
    if (rng.integer(0, 31) == 0) s = specials[rng.integer(0, n_specials - 1)];
    interval e = s;
    detail::product_sum<interval> sum;
    const int terms = static_cast<int>(rng.integer(1, 25));
    for (int k = 0; k < terms; ++k) {
      interval x = random_argument<interval>(rng, dom, rng.integer(0, 1) == 1, 53);
      interval y = random_argument<interval>(rng, dom, rng.integer(0, 1) == 1, 53);
      if (rng.integer(0, 15) == 0) x = specials[rng.integer(0, n_specials - 1)];
      if (rng.integer(0, 15) == 0) y = specials[rng.integer(0, n_specials - 1)];
      if (rng.integer(0, 1) == 0) {
        sum.add(s, x, y);
        e += x * y;
      } else {
        sum.subtract(s, x, y);
        e -= x * y;
      }
    }
    ++cases;
    same += bits(s, e);
    if (!bits(s, e)) BOOST_TEST_MESSAGE("product sum " << to_string(s) << " != " << to_string(e));
  }
  BOOST_TEST(same == cases);
}

BOOST_AUTO_TEST_CASE(interval_results_contain_the_320_bit_values) { run_all<interval>("interval", 53); }

BOOST_AUTO_TEST_CASE(mpfi_64_results_contain_the_320_bit_values) {
  mp_precision_scope scope(64);
  run_all<mpfi>("mpfi at " + std::to_string(scope.bits()) + " bits", scope.bits());
}

BOOST_AUTO_TEST_CASE(mpfi_200_results_contain_the_320_bit_values) {
  mp_precision_scope scope(200);
  run_all<mpfi>("mpfi at " + std::to_string(scope.bits()) + " bits", scope.bits());
}

// arb's pooled limbs (src/scalar/arb_backend.cpp: a value that dies leaves its midpoint's heap
// limbs to its thread, and a result about to be written into a value that holds none takes them)
// change no result: random operations at a precision drawn anew each time (limbs pooled at 4000
// bits serve 64, and the reverse), each result the same ball, bit for bit, as Arb's own on
// variables of its own; between them values kept alive and dropped at random, so that the pool
// runs full and empty; and values made on one thread and dropped on another.
BOOST_AUTO_TEST_CASE(arb_results_do_not_depend_on_the_pooled_limbs) {
  std::mt19937_64 rng(20261206);
  const long precisions[] = {64, 113, 128, 129, 200, 256, 1024, 4000};
  std::uniform_real_distribution<double> u(0.1, 10);
  std::vector<arb> alive;
  auto same_as_arb = [](const arb& r, arb_srcptr expected) {
    return arb_equal(mp::arb_of(r.backend()), expected) != 0;
  };
  int cases = 0, mismatches = 0;
  for (int round = 0; round < 20000; ++round) {
    const long p = precisions[rng() % 8];
    const mp_precision_scope scope(static_cast<unsigned>(p));
    // operands with every limb in use: square roots of random doubles (a ball of radius > 0)
    arb a = sqrt(arb(u(rng))), b = sqrt(arb(u(rng)));
    if (rng() % 2) a = -a;
    arb_t x, y, want;
    arb_init(x);
    arb_init(y);
    arb_init(want);
    arb_set(x, mp::arb_of(a.backend()));
    arb_set(y, mp::arb_of(b.backend()));
    arb r;
    arb_t three;  // a small exact value: its midpoint's limbs inline, none on the heap
    arb_init(three);
    arb_set_si(three, 3);
    switch (const int op = static_cast<int>(rng() % 18)) {
      case 0: r = a + b; arb_add(want, x, y, p); break;
      case 1: r = a - b; arb_sub(want, x, y, p); break;
      case 2: r = a * b; arb_mul(want, x, y, p); break;
      case 3: r = a / b; arb_div(want, x, y, p); break;
      case 4: r = sqrt(b); arb_sqrtpos(want, y, p); break;
      case 5: r = sin(a); arb_sin(want, x, p); break;
      case 6: r = cos(a); arb_cos(want, x, p); break;
      case 7: r = 3; r *= a; arb_mul(want, three, x, p); break;  // r the result and an operand
      case 8: r = 3; r /= b; arb_div(want, three, y, p); break;
      case 9: r = exp(a); arb_exp(want, x, p); break;
      case 10: r = abs(a); arb_abs(want, x); break;
      case 11: r = atan(a); arb_atan(want, x, p); break;
      case 12: r = log(b); arb_log(want, y, p); break;
      case 13: {  // a b - b a through Arb's dot product (products.hpp), the subtracted term's sign flipped
        r = difference_of_products(a, b, b, a);
        arb_struct xs[2] = {*x, *y}, ys[2] = {*y, *x};
        ARF_NEG(arb_midref(xs + 1));  // a copy's sign: the limbs are y's, read only
        arb_dot(want, nullptr, 0, xs, 1, ys, 1, 2, p);
        break;
      }
      case 14: {  // a sum begun at 0: the accumulator holds no limbs at first
        r = 0;
        r += a * b;
        r -= b;
        arb_t t;
        arb_init(t);
        arb_mul(t, x, y, p);
        arb_add(want, want, t, p);
        arb_sub(want, want, y, p);
        arb_clear(t);
        break;
      }
      case 15:  // s += a b in one rounding (Arb's arb_addmul), s small and exact
        r = 3;
        mp::arb_add_product(r.backend(), a.backend(), b.backend());
        arb_set(want, three);
        arb_addmul(want, x, y, p);
        break;
      case 16: r = 3; r *= r; arb_sqr(want, three, p); break;
      default: r = arb(a); arb_set(want, x); (void)op; break;
    }
    arb_clear(three);
    ++cases;
    if (!same_as_arb(r, want)) {
      ++mismatches;
      BOOST_TEST_MESSAGE("at " << p << " bits: " << to_string(r) << " vs Arb's own");
    }
    arb_clear(x);
    arb_clear(y);
    arb_clear(want);
    // keep some results alive (their limbs out of the pool) and drop others (into it)
    if (rng() % 3 == 0 && alive.size() < 100) alive.push_back(r);
    while (!alive.empty() && rng() % 4 == 0) {
      const std::size_t k = rng() % alive.size();
      alive[k] = std::move(alive.back());
      alive.pop_back();
    }
  }
  BOOST_TEST(mismatches == 0, mismatches << " of " << cases << " results differ from Arb's own");
  // made on a worker thread (from its pool), dropped here (into this thread's); then the other way
  std::vector<arb> made;
  std::thread([&] {
    const mp_precision_scope scope(256);
    for (int k = 0; k < 200; ++k) made.push_back(sqrt(arb(k + 2)) * sqrt(arb(k + 3)));
  }).join();
  {
    const mp_precision_scope scope(256);
    for (int k = 0; k < 200; ++k) {  // (sqrt(k + 2) sqrt(k + 3))^2 encloses (k + 2)(k + 3)
      const arb& m = made[static_cast<std::size_t>(k)];
      const arb square = m * m;
      BOOST_TEST_REQUIRE(arb_contains_si(mp::arb_of(square.backend()), (k + 2) * (k + 3)) != 0, to_string(square));
    }
  }
  std::thread([moved = std::move(made)]() mutable { moved.clear(); }).join();
  alive.clear();
  // values that outlive their thread's pool (a thread_local made before the pool's first use is
  // destroyed after it): cleared then, not kept where nothing frees them (under valgrind and
  // LeakSanitizer, scripts/sanitize.sh --numbers, a leak fails the suite)
  std::thread([] {
    static thread_local std::vector<arb> outliving;
    outliving.reserve(8);
    const mp_precision_scope scope(256);
    for (int k = 0; k < 8; ++k) outliving.push_back(sqrt(arb(k + 2)));
  }).join();
}

BOOST_AUTO_TEST_CASE(arb_64_results_contain_the_320_bit_values) {
  mp_precision_scope scope(64);
  run_all<arb>("arb at " + std::to_string(scope.bits()) + " bits", scope.bits());
}

BOOST_AUTO_TEST_CASE(arb_200_results_contain_the_320_bit_values) {
  mp_precision_scope scope(200);
  run_all<arb>("arb at " + std::to_string(scope.bits()) + " bits", scope.bits());
}

// arb against mpfi on the same arguments (the cross-check the two rigorous multiprecision
// scalars give each other): both enclose the truth, so their results must overlap; and arb's
// ball, whose radius is a 30-bit number, is about as tight as mpfi's two bounds on thin
// arguments.  The median ratio of widths is reported; overlap is required of every case.
BOOST_AUTO_TEST_CASE(arb_and_mpfi_overlap_on_the_same_arguments) {
  for (const unsigned bits : {113u, 256u}) {
    mp_precision_scope scope(bits);
    rng_t rng;
    long cases = 0, disjoint = 0;
    std::vector<double> ratios;
    const std::vector<std::string> names = {"sqrt", "sin", "cos", "tan", "atan", "exp", "log", "pown"};
    for (const std::string& name : names) {
      const bool positive = name == "sqrt" || name == "log";
      for (int c = 0; c < 400; ++c) {
        const bool wide = c >= 300;
        mpfr_value a, w;
        random_number(rng, bits, -20, 8, positive, a);
        mpfr_value b(bits);
        mpfr_set(b, a, MPFR_RNDN);
        if (wide) {
          random_number(rng, bits, -40, -4, true, w);
          mpfr_add(b, a, w, MPFR_RNDU);
        }
        const int n = rng.integer(1, 6) * (rng.integer(0, 1) ? 1 : -1);
        const arb xa = scalar_traits<arb>::from_mpfr_bounds(a, b);
        const mpfi xm = scalar_traits<mpfi>::from_mpfr_bounds(a, b);
        arb ya;
        mpfi ym;
        try {
          ya = apply(name, xa, n);
          ym = apply(name, xm, n);
        } catch (const domain_error&) {
          continue;
        }
        if (!is_finite(ya) || !is_finite(ym)) continue;  // a pole inside (tan, a negative power of 0)
        ++cases;
        mpfr_value al, ah, ml, mh;
        scalar_traits<arb>::to_mpfr(ya, al, ah);
        scalar_traits<mpfi>::to_mpfr(ym, ml, mh);
        if (mpfr_less_p(ah, ml) || mpfr_less_p(mh, al)) {
          ++disjoint;
          BOOST_TEST_MESSAGE("disjoint: " << name << " " << to_string(xa) << " arb " << to_string(ya) << " mpfi "
                                          << to_string(ym));
        }
        const double wa = mpfr_get_d(width(ya).backend().data(), MPFR_RNDU);
        const double wm = mpfr_get_d(width(ym).backend().data(), MPFR_RNDU);
        if (wm > 0 && wa > 0) ratios.push_back(wa / wm);
      }
    }
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios.empty() ? 0 : ratios[ratios.size() / 2];
    BOOST_TEST_MESSAGE("arb against mpfi at " << bits << " bits: " << cases << " cases, " << disjoint
                                              << " disjoint, median width ratio arb/mpfi " << median);
    BOOST_TEST(disjoint == 0);
    BOOST_TEST(cases >= 2500);
    BOOST_TEST(median < 4.0);  // a ball is at most a few times wider than two bounds, never orders of magnitude
  }
}

// sin and cos of narrow arguments (|x| < 2^20) take a Cody-Waite reduction and
// Taylor polynomials in interval<double> arithmetic (interval_functions.cpp).
// Check that path on its own: thin and narrow arguments, uniform in size and
// clustered at multiples of pi/2 (where the reduction cancels), containment of
// MPFR's 320-bit values at the endpoints and the midpoint, and tightness: the
// width stays within 6 ulps of the result plus the argument's width (and 2 of its ulps).
BOOST_AUTO_TEST_CASE(sin_cos_of_narrow_arguments_contain_and_are_tight) {
  std::mt19937_64 gen(1907);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  mpfr_value half_pi(ref_prec), v(ref_prec), r(ref_prec);
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
  long cases = 0, misses = 0, loose = 0;
  std::vector<std::string> first;
  for (int c = 0; c < 40000; ++c) {
    double x;
    if (c % 2 == 0) {
      x = std::ldexp(unit(gen) * 2 - 1, static_cast<int>(unit(gen) * 40) - 20);  // |x| < 2^20
    } else {  // next to k pi/2, k up to 2^19
      const long k = static_cast<long>(unit(gen) * 524288) - 262144;
      mpfr_mul_si(v, half_pi, k, MPFR_RNDN);
      x = mpfr_get_d(v, MPFR_RNDN);
      x = std::nextafter(x, unit(gen) < 0.5 ? -INFINITY : INFINITY);
    }
    const double w = c % 3 == 0 ? 0.0 : std::abs(x) * 1e-12 * unit(gen);
    const interval X(x, x + w);  // nearest-mode sum: X is some narrow interval, fine
    for (int f = 0; f < 2; ++f) {
      const interval y = f == 0 ? appell::sin(X) : appell::cos(X);
      ++cases;
      const double points[3] = {X.lower(), X.upper(), X.lower() + (X.upper() - X.lower()) / 2};
      for (double p : points) {
        mpfr_set_d(v, p, MPFR_RNDN);
        if (f == 0) mpfr_sin(r, v, MPFR_RNDN);
        else mpfr_cos(r, v, MPFR_RNDN);
        if (!contains(y, r)) {
          ++misses;
          if (first.size() < 5) first.push_back((f ? "cos " : "sin ") + to_string(X) + " -> " + to_string(y));
        }
      }
      const double mag = std::max(std::abs(y.lower()), std::abs(y.upper()));
      const double eps = std::ldexp(1.0, -52);  // the mid of x is within an ulp of its centre: allow 2 ulps of x
      if (y.upper() - y.lower() > 6 * eps * mag + (X.upper() - X.lower()) + 2 * eps * std::abs(x) + 1e-300) {
        ++loose;
        if (loose < 8) BOOST_TEST_MESSAGE("  loose " << (f ? "cos " : "sin ") << to_string(X) << " -> " << to_string(y));
      }
    }
  }
  BOOST_TEST_MESSAGE("narrow sin/cos: " << cases << " cases, " << misses << " misses, " << loose
                                        << " wider than 6 ulps + the argument's width");
  for (const auto& m : first) BOOST_TEST_MESSAGE("  MISS " << m);
  BOOST_TEST(misses == 0);
  BOOST_TEST(loose == 0);
}

// mpfi's sin and cos of narrow arguments come from one mpfr_sin_cos at the midpoint
// plus a mean-value bound (sin_cos_mpfi, src/scalar/mpfi_functions.cpp).  On thin
// and narrow arguments at 128 and 320 bits, uniform in size and next to k pi/2:
// the endpoints, the midpoint and random interior points (at 640 bits) are
// contained, and the width exceeds MPFI's own endpoint enclosure (mpfi_sin,
// mpfi_cos) by at most 8 ulps of the result's magnitude plus 17/16 r^2, r the
// argument's radius (the mean-value form's second-order term is r^2/2 on each
// side), plus 2 ulps of the argument (the midpoint is placed to within half an
// ulp of its centre).
BOOST_AUTO_TEST_CASE(mpfi_sin_cos_of_narrow_arguments_contain_and_are_tight) {
  std::mt19937_64 gen(1788);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long cases = 0, misses = 0, loose = 0;
  for (mpfr_prec_t prec : {128, 320}) {
    const mp_precision_scope scope(static_cast<unsigned>(prec));
    mpfr_value half_pi(640), v(640), r(640), lo(prec), hi(prec), w(prec);
    mpfr_const_pi(half_pi, MPFR_RNDN);
    mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
    for (int c = 0; c < 6000; ++c) {
      if (c % 2 == 0) {
        mpfr_set_d(lo, std::ldexp(unit(gen) * 2 - 1, static_cast<int>(unit(gen) * 40) - 20), MPFR_RNDN);
      } else {  // next to k pi/2
        const long k = static_cast<long>(unit(gen) * 524288) - 262144;
        mpfr_mul_si(v, half_pi, k, MPFR_RNDN);
        mpfr_set(lo, v, MPFR_RNDN);
      }
      // width 0, up to 2^-(p/2) relative, or up to 2^-18 relative (inside and beyond the narrow path's 2^-20)
      const int kind = c % 3;
      mpfr_abs(w, lo, MPFR_RNDN);
      mpfr_mul_d(w, w, kind == 0 ? 0.0 : unit(gen), MPFR_RNDN);
      mpfr_mul_2si(w, w, kind == 1 ? -static_cast<long>(prec) / 2 : -18, MPFR_RNDN);
      mpfr_add(hi, lo, w, MPFR_RNDU);
      const mpfi X = mpfi_from_bounds(mpfr(lo.get()), mpfr(hi.get()));
      mpfi s, co;
      sin_cos_mpfi(X, s, co);
      const mpfi s2 = sin(X), c2 = cos(X);  // the plain overloads: the same values
      if (c % 50 == 0) {  // the outputs may be the argument itself
        mpfi a = X, b;
        sin_cos_mpfi(a, a, b);
        BOOST_REQUIRE(mpfr_equal_p(&a.backend().data()->left, &s.backend().data()->left) &&
                      mpfr_equal_p(&b.backend().data()->right, &co.backend().data()->right));
        mpfi d = X, e;
        sin_cos_mpfi(d, e, d);
        BOOST_REQUIRE(mpfr_equal_p(&e.backend().data()->right, &s.backend().data()->right) &&
                      mpfr_equal_p(&d.backend().data()->left, &co.backend().data()->left));
      }
      BOOST_REQUIRE(mpfr_equal_p(&s.backend().data()->left, &s2.backend().data()->left) &&
                    mpfr_equal_p(&co.backend().data()->right, &c2.backend().data()->right));
      for (int f = 0; f < 2; ++f) {
        const mpfi& y = f == 0 ? s : co;
        ++cases;
        for (int sample = 0; sample < 5; ++sample) {
          // lo, hi, the midpoint, two random interior points, all at 640 bits
          mpfr_set(v, lo, MPFR_RNDN);
          if (sample == 1) mpfr_set(v, hi, MPFR_RNDN);
          if (sample >= 2) {
            mpfr_sub(r, hi, lo, MPFR_RNDN);
            mpfr_mul_d(r, r, sample == 2 ? 0.5 : unit(gen), MPFR_RNDN);
            mpfr_add(v, v, r, MPFR_RNDN);
          }
          if (f == 0) mpfr_sin(r, v, MPFR_RNDN);
          else mpfr_cos(r, v, MPFR_RNDN);
          if (mpfr_cmp(r, &y.backend().data()->left) < 0 || mpfr_cmp(r, &y.backend().data()->right) > 0) ++misses;
        }
        mpfi ref;
        if (f == 0) mpfi_sin(ref.backend().data(), X.backend().data());
        else mpfi_cos(ref.backend().data(), X.backend().data());
        const mpfr a1 = abs(mpfi_lower(y)), a2 = abs(mpfi_upper(y));
        const mpfr mag = a1 > a2 ? a1 : a2;
        mpfr rx = mpfi_width(X);  // the mean-value form's second-order term: about r^2 = (width / 2)^2
        rx = rx * rx / 4;
        // and the midpoint sits within half an ulp of x's centre: 2 ulps of |x| (as for interval above)
        const mpfr x_ulps = ldexp(abs(mpfi_upper(X)), 2 - static_cast<int>(prec));
        const mpfr allowed = mpfi_width(ref) + ldexp(mpfr(mag), 3 - static_cast<int>(prec)) + rx * mpfr(1.0625) + x_ulps;
        if (mpfi_width(y) > allowed) ++loose;
      }
    }
  }
  BOOST_TEST_MESSAGE("mpfi narrow sin/cos: " << cases << " cases, " << misses << " misses, " << loose
                                             << " wider than MPFI's enclosure + 8 ulps + 17/16 r^2 + 2 ulps of x");
  BOOST_TEST(misses == 0);
  BOOST_TEST(loose == 0);
}
