// appell/studies/accuracy.hpp -- the accuracy of an evaluation against a high-precision
// reference (every result component in MPFR at many bits): the measure of `appell tradeoff`
// and `appell extremes`, and of the guarantees tests/extremes.cpp holds them to.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"

namespace appell::studies {

/// Every result component of the scene, evaluated in mpfr at `bits` bits (input_error where
/// the build left mpfr out).
template <class M = mpfr>
std::vector<mpfr_value> reference_values(const scene_input& scene, unsigned bits) {
  if constexpr (!scalar_built<M>) throw input_error(left_out_scalar_message("the reference values", "mpfr"));
  mp_precision_scope scope(bits);
  std::vector<mpfr_value> ref;
  for (const auto& r : compute<M>(prepare<M>(scene)).results)
    for (const M& x : r.values) {
      mpfr_value v;
      to_mpfr_exact(x, v);
      ref.push_back(v);
    }
  return ref;
}

struct accuracy {
  double digits = NAN;     ///< -log10 of the largest relative error (interval types: of the farther bound)
  double rel_width = NAN;  ///< interval types: the largest width / |reference|
};

/// Relative error is taken against |reference|, or absolute where the
/// reference is below 1e-300 (an exact 0); digits are capped at `cap`.
template <class T>
accuracy measure_accuracy(const evaluation<T>& e, const std::vector<mpfr_value>& ref, double cap) {
  double worst = 0, widest = 0;
  std::size_t i = 0;
  for (const auto& r : e.results)
    for (const T& x : r.values) {
      const mpfr_prec_t p = mpfr_get_prec(ref[i]) + 64;
      mpfr_value lo, hi, d1(p), d2(p), mag(64), w(64);
      scalar_traits<T>::to_mpfr(x, lo, hi);
      mpfr_sub(d1, lo, ref[i], MPFR_RNDU);
      mpfr_sub(d2, hi, ref[i], MPFR_RNDU);
      mpfr_abs(d1, d1, MPFR_RNDU);
      mpfr_abs(d2, d2, MPFR_RNDU);
      mpfr_max(d1, d1, d2, MPFR_RNDU);
      mpfr_sub(w, hi, lo, MPFR_RNDU);
      mpfr_abs(mag, ref[i], MPFR_RNDN);
      if (mpfr_cmp_d(mag, 1e-300) > 0) {
        mpfr_div(d1, d1, mag, MPFR_RNDU);
        mpfr_div(w, w, mag, MPFR_RNDU);
      }
      worst = std::max(worst, mpfr_get_d(d1, MPFR_RNDU));
      widest = std::max(widest, mpfr_get_d(w, MPFR_RNDU));
      ++i;
    }
  accuracy a;
  a.digits = worst > 0 ? std::min(-std::log10(worst), cap) : cap;
  if constexpr (scalar_traits<T>::is_interval) a.rel_width = widest;
  return a;
}

}  // namespace appell::studies
