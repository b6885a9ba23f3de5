// proofs/top_box.hpp -- Example I over a box of states, in interval arithmetic.
// The scene's top and cone (data/scenes/top_on_cone.json) with the state
// ranging over theta in [0.6, 0.8], phi in [0.2, 0.4], theta' in [1.0, 1.4],
// phi' in [38, 42], cut into sub-boxes; every library result for a sub-box is an
// enclosure of the result for every state in it.
#pragma once

#include <functional>

#include "appell/io/scene.hpp"

namespace appell::proof {

struct top_box_result {
  interval theta, phi, theta_dot, phi_dot;         // the sub-box
  interval H, lambda, theta_ddot, theta_ddot_lagrange, phi_ddot;
  vec3<interval> couple, n, ez, e3;
  interval fprime;
  cotton_result<interval> cotton;
};

inline void for_each_sub_box(int splits, const std::function<void(const top_box_result&)>& visit) {
  const scene_input s = read_scene_file(APPELL_SOURCE_DIR "/data/scenes/top_on_cone.json");
  const auto& in = std::get<top_on_cone_input>(s.input);
  using T = interval;
  const heavy_top<T> top{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)};
  const bound_expression<T> fprime(*in.fprime);
  auto piece = [&](const char* lo, const char* hi, int i, int n) {  // i-th of n equal pieces of [lo, hi]
    const T a = from_decimal<T>(lo), b = from_decimal<T>(hi);
    const T l = a + (b - a) * T(i) / T(n), u = a + (b - a) * T(i + 1) / T(n);
    return T(l.lower(), u.upper());
  };
  for (int i = 0; i < splits; ++i)
    for (int j = 0; j < splits; ++j)
      for (int k = 0; k < splits; ++k)
        for (int m = 0; m < 2; ++m) {
          top_box_result r;
          r.theta = piece("0.6", "0.8", i, splits);
          r.theta_dot = piece("1.0", "1.4", j, splits);
          r.phi_dot = piece("38", "42", k, splits);
          r.phi = piece("0.2", "0.4", m, 2);
          r.fprime = in.fprime->eval(r.theta);
          vector_t<T> q(3), v_a(2), u(3);
          q << in.f->eval(r.theta), r.theta, r.phi;
          v_a << r.theta_dot, r.phi_dot;
          const auto sys = change_speeds(top, cone_speeds<T>{&fprime}, 3);
          r.cotton = cotton_reactions(sys, q, v_a, T(0), 1);
          r.H = r.cotton.reactions(0);
          r.theta_ddot = r.cotton.free_accelerations(0);
          r.phi_ddot = r.cotton.free_accelerations(1);
          u << r.fprime * r.theta_dot, r.theta_dot, r.phi_dot;
          const auto lag = lagrange_multipliers(top, cone_constraint<T>{&fprime}, q, u, T(0));
          r.lambda = lag.reactions(0);
          r.theta_ddot_lagrange = lag.accelerations(1);
          vector_t<T> v(3), g(3);
          v << r.theta_dot, r.phi_dot, T(0);
          g << T(0), T(0), r.H;
          r.couple = constraint_couple(differentiate_kinematics(sys, q, v, T(0))[0], g);
          heavy_top<T>::axes(q, r.n, r.ez);
          r.e3 = vec3<T>(T(0), T(0), T(1));
          visit(r);
        }
}

inline bool overlap(const interval& a, const interval& b) { return a.lower() <= b.upper() && b.lower() <= a.upper(); }
inline double magnitude(const interval& x) { return std::max(std::abs(x.lower()), std::abs(x.upper())); }

}  // namespace appell::proof
