// appell/scalar/rational.hpp -- exact rationals (GMP), an eighth scalar for proofs.
//
// Not one of the seven evaluation scalars: no sin or cos, no sqrt.  Systems
// whose kinematics are rational (Euler's body, the free body on moving axes
// with a rational rotation) run through the generic Gibbs-Appell path in it,
// so identities such as Cotton's eq. (6) and the invariance of eq. (4) can be
// checked with no rounding at all (proofs/).
#pragma once

#include <boost/multiprecision/gmp.hpp>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/eigen.hpp"

namespace appell {

using rational_q = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;

template <>
struct scalar_traits<rational_q> {
  static constexpr const char* name = "rational";
  static constexpr bool is_interval = false;
  static constexpr bool is_rigorous = true;  // exact
  static constexpr bool is_exact = true;     // no sqrt: solves use LU
  using bound_type = rational_q;
  static unsigned precision_bits() { return 0; }  // unbounded
  static rational_q lower(const rational_q& x) { return x; }
  static rational_q upper(const rational_q& x) { return x; }
  static rational_q mid(const rational_q& x) { return x; }
  static rational_q width(const rational_q&) { return rational_q(0); }
};

/// The exact value of a decimal literal.
rational_q rational_from_decimal(const std::string& s);

/// A rational in scalar T: correctly rounded (point types) or enclosed (interval types).
template <Scalar T>
T from_rational(const rational_q& r) {
  if constexpr (requires { scalar_traits<T>::is_exact; }) {
    return r;
  } else {
    mpq_srcptr q = r.backend().data();
    return produce<T>([q](mpfr_ptr out, mpfr_rnd_t rnd) { return mpfr_set_q(out, q, rnd); });
  }
}

}  // namespace appell

namespace boost::multiprecision {
/// The exact square root of a rational that is a perfect square (numerator and
/// denominator); throws std::domain_error otherwise.  Found by argument-
/// dependent lookup from generic code (`using std::sqrt; sqrt(x)`).
appell::rational_q sqrt(const appell::rational_q& x);
}  // namespace boost::multiprecision

namespace Eigen {
template <>
struct NumTraits<appell::rational_q> : appell::detail::numtraits_common<appell::rational_q> {
  static int digits() { return 0; }
  static int digits10() { return 0; }
  static appell::rational_q epsilon() { return 0; }
  static appell::rational_q dummy_precision() { return 0; }
  static appell::rational_q highest() { return appell::rational_q(std::numeric_limits<double>::max()); }
  static appell::rational_q lowest() { return -highest(); }
};
}  // namespace Eigen
