// The jets' recurrences over mpfr and mpfi accumulate their products in a scratch value
// (detail::product_sum, derivatives/jet.hpp) instead of writing `s += x * y`: the numbers must be
// the expression's, bit for bit and precision for precision. Checked two ways on random inputs:
// each accumulation against the expression (every precision class: below and above the inline
// capacity, the default and mixed precisions, a product of a value with itself), and whole
// series (product, quotient, sine and cosine, square root) against the same recurrences written
// with the expressions here (the library's loops before the scratch value).
#define BOOST_TEST_MODULE jet_products
#include <boost/test/unit_test.hpp>

#include <random>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/scalar/decimal.hpp"
#include "mpfr_same.hpp"

using namespace appell;
using appell::test::same;

namespace {

bool identical_numbers(const mpfr& a, const mpfr& b) { return same(a.backend().data(), b.backend().data()); }
bool identical_numbers(const mpfi& a, const mpfi& b) {
  return same(&a.backend().data()->left, &b.backend().data()->left) &&
         same(&a.backend().data()->right, &b.backend().data()->right);
}

template <class T>
T random_number(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-4, 4);
  if constexpr (std::is_same_v<T, mpfr>) {
    T x = T(u(rng)) / T(u(rng) + 9.5);  // a quotient: all its bits used
    return x;
  } else {
    const double a = u(rng), w = std::ldexp(std::abs(u(rng)), -(10 + static_cast<int>(rng() % 40)));
    if (rng() % 4 == 0) return mpfi_from_bounds(mpfr(-w), mpfr(a * w));  // straddling 0: x x is MPFI's square there
    return T(a) / T(3) + mpfi_from_bounds(mpfr(-w), mpfr(w));  // some width
  }
}

// The library's recurrences as they were written before the scratch value.
template <class T>
jet<T> product_by_expression(const jet<T>& a, const jet<T>& b) {
  const int n = jet_order();
  const int la = std::min(a.size(), n + 1), lb = std::min(b.size(), n + 1);
  const int lr = std::min(la + lb - 1, n + 1);
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(lr), T(0));
  for (int k = 0; k < lr; ++k) {
    T s = T(0);
    const int lo = std::max(0, k - lb + 1), hi = std::min(k, la - 1);
    for (int i = lo; i <= hi; ++i) s += a.c[static_cast<std::size_t>(i)] * b.c[static_cast<std::size_t>(k - i)];
    r.c[static_cast<std::size_t>(k)] = s;
  }
  return r;
}
template <class T>
jet<T> quotient_by_expression(const jet<T>& a, const jet<T>& b) {
  const int n = jet_order();
  const int lb = std::min(b.size(), n + 1);
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  for (int k = 0; k <= n; ++k) {
    T s = a[k];
    for (int j = 1; j <= std::min(k, lb - 1); ++j) s -= b.c[static_cast<std::size_t>(j)] * r.c[static_cast<std::size_t>(k - j)];
    r.c[static_cast<std::size_t>(k)] = s / b.c[0];
  }
  return r;
}
template <class T>
void sin_cos_by_expression(const jet<T>& x, jet<T>& s, jet<T>& c) {
  const int n = jet_order();
  s.c.assign(static_cast<std::size_t>(n + 1), T(0));
  c.c.assign(static_cast<std::size_t>(n + 1), T(0));
  const int lx = std::min(x.size(), n + 1);
  T s0, c0;
  sin_cos(x.c[0], s0, c0);
  s.c[0] = s0;
  c.c[0] = c0;
  for (int k = 1; k <= n; ++k) {
    T a = T(0), b = T(0);
    for (int j = 1; j <= std::min(k, lx - 1); ++j) {
      const T jx = T(j) * x.c[static_cast<std::size_t>(j)];
      a += jx * c.c[static_cast<std::size_t>(k - j)];
      b += jx * s.c[static_cast<std::size_t>(k - j)];
    }
    s.c[static_cast<std::size_t>(k)] = a / T(k);
    c.c[static_cast<std::size_t>(k)] = -b / T(k);
  }
}
template <class T>
jet<T> sqrt_by_expression(const jet<T>& x) {
  using std::sqrt;
  const int n = jet_order();
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  r.c[0] = sqrt(x.c[0]);
  const T two_r0 = T(2) * r.c[0];
  for (int k = 1; k <= n; ++k) {
    T s = x[k];
    for (int j = 1; j < k; ++j) s -= r.c[static_cast<std::size_t>(j)] * r.c[static_cast<std::size_t>(k - j)];
    r.c[static_cast<std::size_t>(k)] = s / two_r0;
  }
  return r;
}

template <class T>
bool same_jet(const jet<T>& a, const jet<T>& b) {
  if (a.size() != b.size()) return false;
  for (int k = 0; k < a.size(); ++k)
    if (!identical_numbers(a.c[static_cast<std::size_t>(k)], b.c[static_cast<std::size_t>(k)])) return false;
  return true;
}

template <class T>
void check_accumulations(unsigned bits, long& checked, long& in_place) {
  const mp_precision_scope scope(bits);
  std::mt19937_64 rng(bits * 7919u);
  for (int i = 0; i < 3000; ++i) {
    T s = random_number<T>(rng), x = random_number<T>(rng), y = random_number<T>(rng);
    if (i % 5 == 1) y.backend().round_prec(static_cast<mpfr_prec_t>(bits + 7));  // mixed: the expression's path
    const bool all_default = x.backend().prec() == y.backend().prec() && s.backend().prec() == x.backend().prec();
    T expected = s, got = s;
    detail::product_sum<T> sum;
    const bool self = i % 7 == 3;  // x x: MPFI's square, tighter than a product
    if (i % 2) {
      expected += self ? x * x : x * y;
      sum.add(got, x, self ? x : y);
    } else {
      expected -= self ? x * x : x * y;
      sum.subtract(got, x, self ? x : y);
    }
    BOOST_REQUIRE_MESSAGE(identical_numbers(expected, got), scalar_traits<T>::name << " at " << bits << " bits, case " << i);
    ++checked;
    if (all_default) ++in_place;
  }
}

template <class T>
void check_series(unsigned bits, long& checked) {
  const mp_precision_scope scope(bits);
  std::mt19937_64 rng(bits * 104729u);
  for (int order : {1, 4, 12}) {
    const jet_order_scope o(order);
    for (int i = 0; i < 20; ++i) {
      std::vector<T> ca, cb;
      for (int k = 0; k <= order; ++k) {
        ca.push_back(random_number<T>(rng));
        cb.push_back(random_number<T>(rng));
      }
      cb[0] = T(5) + cb[0];  // away from 0: a quotient and a square root
      ca[0] = T(5) + ca[0];
      const jet<T> a(ca), b(cb);
      BOOST_REQUIRE(same_jet(a * b, product_by_expression(a, b)));
      BOOST_REQUIRE(same_jet(a * a, product_by_expression(a, a)));
      BOOST_REQUIRE(same_jet(a / b, quotient_by_expression(a, b)));
      BOOST_REQUIRE(same_jet(sqrt(a), sqrt_by_expression(a)));
      jet<T> s1, c1, s2, c2;
      sin_cos(a, s1, c1);
      sin_cos_by_expression(a, s2, c2);
      BOOST_REQUIRE(same_jet(s1, s2));
      BOOST_REQUIRE(same_jet(c1, c2));
      checked += 6;
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(accumulated_products_are_the_expressions_bit_for_bit) {
  long checked = 0, in_place = 0;
  for (unsigned bits : {53u, 113u, 256u, 300u, 400u, 1000u}) {
    check_accumulations<mpfr>(bits, checked, in_place);
    check_accumulations<mpfi>(bits, checked, in_place);
  }
  BOOST_TEST_MESSAGE("accumulations compared: " << checked << ", at the default precision: " << in_place);
  BOOST_TEST(in_place > checked / 2);
  BOOST_TEST(in_place < checked);  // the mixed precisions went the expression's way
}

BOOST_AUTO_TEST_CASE(series_are_the_expressions_bit_for_bit) {
  long checked = 0;
  for (unsigned bits : {64u, 113u, 256u, 400u}) {
    check_series<mpfr>(bits, checked);
    check_series<mpfi>(bits, checked);
  }
  BOOST_TEST_MESSAGE("series compared: " << checked);
}
