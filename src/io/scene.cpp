// The scene layer's model-independent part: the registry lookup, reading and
// validating scene files, and the measured error amplification.
#include "appell/io/scene.hpp"
#include "appell/io/amplification.hpp"

#include <filesystem>
#include <fstream>
#include <limits>

#include "appell/io/files.hpp"
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

std::string detail::component_name(const std::string& name, bool is_vector, std::size_t i) {
  return is_vector ? name + "[" + std::to_string(i) + "]" : name;
}

namespace {
const model_entry* registered_model(const std::string& name) {
  for (const model_entry* m : registered_models())
    if (m->name == name) return m;
  return nullptr;
}
}  // namespace

const model_entry& find_model(const std::string& name) {
  if (const model_entry* m = registered_model(name)) return *m;
  std::string known;
  for (const model_entry* m : registered_models()) known += (known.empty() ? "" : ", ") + m->name;
  throw input_error("model: unknown model '" + name + "' (known: " + known + ")");
}

const model_entry* scene_model(const json_value& scene) {
  const json_value* model = scene.type == json_value::kind::object ? scene.find("model") : nullptr;
  if (!model || model->type != json_value::kind::string) return nullptr;
  return registered_model(model->text);
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

namespace {

/// The largest relative width of the results bounded away from 0 (a result that may be 0
/// has no relative accuracy to lose; the absolute widths if all may be 0), over 2^-53;
/// infinity where a result is not finite.
template <class I>
double amplification_of(const evaluation<I>& e) {
  using B = bound_t<I>;
  double widest = 0, widest_abs = 0;
  bool any_nonzero = false;
  for (const auto& r : e.results)
    for (const I& x : r.values) {
      if (!is_finite(x)) return std::numeric_limits<double>::infinity();
      const B w = scalar_traits<I>::width(x), lo = scalar_traits<I>::lower(x), hi = scalar_traits<I>::upper(x);
      widest_abs = std::max(widest_abs, approx_double(w));
      if (lo > 0 || hi < 0) {
        using std::abs;
        any_nonzero = true;
        const B m = abs(lo) < abs(hi) ? B(abs(lo)) : B(abs(hi));
        widest = std::max(widest, approx_double(B(w / m)));
      }
    }
  return (any_nonzero ? widest : widest_abs) / std::ldexp(1.0, -53);
}

}  // namespace

double error_amplification(const scene_input& scene, const evaluation<interval>& e) {
  const double a = amplification_of(e);
  return std::isfinite(a) ? a : error_amplification(scene);
}

double error_amplification(const scene_input& scene) {
  // interval<double>: the rounding of double arithmetic, enclosed
  try {
    const double a = amplification_of(compute<interval>(prepare<interval>(scene), with_checks::no));
    if (std::isfinite(a)) return a;
  } catch (const std::exception&) {
  }
  // Outside double's range (results near 1e999999 in mpfr, say) the same interval evaluation
  // with 53-bit bounds in MPFR's exponent range: mpfi at 53 bits in every operation (no guard
  // bits, so its widths are double's), each operation rounded outward by MPFI.
  try {
    const mp_precision_scope bits(53);
    return amplification_of(prepare<mpfi>(scene).run(with_checks::no));
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

std::string& scene_directory() {
  static thread_local std::string dir;
  return dir;
}

std::string scene_relative_path(const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_relative() && !scene_directory().empty()) return (std::filesystem::path(scene_directory()) / p).string();
  return path;
}

std::string read_text_file(const std::string& path, std::size_t limit, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw input_error(path + ": is a directory, not " + what);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw input_error(path + ": cannot read " + what);
  // In blocks, up to one byte past the limit: a large limit (the states file's 1 GiB) costs
  // nothing for a small file, and /dev/zero or a pipe cannot hang the command.
  std::string text;
  char buffer[1 << 16];
  while (text.size() <= limit && file.read(buffer, sizeof buffer).gcount() > 0)
    text.append(buffer, static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw input_error(path + ": cannot read " + what);
  if (text.size() > limit)
    throw input_error(path + ": larger than the limit of " + std::to_string(limit) + " bytes for " + what);
  return text;
}

scene_input read_scene_file(const std::string& path) {
  const std::string text = read_text_file(path, json_limits::bytes, "a scene file");
  if (text.empty()) throw input_error(path + ": empty, not a scene file");
  // paths in the scene (a URDF's "file") are relative to its directory
  const scene_directory_scope scope(std::filesystem::path(path).parent_path().string());
  return read_scene(parse_json(text));
}

}  // namespace appell
