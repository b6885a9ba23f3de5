// appell/scalar/functions.hpp -- the few functions whose best form depends on the scalar.
//
// Elementary functions are called unqualified with `using std::sin;` in
// scope, so that argument-dependent lookup finds each scalar's own:
// appell::sin for interval (rigorous, src/scalar/interval_functions.cpp),
// MPFI's for mpfi, Arb's for arb, MPFR's for mpfr, QD's for dd, libquadmath's for float128.
// Integer powers and squares are not left to x*x*...: on intervals that
// overestimates around 0 ([-1,2]*[-1,2] = [-2,4], but [-1,2]^2 = [0,4]).
#pragma once

#include <cmath>

#include "appell/scalar/traits.hpp"

namespace appell {

/// x^n for mpfi, tight: each bound from mpfr_pow_si with directed rounding.
mpfi pown_mpfi(const mpfi& x, int n);

/// sin and cos of an mpfi together (src/scalar/mpfi_functions.cpp): for a narrow
/// argument, one mpfr_sin_cos at its midpoint plus a Taylor bound; otherwise MPFI's.
void sin_cos_mpfi(const mpfi& x, mpfi& s, mpfi& c);
void sin_cos_mpfi(const mp::mpfi_backend& x, mp::mpfi_backend& s, mp::mpfi_backend& c);

/// x^n for arb (src/scalar/arb_backend.cpp): Arb's powering; an even power of a ball that
/// holds 0 from 0 to the power of its largest magnitude.
arb pown_arb(const arb& x, int n);
/// sin and cos of an arb together (Arb's arb_sin_cos).
void sin_cos_arb(const arb& x, arb& s, arb& c);

/// s = sin x, c = cos x: one MPFR call for mpfr and mpfi (a dual number needs both).
template <class T>
void sin_cos(const T& x, T& s, T& c) {
  if constexpr (std::is_same_v<T, mpfr>) {
    mpfr_sin_cos(s.backend().data(), c.backend().data(), x.backend().data(), MPFR_RNDN);  // each correctly rounded
  } else if constexpr (std::is_same_v<T, mpfi>) {
    sin_cos_mpfi(x, s, c);
  } else if constexpr (std::is_same_v<T, arb>) {
    sin_cos_arb(x, s, c);
  } else {
    using std::sin, std::cos;
    s = sin(x);
    c = cos(x);
  }
}

/// x^n for an integer n.
template <Scalar T>
T pown(const T& x, int n) {
  if (n == 0) return T(1);  // x^0 = 1, 0^0 included (QD's npwr refuses 0^0: a dual's x^1 asks for it)
  if constexpr (std::is_same_v<T, interval>) return appell::pown(x, n);
  else if constexpr (std::is_same_v<T, mpfi>) return pown_mpfi(x, n);
  else if constexpr (std::is_same_v<T, arb>) return pown_arb(x, n);
  else if constexpr (std::is_same_v<T, dd>) return ::npwr(x, n);
  else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, long double>) return std::pow(x, n);
  else {
    using boost::multiprecision::pow;
    return pow(x, T(n));
  }
}

/// x^2, tight on intervals.
template <Scalar T>
T sqr(const T& x) {
  if constexpr (scalar_traits<T>::is_interval) return pown(x, 2);
  else return x * x;
}

}  // namespace appell
