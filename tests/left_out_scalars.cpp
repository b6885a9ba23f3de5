// A build that left scalars out (CMake's APPELL_SCALARS): the dispatcher from `--scalar NAME`
// refuses a left-out scalar with a message saying how to build it, and never instantiates the
// command for it; the built ones run as in a whole build.  This suite is compiled as such a
// build is (APPELL_BUILT_SCALAR_MASK set below, whatever the build's own: interval and mpfi only)
// and uses the header alone, so it needs no library built that way.  The configure-time refusals of
// APPELL_SCALARS are CTest entries of their own (tests/CMakeLists.txt).
#define BOOST_TEST_MODULE left_out_scalars
#undef APPELL_BUILT_SCALAR_MASK  // a build of some scalars defines its own (scripts/test.sh's quick tier)
#define APPELL_BUILT_SCALAR_MASK 0x60u
#include <boost/test/unit_test.hpp>

#include <optional>
#include <string>
#include <type_traits>

#include "appell/scalar/standard_scalars.hpp"
#include "appell/scalar/types.hpp"

using namespace appell;

BOOST_AUTO_TEST_CASE(the_mask_names_the_built_scalars) {
  BOOST_TEST(scalar_built<interval>);
  BOOST_TEST(scalar_built<mpfi>);
  BOOST_TEST(!scalar_built<double>);
  BOOST_TEST(!scalar_built<long double>);
  BOOST_TEST(!scalar_built<dd>);
  BOOST_TEST(!scalar_built<float128>);
  BOOST_TEST(!scalar_built<mpfr>);
  BOOST_TEST(!scalar_built<int>);  // not a standard scalar at all
  BOOST_TEST(built_scalar_names() == "interval, mpfi");
  std::size_t built = 0;
  for (const scalar_info& s : standard_scalar_infos()) built += s.built ? 1 : 0;
  BOOST_TEST(standard_scalar_infos().size() == 8u);
  BOOST_TEST(built == 2u);
}

BOOST_AUTO_TEST_CASE(a_left_out_scalar_is_refused_saying_how_to_build_it) {
  for (const std::string name : {"double", "long-double", "dd", "float128", "mpfr"}) {
    bool called = false;
    try {
      with_scalar(name, std::nullopt, [&]<class T>(std::type_identity<T>) {
        called = true;
        return 0;
      });
      BOOST_TEST(false, name << " was not refused");
    } catch (const input_error& e) {
      const std::string m = e.what();
      BOOST_TEST_MESSAGE(m);
      BOOST_TEST(m.find("--scalar") == 0u);
      BOOST_TEST(m.find("'" + name + "'") != std::string::npos);
      BOOST_TEST(m.find("interval, mpfi") != std::string::npos);
      BOOST_TEST(m.find("-DAPPELL_SCALARS=all") != std::string::npos);
      BOOST_TEST(m.find("scripts/run.sh SCENE --scalar " + name) != std::string::npos);
    }
    BOOST_TEST(!called);
  }
}

BOOST_AUTO_TEST_CASE(the_built_scalars_run_and_an_unknown_one_is_still_unknown) {
  std::string got;
  with_scalar("interval", std::nullopt, [&]<class T>(std::type_identity<T>) {
    got = scalar_traits<T>::name;
    return 0;
  });
  BOOST_TEST(got == "interval");
  unsigned bits = 0;
  with_scalar("mpfi", 113u, [&]<class T>(std::type_identity<T>) {
    got = scalar_traits<T>::name;
    bits = scalar_traits<T>::precision_bits();
    return 0;
  });
  BOOST_TEST(got == "mpfi");
  BOOST_TEST(bits == 113u);
  try {
    with_scalar("quad", std::nullopt, [&]<class T>(std::type_identity<T>) { return 0; });
    BOOST_TEST(false, "quad was not refused");
  } catch (const input_error& e) {
    BOOST_TEST(std::string(e.what()).find("unknown scalar 'quad'") != std::string::npos);
  }
}
