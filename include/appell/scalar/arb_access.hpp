// appell/scalar/arb_access.hpp -- Arb's own view of an appell::arb value, for the few units that
// call Arb directly (src/scalar/arb_backend.cpp, tests).  It includes arb.h, whose flint.h
// defines `ulong` and `slong` as macros: keep it out of public headers.
#pragma once

#include <arb.h>

#include "appell/scalar/arb_backend.hpp"

namespace appell::mp {

inline arb_ptr arb_of(arb_backend& x) noexcept { return static_cast<arb_ptr>(x.raw()); }
inline arb_srcptr arb_of(const arb_backend& x) noexcept { return static_cast<arb_srcptr>(x.raw()); }
}  // namespace appell::mp

namespace appell {
class mpfr_value;
}

namespace appell::mp {
/// x's bounds exactly, each MPFR number's precision set to hold them; +-inf where x is not finite.
void exact_bounds_of(const arb_backend& x, mpfr_value& lo, mpfr_value& hi);

}  // namespace appell::mp
