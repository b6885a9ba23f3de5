// The compile flags that keep interval arithmetic rigorous are in force.
// Without -frounding-math, GCC at -O2/-O3 folds 1/3 and sqrt(2) of constant
// intervals into a single double (a thin, wrong box) -- docs/design.md §3.
#define BOOST_TEST_MODULE rounding_flags
#include <boost/test/unit_test.hpp>

#include <cfenv>
#include <cmath>
#include <random>
#include <vector>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/interval.hpp"

using appell::interval;

BOOST_AUTO_TEST_CASE(one_third_of_constants_is_not_folded_thin) {
  const interval third = interval(1.0) / interval(3.0);
  // The two doubles around 1/3: 0x1.5555555555555p-2 and its successor.
  BOOST_TEST(third.lower() == 0x1.5555555555555p-2);
  BOOST_TEST(third.upper() == 0x1.5555555555556p-2);
}

BOOST_AUTO_TEST_CASE(sqrt_of_two_is_not_folded_thin) {
  const interval r = appell::sqrt(interval(2.0));
  BOOST_TEST(r.lower() < r.upper());
  // The Boost operation (hardware sqrt under directed rounding) too.
  const interval b = boost::numeric::sqrt(interval(2.0));
  BOOST_TEST(b.lower() < b.upper());
}

BOOST_AUTO_TEST_CASE(constant_products_and_sums_are_rounded_outward) {
  const interval x = interval(0.1) * interval(3.0);  // 0.1 * 3 is not a double
  BOOST_TEST(x.lower() < x.upper());
  const interval s = interval(1.0) + interval(1e-30);
  BOOST_TEST(s.lower() == 1.0);
  BOOST_TEST(s.upper() > 1.0);
}

BOOST_AUTO_TEST_CASE(interval_operations_leave_the_rounding_mode_as_found) {
  const interval x = interval(1.0) / interval(3.0);
  BOOST_TEST(std::fegetround() == FE_TONEAREST);
  // A round-to-nearest quotient after the interval one is not the upward one
  // reused (GCC bug 34678 would do that without the opaque operands).
  const double nearest = 1.0 / 3.0;
  BOOST_TEST(nearest == 0x1.5555555555555p-2);
  BOOST_TEST(x.upper() == 0x1.5555555555556p-2);
}

BOOST_AUTO_TEST_CASE(boost_helpers_leave_both_units_in_round_to_nearest) {
  // median, sqrt and floor/ceil go through the rounding policy too: neither the
  // SSE nor the x87 unit (long double) may be left in another mode.
  const interval x(1.0, 2.0);
  (void)boost::numeric::median(x);
  (void)boost::numeric::sqrt(x);
  (void)boost::numeric::fmod(interval(7.0), interval(2.0));
  BOOST_TEST(std::fegetround() == FE_TONEAREST);
  volatile long double a = 1.0L, b = 3.0L;
  BOOST_TEST(a / b == 1.0L / 3.0L);
  {
    const appell::upward_rounding scope;
    (void)(x * x);
  }
  BOOST_TEST(std::fegetround() == FE_TONEAREST);
  volatile double c = 1.0, d = 3.0;
  BOOST_TEST(c / d == 0x1.5555555555555p-2);
}

BOOST_AUTO_TEST_CASE(no_fast_math) {
#ifdef __FAST_MATH__
  BOOST_FAIL("compiled with -ffast-math: interval results are not rigorous");
#else
  BOOST_TEST(true);
#endif
}

// Inside an upward_rounding scope interval operations trust a thread-local flag
// instead of reading MXCSR.  Check them there on random operands, exactly:
// for a product p of doubles, fma(a, b, -p) (round to nearest, one rounding) has
// the sign of a*b - p; for a sum, the two-sum error term does the same.
namespace {
double exact_minus_product(double a, double b, double p) { return std::fma(a, b, -p); }
int sign_of_sum_minus(double a, double b, double s) {  // sign of a + b - s, exactly (round to nearest)
  const double h = a + b, bb = h - a, err = (a - (h - bb)) + (b - bb);  // h + err = a + b exactly
  const double d = h - s;                                                 // exact (Sterbenz) when s is near h
  if (d != 0) return d > 0 ? 1 : -1;
  return err > 0 ? 1 : (err < 0 ? -1 : 0);
}
}  // namespace

BOOST_AUTO_TEST_CASE(operations_inside_an_upward_scope_enclose_exactly) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-30, 30);
  constexpr int n = 20000;
  std::vector<double> a(n), b(n), c(n), d(n);
  for (int i = 0; i < n; ++i) {
    a[i] = std::ldexp(unit(rng), expo(rng));
    b[i] = std::ldexp(unit(rng), expo(rng));
    c[i] = std::ldexp(unit(rng), expo(rng));
    d[i] = std::ldexp(unit(rng), expo(rng));
  }
  std::vector<interval> prod(n), sum(n), diff(n), prod_nearest(n);
  {
    const appell::upward_rounding scope;
    BOOST_TEST(appell::detail::upward_known);
    for (int i = 0; i < n; ++i) {
      prod[i] = interval(a[i]) * interval(b[i]);
      sum[i] = interval(a[i]) + interval(b[i]);
      diff[i] = interval(c[i]) - interval(d[i]);
    }
    {
      const appell::nearest_rounding inner;  // the flag is off again: operations switch for themselves
      BOOST_TEST(!appell::detail::upward_known);
      for (int i = 0; i < n; ++i) prod_nearest[i] = interval(a[i]) * interval(b[i]);
    }
    BOOST_TEST(appell::detail::upward_known);
    BOOST_TEST(scope.intact());
  }
  BOOST_TEST(!appell::detail::upward_known);
  BOOST_TEST(std::fegetround() == FE_TONEAREST);
  int missed = 0, wide = 0;
  for (int i = 0; i < n; ++i) {
    // enclosure, and tightness: each bound is the exact value rounded outward (at most 1 ulp away)
    missed += exact_minus_product(a[i], b[i], prod[i].lower()) < 0 || exact_minus_product(a[i], b[i], prod[i].upper()) > 0;
    missed += !(prod_nearest[i].lower() == prod[i].lower() && prod_nearest[i].upper() == prod[i].upper());
    wide += std::nextafter(prod[i].lower(), INFINITY) < prod[i].upper() &&
            std::nextafter(std::nextafter(prod[i].lower(), INFINITY), INFINITY) < prod[i].upper();
    missed += sign_of_sum_minus(a[i], b[i], sum[i].lower()) < 0 || sign_of_sum_minus(a[i], b[i], sum[i].upper()) > 0;
    missed += sign_of_sum_minus(c[i], -d[i], diff[i].lower()) < 0 || sign_of_sum_minus(c[i], -d[i], diff[i].upper()) > 0;
  }
  BOOST_TEST(missed == 0);
  BOOST_TEST(wide == 0);
}

BOOST_AUTO_TEST_CASE(a_mode_changed_behind_the_scope_is_detected) {
  const appell::upward_rounding scope;
  std::fesetround(FE_TONEAREST);  // what a careless callback could do
  BOOST_TEST(!scope.intact());
  std::fesetround(FE_UPWARD);
  BOOST_TEST(scope.intact());
}

BOOST_AUTO_TEST_CASE(flush_to_zero_left_by_other_code_is_turned_off) {
  // A program linked with -ffast-math (GCC's crtfastmath) starts with MXCSR's flush-to-zero and
  // denormals-are-zero bits set: the product 1e-160 x 1e-160 = 1e-320 (subnormal), rounded up,
  // would flush to +0, an upper bound below the true product, and a subnormal operand would be
  // read as 0. Every mode appell sets turns both bits off; an upward scope with them set again
  // behind its back is not intact.
  const unsigned saved = appell::detail::read_mxcsr();
  appell::detail::write_mxcsr(saved | 0x8040u);
  volatile double tiny_v = 1e-160, sub_v = 0x1p-1070;  // not constants the compiler could fold
  const double tiny = tiny_v, sub = sub_v;
  const interval outside = interval(tiny) * interval(tiny);  // the operation sets the mode itself
  interval inside, sub_sum;
  bool intact = false, intact_after = true;
  {
    const appell::upward_rounding scope;
    inside = interval(tiny) * interval(tiny);
    sub_sum = interval(sub) + interval(sub);
    intact = scope.intact();
    appell::detail::write_mxcsr(appell::detail::read_mxcsr() | 0x8000u);  // flush-to-zero set behind the scope
    intact_after = scope.intact();
    appell::detail::write_mxcsr(appell::detail::read_mxcsr() & ~0x8000u);
  }
  const unsigned after = appell::detail::read_mxcsr();
  appell::detail::write_mxcsr(saved);
  BOOST_TEST(outside.lower() > 0.0);  // 1e-320 rounded down and up: subnormals, not flushed
  BOOST_TEST(outside.lower() <= outside.upper());
  BOOST_TEST(outside.upper() < 1.001e-320);
  BOOST_TEST(inside.lower() == outside.lower());
  BOOST_TEST(inside.upper() == outside.upper());
  BOOST_TEST(sub_sum.lower() == 0x1p-1069);  // the subnormals read as themselves, added exactly
  BOOST_TEST(sub_sum.upper() == 0x1p-1069);
  BOOST_TEST(intact);
  BOOST_TEST(!intact_after);
  BOOST_TEST((after & 0x8040u) == 0x8040u);  // the scope gave back the mode it found
}

BOOST_AUTO_TEST_CASE(products_with_infinite_bounds_use_zero_times_infinity_is_zero) {
  const double inf = INFINITY;
  const appell::upward_rounding scope;  // the fast path's slow branch, under the flag
  const interval p1 = interval(0.0, 1.0) * interval(1.0, inf);
  BOOST_TEST(p1.lower() == 0.0);
  BOOST_TEST(p1.upper() == inf);
  const interval p2 = interval(0.0, 0.0) * interval(-inf, inf);
  BOOST_TEST(p2.lower() == 0.0);
  BOOST_TEST(p2.upper() == 0.0);
  const interval p3 = interval(-1.0, 2.0) * interval(-inf, 3.0);
  BOOST_TEST(p3.lower() == -inf);
  BOOST_TEST(p3.upper() == inf);
  const interval p4 = interval(-3.0, -2.0) * interval(4.0, inf);
  BOOST_TEST(p4.lower() == -inf);
  BOOST_TEST(p4.upper() == -8.0);
  BOOST_TEST(boost::numeric::empty(interval::empty() * interval(1.0, 2.0)));
}
