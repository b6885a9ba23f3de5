// appell/scalar/policy.hpp -- the evaluation policy of each scalar, in the library.
//
// What makes an evaluation in scalar T rigorous (interval types) or
// reproducible (all types) lives here, not in the scene or I/O layer, so that a
// direct library call and `appell eval` give the same bounds:
//
//   evaluation_scope<T>   RAII around one evaluation (inputs enclosed and
//                         dynamics computed inside it):
//       interval: one upward-rounding scope (interval.hpp) and a fresh memo of
//                 function values; finish() refuses (certification_error) if
//                 the rounding mode was changed behind the scope's back;
//       mpfi, arb: the working precision scalar_traits<T>::working_bits(p)
//                 (guard bits); finish(x) rounds x outward to the p bits asked for;
//       others:   nothing.
//   require_finite(x, name)
//                         refuses (certification_error naming it: exit 3) a
//                         value that is not finite in T, an overflow: every
//                         command's numbers pass here before they are written.
//   consistent_with_zero(residual, scale)
//                         the admissibility test of a state against a
//                         constraint: interval types, the enclosure holds 0;
//                         point types, |residual| <= 64 * 2^(1 - p) * scale.
//
// Usage (what compute<T> of every scene does):
//     evaluation_scope<T> scope;                 // before enclosing the inputs
//     T x = ...;                                 // inputs and dynamics
//     scope.finish(x);                           // every result, then use them
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "appell/errors.hpp"
#include "appell/scalar/format.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

template <Scalar T>
class evaluation_scope {
 public:
  evaluation_scope() : result_bits_(scalar_traits<T>::precision_bits()) {
    if constexpr (scalar_traits<T>::needs_upward_rounding) {
      forget_interval_function_values();
      mode_.emplace();
    }
    if constexpr (std::is_same_v<T, mpfi> || std::is_same_v<T, arb>)
      precision_.emplace(scalar_traits<T>::working_bits(result_bits_));
  }
  evaluation_scope(const evaluation_scope&) = delete;
  evaluation_scope& operator=(const evaluation_scope&) = delete;

  /// The precision, in bits, of the results (the caller's, not the working one).
  unsigned result_bits() const { return result_bits_; }

  /// Makes x a result of this evaluation: mpfi and arb round outward to result_bits();
  /// interval checks that the rounding mode stayed upward.
  void finish(T& x) const {
    verify();
    if constexpr (std::is_same_v<T, mpfi>) x.backend().round_prec(static_cast<mpfr_prec_t>(result_bits_));
    if constexpr (std::is_same_v<T, arb>) x.backend().round_prec(static_cast<long>(result_bits_));
    (void)x;
  }
  /// interval: certification_error if the rounding mode was changed behind the
  /// scope's back (the operations assumed upward rounding: refuse, never return
  /// an unproved box).  Other scalars: nothing to check.
  void verify() const {
    if constexpr (scalar_traits<T>::needs_upward_rounding) {
      if (!mode_->intact())
        throw certification_error("the rounding mode was changed during the interval evaluation");
    }
  }

 private:
  unsigned result_bits_;
  std::optional<upward_rounding> mode_;
  std::optional<mp_precision_scope> precision_;
};

/// Refuses a value that is not finite in T (an overflow): certification_error naming it,
/// with its value (exit 3; a scalar with a wider range may succeed).  Never a number that
/// is not one in what a command writes.
template <Scalar T>
void require_finite(const T& x, const std::string& name) {
  if (!is_finite(x))
    throw certification_error(name + ": not finite in " + scalar_traits<T>::name + " (" + to_string(x) +
                              "; an overflow? a scalar with a wider range may succeed)");
}

/// A constraint residual at a state is consistent with 0: for interval types
/// the enclosure holds 0 (decided, not tolerated); for point types
/// |residual| <= 64 * 2^(1 - p) * scale, `scale` the size of the terms whose
/// rounding errors the residual carries.
template <Scalar T>
bool consistent_with_zero(const T& residual, const T& scale) {
  if constexpr (scalar_traits<T>::is_interval) {
    (void)scale;
    return possibly_zero(residual);
  } else {
    using std::abs;
    const T eps = pown(T(2), 1 - static_cast<int>(scalar_traits<T>::precision_bits()));  // no double underflow at 2048 bits
    return abs(residual) <= T(64) * eps * scale;
  }
}

}  // namespace appell
