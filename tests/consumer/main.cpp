// Uses the installed library: an enclosure of Euler's equations, a scene's evaluation and an
// enclosure of its motion (appell::motion).
#include <appell/io/scene.hpp>
#include <appell/motion/motion.hpp>
#include <appell/models/euler_body.hpp>
#include <iostream>

int main(int argc, char** argv) {
  using namespace appell;
  const euler_body<interval> body{vec3<interval>(from_decimal<interval>("2"), from_decimal<interval>("3"),
                                                 from_decimal<interval>("4")),
                                  vec3<interval>::Zero()};
  const vec3<interval> omega(from_decimal<interval>("0.1"), from_decimal<interval>("1"),
                             from_decimal<interval>("0.2"));
  const vec3<interval> w = euler_omega_dot(body, omega);
  // p' = (B - C) q r / A = -0.1 exactly: the enclosure must hold it.
  if (!(w(0).lower() <= -0.1 && -0.1 <= w(0).upper()) || !(w(0).lower() < w(0).upper())) return 1;
  if (argc > 1) {
    const scene_input scene = read_scene_file(argv[1]);
    std::cout << format_json(scene, evaluate<interval>(scene));
    // The motion over [0, 1], enclosed (docs/motion.md): every step's rows to a sink, a report back.
    motion::settings s;
    s.t_end = "1";
    motion::discard_rows rows;
    const motion::enclose_report r = motion::enclose(scene, s, rows);
    if (!r.complete || r.t_reached.empty()) return 1;
    std::cout << "enclosed to t = " << r.t_reached << " in " << r.steps << " steps; the state's largest width "
              << r.final_width << "\n";
  }
  std::cout << "consumer OK: p' in " << to_string(w(0)) << "\n";
  return 0;
}
