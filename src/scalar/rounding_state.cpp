// The definition of appell::detail::upward_known (appell/scalar/rounding_state.hpp), the only
// unit of libappell_rounding.so: a shared object of its own so that its thread-local block (one
// byte) is all that the initial-exec accesses ask glibc to place in static TLS.
#include "appell/scalar/rounding_state.hpp"

namespace appell::detail {
thread_local constinit bool upward_known = false;
}  // namespace appell::detail
