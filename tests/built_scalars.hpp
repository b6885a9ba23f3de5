// tests/built_scalars.hpp -- which standard scalars this build compiled, for the suites.
//
// scripts/test.sh's quick tier builds the library in double, interval and mpfi only (CMake's
// APPELL_SCALARS; `scripts/test.sh --full`, which CI runs, builds all eight).  A case that needs
// another scalar's instantiations
//   * guards the code that names it with `#if APPELL_TEST_HAS(mpfr)`: a call of a left-out
//     scalar's explicit instance is a link error, so the guard is the preprocessor's;
//   * carries the decorator `* needs_scalars({"mpfr"})`, which skips it in such a build with a
//     line naming the scalars it needs and the command that builds them.
// Code that loops over the scalars at run time asks scalar_info::built (standard_scalars.hpp).
#pragma once

#include <boost/test/unit_test.hpp>

#include <initializer_list>
#include <string>
#include <tuple>
#include <type_traits>

#include "appell/scalar/standard_scalars.hpp"
#include "appell/scalar/types.hpp"

// The place of each scalar in APPELL_STANDARD_SCALARS (checked against the list below).
#define APPELL_TEST_SCALAR_INDEX_double 0
#define APPELL_TEST_SCALAR_INDEX_long_double 1
#define APPELL_TEST_SCALAR_INDEX_dd 2
#define APPELL_TEST_SCALAR_INDEX_float128 3
#define APPELL_TEST_SCALAR_INDEX_mpfr 4
#define APPELL_TEST_SCALAR_INDEX_interval 5
#define APPELL_TEST_SCALAR_INDEX_mpfi 6
#define APPELL_TEST_SCALAR_INDEX_arb 7
/// 1 where this build compiled the library in the scalar NAME (long double: long_double), else 0.
#define APPELL_TEST_HAS(name) ((((APPELL_BUILT_SCALAR_MASK) >> APPELL_TEST_SCALAR_INDEX_##name) & 1u) != 0)

/// 1 where this build compiled every standard scalar (scripts/test.sh --full, CI's build); the
/// quick tier's three-scalar build is 0, and the suites that draw many random inputs draw fewer
/// there (each says how many), the full tier keeping the statistics.
#define APPELL_TEST_EVERY_SCALAR (((APPELL_BUILT_SCALAR_MASK) & 0xffu) == 0xffu)

namespace appell::test {

static_assert(standard_scalar_index<double> == APPELL_TEST_SCALAR_INDEX_double);
static_assert(standard_scalar_index<long double> == APPELL_TEST_SCALAR_INDEX_long_double);
static_assert(standard_scalar_index<dd> == APPELL_TEST_SCALAR_INDEX_dd);
static_assert(standard_scalar_index<float128> == APPELL_TEST_SCALAR_INDEX_float128);
static_assert(standard_scalar_index<mpfr> == APPELL_TEST_SCALAR_INDEX_mpfr);
static_assert(standard_scalar_index<interval> == APPELL_TEST_SCALAR_INDEX_interval);
static_assert(standard_scalar_index<mpfi> == APPELL_TEST_SCALAR_INDEX_mpfi);
static_assert(standard_scalar_index<arb> == APPELL_TEST_SCALAR_INDEX_arb);
// APPELL_TEST_EVERY_SCALAR's 0xff: the eight scalars above (a ninth needs its bit there too)
static_assert(std::tuple_size_v<per_standard_scalar<std::type_identity_t>> == 8);
static_assert(APPELL_TEST_HAS(double) == scalar_built<double> && APPELL_TEST_HAS(long_double) == scalar_built<long double> &&
              APPELL_TEST_HAS(dd) == scalar_built<dd> && APPELL_TEST_HAS(float128) == scalar_built<float128> &&
              APPELL_TEST_HAS(mpfr) == scalar_built<mpfr> && APPELL_TEST_HAS(interval) == scalar_built<interval> &&
              APPELL_TEST_HAS(mpfi) == scalar_built<mpfi> && APPELL_TEST_HAS(arb) == scalar_built<arb>);

/// Whether this build compiled the scalar of CLI name `name` (standard_scalar_infos).
inline bool built(const std::string& name) {
  for (const scalar_info& s : standard_scalar_infos())
    if (s.name == name) return s.built;
  return false;
}

/// Calls f(std::type_identity<T>{}) where this build compiled T (f a generic lambda: its body is
/// instantiated only then); otherwise says that it skipped T.
template <class T, class F>
void if_built(F&& f) {
  if constexpr (scalar_built<T>)
    f(std::type_identity<T>{});
  else
    BOOST_TEST_MESSAGE("skipped " << scalar_traits<T>::name << ": this build left it out (scripts/test.sh --full builds every scalar)");
}

/// A test case's decorator: the case runs where this build compiled every scalar named (CLI
/// names), and is skipped, saying so, where it left one out.
inline boost::unit_test::decorator::precondition needs_scalars(std::initializer_list<const char*> names) {
  std::string missing;
  for (const char* n : names)
    if (!built(n)) missing += (missing.empty() ? "" : ", ") + std::string(n);
  return boost::unit_test::decorator::precondition([missing](boost::unit_test::test_unit_id) {
    boost::test_tools::assertion_result r(missing.empty());
    if (!missing.empty())
      r.message() << "this build left out " << missing << " (APPELL_SCALARS); scripts/test.sh --full builds every scalar";
    return r;
  });
}

}  // namespace appell::test
