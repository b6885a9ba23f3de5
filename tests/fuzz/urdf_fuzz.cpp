// tests/fuzz/urdf_fuzz.cpp -- fuzz harness for the URDF reader: any bytes as a URDF file (XML
// syntax, the robot's elements, its numbers and tree), then what was accepted as the `system`
// file `appell convert` prints (at rest, standard gravity) through the system reader and `eval`
// in interval<double> and mpfi at 64 bits.  Oracle beyond the contract (harness.hpp): the
// converted file is read (a URDF the URDF reader accepts is a system file, or an input_error
// naming why: the mass matrix singular), and the two enclosures of every result intersect.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "appell/io/scene.hpp"
#include "appell/io/urdf.hpp"
#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace appell;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<urdf_robot> robot;
  fuzz::within_contract([&] { robot = parse_urdf(text, "fuzz.urdf"); });
  if (!robot) return 0;
  std::string system;
  try {
    system = urdf_to_system(*robot, urdf_scene_options{});
  } catch (const input_error& e) {
    // A robot whose joints are all fixed has nothing to move with a fixed base (urdf.hpp).
    if (std::string(e.what()).find("no joint moves") == std::string::npos)
      fuzz::finding(std::string("a URDF the reader accepted could not be converted: ") + e.what());
    return 0;
  } catch (const std::exception& e) {
    fuzz::finding(std::string("a URDF the reader accepted could not be converted: ") + e.what());
  }
  std::optional<scene_input> scene;
  try {
    scene = read_scene(parse_json(system));
  } catch (const input_error& e) {
    const std::string why = e.what();
    if (why.find("mass matrix is singular") == std::string::npos && why.find("must be positive") == std::string::npos &&
        why.find("positive semidefinite") == std::string::npos && why.find("more than") == std::string::npos &&
        why.find("exceed") == std::string::npos)
      fuzz::finding("a URDF the reader accepted converts to a system file the system reader refuses: " + why);
    return 0;
  } catch (const std::exception& e) {
    fuzz::finding(std::string("unexpected exception reading the converted file: ") + e.what());
  }
  std::optional<evaluation<interval>> a;
  fuzz::within_contract([&] { a = evaluate<interval>(*scene); });
  fuzz::within_contract([&] {
    const mp_precision_scope bits(64);
    const evaluation<mpfi> b = evaluate<mpfi>(*scene);
    if (!a) return;
    for (std::size_t i = 0; i < a->results.size(); ++i)
      for (std::size_t j = 0; j < a->results[i].values.size(); ++j) {
        const interval& x = a->results[i].values[j];
        const mpfi& y = b.results.at(i).values.at(j);
        const mpfr lo = mpfi_lower(y), hi = mpfi_upper(y);
        if (mpfr_cmp_d(lo.backend().data(), x.upper()) > 0 || mpfr_cmp_d(hi.backend().data(), x.lower()) < 0)
          fuzz::finding("disjoint enclosures of " + a->results[i].name);
      }
  });
  return 0;
}
