// The report of `appell linearize` (models/system_linearization.hpp): linearize_scene<T>
// (computed in the library's generated units, one per scalar) as JSON (io/json_text.hpp's writer)
// or text, in the scalar named at run time.
#include "appell/models/system_linearization.hpp"

#include <sstream>

#include "appell/build_options.hpp"
#include "appell/io/json_text.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell {

namespace {

template <Scalar T>
std::string report_in(const system_input& in, const std::string& format) {
  const linearization_report<T> report = linearize_scene<T>(in);
  const linearize_input& li = *in.linearize;
  const system_definition& d = *in.def;
  using P = bound_t<T>;
  const linearized_equations<T>& r = report.equations;
  const auto& spectra = report.spectra;
  const auto& speed_texts = report.speed_texts;
  const auto& critical = report.critical;
  const P from = report.from, to = report.to;
  const bool json = format == "json";
  auto number_of = [](const T& x) { return number_json(printed(x)); };
  auto bound_text = [&](const P& p) { return lower_string(detail::from_bound<T>(p)); };
  const auto& names = d.names;
  auto coordinate = [&](int i) { return names[static_cast<std::size_t>(d.vars.q(i))]; };
  const std::string speed_name = names[static_cast<std::size_t>(d.vars.u(li.def.speed))];
  const std::string g_name = li.def.gravity >= 0 ? names[static_cast<std::size_t>(li.def.gravity)] : "1";
  const auto m = static_cast<Eigen::Index>(li.def.coordinates.size());
  auto kind_name = [](const critical_speed<T>& cs) {
    return cs.kind == critical_speed<T>::zero_root ? "zero_root" : "imaginary_pair";
  };

  if (json) {
    using J = nlohmann::ordered_json;
    auto matrix = [&](const matrix_t<T>& X) {
      J rows = J::array();
      for (Eigen::Index i = 0; i < m; ++i) {
        J row = J::array();
        for (Eigen::Index j = 0; j < m; ++j) row.push_back(number_of(X(i, j)));
        rows.push_back(std::move(row));
      }
      return rows;
    };
    J j;
    j["model"] = "system";
    add_scalar_fields(j, identity_of<T>());
    J coordinates = J::array();
    for (Eigen::Index i = 0; i < m; ++i) coordinates.push_back(coordinate(li.def.coordinates[static_cast<std::size_t>(i)]));
    j["coordinates"] = std::move(coordinates);
    j["speed"] = speed_name;
    j["gravity"] = g_name;
    j["form"] = "M q'' + v C1 q' + (g K0 + v^2 K2) q = f";
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2}})
      j[name] = matrix(*X);
    J eigenvalues = J::array();
    for (std::size_t k = 0; k < spectra.size(); ++k) {
      const auto [unstable, stable] = stability_of(spectra[k]);
      J values = J::array();
      for (const auto& x : spectra[k]) {
        J v = {{"re", number_of(x.real_part)}, {"im", number_of(x.imaginary_part)}};
        if constexpr (scalar_traits<T>::is_interval) v["isolated"] = x.isolated;
        values.push_back(std::move(v));
      }
      eigenvalues.push_back({{"speed", speed_texts[k]}, {"stable", stable}, {"certainly_unstable", unstable}, {"values", std::move(values)}});
    }
    j["eigenvalues"] = std::move(eigenvalues);
    J found = J::array();
    for (const auto& cs : critical) {
      J c = {{"kind", kind_name(cs)}, {"speed", number_of(cs.speed)}};
      if constexpr (scalar_traits<T>::is_interval) c["unique"] = cs.unique;
      c["certainly_unstable_below"] = cs.unstable_below;
      c["certainly_unstable_above"] = cs.unstable_above;
      found.push_back(std::move(c));
    }
    j["critical_speeds"] = {{"from", bound_text(from)}, {"to", bound_text(to)}, {"steps", li.steps}, {"found", std::move(found)}};
    J checks = J::object();
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"stiffness_at_twice_the_speed", &r.stiffness_residual},
                                  {"damping_at_twice_the_speed", &r.damping_residual}, {"damping_at_rest", &r.damping_at_rest}})
      checks[name] = matrix(*X);
    j["checks"] = std::move(checks);
    return json_text(j, json_style::document);
  }
  std::ostringstream s;
  s << "linearized about " << speed_name << " = " << li.u[static_cast<std::size_t>(li.def.speed)].text << " in "
    << scalar_traits<T>::name << " (" << scalar_traits<T>::precision_bits() << " bits, "
    << (scalar_traits<T>::is_rigorous ? "rigorous enclosures" : "point values") << ")\n"
    << "M q'' + v C1 q' + (" << g_name << " K0 + v^2 K2) q = f,  q = (";
  for (Eigen::Index i = 0; i < m; ++i) s << (i ? ", " : "") << coordinate(li.def.coordinates[static_cast<std::size_t>(i)]);
  s << "), v = " << speed_name << "\n";
  for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2}})
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j) s << "  " << name << "(" << i + 1 << "," << j + 1 << ") = " << to_string((*X)(i, j)) << "\n";
  for (std::size_t k = 0; k < spectra.size(); ++k) {
    const auto [unstable, stable] = stability_of(spectra[k]);
    s << "eigenvalues at v = " << speed_texts[k] << (stable ? " (stable)" : unstable ? " (unstable)" : "") << ":\n";
    for (const auto& x : spectra[k])
      s << "  " << to_string((x.real_part)) << " + i " << to_string((x.imaginary_part)) << "\n";
  }
  s << "speeds in [" << bound_text(from) << ", " << bound_text(to) << "] where a real part crosses 0 (" << li.steps
    << " grid steps):\n";
  for (const auto& cs : critical)
    s << "  " << (cs.kind == critical_speed<T>::zero_root ? "a real eigenvalue through 0 (capsize-like)"
                                                          : "a pair +-i w on the imaginary axis (weave-like)")
      << ": v = " << to_string((cs.speed)) << (cs.unique ? " (unique)" : "") << "; unstable eigenvalues "
      << cs.unstable_below << " below, " << cs.unstable_above << " above\n";
  return s.str();
}

}  // namespace

std::string system_model::linearize(const model_input& in, const std::string& scalar, std::optional<unsigned> bits,
                                    const std::string& format) {
  return linearization_text(dynamic_cast<const system_input&>(in), scalar, bits, format);
}

std::string linearization_text(const system_input& in, const std::string& scalar, std::optional<unsigned> bits,
                              const std::string& format) {
  if (format != "json" && format != "text") throw input_error("--format: expected json or text, got '" + format + "'");
  if (!in.linearize)
    throw input_error(!in.linearize_refusal.empty() ? in.linearize_refusal
                                                    : "linearize: the scene has no \"linearize\" section (SCENES.md)");
#ifdef APPELL_EVAL_ONLY
  (void)scalar;
  (void)bits;
  throw input_error(left_out_message("linearize"));
#else
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) { return report_in<T>(in, format); });
#endif
}

}  // namespace appell
