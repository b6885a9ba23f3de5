// appell/models/system.hpp -- the scene model "system": a mechanical system
// of the user's own, described by expressions (SCENES.md in this repository):
// parameters, coordinates, speeds (the coordinates' rates, or quasi-velocities
// with their kinematics), bodies, gravity, applied forces and couples, and
// named holonomic and nonholonomic constraints.  The model's home: its input,
// prepare, evaluation and results here; its reader (src/models/system.cpp)
// parses, differentiates and checks everything once, at 256 bits, on exact
// decimals; the mechanics are the library's (system/motion.hpp, the tree
// recursions of system/tree.hpp).  Below the evaluation: `appell linearize`'s
// report (linearize_scene, its definition at the end, compiled in generated
// units), and how a system file moves (system_problem, model_motion<system_model>,
// for simulate, enclose, horizon and reference --trajectory):
//
// The state is x = (q, v_a[, t]): every coordinate, the free speeds v_a, and
// the time when the system depends on it (carried as a component, t' = 1, so
// that the integrators stay autonomous).  The free speeds are those the file
// does not list in solve_speeds; without solve_speeds, those left free by
// pivoting on the constraints' matrix at the initial state (speeds.hpp,
// adapt_speeds).  At each evaluation of the right-hand side the other speeds
// are solved from the constraints, A(q, t) u = a(q, t), so that every velocity
// constraint holds exactly along the motion; then
//   q'   = the file's kinematics at (q, u, t)   (q' = W u + w),
//   v_a' = Cotton's free accelerations  (the Gibbs-Appell equations in the
//          speeds adapted to the constraints, the free speeds' columns only:
//          cotton_free_accelerations, the path `appell eval` runs).
// A holonomic constraint f(q, t) = 0 is kept by its rate (A u = a is its time
// derivative): f(q(t), t) is constant along the true motion, and is reported as
// an invariant that is 0 in truth (its enclosure must contain 0 at every step).
// This is the exact motion of the constrained system: nothing is projected or
// stabilised, so an enclosure of x encloses the true motion.
//
// Results along the motion (each enclosed over whole steps by `enclose`): every
// speed's acceleration (as eval names them), the solved speeds, each
// constraint's reaction (Cotton's Q'_c), each wrench's force and moment, and
// each contact's normal force and friction force (the commands judge them).
// Invariants: the energy when it is conserved (energy_conserved below), and
// the holonomic constraints' residuals.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "appell/derivatives/jet.hpp"
#include "appell/io/model.hpp"
#include "appell/io/model_motion.hpp"
#include "appell/ode/enclose.hpp"
#include "appell/ode/taylor.hpp"
#include "appell/scalar/decimal.hpp"
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
  /// `appell linearize`'s report (linearization_text, below).
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

/// The report of `appell linearize` (SCENES.md, "linearize") in `scalar` (mpfr, mpfi and arb at
/// `bits`, default 256), `format` "json" or "text": the linearized equations about the steady
/// motion the "linearize" section names, the eigenvalues, and the speeds where a real part
/// crosses 0.  Scalar-free (src/models/system.cpp).  input_error for a scene
/// without a "linearize" section, an unknown format or scalar, or a build without the
/// linearization (APPELL_EVAL_ONLY).
std::string linearization_text(const system_input& in, const std::string& scalar, std::optional<unsigned> bits,
                               const std::string& format);


// ---- how a system file moves: the model module's motion (io/model_motion.hpp) ----

/// Whether any expression of the system depends on t (then t is carried in the state).
inline bool depends_on_time(const system_definition& d) {
  const int t = d.vars.t();
  auto timed = [&](const shared_expression& e) { return e && e->depends_on(t); };
  auto timed_d = [&](const differentiated_expression& e) { return bool(e.dt) || timed(e.value); };
  for (const auto& g : d.gravity)
    if (timed(g)) return true;
  for (const auto& k : d.kinematics)
    if (timed(k)) return true;
  for (const auto& b : d.bodies) {
    for (std::size_t i = 0; i < 3; ++i)
      if (timed(b.force[i]) || timed(b.couple[i]) || timed(b.omega[i]) || timed(b.velocity[i]) || timed_d(b.center[i]))
        return true;
    if (timed(b.mass)) return true;
    for (const auto& e : b.inertia)
      if (timed(e)) return true;
    for (const auto& [axis, angle] : b.rotations)
      if (timed_d(angle)) return true;
    if (b.has_matrix)
      for (const auto& m : b.matrix)
        if (timed_d(m)) return true;
    // a link's actuator: a torque or force given as a function of time (a push, a logged
    // controller's ramp) makes the motion non-autonomous too
    if (b.is_link && timed(b.joint.effort)) return true;
  }
  for (const auto& c : d.constraints) {
    if (timed_d(c.f) || timed(c.g)) return true;
    for (std::size_t i = 0; i < 3; ++i)
      if (timed(c.point[i]) || timed(c.direction[i]) || timed(c.support[i])) return true;
  }
  return false;
}

/// Whether the system's energy sum (m v^2 / 2 + omega . I omega / 2) - sum m g . G is a
/// first integral, proved from the expressions as written: nothing depends on t, no applied
/// force or couple but gravity, a body on its own axes has a centre where there is gravity (the
/// potential needs it), and the kinematics and the nonholonomic constraints are homogeneous in
/// the speeds (no constraint then does work: its rows read A(q) u = 0).
inline bool energy_conserved(const system_definition& d) {
  if (depends_on_time(d)) return false;
  std::vector<int> speeds;
  for (int j = 0; j < d.vars.speeds; ++j) speeds.push_back(d.vars.u(j));
  for (const auto& k : d.kinematics)
    if (k && !k->vanishes_when_zero(speeds)) return false;
  const bool has_gravity = d.gravity[0] || d.gravity[1] || d.gravity[2];
  for (const auto& b : d.bodies) {
    // a link of a tree: its centre on the fixed axes (the potential) is not formed, and its
    // joint's effort works; no energy invariant is claimed for a tree
    if (b.is_link) return false;
    for (std::size_t i = 0; i < 3; ++i)
      if (b.force[i] || b.couple[i]) return false;
    if (has_gravity && b.body_axes && !b.center[0].value && !b.center[1].value && !b.center[2].value) return false;
  }
  for (const auto& c : d.constraints) {
    if (!c.holonomic && c.body < 0 && !c.g->vanishes_when_zero(speeds)) return false;
    if (c.support[0] || c.support[1] || c.support[2]) return false;  // a moving support works
  }
  return true;
}

/// A system file's motion as an ordinary differential equation x' = f(x) (ode/).
/// Dim: 0 for the point integrator (any size); runtime_slopes (derivatives/slope.hpp) for
/// enclose at the state's own size, the slopes in vectors (a tree of links: any size);
/// otherwise the compile-time size the enclosure's Jacobians and slopes are carried in, at
/// least size(): the state is then padded with constant zeros (x' = 0 there), which
/// state_names() leaves out.
template <Scalar T, int Dim = 0>
struct system_problem {
  static constexpr int dim = Dim;
  std::shared_ptr<const system_model::prepared<T>> model;  ///< the compiled system (it refers to the input)
  std::vector<int> free_columns, bound_columns;           ///< the free speeds v_a, the solved ones
  bool timed = false;    ///< t carried as the last state component
  bool energy = false;   ///< the energy is a first integral (energy_conserved)
  std::vector<std::string> names;

  int coordinates() const { return model->sys.def->vars.coordinates; }
  int speeds() const { return model->sys.def->vars.speeds; }
  int constraints() const { return static_cast<int>(model->sys.constraints.size()); }
  /// The state's components (without the padding).
  int size() const { return coordinates() + static_cast<int>(free_columns.size()) + (timed ? 1 : 0); }
  const std::vector<std::string>& state_names() const { return names; }

  /// The most components the generic path is carried in at a size fixed at compile time (its
  /// 3 x 3 matrices of multi_dual slopes outgrow Eigen's fixed-size storage beyond); a larger
  /// state takes the slopes sized at run time (runtime_slopes), the generic path or the tree's.
  static constexpr int generic_capacity = 12;
  static_assert(Dim == runtime_slopes || (Dim >= 0 && Dim <= generic_capacity),
                "system_problem: a compile-time capacity above 12; a larger state takes runtime_slopes");
  bool recursion() const { return tree_links_apply(model->sys); }

  /// The same motion carried in D components.
  template <int D>
  system_problem<T, D> with_capacity() const {
    return {model, free_columns, bound_columns, timed, energy, names};
  }

  /// The times where the right-hand side is not smooth (every table's breakpoints, sorted, each
  /// once): enclose and simulate end a step at each (SCENES.md, "tables").
  std::vector<double> breakpoints() const {
    std::vector<double> b;
    for (const auto& table : model->sys.def->tables) b.insert(b.end(), table->times.begin(), table->times.end());
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
  }

  /// input_error, naming the table, unless every table is given from `from` (the time of the
  /// motion's start) to `elapsed` after it (a table is not extended past its times: a logged force
  /// ends with its log).
  template <class S>
  void check_tables_cover(const S& from, const S& elapsed) const {
    const S to = S(from + elapsed);
    for (const auto& table : model->sys.def->tables)
      if (lower(from) < table->times.front() || upper(to) > table->times.back())
        throw input_error("tables." + table->name + ": given for t in [" + ode::number_text(table->times.front()) +
                          ", " + ode::number_text(table->times.back()) + "]; the motion runs over [" +
                          ode::number_text(approx_double(from)) + ", " + ode::number_text(approx_double(to)) + "]");
  }
  /// The state's component that is t (t' = 1), or -1 when t is not carried.
  int time_component() const { return timed ? coordinates() + static_cast<int>(free_columns.size()) : -1; }

  /// The initial state x0 (padded to Dim).
  vector_t<T> initial_state() const {
    vector_t<T> x = vector_t<T>::Zero(std::max(Dim, size()));
    const int nq = coordinates(), k = static_cast<int>(free_columns.size());
    for (int i = 0; i < nq; ++i) x(i) = model->q(i);
    for (int i = 0; i < k; ++i) x(nq + i) = model->u(free_columns[static_cast<std::size_t>(i)]);
    if (timed) x(nq + k) = model->t;
    return x;
  }

  /// The motion's pieces at the state x.
  template <class S>
  struct at_state {
    vector_t<S> q, v_a;
    S t;
  };
  template <class S>
  at_state<S> split(const vector_t<S>& x) const {
    const int nq = coordinates(), k = static_cast<int>(free_columns.size());
    at_state<S> a{vector_t<S>(nq), vector_t<S>(k), timed ? x(nq + k) : detail::from_base<S>(model->t)};
    for (int i = 0; i < nq; ++i) a.q(i) = x(i);
    for (int i = 0; i < k; ++i) a.v_a(i) = x(nq + i);
    return a;
  }
  adapted_change<expression_constraints<T>> change() const {
    return {expression_constraints<T>{&model->sys}, free_columns, bound_columns};
  }
  /// Every speed at the state: the free ones from x, the others solved from the constraints.
  template <class S>
  vector_t<S> all_speeds(const at_state<S>& a) const {
    if (constraints() == 0) return a.v_a;
    vector_t<S> v = vector_t<S>::Zero(speeds());
    v.head(a.v_a.size()) = a.v_a;
    return change().template apply<S>(a.q, v, a.t);
  }

  template <class S>
  vector_t<S> rhs(const vector_t<S>& x) const {
    const at_state<S> a = split(x);
    const expression_system<T> sys{&model->sys};
    const int nq = coordinates(), k = static_cast<int>(free_columns.size()), s = constraints();
    vector_t<S> d = vector_t<S>::Zero(x.size());
    vector_t<S> qd, acc;
    if (s > 0 && tree_constraints_apply(model->sys)) {  // Cotton's method on the tree (system/tree_constraints.hpp)
      const vector_t<S> u = all_speeds(a);
      qd = sys.template qdot<S>(a.q, u, a.t);
      vector_t<S> udot;
      tree_cotton_result<S> tc;
      tree_cotton_into<T, S>(model->sys, free_columns, bound_columns, a.q, u, a.t, {}, udot, tc);
      acc = std::move(tc.free_accelerations);
    } else if (s == 0) {
      qd = sys.template qdot<S>(a.q, a.v_a, a.t);
      if (tree_recursions_apply(model->sys)) {  // by the recursions along the tree (system/tree.hpp)
        appell_equations<S> e;
        tree_equations_into<T, S>(model->sys, a.q, a.v_a, a.t, e);
        acc = e.accelerations();
      } else {
        acc = cotton_free_accelerations<4>(sys, a.q, a.v_a, a.t, 0);
      }
    } else {
      const auto adapted = change_speeds(sys, change(), speeds());
      vector_t<S> v = vector_t<S>::Zero(speeds());
      v.head(k) = a.v_a;
      qd = adapted.template qdot<S>(a.q, v, a.t);
      acc = cotton_free_accelerations<4>(adapted, a.q, a.v_a, a.t, s);
    }
    for (int i = 0; i < nq; ++i) d(i) = qd(i);
    for (int i = 0; i < k; ++i) d(nq + i) = acc(i);
    if (timed) d(nq + k) = S(1);
    return d;
  }

  /// eval's results along the motion: the accelerations, the solved speeds, the reactions and
  /// the wrenches.
  template <class S>
  void results(const vector_t<S>& x, std::vector<ode::named_values<S>>& out) const {
    const at_state<S> a = split(x);
    const expression_system<T> sys{&model->sys};
    const system_input& in = *model->in;
    const vector_t<S> u = all_speeds(a);
    vector_t<S> acc, reactions;
    if (constraints() == 0) {
      acc = system_equations<T, S>(model->sys, a.q, u, a.t).accelerations();
    } else if (tree_constraints_apply(model->sys)) {  // Cotton's method on the tree (system/tree_constraints.hpp)
      tree_cotton_result<S> tc;
      tree_cotton_into<T, S>(model->sys, free_columns, bound_columns, a.q, u, a.t, {true, false}, acc, tc);
      reactions = std::move(tc.reactions);
    } else {
      const constrained_motion<S> m = cotton_reactions(sys, change(), a.q, u, a.t);
      acc = m.accelerations;
      reactions = m.reactions;
    }
    for (int j = 0; j < speeds(); ++j) out.push_back({in.acceleration_names[static_cast<std::size_t>(j)], {acc(j)}});
    const system_definition& d = *in.def;
    for (int j : bound_columns) out.push_back({d.names[static_cast<std::size_t>(d.vars.u(j))], {u(j)}});
    for (int c = 0; c < constraints(); ++c)
      out.push_back({d.constraints[static_cast<std::size_t>(c)].name + "_reaction", {reactions(c)}});
    if (!d.wrenches.empty()) {
      const auto w = constraint_wrenches<T, S>(model->sys, a.q, a.t, reactions);
      for (std::size_t k = 0; k < w.size(); ++k) {
        out.push_back({d.wrenches[k].name + "_force", {w[k].force(0), w[k].force(1), w[k].force(2)}});
        out.push_back({d.wrenches[k].name + "_moment", {w[k].moment(0), w[k].moment(1), w[k].moment(2)}});
      }
    }
    if (!d.contacts.empty()) {  // the contacts' normal force and friction (judged by the commands: contact.hpp)
      const auto f = contact_forces<T, S>(model->sys, a.q, a.t, reactions);
      for (std::size_t k = 0; k < f.size(); ++k) {
        out.push_back({d.contacts[k].name + "_normal_force", {f[k].normal}});
        out.push_back({d.contacts[k].name + "_friction_force", {f[k].tangential(0), f[k].tangential(1), f[k].tangential(2)}});
        if (!d.contacts[k].surface) continue;
        // a sole: its couple and its wrench cone's margins (judged along the motion: contact_track.hpp)
        out.push_back({d.contacts[k].name + "_moment", {f[k].moment(0), f[k].moment(1), f[k].moment(2)}});
        const auto& ck = model->sys.contacts[k];
        const vec3<S> force(f[k].tangential(0), f[k].tangential(1), f[k].normal);
        const bool has_mu = !d.contacts[k].mu.empty();
        const S mu = has_mu ? S(from_decimal<T>(d.contacts[k].mu)) : S(0);
        const wrench_cone_margins<S> w = sole_wrench_margins(force, f[k].moment, S(ck.half_x), S(ck.half_y), mu);
        std::vector<S> margins;
        if (has_mu) {
          const std::array<S, 16> all = all_margins(w);
          margins.assign(all.begin(), all.end());
        } else {
          margins.assign(w.pressure.begin(), w.pressure.end());
        }
        out.push_back({d.contacts[k].name + "_margins", margins});
      }
    }
    // each joint's wrench, as eval gives it, where the tree's recursion gives the bodies'
    // accelerations (the speeds the coordinates' rates: every urdf scene)
    if (!model->sys.links.empty() && tree_accelerations_apply(model->sys)) {
      std::vector<joint_wrench_result<S>> w;
      joint_wrenches_along<T, S>(model->sys, a.q, u, a.t, acc, constraints() > 0 ? &reactions : nullptr, w);
      for (std::size_t k = 0; k < w.size(); ++k) {
        const std::string& joint = d.bodies[static_cast<std::size_t>(model->sys.links[k].body)].joint.name;
        out.push_back({joint + "_force", {w[k].force(0), w[k].force(1), w[k].force(2)}});
        out.push_back({joint + "_moment", {w[k].moment(0), w[k].moment(1), w[k].moment(2)}});
      }
    }
  }

  /// Whether state component i is a coordinate that a holonomic constraint involves (so that a
  /// range of values for it would leave the constraint: `appell validity` refuses to vary it).
  bool on_holonomic_constraint(int i) const {
    if (i >= coordinates()) return false;
    const system_definition& d = *model->in->def;
    for (const auto& c : d.constraints)
      if (c.holonomic && c.f.value->depends_on(d.vars.q(i))) return true;
    return false;
  }

  /// The same, as validity asks it of every model: whether a range of component i would leave a
  /// constraint at the state (the speeds the constraints solve are not in the state).
  template <class S>
  bool constrains(int i, const vector_t<S>&) const {
    return on_holonomic_constraint(i);
  }

  /// What `appell validity --vary NAME` can take over a range in this motion, besides the state's
  /// components and mu: a parameter of the file (NAME or parameters.NAME), a joint's effort given
  /// as a number (torques.JOINT, JOINT the joint's name in the system: in a `urdf` scene the name
  /// its coordinate has in the state, which is the URDF's own unless that had characters other
  /// than letters, digits and _ or clashed; or bodies.BODY.joint.effort), a sole's half-length
  /// (contacts.NAME.sole.half_lengths[0] or [1]), a value of a table (tables.NAME.value[K], the
  /// K-th of its points counted from 0: a torque or force a controller logged, its peak or a step's
  /// height over a range).
  struct varied_field {
    enum class kind { none, parameter, effort, half_length, table_value } what = kind::none;
    int index = -1;  ///< the parameter's variable, the link's place in sys.links, the contact's in sys.contacts, the table's in def->tables
    long axis = 0;   ///< half_length: 0 for X, 1 for Y; table_value: K (-1: not a count of points)
  };
  /// Each field this motion can vary, once: f(name, another spelling of it or "", the field,
  /// whether a message that lists the fields names it: a joint's effort only where the scene
  /// gives one). find_varied and parameter_names both read this one list (and the tables, find_table_value).
  template <class F>
  void for_each_varied(F&& f) const {
    const system_definition& d = *model->in->def;
    using K = typename varied_field::kind;
    for (int p = 0; p < d.vars.parameters; ++p) {
      const std::string& n = d.names[static_cast<std::size_t>(p)];
      f(n, "parameters." + n, varied_field{K::parameter, p, 0}, true);
    }
    const compiled_system<T>& c = model->sys;
    for (std::size_t k = 0; k < c.links.size(); ++k) {
      const system_body_definition& b = d.bodies[static_cast<std::size_t>(c.links[k].body)];
      if (b.joint.type == system_joint_definition::kind::fixed || b.joint.coordinate < 0) continue;
      f("torques." + b.joint.name, "bodies." + b.name + ".joint.effort", varied_field{K::effort, static_cast<int>(k), 0},
        bool(b.joint.effort));
    }
    for (std::size_t k = 0; k < d.contacts.size(); ++k)
      for (int a = 0; a < 2; ++a)
        if (d.contacts[k].surface)
          f("contacts." + d.contacts[k].name + ".sole.half_lengths[" + std::to_string(a) + "]", "",
            varied_field{K::half_length, static_cast<int>(k), a}, true);
  }
  varied_field find_varied(const std::string& name) const {
    varied_field found;
    for_each_varied([&](const std::string& n, const std::string& other, const varied_field& v, bool) {
      if (found.what == varied_field::kind::none && (name == n || (!other.empty() && name == other))) found = v;
    });
    if (found.what == varied_field::kind::none) found = find_table_value(name);
    return found;
  }
  /// tables.NAME.value[K] of a table of the scene: K its digits (-1 when they are not a count of
  /// the table's points; parameter_refusal says how many it has); none for another name.
  varied_field find_table_value(const std::string& name) const {
    const table_list& tables = model->in->def->tables;
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const std::string head = "tables." + tables[i]->name + ".value[";
      if (name.size() <= head.size() + 1 || name.compare(0, head.size(), head) != 0 || name.back() != ']') continue;
      const std::string digits = name.substr(head.size(), name.size() - head.size() - 1);
      long k = -1;
      if (digits.size() <= 7 && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
          (digits.size() == 1 || digits[0] != '0'))
        k = std::stol(digits);
      if (k >= static_cast<long>(tables[i]->values.size())) k = -1;
      return {varied_field::kind::table_value, static_cast<int>(i), k};
    }
    return {};
  }
  /// Every name find_varied knows (for a message that lists them); a table's values as one entry.
  std::vector<std::string> parameter_names() const {
    std::vector<std::string> out;
    for_each_varied([&](const std::string& n, const std::string&, const varied_field&, bool listed) {
      if (listed) out.push_back(n);
    });
    for (const auto& table : model->in->def->tables)
      out.push_back("tables." + table->name + ".value[K] (K from 0 to " + std::to_string(table->values.size() - 1) + ")");
    return out;
  }
  /// Whether `name` is a field find_varied knows.
  bool can_vary(const std::string& name) const { return find_varied(name).what != varied_field::kind::none; }
  /// The parameters whose value follows p's (p and those defined from it, at any depth).
  std::vector<bool> following(int p) const {
    const system_definition& d = *model->in->def;
    std::vector<bool> f(static_cast<std::size_t>(d.vars.parameters), false);
    f[static_cast<std::size_t>(p)] = true;
    for (int r : d.parameter_order)  // each after those it uses
      for (int s = 0; s < d.vars.parameters; ++s)
        if (f[static_cast<std::size_t>(s)] && d.parameters[static_cast<std::size_t>(r)]->depends_on(s))
          f[static_cast<std::size_t>(r)] = true;
    return f;
  }
  /// Why the field cannot take the range `value` ("" when it can). A parameter written as an
  /// expression of others (vary one it uses), or one a holonomic constraint involves (the state's
  /// coordinates would have to move with it to stay on the constraint; a velocity constraint is
  /// solved at every value, so its parameters can vary). An effort that is not a number (an
  /// expression of the state, of time, of a table or a parameter: vary what it is made of). A
  /// half-length whose range is not proved positive.
  std::string parameter_refusal(const std::string& name, const T& value) const {
    const system_definition& d = *model->in->def;
    const varied_field v = find_varied(name);
    using K = typename varied_field::kind;
    if (v.what == K::effort) {
      const system_joint_definition& j = d.bodies[static_cast<std::size_t>(model->sys.links[static_cast<std::size_t>(v.index)].body)].joint;
      if (!j.effort) return "the joint " + j.name + " has no effort in the scene (give it one, a number, to vary it)";
      for (int s = 0; s < d.vars.size(); ++s)
        if (j.effort->depends_on(s))
          return "its effort is an expression of " + d.names[static_cast<std::size_t>(s)] +
                 ", not a number (vary the number or the parameter it is made of)";
      return "";
    }
    if (v.what == K::half_length)
      return certainly_positive(value) ? "" : "a sole's half-length must be positive over the whole range";
    if (v.what == K::table_value) {
      const piecewise_linear& table = *d.tables[static_cast<std::size_t>(v.index)];
      if (v.axis < 0)
        return "the table " + table.name + " has " + std::to_string(table.values.size()) + " values: value[0] to value[" +
               std::to_string(table.values.size() - 1) + "] (K counted from 0, without leading zeros)";
      if (model->sys.table_readers(table.name) == 0)
        return "no force, couple or effort of the scene calls the table " + table.name + "(t)";
      return "";
    }
    const int p = v.index;
    for (int s = 0; s < d.vars.parameters; ++s)
      if (d.parameters[static_cast<std::size_t>(p)]->depends_on(s))
        return "it is defined from the parameter " + d.names[static_cast<std::size_t>(s)] + "; vary that one";
    const std::vector<bool> f = following(p);
    for (const auto& c : d.constraints) {
      if (!c.holonomic) continue;
      for (int s = 0; s < d.vars.parameters; ++s)
        if (f[static_cast<std::size_t>(s)] && c.f.value->depends_on(s))
          return "it enters the holonomic constraint " + c.name +
                 " (the state's coordinates would have to move with it to stay on the constraint)";
    }
    return "";
  }
  /// The same motion with the field `name` at `value` (an interval in validity): a parameter with
  /// those defined from it evaluated again, a joint's effort, or a sole's half-length (the sole's
  /// margins formed with it), or a table's value (on every tape that reads the table: an applied
  /// force, couple or effort; its pieces on either side of the point follow). The state is kept
  /// (no holonomic constraint involves a varied parameter: parameter_refusal; the solved speeds
  /// follow from the constraints at every evaluation; efforts, soles and tables enter no
  /// constraint: a table in a position, a rate or a constraint is refused when the file is read).
  system_problem with_parameter(const std::string& name, const T& value, vector_t<T>&) const {
    const system_definition& d = *model->in->def;
    const varied_field v = find_varied(name);
    using K = typename varied_field::kind;
    auto m = std::make_shared<system_model::prepared<T>>(*model);
    if (v.what == K::effort) {
      m->sys.links[static_cast<std::size_t>(v.index)].effort_fixed = value;
    } else if (v.what == K::table_value) {
      if (v.axis < 0) throw input_error("--vary " + name + ": " + parameter_refusal(name, value));
      m->sys.set_table_value(d.tables[static_cast<std::size_t>(v.index)]->name, static_cast<std::size_t>(v.axis), value);
    } else if (v.what == K::half_length) {
      auto& k = m->sys.contacts[static_cast<std::size_t>(v.index)];
      (v.axis == 0 ? k.half_x : k.half_y) = value;
    } else {
      const int p = v.index;
      std::vector<T> x(static_cast<std::size_t>(d.vars.size()), T(0));
      for (int s = 0; s < d.vars.parameters; ++s) x[static_cast<std::size_t>(s)] = m->sys.parameters[static_cast<std::size_t>(s)];
      x[static_cast<std::size_t>(p)] = value;
      m->sys.parameters[static_cast<std::size_t>(p)] = value;
      const std::vector<bool> f = following(p);
      for (int r : d.parameter_order) {
        const auto i = static_cast<std::size_t>(r);
        if (r == p || !f[i]) continue;
        m->sys.parameters[i] = compiled_expression<T>(*d.parameters[i]).eval_at(x.data());
        x[i] = m->sys.parameters[i];
      }
      m->sys.refresh_links();  // the joints' constants from the parameters' new values
    }
    system_problem out = *this;
    out.model = std::move(m);
    return out;
  }

  /// The contacts to judge along the motion: each one's name and mu as written (empty: none).
  std::vector<std::pair<std::string, std::string>> contacts() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& k : model->in->def->contacts) out.emplace_back(k.name, k.mu);
    return out;
  }
  /// A sole's half-lengths (a `surface` contact of a link), none for another contact: the
  /// judgement of a motion with a friction coefficient of its own (--mu, validity --vary mu)
  /// forms the sole's margins again from its force and couple (motion/contact_track.hpp).
  std::optional<std::array<T, 2>> sole_half_lengths(const std::string& name) const {
    const auto& cs = model->in->def->contacts;
    for (std::size_t k = 0; k < cs.size(); ++k)
      if (cs[k].name == name && cs[k].surface) return std::array<T, 2>{model->sys.contacts[k].half_x, model->sys.contacts[k].half_y};
    return std::nullopt;
  }

  /// The energy (when conserved) and each holonomic constraint's residual f(q, t) (0 in truth).
  template <class S>
  void invariants(const vector_t<S>& x, std::vector<ode::named_values<S>>& out) const {
    const at_state<S> a = split(x);
    const compiled_system<T>& c = model->sys;
    const system_definition& d = *c.def;
    if (energy) {
      const expression_system<T> sys{&c};
      const vector_t<S> u = all_speeds(a);
      std::vector<body_state<S>> bodies;
      sys.template bodies<S>(a.q, u, a.t, bodies);
      const std::vector<S> values = c.evaluate(c.body_tape, c.template variables<S>(a.q, u, a.t));
      const S* v = values.data();
      S e = S(0);
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const body_state<S>& st = bodies[b];
        e += st.mass * dot(st.velocity, st.velocity) / S(2);
        if (c.bodies[b].has_inertia) e += dot(st.omega, mat_vec(st.inertia, st.omega)) / S(2);
        for (std::size_t i = 0; i < 3; ++i)
          if (c.gravity[i] && c.bodies[b].center[i].value)
            e -= st.mass * c.gravity[i].at(v) * c.bodies[b].center[i].value.at(v);
      }
      out.push_back({"energy", {e}});
    }
    bool any_holonomic = false;
    for (const auto& k : d.constraints) any_holonomic = any_holonomic || k.holonomic;
    if (!any_holonomic) return;
    const vector_t<S> u0 = vector_t<S>::Zero(speeds());
    const std::vector<S> values = c.evaluate(c.constraint_tape, c.template variables<S>(a.q, u0, a.t));
    for (std::size_t r = 0; r < d.constraints.size(); ++r)
      if (d.constraints[r].holonomic)
        out.push_back({d.constraints[r].name + "_residual", {c.constraints[r].f.value.at(values.data())}, true});
  }
};

/// The module's motion: a system file moves (simulate, enclose, horizon, reference --trajectory).
template <>
struct model_motion<system_model> {
  static constexpr bool moves = true;

  /// The motion and its initial state.
  template <Scalar T>
  static std::pair<system_problem<T>, vector_t<T>> start(const system_model::prepared<T>& m) {
    system_problem<T> p;
    p.model = std::make_shared<const system_model::prepared<T>>(m);
    const system_input& in = *m.in;
    const system_definition& d = *in.def;
    const int n = d.vars.speeds;
    if (!d.constraints.empty()) {
      const expression_constraints<T> con{&p.model->sys};
      std::vector<int> given_free;
      for (int j = 0; j < n; ++j)
        if (std::find(in.solved.begin(), in.solved.end(), j) == in.solved.end()) given_free.push_back(j);
      // The solved speeds in pivot order (the elimination of adapted_change needs it); without
      // solve_speeds the library chooses them at the initial state.
      const auto change = adapt_speeds<T>(con, p.model->q, p.model->t, n, in.solved.empty() ? nullptr : &given_free);
      p.free_columns = change.free_columns;
      p.bound_columns = change.bound_columns;
    } else {
      for (int j = 0; j < n; ++j) p.free_columns.push_back(j);
    }
    p.timed = depends_on_time(d);
    p.energy = energy_conserved(d);
    p.names = state_fields(in, p.free_columns, p.timed);
    vector_t<T> x0 = p.initial_state();
    return {std::move(p), std::move(x0)};
  }
  /// The scene's state fields, in the order of the motion's state.
  static std::vector<std::string> state_fields(const system_input& in, const std::vector<int>& free, bool timed) {
    const system_definition& d = *in.def;
    std::vector<std::string> f;
    for (int i = 0; i < d.vars.coordinates; ++i) f.push_back(d.names[static_cast<std::size_t>(d.vars.q(i))]);
    for (int j : free) f.push_back(d.names[static_cast<std::size_t>(d.vars.u(j))]);
    if (timed) f.push_back("t");
    return f;
  }
  /// What reference --trajectory writes: the same fields, when they determine the state.
  static std::vector<std::string> state_fields(const system_input& in) {
    const system_definition& d = *in.def;
    if (!d.constraints.empty() && in.solved.empty())
      throw input_error("solve_speeds: a constrained system's trajectory needs solve_speeds (the speeds its states "
                        "leave out and the constraints give)");
    std::vector<int> free;
    for (int j = 0; j < d.vars.speeds; ++j)
      if (std::find(in.solved.begin(), in.solved.end(), j) == in.solved.end()) free.push_back(j);
    return state_fields(in, free, depends_on_time(d));
  }
};

/// The motion in the capacities enclose carries it in (cli: 6 or 12 components).
template <Scalar T>
using system_problem_6 = system_problem<T, 6>;
template <Scalar T>
using system_problem_12 = system_problem<T, 12>;

// Compiled once (see the end of ode/taylor.hpp): the system's integrators, defined by the
// library (ode_system_* units): the series in every scalar, simulate of the run-time sized
// problem in the point scalars, the slopes and enclose of the padded ones in the interval scalars.
#define APPELL_SYSTEM_POINT_PROBLEMS(X, T) X(::appell::system_problem<T>, T)
#define APPELL_SYSTEM_INTERVAL_PROBLEMS(X, T) X(::appell::system_problem_6<T>, T) X(::appell::system_problem_12<T>, T)
#define APPELL_DETAIL_EXTERN_SYSTEM_MOTION(ctx, T, name)                                                           \
  APPELL_SYSTEM_POINT_PROBLEMS(APPELL_ODE_EXTERN_SERIES, T) APPELL_SYSTEM_POINT_PROBLEMS(APPELL_ODE_EXTERN_SIMULATE, T) \
  APPELL_SYSTEM_INTERVAL_PROBLEMS(APPELL_ODE_EXTERN_SERIES, T) APPELL_SYSTEM_INTERVAL_PROBLEMS(APPELL_ODE_EXTERN_ENCLOSE, T)
namespace ode {
APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_SYSTEM_MOTION, )
}  // namespace ode
#undef APPELL_DETAIL_EXTERN_SYSTEM_MOTION


// ---- linearize_scene<T>: its definition, compiled once per standard scalar in the units CMake
// generates (cmake/instantiate.cmake); declared extern above, so no other unit instantiates it.

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
