// The sweeps of the stability study (appell/studies/extreme_sweeps.hpp).
#include <mpfr.h>

#include <cmath>

#include "appell/scalar/format.hpp"
#include "appell/scalar/traits.hpp"
#include "appell/studies/extreme_sweeps.hpp"

namespace appell::studies {
namespace {

std::string pow10(int k) { return "1e" + std::to_string(k); }

// pi - 10^-k as a 60-digit decimal
std::string pi_minus(int k) {
  mpfr_value v(400), e(400);
  mpfr_const_pi(v, MPFR_RNDN);
  mpfr_set_ui(e, 10, MPFR_RNDN);
  mpfr_pow_si(e, e, -k, MPFR_RNDN);
  mpfr_sub(v, v, e, MPFR_RNDN);
  return mpfr_to_decimal(v, 60, MPFR_RNDN);
}

// 1 - 10^-k and 3 + 10^-k as exact decimals
std::string one_minus(int k) { return "0." + std::string(static_cast<std::size_t>(k), '9'); }
std::string three_plus(int k) { return "3." + std::string(static_cast<std::size_t>(k - 1), '0') + "1"; }

std::string top(const std::string& cone, const std::string& theta, const std::string& phi_dot) {
  return "{\"model\": \"top_on_cone\", \"top\": {\"A\": \"0.08\", \"C\": \"0.02\", \"mass\": \"1.5\", \"l\": \"0.2\"},"
         " \"gravity\": \"9.81\", \"cone\": \"" + cone + "\", \"state\": {\"theta\": \"" + theta +
         "\", \"phi\": \"0.3\", \"theta_dot\": \"1.2\", \"phi_dot\": \"" + phi_dot + "\"}}";
}
std::string euler(const std::string& C) {
  return "{\"model\": \"euler_body\", \"inertia\": {\"A\": \"2\", \"B\": \"3\", \"C\": \"" + C +
         "\"}, \"state\": {\"omega\": [\"0.1\", \"1.0\", \"0.2\"]}}";
}
std::string plane(const std::string& mass, const std::string& radius) {
  return "{\"model\": \"rolling_sphere\", \"sphere\": {\"mass\": \"" + mass + "\", \"radius\": \"" + radius +
         "\"}, \"surface\": {\"type\": \"plane\"}, \"gravity\": [\"1.2\", \"0\", \"-9.7\"],"
         " \"state\": {\"center\": [\"0.3\", \"-1\", \"" + radius + "\"], \"omega\": [\"1.5\", \"-4\", \"0\"]}}";
}
std::string bowl(int k) {
  return "{\"model\": \"rolling_sphere\", \"sphere\": {\"mass\": \"2\", \"radius\": \"" + one_minus(k) +
         "\"}, \"surface\": {\"type\": \"sphere\", \"radius\": \"1\", \"side\": \"inside\"},"
         " \"gravity\": [\"0\", \"0\", \"-9.81\"], \"state\": {\"center\": [\"0\", \"0\", \"-" + pow10(-k) +
         "\"], \"omega\": [\"0\", \"2\", \"0\"]}}";
}

}  // namespace

std::vector<sweep> extreme_sweeps() {
  std::vector<sweep> s;
  {
    sweep w{"top_theta_to_0", "top: axis near vertical, theta = 10^-k (Euler-angle singularity)", "log10 theta", {}};
    for (int k : {1, 2, 4, 6, 8, 10, 12}) w.points.push_back({pow10(-k), static_cast<double>(-k), top("0.5*theta + 0.1*sin(2*theta)", pow10(-k), "40")});
    s.push_back(w);
  }
  {
    sweep w{"top_theta_to_pi", "top: axis near downward vertical, theta = pi - 10^-k", "log10 (pi - theta)", {}};
    for (int k : {1, 2, 4, 6, 8, 10, 12}) w.points.push_back({"pi-" + pow10(-k), static_cast<double>(-k), top("0.5*theta + 0.1*sin(2*theta)", pi_minus(k), "40")});
    s.push_back(w);
  }
  {
    sweep w{"top_steep_cone", "top: cone psi = K theta with a huge slope K", "log10 K", {}};
    for (int k : {0, 2, 4, 6, 8}) w.points.push_back({pow10(k), static_cast<double>(k), top(pow10(k) + "*theta", "0.7", "40")});
    s.push_back(w);
  }
  {
    sweep w{"top_spin", "top: spin phi' from 1e-6 to 1e7", "log10 phi'", {}};
    for (int k : {-6, -3, 0, 2, 4, 6, 7}) w.points.push_back({pow10(k), static_cast<double>(k), top("0.5*theta + 0.1*sin(2*theta)", "0.7", pow10(k))});
    s.push_back(w);
  }
  {
    sweep w{"euler_near_equal_inertias", "Euler's body: B = 3, C = 3 + 10^-k (near-equal inertias)", "log10 (C - B)", {}};
    for (int k : {1, 3, 5, 7, 9, 11, 13, 15}) w.points.push_back({three_plus(k), static_cast<double>(-k), euler(three_plus(k))});
    s.push_back(w);
  }
  {
    sweep w{"sphere_mass_scale", "sphere on a plane: mass from 1e-12 to 1e12", "log10 mass", {}};
    for (int k : {-12, -8, -4, 0, 4, 8, 12}) w.points.push_back({pow10(k), static_cast<double>(k), plane(pow10(k), "0.2")});
    s.push_back(w);
  }
  {
    sweep w{"sphere_radius_to_0", "sphere on a plane: radius a = 10^-k", "log10 a", {}};
    for (int k : {1, 3, 5, 7, 9, 11}) w.points.push_back({pow10(-k), static_cast<double>(-k), plane("1.5", pow10(-k))});
    s.push_back(w);
  }
  {
    sweep w{"bowl_gap_to_0", "sphere in a bowl: b - a = 10^-k (sphere nearly as large as the bowl)", "log10 (b - a)", {}};
    for (int k : {1, 3, 5, 7, 9, 11}) w.points.push_back({pow10(-k), static_cast<double>(-k), bowl(k)});
    s.push_back(w);
  }
  return s;
}

}  // namespace appell::studies
