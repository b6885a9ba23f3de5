// appell/scalar/rounding_state.hpp -- the one thread-local flag every interval operation reads:
// whether this thread's SSE unit is known to round upward (scalar/interval.hpp explains the
// flag and the scopes that set it).
//
// It is defined once, in a shared object of its own, libappell_rounding.so
// (src/scalar/rounding_state.cpp), and reached through the initial-exec model from every unit:
// the programs', the library's and the Python module's.  Initial-exec is one load from the GOT
// and one from the thread's block, where the other models call into the dynamic linker at every
// access (a few nanoseconds, at every interval operation).  glibc grants initial-exec access to
// an object opened at run time (the Python module, opened by `import appell`) only if that
// object's whole thread-local block fits the few hundred bytes of static TLS it keeps for such
// objects: the library's own block (its scratch pools and caches, about 130 KB) never would, the
// one byte of libappell_rounding.so does (docs/architecture.md, "Python").  `constinit` tells the
// compiler that no dynamic initialization is pending, so an access calls no TLS wrapper.
#pragma once

namespace appell::detail {
extern thread_local constinit bool upward_known __attribute__((tls_model("initial-exec"), visibility("default")));
}  // namespace appell::detail
