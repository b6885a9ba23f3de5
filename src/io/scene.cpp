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

symmetric_top_fields read_symmetric_top(object_reader& scene) {
  symmetric_top_fields in;
  object_reader top = scene.object("top");
  in.A = top.number("A");
  in.C = top.number("C");
  in.mass = top.number("mass");
  in.l = top.number("l");
  top.finish();
  require_positive(top, "A", in.A);
  require_positive(top, "C", in.C);
  require_positive(top, "mass", in.mass);
  // A >= m l^2 and C <= 2 (A - m l^2), exactly.
  if (decimal_sign_of_polynomial({{1, {in.A.text}}, {-1, {in.mass.text, in.l.text, in.l.text}}}) < 0)
    throw input_error(top.path("A") + ": a body of revolution has A >= m l^2 (A = " + in.A.text + ", m l^2 = " +
                      in.mass.text + " * " + in.l.text + "^2)");
  if (decimal_sign_of_polynomial({{2, {in.A.text}}, {-2, {in.mass.text, in.l.text, in.l.text}}, {-1, {in.C.text}}}) < 0)
    throw input_error(top.path("C") + ": a body of revolution has C <= 2 (A - m l^2) (C = " + in.C.text + ")");
  return in;
}

void require_angle_in_range(const object_reader& r, const std::string& key, const decimal_field& d) {
  // Angles beyond 2^40 rad are no physical state, and their sines cost time in
  // the exponent (MPFR, MPFI) or lose every digit (QD): refused, exactly.
  if (decimal_sign_of_sum({{1, d.text}, {-1, "1099511627776"}}) > 0 ||
      decimal_sign_of_sum({{1, d.text}, {1, "1099511627776"}}) < 0)
    throw input_error(r.path(key) + ": an angle beyond 2^40 rad, got " + printable(d.text));
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
