// `appell eval`'s document: the JSON (through io/json_text.hpp's writer) and the text rendering of
// a printed evaluation (io/scene.hpp), and both in a scalar named at run time
// (io/evaluation_text.hpp).
#include "appell/io/evaluation_text.hpp"

#include "appell/io/json_text.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell {

nlohmann::ordered_json number_json(const printed_number& x) {
  if (x.interval) return {{"lo", x.lo}, {"hi", x.hi}};
  return {{"value", x.lo}};
}

void add_scalar_fields(nlohmann::ordered_json& j, const scalar_identity& s) {
  j["scalar"] = s.name;
  j["bits"] = s.bits;
  if (s.bits_requested) j["bits_requested"] = *s.bits_requested;
  j["rigorous"] = s.rigorous;
}

std::string format_json(const printed_evaluation& e) {
  auto group = [](const std::vector<printed_result>& items) {
    nlohmann::ordered_json g = nlohmann::ordered_json::object();
    for (const printed_result& r : items) {
      if (r.is_vector) {
        nlohmann::ordered_json v = nlohmann::ordered_json::array();
        for (const printed_number& x : r.values) v.push_back(number_json(x));
        g[r.name] = std::move(v);
      } else {
        g[r.name] = number_json(r.values.at(0));
      }
    }
    return g;
  };
  nlohmann::ordered_json j;
  j["model"] = e.model;
  add_scalar_fields(j, e.scalar);
  j["results"] = group(e.results);
  j["checks"] = group(e.checks);
  if (!e.derived.empty()) j["derived"] = group(e.derived);
  if (!e.contacts.empty()) {
    nlohmann::ordered_json contacts = nlohmann::ordered_json::object();
    for (const contact_judgement& c : e.contacts) {
      nlohmann::ordered_json one = {{"verdict", c.verdict}};
      if (!c.mu.empty()) one["mu"] = c.mu;
      if (c.required_mu) one["required_mu"] = number_json(*c.required_mu);
      if (c.center_of_pressure)
        one["center_of_pressure"] = {number_json((*c.center_of_pressure)[0]), number_json((*c.center_of_pressure)[1])};
      contacts[c.name] = std::move(one);
    }
    j["contacts"] = std::move(contacts);
  }
  return json_text(j, json_style::document);
}

/// A number in the text format: to_string's rendering, "[lo, hi]" for an interval.
std::string text_of(const printed_number& x) { return x.interval ? "[" + x.lo + ", " + x.hi + "]" : x.lo; }

std::string format_text(const printed_evaluation& e) {
  std::string s = e.model + " in " + e.scalar.name + " (" + std::to_string(e.scalar.bits) + " bits, " +
                  (e.scalar.rigorous ? "rigorous enclosures" : "point values") + ")\n";
  auto lines = [&](const std::vector<printed_result>& items, const char* heading) {
    s += heading;
    for (const auto& r : items)
      for (std::size_t j = 0; j < r.values.size(); ++j)
        s += "  " + r.name + (r.is_vector ? "[" + std::to_string(j) + "]" : "") + " = " + text_of(r.values[j]) + "\n";
  };
  lines(e.results, "results:\n");
  lines(e.checks, "checks (0 if consistent):\n");
  if (!e.derived.empty()) lines(e.derived, "derived state:\n");
  if (!e.contacts.empty()) s += "contacts (" + std::string(e.scalar.rigorous ? "proved" : "not proved: point values") + "):\n";
  for (const auto& c : e.contacts)
    s += "  " + c.name + ": " + c.verdict + (c.mu.empty() ? " (the normal force's sign only)" : " (mu = " + c.mu + ")") +
         (c.required_mu ? "; required mu " + json_text(number_json(*c.required_mu), json_style::spaced) : "") +
         (c.center_of_pressure ? "; centre of pressure (" + text_of((*c.center_of_pressure)[0]) + ", " +
                                     text_of((*c.center_of_pressure)[1]) + ")"
                               : "") +
         "\n";
  return s;
}

std::string evaluation_text(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits,
                            const std::string& format) {
  if (format != "json" && format != "text") throw input_error("--format: expected json or text, got '" + format + "'");
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    const evaluation<T> e = evaluate<T>(scene);
    return format == "json" ? format_json<T>(scene, e) : format_text<T>(scene, e);
  });
}

}  // namespace appell
