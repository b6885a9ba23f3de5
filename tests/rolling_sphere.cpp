// Example II (paper sec. 7): the rolling sphere against Newton-Euler with
// contact multipliers in a fixed frame (tests/independent/sphere_newton_euler.hpp),
// solved at 532 bits (160 digits) -- an independent
// formulation (no trihedron, no quasi-velocities, no Appell):
//   M a_G = F + F_c,                      A alpha = tau + (-a n) x F_c + G_n n,
//   a_G - a alpha x n - a omega x n' = 0, alpha . n + omega . n' = 0,
// ten linear equations for a_G, alpha, the contact force F_c and the pivoting
// couple G_n, with n' = +-v_G / rho (sphere), its horizontal part (cylinder), 0 (plane).
#define BOOST_TEST_MODULE rolling_sphere
#include <boost/test/unit_test.hpp>

#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/scalar/rational.hpp"
#include "independent/sphere_newton_euler.hpp"

using namespace appell;
// References at fixed precisions of their own (not appell::mpfr, whose precision the tests set).
using ref_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<160>, boost::multiprecision::et_off>;
using fast_ref_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<60>, boost::multiprecision::et_off>;
using Q = rational_q;

namespace {

// A consistent state, exactly: rationals on the surface of centres, omega . n = 0.
struct state_q {
  Q M, A, a;
  surface_type type;
  bool inside;
  Q b;
  vec3<Q> c, omega, F, tau;
};

template <class R>
using reference = independent::sphere_contact<R>;

template <class R>
R ref(const Q& x) {
  R r;
  mpfr_set_q(r.backend().data(), x.backend().data(), MPFR_RNDN);
  return r;
}

template <class R>
reference<R> newton_euler(const state_q& s) {
  using V = Eigen::Matrix<R, 3, 1>;
  auto v3 = [](const vec3<Q>& x) { return V(ref<R>(x(0)), ref<R>(x(1)), ref<R>(x(2))); };
  return independent::sphere_newton_euler<R>(ref<R>(s.M), ref<R>(s.A), ref<R>(s.a), s.type, s.inside, ref<R>(s.b), v3(s.c),
                                       v3(s.omega), v3(s.F), v3(s.tau),
                                       [](const auto& K, const auto& rhs) { return K.partialPivLu().solve(rhs).eval(); });
}

std::mt19937_64 rng(7);
Q rq(long lo, long hi, long den) { return Q(std::uniform_int_distribution<long>(lo, hi)(rng), den); }

state_q random_state(surface_type type, bool inside) {
  state_q s;
  s.type = type;
  s.inside = inside;
  s.M = rq(1, 50, 10);
  s.a = rq(1, 30, 100);
  // homogeneous (2/5 M a^2) or any 0 < A <= 2/3 M a^2 (up to the thin shell)
  s.A = std::uniform_int_distribution<int>(0, 1)(rng) ? Q(2, 5) * s.M * s.a * s.a : rq(1, 100, 100) * Q(2, 3) * s.M * s.a * s.a;
  s.b = s.a + rq(1, 200, 100);
  const Q rho = inside ? s.b - s.a : s.b + s.a;
  const Q u = rq(-300, 300, 100), t = rq(-300, 300, 100), d = 1 + u * u + t * t;
  vec3<Q> m;
  if (type == surface_type::plane) {
    s.c = vec3<Q>(rq(-100, 100, 10), rq(-100, 100, 10), s.a);
    m = vec3<Q>(0, 0, 1);
  } else if (type == surface_type::sphere) {
    m = vec3<Q>(2 * u / d, 2 * t / d, (1 - u * u - t * t) / d);
    s.c = m * rho;
  } else {
    const Q e = 1 + u * u;
    m = vec3<Q>((1 - u * u) / e, 2 * u / e, 0);
    s.c = m * rho + vec3<Q>(0, 0, rq(-100, 100, 10));
  }
  const vec3<Q> w0(rq(-200, 200, 10), rq(-200, 200, 10), rq(-200, 200, 10));
  s.omega = w0 - m * dot(w0, m);
  s.F = vec3<Q>(rq(-50, 50, 10), rq(-50, 50, 10), rq(-150, 50, 10)) * s.M;
  s.tau = vec3<Q>(rq(-10, 10, 100), rq(-10, 10, 100), rq(-10, 10, 100));
  return s;
}

template <class T>
rolling_sphere_result<T> library(const state_q& s) {
  auto t = [](const Q& x) { return from_rational<T>(x); };
  auto t3 = [&](const vec3<Q>& x) { return vec3<T>(t(x(0)), t(x(1)), t(x(2))); };
  rolling_surface<T> surf;
  surf.type = s.type;
  surf.inside = s.inside;
  surf.b = t(s.b);
  return rolling_sphere_motion(t(s.M), t(s.A), t(s.a), surf, t3(s.c), t3(s.omega), t3(s.F), t3(s.tau));
}

// Interval types must contain the reference, up to the reference's own error
// (10^(20 - digits) * scale: an exact 0 is computed as ~1e-77 at 160 digits);
// point types agree to within 32 eps * scale, eps = 2^(1 - p) = 2u, scale the
// size of the terms that cancel in that quantity (scales_of).  Measured on
// 1000 states (200 per surface) against the 160-digit reference, the largest
// errors in units of eps * scale were: double 13.9 (F_c; a_G 13.2, G_n 2.9,
// alpha 0.6), long double 4.2, dd 7.6, float128 11.5, mpfr (257 bits) 9.1, so
// 32 leaves a margin of 2.3 or more.  A relative error of 1e-12 in a double
// result exceeds the tolerance in 89% of the F_c, 86% of the a_G and 76% of
// the alpha and G_n components (the others are small against their terms), so
// it fails the test; the earlier 1024 eps * (one scale of the whole state,
// plus 10 M + 1) let it pass in all but 177 of 10000.
template <class T, class R>
bool agrees(const T& x, const R& r, const R& scale) {
  if constexpr (scalar_traits<T>::is_interval) {
    R delta = 10;
    delta = pow(delta, 20 - static_cast<int>(std::numeric_limits<R>::digits10)) * scale;
    const R rlo = r - delta, rhi = r + delta;
    mpfr_value lo(700), hi(700);
    mpfr_set(lo, rlo.backend().data(), MPFR_RNDN);
    mpfr_set(hi, rhi.backend().data(), MPFR_RNDN);
    mpfr_value xl, xh;
    scalar_traits<T>::to_mpfr(x, xl, xh);
    return mpfr_lessequal_p(xl, hi) && mpfr_lessequal_p(lo, xh);  // [x] meets [r - delta, r + delta]
  } else {
    const double eps = std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits()));
    return abs(R(to_decimal(x)) - r) <= R(32 * eps) * scale;
  }
}

// The size of the terms that cancel in each result: the magnitudes of the
// terms of the Newton-Euler balance it is solved from, plus the velocity-
// product terms (|w|^2 in its units); |x| is the sum of the components'
// magnitudes, w = omega, and each scale is in the result's own units:
//   a_G = (F + F_c) / M = a alpha x n + a w x n'   (|F| + |F_c|) / M + a |alpha| + a |w|^2
//   alpha = (tau - a n x F_c + G_n n) / A          (|tau| + a |F_c| + |G_n|) / A + |w|^2
//   F_c = M a_G - F                                M |a_G| + |F| + M a |w|^2
//   G_n = n . (A alpha - tau + a n x F_c)          A |alpha| + |tau| + A |w|^2
template <class RT>
struct result_scales {
  RT aG, alpha, Fc, Gn;
};
template <class RT>
result_scales<RT> scales_of(const state_q& s, const reference<RT>& R) {
  RT F = 0, Fc = 0, tau = 0, aG = 0, alpha = 0, w2 = 0;
  for (int i = 0; i < 3; ++i) {
    F += abs(ref<RT>(s.F(i)));
    Fc += abs(R.Fc(i));
    tau += abs(ref<RT>(s.tau(i)));
    aG += abs(R.aG(i));
    alpha += abs(R.alpha(i));
    w2 += abs(ref<RT>(s.omega(i))) * abs(ref<RT>(s.omega(i)));
  }
  const RT M = ref<RT>(s.M), A = ref<RT>(s.A), a = ref<RT>(s.a);
  return {(F + Fc) / M + a * alpha + a * w2, (tau + a * Fc + abs(R.Gn)) / A + w2, M * aG + F + M * a * w2,
          A * alpha + tau + A * w2};
}

template <class T>
long compare_all(const state_q& s, const reference<ref_t>& R) {
  const auto r = library<T>(s);
  const result_scales<ref_t> scale = scales_of(s, R);
  long n = 0;
  for (int i = 0; i < 3; ++i) {
    BOOST_REQUIRE_MESSAGE(agrees(r.center_ddot(i), R.aG(i), scale.aG), scalar_traits<T>::name << " center_ddot " << to_string(r.center_ddot(i)) << " vs " << R.aG(i).str(20));
    BOOST_REQUIRE_MESSAGE(agrees(r.omega_dot(i), R.alpha(i), scale.alpha), scalar_traits<T>::name << " omega_dot " << to_string(r.omega_dot(i)) << " vs " << R.alpha(i).str(20));
    BOOST_REQUIRE_MESSAGE(agrees(r.contact_force(i), R.Fc(i), scale.Fc), scalar_traits<T>::name << " contact_force " << to_string(r.contact_force(i)) << " vs " << R.Fc(i).str(20));
    n += 3;
  }
  BOOST_REQUIRE_MESSAGE(agrees(r.pivot_couple, R.Gn, scale.Gn), scalar_traits<T>::name << " pivot " << to_string(r.pivot_couple) << " vs " << R.Gn.str(20));
  return n + 1;
}

const std::pair<surface_type, bool> surfaces[] = {{surface_type::plane, false},
                                                  {surface_type::sphere, false},
                                                  {surface_type::sphere, true},
                                                  {surface_type::cylinder, false},
                                                  {surface_type::cylinder, true}};
const char* surface_name(surface_type t, bool inside) {
  return t == surface_type::plane ? "plane" : t == surface_type::sphere ? (inside ? "inside a sphere" : "outside a sphere")
                                                                        : (inside ? "inside a cylinder" : "outside a cylinder");
}

}  // namespace

/// compare_all in T where this build compiled T (tests/built_scalars.hpp); 0 values otherwise.
template <class T>
long compare_if_built(const state_q& s, const reference<ref_t>& R) {
  if constexpr (scalar_built<T>)
    return compare_all<T>(s, R);
  else
    return 0;
}

BOOST_AUTO_TEST_CASE(all_seven_scalars_agree_with_newton_euler_at_532_bits) {
  mp_precision_scope scope(256);
  for (const auto& [type, inside] : surfaces) {
    long n = 0;
    for (int k = 0; k < 20; ++k) {
      const state_q s = random_state(type, inside);
      const auto R = newton_euler<ref_t>(s);
      n += compare_all<double>(s, R) + compare_if_built<long double>(s, R) + compare_if_built<dd>(s, R) +
           compare_if_built<float128>(s, R) + compare_if_built<mpfr>(s, R) + compare_all<interval>(s, R) + compare_all<mpfi>(s, R);
    }
    BOOST_TEST_MESSAGE(surface_name(type, inside) << ": 20 states x the scalars of this build, " << n << " values agree");
  }
}

// A sanitized build (scripts/sanitize.sh; its default list leaves this suite out)
// runs 1000 states per surface: it looks for memory and undefined-behaviour errors,
// which do not depend on the count; so does the quick tier (scripts/test.sh, three
// scalars: 24 s less of its run); the full tier keeps 10,000 for the statistics.
#if defined(APPELL_SANITIZED) || !APPELL_TEST_EVERY_SCALAR
constexpr int random_states = 1000;
#else
constexpr int random_states = 10000;
#endif

BOOST_AUTO_TEST_CASE(interval_results_contain_newton_euler_on_random_states_per_surface) {
  // fast_ref_t: 60 digits, the reference's error 1e-40 * scale is far below the widths
  for (const auto& [type, inside] : surfaces) {
    long contained = 0;
    for (int k = 0; k < random_states; ++k) {
      const state_q s = random_state(type, inside);
      const auto R = newton_euler<fast_ref_t>(s);
      const auto r = library<interval>(s);
      const result_scales<fast_ref_t> scale = scales_of(s, R);
      for (int i = 0; i < 3; ++i) {
        BOOST_REQUIRE(agrees(r.center_ddot(i), R.aG(i), scale.aG));
        BOOST_REQUIRE(agrees(r.omega_dot(i), R.alpha(i), scale.alpha));
        BOOST_REQUIRE(agrees(r.contact_force(i), R.Fc(i), scale.Fc));
      }
      BOOST_REQUIRE(agrees(r.pivot_couple, R.Gn, scale.Gn));
      ++contained;
    }
    BOOST_TEST_MESSAGE(surface_name(type, inside) << ": " << contained << " random consistent states, interval contains Newton-Euler");
    BOOST_TEST(contained == random_states);
  }
}

BOOST_AUTO_TEST_CASE(mpfi_results_contain_newton_euler_on_random_states_per_surface) {
  mp_precision_scope scope(128);  // widths ~1e-35 relative; the 60-digit reference errs by 1e-40 * scale
  for (const auto& [type, inside] : surfaces) {
    long contained = 0;
    for (int k = 0; k < random_states; ++k) {
      const state_q s = random_state(type, inside);
      const auto R = newton_euler<fast_ref_t>(s);
      const auto r = library<mpfi>(s);
      const result_scales<fast_ref_t> scale = scales_of(s, R);
      for (int i = 0; i < 3; ++i) {
        BOOST_REQUIRE(agrees(r.center_ddot(i), R.aG(i), scale.aG));
        BOOST_REQUIRE(agrees(r.contact_force(i), R.Fc(i), scale.Fc));
      }
      BOOST_REQUIRE(agrees(r.pivot_couple, R.Gn, scale.Gn));
      ++contained;
    }
    BOOST_TEST_MESSAGE(surface_name(type, inside) << ": " << contained << " states, mpfi 128 contains Newton-Euler");
    BOOST_TEST(contained == random_states);
  }
}

BOOST_AUTO_TEST_CASE(textbook_incline_bowl_and_cylinder) {
  // Incline of angle alpha: the plane with gravity g (sin alpha, 0, -cos alpha).
  using T = interval;
  const T g = from_decimal<T>("9.81"), m = from_decimal<T>("2"), a = from_decimal<T>("0.1");
  const T alpha = from_decimal<T>("0.5"), s = appell::sin(alpha), c = appell::cos(alpha);
  rolling_surface<T> plane;
  const auto r = rolling_sphere_motion(m, rational<T>(2, 5) * m * a * a, a, plane, vec3<T>(T(0), T(0), a),
                                       vec3<T>(T(0), from_decimal<T>("3"), T(0)), vec3<T>(m * g * s, T(0), -m * g * c),
                                       vec3<T>(T(0), T(0), T(0)));
  auto overlaps = [](const T& x, const T& y) { return !(x.upper() < y.lower() || y.upper() < x.lower()); };
  BOOST_TEST(overlaps(r.center_ddot(0), rational<T>(5, 7) * g * s));      // 5/7 g sin alpha
  BOOST_TEST(overlaps(r.tangential_force(), rational<T>(2, 7) * m * g * s)); // 2/7 m g sin alpha
  BOOST_TEST(overlaps(r.normal_force, m * g * c));                        // m g cos alpha
  BOOST_TEST_MESSAGE("incline: acceleration " << to_string(r.center_ddot(0)) << ", friction "
                                              << to_string(r.tangential_force()) << ", normal " << to_string(r.normal_force));
  // At rest at the bottom of a bowl: no acceleration, normal force m g, no friction.
  rolling_surface<T> bowl{surface_type::sphere, true, T(1), T(0)};
  const auto rest = rolling_sphere_motion(m, rational<T>(2, 5) * m * a * a, a, bowl, vec3<T>(T(0), T(0), a - T(1)),
                                          vec3<T>(T(0), T(0), T(0)), vec3<T>(T(0), T(0), -m * g), vec3<T>(T(0), T(0), T(0)));
  for (int i = 0; i < 3; ++i) BOOST_TEST(possibly_zero(rest.center_ddot(i)));
  BOOST_TEST(overlaps(rest.normal_force, m * g));
  BOOST_TEST(possibly_zero(rest.tangential_force()));
  // Inside a vertical cylinder: the wall's normal force is the centripetal one,
  // M v^2 / rho, whatever the spin (v = horizontal speed of G).
  const auto tube = evaluate<T>(read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/rolling_sphere_tube.json"));
  // omega = (0, -2, 30), n = (-1, 0, 0): v_G = a omega x n = (0, -3, -0.2); M v_h^2 / rho = 9 / 0.4
  BOOST_TEST(overlaps(tube.result("contact_force").values[0], T(-22.5)));
}

BOOST_AUTO_TEST_CASE(the_papers_reduced_equations_and_reaction_formulas, *test::needs_scalars({"mpfr"})) {
#if APPELL_TEST_HAS(mpfr)
  // With axes spinning about n (R != 0) the generic path must reproduce
  //   (A + M a^2)(p' - R q) = L - a Y,  (A + M a^2)(q' + R p) = M + a X,
  //   F - X = M a (q' + R p) - X,  H - Y = M a (-p' + R q) - Y,
  //   K - Z = -M a (P p + Q q) - Z,  L - N = A (P q - Q p) - N
  // (paper sec. 7, with the misprints corrected as in docs/design.md §4).
  using T = mpfr;
  mp_precision_scope scope(200);
  long checked = 0;
  for (const auto& [type, inside] : surfaces) {
    for (int k = 0; k < 20; ++k) {
      const state_q s = random_state(type, inside);
      auto t = [](const Q& x) { return from_rational<T>(x); };
      auto t3 = [&](const vec3<Q>& x) { return vec3<T>(t(x(0)), t(x(1)), t(x(2))); };
      rolling_surface<T> surf{type, inside, t(s.b), t(rq(-30, 30, 10))};
      const T M = t(s.M), A = t(s.A), a = t(s.a);
      const auto r = rolling_sphere_motion(M, A, a, surf, t3(s.c), t3(s.omega), t3(s.F), t3(s.tau));
      const mat3<T> Rt = r.axes.transpose();
      const vec3<T> X = mat_vec(Rt, t3(s.F)), L = mat_vec(Rt, t3(s.tau)), w = mat_vec(Rt, t3(s.omega));
      const T p = w(0), q = w(1), pd = r.speeds_dot(3), qd = r.speeds_dot(4);
      const T P = r.frame_rate(0), Qr = r.frame_rate(1), R = r.frame_rate(2);
      const T tol = T(1e-50) * (abs(M) + 1) * (1 + abs(p) + abs(q)) * (1 + abs(R)) * 100;
      BOOST_REQUIRE(abs((A + M * a * a) * (pd - R * q) - (L(0) - a * X(1))) < tol);
      BOOST_REQUIRE(abs((A + M * a * a) * (qd + R * p) - (L(1) + a * X(0))) < tol);
      BOOST_REQUIRE(abs(r.reactions(0) - (M * a * (qd + R * p) - X(0))) < tol);
      BOOST_REQUIRE(abs(r.reactions(1) - (M * a * (-pd + R * q) - X(1))) < tol);
      BOOST_REQUIRE(abs(r.reactions(2) - (-M * a * (P * p + Qr * q) - X(2))) < tol);
      BOOST_REQUIRE(abs(r.reactions(3) - (A * (P * q - Qr * p) - L(2))) < tol);
      ++checked;
    }
  }
  BOOST_TEST_MESSAGE(checked << " states: the paper's reduced equations and reaction formulas hold to 1e-50");
#endif
}
