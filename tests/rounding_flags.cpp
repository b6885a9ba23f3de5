// The compile flags that keep interval arithmetic rigorous are in force.
// Without -frounding-math, GCC at -O2/-O3 folds 1/3 and sqrt(2) of constant
// intervals into a single double (a thin, wrong box) -- DESIGN.md sec. 3.
#define BOOST_TEST_MODULE rounding_flags
#include <boost/test/unit_test.hpp>

#include <cfenv>

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
