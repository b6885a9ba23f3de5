// The affine set of appell enclose (include/appell/ode/enclose.hpp, detail::affine_set) against
// true points computed in MPFR at 332 bits: many random runs of steps x' = z + J* (x - xh), with
// J* a point inside the interval matrix J handed to the step and z a point inside the box zr,
// merges forced often (a small max_cols) on every other run.  After every step the set's box
// must hold x'.  In one dimension the box is the set itself, and the runs take the largest x'
// each step allows (x0 at the top of X0, J* at its bound on the side of x - xh, z at the top of
// zr): the true point then lies at (or, through the set's shift, within a rounding of) the
// set's upper bound, and a term left out misses.  Every other step the new centre is taken off
// zr's midpoint, by up to 512 times more on odd components, so that the set's shift is off 0,
// of mixed magnitudes, and must be carried by the next step's J.
// Included by tests/motion.cpp (interval<double>: the double mid-rad product) and
// tests/motion_mpfi.cpp (MPFI: the interval product); its bounds and holds() by the other motion
// tests.
#pragma once

#include <boost/multiprecision/mpfr.hpp>
#include <random>
#include <string>

#include "appell/ode/enclose.hpp"

namespace affine_check {

using truth = boost::multiprecision::mpfr_float_100;

/// The lower (MPFR_RNDD) or upper (MPFR_RNDU) bound of x, rounded outward into truth.
template <class I>
truth bound_of(const I& x, mpfr_rnd_t side) {
  appell::mpfr_value a, b;
  appell::scalar_traits<I>::to_mpfr(x, a, b);
  truth r;
  mpfr_set(r.backend().data(), side == MPFR_RNDD ? a : b, side);
  return r;
}
template <class I>
truth lower_of(const I& x) {
  return bound_of(x, MPFR_RNDD);
}
template <class I>
truth upper_of(const I& x) {
  return bound_of(x, MPFR_RNDU);
}
/// Whether the enclosure x holds the truth v.
template <class I>
bool holds(const I& x, const truth& v) {
  return lower_of(x) <= v && v <= upper_of(x);
}

struct outcome {
  long checks = 0, misses = 0, merges = 0;
  double widest = 0;  ///< the largest box width seen
  std::string first_miss;
};

/// `runs` runs of `steps` steps in dimension n.
template <class I>
outcome run(int n, int runs, int steps, std::uint64_t seed) {
  using namespace appell;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
  std::normal_distribution<double> gauss(0, 1);
  outcome out;
  for (int run = 0; run < runs; ++run) {
    // A start box X0 around xh and a true point in it.
    const double r0 = std::pow(10.0, -3 - 9 * u01(rng));
    vector_t<I> xh(n), X0(n);
    std::vector<truth> x(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      xh(i) = I(sym(rng));
      X0(i) = xh(i) + scalar_traits<I>::hull(I(-r0), I(r0));
      x[static_cast<std::size_t>(i)] = lower_of(xh(i)) + truth(r0) * (n == 1 ? truth(1) : truth(sym(rng)));
    }
    ode::detail::affine_set<I> set = ode::detail::affine_set<I>::from_box(X0, xh);
    // Merges every few steps, or (every other run) none.
    const Eigen::Index max_cols = run % 2 ? 1000 : n * (2 + static_cast<int>(u01(rng) * 6));
    for (int k = 0; k < steps; ++k) {
      // J: I + 0.15 N(0,1), each entry widened by a random relative radius; J* inside.
      matrix_t<I> J(n, n);
      std::vector<truth> Jt(static_cast<std::size_t>(n * n));
      const bool wide_J = k % 7 == 3;  // then J* at J's corners: the J* - mid(J) term at its largest
      const double rel = wide_J ? 1e-4 : std::pow(10.0, -14 - 4 * u01(rng));
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const double m = (i == j ? 1.0 : 0.0) + 0.15 * gauss(rng);
          const double rad = std::abs(m) * rel + 1e-300;
          J(i, j) = I(m) + scalar_traits<I>::hull(I(-rad), I(rad));
          const truth lo = lower_of(J(i, j)), hi = upper_of(J(i, j));
          if (n == 1)  // the largest x' the step allows: J*'s bound on the side of x - xh
            Jt[0] = x[0] >= lower_of(xh(0)) ? hi : lo;
          else
            Jt[static_cast<std::size_t>(i * n + j)] =
                wide_J ? (u01(rng) < 0.5 ? lo : hi) : lo + (hi - lo) * truth(u01(rng));
        }
      // zr: a box around a random point, of random width; z inside.
      vector_t<I> zr(n), xhn(n);
      std::vector<truth> z(static_cast<std::size_t>(n));
      const double w = std::pow(10.0, -16 - 3 * u01(rng)) * (k % 11 == 5 ? 1e8 : 1);
      for (int i = 0; i < n; ++i) {
        zr(i) = I(sym(rng)) + scalar_traits<I>::hull(I(-w * u01(rng)), I(w * u01(rng)));
        const truth lo = lower_of(zr(i)), hi = upper_of(zr(i));
        z[static_cast<std::size_t>(i)] = n == 1 ? hi : lo + (hi - lo) * truth(u01(rng));
        // The new centre off zr's midpoint (every other step), as enclose's can be by up to half an
        // ulp of the state: dz = zr - xhn is then off 0, and the set's shift (its centre less xhn),
        // carried by the next steps' J, must be where the set is.
        const double off = k % 2 ? 0.0 : sym(rng) * std::max(w, std::ldexp(1.0, -40)) * (i % 2 ? 512 : 1);
        xhn(i) = ode::detail::thin_of<I>(scalar_traits<I>::mid(I(zr(i) + I(off))));
      }
      // The true step x' = z + J* (x - xh).
      std::vector<truth> xn(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        truth s = z[static_cast<std::size_t>(i)];
        for (int j = 0; j < n; ++j)
          s += Jt[static_cast<std::size_t>(i * n + j)] * (x[static_cast<std::size_t>(j)] - lower_of(xh(j)));
        xn[static_cast<std::size_t>(i)] = s;
      }
      const Eigen::Index before = set.C.cols();
      set.step(J, vector_t<I>(zr - xhn), max_cols);
      if (set.C.cols() < before + n) ++out.merges;
      const vector_t<I> box = set.box(xhn);
      for (int i = 0; i < n; ++i) {
        ++out.checks;
        const truth& v = xn[static_cast<std::size_t>(i)];
        if (!(lower_of(box(i)) <= v && v <= upper_of(box(i)))) {
          if (out.misses++ == 0)
            out.first_miss = "run " + std::to_string(run) + " step " + std::to_string(k) + " component " +
                             std::to_string(i) + ": " + v.str(30) + " outside [" + lower_of(box(i)).str(30) + ", " +
                             upper_of(box(i)).str(30) + "]";
        }
        out.widest = std::max(out.widest, approx_double(I(scalar_traits<I>::width(box(i)))));
      }
      x = xn;
      xh = xhn;
    }
  }
  return out;
}

}  // namespace affine_check
