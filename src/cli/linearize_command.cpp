#include "linearize_command.hpp"

#include "linearize_report.hpp"

#include "appell/io/scene.hpp"
#include "appell/motion/motion.hpp"  // left_out_message
#include "commands.hpp"
#include "flags.hpp"

namespace appell::cli {

std::string linearize(const linearize_options& o) {
  if (o.format != "json" && o.format != "text")
    throw input_error("--format: expected json or text, got '" + o.format + "'");
  const scene_input scene = read_scene_file(o.scene);
  if (scene.model != "system")
    throw input_error("model: linearize needs a system file (model \"system\"), not '" + scene.model + "'");
  const system_input& in = scene.as<system_input>();
  if (!in.linearize)
    throw input_error(!in.linearize_refusal.empty() ? in.linearize_refusal
                                                    : "linearize: the scene has no \"linearize\" section (SCENES.md)");
#ifdef APPELL_EVAL_ONLY
  throw input_error(motion::left_out_message("linearize"));
#else
  return with_scalar(o.scalar, o.bits,
                     [&]<class T>(std::type_identity<T>) { return linearize_report<T>(in, o.format); });
#endif
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
