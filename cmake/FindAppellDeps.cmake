# MPFR, MPFI, GMP, QD, Arb (with FLINT) and libquadmath ship no CMake or pkg-config files we can
# rely on (MPFI has neither), so find them by hand and expose appell::deps.
include(FindPackageHandleStandardArgs)
find_path(APPELL_MPFR_INCLUDE mpfr.h)
find_path(APPELL_MPFI_INCLUDE mpfi.h)
find_path(APPELL_QD_INCLUDE qd/dd_real.h)
# Arb (Debian libflint-arb-dev): arb.h beside the other headers, flint's in flint/.
find_path(APPELL_ARB_INCLUDE arb.h)
find_path(APPELL_FLINT_INCLUDE flint/flint.h)
find_library(APPELL_MPFR_LIB mpfr)
find_library(APPELL_MPFI_LIB mpfi)
find_library(APPELL_GMP_LIB gmp)
find_library(APPELL_QD_LIB qd)
find_library(APPELL_ARB_LIB NAMES flint-arb arb)
find_library(APPELL_FLINT_LIB flint)
# libquadmath sits in the compiler's own library directory.
find_library(APPELL_QUADMATH_LIB NAMES quadmath libquadmath.so.0
  HINTS ${CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES})
find_package_handle_standard_args(AppellDeps NAME_MISMATCHED REQUIRED_VARS
  APPELL_MPFR_INCLUDE APPELL_MPFI_INCLUDE APPELL_QD_INCLUDE APPELL_ARB_INCLUDE APPELL_FLINT_INCLUDE
  APPELL_MPFR_LIB APPELL_MPFI_LIB APPELL_GMP_LIB APPELL_QD_LIB APPELL_QUADMATH_LIB APPELL_ARB_LIB APPELL_FLINT_LIB)
if(AppellDeps_FOUND AND NOT TARGET appell::deps)
  add_library(appell::deps INTERFACE IMPORTED)
  set_target_properties(appell::deps PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${APPELL_MPFR_INCLUDE};${APPELL_MPFI_INCLUDE};${APPELL_QD_INCLUDE};${APPELL_ARB_INCLUDE}"
    INTERFACE_LINK_LIBRARIES "${APPELL_ARB_LIB};${APPELL_FLINT_LIB};${APPELL_MPFI_LIB};${APPELL_MPFR_LIB};${APPELL_GMP_LIB};${APPELL_QD_LIB};${APPELL_QUADMATH_LIB}")
endif()
