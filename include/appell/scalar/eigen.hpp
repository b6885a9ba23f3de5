// appell/scalar/eigen.hpp -- Eigen::NumTraits for the eight scalars, in one place.
//
// Boost 1.74's boost/multiprecision/eigen.hpp lacks infinity(), quiet_NaN() and
// digits() and has a wrong lowest(), so it is NOT included; these traits
// replace it.  Eigen must never pivot on interval values (comparisons are
// undecided); appell/linalg/solve.hpp routes interval systems to a verified solver.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <type_traits>

#include "appell/scalar/traits.hpp"

namespace appell::detail {
template <class T>
struct numtraits_common {
  using Real = T;
  using NonInteger = T;
  using Nested = T;
  using Literal = T;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 4,
    MulCost = 4
  };
};
}  // namespace appell::detail

namespace Eigen {

template <>
struct NumTraits<appell::dd> : appell::detail::numtraits_common<appell::dd> {
  static int digits() { return 106; }
  static int digits10() { return 31; }
  static appell::dd epsilon() { return appell::dd(dd_real::_eps); }
  static appell::dd dummy_precision() { return appell::dd(1e-28); }
  static appell::dd highest() { return dd_real::_max; }
  static appell::dd lowest() { return -dd_real::_max; }
  static appell::dd infinity() { return dd_real::_inf; }
  static appell::dd quiet_NaN() { return dd_real::_nan; }
};

template <>
struct NumTraits<appell::float128> : appell::detail::numtraits_common<appell::float128> {
  using L = std::numeric_limits<appell::float128>;
  static int digits() { return 113; }
  static int digits10() { return 33; }
  static appell::float128 epsilon() { return L::epsilon(); }
  static appell::float128 dummy_precision() { return appell::float128(1e-30); }
  static appell::float128 highest() { return (L::max)(); }
  static appell::float128 lowest() { return -(L::max)(); }
  static appell::float128 infinity() { return L::infinity(); }
  static appell::float128 quiet_NaN() { return L::quiet_NaN(); }
};

template <>
struct NumTraits<appell::mpfr> : appell::detail::numtraits_common<appell::mpfr> {
  static int digits() { return static_cast<int>(appell::mpfr_precision_bits()); }
  static int digits10() { return static_cast<int>(appell::mpfr_precision_bits() * 0.30103); }
  static appell::mpfr epsilon() {
    appell::mpfr e(1);
    mpfr_mul_2si(e.backend().data(), e.backend().data(), 1 - digits(), MPFR_RNDN);
    return e;
  }
  static appell::mpfr dummy_precision() {
    appell::mpfr e = epsilon();
    return e * 1024;
  }
  static appell::mpfr highest() { return std::numeric_limits<appell::mpfr>::max(); }
  static appell::mpfr lowest() { return -std::numeric_limits<appell::mpfr>::max(); }
  static appell::mpfr infinity() { return std::numeric_limits<appell::mpfr>::infinity(); }
  static appell::mpfr quiet_NaN() { return std::numeric_limits<appell::mpfr>::quiet_NaN(); }
};

template <>
struct NumTraits<appell::interval> : appell::detail::numtraits_common<appell::interval> {
  using I = appell::interval;
  static constexpr double inf = std::numeric_limits<double>::infinity();
  static int digits() { return 53; }
  static int digits10() { return 15; }
  static I epsilon() { return I(std::numeric_limits<double>::epsilon()); }
  static I dummy_precision() { return I(1e-12); }
  static I highest() { return I(std::numeric_limits<double>::max()); }
  static I lowest() { return I(-std::numeric_limits<double>::max()); }
  static I infinity() { return I(inf); }
  static I quiet_NaN() { return I(-inf, inf); }  // "anything": the honest interval NaN
};

template <>
struct NumTraits<appell::mpfi> : appell::detail::numtraits_common<appell::mpfi> {
  using I = appell::mpfi;
  static int digits() { return static_cast<int>(appell::mp_precision_bits()); }
  static int digits10() { return static_cast<int>(appell::mp_precision_bits() * 0.30103); }
  static I epsilon() { return I(NumTraits<appell::mpfr>::epsilon()); }
  static I dummy_precision() { return I(NumTraits<appell::mpfr>::dummy_precision()); }
  static I highest() { return I(NumTraits<appell::mpfr>::highest()); }
  static I lowest() { return I(NumTraits<appell::mpfr>::lowest()); }
  static I infinity() { return I(NumTraits<appell::mpfr>::infinity()); }
  static I quiet_NaN() { return appell::mpfi_from_bounds(-NumTraits<appell::mpfr>::infinity(), NumTraits<appell::mpfr>::infinity()); }
};

template <>
struct NumTraits<appell::arb> : appell::detail::numtraits_common<appell::arb> {
  using I = appell::arb;
  static int digits() { return static_cast<int>(appell::mp_precision_bits()); }
  static int digits10() { return static_cast<int>(appell::mp_precision_bits() * 0.30103); }
  static I epsilon() { return std::numeric_limits<I>::epsilon(); }
  static I dummy_precision() { return epsilon() * 1024; }
  static I highest() { return (std::numeric_limits<I>::max)(); }
  static I lowest() { return std::numeric_limits<I>::lowest(); }
  static I infinity() { return std::numeric_limits<I>::infinity(); }
  static I quiet_NaN() { return std::numeric_limits<I>::quiet_NaN(); }  // the whole line
};

namespace internal {
// boost::numeric::interval converts implicitly from anything, Eigen matrices
// included, which makes Matrix<I> * Matrix<I> ambiguous with "matrix times
// scalar".  An Eigen expression is never a scalar: say so.
template <typename T>
  requires std::is_base_of_v<Eigen::EigenBase<T>, T>
struct promote_scalar_arg_unsupported<appell::interval, T, appell::interval, true, true> {};
}  // namespace internal

}  // namespace Eigen

namespace appell {
template <class T>
using vector_t = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template <class T>
using matrix_t = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <class T>
using vec3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using mat3 = Eigen::Matrix<T, 3, 3>;
}  // namespace appell
