// tests/bounds_400.hpp -- 400-bit (120-digit) reference numbers and the exact
// bounds of an enclosure (or of a point value) as such numbers: the common
// ground on which the tests compare results with independent references.
#pragma once

#include <boost/multiprecision/mpfr.hpp>
#include <utility>

#include "appell/scalar/traits.hpp"

namespace appell::testing {

using ref_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<120>, boost::multiprecision::et_off>;

/// The bounds of x as 400-bit numbers, rounded outward (exact for every standard scalar).
template <class T>
std::pair<ref_t, ref_t> bounds_of(const T& x) {
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(x, lo, hi);
  std::pair<ref_t, ref_t> r;
  mpfr_set(r.first.backend().data(), lo, MPFR_RNDD);
  mpfr_set(r.second.backend().data(), hi, MPFR_RNDU);
  return r;
}

}  // namespace appell::testing
