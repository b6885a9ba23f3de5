// Printing: round-trip digits for point types, outward rounding for bounds.
#define MPFR_WANT_FLOAT128 1
#include <mpfr.h>

#include "appell/scalar/format.hpp"
#include "stack_limbs.hpp"

#include <gmp.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string_view>

namespace appell {

int roundtrip_digits(unsigned bits) {
  // 1 + ceil(bits * log10 2) digits make any bits-bit number round-trip.
  return 1 + static_cast<int>(std::ceil(bits * 0.30102999566398120));
}

namespace {

// The text of the number 0.s * 10^exp10 (s: its significant digits, at least one), in the form
// every bound and value is printed in: positional for exponents -5 .. 20, scientific otherwise.
std::string decimal_text(bool negative, std::string_view s, long exp10) {
  while (s.size() > 1 && s.back() == '0') s.remove_suffix(1);  // trailing zeros carry nothing
  // value = 0.s * 10^exp10 = s[0].s[1..] * 10^(exp10-1); the text is sized first and written in
  // place (a text of up to 15 characters makes no heap block: std::string's own storage)
  const long e = exp10 - 1;
  const auto n = static_cast<long>(s.size());
  const bool positional = e >= -5 && e < 21;
  char exponent[24];
  const long exponent_length = positional ? 0 : std::to_chars(exponent, exponent + sizeof exponent, e).ptr - exponent;
  const long length = (negative ? 1 : 0) + (!positional ? n + (n > 1 ? 1 : 0) + 1 + exponent_length
                                            : e < 0          ? 2 + (-e - 1) + n
                                            : n <= e + 1     ? e + 1
                                                             : n + 1);
  std::string out(static_cast<std::size_t>(length), '0');
  char* p = out.data();
  auto put = [&](std::string_view t) { p = std::copy(t.begin(), t.end(), p); };
  if (negative) put("-");
  if (!positional) {
    put(s.substr(0, 1));
    if (n > 1) {
      put(".");
      put(s.substr(1));
    }
    put("e");
    put(std::string_view(exponent, static_cast<std::size_t>(exponent_length)));
  } else if (e < 0) {
    put("0.");
    p += -e - 1;  // zeros (the text's fill)
    put(s);
  } else if (n <= e + 1) {
    put(s);  // then e + 1 - n zeros (the fill)
  } else {
    put(s.substr(0, static_cast<std::size_t>(e + 1)));
    put(".");
    put(s.substr(static_cast<std::size_t>(e + 1)));
  }
  return out;
}

// --- the significant digits of a number of at most 64 bits, exactly, without mpfr_get_str ----------
//
// The digits mpfr_get_str gives for a value of at most 64 bits (an interval<double>'s bound, a
// 64-bit error bound), with at most 17 digits: the same string and exponent (tests/decimal.cpp
// compares them on random values, every digit count and rounding), by exact integer arithmetic on
// limbs on the stack (GMP's mpn layer: no allocation). What `appell reference` prints for every
// bound of an interval<double> (mpfr_get_str took half of a state's time: docs/reference-values.md).

using limbs = detail::stack_limbs;
constexpr mp_size_t max_limbs = limbs::capacity;

// q = floor(m 2^e / 10^k) and how the remainder r compares with half the divisor:
// 0 exact, 1 below half, 2 half, 3 above half.  Returns false if q needs more than 64 bits.
bool scaled_digits(std::uint64_t m, long e, long k, std::uint64_t& q, int& remainder) {
  if (k <= 0 && k >= -19 && e < 0 && e > -128) {  // m 10^-k < 2^128, divided by 2^-e: in 128 bits
    unsigned __int128 n = m;
    for (long i = 0; i < -k; ++i) n *= 10;
    const unsigned shift = static_cast<unsigned>(-e);
    const unsigned __int128 quotient = n >> shift, rest = n & ((static_cast<unsigned __int128>(1) << shift) - 1);
    if (quotient >> 64) return false;
    q = static_cast<std::uint64_t>(quotient);
    const unsigned __int128 half = static_cast<unsigned __int128>(1) << (shift - 1);
    remainder = rest == 0 ? 0 : rest < half ? 1 : rest == half ? 2 : 3;
    return true;
  }
  limbs num, den;
  num.set(m);
  den.set(1);
  if (e >= 0) num.shift_left(e);
  else den.shift_left(-e);
  if (k <= 0) num.mul_pow10(-k);
  else den.mul_pow10(k);
  if (num.n < den.n) {  // q = 0
    q = 0;
    remainder = 1;  // nonzero (m > 0) and below half: only asked when q is out of range anyway
    return true;
  }
  mp_limb_t quotient[max_limbs + 1], rest[max_limbs];  // den.n limbs of rest
  mpn_tdiv_qr(quotient, rest, 0, num.d, num.n, den.d, den.n);
  const mp_size_t qn = num.n - den.n + 1;
  for (mp_size_t i = 1; i < qn; ++i)
    if (quotient[i]) return false;
  q = quotient[0];
  limbs twice;  // 2 r, compared with den
  twice.n = den.n;
  std::copy(rest, rest + den.n, twice.d);
  while (twice.n > 0 && twice.d[twice.n - 1] == 0) --twice.n;
  if (twice.n == 0) {
    remainder = 0;
    return true;
  }
  twice.shift_left(1);
  const int c = twice.compare(den);
  remainder = c < 0 ? 1 : c == 0 ? 2 : 3;
  return true;
}

// The digits and exponent of v (a regular number of at most 64 bits: one limb) as
// mpfr_get_str(.., digits, v, rnd) gives them: value = 0.s * 10^exp10.  False when this path does
// not apply (more than 17 digits, an exponent beyond +-1100, another rounding): the caller asks MPFR.
bool small_binary_digits(mpfr_srcptr v, int digits, mpfr_rnd_t rnd, char (&s)[24], long& exp10) {
  if (digits < 1 || digits > 17 || mpfr_get_prec(v) > 64 || !mpfr_regular_p(v)) return false;
  const mpfr_exp_t binary_exponent = mpfr_custom_get_exp(v);  // |v| = 0.significand 2^binary_exponent
  if (binary_exponent < -1100 || binary_exponent > 1100) return false;
  bool up_when_inexact;  // the magnitude rounded away from 0
  const bool negative = mpfr_signbit(v);
  switch (rnd) {
    case MPFR_RNDD: up_when_inexact = negative; break;
    case MPFR_RNDU: up_when_inexact = !negative; break;
    case MPFR_RNDZ: up_when_inexact = false; break;
    case MPFR_RNDA: up_when_inexact = true; break;
    case MPFR_RNDN: up_when_inexact = false; break;  // decided by the remainder below
    default: return false;
  }
  static_assert(GMP_NUMB_BITS == 64, "one 64-bit limb holds a significand of up to 64 bits");
  const std::uint64_t m = static_cast<const mp_limb_t*>(mpfr_custom_get_significand(v))[0];  // top bit set
  const long e = static_cast<long>(binary_exponent) - 64;  // |v| = m 2^e
  std::uint64_t pow_low = 1;  // 10^(digits - 1)
  for (int i = 1; i < digits; ++i) pow_low *= 10;
  const std::uint64_t pow_high = pow_low * 10;  // 10^digits
  // k: |v| / 10^k has `digits` digits before the point; estimated from log10 |v|, then corrected.
  const double log10_v = (std::log2(static_cast<double>(m)) + static_cast<double>(e)) * 0.30102999566398120;
  long k = static_cast<long>(std::floor(log10_v)) - (digits - 1);
  std::uint64_t q = 0;
  int remainder = 0;
  for (int attempt = 0;; ++attempt) {
    if (attempt > 4 || !scaled_digits(m, e, k, q, remainder)) return false;
    if (q >= pow_high) ++k;
    else if (q < pow_low) --k;
    else break;
  }
  bool up = remainder != 0 && up_when_inexact;
  if (rnd == MPFR_RNDN) up = remainder == 3 || (remainder == 2 && (q & 1) != 0);  // ties to even
  if (up && ++q == pow_high) {
    q = pow_low;
    ++k;
  }
  const auto [end, ec] = std::to_chars(s, s + sizeof s - 1, q);
  if (ec != std::errc() || end - s != digits) return false;
  *end = '\0';
  exp10 = k + digits;
  return true;
}

}  // namespace

std::string mpfr_to_decimal(mpfr_srcptr v, int digits, mpfr_rnd_t rnd) {
  if (mpfr_nan_p(v)) return "nan";
  if (mpfr_inf_p(v)) return mpfr_sgn(v) > 0 ? "inf" : "-inf";
  // A zero's sign is a point value's (to nearest: -0 as the scalar holds it); a bound (directed
  // rounding) is a number, and MPFI keeps an upper bound 0 as -0: it prints "0".
  if (mpfr_zero_p(v)) return mpfr_signbit(v) && rnd == MPFR_RNDN ? "-0" : "0";
  {  // at most 64 bits (a double's bound, a 64-bit bound of an error): exact integer arithmetic
    char s[24];
    long exp10 = 0;
    if (small_binary_digits(v, digits, rnd, s, exp10)) return decimal_text(mpfr_signbit(v), s, exp10);
  }
  mpfr_exp_t exp10 = 0;
  std::unique_ptr<char, void (*)(char*)> text(
      mpfr_get_str(nullptr, &exp10, 10, static_cast<std::size_t>(digits), v, rnd), mpfr_free_str);
  std::string_view s(text.get());
  const bool negative = s[0] == '-';
  if (negative) s.remove_prefix(1);
  return decimal_text(negative, s, static_cast<long>(exp10));
}

namespace {
template <class F>
std::string shortest(F x) {
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end);
}
std::string via_mpfr(mpfr_value& v) {
  return mpfr_to_decimal(v, roundtrip_digits(mpfr_get_prec(v)), MPFR_RNDN);
}
}  // namespace

std::string to_decimal(double x) { return shortest(x); }
std::string to_decimal(long double x) { return shortest(x); }
std::string to_decimal(const dd& x) {
  mpfr_value v;
  to_mpfr_exact(x, v);
  return mpfr_to_decimal(v, roundtrip_digits(106), MPFR_RNDN);
}
std::string to_decimal(const float128& x) {
  mpfr_value v;
  to_mpfr_exact(x, v);
  return via_mpfr(v);
}
std::string to_decimal(const mpfr& x) {
  mpfr_value v;
  to_mpfr_exact(x, v);
  return via_mpfr(v);
}

}  // namespace appell
