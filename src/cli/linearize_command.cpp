#include "linearize_command.hpp"

#include "appell/io/scene.hpp"
#include "appell/models/system_linearization.hpp"
#include "commands.hpp"
#include "flags.hpp"

namespace appell::cli {

std::string linearize(const linearize_options& o) {
  const scene_input scene = read_scene_file(o.scene);
  if (scene.model != "system")
    throw input_error("model: linearize needs a system file (model \"system\"), not '" + scene.model + "'");
  return linearization_text(scene.as<system_input>(), o.scalar, o.bits, o.format);
}

int linearize_command(int argc, char** argv, int first) {
  linearize_options o;
  {
    command_line c;
    if (std::string why = read_command_line("linearize", argc, argv, first, {"--scalar", "--bits", "--format"}, {}, 1, c);
        !why.empty())
      return usage_error(why);
    if (std::string why = read_scene_argument(c, o.scene); !why.empty()) return usage_error(why);
    if (std::string why = read_scalar(c, o.scalar, o.bits); !why.empty()) return usage_error(why);
    if (std::string why = read_format(c, o.format); !why.empty()) return usage_error(why);
  }
  return guarded([&] {
    std::string out;
    {
      const cerr_silenced quiet;
      out = linearize(o);
    }
    return print_result(out);
  });
}

}  // namespace appell::cli
