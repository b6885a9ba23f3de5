// tests/fuzz/expression_fuzz.cpp -- fuzz harness for the expression parser:
// any bytes as a cone psi = f(theta) (SCENES.md), then what the top_on_cone
// model does with it: f' and f'' symbolically, and all three evaluated at
// points and on an interval, on scalars and on dual numbers.  Oracle beyond
// the contract: the interval value on the enclosure of 0.7 and the one on
// [0.69, 0.71] both contain f(0.7), so they must intersect.  (Not inclusion
// isotonicity: appell's interval functions may enclose a thin argument less
// tightly than a wide one, through their memo of recent results or their
// narrow-argument path; a first campaign flagged exactly that, with both
// enclosures correct.)
#include <cstddef>
#include <cstdint>
#include <optional>

#include "appell/expr/expression.hpp"
#include "appell/scalar/policy.hpp"
#include "harness.hpp"

namespace {

using namespace appell;

void intersect(const interval& thin, const interval& wide, const expression& e) {
  if (thin.lower() > wide.upper() || thin.upper() < wide.lower())
    fuzz::finding(e.where() + ": f(thin) = " + to_string(thin) + " and f(wide) = " + to_string(wide) + " are disjoint");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<expression> f, fp, fpp;
  fuzz::within_contract([&] {
    f = expression::parse(text, "theta", "cone");
    fp = f->derivative();
    fpp = fp->derivative();
  });
  if (!fpp) return 0;
  for (const expression* e : {&*f, &*fp, &*fpp}) {
    for (const char* at : {"0.7", "0", "-2.5", "1e-300", "3.141592653589793"})
      fuzz::within_contract([&] {
        (void)e->eval(from_decimal<double>(at));
        (void)compiled_expression<double>(*e).eval(dual<double>(from_decimal<double>(at), 1.0));
      });
    std::optional<interval> thin;
    fuzz::within_contract([&] {
      const evaluation_scope<interval> scope;
      thin = compiled_expression<interval>(*e).eval(from_decimal<interval>("0.7"));
      scope.verify();
    });
    fuzz::within_contract([&] {
      const evaluation_scope<interval> scope;
      const interval wide = compiled_expression<interval>(*e).eval(interval(0.69, 0.71));
      scope.verify();
      if (thin) intersect(*thin, wide, *e);
    });
    fuzz::within_contract([&] {
      const mp_precision_scope bits(64);
      const evaluation_scope<mpfi> scope;
      (void)compiled_expression<mpfi>(*e).eval(dual<mpfi>(from_decimal<mpfi>("0.7"), mpfi(1)));
    });
  }
  return 0;
}
