// Certified reference values (studies/certify.hpp): compiled once, for interval, mpfi and arb.
#include "appell/studies/certify.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <mpfr.h>
#include <optional>
#include <string>

#include "appell/errors.hpp"
#include "appell/scalar/standard_scalars.hpp"
#include "appell/io/amplification.hpp"
#include "appell/io/scene_fields.hpp"
#include "appell/scalar/x87_bounds.hpp"

namespace appell {

namespace {

/// An MPFR number of precision p (NaN): appell's `mpfr`, whose significand lives inside the value
/// up to 256 bits, so that describing a quantity (a dozen of these) makes no heap block.
mpfr mp_number(mpfr_prec_t p) {
  mpfr r;
  r.backend().set_prec(p);
  return r;
}
mpfr_ptr ptr(mpfr& x) { return x.backend().data(); }

/// A 64-bit number as MPFR prints it (mpfr_to_decimal), from a long double of 64 bits.
std::string decimal_of_64_bits(long double x, int digits, mpfr_rnd_t rnd) {
  mpfr v = mp_number(64);
  mpfr_set_ld(ptr(v), x, MPFR_RNDN);  // exact: 64 bits
  return mpfr_to_decimal(ptr(v), digits, rnd);
}

/// The description of a quantity enclosed in [lo, hi] (MPFR numbers holding the enclosure's bounds
/// exactly): the bounds rounded outward to decimal, the double nearest the enclosure, the error
/// bound of that double and the tolerance for a double engine (x53: appell's own interval<double>
/// enclosure, null when there is none). `double_bounds`: the interval<double> whose bounds lo and
/// hi hold exactly; its 64-bit error bounds the x87 unit rounds as MPFR does, without MPFR's calls.
certified_quantity describe_bounds(const std::string& name, mpfr_srcptr lo, mpfr_srcptr hi, const interval* x53, double scale,
                         double amplification, const interval* double_bounds = nullptr) {
  certified_quantity q;
  q.name = name;
  q.lower = mpfr_to_decimal(lo, roundtrip_digits(static_cast<unsigned>(mpfr_get_prec(lo))), MPFR_RNDD);
  q.upper = mpfr_to_decimal(hi, roundtrip_digits(static_cast<unsigned>(mpfr_get_prec(hi))), MPFR_RNDU);
  // the bounds rounded to nearest doubles: themselves where they are doubles
  const double dlo = double_bounds ? double_bounds->lower() : mpfr_get_d(lo, MPFR_RNDN),
               dhi = double_bounds ? double_bounds->upper() : mpfr_get_d(hi, MPFR_RNDN);
  double d = dlo;
  q.decided = dlo == dhi;  // round-to-nearest is monotone: every point of [lo, hi] rounds to it
  if (!q.decided) {
    mpfr mid = mp_number(std::max(mpfr_get_prec(lo), mpfr_get_prec(hi)) + 2);
    mpfr_add(ptr(mid), lo, hi, MPFR_RNDN);  // exact at this precision
    mpfr_div_2ui(ptr(mid), ptr(mid), 1, MPFR_RNDN);
    d = mpfr_get_d(ptr(mid), MPFR_RNDN);
  }
  char buffer[64];
  const auto printed = std::to_chars(buffer, buffer + sizeof buffer, d, std::chars_format::general, 17);  // "%.17g"
  q.nearest_double.assign(buffer, printed.ptr);
  // The suggested tolerance on |engine - exact| for a double-precision engine,
  // from the problem's conditioning: 16 x error_amplification x 2^-53 x the
  // largest |component| of the same result (a vector's components are computed
  // together: a component that is 0, or small, carries the rounding of the
  // others, and of terms that cancel in another engine's formulation), and at
  // least 16 times the width of appell's own interval<double> enclosure of it.
  const double w = x53 ? std::max(boost::numeric::width(*x53), std::ldexp(std::max(amplification, 1.0) * scale, -53)) : 0;
  if (double_bounds && x87_bounds_available()) {
    // The same numbers as the MPFR path below, each one upward rounding to 64 bits (x87_bounds.hpp).
    const error_bounds_64 b = x87_error_bounds(d, dlo, dhi, w);  // dlo, dhi exact: lo and hi are doubles
    if (b.has_relative) q.rel_error_bound = decimal_of_64_bits(b.relative, 3, MPFR_RNDU);
    q.tolerance = x53 ? decimal_of_64_bits(b.tolerance, 3, MPFR_RNDU) : "inf";
    return q;
  }
  // |d - exact| <= max(d - lo, hi - d), rounded up; relative to min |x| over the enclosure.
  mpfr e1 = mp_number(64), e2 = mp_number(64), e = mp_number(64), dv = mp_number(53);
  mpfr_set_d(ptr(dv), d, MPFR_RNDN);
  mpfr_sub(ptr(e1), ptr(dv), lo, MPFR_RNDU);
  mpfr_sub(ptr(e2), hi, ptr(dv), MPFR_RNDU);
  mpfr_max(ptr(e), ptr(e1), ptr(e2), MPFR_RNDU);
  if (mpfr_sgn(lo) > 0 || mpfr_sgn(hi) < 0) {
    mpfr m = mp_number(64);
    if (mpfr_sgn(lo) > 0) mpfr_set(ptr(m), lo, MPFR_RNDD);
    else mpfr_neg(ptr(m), hi, MPFR_RNDD);
    mpfr_div(ptr(e), ptr(e), ptr(m), MPFR_RNDU);
    q.rel_error_bound = mpfr_to_decimal(ptr(e), 3, MPFR_RNDU);
  }
  if (x53) {
    mpfr tol = mp_number(64);
    mpfr_set_d(ptr(tol), w, MPFR_RNDU);
    mpfr_mul_ui(ptr(tol), ptr(tol), 16, MPFR_RNDU);
    q.tolerance = mpfr_to_decimal(ptr(tol), 3, MPFR_RNDU);
  } else {
    q.tolerance = "inf";  // interval<double> cannot certify this state: no double engine can be held to it
  }
  return q;
}

template <Scalar T>
certified_quantity describe(const std::string& name, const T& x, const interval* x53, double scale, double amplification) {
  if constexpr (std::is_same_v<T, interval>) {  // the bounds are doubles: exact in 53 bits
    mpfr lo = mp_number(53), hi = mp_number(53);
    mpfr_set_d(ptr(lo), x.lower(), MPFR_RNDN);
    mpfr_set_d(ptr(hi), x.upper(), MPFR_RNDN);
    return describe_bounds(name, ptr(lo), ptr(hi), x53, scale, amplification, &x);
  } else {
    mpfr_value lo, hi;
    scalar_traits<T>::to_mpfr(x, lo, hi);
    return describe_bounds(name, lo, hi, x53, scale, amplification);
  }
}

/// The largest |bound| of x, each bound rounded to the nearest double.
template <Scalar T>
double largest_bound(const T& x) {
  if constexpr (std::is_same_v<T, interval>) {
    return std::max(std::abs(x.lower()), std::abs(x.upper()));
  } else {
    mpfr_value lo, hi;
    scalar_traits<T>::to_mpfr(x, lo, hi);
    return std::max(std::abs(mpfr_get_d(lo, MPFR_RNDN)), std::abs(mpfr_get_d(hi, MPFR_RNDN)));
  }
}

template <Scalar T>
void certify_in(const scene_input& scene, certified_state& r) {
  const evaluation<T> e = evaluate<T>(scene, with_checks::no);  // the dataset prints no check
  // appell's own interval<double> enclosure (the tolerance's floor) and the amplification from
  // it: in interval, e itself (one evaluation a state, not three)
  std::optional<evaluation<interval>> own53;  // in mpfi and arb only
  const evaluation<interval>* e53 = nullptr;
  if constexpr (std::is_same_v<T, interval>) {
    e53 = &e;
  } else {
    try {
      own53 = evaluate<interval>(scene, with_checks::no);
      e53 = &*own53;
    } catch (const std::exception&) {
    }
  }
  r.amplification = e53 ? error_amplification(scene, *e53) : error_amplification(scene);
  for (const bool derived : {false, true}) {
    const auto& group = derived ? e.derived : e.results;
    for (std::size_t i = 0; i < group.size(); ++i) {
      const auto& res = group[i];
      double scale = 0;  // the largest |component| of this result
      for (const T& v : res.values) scale = std::max(scale, largest_bound(v));
      for (std::size_t j = 0; j < res.values.size(); ++j) {
        const std::string name = res.is_vector ? res.name + "[" + std::to_string(j) + "]" : res.name;
        const interval* x53 = e53 ? &(derived ? e53->derived : e53->results)[i].values[j] : nullptr;
        r.quantities.push_back(describe(name, res.values[j], x53, scale, r.amplification));
        r.quantities.back().derived = derived;
      }
    }
  }
}

}  // namespace

certified_state certify(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits) {
  certified_state r;
  if (scalar == "interval") {
    certify_in<interval>(scene, r);
  } else if (scalar == "mpfi") {
    const mp_precision_scope scope(bits.value_or(256));
    certify_in<mpfi>(scene, r);
  } else if (scalar == "arb") {
    if constexpr (scalar_built<arb>) {
      const mp_precision_scope scope(bits.value_or(256));
      certify_in<arb>(scene, r);
    } else {
      throw input_error(left_out_scalar_message("--scalar", "arb"));
    }
  } else {
    throw input_error("--scalar: reference values are certified: interval, mpfi or arb, got '" + scalar + "'");
  }
  return r;
}

state_certificate certify_state(json_value scene, const std::string& scalar, std::optional<unsigned> bits,
                                bool binary64_inputs) {
  state_certificate out;
  try {
    // A front end's scene (a URDF robot) as the scene it reads as, so that the other file's
    // numbers are rounded too.
    if (const model_entry* model = scene_model(scene); binary64_inputs && model && model->read_as_text) {
      scene = parse_json(model->read_as_text(scene));
      to_binary64(scene, "");
    }
    out.state = certify(read_scene(scene), scalar, bits);
    out.certified = true;
  } catch (const input_error& e) {
    out.reason = std::string("refused: ") + e.what();
  } catch (const certification_error& e) {
    out.reason = std::string("cannot certify: ") + e.what();
  } catch (const domain_error& e) {
    out.reason = std::string("cannot certify: ") + e.what();
  }
  return out;
}

}  // namespace appell
