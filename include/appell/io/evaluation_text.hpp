// `appell eval`'s document for a scene in a scalar named at run time: evaluate<T> and
// format_json<T> / format_text<T> (io/scene.hpp) behind one scalar-free call
// (src/io/evaluation_text.cpp).
#pragma once

#include <optional>
#include <string>

#include "appell/io/scene.hpp"

namespace appell {

/// The scene evaluated in `scalar` (mpfr and mpfi at `bits`, default 256), as `format` "json"
/// or "text".  input_error for an unknown or left-out scalar, or bits a fixed scalar cannot take;
/// the evaluation's own errors as evaluate<T> throws them.
std::string evaluation_text(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits,
                            const std::string& format);

}  // namespace appell
