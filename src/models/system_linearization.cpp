// The report of `appell linearize` (models/system_linearization.hpp): linearize_scene<T>
// (computed in the library's generated units, one per scalar) as JSON or text, in the scalar
// named at run time.
#include "appell/models/system_linearization.hpp"

#include <sstream>

#include "appell/build_options.hpp"
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
  auto number = [&](const T& x) {
    if (!json) return to_string(x);
    if constexpr (scalar_traits<T>::is_interval)
      return "{\"lo\": \"" + lower_string(x) + "\", \"hi\": \"" + upper_string(x) + "\"}";
    else
      return "{\"value\": \"" + to_string(x) + "\"}";
  };
  auto bound_text = [&](const P& p) { return lower_string(detail::from_bound<T>(p)); };
  const auto& names = d.names;
  auto coordinate = [&](int i) { return names[static_cast<std::size_t>(d.vars.q(i))]; };
  const std::string speed_name = names[static_cast<std::size_t>(d.vars.u(li.def.speed))];
  const std::string g_name = li.def.gravity >= 0 ? names[static_cast<std::size_t>(li.def.gravity)] : "1";
  const auto m = static_cast<Eigen::Index>(li.def.coordinates.size());
  auto kind_name = [](const critical_speed<T>& cs) {
    return cs.kind == critical_speed<T>::zero_root ? "zero_root" : "imaginary_pair";
  };

  std::ostringstream s;
  if (json) {
    s << "{\"model\": \"system\", " << format_scalar_fields<T>() << ",\n  \"coordinates\": [";
    for (Eigen::Index i = 0; i < m; ++i) s << (i ? ", " : "") << "\"" << coordinate(li.def.coordinates[static_cast<std::size_t>(i)]) << "\"";
    s << "], \"speed\": \"" << speed_name << "\", \"gravity\": \"" << g_name << "\",\n"
      << "  \"form\": \"M q'' + v C1 q' + (g K0 + v^2 K2) q = f\",\n";
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2}}) {
      s << "  \"" << name << "\": [";
      for (Eigen::Index i = 0; i < m; ++i) {
        s << (i ? ", [" : "[");
        for (Eigen::Index j = 0; j < m; ++j) s << (j ? ", " : "") << number((*X)(i, j));
        s << "]";
      }
      s << "],\n";
    }
    s << "  \"eigenvalues\": [";
    for (std::size_t k = 0; k < spectra.size(); ++k) {
      const auto [unstable, stable] = stability_of(spectra[k]);
      s << (k ? ",\n    " : "\n    ") << "{\"speed\": \"" << speed_texts[k] << "\", \"stable\": " << (stable ? "true" : "false")
        << ", \"certainly_unstable\": " << unstable << ", \"values\": [";
      for (std::size_t e = 0; e < spectra[k].size(); ++e) {
        const auto& x = spectra[k][e];
        s << (e ? ", " : "") << "{\"re\": " << number((x.real_part)) << ", \"im\": " << number((x.imaginary_part));
        if constexpr (scalar_traits<T>::is_interval) s << ", \"isolated\": " << (x.isolated ? "true" : "false");
        s << "}";
      }
      s << "]}";
    }
    s << "],\n  \"critical_speeds\": {\"from\": \"" << bound_text(from) << "\", \"to\": \"" << bound_text(to)
      << "\", \"steps\": " << li.steps << ", \"found\": [";
    for (std::size_t k = 0; k < critical.size(); ++k) {
      const auto& cs = critical[k];
      s << (k ? ",\n    " : "\n    ") << "{\"kind\": \"" << kind_name(cs) << "\", \"speed\": " << number((cs.speed));
      if constexpr (scalar_traits<T>::is_interval) s << ", \"unique\": " << (cs.unique ? "true" : "false");
      s << ", \"certainly_unstable_below\": " << cs.unstable_below << ", \"certainly_unstable_above\": " << cs.unstable_above << "}";
    }
    s << "]},\n  \"checks\": {";
    bool first = true;
    for (const auto& [name, X] : {std::pair<const char*, const matrix_t<T>*>{"stiffness_at_twice_the_speed", &r.stiffness_residual},
                                  {"damping_at_twice_the_speed", &r.damping_residual}, {"damping_at_rest", &r.damping_at_rest}}) {
      s << (first ? "\n    \"" : ",\n    \"") << name << "\": [";
      first = false;
      for (Eigen::Index i = 0; i < m; ++i) {
        s << (i ? ", [" : "[");
        for (Eigen::Index j = 0; j < m; ++j) s << (j ? ", " : "") << number(((*X)(i, j)));
        s << "]";
      }
      s << "]";
    }
    s << "}}\n";
    return s.str();
  }
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
