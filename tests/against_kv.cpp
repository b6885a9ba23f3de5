// appell's verified enclosure against a second, independent one: Kashiwagi's kv library
// (odelong_maffine, interval<double>, order 24; vendored under bench/kv, run through
// bench/kv_runs.cpp), on Euler's free body and on the heavy top.  appell integrates the scenes'
// motions (the generic Gibbs-Appell path on jets; the top in Resal's speeds, reported in Euler
// rates), kv the equations written out by hand (Euler's, Lagrange's).  Two enclosures of the one
// true state must meet in every component; both are narrow (below 1e-10 here), so a state off by
// more than that in either, an error of the method or of the equations, shows as a miss.
// And what mixing the two libraries taught: kv switches the rounding mode itself, and appell's
// interval operations inside an upward_rounding scope trust it; enclose refuses to go on once the
// mode was changed inside its scope, before or during the run.
#define BOOST_TEST_MODULE against_kv
#include <boost/test/unit_test.hpp>

#include <cfenv>
#include <iomanip>

#include "appell/models/euler_body.hpp"
#include "appell/models/heavy_top.hpp"
#include "appell/ode/enclose.hpp"
#include "../bench/kv_runs.hpp"

using namespace appell;

namespace {

struct appell_end {
  vector_t<interval> end;
  bool complete = false;
};

template <class P>
appell_end enclose_to(const P& prob, const vector_t<interval>& x0, double t_end) {
  appell_end r;
  const ode::enclose_stats st = ode::enclose(prob, x0, interval(t_end), 24, std::ldexp(1.0, -53), 1.0, 2,
                                             [&](const ode::enclosed_step<interval>& s) { r.end = s.end; });
  r.complete = st.complete;
  return r;
}

void require_meet(const vector_t<interval>& a, const bench::kv_run& kv) {
  BOOST_REQUIRE_EQUAL(kv.status, 2);
  BOOST_REQUIRE_EQUAL(static_cast<std::size_t>(a.size()), kv.end.lower.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const interval b(kv.end.lower[k], kv.end.upper[k]);
    BOOST_TEST_MESSAGE(std::setprecision(17) << "component " << i << ": appell [" << lower(a(i)) << ", " << upper(a(i)) << "], kv [" << kv.end.lower[k]
                                    << ", " << kv.end.upper[k] << "]");
    BOOST_CHECK_LT(boost::numeric::width(a(i)), 1e-10);
    BOOST_CHECK_LT(boost::numeric::width(b), 1e-10);
    BOOST_CHECK_MESSAGE(boost::numeric::overlap(a(i), b), "component " << i << ": appell's enclosure misses kv's");
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(euler_body_at_t_10_meets_kv) {
  const evaluation_scope<interval> scope;
  const ode::euler_body_problem<interval> euler{{vec3<interval>(interval(1), interval(2), interval(3)), vec3<interval>::Zero()}};
  const appell_end a = enclose_to(euler, vector_t<interval>::Constant(3, interval(1)), 10);
  BOOST_REQUIRE(a.complete);
  require_meet(a.end, bench::run_kv(bench::kv_problem::euler_body, 10, 24, false));
}

BOOST_AUTO_TEST_CASE(heavy_top_at_t_2_meets_kv) {
  const evaluation_scope<interval> scope;
  using resal_t = ode::heavy_top_resal_problem<interval>;
  const resal_t top{interval(1), interval(2), interval(1), interval(1), interval(1)};  // A about O, C, m, g, l
  vector_t<interval> x0(6);  // Euler rates: psi, theta, phi, psi', theta', phi'
  x0 << interval(0), interval(1), interval(0), interval(0.5), interval(0), interval(5);
  const appell_end a = enclose_to(top, resal_t::from_euler_rates(x0), 2);
  BOOST_REQUIRE(a.complete);
  require_meet(resal_t::reported<interval>(a.end), bench::run_kv(bench::kv_problem::heavy_top, 2, 24, false));
}

BOOST_AUTO_TEST_CASE(enclose_refuses_a_rounding_mode_changed_inside_its_scope) {
  std::fenv_t caller;
  std::fegetenv(&caller);
  const ode::euler_body_problem<interval> euler{{vec3<interval>(interval(1), interval(2), interval(3)), vec3<interval>::Zero()}};
  const vector_t<interval> x0 = vector_t<interval>::Constant(3, interval(1));
  auto names_the_mode = [](const certification_error& e) { return std::string(e.what()).find("rounding mode") != std::string::npos; };
  {
    const evaluation_scope<interval> scope;
    long seen = 0;  // a step's callback switches to nearest after the third step, as kv does
    BOOST_CHECK_EXCEPTION(ode::enclose(euler, x0, interval(10), 24, std::ldexp(1.0, -53), 1.0, 2,
                                       [&](const ode::enclosed_step<interval>&) {
                                         if (++seen == 3) std::fesetround(FE_TONEAREST);
                                       }),
                          certification_error, names_the_mode);
    BOOST_CHECK_EQUAL(seen, 3);  // no step computed after the change reached the caller
    std::fesetround(FE_TONEAREST);  // the mode changed before the call
    BOOST_CHECK_EXCEPTION(ode::enclose(euler, x0, interval(10), 24, std::ldexp(1.0, -53), 1.0, 2,
                                       [&](const ode::enclosed_step<interval>&) { ++seen; }),
                          certification_error, names_the_mode);
    BOOST_CHECK_EQUAL(seen, 3);
  }
  std::fesetenv(&caller);
  // Outside any scope each interval operation sets the mode itself: the same run completes.
  const appell_end a = enclose_to(euler, x0, 10);
  BOOST_CHECK(a.complete);
  require_meet(a.end, bench::run_kv(bench::kv_problem::euler_body, 10, 24, false));
}
