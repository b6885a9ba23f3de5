// appell/io/amplification.hpp -- a scene's error amplification from an interval evaluation
// already made (io/scene.hpp: error_amplification(scene) makes its own).
//
// `appell reference` evaluates each state in interval<double> anyway (its tolerance needs the
// widths): taking the amplification from that evaluation spares one more evaluation of the same
// scene in the same scalar, with the same number (the evaluation is deterministic).
#pragma once

#include "appell/io/scene.hpp"

namespace appell {

/// error_amplification(scene), given `e = compute<interval>(prepare<interval>(scene))`: the
/// largest relative width of e's results over 2^-53 where that is finite; otherwise
/// error_amplification(scene) (its fallback in 53-bit mpfi, or infinity).
double error_amplification(const scene_input& scene, const evaluation<interval>& e);

}  // namespace appell
