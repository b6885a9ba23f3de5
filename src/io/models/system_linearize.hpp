// The definition of linearize_scene<T> (io/models/system.hpp), included by the
// unit CMake generates for each standard scalar: the linearization runs the
// generic path on multi_dual numbers, one heavy instantiation per unit.
#pragma once

#include "appell/io/models/system.hpp"

namespace appell {

template <Scalar T>
linearization_report<T> linearize_scene(const system_input& in) {
  if (!in.linearize) throw input_error("linearize: the scene has no \"linearize\" section (SCENES.md)");
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
  out.steps = li.steps;
  out.critical = critical_speeds(r, Minv, out.from, out.to, li.steps);

  for (matrix_t<T>* X : {&r.M, &r.C1, &r.K0, &r.K2, &r.stiffness_residual, &r.damping_residual, &r.damping_at_rest})
    for (Eigen::Index i = 0; i < X->rows(); ++i)
      for (Eigen::Index j = 0; j < X->cols(); ++j) scope.finish((*X)(i, j));
  for (auto& spectrum : out.spectra)
    for (auto& e : spectrum) scope.finish(e.real_part), scope.finish(e.imaginary_part);
  for (auto& cs : out.critical) scope.finish(cs.speed);
  return out;
}

}  // namespace appell
