#include "linearize_command.hpp"

#include "linearize_report.hpp"

#include "appell/io/scene.hpp"

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
  return with_scalar(o.scalar, o.bits,
                     [&]<class T>(std::type_identity<T>) { return linearize_report<T>(in, o.format); });
}

}  // namespace appell::cli
