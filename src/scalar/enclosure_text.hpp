// src/scalar/enclosure_text.hpp -- the text of an enclosure [lo, hi] given by two MPFR numbers, as
// the str() of the interval backends (mpfi_backend.cpp, arb_backend.cpp) writes it: with
// digits <= 0 every bound exactly ("x" where they agree, else "{lo,hi}", which their operator=
// reads back); with digits > 0 that many significant digits in scientific notation, the lower
// bound rounded down and the upper up, so that the text still encloses the value.
#pragma once

#include <mpfr.h>

#include <boost/multiprecision/mpfr.hpp>
#include <ios>
#include <new>
#include <string>

namespace appell::mp {

inline std::string enclosure_text(mpfr_srcptr lo, mpfr_srcptr hi, std::streamsize digits, std::ios_base::fmtflags f) {
  if (digits <= 0) {  // every bound exactly, as Boost's mpfr backend writes it
    const auto exact = [&](mpfr_srcptr v) {
      boost::multiprecision::backends::mpfr_float_backend<0> b;
      mpfr_set_prec(b.data(), mpfr_get_prec(v));
      mpfr_set(b.data(), v, MPFR_RNDN);  // exact: the same precision
      return b.str(0, f);
    };
    if (mpfr_equal_p(lo, hi)) return exact(lo);
    return "{" + exact(lo) + "," + exact(hi) + "}";
  }
  const auto bound = [&](mpfr_srcptr v, const char* format) {
    char* out = nullptr;
    if (mpfr_asprintf(&out, format, static_cast<int>(digits - 1), v) < 0) throw std::bad_alloc();
    std::string r(out);
    mpfr_free_str(out);
    return r;
  };
  const std::string l = bound(lo, "%.*RDe"), h = bound(hi, "%.*RUe");
  return l == h ? l : "{" + l + "," + h + "}";
}

}  // namespace appell::mp
