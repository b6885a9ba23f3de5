// The studies' runs in a scalar named at run time (`appell tradeoff`, `appell extremes`): the
// scene evaluated in that scalar against a high-precision reference (studies/accuracy.hpp), and a
// timing loop for it.  Scalar-free at their boundary; compiled once (src/studies/scalar_runs.cpp).
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"
#include "appell/studies/accuracy.hpp"

namespace appell::studies {

/// One scalar's evaluation of a scene against a reference (extremes).
struct scalar_outcome {
  std::string status = "ok";  ///< ok | refused | bad input
  unsigned bits = 0;          ///< the scalar's precision
  double digits = NAN, rel_width = NAN;  ///< against the reference (NaN without one)
  double amplification = NAN;            ///< error_amplification where the scalar reports it
  std::string why;                       ///< refused, bad input: the reason
};
/// The scene evaluated in `scalar` (mpfr, mpfi at `bits`); `ref` null: no reference (digits NaN);
/// `cap` the digits the reference carries.  input_error for an unknown or left-out scalar.
scalar_outcome evaluate_against(const scene_input& scene, const std::vector<mpfr_value>* ref, double cap,
                                const std::string& scalar, std::optional<unsigned> bits);

/// One scalar ready to be timed (tradeoff): its accuracy against the reference, and a batch of
/// evaluations of the prepared scene that lasts at least a millisecond (warmed up).
struct timed_scalar {
  std::string scalar;
  unsigned bits = 0;
  double digits = NAN, rel_width = NAN;
  long batch = 0;                   ///< evaluations in one batch
  std::string note;                 ///< why it could not run ("": it runs)
  std::function<void()> run_batch;  ///< empty when note is set
};
timed_scalar prepare_timing(const scene_input& scene, const std::vector<mpfr_value>& ref, double cap,
                            const std::string& scalar, std::optional<unsigned> bits);

}  // namespace appell::studies
