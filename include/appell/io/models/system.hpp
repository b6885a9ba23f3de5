// appell/io/models/system.hpp -- the scene model "system": a mechanical system
// of the user's own, described by expressions (SCENES.md in this repository):
// parameters, coordinates, speeds (the coordinates' rates, or quasi-velocities
// with their kinematics), bodies, gravity, applied forces and couples, and
// named holonomic and nonholonomic constraints.  The mechanics are in
// system/motion.hpp; the reader (src/io/models/system.cpp) parses,
// differentiates and checks everything once, at 256 bits, on exact decimals.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "appell/io/model.hpp"
#include "appell/reactions/contact.hpp"
#include "appell/system/joint_wrenches.hpp"
#include "appell/system/motion.hpp"
#include "appell/system/linearize.hpp"

namespace appell {

/// The file's "linearize" section (`appell linearize`).
struct linearize_input {
  linearize_definition def;
  std::vector<decimal_field> q, u;               ///< the reference motion: the state (projected, with "project") with "about" applied
  std::vector<std::pair<int, decimal_field>> about_q, about_u;  ///< what "about" sets: (coordinate or speed, value)
  std::vector<decimal_field> eigenvalue_speeds;  ///< where to enclose the eigenvalues (default: the reference speed)
  std::optional<decimal_field> from, to;         ///< where to look for critical speeds (default 0 to twice the reference speed)
  int steps = 200;                               ///< grid intervals of that search
};

struct system_input : model_input {
  std::shared_ptr<const system_definition> def;
  std::vector<decimal_field> q, u;  ///< the state: coordinates and speeds
  decimal_field t;                  ///< the time (default 0)
  std::vector<int> solved;          ///< speeds computed from the constraints (solve_speeds)
  std::vector<std::string> acceleration_names;  ///< per speed: q_ddot (rates) or u_dot
  std::optional<linearize_input> linearize;     ///< the "linearize" section, if any and valid
  /// Why the "linearize" section was refused, if it was: `eval` and the motion ignore the
  /// section (SCENES.md), `linearize` reports this (exit 2).
  std::string linearize_refusal;
  /// "project": accept a state off the constraints and certify the values at its projection
  /// onto them (SCENES.md), moved by at most this in q and in u.  The reader replaces q and u
  /// by the projection, at 256 bits written as 90-digit decimals; the state as given is kept.
  std::optional<decimal_field> project;
  std::vector<decimal_field> q_given, u_given;
  /// "accelerations": inverse dynamics (the efforts of a tree's joints that give these u').
  bool inverse_dynamics = false;
  std::vector<decimal_field> udot;
};

struct system_model {
  static constexpr const char* name = "system";
  using input = system_input;
  static input read(object_reader& scene);

  template <Scalar T>
  struct prepared {
    const system_input* in;
    compiled_system<T> sys;
    vector_t<T> q, u;
    T t;
    vector_t<T> udot;  ///< inverse dynamics: the accelerations given
  };
  /// The system compiled in T for the input's definition: a copy of the last one compiled on this
  /// thread for the same definition at the same working precision (a definition read once serves
  /// the states of `appell reference`: src/io/models/system.cpp), else compiled.  The copy is the
  /// same tapes and constants (a compiled term is an index into its tape).
  template <Scalar T>
  static compiled_system<T> compiled(const input& in) {
    struct kept {
      std::weak_ptr<const system_definition> def;
      unsigned bits = 0;
      std::optional<compiled_system<T>> sys;
    };
    thread_local kept k;
    const unsigned bits = mp_precision_bits();
    if (!k.sys || k.def.lock() != in.def || k.bits != bits) {
      compiled_system<T> sys(*in.def);
      k.sys = std::move(sys);
      k.def = in.def;
      k.bits = bits;
    }
    return *k.sys;
  }
  template <Scalar T>
  static prepared<T> prepare(const input& in) {
    vector_t<T> q(static_cast<Eigen::Index>(in.q.size())), u(static_cast<Eigen::Index>(in.u.size()));
    for (std::size_t i = 0; i < in.q.size(); ++i) q(static_cast<Eigen::Index>(i)) = value<T>(in.q[i]);
    for (std::size_t j = 0; j < in.u.size(); ++j) u(static_cast<Eigen::Index>(j)) = value<T>(in.u[j]);
    prepared<T> p{&in, compiled<T>(in), q, u, value<T>(in.t), vector_t<T>()};
    if (in.inverse_dynamics) {
      p.udot.resize(static_cast<Eigen::Index>(in.udot.size()));
      for (std::size_t j = 0; j < in.udot.size(); ++j) p.udot(static_cast<Eigen::Index>(j)) = value<T>(in.udot[j]);
    }
    if (!in.solved.empty()) solve_dependent_speeds(p.sys, p.q, p.u, p.t, in.solved);
    return p;
  }
  /// A tree's joints: each one's wrench (forward dynamics: with the accelerations r; inverse
  /// dynamics: the efforts that give the accelerations asked for, then the wrenches).
  template <Scalar T>
  static void add_joints(const prepared<T>& m, const vector_t<T>& udot, const vector_t<T>* efforts, evaluation<T>& e,
                         with_checks checks) {
    const std::vector<joint_wrench_result<T>> w = joint_wrenches(m.sys, m.q, m.u, m.t, udot, efforts);
    const system_definition& d = *m.in->def;
    for (std::size_t k = 0; k < w.size(); ++k) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(m.sys.links[k].body)].joint;
      if (efforts && j.type != system_joint_definition::kind::fixed)
        e.results.push_back(detail::scalar_result(j.name + "_effort", w[k].effort));
      e.results.push_back(detail::vector_result(j.name + "_force", w[k].force));
      e.results.push_back(detail::vector_result(j.name + "_moment", w[k].moment));
    }
    for (std::size_t k = 0; k < w.size() && checks == with_checks::yes; ++k) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(m.sys.links[k].body)].joint;
      if (j.type != system_joint_definition::kind::fixed)
        e.checks.push_back(detail::scalar_result(j.name + "_virtual_work", w[k].residual));
    }
  }
  /// Inverse dynamics: the efforts P - Q = M u' + b - Q (Appell's equations), per coordinate.
  template <Scalar T>
  static evaluation<T> compute_inverse(const prepared<T>& m, with_checks checks) {
    const expression_system<T> sys{&m.sys};
    const appell_equations<T> eq = gibbs_appell(sys, m.q, m.u, m.t);
    const vector_t<T> efforts = eq.P(m.udot) - eq.Q;
    evaluation<T> e;
    add_joints(m, m.udot, &efforts, e, checks);
    if (checks == with_checks::no) return e;
    e.checks.insert(e.checks.begin(), detail::scalar_result("virtual_work_invariant",
        virtual_work_residual(sys, eq, m.q, m.u, m.t, m.udot, vector_t<T>(vector_t<T>::Ones(sys.speeds())))));
    return e;
  }
  /// with_checks::no: no Lagrange multipliers and no eq. (4) (system_motion's `checks`), and none
  /// of the checks printed (the wrenches' virtual work is computed with them, and dropped).
  template <Scalar T>
  static evaluation<T> compute(const prepared<T>& m, with_checks checks) {
    if (m.in->inverse_dynamics) return compute_inverse(m, checks);
    const system_motion_result<T> r = system_motion(m.sys, m.q, m.u, m.t, checks == with_checks::yes);
    evaluation<T> e;
    for (std::size_t j = 0; j < m.in->acceleration_names.size(); ++j)
      e.results.push_back(detail::scalar_result(m.in->acceleration_names[j], T(r.accelerations(static_cast<Eigen::Index>(j)))));
    const auto& constraints = m.in->def->constraints;
    for (std::size_t c = 0; c < constraints.size(); ++c)
      e.results.push_back(detail::scalar_result(constraints[c].name + "_reaction", T(r.reactions(static_cast<Eigen::Index>(c)))));
    const auto& wrenches = m.in->def->wrenches;
    std::vector<named_result<T>> wrench_checks;
    if (!wrenches.empty()) {
      const std::vector<constraint_wrench_result<T>> w = constraint_wrenches(m.sys, m.q, m.t, r.reactions);
      for (std::size_t k = 0; k < wrenches.size(); ++k) {
        e.results.push_back(detail::vector_result(wrenches[k].name + "_force", w[k].force));
        e.results.push_back(detail::vector_result(wrenches[k].name + "_moment", w[k].moment));
      }
      for (std::size_t k = 0; k < wrenches.size(); ++k)
        wrench_checks.push_back(detail::scalar_result(wrenches[k].name + "_virtual_work", w[k].residual));
    }
    if (!m.in->def->contacts.empty()) {  // can each contact hold? (reactions/contact.hpp)
      using std::sqrt;
      const auto& contacts = m.in->def->contacts;
      const std::vector<contact_force_result<T>> f = contact_forces(m.sys, m.q, m.t, r.reactions);
      for (std::size_t k = 0; k < contacts.size(); ++k) {
        const std::string& name = contacts[k].name;
        const T tangential = sqrt(dot(f[k].tangential, f[k].tangential));
        e.results.push_back(detail::scalar_result(name + "_normal_force", f[k].normal));
        e.results.push_back(detail::vector_result(name + "_friction_force", f[k].tangential));
        e.results.push_back(detail::scalar_result(name + "_tangential_force", tangential));
        // required mu in the contacts group: the results' list must not depend on the values
        e.contacts.push_back(judged_contact(name, f[k].normal, tangential, contacts[k].mu));
      }
    }
    if (!m.sys.links.empty()) add_joints(m, r.accelerations, static_cast<const vector_t<T>*>(nullptr), e, checks);
    if (checks == with_checks::yes) {
      e.checks.push_back(detail::scalar_result("virtual_work_invariant", r.virtual_work_residual));
      for (std::size_t c = 0; c < constraints.size(); ++c) {
        const auto i = static_cast<Eigen::Index>(c);
        e.checks.push_back(detail::scalar_result(constraints[c].name + "_cotton_minus_lagrange",
                                                 T(r.reactions(i) - r.multipliers(i))));
      }
      e.checks.insert(e.checks.end(), wrench_checks.begin(), wrench_checks.end());
    }
    if (m.in->project) {  // the state certified, and how far the projection moved the given one
      using std::sqrt;
      const system_definition& d = *m.in->def;
      T dq2(0), du2(0);
      for (int i = 0; i < d.vars.coordinates; ++i) {
        e.derived.push_back(detail::scalar_result(d.names[static_cast<std::size_t>(d.vars.q(i))], T(m.q(i))));
        const T step = m.q(i) - value<T>(m.in->q_given[static_cast<std::size_t>(i)]);
        dq2 += step * step;
      }
      for (int j = 0; j < d.vars.speeds; ++j) {
        e.derived.push_back(detail::scalar_result(d.names[static_cast<std::size_t>(d.vars.u(j))], T(m.u(j))));
        if (std::find(m.in->solved.begin(), m.in->solved.end(), j) != m.in->solved.end()) continue;
        const T step = m.u(j) - value<T>(m.in->u_given[static_cast<std::size_t>(j)]);
        du2 += step * step;
      }
      e.derived.push_back(detail::scalar_result("coordinates_moved", T(sqrt(dq2))));
      e.derived.push_back(detail::scalar_result("speeds_moved", T(sqrt(du2))));
    }
    return e;
  }
};

APPELL_EXTERN_MODEL(system_model)

/// `appell linearize`: a system file's linearized equations about the motion
/// its "linearize" section names, their eigenvalues at the speeds it lists, and
/// the speeds where a real part crosses 0 (system/linearize.hpp), in T.
template <Scalar T>
struct linearization_report {
  linearized_equations<T> equations;
  std::vector<std::string> speed_texts;  ///< where the eigenvalues are enclosed
  std::vector<std::vector<root_enclosure<T>>> spectra;
  bound_t<T> from{}, to{};  ///< the critical speeds' search range and grid
  int steps = 0;
  std::vector<critical_speed<T>> critical;
};

/// The report in T (under T's evaluation policy; results rounded outward as
/// `eval`'s).  input_error without a "linearize" section; certification_error
/// when the equations are not of the benchmark form (interval types decide it).
template <Scalar T>
linearization_report<T> linearize_scene(const system_input& in);

// Instantiated once per standard scalar, each in a unit of its own (CMakeLists.txt).
#define APPELL_DETAIL_EXTERN_LINEARIZE(ctx, T, name) \
  extern template linearization_report<T> linearize_scene<T>(const system_input&);
APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_LINEARIZE, )
#undef APPELL_DETAIL_EXTERN_LINEARIZE

}  // namespace appell
