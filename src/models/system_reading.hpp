// What the system model's reader shares between its files (src/models/system*.cpp): the
// phases that need 256 bits (system_checks.cpp) and the projection (system_projection.cpp).
#pragma once

#include "appell/models/system.hpp"
#include "appell/io/validate.hpp"

#include <cstdio>
#include <string>

namespace appell::system_reading {

/// A short decimal of an enclosure's midpoint, for messages.
inline std::string short_text(const mpfi& x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", approx_double(x));
  return buf;
}

/// The sign of each link axis along a basis vector, and every axis not 0, at 256 bits.
void settle_link_axes(system_definition& def);

/// At the state, at 256 bits (system_checks.cpp): everything the reader can decide there, the
/// projection ("project") applied first.  input_error naming the field otherwise.
void check_at_state(system_input& in);

/// The state replaced by its projection onto the constraints, read back into q and u at the
/// caller's precision, the moves checked against "project".
void project_state(system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u);

/// The linearization's reference motion: the state (the projected one, with "project") with
/// what "about" sets.
void set_reference_motion(linearize_input& li, const system_input& in);

}  // namespace appell::system_reading
