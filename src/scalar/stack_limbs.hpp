// A nonnegative integer of at most 48 64-bit limbs (3072 bits) on the stack, through GMP's mpn
// layer (no allocation): the exact arithmetic of the decimal paths that replace MPFR's string
// conversions for doubles (decimal.cpp: a literal into a double; format.cpp: a double's digits).
// Private to src/scalar.
#pragma once

#include <gmp.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace appell::detail {

struct stack_limbs {
  static constexpr mp_size_t capacity = 48;  // 10^350 x 2^64 x 2^64 and 2^1164 x 10^20 fit
  mp_limb_t d[capacity];
  mp_size_t n = 0;  ///< significant limbs (d[n - 1] != 0 unless n == 0)

  void set(std::uint64_t v) {
    d[0] = static_cast<mp_limb_t>(v);
    n = v ? 1 : 0;
  }
  void mul(mp_limb_t f) {
    if (n == 0) return;
    const mp_limb_t carry = mpn_mul_1(d, d, n, f);
    if (carry) d[n++] = carry;
  }
  void mul_pow10(long k) {  // k >= 0
    constexpr mp_limb_t ten19 = 10000000000000000000ULL;
    for (; k >= 19; k -= 19) mul(ten19);
    mp_limb_t f = 1;
    for (; k > 0; --k) f *= 10;
    if (f != 1) mul(f);
  }
  void shift_left(long bits) {  // bits >= 0
    if (n == 0 || bits == 0) return;
    const auto whole = static_cast<mp_size_t>(bits / 64);
    const auto part = static_cast<unsigned>(bits % 64);
    mp_limb_t top = 0;
    if (part) top = mpn_lshift(d + whole, d, n, part);
    else std::memmove(d + whole, d, static_cast<std::size_t>(n) * sizeof(mp_limb_t));
    std::fill(d, d + whole, mp_limb_t(0));
    n += whole;
    if (top) d[n++] = top;
  }
  int compare(const stack_limbs& o) const {
    if (n != o.n) return n < o.n ? -1 : 1;
    return n == 0 ? 0 : mpn_cmp(d, o.d, n);
  }
};

}  // namespace appell::detail
