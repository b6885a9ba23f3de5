// appell::mpfr's backend (include/appell/scalar/mpfr_backend.hpp: exact bits, the
// significand inside the value up to 256 bits) against MPFR called directly:
//  * a differential run: 200,000 random steps on 40 values and their MPFR twins
//    (mpfr_t of their own) -- copies, move constructions and assignments (then use of
//    the value moved from), swaps, set_prec and round_prec, changes of the default
//    precision, + - * / (in place, aliased, mixed precisions, with unsigned long, long
//    and double operands), sqrt, exp, atan, sin, cos, atan2, abs, negation, fma, and
//    assignment from built-in numbers; precisions on both sides of the inline limit
//    (2 to 1000 bits, 256 and 257 among them).  After each step every value equals
//    its twin bit for bit, sign of zero and precision included; a result's
//    precision is the default whenever its operands have the default precision;
//    the default is never left changed by an operation;
//  * exact bits: set_mp_precision_bits(N) gives new mpfr values N bits, N = 2..600;
//  * no heap: at 256 bits and below, making, copying, moving, destroying values and
//    + - * / sqrt on them allocate nothing through GMP's functions (the ones MPFR and
//    this backend use; counted with mp_set_memory_functions); above, a value is one block;
//  * relocation: values copied bitwise to new storage (what Eigen's conservativeResize
//    does with realloc) and then used are still right, and Eigen's conservativeResize;
//  * str, text input (a failure leaves the value), conversions, numeric_limits.
// CTest runs this suite a second time under valgrind (mpfr_backend_memcheck) when
// valgrind is installed: invalid accesses and leaks fail it.
#define BOOST_TEST_MODULE mpfr_backend
#include <boost/test/unit_test.hpp>

#include <Eigen/Core>
#include <cmath>
#include <cstring>
#include <new>
#include <random>
#include <vector>

#include "appell/scalar/eigen.hpp"
#include "appell/scalar/functions.hpp"
#include "mpfr_same.hpp"

using namespace appell;

namespace {

std::mt19937_64 rng(20261128);
int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

using appell::test::same;  // value and precision, bit for bit (tests/mpfr_same.hpp)
std::string show(mpfr_srcptr p) {
  char buf[300];
  mpfr_snprintf(buf, sizeof buf, "%.30Rg (%ld bits)", p, static_cast<long>(mpfr_get_prec(p)));
  return buf;
}

mpfr_prec_t random_prec() {
  static const mpfr_prec_t common[] = {2, 24, 53, 64, 113, 128, 129, 192, 255, 256, 257, 320, 1000};
  return uniform(0, 3) == 0 ? uniform(2, 700) : common[uniform(0, 12)];
}

double random_double() {
  const int kind = uniform(0, 15);
  if (kind == 0) return 0.0;
  if (kind == 1) return -0.0;
  if (kind == 2) return uniform(-5, 5);
  return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), uniform(-60, 60));
}

// A twin: an ordinary MPFR number (mpfr_init2 / mpfr_clear), never a custom one.
struct twin {
  mpfr_t v;
  twin() { mpfr_init2(v, 53); }
  ~twin() { mpfr_clear(v); }
  twin(const twin&) = delete;
  twin& operator=(const twin&) = delete;
  void set(mpfr_srcptr x) {
    if (x == v) return;
    mpfr_set_prec(v, mpfr_get_prec(x));
    mpfr_set(v, x, MPFR_RNDN);
  }
};

unsigned digits_of(mpfr_prec_t p) {
  return static_cast<unsigned>(boost::multiprecision::detail::digits2_2_10(static_cast<unsigned long>(p)));
}
// The precision of a value made while Boost's precision guard holds `digits` decimal
// digits: the guard sets the default to them unless they are already the default's.
// (A count of 0 digits, for values of fewer than 4 bits, leaves the default as it is.)
unsigned guard_digits(unsigned digits) { return digits ? digits : mp::mpfr_backend::default_precision(); }
mpfr_prec_t guarded_prec(unsigned digits) {
  digits = guard_digits(digits);
  if (digits == mp::mpfr_backend::default_precision()) return mp::mpfr_backend::default_bits();
  return static_cast<mpfr_prec_t>(boost::multiprecision::detail::digits10_2_2(digits));
}
// The precision of the result of an operation on values of precisions pa, pb (Boost's
// frontend guards every operation with the largest operand precision).
mpfr_prec_t result_prec(mpfr_prec_t pa, mpfr_prec_t pb) { return guarded_prec(std::max(digits_of(pa), digits_of(pb))); }

}  // namespace

BOOST_AUTO_TEST_CASE(differential_against_mpfr) {
  const mp_precision_scope scope(113);
  constexpr int n = 40;
  std::vector<mpfr> a(n);
  std::vector<twin> t(n);
  for (int i = 0; i < n; ++i) {
    a[i] = random_double();
    t[i].set(a[i].backend().data());
  }
  struct trace_entry {
    int step, op, i, j, k;
  };
  std::vector<trace_entry> trace;  // the steps so far, for the message of a failure
  const auto history = [&](int value) {
    std::string h;
    for (const trace_entry& e : trace)
      if (e.i == value || e.j == value || e.k == value)
        h += " [" + std::to_string(e.step) + ": op " + std::to_string(e.op) + " i" + std::to_string(e.i) + " j" +
             std::to_string(e.j) + " k" + std::to_string(e.k) + "]";
    return h.size() > 600 ? h.substr(h.size() - 600) : h;
  };
  const auto check = [&](int step, const char* what) {
    for (int i = 0; i < n; ++i)
      if (!same(a[i].backend().data(), t[i].v))
        BOOST_FAIL("step " << step << " (" << what << "), value " << i << ": appell " << show(a[i].backend().data())
                           << " vs MPFR " << show(t[i].v) << "; steps on it:" << history(i));
  };
  twin e;  // expected result
  long checked = 0;
  for (int step = 0; step < 200000; ++step) {
    const int i = uniform(0, n - 1), j = uniform(0, n - 1), k = uniform(0, n - 1);
    const unsigned bits_before = mp_precision_bits();
    const int op = uniform(0, 23);
    trace.push_back({step, op, i, j, k});
    const char* what = "";
    const mpfr_prec_t pr = result_prec(mpfr_get_prec(t[j].v), mpfr_get_prec(t[k].v));
    const bool default_operands =
        mpfr_get_prec(t[j].v) == static_cast<mpfr_prec_t>(bits_before) && mpfr_get_prec(t[k].v) == static_cast<mpfr_prec_t>(bits_before);
    const auto binary = [&](auto f, auto op_appell) {
      mpfr_set_prec(e.v, pr);
      f(e.v, t[j].v, t[k].v);
      a[i] = op_appell(a[j], a[k]);
      t[i].set(e.v);
      if (default_operands) BOOST_TEST_REQUIRE(mpfr_get_prec(a[i].backend().data()) == static_cast<mpfr_prec_t>(bits_before));
    };
    const auto unary = [&](int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), auto op_appell) {
      mpfr_set_prec(e.v, guarded_prec(digits_of(mpfr_get_prec(t[j].v))));
      f(e.v, t[j].v, MPFR_RNDN);
      a[i] = op_appell(a[j]);
      t[i].set(e.v);
    };
    switch (op) {
      case 0: what = "+"; binary([](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y) { mpfr_add(r, x, y, MPFR_RNDN); }, [](const mpfr& x, const mpfr& y) { return x + y; }); break;
      case 1: what = "-"; binary([](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y) { mpfr_sub(r, x, y, MPFR_RNDN); }, [](const mpfr& x, const mpfr& y) { return x - y; }); break;
      case 2: what = "*"; binary([](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y) { mpfr_mul(r, x, y, MPFR_RNDN); }, [](const mpfr& x, const mpfr& y) { return x * y; }); break;
      case 3: what = "/"; binary([](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y) { mpfr_div(r, x, y, MPFR_RNDN); }, [](const mpfr& x, const mpfr& y) { return x / y; }); break;
      case 4: what = "atan2"; binary([](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y) { mpfr_atan2(r, x, y, MPFR_RNDN); }, [](const mpfr& x, const mpfr& y) { return atan2(x, y); }); break;
      case 5: {  // in place: at the value's own precision unless the guard asks for another
        what = "+=";
        const unsigned g = guard_digits(std::max(digits_of(mpfr_get_prec(t[i].v)), digits_of(mpfr_get_prec(t[k].v))));
        mpfr_set_prec(e.v, g == digits_of(mpfr_get_prec(t[i].v)) ? mpfr_get_prec(t[i].v) : guarded_prec(g));
        mpfr_add(e.v, t[i].v, t[k].v, MPFR_RNDN);
        a[i] += a[k];
        t[i].set(e.v);
        break;
      }
      case 6: {
        what = "*= (aliased)";
        const unsigned g = guard_digits(digits_of(mpfr_get_prec(t[i].v)));  // as +=, with one operand
        mpfr_set_prec(e.v, g == digits_of(mpfr_get_prec(t[i].v)) ? mpfr_get_prec(t[i].v) : guarded_prec(g));
        mpfr_sqr(e.v, t[i].v, MPFR_RNDN);
        a[i] *= a[i];
        t[i].set(e.v);
        break;
      }
      case 7: {
        what = "* unsigned long";
        const unsigned long u = static_cast<unsigned long>(uniform(0, 1000000));
        mpfr_set_prec(e.v, guarded_prec(digits_of(mpfr_get_prec(t[j].v))));
        mpfr_mul_ui(e.v, t[j].v, u, MPFR_RNDN);
        a[i] = a[j] * u;
        t[i].set(e.v);
        break;
      }
      case 8: {
        what = "long -";
        const long l = uniform(-1000000, 1000000);
        mpfr_set_prec(e.v, guarded_prec(digits_of(mpfr_get_prec(t[j].v))));
        mpfr_si_sub(e.v, l, t[j].v, MPFR_RNDN);
        a[i] = l - a[j];
        t[i].set(e.v);
        break;
      }
      case 9: {  // a double operand: converted at the result's precision, then one rounding
        what = "/ double";
        const double d = random_double();
        const mpfr_prec_t p = guarded_prec(digits_of(mpfr_get_prec(t[j].v)));
        twin dv;
        mpfr_set_prec(dv.v, p);
        mpfr_set_d(dv.v, d, MPFR_RNDN);
        mpfr_set_prec(e.v, p);
        mpfr_div(e.v, t[j].v, dv.v, MPFR_RNDN);
        a[i] = a[j] / d;
        t[i].set(e.v);
        break;
      }
      case 10: what = "sqrt"; unary(mpfr_sqrt, [](const mpfr& x) { return sqrt(x); }); break;
      case 11: what = "exp"; unary(mpfr_exp, [](const mpfr& x) { return exp(x); }); break;
      case 12: what = "atan"; unary(mpfr_atan, [](const mpfr& x) { return atan(x); }); break;
      case 13: what = "sin"; unary(mpfr_sin, [](const mpfr& x) { return sin(x); }); break;
      case 14: what = "cos"; unary(mpfr_cos, [](const mpfr& x) { return cos(x); }); break;
      case 15: what = "abs"; unary(mpfr_abs, [](const mpfr& x) { return abs(x); }); break;
      case 16: {  // copy construction / copy assignment: the source's precision
        what = "copy";
        if (uniform(0, 1)) {
          mpfr c(a[j]);
          a[i] = c;
        } else {
          a[i] = a[j];
        }
        t[i].set(t[j].v);
        break;
      }
      case 17: {  // move construction and assignment, then the value moved from is used again
        what = "move";
        if (i == j) break;
        mpfr m(std::move(a[j]));  // a[j]: +0, its precision kept
        BOOST_TEST_REQUIRE(mpfr_zero_p(a[j].backend().data()));
        BOOST_TEST_REQUIRE(!mpfr_signbit(a[j].backend().data()));
        BOOST_TEST_REQUIRE(mpfr_get_prec(a[j].backend().data()) == mpfr_get_prec(t[j].v));
        a[i] = std::move(m);
        t[i].set(t[j].v);
        mpfr_set_zero(t[j].v, 1);
        a[j] += 1;  // in place at a[j]'s precision: exactly 1
        mpfr_set_ui(t[j].v, 1, MPFR_RNDN);
        break;
      }
      case 18: {
        what = "swap";
        a[i].backend().swap(a[j].backend());
        twin s;
        s.set(t[i].v);
        t[i].set(t[j].v);
        t[j].set(s.v);
        break;
      }
      case 19: {
        what = "round_prec";
        const mpfr_prec_t p = random_prec();
        a[i].backend().round_prec(p);
        mpfr_prec_round(t[i].v, p, MPFR_RNDN);
        break;
      }
      case 20: {
        what = "set_prec";
        const mpfr_prec_t p = random_prec();
        a[i].backend().set_prec(p);
        mpfr_set_prec(t[i].v, p);  // NaN
        break;
      }
      case 21: {  // a built-in number: the value's precision is kept
        what = "= double";
        const double d = random_double();
        a[i] = d;
        mpfr_set_d(t[i].v, d, MPFR_RNDN);
        break;
      }
      case 22: {
        what = "default precision";
        set_mp_precision_bits(static_cast<unsigned>(random_prec()));
        mpfr fresh;
        BOOST_TEST_REQUIRE(mpfr_get_prec(fresh.backend().data()) == static_cast<mpfr_prec_t>(mp_precision_bits()));
        BOOST_TEST_REQUIRE(mpfr_zero_p(fresh.backend().data()));
        break;
      }
      case 23: {
        what = "fma";
        const mpfr_prec_t p = mp_precision_bits();
        mpfr r;
        eval_multiply_add(r.backend(), a[j].backend(), a[k].backend(), a[i].backend());
        mpfr_set_prec(e.v, p);
        mpfr_fma(e.v, t[j].v, t[k].v, t[i].v, MPFR_RNDN);
        a[i] = std::move(r);
        t[i].set(e.v);
        break;
      }
    }
    if (op != 22) BOOST_TEST_REQUIRE(mp_precision_bits() == bits_before);
    check(step, what);
    // Keep the magnitudes moderate (repeated squaring would reach exponents where sin needs
    // pi to millions of bits): a value far from 1 is set anew, on both sides.
    const mpfr_srcptr v = a[i].backend().data();
    if (mpfr_regular_p(v) && (mpfr_get_exp(v) > 80 || mpfr_get_exp(v) < -80)) {
      const double d = random_double();
      a[i] = d;
      mpfr_set_d(t[i].v, d, MPFR_RNDN);
    }
    ++checked;
  }
  BOOST_TEST_MESSAGE("differential run: " << checked << " steps, every value equal to its MPFR twin bit for bit");
}

BOOST_AUTO_TEST_CASE(precision_conversions_are_boosts) {
  // mp::precision_default's constexpr conversions are Boost's (its guard speaks in digits).
  for (unsigned long n = 0; n <= 5000; ++n) {
    BOOST_TEST_REQUIRE(mp::precision_default::digits10_of(n) == boost::multiprecision::detail::digits2_2_10(n));
    BOOST_TEST_REQUIRE(static_cast<unsigned long>(mp::precision_default::bits_of(n)) ==
                       boost::multiprecision::detail::digits10_2_2(n));
  }
}

BOOST_AUTO_TEST_CASE(exact_bits) {
  for (unsigned bits = 2; bits <= 600; ++bits) {
    const mp_precision_scope scope(bits);
    const mpfr x(1), y = x / 3;
    BOOST_TEST_REQUIRE(mpfr_get_prec(x.backend().data()) == static_cast<mpfr_prec_t>(bits));
    BOOST_TEST_REQUIRE(mpfr_get_prec(y.backend().data()) == static_cast<mpfr_prec_t>(bits));
    BOOST_TEST_REQUIRE(mpfr_precision_bits() == bits);
    BOOST_TEST_REQUIRE(Eigen::NumTraits<mpfr>::digits() == static_cast<int>(bits));
  }
}

namespace {
long gmp_allocations = 0;
void* (*default_alloc)(std::size_t) = nullptr;
void* (*default_realloc)(void*, std::size_t, std::size_t) = nullptr;
void (*default_free)(void*, std::size_t) = nullptr;
void* counting_alloc(std::size_t n) {
  ++gmp_allocations;
  return default_alloc(n);
}
void* counting_realloc(void* p, std::size_t a, std::size_t b) {
  ++gmp_allocations;
  return default_realloc(p, a, b);
}
struct counting_scope {
  counting_scope() {
    mp_get_memory_functions(&default_alloc, &default_realloc, &default_free);
    mp_set_memory_functions(counting_alloc, counting_realloc, default_free);
    gmp_allocations = 0;
  }
  ~counting_scope() { mp_set_memory_functions(default_alloc, default_realloc, default_free); }
};
// Arithmetic of the kind a Taylor step does, on values of the default precision.
mpfr work(const std::vector<mpfr>& v) {
  mpfr s = 0;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    const mpfr p = v[i] * v[i + 1] - v[i] / 7 + sqrt(abs(v[i]));
    mpfr q(p);
    mpfr r(std::move(q));
    s += r;
    s = s * 2u - 1;
  }
  return s;
}
}  // namespace

BOOST_AUTO_TEST_CASE(no_heap_up_to_256_bits) {
  for (const unsigned bits : {2u, 53u, 113u, 128u, 200u, 256u}) {
    const mp_precision_scope scope(bits);
    std::vector<mpfr> v;
    for (int i = 1; i <= 20; ++i) v.emplace_back(1.0 / i);
    (void)work(v);  // MPFR's own caches, if any, filled before counting
    counting_scope counting;
    const mpfr s = work(v);
    BOOST_TEST(gmp_allocations == 0, bits << " bits: " << gmp_allocations << " allocations");
    BOOST_TEST(mpfr_number_p(s.backend().data()));
  }
  for (const unsigned bits : {257u, 320u}) {  // above the limit: one block per value
    const mp_precision_scope scope(bits);
    counting_scope counting;
    { const mpfr a(1.5), b(a); }
    BOOST_TEST(gmp_allocations == 2);
  }
}

BOOST_AUTO_TEST_CASE(values_survive_bitwise_relocation) {
  for (const unsigned bits : {64u, 256u, 257u, 1000u}) {
    const mp_precision_scope scope(bits);
    const mpfr third = mpfr(1) / 3;
    // Relocated as Eigen's realloc path does: bytes moved, no constructor or destructor.
    alignas(mpfr) unsigned char from[sizeof(mpfr)], to[sizeof(mpfr)];
    new (from) mpfr(third);
    std::memcpy(to, from, sizeof(mpfr));
    std::memset(from, 0xA5, sizeof(mpfr));  // the old place overwritten
    mpfr& moved = *std::launder(reinterpret_cast<mpfr*>(to));
    BOOST_TEST(moved == third);
    moved = moved * 3;
    BOOST_TEST(moved == mpfr(1) / 3 * 3);
    moved.~mpfr();
    // Eigen's conservativeResize of a vector of values.
    Eigen::Matrix<mpfr, Eigen::Dynamic, 1> x(3);
    for (int i = 0; i < 3; ++i) x(i) = mpfr(i + 1) / 7;
    x.conservativeResize(300);
    for (int i = 0; i < 3; ++i) BOOST_TEST(x(i) == mpfr(i + 1) / 7);
    x.conservativeResize(2);
    BOOST_TEST(x(1) == mpfr(2) / 7);
  }
}

BOOST_AUTO_TEST_CASE(text_conversions_limits) {
  const mp_precision_scope scope(113);
  mpfr x;
  x.backend() = "0.1";
  mpfr_value ref(113);
  mpfr_set_str(ref, "0.1", 10, MPFR_RNDN);
  BOOST_TEST(mpfr_equal_p(x.backend().data(), ref) != 0);
  const mpfr before = x;
  BOOST_CHECK_THROW(x.backend() = "0.1x", std::runtime_error);
  BOOST_TEST(x == before);  // unchanged by the failure
  const mpfr y(x.str(0, std::ios_base::fmtflags{}));
  BOOST_TEST(y == x);  // str(0) round-trips
  BOOST_TEST(static_cast<double>(x) == 0.1);
  BOOST_TEST(static_cast<long>(mpfr(-7.9)) == -7);
  using L = std::numeric_limits<mpfr>;
  BOOST_TEST(mpfr_cmp_ui_2exp(L::epsilon().backend().data(), 1, -112) == 0);
  BOOST_TEST(mpfr_inf_p(L::infinity().backend().data()) != 0);
  BOOST_TEST(mpfr_nan_p(L::quiet_NaN().backend().data()) != 0);
  BOOST_TEST(mpfr_number_p((L::max)().backend().data()) != 0);
  BOOST_TEST(Eigen::NumTraits<mpfr>::digits() == 113);
}
