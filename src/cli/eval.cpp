// `appell eval SCENE [--scalar NAME] [--bits N] [--format json|text] [--project TOL]`: a scene's
// results and checks in one scalar (SCENES.md).  Output is assembled in full before anything is
// written to stdout.
#include <filesystem>
#include <optional>
#include <string>

#include "appell/io/evaluation_text.hpp"
#include "appell/io/files.hpp"
#include "appell/io/scene.hpp"
#include "commands.hpp"
#include "flags.hpp"

namespace appell::cli {

int eval_command(int argc, char** argv, int first) {
  std::string scene_path, scalar = "double", format = "json", project;
  std::optional<unsigned> bits;
  {
    command_line c;
    if (std::string why =
            read_command_line("eval", argc, argv, first, {"--scalar", "--bits", "--format", "--project"}, {}, 1, c);
        !why.empty())
      return usage_error(why);
    if (std::string why = read_scene_argument(c, scene_path); !why.empty()) return usage_error(why);
    if (std::string why = read_scalar(c, scalar, bits); !why.empty()) return usage_error(why);
    if (std::string why = read_format(c, format); !why.empty()) return usage_error(why);
    project = c.value_or("--project", "");
    if (c.has("--project") && project.empty()) return usage_error("--project: empty, expected a tolerance");
  }
  return guarded([&] {
    std::string out;
    {
      const cerr_silenced quiet;
      // --project TOL: the scene's "project" (a state off its constraints moved onto them; the
      // projected state printed in `derived`, to keep)
      auto read = [&] {
        if (project.empty()) return read_scene_file(scene_path);
        json_value root = parse_json(read_text_file(scene_path, json_limits::bytes, "a scene file"));
        set_project(root, project, scene_path);
        const scene_directory_scope scope(std::filesystem::path(scene_path).parent_path().string());
        return read_scene(root);
      };
      const scene_input scene = read();
      out = evaluation_text(scene, scalar, bits, format);
    }
    return print_result(out);
  });
}

}  // namespace appell::cli
