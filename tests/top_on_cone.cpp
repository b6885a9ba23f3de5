// Example I (paper sec. 6) in all seven scalars against an independent
// reference: the closed form of Lagrange's equations of the classical top
// (T = A/2 (theta'^2 + psi'^2 sin^2) + C/2 r^2, V = m g l cos theta, multiplier on
// psi' - f' theta' = 0), derived by hand for this test and evaluated in MPFR at
// 532 bits with hand-written f, f', f''.  The library uses none of it: it
// differentiates the top's kinematics and applies Cotton's method.
#define BOOST_TEST_MODULE top_on_cone
#include <boost/test/unit_test.hpp>

#include <random>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "built_scalars.hpp"
#include "appell/models/top_on_cone.hpp"
#include "independent/top_lagrange.hpp"

using namespace appell;
// The reference has a fixed precision of its own (160 digits, 532 bits), independent of appell::mpfr's.
using ref_t = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<160>, boost::multiprecision::et_off>;

namespace {

struct cone_case {
  std::string text;
  std::function<void(const ref_t&, ref_t&, ref_t&, ref_t&)> f;  // f, f', f''
};

const std::vector<cone_case> cones = {
    {"0.5*theta + 0.1*sin(2*theta)",
     [](const ref_t& t, ref_t& f, ref_t& fp, ref_t& fpp) {
       f = ref_t("0.5") * t + ref_t("0.1") * sin(2 * t);
       fp = ref_t("0.5") + ref_t("0.2") * cos(2 * t);
       fpp = ref_t("-0.4") * sin(2 * t);
     }},
    {"0.8",
     [](const ref_t&, ref_t& f, ref_t& fp, ref_t& fpp) {
       f = ref_t("0.8");
       fp = 0;
       fpp = 0;
     }},
    {"theta^2/(1+theta) - exp(-theta)",
     [](const ref_t& t, ref_t& f, ref_t& fp, ref_t& fpp) {
       f = t * t / (1 + t) - exp(-t);
       fp = (t * t + 2 * t) / ((1 + t) * (1 + t)) + exp(-t);
       fpp = 2 / ((1 + t) * (1 + t) * (1 + t)) - exp(-t);
     }},
};

using reference = independent::top_reference<ref_t>;

reference closed_form(const top_on_cone_input& in, const cone_case& cone) {
  auto d = [](const decimal_field& x) { return ref_t(x.text); };
  ref_t f, fp, fpp;
  cone.f(d(in.theta), f, fp, fpp);
  return independent::top_lagrange<ref_t>(d(in.A), d(in.C), d(in.mass), d(in.l), d(in.gravity), d(in.theta),
                                      d(in.theta_dot), d(in.phi_dot), f, fp, fpp);
}

std::string decimal(std::mt19937_64& rng, double lo, double hi, int digits = 6) {
  const double x = std::uniform_real_distribution<double>(lo, hi)(rng);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

scene_input make_scene(const std::string& A, const std::string& C, const std::string& m, const std::string& l,
                       const std::string& g, const std::string& cone, const std::string& th, const std::string& ph,
                       const std::string& thd, const std::string& phd) {
  const std::string json = "{\"model\": \"top_on_cone\", \"top\": {\"A\": \"" + A + "\", \"C\": \"" + C +
                           "\", \"mass\": \"" + m + "\", \"l\": \"" + l + "\"}, \"gravity\": \"" + g +
                           "\", \"cone\": \"" + cone + "\", \"state\": {\"theta\": \"" + th + "\", \"phi\": \"" +
                           ph + "\", \"theta_dot\": \"" + thd + "\", \"phi_dot\": \"" + phd + "\"}}";
  return read_scene(parse_json(json));
}

std::vector<std::pair<scene_input, const cone_case*>> scenes() {
  std::vector<std::pair<scene_input, const cone_case*>> out;
  for (const char* file : {"top_on_cone.json", "top_on_cone_constant.json", "top_on_cone_steep.json"}) {
    scene_input s = read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
    const auto& in = s.as<top_on_cone_input>();
    for (const auto& c : cones)
      if (c.text == in.cone_text) out.emplace_back(s, &c);
  }
  BOOST_REQUIRE_EQUAL(out.size(), 3u);
  std::mt19937_64 rng(6);
  for (int i = 0; i < 90; ++i) {
    const cone_case& c = cones[static_cast<std::size_t>(i) % cones.size()];
    std::string A, C, m = decimal(rng, 0.5, 2.0), l = decimal(rng, 0.05, 0.2);
    do {
      A = decimal(rng, 0.01, 0.2);
      C = decimal(rng, 0.001, 0.2);
    } while (decimal_sign_of_polynomial({{1, {A}}, {-1, {m, l, l}}}) < 0 ||
             decimal_sign_of_polynomial({{2, {A}}, {-2, {m, l, l}}, {-1, {C}}}) < 0);
    out.emplace_back(make_scene(A, C, m, l, "9.81", c.text, decimal(rng, 0.2, 2.9), decimal(rng, -3, 3),
                                decimal(rng, -3, 3), decimal(rng, -50, 50)),
                     &c);
  }
  return out;
}

template <class T>
void compare(const char* what, const T& x, const ref_t& ref, const ref_t& scale, long& n) {
  mpfr_value v(600);
  mpfr_set(v, ref.backend().data(), MPFR_RNDN);
  if constexpr (scalar_traits<T>::is_interval) {
    BOOST_REQUIRE_MESSAGE(contains(x, v), scalar_traits<T>::name << " " << what << " " << to_string(x)
                                                                  << " misses " << ref.str(30));
  } else {
    mpfr_value xv;
    to_mpfr_exact(x, xv);
    const double eps = std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits()));
    ref_t err = abs(ref_t(to_decimal(x)) - ref);
    // 256 roundings' worth of the largest term: a forward bound for this short computation.
    BOOST_REQUIRE_MESSAGE(err <= ref_t(256 * eps) * scale,
                          scalar_traits<T>::name << " " << what << " error " << err.str(5) << " > 256 eps * "
                                                 << scale.str(5));
  }
  ++n;
}

double worst_check = 0;  // largest point-type check residual seen, in eps * scale
long n_checks = 0;

template <class T>
long check_all() {
  long n = 0;
  for (const auto& [scene, cone] : scenes()) {
    const auto& in = scene.template as<top_on_cone_input>();
    const reference R = closed_form(in, *cone);
    const evaluation<T> e = evaluate<T>(scene);
    compare("theta_ddot", e.result("theta_ddot").values[0], R.theta_ddot, R.scale, n);
    compare("phi_ddot", e.result("phi_ddot").values[0], R.phi_ddot, R.scale, n);
    compare("psi_ddot", e.result("psi_ddot").values[0], R.psi_ddot, R.scale, n);
    compare("H", e.result("H").values[0], R.H, R.scale, n);
    for (int i = 0; i < 3; ++i) compare("couple", e.result("couple").values[static_cast<std::size_t>(i)], R.couple[i], R.scale, n);
    for (const auto& check : e.checks) {  // eq. (4), and Cotton = Lagrange: 0 on every motion
      if (check.name == "error_amplification") continue;
      if constexpr (scalar_traits<T>::is_interval) {
        BOOST_REQUIRE_MESSAGE(possibly_zero(check.values[0]), check.name << " excludes 0");
      } else {
        // Each check is the difference of two independently computed quantities of
        // the size of the terms that cancel (scale): the same forward bound as the results.
        const double eps = std::ldexp(1.0, 1 - static_cast<int>(scalar_traits<T>::precision_bits()));
        const ref_t residual = abs(ref_t(to_decimal(check.values[0])));
        BOOST_REQUIRE_MESSAGE(residual <= ref_t(256 * eps) * R.scale,
                              scalar_traits<T>::name << " " << check.name << " = " << residual.str(5) << " > 256 eps * "
                                                     << R.scale.str(5));
        worst_check = std::max(worst_check, static_cast<double>(residual / (ref_t(eps) * R.scale)));
      }
      ++n_checks;
    }
  }
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(point_types_agree_with_the_532_bit_closed_form) {
  mp_precision_scope scope(256);
  int point_types = 0;  // double, and each other one this build compiled
  auto point = [&]<class T>(std::type_identity<T>, const char* label) {
    const long n = check_all<T>();
    BOOST_TEST_MESSAGE(label << " " << n << " values");
    BOOST_TEST(n == 93 * 7);  // 3 shipped + 90 random scenes, 7 values each
    ++point_types;
  };
  point(std::type_identity<double>{}, "double");
  test::if_built<long double>([&](auto type) { point(type, "long double"); });
  test::if_built<dd>([&](auto type) { point(type, "dd"); });
  test::if_built<float128>([&](auto type) { point(type, "float128"); });
  test::if_built<mpfr>([&](auto type) { point(type, "mpfr 256"); });
  BOOST_TEST(n_checks == point_types * 93 * 3);  // 5 point types (in a build of every scalar) x 93 scenes x 3 checks (eq. 4, H and theta'' Cotton - Lagrange)
  BOOST_TEST_MESSAGE("point-type checks (eq. 4, Cotton - Lagrange): largest |residual| " << worst_check
                                                                                          << " eps * scale (bound 256)");
}

// The evaluation policy is in the library (scalar/policy.hpp): a user who calls
// top_on_cone_motion directly inside an evaluation_scope, enclosing the same
// decimals, gets the bounds `appell eval` prints, digit for digit.
template <class T>
void direct_call_matches_eval(const scene_input& scene) {
  const auto& in = scene.as<top_on_cone_input>();
  std::vector<T> direct;
  {
    const evaluation_scope<T> policy;
    const symmetric_top<T> top{from_decimal<T>(in.A.text), from_decimal<T>(in.C.text), from_decimal<T>(in.mass.text),
                           from_decimal<T>(in.l.text), from_decimal<T>(in.gravity.text)};
    const expression_cone<T> cone{compiled_expression<T>(*in.f), compiled_expression<T>(*in.fprime),
                                  compiled_expression<T>(*in.fsecond)};
    const T theta = from_decimal<T>(in.theta.text);
    const top_on_cone_result<T> r = top_on_cone_motion(
        top, cone,
        top_on_cone_state<T>{cone.psi(theta), theta, from_decimal<T>(in.phi.text), from_decimal<T>(in.theta_dot.text),
                             from_decimal<T>(in.phi_dot.text)});
    direct = {r.theta_ddot, r.phi_ddot, r.psi_ddot, r.H, r.couple(0), r.couple(1), r.couple(2)};
    for (T& x : direct) policy.finish(x);
  }
  const evaluation<T> e = evaluate<T>(scene);
  std::vector<T> cli;
  for (const auto& r : e.results) cli.insert(cli.end(), r.values.begin(), r.values.end());
  BOOST_REQUIRE_EQUAL(cli.size(), direct.size());
  for (std::size_t i = 0; i < cli.size(); ++i) {
    BOOST_TEST(lower_string(direct[i]) == lower_string(cli[i]), scalar_traits<T>::name << " result " << i);
    BOOST_TEST(upper_string(direct[i]) == upper_string(cli[i]), scalar_traits<T>::name << " result " << i);
  }
}

BOOST_AUTO_TEST_CASE(a_direct_library_call_gives_the_bounds_of_appell_eval) {
  for (const char* file : {"top_on_cone.json", "top_on_cone_constant.json", "top_on_cone_steep.json"}) {
    const scene_input s = read_scene_file(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + file);
    direct_call_matches_eval<interval>(s);
    for (unsigned bits : {53u, 113u, 256u}) {
      const mp_precision_scope scope(bits);
      direct_call_matches_eval<mpfi>(s);
    }
  }
}

BOOST_AUTO_TEST_CASE(interval_types_contain_the_532_bit_closed_form) {
  { const long n = check_all<interval>(); BOOST_TEST_MESSAGE("interval " << n << " values contained"); BOOST_TEST(n == 93 * 7); /* 3 shipped + 90 random scenes, 7 values each */ }
  mp_precision_scope scope(256);
  { const long n = check_all<mpfi>(); BOOST_TEST_MESSAGE("mpfi 256 " << n << " values contained"); BOOST_TEST(n == 93 * 7); /* 3 shipped + 90 random scenes, 7 values each */ }
}

BOOST_AUTO_TEST_CASE(a_constant_cone_gives_the_textbook_answer) {
  // f = c: psi' = 0, so phi'' = 0 and H = -C sin(theta) theta' phi'.
  const scene_input s = make_scene("0.08", "0.02", "1.5", "0.2", "9.81", "1.25", "0.7", "0.3", "1.2", "40");
  const auto e = evaluate<interval>(s);
  BOOST_TEST(possibly_zero(e.result("phi_ddot").values[0]));
  const interval expected = -from_decimal<interval>("0.02") * appell::sin(from_decimal<interval>("0.7")) *
                            from_decimal<interval>("1.2") * from_decimal<interval>("40");
  const interval H = e.result("H").values[0];
  BOOST_TEST(!(boost::numeric::intersect(H, expected).lower() > boost::numeric::intersect(H, expected).upper()));
  BOOST_TEST(!boost::numeric::empty(boost::numeric::intersect(H, expected)));
  BOOST_TEST_MESSAGE("H = " << to_string(H) << ", -C sin(theta) theta' phi' = " << to_string(expected));
}

BOOST_AUTO_TEST_CASE(cotton_with_library_built_speeds_equals_cotton_with_the_papers_speeds) {
  // The same reactions when the library adapts the speeds to A u = a itself.
  const scene_input s = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/top_on_cone.json");
  const auto& in = s.as<top_on_cone_input>();
  using T = interval;
  const symmetric_top<T> top{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)};
  const T theta = value<T>(in.theta), thd = value<T>(in.theta_dot), phd = value<T>(in.phi_dot);
  vector_t<T> q(3), u(3);
  q << in.f->eval(theta), theta, value<T>(in.phi);
  u << in.fprime->eval(theta) * thd, thd, phd;
  const expression_cone<T> cone{compiled_expression<T>(*in.f), compiled_expression<T>(*in.fprime),
                                compiled_expression<T>(*in.fsecond)};
  const auto generic = cotton_reactions(top, cone_constraint<expression_cone<T>>{&cone}, q, u, T(0));
  const auto lagrange = lagrange_multipliers(top, cone_constraint<expression_cone<T>>{&cone}, q, u, T(0));
  const auto paper = evaluate<T>(s);
  const T H = paper.result("H").values[0];
  BOOST_TEST(!boost::numeric::empty(boost::numeric::intersect(generic.reactions(0), H)));
  BOOST_TEST(!boost::numeric::empty(boost::numeric::intersect(lagrange.reactions(0), H)));
  for (int i = 0; i < 3; ++i)
    BOOST_TEST(!boost::numeric::empty(boost::numeric::intersect(generic.accelerations(i), lagrange.accelerations(i))));
  BOOST_TEST_MESSAGE("H: paper's speeds " << to_string(H) << ", library's speeds " << to_string(generic.reactions(0))
                                           << ", Lagrange " << to_string(lagrange.reactions(0)));
}

BOOST_AUTO_TEST_CASE(bad_cone_expressions_are_refused_with_a_reason) {
  auto expect = [](const std::string& cone, const std::string& theta, const std::string& needle) {
    try {
      const scene_input s = make_scene("0.08", "0.02", "1.5", "0.2", "9.81", cone, theta, "0", "1", "1");
      (void)evaluate<double>(s);
      BOOST_ERROR("cone '" << cone << "' was accepted");
    } catch (const input_error& e) {
      BOOST_TEST(std::string(e.what()).find(needle) != std::string::npos, e.what());
      BOOST_TEST(std::string(e.what()).find("cone") != std::string::npos, e.what());
    }
  };
  expect("0.5*thet", "0.7", "unknown name 'thet'");
  expect("sinh(theta)", "0.7", "unknown name 'sinh'");
  expect("0.5*(theta", "0.7", "missing ')'");
  expect("0.5**theta", "0.7", "unexpected '*'");
  expect("", "0.7", "unexpected end");
  expect("1/(theta - 0.5)", "0.5", "division by zero");
  expect("log(theta - 0.7)", "0.7", "log of a number <= 0");
  expect("theta^0.5 + 1.5.2", "0.7", "bad number");
}
