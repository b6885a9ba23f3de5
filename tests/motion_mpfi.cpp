// appell enclose in MPFI (113 bits): the checks of tests/motion.cpp that hold in every interval
// type (motion_checks.hpp: Euler's free body against its solution in Jacobi elliptic functions,
// the pendulum's energy and state), and the affine set's interval-product path.
// One heavy scalar in this unit (tests/motion.cpp has interval<double>).
#define BOOST_TEST_MODULE motion_mpfi
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <random>

#include "appell/ode/enclose.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/scalar/decimal.hpp"
#include "affine_check.hpp"
#include "motion_checks.hpp"

using namespace appell;

BOOST_AUTO_TEST_CASE(euler_body_at_113_bits_holds_the_elliptic_solution) {
  // the check of tests/motion.cpp (motion_checks.hpp) on 4 random bodies, order 40, tolerance 2^-113
  const mp_precision_scope precision(113);
  const double widest = motion_checks::euler_body_holds_the_elliptic_solution<mpfi>(11, 4, 40, std::ldexp(1.0, -113));
  BOOST_TEST_MESSAGE("euler_body at 113 bits: 4 random bodies to T = 5 hold the elliptic solution; widest " << widest);
  BOOST_TEST(widest < 1e-25);
}

BOOST_AUTO_TEST_CASE(pendulum_energy_stays_inside_its_initial_value) {
  const mp_precision_scope precision(113);
  for (const bool rod_axes : {true, false})
    BOOST_TEST(motion_checks::pendulum_energy_holds_its_initial_value<mpfi>(rod_axes, 40, std::ldexp(1.0, -113), "10") < 1e-25);
}

BOOST_AUTO_TEST_CASE(the_affine_set_holds_every_true_point_through_steps_and_merges) {
  // The interval-product path of the affine set (tests/affine_check.hpp), at 113 bits.
  const mp_precision_scope precision(113);
  const evaluation_scope<mpfi> scope;
  for (int n : {1, 3, 6}) {
    const affine_check::outcome o = affine_check::run<mpfi>(n, 60, 40, 20261126u + static_cast<unsigned>(n));
    BOOST_TEST_MESSAGE("affine set, mpfi 113, n = " << n << ": " << o.checks << " components checked, " << o.merges
                                                     << " merges, " << o.misses << " misses, widest " << o.widest);
    BOOST_TEST(o.misses == 0, o.first_miss);
    BOOST_TEST(o.merges > 100);
  }
}
