// The definition of linearize_scene<T> (models/system.hpp), included by the
// unit CMake generates for each standard scalar: the linearization runs the
// generic path on multi_dual numbers, one heavy instantiation per unit.
#pragma once

#include "appell/models/system.hpp"

namespace appell {

template <Scalar T>
linearization_report<T> linearize_scene(const system_input& in) {
  if (!in.linearize)
    throw input_error(!in.linearize_refusal.empty() ? in.linearize_refusal
                                                    : "linearize: the scene has no \"linearize\" section (SCENES.md)");
  const linearize_input& li = *in.linearize;
  const system_definition& d = *in.def;
  using P = bound_t<T>;
  linearization_report<T> out;
  evaluation_scope<T> scope;
  const compiled_system<T> c(d);
  vector_t<T> q(d.vars.coordinates), u(d.vars.speeds);
  for (int i = 0; i < d.vars.coordinates; ++i) q(i) = value<T>(li.q[static_cast<std::size_t>(i)]);
  for (int j = 0; j < d.vars.speeds; ++j) u(j) = value<T>(li.u[static_cast<std::size_t>(j)]);
  const T t = value<T>(in.t);
  // The reader checked the reference speed and g at 256 bits; a decimal that is not 0 may
  // still round to 0 in T (1e-999999 in double): C1 and K2 divide by it, K0 by g.
  {
    const decimal_field& v = li.u[static_cast<std::size_t>(li.def.speed)];
    if (possibly_zero(value<T>(v)))
      throw input_error(v.path + ": the reference speed " + v.text + " is 0 in " + scalar_traits<T>::name +
                        " (it underflows; a scalar of wider range, mpfr or mpfi, holds it)");
    if (li.def.gravity >= 0 && possibly_zero(c.parameters[static_cast<std::size_t>(li.def.gravity)]))
      throw input_error("linearize.gravity: the parameter " + d.names[static_cast<std::size_t>(li.def.gravity)] +
                        " is 0 in " + scalar_traits<T>::name + " (it underflows; K0 is the stiffness per unit g)");
  }
  linearized_equations<T>& r = out.equations;
  r = linearize(c, li.def, in.solved, q, u, t);
  const matrix_t<T> Minv = inverse_of(r.M);

  // The form g K0 + v^2 K2 and v C1: its residuals hold 0 (decided in interval types).
  if constexpr (scalar_traits<T>::is_interval)
    for (const auto& [what, R] : {std::pair<const char*, const matrix_t<T>*>{"the stiffness at twice the speed", &r.stiffness_residual},
                                  {"the damping at twice the speed", &r.damping_residual},
                                  {"the damping at rest", &r.damping_at_rest}})
      for (Eigen::Index i = 0; i < R->rows(); ++i)
        for (Eigen::Index j = 0; j < R->cols(); ++j)
          if (!possibly_zero((*R)(i, j)))
            throw certification_error(std::string("linearize: the equations are not of the form M q'' + v C1 q' + ") +
                                      "(g K0 + v^2 K2) q = f (" + what + " differs by " + to_string((*R)(i, j)) + ")");

  std::vector<T> speeds;
  for (const auto& v : li.eigenvalue_speeds) speeds.push_back(value<T>(v)), out.speed_texts.push_back(v.text);
  if (speeds.empty()) speeds.push_back(r.v0), out.speed_texts.push_back(li.u[static_cast<std::size_t>(li.def.speed)].text);
  for (const T& v : speeds) out.spectra.push_back(eigenvalues_at(r, Minv, v));
  out.from = li.from ? P(scalar_traits<T>::lower(value<T>(*li.from))) : P(0);
  out.to = li.to ? P(scalar_traits<T>::upper(value<T>(*li.to))) : P(P(2) * scalar_traits<T>::upper(r.v0));
  for (const auto& [name, b] : {std::pair<const char*, const P*>{"from", &out.from}, {"to", &out.to}})
    require_finite(detail::from_bound<T>(*b), std::string("critical_speeds.") + name);
  out.steps = li.steps;
  out.critical = critical_speeds(r, Minv, out.from, out.to, li.steps);

  // Every number of the report finite in T, or exit 3 naming it (an overflow: never a
  // number that is not one in the document).
  auto finish = [&](T& x, const std::string& name) {
    scope.finish(x);
    require_finite(x, name);
  };
  for (const auto& [name, X] : {std::pair<const char*, matrix_t<T>*>{"M", &r.M}, {"C1", &r.C1}, {"K0", &r.K0}, {"K2", &r.K2},
                                {"checks.stiffness_at_twice_the_speed", &r.stiffness_residual},
                                {"checks.damping_at_twice_the_speed", &r.damping_residual},
                                {"checks.damping_at_rest", &r.damping_at_rest}})
    for (Eigen::Index i = 0; i < X->rows(); ++i)
      for (Eigen::Index j = 0; j < X->cols(); ++j)
        finish((*X)(i, j), std::string(name) + "[" + std::to_string(i) + "][" + std::to_string(j) + "]");
  for (std::size_t k = 0; k < out.spectra.size(); ++k)
    for (std::size_t e = 0; e < out.spectra[k].size(); ++e) {
      const std::string where = "eigenvalues at " + out.speed_texts[k] + "[" + std::to_string(e) + "]";
      finish(out.spectra[k][e].real_part, where + ".re");
      finish(out.spectra[k][e].imaginary_part, where + ".im");
    }
  for (std::size_t k = 0; k < out.critical.size(); ++k)
    finish(out.critical[k].speed, "critical_speeds.found[" + std::to_string(k) + "].speed");
  return out;
}

}  // namespace appell
