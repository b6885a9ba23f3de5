// appell/scalar/format.hpp -- printing that never claims more than it knows.
//
// Point types print enough significant digits to round-trip (shortest for
// double and long double).  Interval types print each bound rounded outward
// (lower bound down, upper bound up), with enough digits to round-trip the
// bound, so the printed interval still encloses the computed one.
#pragma once

#include <algorithm>
#include <string>

#include "appell/scalar/traits.hpp"

namespace appell {

/// Decimal text of an MPFR number with `digits` significant digits, rounded rnd.
std::string mpfr_to_decimal(mpfr_srcptr v, int digits, mpfr_rnd_t rnd);
/// Significant decimal digits that make a `bits`-bit binary number round-trip.
int roundtrip_digits(unsigned bits);

std::string to_decimal(double x);
std::string to_decimal(long double x);
std::string to_decimal(const dd& x);
std::string to_decimal(const float128& x);
std::string to_decimal(const mpfr& x);

/// Point types: the value; interval types: "[lo, hi]" rounded outward.
template <Scalar T>
std::string to_string(const T& x);

namespace detail {
/// The bits whose round-trip digits print a bound of x: the bound's own, but for an arb ball,
/// whose exact ends may need more bits than its midpoint has, the midpoint's (the text is rounded
/// outward either way).
template <Scalar T>
unsigned printed_bits(const T& x, mpfr_srcptr bound) {
  const auto own = static_cast<unsigned>(mpfr_get_prec(bound));
  if constexpr (std::is_same_v<T, arb>) return std::min(own, static_cast<unsigned>(x.backend().prec()));
  else return own;
}
}  // namespace detail

/// The lower and upper bound of x as outward-rounded decimal text.
template <Scalar T>
std::string lower_string(const T& x) {
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(x, lo, hi);
  return mpfr_to_decimal(lo, roundtrip_digits(detail::printed_bits(x, lo)), MPFR_RNDD);
}
template <Scalar T>
std::string upper_string(const T& x) {
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(x, lo, hi);
  return mpfr_to_decimal(hi, roundtrip_digits(detail::printed_bits(x, hi)), MPFR_RNDU);
}

template <Scalar T>
std::string to_string(const T& x) {
  if constexpr (scalar_traits<T>::is_interval)
    return "[" + lower_string(x) + ", " + upper_string(x) + "]";
  else
    return to_decimal(x);
}

}  // namespace appell
