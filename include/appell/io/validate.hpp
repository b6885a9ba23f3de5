// appell/io/validate.hpp -- checks that model readers share, decided on exact decimals.
#pragma once

#include <string>

#include "appell/io/json.hpp"

namespace appell {

/// d > 0 exactly, or input_error naming the field ("WHAT must be positive").
void require_positive(const object_reader& r, const std::string& key, const decimal_field& d,
                      const std::string& what = "");

}  // namespace appell
