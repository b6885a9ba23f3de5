// proofs/top_box.hpp -- Example I over a box of states, in interval arithmetic.
// The scene's top and cone (data/scenes/top_on_cone.json) with the state
// ranging over theta in [0.6, 0.8], phi in [0.2, 0.4], theta' in [1.0, 1.4],
// phi' in [38, 42], cut into sub-boxes; every library result for a sub-box is an
// enclosure of the result for every state in it.
#pragma once

#include <functional>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/models/top_on_cone.hpp"

namespace appell::proof {

struct top_box_result {
  interval theta, phi, theta_dot, phi_dot;         // the sub-box
  interval H, lambda, theta_ddot, theta_ddot_lagrange, phi_ddot;
  vec3<interval> couple, n, ez, e3;
  interval fprime;
  cotton_result<interval> cotton;
};

inline void for_each_sub_box(int splits, const std::function<void(const top_box_result&)>& visit) {
  const scene_input s = read_scene_file(APPELL_SOURCE_DIR + "/data/scenes/top_on_cone.json");
  const auto& in = s.as<top_on_cone_input>();
  using T = interval;
  const symmetric_top<T> top{value<T>(in.A), value<T>(in.C), value<T>(in.mass), value<T>(in.l), value<T>(in.gravity)};
  const expression_cone<T> cone{compiled_expression<T>(*in.f), compiled_expression<T>(*in.fprime),
                                compiled_expression<T>(*in.fsecond)};
  auto piece = [&](const char* lo, const char* hi, int i, int n) {  // i-th of n equal pieces of [lo, hi]
    const T a = from_decimal<T>(lo), b = from_decimal<T>(hi);
    const T l = a + (b - a) * T(i) / T(n), u = a + (b - a) * T(i + 1) / T(n);
    return T(l.lower(), u.upper());
  };
  for (int i = 0; i < splits; ++i)
    for (int j = 0; j < splits; ++j)
      for (int k = 0; k < splits; ++k)
        for (int m = 0; m < 2; ++m) {
          const evaluation_scope<T> scope;  // the library's policy for interval evaluations
          top_box_result r;
          r.theta = piece("0.6", "0.8", i, splits);
          r.theta_dot = piece("1.0", "1.4", j, splits);
          r.phi_dot = piece("38", "42", k, splits);
          r.phi = piece("0.2", "0.4", m, 2);
          r.fprime = cone.fprime(r.theta);
          // the shipped result function, over the sub-box
          const top_on_cone_state<T> state{cone.psi(r.theta), r.theta, r.phi, r.theta_dot, r.phi_dot};
          const top_on_cone_result<T> motion = top_on_cone_motion(top, cone, state);
          r.cotton = motion.cotton;
          r.H = motion.H;
          r.theta_ddot = motion.theta_ddot;
          r.phi_ddot = motion.phi_ddot;
          r.lambda = motion.lagrange_multiplier;
          r.theta_ddot_lagrange = motion.theta_ddot_lagrange;
          r.couple = motion.couple;
          vector_t<T> q(3);
          q << state.psi, state.theta, state.phi;
          symmetric_top<T>::axes(q, r.n, r.ez);
          r.e3 = vec3<T>(T(0), T(0), T(1));
          visit(r);
        }
}

inline bool overlap(const interval& a, const interval& b) { return a.lower() <= b.upper() && b.lower() <= a.upper(); }
inline double magnitude(const interval& x) { return std::max(std::abs(x.lower()), std::abs(x.upper())); }

}  // namespace appell::proof
