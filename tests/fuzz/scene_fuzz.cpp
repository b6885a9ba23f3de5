// tests/fuzz/scene_fuzz.cpp -- fuzz harness for the scene reader: any bytes as
// a scene file (JSON syntax, decimals, the models' fields and constraints,
// cone expressions), then the whole of `appell eval` on what was accepted: all
// seven scalars (mpfr and mpfi at 64 bits, cheap enough to fuzz), both output
// formats.  Oracle beyond "no crash, no hang, only the contract's exceptions":
// the interval<double> and the mpfi enclosures of every result must intersect
// (both claim to contain the same exact value).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "appell/io/scene.hpp"
#include "harness.hpp"

namespace {

using namespace appell;

void enclosures_intersect(const evaluation<interval>& a, const evaluation<mpfi>& b) {
  for (std::size_t i = 0; i < a.results.size(); ++i)
    for (std::size_t j = 0; j < a.results[i].values.size(); ++j) {
      const interval& x = a.results[i].values[j];
      const mpfi& y = b.results.at(i).values.at(j);
      const mpfr lo = mpfi_lower(y), hi = mpfi_upper(y);
      if (mpfr_cmp_d(lo.backend().data(), x.upper()) > 0 || mpfr_cmp_d(hi.backend().data(), x.lower()) < 0)
        fuzz::finding("disjoint enclosures of " + a.results[i].name + ": interval " + to_string(x) + ", mpfi " +
                      to_string(y));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<scene_input> scene;
  fuzz::within_contract([&] { scene = read_scene(parse_json(text)); });
  if (!scene) return 0;
  for (const scalar_info& s : standard_scalar_infos())
    fuzz::within_contract([&] {
      with_scalar(s.name, s.runtime_precision ? std::optional<unsigned>(64) : std::nullopt,
                  [&]<class T>(std::type_identity<T>) {
                    const evaluation<T> e = evaluate<T>(*scene);
                    (void)format_json<T>(*scene, e);
                    (void)format_text<T>(*scene, e);
                    return 0;
                  });
    });
  std::optional<evaluation<interval>> a;
  std::optional<evaluation<mpfi>> b;
  fuzz::within_contract([&] { a = evaluate<interval>(*scene); });
  fuzz::within_contract([&] {
    const mp_precision_scope bits(64);
    b = evaluate<mpfi>(*scene);
    if (a) enclosures_intersect(*a, *b);
  });
  return 0;
}
