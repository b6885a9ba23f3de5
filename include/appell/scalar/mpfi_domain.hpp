// appell/scalar/mpfi_domain.hpp -- sqrt and log of mpfi on the IEEE 1788 terms; sin, cos.
//
// MPFI returns a NaN bound when the argument reaches outside the domain
// (mpfi_sqrt([-1, 4]) = [NaN, 2]), and a NaN bound contains nothing.  These
// overloads restrict the argument to the domain first (sqrt([-1, 4]) = [0, 2],
// log([-1, 4]) = [-inf, log 4]) and throw appell::domain_error where the
// result would be empty.  They are declared in Boost.Multiprecision's
// namespace so that generic code (`using std::sqrt; sqrt(x)`) finds them by
// argument-dependent lookup; being non-templates they win over Boost's.
#pragma once

#include <boost/multiprecision/mpfi.hpp>

namespace boost::multiprecision {
using appell_mpfi = number<mpfi_float_backend<0>, et_off>;
appell_mpfi sqrt(const appell_mpfi& x);
appell_mpfi log(const appell_mpfi& x);
// sin and cos from one mpfr_sin_cos at the midpoint of a narrow argument
// (appell::sin_cos_mpfi, src/scalar/mpfi_functions.cpp); MPFI's otherwise.
appell_mpfi sin(const appell_mpfi& x);
appell_mpfi cos(const appell_mpfi& x);
}  // namespace boost::multiprecision
