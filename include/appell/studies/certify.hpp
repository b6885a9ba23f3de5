// Certified reference values (`appell reference`, docs/reference-values.md): one state of a scene
// evaluated in an interval scalar, each result's components as a quantity an engine is scored
// against: its enclosure's bounds rounded outward to decimal, the double nearest the enclosure
// and that double's error bound, and the tolerance a double-precision engine is held to (from the
// problem's conditioning and appell's own interval<double> enclosure).  Scalar-free at its
// boundary: the scalar by name; compiled once (src/studies/certify.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"

namespace appell {

/// One quantity of one state: a result's component ("pivot_force[0]"), or a derived value's.
struct certified_quantity {
  std::string name, lower, upper, nearest_double, rel_error_bound, tolerance;
  bool decided = false;  ///< every point of [lower, upper] rounds to nearest_double
  bool derived = false;  ///< of the derived state (evaluation::derived), not a result
};

/// A state's quantities, results first, then the derived values, and the state's
/// error_amplification (io/amplification.hpp).
struct certified_state {
  double amplification = 0;
  std::vector<certified_quantity> quantities;
};

/// The scene's state certified in `scalar` ("interval", or "mpfi" or "arb" at `bits`, default 256).
/// input_error for another scalar or a scene it refuses; certification_error or domain_error
/// where the enclosure cannot be formed.
certified_state certify(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits = std::nullopt);

/// One state as `appell reference` (and the Python module's reference) records it: certified, or
/// why not ("refused: ..." where the scene is refused, "cannot certify: ..." where no enclosure
/// can be formed).
struct state_certificate {
  bool certified = false;
  certified_state state;
  std::string reason;
};

/// The state's scene (parsed, its values set) read and certified.  With binary64_inputs a `urdf`
/// scene is first taken as the system file it reads as, every decimal of it replaced by its
/// nearest double: the robot's own numbers as an engine reads them.
state_certificate certify_state(json_value scene, const std::string& scalar, std::optional<unsigned> bits,
                                bool binary64_inputs);

}  // namespace appell
