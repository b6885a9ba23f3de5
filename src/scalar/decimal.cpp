// Exact bridges between the scalars and MPFR, and correctly rounded inputs.
// IEEE formats are emulated in MPFR by restricting the exponent range and
// calling mpfr_subnormalize (MPFR manual, "Exception Related Functions"), so a
// value rounded here is exactly representable in the target format.
#define MPFR_WANT_FLOAT128 1
#include <mpfr.h>
#include <mpfi.h>
#include <gmp.h>

#include "appell/scalar/decimal.hpp"
#include "appell/scalar/rational.hpp"
#include "stack_limbs.hpp"

#include <boost/multiprecision/detail/digits.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <cmath>
#include <initializer_list>

namespace appell {

// --- mp precision ---------------------------------------------------------
unsigned set_mp_precision_bits(unsigned bits) {
  if (bits < 2) throw parse_error("precision must be at least 2 bits");
  mp::mpfr_backend::default_bits(bits);
  mp::mpfi_backend::default_bits(bits);
  mp::arb_backend::default_bits(bits);
  return bits;
}

// The bits of new mpfr and mpfi values: exactly those asked for (appell's backends).
unsigned mp_precision_bits() { return mp::mpfi_backend::default_bits(); }

unsigned mpfr_precision_bits() { return mp::mpfr_backend::default_bits(); }

// Saves and restores both settings as they were.
mp_precision_scope::mp_precision_scope(unsigned bits)
    : saved_mpfr_bits_(mp::mpfr_backend::default_bits()),
      saved_mpfi_bits_(mp::mpfi_backend::default_bits()),
      saved_arb_bits_(mp::arb_backend::default_bits()),
      bits_(set_mp_precision_bits(bits)) {}

mp_precision_scope::~mp_precision_scope() {
  mp::mpfr_backend::default_bits(saved_mpfr_bits_);
  mp::mpfi_backend::default_bits(saved_mpfi_bits_);
  mp::arb_backend::default_bits(saved_arb_bits_);
}

namespace {

struct ieee_format {
  mpfr_prec_t prec;
  mpfr_exp_t emin, emax;  // MPFR convention: x = m 2^e, 1/2 <= m < 1
};
constexpr ieee_format binary64{53, -1073, 1024};
constexpr ieee_format x87_extended{64, -16444, 16384};
constexpr ieee_format binary128{113, -16493, 16384};

// Restricts MPFR's exponent range for a scope (thread-local in MPFR).
class exponent_range {
 public:
  explicit exponent_range(const ieee_format& f) : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
    mpfr_set_emin(f.emin);
    mpfr_set_emax(f.emax);
  }
  ~exponent_range() {
    mpfr_set_emin(emin_);
    mpfr_set_emax(emax_);
  }

 private:
  mpfr_exp_t emin_, emax_;
};

// Rounds into `out` (precision f.prec) so that out is a number of format f.
void produce_in(const ieee_format& f, const mpfr_producer& p, mpfr_rnd_t rnd, mpfr_value& out) {
  mpfr_set_prec(out, f.prec);
  exponent_range range(f);
  int t = p(out, rnd);
  t = mpfr_check_range(out, t, rnd);
  mpfr_subnormalize(out, t, rnd);
}

// Rounds an arbitrary MPFR value into format f.
void round_in(const ieee_format& f, mpfr_srcptr v, mpfr_rnd_t rnd, mpfr_value& out) {
  produce_in(f, [v](mpfr_ptr o, mpfr_rnd_t r) { return mpfr_set(o, v, r); }, rnd, out);
}

}  // namespace

// --- exact conversions to MPFR ---------------------------------------------
void to_mpfr_exact(double x, mpfr_value& out) {
  mpfr_set_prec(out, 53);
  mpfr_set_d(out, x, MPFR_RNDN);
}
void to_mpfr_exact(long double x, mpfr_value& out) {
  mpfr_set_prec(out, 64);
  mpfr_set_ld(out, x, MPFR_RNDN);
}
void to_mpfr_exact(const dd& x, mpfr_value& out) {
  const double hi = x.x[0], lo = x.x[1];
  mpfr_prec_t prec = 53;
  if (lo != 0 && std::isfinite(hi) && hi != 0) {
    int ehi, elo;
    std::frexp(hi, &ehi);
    std::frexp(lo, &elo);
    prec = std::max<mpfr_prec_t>(53, (ehi - elo) + 53 + 1);
  } else if (hi == 0) {
    prec = 53;
  }
  mpfr_set_prec(out, prec);
  mpfr_set_d(out, hi, MPFR_RNDN);
  if (hi == 0) mpfr_set_d(out, lo, MPFR_RNDN);
  else mpfr_add_d(out, out, lo, MPFR_RNDN);  // exact at this precision
}
void to_mpfr_exact(const float128& x, mpfr_value& out) {
  mpfr_set_prec(out, 113);
  mpfr_set_float128(out, x.backend().value(), MPFR_RNDN);
}
void to_mpfr_exact(const mpfr& x, mpfr_value& out) {
  mpfr_set_prec(out, mpfr_get_prec(x.backend().data()));
  mpfr_set(out, x.backend().data(), MPFR_RNDN);
}

// --- rounding from MPFR into each format -----------------------------------
double round_to_double(mpfr_srcptr v, mpfr_rnd_t rnd) {
  mpfr_value r;
  round_in(binary64, v, rnd, r);
  return mpfr_get_d(r, rnd);
}
long double round_to_long_double(mpfr_srcptr v, mpfr_rnd_t rnd) {
  mpfr_value r;
  round_in(x87_extended, v, rnd, r);
  return mpfr_get_ld(r, rnd);
}
float128 round_to_float128(mpfr_srcptr v, mpfr_rnd_t rnd) {
  mpfr_value r;
  round_in(binary128, v, rnd, r);
  return float128(mpfr_get_float128(r, rnd));
}
dd round_to_dd(mpfr_srcptr v, mpfr_rnd_t /*rnd: dd has round-to-nearest only*/) {
  return produce_dd([v](mpfr_ptr o, mpfr_rnd_t r) { return mpfr_set(o, v, r); });
}
mpfr round_to_mpfr(mpfr_srcptr v, mpfr_rnd_t rnd) {
  mpfr r;
  mpfr_set(r.backend().data(), v, rnd);
  return r;
}

// --- a decimal literal into a double, exactly, without MPFR ------------------------------------
//
// std::from_chars rounds to nearest (C++17 [charconv.from.chars]); the exact comparison of the
// decimal D 10^k with that double m 2^e, by integers on limbs on the stack (GMP's mpn layer), says
// whether it is exact and on which side the decimal lies, which gives the directed roundings. The
// results are MPFR's (tests/decimal.cpp compares them on random literals). Outside the normal range
// of doubles, for more than 40 significant digits or beyond 10^+-300, MPFR's path is taken.
namespace {

// The producer of a decimal literal (checked), a type of its own so that produce_double can see it
// and take its exact path (decimal_to_double) rather than MPFR's.
struct decimal_text_producer {
  std::string text;
  int operator()(mpfr_ptr out, mpfr_rnd_t rnd) const {
    char* end = nullptr;
    return mpfr_strtofr(out, text.c_str(), &end, 10, rnd);
  }
};

// The producer of p/q, a type of its own for the same reason (rational_to_double).
struct rational_value_producer {
  long p, q;
  int operator()(mpfr_ptr out, mpfr_rnd_t rnd) const {
    mpq_t r;
    mpq_init(r);
    mpq_set_si(r, p, 1);
    mpq_t d;
    mpq_init(d);
    mpq_set_si(d, q, 1);
    mpq_div(r, r, d);
    int t = mpfr_set_q(out, r, rnd);
    mpq_clear(d);
    mpq_clear(r);
    return t;
  }
};

// p/q (q != 0) into a double in direction rnd, exactly: the quotient rounded to nearest, then the
// remainder p - q x, exact by one fma (the remainder of a correctly rounded quotient is a double),
// says on which side p/q lies. False beyond |p|, |q| <= 2^53 (MPFR's path then).
bool rational_to_double(long p, long q, mpfr_rnd_t rnd, double& out) {
  constexpr long limit = 1L << 53;
  if (p < -limit || p > limit || q < -limit || q > limit) return false;
  if (rnd != MPFR_RNDN && rnd != MPFR_RNDD && rnd != MPFR_RNDU && rnd != MPFR_RNDZ) return false;
  if (p == 0) {
    out = 0.0;  // MPFR's +0 for a zero rational
    return true;
  }
  const nearest_rounding nearest;  // the caller may be inside an upward_rounding scope
  const double a = static_cast<double>(p), b = static_cast<double>(q);
  const double x = a / b;
  const double r = std::fma(-x, b, a);  // p - q x, exact
  const int side = r == 0 ? 0 : (r > 0) == (b > 0) ? 1 : -1;  // sign of p/q - x
  double result = x;
  if (side > 0 && (rnd == MPFR_RNDU || (rnd == MPFR_RNDZ && x < 0)))
    result = std::nextafter(x, std::numeric_limits<double>::infinity());
  if (side < 0 && (rnd == MPFR_RNDD || (rnd == MPFR_RNDZ && x > 0)))
    result = std::nextafter(x, -std::numeric_limits<double>::infinity());
  out = result;
  return true;
}

using limb_number = detail::stack_limbs;

bool decimal_to_double(const std::string& text, mpfr_rnd_t rnd, double& out) {
  if (rnd != MPFR_RNDN && rnd != MPFR_RNDD && rnd != MPFR_RNDU && rnd != MPFR_RNDZ) return false;
  // the literal (already checked by is_decimal_literal): sign, significant digits, exponent
  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
  unsigned char digits[48];
  int count = 0;
  long exponent = 0;  // value = digits x 10^exponent
  bool after_point = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      after_point = true;
      continue;
    }
    const int digit = text[i] - '0';
    if (count == 0 && digit == 0) {  // a leading zero
      if (after_point) --exponent;
      continue;
    }
    if (count == 40) return false;
    digits[count++] = static_cast<unsigned char>(digit);
    if (after_point) --exponent;
  }
  if (i < text.size()) {
    long e10 = 0;
    const char* first = text.data() + i + 1;
    if (*first == '+') ++first;
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), e10);
    if (ec != std::errc() || end != text.data() + text.size()) return false;
    exponent += e10;
  }
  if (count == 0) {  // zero: MPFR's sign of zero
    out = negative ? -0.0 : 0.0;
    return true;
  }
  while (count > 1 && digits[count - 1] == 0) {  // trailing zeros into the exponent
    --count;
    ++exponent;
  }
  const long decade = exponent + count;  // 10^(decade - 1) <= |value| < 10^decade
  if (decade < -300 || decade > 300) return false;
  // the nearest double (from_chars may take a floating-point fast path: the caller may be inside
  // an upward_rounding scope)
  const nearest_rounding nearest;
  const char* first = text.data() + (text[0] == '+' ? 1 : 0);
  double x = 0;
  const auto [end, ec] = std::from_chars(first, text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return false;
  const double magnitude = std::fabs(x);
  if (!(magnitude >= std::numeric_limits<double>::min()) || magnitude == std::numeric_limits<double>::max()) return false;
  // |decimal| = D 10^exponent against |x| = m 2^e
  int e2 = 0;
  const auto m = static_cast<std::uint64_t>(std::ldexp(std::frexp(magnitude, &e2), 53));
  const long e = e2 - 53;
  limb_number lhs, rhs;  // lhs ~ D, rhs ~ m
  lhs.n = static_cast<mp_size_t>(mpn_set_str(lhs.d, digits, static_cast<std::size_t>(count), 10));
  rhs.d[0] = m;
  rhs.n = 1;
  if (exponent >= 0) lhs.mul_pow10(exponent);
  else rhs.mul_pow10(-exponent);
  if (e >= 0) rhs.shift_left(e);
  else lhs.shift_left(-e);
  const int c = lhs.compare(rhs);  // sign of |decimal| - |x|
  if (c == 0 || rnd == MPFR_RNDN) {
    out = x;
    return true;
  }
  const bool toward_larger_magnitude = (rnd == MPFR_RNDU && !negative) || (rnd == MPFR_RNDD && negative);
  double result = magnitude;
  if (c > 0 && toward_larger_magnitude) result = std::nextafter(magnitude, std::numeric_limits<double>::infinity());
  if (c < 0 && !toward_larger_magnitude) result = std::nextafter(magnitude, 0.0);
  out = negative ? -result : result;
  return true;
}

}  // namespace

// --- producers -------------------------------------------------------------
double produce_double(const mpfr_producer& f, mpfr_rnd_t rnd) {
  if (const auto* d = f.target<decimal_text_producer>()) {
    double x = 0;
    if (decimal_to_double(d->text, rnd, x)) return x;
  } else if (const auto* r = f.target<rational_value_producer>()) {
    double x = 0;
    if (rational_to_double(r->p, r->q, rnd, x)) return x;
  }
  mpfr_value r;
  produce_in(binary64, f, rnd, r);
  return mpfr_get_d(r, rnd);
}
long double produce_long_double(const mpfr_producer& f, mpfr_rnd_t rnd) {
  mpfr_value r;
  produce_in(x87_extended, f, rnd, r);
  return mpfr_get_ld(r, rnd);
}
float128 produce_float128(const mpfr_producer& f, mpfr_rnd_t rnd) {
  mpfr_value r;
  produce_in(binary128, f, rnd, r);
  return float128(mpfr_get_float128(r, rnd));
}
dd produce_dd(const mpfr_producer& f) {
  // hi = RN53(x); lo = RN53(x - hi) with x - hi computed from a 600-bit value
  // of x (exact subtraction at that precision).
  const double hi = produce_double(f, MPFR_RNDN);
  if (!std::isfinite(hi)) return dd(hi, 0.0);
  mpfr_value x(600);
  f(x, MPFR_RNDN);
  mpfr_sub_d(x, x, hi, MPFR_RNDN);
  const double lo = round_to_double(x, MPFR_RNDN);
  return dd(hi, lo);
}
mpfr produce_mpfr(const mpfr_producer& f, mpfr_rnd_t rnd) {
  mpfr r;
  f(r.backend().data(), rnd);
  return r;
}
namespace {
// The producer's number enclosed in I (mpfi, arb): its bounds at the mp precision, rounded outward.
template <class I>
I produce_enclosure(const mpfr_producer& f) {
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(mp_precision_bits());
  mpfr_value lo(prec), hi(prec);
  f(lo, MPFR_RNDD);
  f(hi, MPFR_RNDU);
  return scalar_traits<I>::from_mpfr_bounds(lo, hi);
}
}  // namespace
mpfi produce_mpfi(const mpfr_producer& f) { return produce_enclosure<mpfi>(f); }
arb produce_arb(const mpfr_producer& f) { return produce_enclosure<arb>(f); }

// --- decimal syntax and exact values ---------------------------------------
bool is_decimal_literal(std::string_view s) {
  std::size_t i = 0, n = s.size();
  auto digits = [&] {
    std::size_t start = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i - start;
  };
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t int_digits = digits(), frac_digits = 0;
  if (i < n && s[i] == '.') {
    ++i;
    frac_digits = digits();
  }
  if (int_digits + frac_digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exp_digits = digits();
    if (exp_digits == 0 || exp_digits > 7) return false;  // |exponent| < 10^7
  }
  return i == n;
}

mpfr_producer decimal_producer(std::string_view s) {
  if (!is_decimal_literal(s)) throw parse_error("'" + std::string(s) + "' is not a decimal number");
  return decimal_text_producer{std::string(s)};
}

mpfr_producer rational_producer(long p, long q) {
  if (q == 0) throw parse_error("rational with zero denominator");
  return rational_value_producer{p, q};
}

mpfr_producer pi_producer() {
  return [](mpfr_ptr out, mpfr_rnd_t rnd) { return mpfr_const_pi(out, rnd); };
}

void decimal_to_mpfr(std::string_view s, mpfr_value& out, mpfr_rnd_t rnd) {
  decimal_producer(s)(out, rnd);
}

namespace {
// The exact rational value of a decimal literal.
void decimal_to_mpq(std::string_view s, mpq_t out) {
  if (!is_decimal_literal(s)) throw parse_error("'" + std::string(s) + "' is not a decimal number");
  std::string digits;
  long exponent = 0;
  bool negative = false;
  std::size_t i = 0;
  if (s[i] == '+' || s[i] == '-') negative = s[i++] == '-';
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') continue;
    digits.push_back(s[i]);
  }
  std::size_t dot = s.find('.');
  std::size_t epos = s.find_first_of("eE");
  if (dot != std::string_view::npos) {
    std::size_t frac_end = epos == std::string_view::npos ? s.size() : epos;
    exponent -= static_cast<long>(frac_end - dot - 1);
  }
  if (epos != std::string_view::npos) exponent += std::stol(std::string(s.substr(epos + 1)));
  mpz_t num, pow10;
  mpz_init_set_str(num, digits.c_str(), 10);
  mpz_init(pow10);
  mpz_ui_pow_ui(pow10, 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  if (negative) mpz_neg(num, num);
  if (exponent >= 0) {
    mpz_mul(num, num, pow10);
    mpq_set_z(out, num);
  } else {
    mpq_set_num(out, num);
    mpq_set_den(out, pow10);
    mpq_canonicalize(out);
  }
  mpz_clear(num);
  mpz_clear(pow10);
}

// An mpq_t cleared on every way out, a parse error's throw included.
struct scoped_mpq {
  mpq_t v;
  scoped_mpq() { mpq_init(v); }
  ~scoped_mpq() { mpq_clear(v); }
  scoped_mpq(const scoped_mpq&) = delete;
  scoped_mpq& operator=(const scoped_mpq&) = delete;
};
}  // namespace

rational_q rational_from_decimal(const std::string& s) {
  scoped_mpq q;
  decimal_to_mpq(s, q.v);
  return rational_q(q.v);
}

namespace {
// The sign of c d, d one decimal literal, from c's sign and d's digits (no rational made).
int term_sign(long c, std::string_view d) {
  if (!is_decimal_literal(d)) throw parse_error("'" + std::string(d) + "' is not a decimal number");
  const int sign_c = c > 0 ? 1 : c < 0 ? -1 : 0;
  for (const char ch : d.substr(0, d.find_first_of("eE")))
    if (ch >= '1' && ch <= '9') return d[0] == '-' ? -sign_c : sign_c;
  return 0;
}
}  // namespace

int decimal_sign_of_polynomial(const std::vector<decimal_term>& terms) {
  if (terms.size() == 1 && terms[0].factors.size() == 1) return term_sign(terms[0].coefficient, terms[0].factors[0]);
  scoped_mpq sum, term, factor;
  for (const auto& t : terms) {
    mpq_set_si(term.v, t.coefficient, 1);
    for (const auto& f : t.factors) {
      decimal_to_mpq(f, factor.v);
      mpq_mul(term.v, term.v, factor.v);
    }
    mpq_add(sum.v, sum.v, term.v);
  }
  return mpq_sgn(sum.v);
}

int decimal_sign_of_sum(std::initializer_list<std::pair<int, std::string_view>> terms) {
  if (terms.size() == 1) return term_sign(terms.begin()->first, terms.begin()->second);
  std::vector<decimal_term> polynomial;
  for (const auto& [coefficient, text] : terms) polynomial.push_back({coefficient, {std::string(text)}});
  return decimal_sign_of_polynomial(polynomial);
}

// --- mpfi helpers ------------------------------------------------------------
namespace {
mpfr mpfr_at_prec(mpfr_prec_t prec) {
  mpfr r;
  r.backend().set_prec(prec);
  return r;
}
}  // namespace

mpfr mpfi_lower(const mpfi& x) {
  mpfr r = mpfr_at_prec(mpfi_get_prec(x.backend().data()));
  mpfi_get_left(r.backend().data(), x.backend().data());
  return r;
}
mpfr mpfi_upper(const mpfi& x) {
  mpfr r = mpfr_at_prec(mpfi_get_prec(x.backend().data()));
  mpfi_get_right(r.backend().data(), x.backend().data());
  return r;
}
mpfr mpfi_mid(const mpfi& x) {
  mpfr r = mpfr_at_prec(mpfi_get_prec(x.backend().data()));
  mpfi_mid(r.backend().data(), x.backend().data());
  return r;
}
mpfr mpfi_width(const mpfi& x) {
  mpfr r = mpfr_at_prec(mpfi_get_prec(x.backend().data()));
  mpfi_diam_abs(r.backend().data(), x.backend().data());
  return r;
}
mpfi mpfi_from_bounds(const mpfr& lo, const mpfr& hi) {
  return mpfi_from_mpfr_bounds(lo.backend().data(), hi.backend().data());
}
mpfi mpfi_from_mpfr_bounds(mpfr_srcptr lo, mpfr_srcptr hi) {
  mpfi r;
  mpfi_interv_fr(r.backend().data(), lo, hi);  // rounded outward to r's precision
  return r;
}

}  // namespace appell

namespace boost::multiprecision {
appell::rational_q sqrt(const appell::rational_q& x) {
  mpq_srcptr q = x.backend().data();
  if (mpq_sgn(q) < 0 || !mpz_perfect_square_p(mpq_numref(q)) || !mpz_perfect_square_p(mpq_denref(q)))
    throw std::domain_error("sqrt of a rational that is not a perfect square");
  mpz_t n, d;
  mpz_init(n);
  mpz_init(d);
  mpz_sqrt(n, mpq_numref(q));
  mpz_sqrt(d, mpq_denref(q));
  mpq_t r;
  mpq_init(r);
  mpq_set_num(r, n);
  mpq_set_den(r, d);
  mpq_canonicalize(r);
  appell::rational_q out(r);
  mpq_clear(r);
  mpz_clear(n);
  mpz_clear(d);
  return out;
}
}  // namespace boost::multiprecision
