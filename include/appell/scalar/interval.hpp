// appell/scalar/interval.hpp -- the rigorous `interval<double>` of appell.
//
// Rigour contract (in the spirit of CAPD): every operation returns a box that
// contains the exact real result for every point of its arguments.  We do not
// assume that libm rounds correctly, nor that it honours the rounding mode.
//  * + - * / and sqrt: IEEE 754 operations under directed rounding (Boost.Interval,
//    `rounded_arith_opp`: the FPU is put in upward mode, lower bounds are computed
//    as -((-x) op y)).  This needs -frounding-math -ffp-contract=off and no
//    -ffast-math, which the appell::appell target carries (DESIGN.md sec. 3).
//  * sin cos tan atan exp log pown: each bound is MPFR's correctly rounded value
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

namespace detail {
// Rounding for interval<double>: upward mode set and restored by each operation
// (Boost's save_state).  Declared in namespace appell so that argument-dependent
// lookup finds appell::sin(interval) and friends.
struct interval_rounding
    : boost::numeric::interval_lib::save_state<
          boost::numeric::interval_lib::rounded_arith_opp<double>> {};
struct interval_checking : boost::numeric::interval_lib::checking_base<double> {};
}  // namespace detail

using interval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<detail::interval_rounding,
                                                   detail::interval_checking>>;

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
