// appell/models/system.hpp -- the scene model "system": a mechanical system
// of the user's own, described by expressions (SCENES.md in this repository):
// parameters, coordinates, speeds (the coordinates' rates, or quasi-velocities
// with their kinematics), bodies, gravity, applied forces and couples, and
// named holonomic and nonholonomic constraints.  The mechanics are in
// system/motion.hpp; the reader (src/models/system.cpp) parses,
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
  /// `appell linearize`'s report (models/system_linearization.hpp's linearization_text).
  static std::string linearize(const model_input& in, const std::string& scalar, std::optional<unsigned> bits,
                               const std::string& format);

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
  /// the states of `appell reference`: src/models/system.cpp), else compiled.  The copy is the
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
  /// dynamics: the efforts that give the accelerations asked for, then the wrenches): the results,
  /// and where `checks`, the checks (each joint's virtual work).
  template <Scalar T>
  static void add_joints(const prepared<T>& m, const vector_t<T>& udot, const vector_t<T>* efforts,
                         evaluation_writer<T>& out, with_checks checks, const vector_t<T>* reactions = nullptr,
                         const tree_pass<T>* pass = nullptr) {
    using W = evaluation_writer<T>;
    struct site;
    const scratch<std::vector<joint_wrench_result<T>>, site> w_held;  // borrowed (linalg/scratch.hpp)
    // the links' contacts with the ground act on their links (joint_wrenches.hpp)
    joint_wrenches_into(m.sys, m.q, m.u, m.t, udot, efforts, *w_held, reactions, pass);
    const std::vector<joint_wrench_result<T>>& w = *w_held;
    const system_definition& d = *m.in->def;
    for (std::size_t k = 0; k < w.size(); ++k) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(m.sys.links[k].body)].joint;
      if (efforts && j.type != system_joint_definition::kind::fixed) out.scalar(W::results, j.name, "_effort", w[k].effort);
      out.vector(W::results, j.name, "_force", w[k].force);
      out.vector(W::results, j.name, "_moment", w[k].moment);
    }
    for (std::size_t k = 0; k < w.size() && checks == with_checks::yes; ++k) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(m.sys.links[k].body)].joint;
      if (j.type != system_joint_definition::kind::fixed) out.scalar(W::checks, j.name, "_virtual_work", w[k].residual);
    }
  }
  /// Inverse dynamics: the efforts P - Q = M u' + b - Q (Appell's equations), per coordinate.
  template <Scalar T>
  static void compute_inverse(const prepared<T>& m, evaluation_writer<T>& out, with_checks checks) {
    const expression_system<T> sys{&m.sys};
    const int n = sys.speeds();
    struct site;  // working storage borrowed (linalg/scratch.hpp)
    const scratch<appell_equations<T>, site> eq_held;
    const scratch<vector_t<T>, site> efforts_held, ones;
    const appell_equations<T>& eq = *eq_held;
    system_equations_into<T, T>(m.sys, m.q, m.u, m.t, *eq_held);
    vector_t<T>& efforts = *efforts_held;
    efforts.resize(n);
    for (int i = 0; i < n; ++i) {  // P - Q, P = M u' + b as eq.P computes it (detail::product's sums)
      T sum = eq.M(i, 0) * m.udot(0);
      for (int k = 1; k < n; ++k) sum += eq.M(i, k) * m.udot(k);
      const T P = sum + eq.b(i);
      efforts(i) = P - eq.Q(i);
    }
    ones->setOnes(n);
    if (checks == with_checks::yes)  // first among the checks, before the joints'
      out.scalar(evaluation_writer<T>::checks, "virtual_work_invariant", "",
                 virtual_work_residual(sys, eq, m.q, m.u, m.t, m.udot, *ones));
    add_joints(m, m.udot, &efforts, out, checks);
  }
  /// with_checks::no: no Lagrange multipliers and no eq. (4) (system_motion's `checks`), and none
  /// of the checks printed (the wrenches' virtual work is computed with them, and dropped).
  template <Scalar T>
  static evaluation<T> compute(const prepared<T>& m, with_checks checks) {
    evaluation<T> e;
    compute_into(m, e, checks);
    return e;
  }
  /// The same written over e (appell::compute_into: its names' and values' storage reused).
  template <Scalar T>
  static void compute_into(const prepared<T>& m, evaluation<T>& e, with_checks checks) {
    using W = evaluation_writer<T>;
    W out(e);
    if (m.in->inverse_dynamics) {
      compute_inverse(m, out, checks);
      out.finish();
      return;
    }
    const scratch<system_motion_result<T>, system_model> r_held;  // borrowed (linalg/scratch.hpp)
    system_motion_into(m.sys, m.q, m.u, m.t, checks == with_checks::yes, *r_held);
    const system_motion_result<T>& r = *r_held;
    for (std::size_t j = 0; j < m.in->acceleration_names.size(); ++j)
      out.scalar(W::results, m.in->acceleration_names[j], "", r.accelerations(static_cast<Eigen::Index>(j)));
    const auto& constraints = m.in->def->constraints;
    for (std::size_t c = 0; c < constraints.size(); ++c)
      out.scalar(W::results, constraints[c].name, "_reaction", r.reactions(static_cast<Eigen::Index>(c)));
    const auto& wrenches = m.in->def->wrenches;
    struct site;
    const scratch<std::vector<constraint_wrench_result<T>>, site> w_held;  // borrowed (linalg/scratch.hpp)
    const std::vector<constraint_wrench_result<T>>& w = *w_held;
    if (!wrenches.empty()) {
      constraint_wrenches_into(m.sys, m.q, m.t, r.reactions, *w_held);
      for (std::size_t k = 0; k < wrenches.size(); ++k) {
        out.vector(W::results, wrenches[k].name, "_force", w[k].force);
        out.vector(W::results, wrenches[k].name, "_moment", w[k].moment);
      }
    }
    if (!m.in->def->contacts.empty()) {  // can each contact hold? (reactions/contact.hpp)
      using std::sqrt;
      const auto& contacts = m.in->def->contacts;
      const scratch<std::vector<contact_force_result<T>>, site> f_held;
      contact_forces_into(m.sys, m.q, m.t, r.reactions, *f_held);
      const std::vector<contact_force_result<T>>& f = *f_held;
      for (std::size_t k = 0; k < contacts.size(); ++k) {
        const std::string& name = contacts[k].name;
        const T tangential = sqrt(dot(f[k].tangential, f[k].tangential));
        out.scalar(W::results, name, "_normal_force", f[k].normal);
        out.vector(W::results, name, "_friction_force", f[k].tangential);
        out.scalar(W::results, name, "_tangential_force", tangential);
        if (contacts[k].surface) {  // a sole: its couple and its contact wrench cone (reactions/wrench_cone.hpp)
          out.vector(W::results, name, "_moment", f[k].moment);
          const auto& ck = m.sys.contacts[k];
          const std::optional<T> mu = contacts[k].mu.empty() ? std::nullopt : std::optional<T>(from_decimal<T>(contacts[k].mu));
          const vec3<T> force(f[k].tangential(0), f[k].tangential(1), f[k].normal);
          e.contacts.push_back(judged_sole(name, force, f[k].moment, ck.half_x, ck.half_y, mu, contacts[k].mu));
          out.list(W::results, name, "_margins", sole_margin_values(force, f[k].moment, ck.half_x, ck.half_y, mu));
          continue;
        }
        // required mu in the contacts group: the results' list must not depend on the values
        e.contacts.push_back(judged_contact(name, f[k].normal, tangential, contacts[k].mu));
      }
    }
    if (!m.sys.links.empty())  // the tree's pass of system_motion_into reused where it kept one
      add_joints(m, r.accelerations, static_cast<const vector_t<T>*>(nullptr), out, checks, &r.reactions, &r.pass);
    if (checks == with_checks::yes) {
      out.scalar(W::checks, "virtual_work_invariant", "", r.virtual_work_residual);
      for (std::size_t c = 0; c < constraints.size(); ++c) {
        const auto i = static_cast<Eigen::Index>(c);
        out.scalar(W::checks, constraints[c].name, "_cotton_minus_lagrange", T(r.reactions(i) - r.multipliers(i)));
      }
      for (std::size_t k = 0; k < wrenches.size(); ++k)
        out.scalar(W::checks, wrenches[k].name, "_virtual_work", w[k].residual);
    }
    if (m.in->project) {  // the state certified, and how far the projection moved the given one
      using std::sqrt;
      const system_definition& d = *m.in->def;
      T dq2(0), du2(0);
      for (int i = 0; i < d.vars.coordinates; ++i) {
        out.scalar(W::derived, d.names[static_cast<std::size_t>(d.vars.q(i))], "", m.q(i));
        const T step = m.q(i) - value<T>(m.in->q_given[static_cast<std::size_t>(i)]);
        dq2 += step * step;
      }
      for (int j = 0; j < d.vars.speeds; ++j) {
        out.scalar(W::derived, d.names[static_cast<std::size_t>(d.vars.u(j))], "", m.u(j));
        if (std::find(m.in->solved.begin(), m.in->solved.end(), j) != m.in->solved.end()) continue;
        const T step = m.u(j) - value<T>(m.in->u_given[static_cast<std::size_t>(j)]);
        du2 += step * step;
      }
      out.scalar(W::derived, "coordinates_moved", "", T(sqrt(dq2)));
      out.scalar(W::derived, "speeds_moved", "", T(sqrt(du2)));
    }
    out.finish();
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
