// The scene layer's model-independent part: the registry lookup, reading and
// validating scene files, and the measured error amplification.
#include "appell/io/scene.hpp"

#include <filesystem>
#include <fstream>
#include <limits>

#include "appell/io/validate.hpp"

namespace appell {

void require_positive(const object_reader& r, const std::string& key, const decimal_field& d,
                      const std::string& what) {
  if (decimal_sign_of_sum({{1, d.text}}) <= 0)
    throw input_error(r.path(key) + ": " + (what.empty() ? "" : what + " ") + "must be positive, got " + d.text);
}

const model_entry& find_model(const std::string& name) {
  std::string known;
  for (const model_entry* m : registered_models()) {
    if (m->name == name) return *m;
    known += (known.empty() ? "" : ", ") + m->name;
  }
  throw input_error("model: unknown model '" + name + "' (known: " + known + ")");
}

scene_input read_scene(const json_value& root) {
  object_reader scene(root, "");
  scene_input out;
  out.model = scene.string("model");
  out.entry = &find_model(out.model);
  out.input = out.entry->read(scene);
  scene.finish();
  return out;
}

double error_amplification(const scene_input& scene) {
  try {
    const evaluation<interval> e = compute<interval>(prepare<interval>(scene));
    // relative widths of the components bounded away from 0 (a result that
    // may be 0 has no relative accuracy to lose); absolute ones if all may be 0
    double widest = 0, widest_abs = 0;
    bool any_nonzero = false;
    for (const auto& r : e.results)
      for (const interval& x : r.values) {
        const double w = boost::numeric::width(x);
        widest_abs = std::max(widest_abs, w);
        if (x.lower() > 0 || x.upper() < 0) {
          any_nonzero = true;
          widest = std::max(widest, w / std::min(std::abs(x.lower()), std::abs(x.upper())));
        }
      }
    return (any_nonzero ? widest : widest_abs) / std::ldexp(1.0, -53);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

scene_input read_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw input_error(path + ": is a directory, not a scene file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw input_error(path + ": cannot read the scene file");
  // read at most one byte past the limit: /dev/zero or a pipe must not hang us
  std::string text(json_limits::bytes + 1, '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw input_error(path + ": cannot read the scene file");
  if (text.size() > json_limits::bytes)
    throw input_error(path + ": larger than the limit of " + std::to_string(json_limits::bytes) + " bytes");
  if (text.empty()) throw input_error(path + ": empty, not a scene file");
  return read_scene(parse_json(text));
}

}  // namespace appell
