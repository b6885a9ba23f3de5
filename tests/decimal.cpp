// Decimal input is enclosed exactly (interval types) or rounded once,
// correctly (point types); printing round-trips and rounds bounds outward.
// Checked against exact rationals (GMP), not against the code under test.
#define BOOST_TEST_MODULE decimal
#include <boost/test/unit_test.hpp>

#include <gmp.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/scalar/x87_bounds.hpp"

using namespace appell;

namespace {

// An exact rational, RAII.
struct rational_q {
  mpq_t q;
  explicit rational_q(const char* text) {  // "p/q" or "p"
    mpq_init(q);
    mpq_set_str(q, text, 10);
    mpq_canonicalize(q);
  }
  rational_q(const char* numerator, unsigned long pow10) {  // numerator / 10^pow10
    mpq_init(q);
    mpz_t n, d;
    mpz_init_set_str(n, numerator, 10);
    mpz_init(d);
    mpz_ui_pow_ui(d, 10, pow10);
    mpq_set_num(q, n);
    mpq_set_den(q, d);
    mpq_canonicalize(q);
    mpz_clear(n);
    mpz_clear(d);
  }
  ~rational_q() { mpq_clear(q); }
};

int cmp_mpfr_q(mpfr_srcptr x, const rational_q& r) { return mpfr_cmp_q(x, r.q); }

struct case_t {
  const char* text;
  const char* numerator;
  unsigned long pow10;
};
const case_t cases[] = {{"0.1", "1", 1},
                        {"1e-300", "1", 300},
                        {"123456789.123456789", "123456789123456789", 9},
                        {"-2.5e-3", "-25", 4},
                        {"0.5", "5", 1}};

template <class I>
void check_enclosure(const case_t& c, bool representable_in_53) {
  const I x = from_decimal<I>(c.text);
  rational_q exact(c.numerator, c.pow10);
  mpfr_value lo, hi;
  scalar_traits<I>::to_mpfr(x, lo, hi);
  BOOST_TEST(cmp_mpfr_q(lo, exact) <= 0, c.text << ": lower bound above the exact decimal");
  BOOST_TEST(cmp_mpfr_q(hi, exact) >= 0, c.text << ": upper bound below the exact decimal");
  if (representable_in_53) {
    BOOST_TEST(mpfr_equal_p(lo, hi), c.text << " is representable: the box must be thin");
  } else {
    // One ulp wide: hi is the successor of lo at the bound precision.
    mpfr_value next(mpfr_get_prec(lo));
    mpfr_set(next, lo, MPFR_RNDN);
    mpfr_nextabove(next);
    BOOST_TEST(mpfr_equal_p(next, hi), c.text << ": enclosure wider than one ulp");
    BOOST_TEST(cmp_mpfr_q(lo, exact) < 0);
    BOOST_TEST(cmp_mpfr_q(hi, exact) > 0);
  }
}

// |x - exact| <= |y - exact| for both neighbours y of x: x is the nearest.
template <class T>
void check_nearest(const case_t& c) {
  const T x = from_decimal<T>(c.text);
  rational_q exact(c.numerator, c.pow10);
  mpfr_value v;
  to_mpfr_exact(x, v);
  const mpfr_prec_t p = mpfr_get_prec(v);
  mpfr_value below(p), above(p);
  mpfr_set(below, v, MPFR_RNDN);
  mpfr_nextbelow(below);
  mpfr_set(above, v, MPFR_RNDN);
  mpfr_nextabove(above);
  // exact lies within half an ulp of x: between the midpoints to the neighbours.
  mpfr_value mlo(p + 2), mhi(p + 2);
  mpfr_add(mlo, v, below, MPFR_RNDN);  // exact at p+2 bits
  mpfr_div_2ui(mlo, mlo, 1, MPFR_RNDN);
  mpfr_add(mhi, v, above, MPFR_RNDN);
  mpfr_div_2ui(mhi, mhi, 1, MPFR_RNDN);
  BOOST_TEST(cmp_mpfr_q(mlo, exact) <= 0, scalar_traits<T>::name << " " << c.text << " not nearest");
  BOOST_TEST(cmp_mpfr_q(mhi, exact) >= 0, scalar_traits<T>::name << " " << c.text << " not nearest");
}

}  // namespace

BOOST_AUTO_TEST_CASE(interval_encloses_the_exact_decimal_in_one_ulp) {
  for (const auto& c : cases) check_enclosure<interval>(c, std::string(c.text) == "0.5");
}

BOOST_AUTO_TEST_CASE(mpfi_encloses_the_exact_decimal_in_one_ulp) {
  for (unsigned bits : {64u, 200u}) {
    mp_precision_scope scope(bits);
    for (const auto& c : cases) check_enclosure<mpfi>(c, std::string(c.text) == "0.5");
  }
}

BOOST_AUTO_TEST_CASE(point_types_round_the_exact_decimal_to_nearest) {
  mp_precision_scope scope(150);
  for (const auto& c : cases) {
    check_nearest<double>(c);
    check_nearest<long double>(c);
    check_nearest<float128>(c);
    check_nearest<mpfr>(c);
  }
}

BOOST_AUTO_TEST_CASE(dd_holds_the_decimal_to_106_bits) {
  // Below about 2^-969 the low double is subnormal and dd holds fewer than
  // 106 bits (1e-300 is such a number); the claim is for the normal range.
  for (const auto& c : cases) {
    if (std::string(c.text) == "1e-300") continue;
    const dd x = from_decimal<dd>(c.text);
    rational_q exact(c.numerator, c.pow10);
    mpfr_value v;
    to_mpfr_exact(x, v);
    mpfr_value err(400);
    mpfr_set_q(err, exact.q, MPFR_RNDN);
    mpfr_sub(err, err, v, MPFR_RNDN);
    mpfr_value tol(64);
    mpfr_set_q(tol, exact.q, MPFR_RNDN);
    mpfr_abs(tol, tol, MPFR_RNDN);
    mpfr_mul_2si(tol, tol, -105, MPFR_RNDN);
    mpfr_abs(err, err, MPFR_RNDN);
    BOOST_TEST(mpfr_lessequal_p(err, tol), c.text);
  }
}

BOOST_AUTO_TEST_CASE(a_subnormal_decimal_rounds_like_ieee) {
  // 2^-1074 = 4.94e-324 is the least subnormal; 3e-324 lies between 0 and it,
  // nearer to it; 7e-324 lies between 2^-1074 and 2^-1073, nearer to 2^-1074.
  BOOST_TEST(from_decimal<double>("3e-324") == std::ldexp(1.0, -1074));
  BOOST_TEST(from_decimal<double>("7e-324") == std::ldexp(1.0, -1074));
  const interval y = from_decimal<interval>("3e-324");
  BOOST_TEST(y.lower() == 0.0);
  BOOST_TEST(y.upper() == std::ldexp(1.0, -1074));
  const interval x = from_decimal<interval>("7e-324");
  BOOST_TEST(x.lower() == std::ldexp(1.0, -1074));
  BOOST_TEST(x.upper() == std::ldexp(1.0, -1073));
  const interval tiny = from_decimal<interval>("1e-400");
  BOOST_TEST(tiny.lower() == 0.0);
  BOOST_TEST(tiny.upper() == std::ldexp(1.0, -1074));
}

BOOST_AUTO_TEST_CASE(bad_literals_are_refused) {
  for (const char* bad : {"", "abc", "1e", "1e+", ".", "-", "0x10", "inf", "nan", " 1", "1 ", "1,5",
                          "1e99999999", "--1", "1.2.3"}) {
    BOOST_CHECK_THROW(from_decimal<double>(bad), parse_error);
    BOOST_CHECK_THROW(from_decimal<interval>(bad), parse_error);
  }
  for (const char* good : {"1", "-1", "+1", "1.", ".5", "1e5", "1E-5", "007"})
    BOOST_CHECK_NO_THROW(from_decimal<double>(good));
}

BOOST_AUTO_TEST_CASE(values_out_of_range_are_refused) {
  BOOST_CHECK_THROW(from_decimal<double>("1e400"), parse_error);
  BOOST_CHECK_THROW(from_decimal<interval>("-1e400"), parse_error);
  BOOST_CHECK_NO_THROW(from_decimal<long double>("1e400"));
  BOOST_CHECK_NO_THROW(from_decimal<mpfr>("1e400"));
}

BOOST_AUTO_TEST_CASE(enclosed_constants) {
  const interval pi = constant_pi<interval>();
  BOOST_TEST(pi.lower() == 3.141592653589793);
  BOOST_TEST(std::nextafter(pi.lower(), 4.0) == pi.upper());
  const interval two_fifths = rational<interval>(2, 5);
  rational_q exact("2/5");
  mpfr_value lo, hi;
  scalar_traits<interval>::to_mpfr(two_fifths, lo, hi);
  BOOST_TEST(cmp_mpfr_q(lo, exact) < 0);
  BOOST_TEST(cmp_mpfr_q(hi, exact) > 0);
  BOOST_TEST(rational<double>(2, 5) == 0.4);
}

BOOST_AUTO_TEST_CASE(printing_round_trips_and_rounds_bounds_outward) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-300, 300);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = std::ldexp(mant(rng), expo(rng));
    BOOST_REQUIRE(from_decimal<double>(to_decimal(x)) == x);
    const long double lx = static_cast<long double>(x) / 3.0L;
    BOOST_REQUIRE(from_decimal<long double>(to_decimal(lx)) == lx);
    const float128 q = float128(x) / 3;
    BOOST_REQUIRE(from_decimal<float128>(to_decimal(q)) == q);
    const interval box = interval(x) / interval(3.0);
    const interval back(from_decimal<interval>(lower_string(box)).lower(),
                        from_decimal<interval>(upper_string(box)).upper());
    BOOST_REQUIRE(back.lower() <= box.lower());
    BOOST_REQUIRE(back.upper() >= box.upper());
    ++checked;
  }
  BOOST_TEST_MESSAGE("round trips checked: " << checked);
  {
    mp_precision_scope scope(256);
    const mpfr third = mpfr(1) / 3;
    BOOST_TEST(from_decimal<mpfr>(to_decimal(third)) == third);
  }
}

// mpfr_to_decimal prints a value of at most 64 bits (an interval<double>'s bound, a 64-bit error
// bound) by exact integer arithmetic of its own, not through mpfr_get_str: the text must be MPFR's,
// character for character, for every digit count 1 .. 17 and every rounding. MPFR's mpfr_get_str
// is reached with the same value at 80 bits (the own path takes at most 64).
BOOST_AUTO_TEST_CASE(doubles_print_as_mpfr_prints_them) {
  std::mt19937_64 rng(20261128);
  std::uniform_int_distribution<int> digits_of(1, 17);
  std::uniform_int_distribution<int> kind_of(0, 4);
  std::uniform_int_distribution<int> exponent_of(-1150, 1150);
  std::uniform_int_distribution<int> small(-40, 40);
  const mpfr_rnd_t modes[] = {MPFR_RNDN, MPFR_RNDD, MPFR_RNDU, MPFR_RNDZ, MPFR_RNDA};
  mpfr_value as_double(53), as_64(64), wide(80);
  long compared = 0, ties = 0, beyond_double = 0;
  for (int i = 0; i < 60000; ++i) {
    double x = 0;
    const int kind = kind_of(rng);
    if (kind == 4) {  // 64 random bits of significand, exponents beyond a double's (and beyond the own path's)
      mpfr_set_uj(wide, rng() | 1, MPFR_RNDN);
      mpfr_mul_2si(wide, wide, exponent_of(rng), MPFR_RNDN);
      if (rng() & 1) mpfr_neg(wide, wide, MPFR_RNDN);
      BOOST_REQUIRE(mpfr_set(as_64, wide, MPFR_RNDN) == 0);
      if (std::abs(mpfr_get_exp(wide)) > 1022) ++beyond_double;
      const int digits = digits_of(rng);
      for (const mpfr_rnd_t rnd : modes) {
        BOOST_REQUIRE_MESSAGE(mpfr_to_decimal(as_64, digits, rnd) == mpfr_to_decimal(wide, digits, rnd),
                              "64-bit value " << mpfr_to_decimal(wide, 30, MPFR_RNDN) << ", " << digits << " digits, rounding "
                                              << mpfr_print_rnd_mode(rnd) << ": " << mpfr_to_decimal(as_64, digits, rnd)
                                              << " against MPFR's " << mpfr_to_decimal(wide, digits, rnd));
        ++compared;
      }
      continue;
    }
    switch (kind) {
      case 0: {  // any finite double: every exponent, subnormals included
        std::uint64_t bits = rng();
        std::memcpy(&x, &bits, sizeof x);
        if (!std::isfinite(x)) continue;
        break;
      }
      case 1:  // a short dyadic number: exact decimal expansions, ties at small digit counts
        x = std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng() % 2000001) - 1000000), small(rng));
        break;
      case 2: {  // near a power of ten (the decade of the digits changes there)
        x = std::pow(10.0, small(rng) * 7);
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        bits += static_cast<std::uint64_t>(static_cast<std::int64_t>(rng() % 7) - 3);
        std::memcpy(&x, &bits, sizeof x);
        if (rng() & 1) x = -x;
        break;
      }
      default: {  // a 17-digit decimal rounded to a double (what engines print)
        const double mantissa = 1.0 + static_cast<double>(rng() % 9000000000000000ULL) / 1e15;
        x = mantissa * std::pow(10.0, small(rng));
        if (rng() & 1) x = -x;
      }
    }
    if (x == 0) continue;
    mpfr_set_d(as_double, x, MPFR_RNDN);
    mpfr_set_d(as_64, x, MPFR_RNDN);
    mpfr_set_d(wide, x, MPFR_RNDN);
    const int digits = digits_of(rng);
    for (const mpfr_rnd_t rnd : modes) {
      const std::string mpfrs = mpfr_to_decimal(wide, digits, rnd);
      BOOST_REQUIRE_MESSAGE(mpfr_to_decimal(as_double, digits, rnd) == mpfrs,
                            "x = " << to_decimal(x) << ", " << digits << " digits, rounding " << mpfr_print_rnd_mode(rnd)
                                   << ": " << mpfr_to_decimal(as_double, digits, rnd) << " against MPFR's " << mpfrs);
      BOOST_REQUIRE(mpfr_to_decimal(as_64, digits, rnd) == mpfrs);
      ++compared;
    }
    // the text of the nearest rounding decides the ties: count them, so that the test shows it met some
    // a tie: the exact expansion (at most 767 digits) has digits + 1 significant digits, the last a 5
    if (std::string exact = mpfr_to_decimal(wide, 800, MPFR_RNDN); [&] {
          std::string significant;
          for (const char c : exact.substr(0, exact.find('e')))
            if (c >= '0' && c <= '9' && !(significant.empty() && c == '0')) significant += c;
          while (!significant.empty() && significant.back() == '0') significant.pop_back();
          return static_cast<int>(significant.size()) == digits + 1 && significant.back() == '5';
        }())
      ++ties;
  }
  BOOST_TEST_MESSAGE("texts compared: " << compared << ", ties to even among them: " << ties
                                        << ", 64-bit values beyond a double's exponents: " << beyond_double);
  BOOST_TEST(beyond_double > 1000);
  BOOST_TEST(compared > 200000);
  BOOST_TEST(ties > 100);
}

namespace {
/// f() inside an upward_rounding scope (an interval evaluation's: the processor rounds upward
/// there) when `upward`, else outside any.
template <class F>
double in_rounding_scope(bool upward, F f) {
  if (upward) {
    const upward_rounding scope;
    return f();
  }
  return f();
}
}  // namespace

// A decimal literal becomes a double (each bound of an interval, every point double) by an exact
// path of appell's own (from_chars, then the exact comparison of the decimal with that double):
// the doubles must be MPFR's (mpfr_strtofr in binary64's range, the path produce_double takes for
// any other producer), in every rounding, on random literals of every shape: signs, leading and
// trailing zeros, points at either end, exponents, exact values, midpoints between two doubles,
// subnormals, near the largest double, and more than 40 digits (MPFR's path on both sides).
BOOST_AUTO_TEST_CASE(decimals_become_the_doubles_mpfr_gives) {
  std::mt19937_64 rng(11282026);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); };
  const mpfr_rnd_t modes[] = {MPFR_RNDN, MPFR_RNDD, MPFR_RNDU, MPFR_RNDZ};
  long compared = 0, exact = 0, midpoints = 0;
  for (int i = 0; i < 40000; ++i) {
    std::string text;
    const int kind = pick(5);
    if (kind == 0) {  // random digits, a point somewhere, an exponent
      if (pick(3) == 0) text += pick(2) ? "-" : "+";
      const int n = 1 + pick(45);
      const int point = pick(n + 2) - 1;  // -1: none
      for (int d = 0; d < n; ++d) {
        if (d == point) text += '.';
        text += static_cast<char>('0' + (d < 2 && pick(4) == 0 ? 0 : pick(10)));
      }
      if (point == n) text += '.';
      if (pick(2)) text += (pick(2) ? "e" : "E") + std::to_string(pick(640) - 320);
    } else if (kind == 1) {  // an exact dyadic value: short decimal expansions
      const double x = std::ldexp(static_cast<double>(pick(1 << 20)) - (1 << 19), pick(60) - 30);
      mpfr_value v(60);
      mpfr_set_d(v, x, MPFR_RNDN);
      text = mpfr_to_decimal(v, 40, MPFR_RNDN);
    } else if (kind == 2) {  // the midpoint of two doubles in [2^53, 2^63): an integer
      const int shift = pick(10);
      const std::uint64_t x = ((std::uint64_t(1) << 52) | (rng() >> 12)) << shift;  // a double's value
      const std::uint64_t mid = x + (shift ? std::uint64_t(1) << (shift - 1) : 0);
      text = std::to_string(shift ? mid : x);
      if (shift) ++midpoints;
    } else if (kind == 3) {  // near the ends of the range: subnormals and the largest doubles
      text = std::to_string(1 + pick(9)) + "." + std::to_string(rng() % 1000000) + "e" +
             std::to_string(pick(2) ? 300 + pick(9) : -300 - pick(30));
    } else {  // what an engine prints: 17 significant digits
      char buffer[64];
      const double x = std::ldexp(static_cast<double>(rng() >> 11), pick(200) - 150);
      std::snprintf(buffer, sizeof buffer, "%.17g", pick(2) ? -x : x);
      text = buffer;
    }
    if (!is_decimal_literal(text)) continue;
    const mpfr_producer own = decimal_producer(text);
    const mpfr_producer by_mpfr = [text](mpfr_ptr out, mpfr_rnd_t rnd) {
      return mpfr_strtofr(out, text.c_str(), nullptr, 10, rnd);
    };
    const double down = produce_double(by_mpfr, MPFR_RNDD), up = produce_double(by_mpfr, MPFR_RNDU);
    if (down == up) ++exact;
    for (const mpfr_rnd_t rnd : modes) {
      const double a = in_rounding_scope(i % 2, [&] { return produce_double(own, rnd); });
      const double b = produce_double(by_mpfr, rnd);
      BOOST_REQUIRE_MESSAGE(a == b && std::signbit(a) == std::signbit(b),
                            "'" << text << "' rounded " << mpfr_print_rnd_mode(rnd) << ": " << to_decimal(a)
                                << " against MPFR's " << to_decimal(b));
      ++compared;
    }
  }
  BOOST_TEST_MESSAGE("doubles compared: " << compared << ", exact decimals: " << exact << ", midpoints: " << midpoints);
  BOOST_TEST(compared > 100000);
  BOOST_TEST(exact > 1000);
  BOOST_TEST(midpoints > 1000);
}

// p/q becomes a double (rational<double>, rational<interval>: the models' constants such as 2/5) by
// an exact path of its own (the quotient, then its remainder by one fma): the doubles must be MPFR's
// (mpfr_set_q), in every rounding, inside and outside an upward-rounding scope, for small and
// large numerators and denominators of both signs, exact quotients included.
BOOST_AUTO_TEST_CASE(rationals_become_the_doubles_mpfr_gives) {
  std::mt19937_64 rng(20261129);
  const mpfr_rnd_t modes[] = {MPFR_RNDN, MPFR_RNDD, MPFR_RNDU, MPFR_RNDZ};
  long compared = 0, exact = 0;
  for (int i = 0; i < 40000; ++i) {
    const int bits_p = 1 + static_cast<int>(rng() % 56), bits_q = 1 + static_cast<int>(rng() % 56);
    long p = static_cast<long>(rng() >> (64 - bits_p)), q = static_cast<long>(rng() >> (64 - bits_q));
    if (i % 5 == 0) p = q * static_cast<long>(rng() % 64);  // exact quotients
    if (q == 0) q = 1;
    if (rng() & 1) p = -p;
    if (rng() & 1) q = -q;
    const mpfr_producer own = rational_producer(p, q);
    const mpfr_producer by_mpfr = [p, q](mpfr_ptr out, mpfr_rnd_t rnd) {
      mpq_t r;
      mpq_init(r);
      mpq_set_si(r, p, static_cast<unsigned long>(q < 0 ? -q : q));
      mpq_canonicalize(r);
      if (q < 0) mpq_neg(r, r);
      const int t = mpfr_set_q(out, r, rnd);
      mpq_clear(r);
      return t;
    };
    if (produce_double(by_mpfr, MPFR_RNDD) == produce_double(by_mpfr, MPFR_RNDU)) ++exact;
    for (const mpfr_rnd_t rnd : modes) {
      const double a = in_rounding_scope(i % 2, [&] { return produce_double(own, rnd); });
      const double b = produce_double(by_mpfr, rnd);
      BOOST_REQUIRE_MESSAGE(a == b && std::signbit(a) == std::signbit(b),
                            p << "/" << q << " rounded " << mpfr_print_rnd_mode(rnd) << ": " << to_decimal(a)
                              << " against MPFR's " << to_decimal(b));
      ++compared;
    }
  }
  BOOST_TEST_MESSAGE("doubles compared: " << compared << ", exact quotients: " << exact);
  BOOST_TEST(compared == 160000);
  BOOST_TEST(exact > 5000);
}

// The 64-bit error bounds of `appell reference` in interval (x87_bounds.hpp), bit for bit against
// MPFR at 64 bits rounding upward: random enclosures [lo, hi] of doubles of every exponent
// (subnormals, both signs, straddling 0, a few ulps wide or spanning binades), d one of the
// doubles in it, w any double >= 0. A bound rounded to nearest instead would differ from MPFR's
// on a good part of them: the test counts those and requires many.
BOOST_AUTO_TEST_CASE(x87_error_bounds_are_mpfrs_upward_64_bit_bounds) {
  if (!appell::x87_bounds_available()) {  // no x87 unit: reference.cpp uses MPFR itself
    BOOST_TEST_MESSAGE("no x87 unit with a 64-bit long double: nothing to compare");
    return;
  }
  std::mt19937_64 rng(20261130);
  auto any_double = [&] {
    for (;;) {
      const std::uint64_t bits = rng();
      double x;
      std::memcpy(&x, &bits, sizeof x);
      if (std::isfinite(x)) return x;
    }
  };
  auto ulps_above = [](double x, std::uint64_t k) {
    for (std::uint64_t i = 0; i < k; ++i) x = std::nextafter(x, HUGE_VAL);
    return x;
  };
  mpfr_value lo64(64), hi64(64), d64(64), e1(64), e2(64), e(64), rel(64), tol(64), near(64), got(64);
  long compared = 0, relative = 0, nearest_differs = 0;
  for (int i = 0; i < 200000; ++i) {
    double lo = any_double(), hi = 0;
    switch (i % 4) {
      case 0: hi = ulps_above(lo, rng() % 8); break;                 // a few ulps wide
      case 1: hi = any_double(); break;                              // any two doubles
      case 2: hi = std::ldexp(lo, static_cast<int>(rng() % 60)); break;  // binades apart (either sign)
      default: hi = std::abs(any_double()); lo = -std::abs(lo); break;   // straddling 0
    }
    if (!std::isfinite(hi)) continue;
    if (hi < lo) std::swap(lo, hi);
    const double d = rng() % 3 == 0 ? lo : rng() % 2 ? hi : (lo == hi ? lo : ulps_above(lo, 1 + rng() % 3));
    if (d > hi) continue;
    const double w = std::abs(any_double());
    const appell::error_bounds_64 b = appell::x87_error_bounds(d, lo, hi, w);
    mpfr_set_d(lo64, lo, MPFR_RNDN);
    mpfr_set_d(hi64, hi, MPFR_RNDN);
    mpfr_set_d(d64, d, MPFR_RNDN);
    mpfr_sub(e1, d64, lo64, MPFR_RNDU);
    mpfr_sub(e2, hi64, d64, MPFR_RNDU);
    mpfr_max(e, e1, e2, MPFR_RNDU);
    mpfr_set_ld(got, b.absolute, MPFR_RNDN);
    BOOST_REQUIRE_MESSAGE(mpfr_equal_p(got, e), "absolute bound of " << d << " in [" << lo << ", " << hi << "]");
    BOOST_REQUIRE(b.has_relative == (lo > 0 || hi < 0));
    if (b.has_relative) {
      ++relative;
      mpfr_set_d(rel, lo > 0 ? lo : -hi, MPFR_RNDN);
      mpfr_div(near, e, rel, MPFR_RNDN);
      mpfr_div(rel, e, rel, MPFR_RNDU);
      mpfr_set_ld(got, b.relative, MPFR_RNDN);
      BOOST_REQUIRE_MESSAGE(mpfr_equal_p(got, rel), "relative bound of " << d << " in [" << lo << ", " << hi << "]");
      if (!mpfr_equal_p(near, rel)) ++nearest_differs;
    }
    mpfr_set_d(tol, w, MPFR_RNDU);
    mpfr_mul_ui(tol, tol, 16, MPFR_RNDU);
    mpfr_set_ld(got, b.tolerance, MPFR_RNDN);
    BOOST_REQUIRE_MESSAGE(mpfr_equal_p(got, tol), "tolerance of " << w);
    ++compared;
  }
  BOOST_TEST_MESSAGE("enclosures compared: " << compared << ", with a relative bound: " << relative
                                             << ", where rounding to nearest would differ: " << nearest_differs);
  BOOST_TEST(compared > 150000);
  BOOST_TEST(relative > 50000);
  BOOST_TEST(nearest_differs > 10000);
  // The x87 unit is back in the caller's mode (round to nearest, 64 bits): 1 + 2^-70 rounds to 1
  // (upward it would be the next long double, at 53 bits 1 + 2^-60 would be 1 too).
  volatile long double one = 1, tiny = 0x1p-70L, small = 0x1p-60L;
  BOOST_TEST((one + tiny == one));
  BOOST_TEST((one + small != one));
}
