// Uses the installed library: an enclosure of Euler's equations and a scene.
#include <appell/io/scene.hpp>
#include <appell/scenes/euler_body.hpp>
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
  if (argc > 1) std::cout << format_json(read_scene_file(argv[1]), evaluate<interval>(read_scene_file(argv[1])));
  std::cout << "consumer OK: p' in " << to_string(w(0)) << "\n";
  return 0;
}
