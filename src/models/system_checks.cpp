// Scene model "system": the checks at the state, at 256 bits (every expression and derivative
// defined, masses positive, inertia tensors positive semidefinite, orientation matrices
// rotations, a tree's mass matrix positive definite, the state on every constraint, the
// constraints independent, each wrench and contact fixed by its virtual work, the linearization's
// reference motion).  What 256 bits cannot tell from exact is taken as exact; the scalar the
// user asks for certifies the rest.  Also each link axis's sign, settled at 256 bits.
#include "system_reading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace appell::system_reading {

void require_in_256_bits(bool certainly_true, bool certainly_false, const std::string& what) {
  if (certainly_false) throw input_error(what);
  if (!certainly_true) throw input_error(what + " (within 2^-256: taken as exact)");
}



/// At 256 bits, at the state: the speeds move `body` in 6 independent ways (J J^T, Gaussian
/// elimination with every pivot certainly positive), so that the constraints' virtual work fixes
/// `what` (a wrench, a contact's force); and each named constraint's row is a virtual power of
/// that body alone (A_c^T in the range of J^T).  input_error naming `where` otherwise.
void check_body_fixes_force(const system_definition& d, const std::string& where, int body, const matrix_t<mpfi>& J,
                            const matrix_t<mpfi>& A, const std::vector<int>& constraints, const std::string& what) {
  const int n = d.vars.speeds, m = static_cast<int>(J.rows());  // m: 6, or 3 for a point mass (its force alone)
  const std::string& name = d.bodies[static_cast<std::size_t>(body)].name;
  matrix_t<mpfi> N = wrench_normal_equations(J, vector_t<mpfi>(vector_t<mpfi>::Zero(n))).first;
  for (int p = 0; p < m; ++p) {
    if (!certainly_positive(N(p, p)))
      throw input_error(where + ".body: the speeds move " + name + " in fewer than " + std::to_string(m) +
                        " independent ways at the state, so the constraints' virtual work does not fix " + what +
                        (m == 6 ? " (describe the body free: 6 speeds, the constraints as rows)"
                                : " (describe the point mass free: 3 speeds of its centre, the constraints as rows)"));
    for (int r = p + 1; r < m; ++r) {
      const mpfi f = N(r, p) / N(p, p);
      for (int c = p; c < m; ++c) N(r, c) -= f * N(p, c);
    }
  }
  for (int c : constraints) {
    const vector_t<mpfi> g = A.row(c).transpose();
    const auto [Nc, rhs] = wrench_normal_equations(J, g);
    const vector_t<mpfi> y = solve_spd(Nc, rhs);
    for (int j = 0; j < n; ++j) {
      mpfi e = -g(j);
      for (int r = 0; r < m; ++r) e += J(r, j) * y(r);
      if (!possibly_zero(e))
        throw input_error(where + ".constraints: " + d.constraints[static_cast<std::size_t>(c)].name +
                          " is not a constraint on " + name + " alone (its virtual work involves " +
                          d.names[static_cast<std::size_t>(d.vars.u(j))] + " beyond the body's motion)");
    }
  }
}

void settle_link_axes(system_definition& def) {
  if (def.link_order.empty()) return;
  mp_precision_scope scope(256);
  std::vector<mpfi> x(static_cast<std::size_t>(def.vars.size()), mpfi(0));
  for (int p : def.parameter_order)
    x[static_cast<std::size_t>(p)] = compiled_expression<mpfi>(*def.parameters[static_cast<std::size_t>(p)]).eval_at(x.data());
  for (auto& body : def.bodies) {
    auto& j = body.joint;
    if (!body.is_link || j.type == system_joint_definition::kind::fixed) continue;
    const std::string where = "bodies." + body.name + ".joint.axis";
    mpfi n2 = 0;
    for (const auto& e : j.axis)
      if (e) n2 += sqr(compiled_expression<mpfi>(*e).eval_at(x.data()));
    if (!certainly_positive(n2)) throw input_error(where + ": the axis is 0");
    if (j.along >= 0) {
      const mpfi a = compiled_expression<mpfi>(*j.axis[static_cast<std::size_t>(j.along)]).eval_at(x.data());
      j.sign = certainly_negative(a) ? -1 : 1;
    }
  }
}

/// The state at 256 bits, as the checks read it: the compiled system, q, u (the dependent
/// speeds solved), t, the tapes of the bodies and the constraints evaluated there, and (with
/// constraints) their rows A u = a and the constraint tape at u = 0.
struct state_at_256_bits {
  const system_definition& d;
  const compiled_system<mpfi>& sys;
  const vector_t<mpfi>& q;
  const vector_t<mpfi>& u;
  const mpfi& t;
  const std::vector<mpfi>& bv;
  const std::vector<mpfi>& cv;
  const matrix_t<mpfi>& A;
  const vector_t<mpfi>& a;
  const std::vector<mpfi>& w0;
};

/// Every body's expressions defined at the state; an orientation matrix a rotation (orthogonal,
/// determinant 1, R^T dR skew in every coordinate and t); masses positive; inertia tensors
/// positive semidefinite, principal moments within the triangle inequalities.
void check_bodies(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  for (std::size_t i = 0; i < d.bodies.size(); ++i) {
    const auto& bd = d.bodies[i];
    const auto& bc = sys.bodies[i];
    const std::string where = "bodies." + bd.name;
    for (const auto& c : bc.center) (void)c.value.at(bv.data());
    for (const auto& [axis, angle] : bc.rotations) (void)angle.value.at(bv.data());
    if (bd.has_matrix) {  // orthogonal with det 1, and R^T dR skew in every coordinate and t (to first order a rotation)
      mat3<mpfi> R;
      for (int k = 0; k < 9; ++k) R(k / 3, k % 3) = bc.matrix[static_cast<std::size_t>(k)].value.at(bv.data());
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          mpfi e = i == j ? mpfi(-1) : mpfi(0);
          for (int k = 0; k < 3; ++k) e += R(i, k) * R(j, k);
          if (!possibly_zero(e))
            throw input_error(where + ".orientation: not orthogonal at the state ((R R^T)(" + std::to_string(i) + ", " +
                              std::to_string(j) + ") - " + (i == j ? "1" : "0") + " = " + to_string(e) + ")");
        }
      const mpfi det = R(0, 0) * (R(1, 1) * R(2, 2) - R(1, 2) * R(2, 1)) - R(0, 1) * (R(1, 0) * R(2, 2) - R(1, 2) * R(2, 0)) +
                       R(0, 2) * (R(1, 0) * R(2, 1) - R(1, 1) * R(2, 0));
      if (!possibly_zero(mpfi(det - 1)))
        throw input_error(where + ".orientation: its determinant is " + to_string(det) + ", not 1 (a reflection)");
      for (int var = 0; var <= d.vars.coordinates; ++var) {  // the coordinates, then t
        mat3<mpfi> D = mat3<mpfi>::Zero();
        for (int k = 0; k < 9; ++k) {
          const auto& e = bc.matrix[static_cast<std::size_t>(k)];
          if (var == d.vars.coordinates) {
            if (e.dt) D(k / 3, k % 3) = e.dt.at(bv.data());
          } else {
            for (const auto& [i, de] : e.dq)
              if (i == var) D(k / 3, k % 3) = de.at(bv.data());
          }
        }
        for (int i = 0; i < 3; ++i)
          for (int j = i; j < 3; ++j) {
            mpfi e = 0;
            for (int k = 0; k < 3; ++k) e += R(k, i) * D(k, j) + D(k, i) * R(k, j);
            if (!possibly_zero(e))
              throw input_error(where + ".orientation: not a rotation near the state (R^T dR/d" +
                                (var == d.vars.coordinates ? std::string("t") : d.names[static_cast<std::size_t>(d.vars.q(var))]) +
                                " is not skew-symmetric)");
          }
      }
    }
    if (bd.is_link && !bd.mass) continue;  // a massless frame
    const mpfi mass = bc.mass.at(bv.data());
    require_in_256_bits(certainly_positive(mass), certainly_nonpositive(mass),
                        where + ".mass: must be positive (" + to_string(mass) + ")");
    // Inertia: positive semidefinite (every principal minor >= 0); principal moments: the triangle inequalities.
    mpfi I[6];
    for (std::size_t k = 0; k < 6; ++k) I[k] = bc.inertia[k].at(bv.data());
    const mpfi minors[] = {I[0], I[1], I[2], mpfi(I[0] * I[1] - I[3] * I[3]), mpfi(I[1] * I[2] - I[4] * I[4]),
                           mpfi(I[0] * I[2] - I[5] * I[5]),
                           mpfi(I[0] * (I[1] * I[2] - I[4] * I[4]) - I[3] * (I[3] * I[2] - I[4] * I[5]) +
                                I[5] * (I[3] * I[4] - I[1] * I[5]))};
    for (const mpfi& m : minors)
      if (certainly_negative(m))
        throw input_error(where + ".inertia: not positive semidefinite (a principal minor is " + to_string(m) + ")");
    if (bd.inertia[0] && !bd.inertia[3])
      for (int k = 0; k < 3; ++k) {
        const mpfi slack = I[(k + 1) % 3] + I[(k + 2) % 3] - I[k];
        if (certainly_negative(slack))
          throw input_error(where + ".inertia: principal moments must satisfy the triangle inequalities");
      }
  }
}

namespace {
/// The system compiled in T (at the working precision, for mpfi) for a definition, kept on this
/// thread for the next state of the same definition (a definition read once serves the states of
/// `appell reference`: system.cpp): the same tapes and constants, compiled once.
template <class T>
const compiled_system<T>& compiled_for(const std::shared_ptr<const system_definition>& def) {
  struct kept {
    std::weak_ptr<const system_definition> def;
    unsigned bits = 0;
    std::unique_ptr<const compiled_system<T>> sys;
  };
  thread_local kept k;
  const unsigned bits = mp_precision_bits();
  if (!k.sys || k.def.lock() != def || k.bits != bits) {
    auto sys = std::make_unique<const compiled_system<T>>(*def);
    k.sys = std::move(sys);
    k.def = def;
    k.bits = bits;
  }
  return *k.sys;
}

interval enclosure_in_doubles(const mpfi& x) {
  mpfr_value lo, hi;
  scalar_traits<mpfi>::to_mpfr(x, lo, hi);
  return interval(mpfr_get_d(lo, MPFR_RNDD), mpfr_get_d(hi, MPFR_RNDU));
}

/// Every matrix in a mass matrix's enclosure proved nonsingular (verified_solve's proof, which
/// holds where an interval Cholesky loses its pivots to the widths it accumulates, on long
/// chains).  The exact M is positive semidefinite (sum m Jv^T Jv + Jw^T I Jw, the inertias checked
/// positive semidefinite above), so nonsingular is positive definite.
template <class I>
bool proved_nonsingular(const matrix_t<I>& M) {
  try {
    (void)verified_solve(M, vector_t<I>(vector_t<I>::Ones(M.rows())));
    return true;
  } catch (const certification_error&) {
    return false;
  }
}

/// The mass matrix at the state proved positive definite in interval<double>: M's enclosure (the
/// system compiled in interval, at enclosures of the 256-bit state; a tree's by its recursion)
/// has a Cholesky factorization with every pivot certainly positive, which proves every symmetric
/// matrix in the enclosure positive definite, the exact M among them; or, where the pivots' widths
/// grow too wide (long chains), the enclosure is proved nonsingular (proved_nonsingular).  False
/// where it cannot tell (a singular or nearly singular M, or a state beyond double's range): then
/// the check at 256 bits decides and names the joint.  A tenth of the 256-bit check's work, which was half of a robot's state in
/// `appell reference` (docs/reference-values.md).
bool tree_mass_matrix_proved_in_doubles(const state_at_256_bits& at, const std::shared_ptr<const system_definition>& def) {
  try {
    const auto& [d, sys256, q256, u256, t256, bv, cv, A, a, w0] = at;
    const evaluation_scope<interval> scope;
    const compiled_system<interval>& sys = compiled_for<interval>(def);
    vector_t<interval> q(q256.size()), u(u256.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = enclosure_in_doubles(q256(i));
    for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = enclosure_in_doubles(u256(i));
    const appell_equations<interval> eq = system_equations<interval, interval>(sys, q, u, enclosure_in_doubles(t256));
    const int n = d.vars.speeds;
    matrix_t<interval> L = matrix_t<interval>::Zero(n, n);
    for (int k = 0; k < n; ++k) {
      interval pivot = eq.M(k, k);
      for (int j = 0; j < k; ++j) pivot -= sqr(L(k, j));
      if (!certainly_positive(pivot)) {
        const bool proved = proved_nonsingular(eq.M);
        scope.verify();
        return proved;
      }
      L(k, k) = sqrt(pivot);
      for (int i = k + 1; i < n; ++i) {
        interval x = eq.M(i, k);
        for (int j = 0; j < k; ++j) x -= L(i, j) * L(k, j);
        L(i, k) = x / L(k, k);
      }
    }
    scope.verify();
    return true;
  } catch (const std::exception&) {  // out of double's range, a tape undefined in doubles: 256 bits decide
    return false;
  }
}
}  // namespace

/// A tree's mass matrix positive definite (Cholesky with every pivot certainly positive): proved
/// in interval<double> where it can be, at 256 bits otherwise.
void check_tree_mass_matrix(const state_at_256_bits& at, const std::shared_ptr<const system_definition>& def) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // A tree's mass matrix positive definite: each joint moves some mass or inertia that the
  // joints before it do not (a link without inertial data at the end of a chain makes it singular).
  if (!d.link_order.empty() && !tree_mass_matrix_proved_in_doubles(at, def)) {
    const appell_equations<mpfi> eq = system_equations<mpfi, mpfi>(sys, q, u, t);
    const int n = d.vars.speeds;
    matrix_t<mpfi> L = matrix_t<mpfi>::Zero(n, n);
    for (int k = 0; k < n; ++k) {
      mpfi pivot = eq.M(k, k);
      for (int j = 0; j < k; ++j) pivot -= sqr(L(k, j));
      if (!certainly_positive(pivot)) {
        if (proved_nonsingular(eq.M)) return;  // hence positive definite (proved_nonsingular)
        std::string field = "coordinates." + d.names[static_cast<std::size_t>(d.vars.q(k < d.vars.coordinates ? k : 0))];
        for (const auto& bd : d.bodies)
          if (bd.is_link && bd.joint.coordinate == k) field = "bodies." + bd.name + ".joint";
        throw input_error(field + ": the mass matrix is singular at the state: this joint moves no mass or inertia "
                                  "that the joints before it do not move (a link without inertial data?)");
      }
      L(k, k) = sqrt(pivot);
      for (int i = k + 1; i < n; ++i) {
        mpfi x = eq.M(i, k);
        for (int j = 0; j < k; ++j) x -= L(i, j) * L(k, j);
        L(i, k) = x / L(k, k);
      }
    }
  }
}

/// What a refusal of a state off its constraints by at most 1e-6 adds (a state written to a few
/// digits): the remedy, with a tolerance to try (a thousand times the residual, as a power of
/// ten: the coordinates move by about |f| / |grad f|).
std::string projection_remedy(const mpfi& residual, bool projected) {
  if (projected) return "";
  const double r = std::max(std::fabs(std::strtod(lower_string(residual).c_str(), nullptr)),
                            std::fabs(std::strtod(upper_string(residual).c_str(), nullptr)));
  if (!(r <= 1e-6)) return "";  // off by more than digits: not a state on the constraint, given short
  double tol = 1e-30;
  if (r > 0) tol = std::max(1e-30, std::pow(10.0, std::ceil(std::log10(r)) + 3));
  char t[32];
  std::snprintf(t, sizeof t, "%.0e", tol);
  return std::string(" (a state given to a few digits is off a closed loop's constraints: \"project\": \"") + t +
         "\" in the scene, or --project " + t + " of eval and reference, moves it onto them and prints it; SCENES.md, "
         "\"project\")";
}

/// The state on every constraint, and the constraints independent.
void check_constraints_at_state(const state_at_256_bits& at, bool projected) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A_at, a, w0] = at;
  if (!d.constraints.empty()) {
    const int s = static_cast<int>(d.constraints.size()), n = d.vars.speeds;
    matrix_t<mpfi> A = A_at;  // eliminated below
    for (int r = 0; r < s; ++r) {
      const auto& k = d.constraints[static_cast<std::size_t>(r)];
      const std::string where = "state: constraint " + k.name;
      if (k.holonomic) {
        const mpfi f = sys.constraints[static_cast<std::size_t>(r)].f.value.at(cv.data());
        if (!possibly_zero(f))
          throw input_error(where + " does not hold: f(q, t) = " + to_string(f) + projection_remedy(f, projected));
      } else if (k.body >= 0) {
        // the direction was checked before the speeds were solved
      } else {
        (void)sys.constraints[static_cast<std::size_t>(r)].g.at(cv.data());
      }
      mpfi res = -a(r);
      for (int j = 0; j < n; ++j) res += A(r, j) * u(j);
      if (!possibly_zero(res))
        throw input_error(where + ": the speeds violate it (" +
                          std::string(k.holonomic ? "df/dt" : k.body >= 0 ? "n . v" : k.link_contact >= 0 ? "the link's velocity there" : "g") + " = " +
                          to_string(res) + ")" + projection_remedy(res, projected));
    }
    // Independence: elimination with a pivot that is certainly nonzero in each row.
    std::vector<bool> used(static_cast<std::size_t>(n), false);
    for (int r = 0; r < s; ++r) {
      int best = -1;
      double best_abs = 0;
      for (int j = 0; j < n; ++j)
        if (!used[static_cast<std::size_t>(j)] && !possibly_zero(A(r, j)) && std::abs(approx_double(A(r, j))) > best_abs) {
          best_abs = std::abs(approx_double(A(r, j)));
          best = j;
        }
      if (best < 0) {
        const system_constraint_definition& k = d.constraints[static_cast<std::size_t>(r)];
        if (k.link_contact >= 0) {  // a link's contact: name it, and the contacts before it
          std::string before;
          for (int c = 0; c < k.link_contact; ++c)
            if (d.contacts[static_cast<std::size_t>(c)].link >= 0) before += (before.empty() ? "" : ", ") + d.contacts[static_cast<std::size_t>(c)].name;
          throw input_error("contacts." + d.contacts[static_cast<std::size_t>(k.link_contact)].name + ": its constraint " + k.name +
                            " depends on the constraints before it at the state" +
                            (before.empty() ? std::string(" (the joints cannot move the link that way)")
                                            : " (with the contacts " + before + ": a closed chain through the ground at a singular pose)"));
        }
        throw input_error("constraints." + k.name + ": depends on the constraints before it at the state (or is 0 there)");
      }
      used[static_cast<std::size_t>(best)] = true;
      for (int r2 = r + 1; r2 < s; ++r2) {
        const mpfi f = A(r2, best) / A(r, best);
        for (int j = 0; j < n; ++j) A(r2, j) -= f * A(r, j);
      }
    }
  }
}

/// Each wrench fixed by the constraints' virtual work.
void check_wrenches_fixed(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // Each wrench fixed by its virtual work: the body moves in 6 independent ways
  // (J J^T nonsingular), and each of its constraints' rows is a virtual power of
  // that body alone (A_c^T in the range of J^T).
  if (!d.wrenches.empty()) {
    for (std::size_t k = 0; k < d.wrenches.size(); ++k) {
      const system_wrench_definition& wd = d.wrenches[k];
      const std::string where = "wrenches." + wd.name;
      const matrix_t<mpfi> J = point_twist_jacobian(sys, sys.wrenches[k], w0.data());
      check_body_fixes_force(d, where, wd.body, J, A, wd.constraints, "a wrench");
    }
  }
}

/// Each contact: its force fixed by the virtual work, a force at its point, its normal.
void check_contacts_at_state(const state_at_256_bits& at) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  // Each contact: a body that moves in 6 independent ways (its force from the virtual work),
  // each constraint's force at the point a force alone, a normal that is not 0, and the
  // other constraints' forces orthogonal to a normal constraint's.
  if (!d.contacts.empty()) {
    for (std::size_t k = 0; k < d.contacts.size(); ++k) {
      const system_contact_definition& kd = d.contacts[k];
      const std::string where = "contacts." + kd.name;
      if (kd.link >= 0) continue;  // a link's contact: its rows are its frame's axes (read_link_contact)
      if (kd.body >= 0) {
        const matrix_t<mpfi> J = contact_twist_jacobian(sys, sys.contacts[k], w0.data());
        check_body_fixes_force(d, where, kd.body, J, A, kd.constraints, "the contact's force");
      }
      if (kd.normal < 0) {
        mpfi nn = 0;
        for (const auto& e : sys.contacts[k].direction) nn += sqr(e.at(w0.data()));
        if (!certainly_positive(nn)) throw input_error(where + ".normal: 0 at the state");
      }
      for (std::size_t i = 0; i < kd.constraints.size(); ++i) {  // unit reactions, one at a time
        vector_t<mpfi> unit = vector_t<mpfi>::Zero(static_cast<Eigen::Index>(d.constraints.size()));
        unit(kd.constraints[i]) = 1;
        const contact_force_result<mpfi> f = contact_forces<mpfi, mpfi>(sys, q, t, unit)[k];
        const std::string cname = d.constraints[static_cast<std::size_t>(kd.constraints[i])].name;
        for (int x = 0; x < 3; ++x)
          if (!possibly_zero(f.moment(x)))
            throw input_error(where + ".point: " + cname + " exerts a couple about the point (a contact transmits a "
                              "force at its point: leave pivoting or rolling constraints out of it)");
        if (kd.constraints[i] == kd.normal && !certainly_positive(kd.side > 0 ? f.normal : mpfi(-f.normal)))
          throw input_error(where + ".normal: " + cname + "'s force at the point is 0 at the state (no normal)");
        if (kd.normal >= 0 && kd.constraints[i] != kd.normal) {
          const mpfi along = f.normal;  // d_c . n for a unit reaction
          if (!possibly_zero(along))
            throw input_error(where + ".constraints: " + cname + " is not orthogonal to the normal " +
                              d.constraints[static_cast<std::size_t>(kd.normal)].name + " at the state (its force along "
                              "the normal per unit reaction: " + short_text(along) + ")");
        }
      }
    }
  }
}

/// The linearization's reference motion on the holonomic constraints, its speed not 0, its
/// range of speeds ordered, its gravity parameter not 0; a refusal kept for `linearize`.
void check_linearization_reference(const state_at_256_bits& at, system_input& in) {
  [[maybe_unused]] const auto& [d, sys, q, u, t, bv, cv, A, a, w0] = at;
  if (in.linearize) try {  // the reference motion on the holonomic constraints; a nonzero speed; a range
    const linearize_input& li = *in.linearize;
    vector_t<mpfi> ql(d.vars.coordinates);
    for (int i = 0; i < d.vars.coordinates; ++i) ql(i) = value<mpfi>(li.q[static_cast<std::size_t>(i)]);
    const std::vector<mpfi> lv = sys.evaluate(sys.constraint_tape, sys.variables(ql, vector_t<mpfi>(vector_t<mpfi>::Zero(d.vars.speeds)), t));
    for (int r : li.def.holonomic_rows) {
      const mpfi f = sys.constraints[static_cast<std::size_t>(r)].f.value.at(lv.data());
      if (!possibly_zero(f))
        throw input_error("linearize.about: constraint " + d.constraints[static_cast<std::size_t>(r)].name +
                          " does not hold: f(q, t) = " + to_string(f));
    }
    const decimal_field& v = li.u[static_cast<std::size_t>(li.def.speed)];
    if (possibly_zero(value<mpfi>(v)))
      throw input_error(v.path + ": the reference speed must not be 0 (K2 and C1 come from the motion at that speed)");
    if (li.from && !certainly_less(value<mpfi>(*li.from), value<mpfi>(*li.to)))
      throw input_error("linearize.critical_speeds: from must be less than to");
    if (li.def.gravity >= 0 && possibly_zero(sys.parameters[static_cast<std::size_t>(li.def.gravity)]))
      throw input_error("linearize.gravity: the parameter is 0 (K0 is the stiffness per unit g)");
  } catch (const input_error& e) {
    in.linearize.reset();
    in.linearize_refusal = e.what();
  } catch (const certification_error& e) {
    in.linearize.reset();
    in.linearize_refusal = std::string(e.what()) + " (within 2^-256 of it: taken as exact)";
  }
}

void check_at_state(system_input& in) {
  const std::shared_ptr<const system_definition> shared = in.def;
  // At the state, at 256 bits.
  try {
    mp_precision_scope scope(256);
    const compiled_system<mpfi>& sys = compiled_for<mpfi>(shared);
    const system_definition& d = *shared;
    vector_t<mpfi> q(d.vars.coordinates), u(d.vars.speeds);
    for (int i = 0; i < d.vars.coordinates; ++i) q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
    for (int j = 0; j < d.vars.speeds; ++j) u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
    const mpfi t = value<mpfi>(in.t);
    if (in.project) {
      project_state(in, q, u);
      if (in.linearize) set_reference_motion(*in.linearize, in);  // from the projected state
    }
    for (std::size_t r = 0; r < d.constraints.size(); ++r) {  // point_velocity directions, before any solve
      const auto& kc = sys.constraints[r];
      if (kc.body < 0) continue;
      const std::vector<mpfi> cv0 = sys.evaluate(sys.constraint_tape, sys.variables(q, u, t));
      mpfi nn = 0;
      for (const auto& e : kc.direction) nn += sqr(e.at(cv0.data()));
      if (!certainly_positive(nn))
        throw input_error("constraints." + d.constraints[r].name + ".point_velocity.direction: 0 at the state");
    }
    if (!in.solved.empty()) {
      try {
        solve_dependent_speeds(sys, q, u, t, in.solved);
      } catch (const certification_error&) {
        throw input_error("solve_speeds: the constraints do not determine these speeds at the state (singular)");
      }
    }
    const std::vector<mpfi> x = sys.variables(q, u, t);
    (void)sys.evaluate(sys.kinematics_tape, x);
    const std::vector<mpfi> bv = sys.evaluate(sys.body_tape, x), cv = sys.evaluate(sys.constraint_tape, x);
    std::vector<body_state<mpfi>> states;
    expression_system<mpfi>{&sys}.bodies<mpfi>(q, u, t, states);
    const int n_constraints = static_cast<int>(d.constraints.size());
    matrix_t<mpfi> A(n_constraints, d.vars.speeds);
    vector_t<mpfi> a(n_constraints);
    std::vector<mpfi> w0;
    if (n_constraints > 0) {
      expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
      w0 = sys.evaluate(sys.constraint_tape, sys.variables(q, vector_t<mpfi>(vector_t<mpfi>::Zero(d.vars.speeds)), t));
    }
    const state_at_256_bits at{d, sys, q, u, t, bv, cv, A, a, w0};
    check_bodies(at);
    check_tree_mass_matrix(at, shared);
    check_constraints_at_state(at, in.project.has_value());
    check_wrenches_fixed(at);
    check_contacts_at_state(at);
    check_linearization_reference(at, in);
  } catch (const certification_error& e) {
    throw input_error(std::string(e.what()) + " (within 2^-256 of it: taken as exact)");
  }
}

}  // namespace appell::system_reading
