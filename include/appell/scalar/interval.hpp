// appell/scalar/interval.hpp -- the rigorous `interval<double>` of appell.
//
// Rigour contract (in the spirit of CAPD): every operation returns a box that
// contains the exact real result for every point of its arguments.  We do not
// assume that libm rounds correctly, nor that it honours the rounding mode.
//  * + - * /: IEEE 754 operations under directed rounding (upward mode; lower
//    bounds as -((-x) op y)), each operand made opaque to the optimiser.  This
//    also needs -frounding-math -ffp-contract=off and no -ffast-math, which the
//    appell::appell target carries (DESIGN.md sec. 3).
//  * sqrt sin cos tan atan exp log pown: each bound is MPFR's correctly rounded value
//    at 53 bits with MPFR_RNDD / MPFR_RNDU, converted to double with the same
//    direction.  Extrema inside wide arguments are located by a certified
//    range reduction (src/scalar/interval_functions.cpp).
// Empty sets are allowed in arithmetic (for IEEE 1788 test vectors) but a
// function whose result would be empty throws `appell::domain_error`.
#pragma once

#include <boost/numeric/interval/interval.hpp>
#include <boost/numeric/interval/policies.hpp>
#include <boost/numeric/interval/hw_rounding.hpp>
#include <boost/numeric/interval/rounded_arith.hpp>
#include <boost/numeric/interval/checking.hpp>
#include <boost/numeric/interval/compare.hpp>
#include <boost/numeric/interval/utility.hpp>
#include <boost/numeric/interval/arith.hpp>
#include <boost/numeric/interval/arith2.hpp>

#include <stdexcept>
#include <string>

namespace appell {

/// Thrown when a function is applied wholly outside its domain (log of [-2,-1]).
struct domain_error : std::domain_error {
  using std::domain_error::domain_error;
};

// Rounding for interval<double>.  The FPU is put in upward mode by each
// operation and restored after it (Boost's save_state); lower bounds are
// computed by negation, -((-x) - y), so only one mode is ever needed.
// Every operand and result passes through an empty `asm volatile`: without
// it GCC, even with -frounding-math, folds or reuses a result computed in
// another rounding mode (measured here: the upper bound of [1]/[3], computed
// upward, was reused for a later round-to-nearest 1.0/3.0, GCC bug 34678).
// Declared in namespace appell itself (not a nested one) so that
// argument-dependent lookup on an interval finds appell::sin and friends.
struct interval_arith : boost::numeric::interval_lib::rounded_arith_opp<double> {
  static double opaque(double x) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    asm volatile("" : "+x"(x));
    return x;
#else
    volatile double v = x;
    return v;
#endif
  }
  template <class U>
  double conv_down(const U& v) { return -opaque(-static_cast<double>(opaque(v))); }
  template <class U>
  double conv_up(const U& v) { return opaque(static_cast<double>(opaque(v))); }
  double add_down(double x, double y) { return -opaque(opaque(-x) - opaque(y)); }
  double sub_down(double x, double y) { return -opaque(opaque(y) - opaque(x)); }
  double mul_down(double x, double y) { return -opaque(opaque(x) * opaque(-y)); }
  double div_down(double x, double y) { return -opaque(opaque(x) / opaque(-y)); }
  double add_up(double x, double y) { return opaque(opaque(x) + opaque(y)); }
  double sub_up(double x, double y) { return opaque(opaque(x) - opaque(y)); }
  double mul_up(double x, double y) { return opaque(opaque(x) * opaque(y)); }
  double div_up(double x, double y) { return opaque(opaque(x) / opaque(y)); }
};
struct interval_rounding : boost::numeric::interval_lib::save_state<interval_arith> {};
struct interval_checking : boost::numeric::interval_lib::checking_base<double> {};

using interval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<interval_rounding, interval_checking>>;

// Rigorous elementary functions (definitions in src/scalar/interval_functions.cpp).
interval sqrt(const interval& x);
interval sin(const interval& x);
interval cos(const interval& x);
interval tan(const interval& x);
interval atan(const interval& x);
interval exp(const interval& x);
interval log(const interval& x);
interval pown(const interval& x, int n);  ///< x^n for integer n, tight at 0
interval sqr(const interval& x);          ///< x^2, tight at 0 (not x*x)
interval abs(const interval& x);

/// The tightest enclosure of pi.
interval interval_pi();

}  // namespace appell
