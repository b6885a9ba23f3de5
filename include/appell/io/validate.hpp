// appell/io/validate.hpp -- checks that model readers share, decided on exact decimals.
#pragma once

#include <string>

#include "appell/io/json.hpp"

namespace appell {

/// d > 0 exactly, or input_error naming the field ("WHAT must be positive").
void require_positive(const object_reader& r, const std::string& key, const decimal_field& d,
                      const std::string& what = "");

/// The fields of a symmetric top on a fixed point O of its axis (dynamics/symmetric_top.hpp):
/// A about O, C about the axis, mass, l = OG.
struct symmetric_top_fields {
  decimal_field A, C, mass, l;
};
/// Reads scene.top {A, C, mass, l}: A, C, mass positive, and a real body of revolution
/// (A >= m l^2, C <= 2 (A - m l^2)), decided exactly; input_error naming the field otherwise.
symmetric_top_fields read_symmetric_top(object_reader& scene);

/// |d| <= 2^40 exactly (an angle in radians), or input_error naming the field.
void require_angle_in_range(const object_reader& r, const std::string& key, const decimal_field& d);

}  // namespace appell
