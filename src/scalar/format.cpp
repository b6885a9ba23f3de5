// Printing: round-trip digits for point types, outward rounding for bounds.
#define MPFR_WANT_FLOAT128 1
#include <mpfr.h>

#include "appell/scalar/format.hpp"

#include <charconv>
#include <cmath>
#include <memory>

namespace appell {

int roundtrip_digits(unsigned bits) {
  // 1 + ceil(bits * log10 2) digits make any bits-bit number round-trip.
  return 1 + static_cast<int>(std::ceil(bits * 0.30102999566398120));
}

std::string mpfr_to_decimal(mpfr_srcptr v, int digits, mpfr_rnd_t rnd) {
  if (mpfr_nan_p(v)) return "nan";
  if (mpfr_inf_p(v)) return mpfr_sgn(v) > 0 ? "inf" : "-inf";
  if (mpfr_zero_p(v)) return mpfr_signbit(v) ? "-0" : "0";
  mpfr_exp_t exp10 = 0;
  std::unique_ptr<char, void (*)(char*)> text(
      mpfr_get_str(nullptr, &exp10, 10, static_cast<std::size_t>(digits), v, rnd), mpfr_free_str);
  std::string s(text.get());
  bool negative = s[0] == '-';
  if (negative) s.erase(0, 1);
  while (s.size() > 1 && s.back() == '0') s.pop_back();  // trailing zeros carry nothing
  // value = 0.s * 10^exp10 = s[0].s[1..] * 10^(exp10-1)
  long e = static_cast<long>(exp10) - 1;
  std::string out = negative ? "-" : "";
  if (e >= -5 && e < 21) {
    if (e >= 0) {
      if (static_cast<long>(s.size()) <= e + 1) {
        out += s + std::string(static_cast<std::size_t>(e + 1) - s.size(), '0');
      } else {
        out += s.substr(0, static_cast<std::size_t>(e + 1)) + "." + s.substr(static_cast<std::size_t>(e + 1));
      }
    } else {
      out += "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + s;
    }
  } else {
    out += s.substr(0, 1);
    if (s.size() > 1) out += "." + s.substr(1);
    out += "e" + std::to_string(e);
  }
  return out;
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
