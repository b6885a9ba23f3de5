// appell/scalar/products.hpp -- sums of two and three products, the kernels of 3 x 3 products,
// dot and cross products.
//
// Written out, a0 b0 + a1 b1 + a2 b2 forms each product and each partial sum as a number of its
// own. Two scalars do better in one call with the same or a tighter enclosure:
//  * interval: the products and sums in SSE pairs (-lower, upper), rounded up lane by lane, the
//    operands checked once (interval.hpp, detail::interval_sum_of_products): the same bounds as the
//    operations one by one, about a quarter less time;
//  * arb: Arb's arb_dot, each product exact and the sum rounded once (arb_backend.hpp): a third
//    of the time at 113 bits, a ball as tight or tighter.
// Every other scalar, and mixed or differentiated operands (jets, slopes), take the expression
// as written: the same operations in the same order as before, so point results keep their bits.
#pragma once

#include <type_traits>

#include "appell/scalar/types.hpp"

namespace appell {

/// a0 b0 + a1 b1 + a2 b2 (in that order where the scalar rounds each operation).
template <class S>
S sum_of_products(const S& a0, const S& b0, const S& a1, const S& b1, const S& a2, const S& b2) {
  if constexpr (std::is_same_v<S, interval>) {
    return detail::interval_sum_of_products(a0, b0, a1, b1, a2, b2);
  } else if constexpr (std::is_same_v<S, arb>) {
    // x x alone keeps Arb's square (>= 0) where a product of two balls would not: as written
    if (&a0 == &b0 || &a1 == &b1 || &a2 == &b2) return a0 * b0 + a1 * b1 + a2 * b2;
    const mp::arb_backend* x[3] = {&a0.backend(), &a1.backend(), &a2.backend()};
    const mp::arb_backend* y[3] = {&b0.backend(), &b1.backend(), &b2.backend()};
    S r;
    mp::arb_sum_of_products(r.backend(), x, y, 3, 0u);
    return r;
  } else {
    return a0 * b0 + a1 * b1 + a2 * b2;
  }
}

/// a0 b0 - a1 b1.
template <class S>
S difference_of_products(const S& a0, const S& b0, const S& a1, const S& b1) {
  if constexpr (std::is_same_v<S, interval>) {
    return detail::interval_difference_of_products(a0, b0, a1, b1);
  } else if constexpr (std::is_same_v<S, arb>) {
    if (&a0 == &b0 || &a1 == &b1) return a0 * b0 - a1 * b1;
    const mp::arb_backend* x[2] = {&a0.backend(), &a1.backend()};
    const mp::arb_backend* y[2] = {&b0.backend(), &b1.backend()};
    S r;
    mp::arb_sum_of_products(r.backend(), x, y, 2, 2u);
    return r;
  } else {
    return a0 * b0 - a1 * b1;
  }
}

}  // namespace appell
