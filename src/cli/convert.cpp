// `appell convert PATH`: a file of a front end's own kind (a URDF robot) or one of its scenes, as
// the scene file appell reads it as (stdout).  The front ends are the registered models with a
// `convert` hook (io/scene.hpp's model_entry): the first that takes the file converts it.
#include <string>
#include <vector>

#include "appell/io/files.hpp"
#include "appell/io/json.hpp"
#include "appell/io/scene.hpp"
#include "commands.hpp"

namespace appell::cli {

namespace {

std::vector<const model_entry*> converters() {
  std::vector<const model_entry*> out;
  for (const model_entry* e : registered_models())
    if (e->convert) out.push_back(e);
  return out;
}

// What convert takes: "a URDF file or a "urdf" scene", each front end's words joined by "or".
std::string what_converts(const std::vector<const model_entry*>& front_ends) {
  std::string s;
  for (const model_entry* e : front_ends) s += (s.empty() ? "" : " or ") + std::string(e->converts ? e->converts : e->name.c_str());
  return s.empty() ? "nothing (no model of this build converts files)" : s;
}

// A scene's "model", where the file is a JSON object that names one ("" otherwise).
std::string scene_model_name(const std::string& path) {
  try {
    const json_value doc = parse_json(read_text_file(path, json_limits::bytes, "a scene file"));
    const json_value* model = doc.type == json_value::kind::object ? doc.find("model") : nullptr;
    if (model && model->type == json_value::kind::string) return model->text;
  } catch (const input_error&) {
  }
  return "";
}

}  // namespace

std::string what_converts() { return what_converts(converters()); }

int convert_command(int argc, char** argv, int first) {
  const std::vector<const model_entry*> front_ends = converters();
  if (argc != first + 1) return usage_error("convert: expected one file: " + what_converts(front_ends));
  const std::string path = argv[first];
  return guarded([&] {
    for (const model_entry* e : front_ends)
      if (std::optional<std::string> out = e->convert(path)) return print_result(*out);
    const std::string model = scene_model_name(path);
    throw input_error(model.empty() ? path + ": convert reads " + what_converts(front_ends)
                                    : "model: convert reads " + what_converts(front_ends) + ", not a '" +
                                          printable(model) + "' scene (it reads as itself)");
  });
}

}  // namespace appell::cli
