// appell::mpfi's backend (include/appell/scalar/mpfi_backend.hpp: both bounds in
// one allocation) against Boost's own mpfi_float_backend<0>, which it replaced:
//  * a differential run: 300,000 random steps on 48 pairs of values -- copies,
//    move assignments (then assignment to the value moved from), swaps, precision changes of
//    the default and of values, mixed-precision + - * / (also in place and
//    aliased), products and quotients by unsigned integers, sqrt, exp, atan,
//    abs, negation, built-in numbers (long, long long, unsigned long long,
//    double, long double; magnitudes up to 2^+-1000) -- after each of which the
//    two agree bound for bound, sign of zero and precision included.  Where both
//    sides call the same MPFI function (/, exp, atan, ...) this checks the
//    backend's plumbing (precisions, aliasing, ownership), not MPFI; + - * are
//    appell's own endpoint operations (mpfi_ops.hpp);
//  * the cases where appell differs on purpose: sqrt and log restricted to
//    their domain, round_prec/set_prec, self-assignment (x = x keeps x; Boost's
//    backend makes it NaN), values left empty by a move construction that stay
//    usable (Boost's crash), text input decided on the exact decimals;
//  * the rest of the backend's surface: str and its round trip, conversions,
//    pow (zero bases, aliasing), floor/ceil, frexp, numeric_limits, and MPFI's
//    cbrt, log1p, expm1, asinh, acosh, atanh, hypot.
//  * relocation: a value's bytes moved to new storage (as Eigen's conservativeResize does)
//    make a valid value, at 320 bits and below (significands inside the value) and above.
// CTest runs this suite a second time under valgrind (mpfi_backend_memcheck)
// when valgrind is installed: invalid accesses and leaks fail it.
#define BOOST_TEST_MODULE mpfi_backend
#include <boost/test/unit_test.hpp>

#include <Eigen/Core>
#include <boost/multiprecision/mpfi.hpp>
#include <cmath>
#include <cstring>
#include <new>
#include <random>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/eigen.hpp"
#include "appell/scalar/functions.hpp"
#include "mpfr_same.hpp"

using namespace appell;
using boost_mpfi = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<0>, boost::multiprecision::et_off>;

namespace {

std::mt19937_64 rng(20261121);
int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

using appell::test::same;  // bound for bound (tests/mpfr_same.hpp)
bool same(const mpfi& x, const boost_mpfi& y) {
  return same(&x.backend().data()->left, &y.backend().data()->left) &&
         same(&x.backend().data()->right, &y.backend().data()->right);
}
std::string show(mpfi_srcptr p) {
  char buf[200];
  mpfr_snprintf(buf, sizeof buf, "[%.20Rg, %.20Rg] (%ld bits)", &p->left, &p->right, (long)mpfi_get_prec(p));
  return buf;
}

double random_double() {
  const int kind = uniform(0, 15);
  if (kind == 0) return 0.0;
  if (kind == 1) return -0.0;
  if (kind == 2) return uniform(-5, 5);
  if (kind == 3) return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), uniform(-1000, 1000));
  return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), uniform(-40, 40));
}

const unsigned digits10_choices[] = {1, 5, 15, 16, 19, 20, 33, 34, 38, 39, 77, 78, 300};

// x within y (bounds compared exactly)
bool subset_of(const mpfi& x, const mpfi& y) {
  return mpfr_lessequal_p(&y.backend().data()->left, &x.backend().data()->left) &&
         mpfr_lessequal_p(&x.backend().data()->right, &y.backend().data()->right);
}

}  // namespace

BOOST_AUTO_TEST_CASE(differential_run_against_boosts_mpfi_backend) {
  constexpr int slots = 48;
  const unsigned saved = mpfi::default_precision();
  std::vector<mpfi> a(slots);
  std::vector<boost_mpfi> b(slots);
  long checked = 0;
  for (int step = 0; step < 300000; ++step) {
    const int i = uniform(0, slots - 1), j = uniform(0, slots - 1), k = uniform(0, slots - 1);
    const int op = uniform(0, 25);
    std::string what;
    switch (op) {
      case 0: {  // the default precision of new values
        const unsigned d = digits10_choices[uniform(0, std::size(digits10_choices) - 1)];
        mpfi::default_precision(d);
        boost_mpfi::default_precision(d);
        what = "default precision";
        break;
      }
      case 1: {
        if (i == j) {  // Boost's backend turns x = x into NaN (mpfi_set_prec before mpfi_set); appell keeps x
          const mpfi before = a[i];
          a[i] = a[j];
          BOOST_TEST(same(&a[i].backend().data()->left, &before.backend().data()->left));
          BOOST_TEST(same(&a[i].backend().data()->right, &before.backend().data()->right));
          continue;
        }
        a[i] = a[j], b[i] = b[j];
        what = "copy-assign";
        break;
      }
      case 2: {
        a[i] = mpfi(a[j]), b[i] = boost_mpfi(b[j]);
        what = "copy-construct";
        break;
      }
      case 3: {  // move out of j, then assign to the moved-from value
        if (i == j) continue;
        a[i] = std::move(a[j]), b[i] = std::move(b[j]);
        const double d = random_double();
        if (uniform(0, 1)) a[j] = d, b[j] = d;
        else a[j] = a[k == j ? i : k], b[j] = b[k == j ? i : k];
        what = "move";
        break;
      }
      case 4: std::swap(a[i], a[j]), std::swap(b[i], b[j]), what = "swap"; break;
      case 5: {
        const double d = random_double();
        a[i] = d, b[i] = d;
        what = "double";
        break;
      }
      case 6: {
        const long v = uniform(-1000, 1000);
        a[i] = v, b[i] = v;
        what = "long";
        break;
      }
      case 7: a[i] = a[j] + a[k], b[i] = b[j] + b[k], what = "+"; break;
      case 8: a[i] = a[j] - a[k], b[i] = b[j] - b[k], what = "-"; break;
      case 9: a[i] = a[j] * a[k], b[i] = b[j] * b[k], what = "*"; break;
      case 10: a[i] = a[j] / a[k], b[i] = b[j] / b[k], what = "/"; break;
      case 11: a[i] += a[j], b[i] += b[j], what = "+="; break;
      case 12: a[i] -= a[j], b[i] -= b[j], what = "-="; break;
      case 13: a[i] *= a[j], b[i] *= b[j], what = "*="; break;
      case 14: a[i] /= a[j], b[i] /= b[j], what = "/="; break;
      case 15: a[i] = -a[j], b[i] = -b[j], what = "negate"; break;
      case 16: {  // both give MPFI's sqrt where the argument is in the domain
        if (mpfr_sgn(&a[j].backend().data()->left) < 0 || mpfi_nan_p(a[j].backend().data())) continue;
        a[i] = sqrt(a[j]), b[i] = sqrt(b[j]);
        what = "sqrt";
        break;
      }
      case 17: {
        if (mpfr_cmp_ui(&a[j].backend().data()->right, 100) > 0) continue;  // keep the values finite
        a[i] = exp(a[j]), b[i] = exp(b[j]);
        what = "exp";
        break;
      }
      case 18: a[i] = atan(a[j]), b[i] = atan(b[j]), what = "atan"; break;
      case 19: a[i] = abs(a[j]), b[i] = abs(b[j]), what = "abs"; break;
      case 20: {  // a value's own precision, kept value enclosed outward
        const unsigned d = digits10_choices[uniform(0, std::size(digits10_choices) - 1)];
        a[i].precision(d), b[i].precision(d);
        what = "precision(d)";
        break;
      }
      case 21: {  // from a mixed-precision pair, written over an operand
        a[i] = a[i] * a[j] + a[i], b[i] = b[i] * b[j] + b[i];
        what = "x*y+x";
        break;
      }
      case 22: {  // 64-bit integers: exact at 64 bits and more, rounded outward below
        const long long v = static_cast<long long>(rng() >> uniform(1, 63)) * (uniform(0, 1) ? 1 : -1);
        const unsigned long long u = rng() >> uniform(0, 63);
        if (v == 0 || u == 0) continue;  // zero: see zero_has_mpfis_signs
        if (uniform(0, 1)) a[i] = v, b[i] = v;
        else a[i] = u, b[i] = u;
        what = "long long";
        break;
      }
      case 23: {
        const long double d = static_cast<long double>(random_double()) / 3;  // 64-bit significand
        if (d == 0) continue;  // zero: see zero_has_mpfis_signs
        a[i] = d, b[i] = d;
        what = "long double";
        break;
      }
      case 24: {
        const unsigned u = static_cast<unsigned>(uniform(1, 1000));
        a[i] = a[j] * u, b[i] = b[j] * u;
        what = "* unsigned";
        break;
      }
      case 25: {
        const unsigned u = static_cast<unsigned>(uniform(1, 1000));
        a[i] = a[j] / u, b[i] = b[j] / u;
        what = "/ unsigned";
        break;
      }
    }
    ++checked;
    if (!same(a[i], b[i]))
      BOOST_FAIL("step " << step << " (" << what << "): appell " << show(a[i].backend().data()) << " vs Boost "
                         << show(b[i].backend().data()));
    if (op == 3 && !same(a[j], b[j])) BOOST_FAIL("step " << step << " (assignment after a move) differs");
  }
  for (int i = 0; i < slots; ++i) BOOST_TEST(same(a[i], b[i]));
  mpfi::default_precision(saved);
  boost_mpfi::default_precision(saved);
  BOOST_TEST_MESSAGE("differential run: " << checked << " steps, all equal bound for bound");
}

BOOST_AUTO_TEST_CASE(new_values_are_mpfi_zero_at_the_default_precision) {
  const mp_precision_scope scope(200);
  const mpfi z;
  BOOST_TEST(mpfi_get_prec(z.backend().data()) == static_cast<mpfr_prec_t>(scope.bits()));
  BOOST_TEST(mpfr_zero_p(&z.backend().data()->left));
  BOOST_TEST(!mpfr_signbit(&z.backend().data()->left));  // [+0, -0], MPFI's zero
  BOOST_TEST(mpfr_signbit(&z.backend().data()->right));
  BOOST_TEST(mpfi_is_zero(z.backend().data()) != 0);
}

// Every way of making a zero gives MPFI's [+0, -0] (Boost's backend gives [+0, +0]
// for a long long or long double 0, which the differential run therefore skips).
BOOST_AUTO_TEST_CASE(zero_has_mpfis_signs) {
  const mp_precision_scope scope(100);
  mpfi z[6];
  z[0] = 0L, z[1] = 0UL, z[2] = 0LL, z[3] = 0ULL, z[4] = 0.0L, z[5] = -0.0;
  for (const mpfi& x : z) {
    BOOST_TEST(mpfi_is_zero(x.backend().data()) != 0);
    BOOST_TEST(!mpfr_signbit(&x.backend().data()->left));
    BOOST_TEST(mpfr_signbit(&x.backend().data()->right));
  }
}

BOOST_AUTO_TEST_CASE(set_prec_and_round_prec) {
  const mp_precision_scope scope(128);
  mpfi x = mpfi(1) / 3;
  x.backend().round_prec(20);
  BOOST_TEST(mpfi_get_prec(x.backend().data()) == 20);
  mpfr_value third(400);
  mpfr_set_ui(third, 1, MPFR_RNDN);
  mpfr_div_ui(third, third, 3, MPFR_RNDN);
  BOOST_TEST(contains(x, third.get()));  // outward
  BOOST_TEST(mpfr_cmp(&x.backend().data()->left, &x.backend().data()->right) < 0);
  const mpfi before = x;
  x.backend().round_prec(1000);  // more bits: the same bounds
  BOOST_TEST(mpfi_get_prec(x.backend().data()) == 1000);
  BOOST_TEST(mpfr_equal_p(&x.backend().data()->left, &before.backend().data()->left));
  BOOST_TEST(mpfr_equal_p(&x.backend().data()->right, &before.backend().data()->right));
  x.backend().set_prec(64);
  BOOST_TEST(mpfi_get_prec(x.backend().data()) == 64);
  BOOST_TEST(mpfi_nan_p(x.backend().data()) != 0);
  x = 2;  // assignment of a built-in number keeps the precision
  BOOST_TEST(mpfi_get_prec(x.backend().data()) == 64);
  BOOST_TEST(mpfr_cmp_ui(&x.backend().data()->left, 2) == 0);
}

BOOST_AUTO_TEST_CASE(domain_restricted_functions) {
  const mp_precision_scope scope(113);
  const mpfi x = mpfi_from_bounds(mpfr(-1), mpfr(4));
  const mpfi s = sqrt(x);
  BOOST_TEST(mpfr_zero_p(&s.backend().data()->left));
  BOOST_TEST(mpfr_cmp_ui(&s.backend().data()->right, 2) == 0);
  const mpfi l = log(x);
  BOOST_TEST((mpfr_inf_p(&l.backend().data()->left) && mpfr_sgn(&l.backend().data()->left) < 0));  // -inf
  BOOST_TEST(mpfr_sgn(&l.backend().data()->right) > 0);
  const mpfi neg = mpfi_from_bounds(mpfr(-2), mpfr(-1));
  const mpfi nonpos = mpfi_from_bounds(mpfr(-2), mpfr(0));
  BOOST_CHECK_THROW(sqrt(neg), appell::domain_error);
  BOOST_CHECK_THROW(log(nonpos), appell::domain_error);
  BOOST_CHECK_THROW(log2(nonpos), appell::domain_error);
  BOOST_CHECK_THROW(log10(nonpos), appell::domain_error);
  BOOST_TEST(mpfr_zero_p(&sqrt(nonpos).backend().data()->right));  // sqrt [-2, 0] = [0, 0]
  const mpfi l2 = log2(mpfi_from_bounds(mpfr(-3), mpfr(8)));
  BOOST_TEST(mpfr_cmp_ui(&l2.backend().data()->right, 3) == 0);
}

BOOST_AUTO_TEST_CASE(comparisons_and_signs_decided_or_refused) {
  const mp_precision_scope scope(113);
  const mpfi a = mpfi_from_bounds(mpfr(1), mpfr(2)), b = mpfi_from_bounds(mpfr(3), mpfr(4));
  const mpfi c = mpfi_from_bounds(mpfr(-1), mpfr(1));
  BOOST_TEST((a < b));
  BOOST_TEST((b > a));
  BOOST_TEST((a == a));
  BOOST_CHECK_THROW((void)(a < mpfi_from_bounds(mpfr(1.5), mpfr(5))), mp::interval_error);
  BOOST_TEST(a.sign() == 1);
  BOOST_TEST((-a).sign() == -1);
  BOOST_TEST(mpfi(0).sign() == 0);
  BOOST_CHECK_THROW((void)c.sign(), mp::interval_error);
  BOOST_TEST((a < 3));
  BOOST_CHECK_THROW((void)(c < 0), mp::interval_error);
}

BOOST_AUTO_TEST_CASE(text_conversions_pow_floor_frexp) {
  const mp_precision_scope scope(113);
  BOOST_TEST(mpfi(3).str() == "3");
  const std::string s = mpfi_from_bounds(mpfr(1), mpfr(2)).str();
  BOOST_TEST(s == "{1,2}");
  const mpfi parsed("0.1");
  mpfr_value tenth(400);
  mpfr_set_ui(tenth, 1, MPFR_RNDN);
  mpfr_div_ui(tenth, tenth, 10, MPFR_RNDN);
  BOOST_TEST(contains(parsed, tenth.get()));
  BOOST_CHECK_THROW(mpfi("not a number"), std::runtime_error);
  BOOST_TEST(static_cast<double>(mpfi_from_bounds(mpfr(1), mpfr(2))) == 1.5);  // the midpoint
  BOOST_TEST(static_cast<long>(mpfi_from_bounds(mpfr(3), mpfr(5))) == 4);

  BOOST_TEST(static_cast<mpfr>(mpfi_from_bounds(mpfr(1), mpfr(2))) == mpfr(1.5));  // to mpfr: the midpoint
  const mpfi two_args(mpfr(-1), mpfr(0.5));  // number(lower, upper)
  BOOST_TEST((mpfr_cmp_si(&two_args.backend().data()->left, -1) == 0 && mpfr_cmp_d(&two_args.backend().data()->right, 0.5) == 0));
  BOOST_CHECK_THROW(mpfi(mpfr(2), mpfr(1)), std::runtime_error);

  const mpfi p = pow(mpfi_from_bounds(mpfr(2), mpfr(3)), mpfi(2));
  BOOST_TEST(mpfr_cmp_ui(&p.backend().data()->left, 4) <= 0);
  BOOST_TEST(mpfr_cmp_ui(&p.backend().data()->right, 9) >= 0);
  const mpfi m = pow(mpfi(-2), mpfi(3));  // integer exponent of a negative base
  BOOST_TEST(mpfr_cmp_si(&m.backend().data()->left, -8) <= 0);
  BOOST_TEST(mpfr_cmp_si(&m.backend().data()->right, -8) >= 0);
  BOOST_TEST(mpfr_cmp_si(&m.backend().data()->right, -7) < 0);
  BOOST_TEST(mpfi_nan_p(pow(mpfi(-2), mpfi(0.5)).backend().data()) != 0);  // no real value: NaN, never a number
  BOOST_TEST(mpfr_cmp_ui(&pow(mpfi(0), mpfi(0)).backend().data()->left, 1) == 0);

  const mpfi f = floor(mpfi_from_bounds(mpfr(1.25), mpfr(1.75)));
  BOOST_TEST(mpfr_cmp_ui(&f.backend().data()->left, 1) == 0);
  BOOST_TEST(mpfr_cmp_ui(&ceil(mpfi_from_bounds(mpfr(1.25), mpfr(1.75))).backend().data()->right, 2) == 0);
  BOOST_CHECK_THROW(floor(mpfi_from_bounds(mpfr(0.5), mpfr(1.5))), mp::interval_error);
  int e = 0;
  const mpfi fr = frexp(mpfi_from_bounds(mpfr(5), mpfr(6)), &e);
  BOOST_TEST(e == 3);
  BOOST_TEST(mpfr_cmp_d(&fr.backend().data()->left, 0.625) == 0);
  BOOST_TEST(mpfr_cmp_d(&fr.backend().data()->right, 0.75) == 0);
}

BOOST_AUTO_TEST_CASE(text_round_trips_and_encloses) {
  const mp_precision_scope scope(113);
  for (int k = 0; k < 2000; ++k) {
    mpfr lo = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), uniform(-300, 300));
    lo /= 3;  // all 113 bits (mpfr and mpfi both have exactly 113)
    BOOST_TEST_REQUIRE(lo.backend().prec() == static_cast<mpfr_prec_t>(mp_precision_bits()));
    const mpfr hi = lo + abs(lo) * std::ldexp(1.0, -uniform(20, 100));
    const mpfi x = mpfi_from_bounds(lo, hi);
    const mpfi y(x.str(0));  // "{a,b}" at full precision
    BOOST_TEST_REQUIRE(subset_of(x, y), x.str(0) << " read back as " << y.str(0));
    BOOST_TEST(mpfi_from_bounds(lo, lo).str(0).front() != '{');
  }
  BOOST_CHECK_THROW(mpfi("{2,1}"), std::runtime_error);
  BOOST_CHECK_THROW(mpfi("[1,"), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(text_input_is_strict_and_decided_exactly) {
  const mp_precision_scope scope(53);
  for (const char* bad : {"nan", "[nan, 1]", "[-1, nan]", "{nan,nan}", "[1,2]junk", "[1,2", "1.0x", "", "[1,2,3]",
                          "[inf, 1]", "[1, -inf]", "[0.3000000000000000001, 0.3]"})  // the last: a > b by 1e-19,
    BOOST_CHECK_THROW(mpfi{bad}, std::runtime_error);                                  // below one ulp at 53 bits
  const mpfi z("0");
  BOOST_TEST((!mpfr_signbit(&z.backend().data()->left) && mpfr_signbit(&z.backend().data()->right)));
  const mpfi h("[-inf, 1]");
  BOOST_TEST((mpfr_inf_p(&h.backend().data()->left) && mpfr_cmp_ui(&h.backend().data()->right, 1) == 0));
  const mpfi close("[0.3, 0.3000000000000000001]");  // a < b by 1e-19: accepted, enclosed
  mpfr_value lo(400), hi(400);
  decimal_to_mpfr("0.3", lo, MPFR_RNDD);
  decimal_to_mpfr("0.3000000000000000001", hi, MPFR_RNDU);
  BOOST_TEST((contains(close, lo.get()) && contains(close, hi.get())));
  // str(d) rounds outward: the text encloses the value
  const mpfi third = mpfi(1) / 3;
  const std::string t = third.str(5);
  BOOST_TEST(t == "{3.3333e-01,3.3334e-01}");
  BOOST_TEST(mpfi(2).str(5) == "2.0000e+00");
}

BOOST_AUTO_TEST_CASE(limits_and_hypot) {
  const mp_precision_scope scope(113);
  using L = std::numeric_limits<mpfi>;
  BOOST_TEST(!L::is_specialized);  // Boost.Math's point algorithms must refuse mpfi
  BOOST_TEST((mpfr_inf_p(&L::infinity().backend().data()->left) && mpfr_sgn(&L::infinity().backend().data()->left) > 0));
  BOOST_TEST(mpfi_nan_p(L::quiet_NaN().backend().data()) != 0);
  const mpfi eps = L::epsilon();
  BOOST_TEST(mpfr_cmp_ui_2exp(&eps.backend().data()->left, 1, 1 - static_cast<long>(scope.bits())) == 0);
  BOOST_TEST(mpfr_number_p(&(L::max)().backend().data()->right));
  BOOST_TEST(mpfr_sgn(&(L::min)().backend().data()->left) > 0);
  const mpfi h = hypot(mpfi(3), mpfi_from_bounds(mpfr(4), mpfr(4)));
  BOOST_TEST(contains(h, mpfr(5).backend().data()));
  BOOST_TEST(mpfi_get_prec(h.backend().data()) == static_cast<mpfr_prec_t>(scope.bits()));
}

// A moved-from value is valid (a new [+0, -0] on first use) and never touches
// the block it gave away, whichever of the two is used or destroyed first.
BOOST_AUTO_TEST_CASE(moved_from_values_stay_valid) {
  const mp_precision_scope scope(128);
  mpfi a = mpfi(1) / 3, c = 2;
  const mpfi third = a;
  mpfi b(std::move(a));
  a += c;  // reads as 0 + 2
  BOOST_TEST(mpfr_cmp_ui(&a.backend().data()->left, 2) == 0);
  BOOST_TEST(mpfr_cmp_ui(&a.backend().data()->right, 2) == 0);
  BOOST_TEST(mpfr_equal_p(&b.backend().data()->left, &third.backend().data()->left));  // b untouched
  BOOST_TEST(mpfr_equal_p(&b.backend().data()->right, &third.backend().data()->right));
  {
    mpfi owner(std::move(b));  // b moved from; owner destroyed at the end of this scope
  }
  const mpfi copy(b);  // copy of a moved-from value: [+0, -0]
  BOOST_TEST(mpfi_is_zero(copy.backend().data()) != 0);
  mpfi d = third;
  mpfi e(std::move(d));
  d.backend().round_prec(64);
  BOOST_TEST(mpfi_get_prec(d.backend().data()) == 64);
  BOOST_TEST(mpfi_is_zero(d.backend().data()) != 0);
  mpfi f = third;
  mpfi g(std::move(f));
  BOOST_TEST(-f == mpfi(0));
  BOOST_TEST(f.str() == "0");
  mpfi h = third;
  mpfi k(std::move(h));
  h = third;  // assignment to a moved-from value
  BOOST_TEST(mpfr_equal_p(&h.backend().data()->left, &third.backend().data()->left));
}

BOOST_AUTO_TEST_CASE(pow_of_zero_bases_and_aliased_operands) {
  const mp_precision_scope scope(113);
  const mpfi zero(0);
  const mpfi p01 = pow(zero, mpfi_from_bounds(mpfr(0), mpfr(1)));  // 0^0 = 1 and 0^e = 0 for e > 0
  BOOST_TEST(mpfr_zero_p(&p01.backend().data()->left));
  BOOST_TEST(mpfr_cmp_ui(&p01.backend().data()->right, 1) == 0);
  BOOST_TEST(mpfi_is_zero(pow(zero, mpfi(2)).backend().data()) != 0);
  BOOST_TEST(mpfi_nan_p(pow(zero, mpfi(-1)).backend().data()) != 0);  // no real value
  const mpfi q = pow(mpfi_from_bounds(mpfr(0), mpfr(4)), mpfi(2));    // base touching 0, e > 0
  BOOST_TEST(mpfr_zero_p(&q.backend().data()->left));
  BOOST_TEST(mpfr_cmp_ui(&q.backend().data()->right, 16) >= 0);
  BOOST_TEST(mpfr_cmp_ui(&q.backend().data()->right, 17) < 0);
  BOOST_TEST(mpfi_nan_p(pow(mpfi_from_bounds(mpfr(-1), mpfr(4)), mpfi(0.5)).backend().data()) != 0);
  // base touching 0 with an exponent that contains 0: NaN (0^0 and 0^-e), never a finite box
  BOOST_TEST(mpfi_nan_p(pow(mpfi_from_bounds(mpfr(0), mpfr(4)), mpfi_from_bounds(mpfr(-1), mpfr(1))).backend().data()) != 0);
  BOOST_TEST(mpfi_nan_p(pow(mpfi_from_bounds(mpfr(0), mpfr(4)), mpfi(0)).backend().data()) != 0);
  const mpfi h = pow(mpfi_from_bounds(mpfr(0), mpfr(4)), mpfi(0.5));  // [0, 2]
  BOOST_TEST(mpfr_zero_p(&h.backend().data()->left));
  BOOST_TEST((mpfr_cmp_ui(&h.backend().data()->right, 2) >= 0 && mpfr_cmp_d(&h.backend().data()->right, 2.0001) < 0));
  const mpfi even = pow(mpfi_from_bounds(mpfr(-3), mpfr(-2)), mpfi(2));  // [4, 9], positive
  BOOST_TEST((mpfr_cmp_ui(&even.backend().data()->left, 4) <= 0 && mpfr_cmp_d(&even.backend().data()->left, 3.999) > 0));
  BOOST_TEST((mpfr_cmp_ui(&even.backend().data()->right, 9) >= 0 && mpfr_cmp_d(&even.backend().data()->right, 9.001) < 0));
  // r aliasing the exponent, then the base: the same as into a fresh value
  mpfi e = 3, b = mpfi_from_bounds(mpfr(1.5), mpfr(2));
  const mpfi fresh = pow(b, e);
  eval_pow(e.backend(), b.backend(), e.backend());
  BOOST_TEST(mpfr_equal_p(&e.backend().data()->left, &fresh.backend().data()->left));
  BOOST_TEST(mpfr_equal_p(&e.backend().data()->right, &fresh.backend().data()->right));
  mpfi n = -2;
  eval_pow(n.backend(), n.backend(), mpfi(3).backend());
  BOOST_TEST(contains(n, mpfr(-8).backend().data()));
  BOOST_TEST(mpfr_sgn(&n.backend().data()->right) < 0);
}

// MPFI's cbrt, log1p, expm1, asinh, acosh, atanh (found by argument-dependent
// lookup for appell::mpfi): each contains the 320-bit MPFR value at 500 random
// points of its domain.
BOOST_AUTO_TEST_CASE(mpfi_only_functions_contain_320_bit_values) {
  const mp_precision_scope scope(113);
  struct fn {
    const char* name;
    mpfi (*f)(const mpfi&);
    int (*ref)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
    double lo, hi;
  };
  const fn fns[] = {{"cbrt", [](const mpfi& x) { return cbrt(x); }, mpfr_cbrt, -1e6, 1e6},
                    {"log1p", [](const mpfi& x) { return log1p(x); }, mpfr_log1p, -0.999, 1e6},
                    {"expm1", [](const mpfi& x) { return expm1(x); }, mpfr_expm1, -50, 50},
                    {"asinh", [](const mpfi& x) { return asinh(x); }, mpfr_asinh, -1e6, 1e6},
                    {"acosh", [](const mpfi& x) { return acosh(x); }, mpfr_acosh, 1, 1e6},
                    {"atanh", [](const mpfi& x) { return atanh(x); }, mpfr_atanh, -0.999, 0.999}};
  int checked = 0;
  for (const fn& f : fns) {
    for (int k = 0; k < 500; ++k) {
      const double v = std::uniform_real_distribution<double>(f.lo, f.hi)(rng) / (k % 2 ? 1 : 1e3);
      if (v < f.lo) continue;
      const mpfi y = f.f(mpfi(v));
      mpfr_value x(320), exact(320);
      mpfr_set_d(x, v, MPFR_RNDN);
      f.ref(exact, x, MPFR_RNDN);  // within 2^-319 relative of the truth, far inside y's width
      BOOST_TEST_REQUIRE(contains(y, exact.get()), f.name << "(" << v << ") = " << y.str(0));
      BOOST_TEST_REQUIRE(mpfi_get_prec(y.backend().data()) == static_cast<mpfr_prec_t>(scope.bits()));
      // a wide argument [v, w]: the functions are monotone, so f(v) and f(w) are inside
      const double w = v + std::abs(v) * 1e-3 + 1e-6;
      if (w > f.hi) continue;
      const mpfi Y = f.f(mpfi_from_bounds(mpfr(v), mpfr(w)));
      mpfr_value xw(320), ew(320);
      mpfr_set_d(xw, w, MPFR_RNDN);
      f.ref(ew, xw, MPFR_RNDN);
      BOOST_TEST_REQUIRE((contains(Y, exact.get()) && contains(Y, ew.get())), f.name << " on [" << v << ", " << w << "]");
      ++checked;
    }
  }
  BOOST_TEST_MESSAGE("MPFI-only functions: " << checked << " points contained");
}

// Up to 320 bits (--bits 256 with its guard bits) a value keeps both bounds' significands inside itself: bytes moved to new
// storage without a constructor (Eigen's conservativeResize reallocs its elements) still make a
// valid value, with the bounds in either order (negate() swaps them), and so does Eigen's resize.
BOOST_AUTO_TEST_CASE(values_survive_bitwise_relocation) {
  for (const unsigned bits : {64u, 256u, 257u, 1000u}) {
    const mp_precision_scope scope(bits);
    for (const bool negated : {false, true}) {
      mpfi third = mpfi(1) / 3;
      if (negated) third = -third;
      alignas(mpfi) unsigned char from[sizeof(mpfi)], to[sizeof(mpfi)];
      new (from) mpfi(third);
      std::memcpy(to, from, sizeof(mpfi));
      std::memset(from, 0xA5, sizeof(mpfi));  // the old place overwritten
      mpfi& moved = *std::launder(reinterpret_cast<mpfi*>(to));
      BOOST_TEST(same(&moved.backend().data()->left, &third.backend().data()->left));
      BOOST_TEST(same(&moved.backend().data()->right, &third.backend().data()->right));
      moved = moved * 3;
      BOOST_TEST(contains(moved, mpfr(negated ? -1 : 1).backend().data()));
      moved.~mpfi();
    }
    Eigen::Matrix<mpfi, Eigen::Dynamic, 1> x(3);
    for (int i = 0; i < 3; ++i) x(i) = mpfi(i + 1) / 7;
    const Eigen::Matrix<mpfi, Eigen::Dynamic, 1> before = x;
    x.conservativeResize(300);
    for (int i = 0; i < 3; ++i) {
      BOOST_TEST(same(&x(i).backend().data()->left, &before(i).backend().data()->left));
      BOOST_TEST(same(&x(i).backend().data()->right, &before(i).backend().data()->right));
    }
  }
}
