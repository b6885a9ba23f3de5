// mpfi's + - * (include/appell/scalar/mpfi_ops.hpp) give, bound for bound,
// what MPFI's own mpfi_add / mpfi_sub / mpfi_mul give: on random operands of
// every sign case (positive, negative, straddling 0, with zero and infinite
// bounds), at mixed precisions, and written over either operand.  Each MPFI
// bound is correctly rounded outward, so equality also proves containment.
#define BOOST_TEST_MODULE mpfi_ops
#include <boost/test/unit_test.hpp>

#include <random>

#include "appell/scalar/traits.hpp"

using namespace appell;

namespace {

std::mt19937_64 rng(20261121);

// A random bound: mostly regular numbers of random sign and exponent, sometimes 0 or +-inf.
void random_value(mpfr_ptr v) {
  const int kind = std::uniform_int_distribution<int>(0, 19)(rng);
  if (kind == 0) return mpfr_set_zero(v, 1);
  if (kind == 1) return mpfr_set_zero(v, -1);
  if (kind == 2) return mpfr_set_inf(v, std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1);
  mpfr_set_d(v, std::uniform_real_distribution<double>(-1, 1)(rng), MPFR_RNDN);
  mpfr_mul_2si(v, v, std::uniform_int_distribution<int>(-60, 60)(rng), MPFR_RNDN);
  // fill the low bits too
  mpfr_t extra;
  mpfr_init2(extra, mpfr_get_prec(v));
  mpfr_set_d(extra, std::uniform_real_distribution<double>(0, 1)(rng), MPFR_RNDN);
  mpfr_mul_2si(extra, extra, -50, MPFR_RNDN);
  mpfr_add(v, v, extra, MPFR_RNDN);
  mpfr_clear(extra);
}

mpfi random_interval(mpfr_prec_t prec) {
  mpfi x;
  x.backend().set_prec(prec);
  mpfi_ptr p = x.backend().data();
  const int shape = std::uniform_int_distribution<int>(0, 4)(rng);
  random_value(&p->left);
  if (shape == 4) {  // [0, 0], as the derivative parts of constants are
    mpfr_set_zero(&p->left, 1);
    mpfr_set_zero(&p->right, -1);
  } else if (shape == 0) {  // thin
    mpfr_set(&p->right, &p->left, MPFR_RNDN);
  } else {
    random_value(&p->right);
  }
  if (mpfr_cmp(&p->left, &p->right) > 0) mpfr_swap(&p->left, &p->right);
  if (mpfr_inf_p(&p->left) && mpfr_sgn(&p->left) > 0) mpfr_set_inf(&p->left, -1);    // no [+inf, .]
  if (mpfr_inf_p(&p->right) && mpfr_sgn(&p->right) < 0) mpfr_set_inf(&p->right, 1);  // no [., -inf]
  if (mpfr_zero_p(&p->left)) mpfr_set_zero(&p->left, 1);    // MPFI's convention: [+0, .]
  if (mpfr_zero_p(&p->right)) mpfr_set_zero(&p->right, -1); // and [., -0]
  return x;
}

bool same_bound(mpfr_srcptr a, mpfr_srcptr b) {
  if (mpfr_nan_p(a) || mpfr_nan_p(b)) return mpfr_nan_p(a) && mpfr_nan_p(b);
  return mpfr_equal_p(a, b) && (!mpfr_zero_p(a) || mpfr_signbit(a) == mpfr_signbit(b));
}
bool same(const mpfi& x, mpfi_srcptr y) {
  return same_bound(&x.backend().data()->left, &y->left) && same_bound(&x.backend().data()->right, &y->right);
}

}  // namespace

BOOST_AUTO_TEST_CASE(sums_differences_and_products_equal_mpfi_bound_for_bound) {
  const mpfr_prec_t precs[] = {53, 113, 128, 320};
  int checked = 0, endpoint_cases = 0;
  for (int c = 0; c < 200000; ++c) {
    const mpfr_prec_t pa = precs[std::uniform_int_distribution<int>(0, 3)(rng)];
    const mpfr_prec_t pb = precs[std::uniform_int_distribution<int>(0, 3)(rng)];
    const mpfr_prec_t pr = precs[std::uniform_int_distribution<int>(0, 3)(rng)];
    const mp_precision_scope scope(static_cast<unsigned>(pr));  // results of a + b etc. take the default precision
    const mpfi a = random_interval(pa), b = random_interval(pb);
    mpfi_t ref;
    mpfi_init2(ref, static_cast<mpfr_prec_t>(mp_precision_bits()));
    const int op = c % 3;
    auto reference = [&](mpfi_srcptr x, mpfi_srcptr y) {
      if (op == 0) mpfi_add(ref, x, y);
      else if (op == 1) mpfi_sub(ref, x, y);
      else mpfi_mul(ref, x, y);
    };
    // r = a op b into a fresh value (Boost picks its precision; the reference takes the same)
    const mpfi r = op == 0 ? a + b : op == 1 ? a - b : a * b;
    mpfi_set_prec(ref, mpfi_get_prec(r.backend().data()));
    reference(a.backend().data(), b.backend().data());
    BOOST_REQUIRE_MESSAGE(same(r, ref), "op " << op << " differs from MPFI");
    // a op= b (in place, over the first operand)
    {
      mpfi x = a;
      if (op == 0) x += b;
      else if (op == 1) x -= b;
      else x *= b;
      mpfi_set_prec(ref, mpfi_get_prec(x.backend().data()));  // Boost chooses the result's precision
      reference(a.backend().data(), b.backend().data());
      BOOST_REQUIRE_MESSAGE(same(x, ref), "op= " << op << " differs from MPFI");
    }
    // the backend's in-place form called directly (over the first operand, then over the second)
    {
      using namespace boost::multiprecision::backends;
      mpfi x = a, y = b;
      if (op == 0) eval_add(x.backend(), b.backend());
      else if (op == 1) eval_subtract(x.backend(), b.backend());
      else eval_multiply(x.backend(), b.backend());
      mpfi_set_prec(ref, mpfi_get_prec(x.backend().data()));
      reference(a.backend().data(), b.backend().data());
      BOOST_REQUIRE_MESSAGE(same(x, ref), "in-place backend op " << op << " differs from MPFI");
      if (op == 0) eval_add(y.backend(), a.backend(), y.backend());
      else if (op == 1) eval_subtract(y.backend(), a.backend(), y.backend());
      else eval_multiply(y.backend(), a.backend(), y.backend());
      mpfi_set_prec(ref, mpfi_get_prec(y.backend().data()));
      reference(a.backend().data(), b.backend().data());
      BOOST_REQUIRE_MESSAGE(same(y, ref), "backend op " << op << " over its second operand differs from MPFI");
    }
    // b op b (aliased operands)
    {
      const mpfi y = op == 0 ? b + b : op == 1 ? b - b : b * b;
      mpfi_set_prec(ref, mpfi_get_prec(y.backend().data()));
      if (op == 2) mpfi_sqr(ref, b.backend().data());  // b * b is a square (as in Boost's own operator)
      else reference(b.backend().data(), b.backend().data());
      BOOST_REQUIRE_MESSAGE(same(y, ref), "aliased op " << op << " differs from MPFI");
    }
    // the rvalue forms Boost uses for chained expressions: (a op b) op a
    {
      const mpfi z = op == 0 ? (a + b) + a : op == 1 ? (a - b) - a : (a * b) * a;
      mpfi_t t;
      mpfi_init2(t, mpfi_get_prec(z.backend().data()));
      mpfi_set_prec(ref, mpfi_get_prec(z.backend().data()));
      reference(a.backend().data(), b.backend().data());
      mpfi_set(t, ref);
      reference(t, a.backend().data());
      BOOST_REQUIRE_MESSAGE(same(z, ref), "chained op " << op << " differs from MPFI");
      mpfi_clear(t);
    }
    if (detail::mpfi_all_finite(a.backend().data(), b.backend().data())) ++endpoint_cases;
    mpfi_clear(ref);
    ++checked;
  }
  BOOST_TEST_MESSAGE(checked << " random operand pairs (x6 forms) equal to MPFI bound for bound; " << endpoint_cases
                             << " of them on the direct endpoint path");
  BOOST_TEST(endpoint_cases > checked / 2);
}
