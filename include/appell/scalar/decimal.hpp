// appell/scalar/decimal.hpp -- numbers into a scalar, never through a double.
//
// from_decimal<T>("0.1"):   point types: the value of T nearest to the exact
//                           decimal 1/10 (one correct rounding, IEEE subnormals
//                           honoured); interval types: the tightest enclosure of
//                           the exact decimal (lower bound rounded down, upper up).
// constant_pi<T>(), rational<T>(p, q): the same rule for pi and for p/q.
// Everything goes through MPFR's correctly rounded conversions
// (mpfr_strtofr, mpfr_const_pi, mpfr_set_q) in the target's own format.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "appell/errors.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

/// Strict decimal syntax: [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?
bool is_decimal_literal(std::string_view s);

/// A real number given by a correctly rounding MPFR routine: f(out, rnd) sets
/// `out` (at its own precision) to the number rounded in direction rnd.
using mpfr_producer = std::function<int(mpfr_ptr, mpfr_rnd_t)>;  // returns the ternary value

// One correct rounding of the producer's number into each format.
double produce_double(const mpfr_producer& f, mpfr_rnd_t rnd);
long double produce_long_double(const mpfr_producer& f, mpfr_rnd_t rnd);
dd produce_dd(const mpfr_producer& f);
float128 produce_float128(const mpfr_producer& f, mpfr_rnd_t rnd);
mpfr produce_mpfr(const mpfr_producer& f, mpfr_rnd_t rnd);
mpfi produce_mpfi(const mpfr_producer& f);
arb produce_arb(const mpfr_producer& f);

/// The number a producer gives, in T: correctly rounded (point) or enclosed (interval).
template <Scalar T>
T produce(const mpfr_producer& f) {
  if constexpr (std::is_same_v<T, double>) return produce_double(f, MPFR_RNDN);
  else if constexpr (std::is_same_v<T, long double>) return produce_long_double(f, MPFR_RNDN);
  else if constexpr (std::is_same_v<T, dd>) return produce_dd(f);
  else if constexpr (std::is_same_v<T, float128>) return produce_float128(f, MPFR_RNDN);
  else if constexpr (std::is_same_v<T, mpfr>) return produce_mpfr(f, MPFR_RNDN);
  else if constexpr (std::is_same_v<T, interval>)
    return interval(produce_double(f, MPFR_RNDD), produce_double(f, MPFR_RNDU));
  else if constexpr (std::is_same_v<T, mpfi>) return produce_mpfi(f);
  else if constexpr (std::is_same_v<T, arb>) return produce_arb(f);
  else static_assert(sizeof(T) == 0, "no correctly rounded conversion for this scalar");
}

/// The producer of an exact decimal (checks the syntax; throws parse_error).
mpfr_producer decimal_producer(std::string_view s);
/// The producer of the rational p/q (q != 0).
mpfr_producer rational_producer(long p, long q);
/// The producer of pi.
mpfr_producer pi_producer();

/// The decimal `s` in T; throws parse_error for bad syntax or a value out of T's range.
template <Scalar T>
T from_decimal(std::string_view s) {
  T x = produce<T>(decimal_producer(s));
  if (!is_finite(x))
    throw parse_error("'" + std::string(s) + "' is out of the range of " + scalar_traits<T>::name);
  return x;
}

template <Scalar T> T rational(long p, long q) { return produce<T>(rational_producer(p, q)); }
template <Scalar T> T constant_pi() { return produce<T>(pi_producer()); }

/// The exact value of a decimal literal as an MPFR number with `bits` bits,
/// rounded in direction rnd (used by tests and by exact input validation).
void decimal_to_mpfr(std::string_view s, mpfr_value& out, mpfr_rnd_t rnd);

/// The sign (-1, 0, 1) of an exact sum of terms coefficient * d1 * d2 * ...
/// of decimal literals, computed over the rationals: inputs are validated on
/// their exact values, never after rounding.
struct decimal_term {
  long coefficient;
  std::vector<std::string> factors;
};
int decimal_sign_of_polynomial(const std::vector<decimal_term>& terms);
/// Shorthand for sums of single decimals: sign of c1 d1 + c2 d2 + ...
int decimal_sign_of_sum(std::initializer_list<std::pair<int, std::string_view>> terms);

}  // namespace appell
