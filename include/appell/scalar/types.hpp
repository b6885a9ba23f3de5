// appell/scalar/types.hpp -- the seven standard scalars of appell, by name.
//
//  CLI name     C++ type                  kind
//  double       double                    point, 53 bits
//  long-double  long double               point, 64 bits (x87)
//  dd           dd_real (QD)              point, ~106 bits (double-double)
//  float128     appell::float128          point, 113 bits (libquadmath)
//  mpfr         appell::mpfr              point, bits chosen at run time (exactly)
//  interval     appell::interval          rigorous, 53-bit bounds
//  mpfi         appell::mpfi              rigorous, bits chosen at run time
//  arb          appell::arb               rigorous (Arb's balls), bits chosen at run time
//
// The Boost.Multiprecision types are used without expression templates
// (et_off): Eigen's own expression templates do not compose with Boost's.
// appell::mpfi is MPFI under appell's own backend (mpfi_backend.hpp: both
// bounds in one allocation), not Boost's mpfi_float_backend; appell::mpfr is
// MPFR under appell's own backend (mpfr_backend.hpp: exactly the bits asked
// for, and no heap up to 256 bits), not Boost's mpfr_float_backend.  appell::arb is a ball of
// Arb (libflint-arb) under appell's backend (arb_backend.hpp: the value opaque, arb.h kept out).
#pragma once

#if defined(__GNUC__) && defined(__STRICT_ANSI__)
#error "appell needs the GNU dialect (-std=gnu++20): Boost's float128 does not compile in strict ISO mode. With CMake, leave CXX_EXTENSIONS on (the default) for targets that use appell."
#endif

#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <qd/dd_real.h>

#include "appell/scalar/arb_backend.hpp"
#include "appell/scalar/interval.hpp"
#include "appell/scalar/mpfi_backend.hpp"
#include "appell/scalar/mpfr_backend.hpp"

namespace appell {

using float128 = boost::multiprecision::float128;
using mpfr = boost::multiprecision::number<mp::mpfr_backend, boost::multiprecision::et_off>;
using mpfi = boost::multiprecision::number<mp::mpfi_backend, boost::multiprecision::et_off>;
using arb = boost::multiprecision::number<mp::arb_backend, boost::multiprecision::et_off>;
using dd = ::dd_real;

/// Sets the precision of new `mpfr`, `mpfi` and `arb` values (on this thread and
/// others) and returns `bits`: both get exactly `bits` bits (appell's own
/// backends; Boost 1.74's mpfr_float, set in decimal digits, gave 113 -> 114).
unsigned set_mp_precision_bits(unsigned bits);
/// The precision, in bits, of new `mpfr` and `mpfi` values: what the last set_mp_precision_bits asked for.
unsigned mp_precision_bits();
/// The precision, in bits, that new `mpfr` values get (== mp_precision_bits()).
unsigned mpfr_precision_bits();

/// RAII: sets the mp precision for a scope and restores it.
class mp_precision_scope {
 public:
  explicit mp_precision_scope(unsigned bits);
  ~mp_precision_scope();
  mp_precision_scope(const mp_precision_scope&) = delete;
  mp_precision_scope& operator=(const mp_precision_scope&) = delete;
  unsigned bits() const { return bits_; }

 private:
  unsigned saved_mpfr_bits_;
  unsigned saved_mpfi_bits_;
  unsigned saved_arb_bits_;
  unsigned bits_;
};

}  // namespace appell
