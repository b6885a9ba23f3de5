// The report of `appell linearize` (SCENES.md, "linearize"): the linearized equations of a system
// file about the steady motion its "linearize" section names, with the eigenvalues and the speeds
// where an eigenvalue's real part crosses 0 (system/linearize.hpp), as JSON or text.
// Scalar-free: the scalar by name (src/models/system_linearization.cpp).
#pragma once

#include <optional>
#include <string>

#include "appell/models/system.hpp"

namespace appell {

/// The report in `scalar` (mpfr and mpfi at `bits`, default 256), `format` "json" or "text".
/// input_error for a scene without a "linearize" section, an unknown format or scalar, or a
/// build without the linearization (APPELL_EVAL_ONLY).
std::string linearization_text(const system_input& in, const std::string& scalar, std::optional<unsigned> bits,
                              const std::string& format);

}  // namespace appell
