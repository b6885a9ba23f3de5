// appell/scalar/mp_default_precision.hpp -- the default precision of a variable-precision
// backend (mpfr_backend.hpp, mpfi_backend.hpp), in bits and in decimal digits.
//
// appell sets it in bits (set_mp_precision_bits: new values get exactly that many).  Boost's
// frontend reads and sets it in decimal digits: its precision guard raises the default to an
// operand's digits for one operation and restores the saved digits afterwards.  Digits do not
// name a bit count (113 and 114 bits are both 34 digits), so the restore gives back the bits
// that were set in bits whenever the digits are theirs.
#pragma once

#include <mpfr.h>

namespace appell::mp {

class precision_default {
 public:
  explicit constexpr precision_default(unsigned digits10) noexcept
      : digits10_(digits10), bits_(bits_of(digits10)), exact_digits10_(digits10), exact_bits_(bits_) {}
  unsigned digits10() const noexcept { return digits10_; }
  mpfr_prec_t bits() const noexcept { return bits_; }
  constexpr void set_digits10(unsigned digits10) noexcept {
    bits_ = digits10 == exact_digits10_ ? exact_bits_ : bits_of(digits10);
    digits10_ = digits10;
  }
  constexpr void set_bits(unsigned bits) noexcept {
    bits_ = exact_bits_ = static_cast<mpfr_prec_t>(bits);
    digits10_ = exact_digits10_ = digits10_of(bits);
  }
  // Boost's conversions (boost/multiprecision/detail/digits.hpp: digits2_2_10, digits10_2_2),
  // written constexpr so that the defaults are set before any dynamic initialisation
  // (tests/mpfr_backend.cpp checks them against Boost's).
  static constexpr unsigned digits10_of(unsigned long bits) noexcept {
    return static_cast<unsigned>((bits * 301uL) / 1000uL);
  }
  static constexpr mpfr_prec_t bits_of(unsigned long digits10) noexcept {
    return static_cast<mpfr_prec_t>((digits10 * 1000uL) / 301uL + ((digits10 * 1000uL) % 301 ? 2u : 1u));
  }

 private:
  unsigned digits10_;
  mpfr_prec_t bits_;
  unsigned exact_digits10_;  // the digits of the last count set in bits, and those bits
  mpfr_prec_t exact_bits_;
};

}  // namespace appell::mp
