// The generic Gibbs-Appell path, as optimized (issue "generic path within 10x"):
//  1. the evaluations on multi_dual numbers (one for systems with max_speeds,
//     8 directions at a time for the others) give the same J, c and body
//     states, bit for bit, as k + 1 single-dual passes, in double, interval and
//     mpfi, on random states of every scene's system, of the Cotton speeds built
//     on them, and of a 12-link chain (two evaluations);
//  2. the generic path against the closed forms of tests/independent/hand_derived.hpp
//     (Euler's equations; the rolling sphere by Newton-Euler eliminated by hand;
//     Example I by Lagrange's equations), an independent formulation: on random
//     states the closed form at 320 bits lies inside every interval result of
//     the generic path, and the generic path in double agrees with it.
#define BOOST_TEST_MODULE generic_path
#include <boost/test/unit_test.hpp>

#include <cstring>
#include <iomanip>
#include <sstream>
#include <random>

#include "appell/scalar/standard_scalars.hpp"
#include "appell/models/euler_body.hpp"
#include "appell/models/rolling_sphere.hpp"
#include "appell/models/top_on_cone.hpp"
#include "independent/hand_derived.hpp"
#include "../examples/planar_chain.hpp"

using namespace appell;

namespace {

/// The same system without max_speeds: differentiated 8 directions at a time.
template <class Sys>
struct unbounded {
  const Sys* sys;
  int speeds() const { return sys->speeds(); }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& u, const S& t) const {
    return sys->template qdot<S>(q, u, t);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& u, const S& t, std::vector<body_state<S>>& out) const {
    sys->template bodies<S>(q, u, t, out);
  }
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const interval& a, const interval& b) {
  return same_bits(lower(a), lower(b)) && same_bits(upper(a), upper(b));
}
bool same_bits(const mpfi& a, const mpfi& b) {
  const auto* x = a.backend().data();
  const auto* y = b.backend().data();
  auto same = [](mpfr_srcptr p, mpfr_srcptr q) {
    return mpfr_get_prec(p) == mpfr_get_prec(q) && mpfr_signbit(p) == mpfr_signbit(q) &&
           ((mpfr_nan_p(p) && mpfr_nan_p(q)) || mpfr_equal_p(p, q));
  };
  return same(&x->left, &y->left) && same(&x->right, &y->right);
}

int mismatches = 0;
template <class T, int R, int C>
void compare(const Eigen::Matrix<T, R, C>& a, const Eigen::Matrix<T, R, C>& b, const char* what) {
  BOOST_REQUIRE(a.rows() == b.rows() && a.cols() == b.cols());
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      if (!same_bits(a(i, j), b(i, j))) {
        if (++mismatches <= 5) BOOST_ERROR(what << "(" << i << ", " << j << ") differs between one pass and k + 1 passes");
      }
}

template <Scalar T, class Sys>
void expect_same_differentiation(const Sys& sys, const vector_t<T>& q, const vector_t<T>& u, const T& t) {
  const auto passes = differentiate_kinematics_by_columns(sys, q, u, t);
  if constexpr (bounded_speeds<Sys>) expect_same_differentiation<T>(unbounded<Sys>{&sys}, q, u, t);  // 8 slots at a time
  const auto once = differentiate_kinematics(sys, q, u, t);
  BOOST_REQUIRE_EQUAL(once.size(), passes.size());
  for (std::size_t i = 0; i < once.size(); ++i) {
    const body_state<T>&a = once[i].state, &b = passes[i].state;
    compare(vec3<T>(a.mass, a.mass, a.mass), vec3<T>(b.mass, b.mass, b.mass), "mass");
    compare(a.inertia, b.inertia, "inertia");
    compare(a.velocity, b.velocity, "velocity");
    compare(a.omega, b.omega, "omega");
    compare(a.frame_rate, b.frame_rate, "frame_rate");
    compare(a.force, b.force, "force");
    compare(a.couple, b.couple, "couple");
    compare(once[i].Jv, passes[i].Jv, "Jv");
    compare(once[i].Jw, passes[i].Jw, "Jw");
    compare(once[i].cv, passes[i].cv, "cv");
    compare(once[i].cw, passes[i].cw, "cw");
  }
}

std::mt19937_64 rng(20261123);
double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

template <Scalar T>
using hand_cone = independent::example_one_cone<T>;  // Example I's cone, written by hand

template <Scalar T>
vector_t<T> random_vector(int n, double lo, double hi) {
  vector_t<T> v(n);
  for (int i = 0; i < n; ++i) v(i) = T(uniform(lo, hi));
  return v;
}

template <Scalar T>
rolling_surface<T> random_surface(int kind) {
  rolling_surface<T> s;
  s.type = kind == 0 ? surface_type::plane : kind <= 2 ? surface_type::sphere : surface_type::cylinder;
  s.inside = kind == 1 || kind == 4;
  s.b = T(uniform(1, 3));
  s.spin = kind % 2 ? T(uniform(-2, 2)) : T(0);
  return s;
}

template <Scalar T>
void differentiation_on_random_states(int states) {
  const evaluation_scope<T> scope;
  for (int n = 0; n < states; ++n) {
    const vector_t<T> q3 = random_vector<T>(3, 0.2, 2.9), u3 = random_vector<T>(3, -5, 5);
    const vector_t<T> q6 = random_vector<T>(6, -1, 1), u6 = random_vector<T>(6, -5, 5);
    const T t(uniform(0, 1));
    const euler_system<T> euler{{vec3<T>(T(uniform(1, 2)), T(uniform(1, 2)), T(uniform(1, 2))),
                                 vec3<T>(T(uniform(-1, 1)), T(uniform(-1, 1)), T(uniform(-1, 1)))}};
    expect_same_differentiation<T>(euler, q3, u3, t);
    const symmetric_top<T> top{T(uniform(0.05, 0.2)), T(uniform(0.01, 0.1)), T(uniform(0.5, 2)), T(uniform(0.05, 0.3)),
                           T(9.81)};
    expect_same_differentiation<T>(top, q3, u3, t);
    const symmetric_top_resal<T> resal{top.A, top.C, top.mass, top.l, top.g};
    expect_same_differentiation<T>(resal, q3, u3, t);
    const hand_cone<T> cone;
    expect_same_differentiation<T>(change_speeds(resal, cone_speeds<hand_cone<T>>{&cone}, 3), q3, u3, t);
    const T a(uniform(0.05, 0.5));
    const free_sphere<T> sphere{T(uniform(0.5, 3)), T(uniform(0.01, 0.2)), a, random_surface<T>(n % 5),
                                vec3<T>(T(uniform(-9, 9)), T(uniform(-9, 9)), T(uniform(-9, 9))),
                                vec3<T>(T(uniform(-1, 1)), T(uniform(-1, 1)), T(uniform(-1, 1)))};
    expect_same_differentiation<T>(sphere, q6, u6, t);
    const rolling_constraint<T> con{a};
    const auto change = adapt_speeds_keeping(con, 6, {3, 4});
    expect_same_differentiation<T>(change_speeds(sphere, change, 6), q6, u6, t);
    expect_same_differentiation<T>(appell::examples::planar_chain<T>{12}, random_vector<T>(12, -1, 1), random_vector<T>(12, -3, 3), t);
  }
  scope.verify();
}

}  // namespace

BOOST_AUTO_TEST_CASE(multi_dual_evaluations_equal_k_plus_one_dual_passes_bit_for_bit) {
  differentiation_on_random_states<double>(300);
  differentiation_on_random_states<interval>(300);
  {
    const mp_precision_scope scope(113);
    differentiation_on_random_states<mpfi>(40);
  }
  BOOST_TEST(mismatches == 0);
  BOOST_TEST_MESSAGE("slotted evaluations = k + 1 single-dual passes on 300 random states (double, interval) and 40 "
                     "(mpfi 113 bits) of 7 systems, one evaluation and 8 slots at a time, every entry of J, c and "
                     "the body states compared bit for bit");
}

namespace {

using ref_t = mpfr;  // at 320 bits in the test below

int outside = 0, checked = 0;
std::string state_label;
double worst_double = 0;
/// The generic interval x encloses the closed form's value r (at 320 bits); the
/// generic double d agrees with r to 64 eps of the scale (measured: 1.4e-15, 6.3 eps).
void expect(const char* what, const interval& x, double d, const ref_t& r, double scale) {
  ++checked;
  if (!(ref_t(lower(x)) <= r && r <= ref_t(upper(x)))) {
    if (++outside <= 5)
      BOOST_ERROR(what << ": the interval [" << std::setprecision(17) << lower(x) << ", " << upper(x)
                       << "] misses the closed form " << r.str(25) << " (state " << state_label << ")");
  }
  const double err = std::abs(static_cast<double>(ref_t(ref_t(d) - r))) / scale;
  worst_double = std::max(worst_double, err);
}

template <Scalar T>
struct sphere_case {
  T M, A, a;
  rolling_surface<T> surface;
  vec3<T> c, omega, F, tau;
};

}  // namespace

BOOST_AUTO_TEST_CASE(generic_path_encloses_and_agrees_with_the_closed_forms) {
  const mp_precision_scope precision(320);
  const int states = 300;
  for (int n = 0; n < states; ++n) {
    // Euler's body
    {
      const double A = uniform(1, 2), B = uniform(1, 2), C = uniform(1, 2);
      const double w[3] = {uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)}, L[3] = {uniform(-1, 1), 0, uniform(-1, 1)};
      auto body = [&]<class T>(std::type_identity<T>) {
        return euler_body<T>{vec3<T>(T(A), T(B), T(C)), vec3<T>(T(L[0]), T(L[1]), T(L[2]))};
      };
      const vec3<ref_t> wr{ref_t{w[0]}, ref_t{w[1]}, ref_t{w[2]}};
      const auto ref = independent::euler(body(std::type_identity<ref_t>{}), wr);
      const euler_body_result<double> d =
          euler_body_motion(body(std::type_identity<double>{}), vec3<double>(w[0], w[1], w[2]));
      const evaluation_scope<interval> scope;
      const euler_body_result<interval> x = euler_body_motion(
          body(std::type_identity<interval>{}), vec3<interval>(interval(w[0]), interval(w[1]), interval(w[2])));
      const double scale = d.omega_dot.norm() + 1;
      for (int i = 0; i < 3; ++i) expect("euler omega_dot", x.omega_dot(i), d.omega_dot(i), ref.omega_dot(i), scale);
    }
    // The rolling sphere on every surface
    {
      const int kind = n % 5;
      const double M = uniform(0.5, 3), a = uniform(0.05, 0.5), b = uniform(1, 3);
      // Every input is a double fixed here, in round-to-nearest: a product formed inside the
      // interval scope below would round upward, and the interval run would solve another problem.
      const double A = uniform(0.2, 0.7) * M * a * a;
      double c[3] = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const double w[3] = {uniform(-5, 5), uniform(-5, 5), kind == 0 ? 0.0 : uniform(-5, 5)};
      const double F[3] = {uniform(-10, 10), uniform(-10, 10), uniform(-10, 10)};
      const double tau[3] = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      if (kind == 0) c[2] = a;
      {
        std::ostringstream o;
        o << std::setprecision(17) << "sphere kind " << kind << " M " << M << " a " << a << " A " << A << " b " << b
          << " c " << c[0] << " " << c[1] << " " << c[2] << " w " << w[0] << " " << w[1] << " " << w[2] << " F " << F[0]
          << " " << F[1] << " " << F[2] << " tau " << tau[0] << " " << tau[1] << " " << tau[2];
        state_label = o.str();
      }
      auto make = [&]<class T>(std::type_identity<T>) {
        sphere_case<T> s;
        s.M = T(M);
        s.a = T(a);
        s.A = T(A);
        s.surface.type = kind == 0 ? surface_type::plane : kind <= 2 ? surface_type::sphere : surface_type::cylinder;
        s.surface.inside = kind == 1 || kind == 4;
        s.surface.b = T(b);
        s.c = vec3<T>(T(c[0]), T(c[1]), T(c[2]));
        s.omega = vec3<T>(T(w[0]), T(w[1]), T(w[2]));
        s.F = vec3<T>(T(F[0]), T(F[1]), T(F[2]));
        s.tau = vec3<T>(T(tau[0]), T(tau[1]), T(tau[2]));
        return s;
      };
      auto run = [](const auto& s) {
        return rolling_sphere_motion(s.M, s.A, s.a, s.surface, s.c, s.omega, s.F, s.tau);
      };
      sphere_case<ref_t> r = make(std::type_identity<ref_t>{});
      // The generic path keeps omega's tangential part (the state's omega . n = 0): so does the reference.
      const vec3<ref_t> nr = r.surface.normal(r.c);
      r.omega = r.omega - nr * dot(r.omega, nr);
      const auto ref = independent::rolling_sphere(r.M, r.A, r.a, r.surface, r.c, r.omega, r.F, r.tau);
      const rolling_sphere_result<double> d = run(make(std::type_identity<double>{}));
      const evaluation_scope<interval> scope;
      const rolling_sphere_result<interval> x = run(make(std::type_identity<interval>{}));
      const double scale = d.center_ddot.norm() + d.omega_dot.norm() + d.contact_force.norm() + 1;
      for (int i = 0; i < 3; ++i) {
        expect("sphere center_ddot", x.center_ddot(i), d.center_ddot(i), ref.center_ddot(i), scale);
        expect("sphere omega_dot", x.omega_dot(i), d.omega_dot(i), ref.omega_dot(i), scale);
        expect("sphere contact_force", x.contact_force(i), d.contact_force(i), ref.contact_force(i), scale);
      }
      expect("sphere normal_force", x.normal_force, d.normal_force, ref.normal_force, scale);
      expect("sphere pivot_couple", x.pivot_couple, d.pivot_couple, ref.pivot_couple, scale);
      expect("sphere tangential_force", x.tangential_force(), d.tangential_force(), ref.tangential_force, scale);
    }
    // Example I with the cone written by hand
    {
      const double A = uniform(0.05, 0.2), C = uniform(0.01, 0.1), m = uniform(0.5, 2), l = uniform(0.05, 0.3);
      const double th = uniform(0.3, 2.8), thd = uniform(-3, 3), phd = uniform(-50, 50);
      auto run = [&]<class T>(std::type_identity<T>) {
        const hand_cone<T> cone;
        const symmetric_top<T> top{T(A), T(C), T(m), T(l), T(9.81)};
        const top_on_cone_state<T> s{cone.f(T(th)), T(th), T(0), T(thd), T(phd)};
        return top_on_cone_motion(top, cone, s);
      };
      const hand_cone<ref_t> cone;
      const ref_t thr(th);
      const auto ref = independent::top_on_cone(ref_t(A), ref_t(C), ref_t(m), ref_t(l), ref_t(9.81), thr, ref_t(thd),
                                                ref_t(phd), cone.f(thr), cone.fprime(thr), cone.fsecond(thr));
      const top_on_cone_result<double> d = run(std::type_identity<double>{});
      const evaluation_scope<interval> scope;
      const top_on_cone_result<interval> x = run(std::type_identity<interval>{});
      const double scale = std::abs(d.theta_ddot) + std::abs(d.phi_ddot) + std::abs(d.H) + d.couple.norm() + 1;
      expect("top theta_ddot", x.theta_ddot, d.theta_ddot, ref.theta_ddot, scale);
      expect("top phi_ddot", x.phi_ddot, d.phi_ddot, ref.phi_ddot, scale);
      expect("top psi_ddot", x.psi_ddot, d.psi_ddot, ref.psi_ddot, scale);
      expect("top H", x.H, d.H, ref.H, scale);
      for (int i = 0; i < 3; ++i) expect("top couple", x.couple(i), d.couple(i), ref.couple(i), scale);
    }
  }
  BOOST_TEST(outside == 0);
  BOOST_TEST(worst_double <= 64 * std::ldexp(1.0, -53));
  BOOST_TEST_MESSAGE(checked << " results on " << states << " random states of each scene: " << outside
                             << " interval results miss the closed form at 320 bits; double's largest error "
                             << worst_double << " of the scale");
}
