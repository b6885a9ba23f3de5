// `appell linearize` (linearize_command.hpp): reads the system file, runs the linearization in the
// scalar asked for, writes the document (JSON or text).
#include "linearize_command.hpp"

#include "appell/io/scene.hpp"
#include "commands.hpp"
#include "flags.hpp"

namespace appell::cli {

std::string linearize(const linearize_options& o) {
  const scene_input scene = read_scene_file(o.scene);
  if (!scene.entry->linearize) {
    std::string models;  // those that linearize
    for (const model_entry* m : registered_models())
      if (m->linearize) models += (models.empty() ? "" : ", ") + m->name;
    throw input_error("model: linearize needs a scene of a model that linearizes (" + models + "), not '" + scene.model + "'");
  }
  return scene.entry->linearize(*scene.input, o.scalar, o.bits, o.format);
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
