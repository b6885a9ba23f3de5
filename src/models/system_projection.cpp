// Scene model "system": "project" (SCENES.md), the state moved onto the constraints at 400 bits
// and written back as 90-digit decimals; and the linearization's reference motion.
#include "system_reading.hpp"

namespace appell::system_reading {

/// x as a 90-digit decimal (the midpoint of its enclosure).
std::string decimal_90(const mpfi& x) { return mpfi_mid(x).str(90, std::ios_base::scientific); }

/// "project" (SCENES.md): the state moved onto the constraints, at 400 bits.  The coordinates
/// move along the holonomic constraints' gradients taken at the given state,
/// q = q0 + W(q0) A_h(q0)^T lambda with f(q, t) = 0 (lambda by the chord iteration with
/// A_h A_h^T; the step shrinks by about the distance at each pass), then the speeds
/// orthogonally onto A(q, t) u = a(q, t) (unless solve_speeds computes them from the
/// constraints).  Written back as 90-digit decimals, which the checks that follow accept
/// or refuse as any state: the values certified are those of that state.
void project_at_400_bits(system_input& in) {
  // At 400 bits (constants and all): the 90-digit decimals it writes are then within 1e-90 of
  // the projection, far inside the 256-bit checks that follow.
  const system_definition& d = *in.def;
  const mp_precision_scope precision(400);
  const compiled_system<mpfi> sys(d);
  vector_t<mpfi> q(d.vars.coordinates), u(d.vars.speeds);
  for (int i = 0; i < d.vars.coordinates; ++i) q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
  for (int j = 0; j < d.vars.speeds; ++j) u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
  const mpfi t = value<mpfi>(in.t);
  const int s = static_cast<int>(d.constraints.size()), nq = d.vars.coordinates, n = d.vars.speeds;
  in.q_given = in.q;
  in.u_given = in.u;
  auto mids = [](vector_t<mpfi>& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = mpfi(mpfi_mid(v(i)));
  };
  std::vector<int> H;
  for (int r = 0; r < s; ++r)
    if (d.constraints[static_cast<std::size_t>(r)].holonomic) H.push_back(r);
  const int m = static_cast<int>(H.size());
  if (m > 0) {
    matrix_t<mpfi> A(s, n);
    vector_t<mpfi> a(s);
    expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
    matrix_t<mpfi> W(nq, n);
    if (d.rates_as_speeds) {
      W = matrix_t<mpfi>::Identity(nq, n);
    } else {  // q' = W u + w: W's columns from the kinematics at the unit speeds
      const expression_system<mpfi> es{&sys};
      vector_t<mpfi> e = vector_t<mpfi>::Zero(n);
      const vector_t<mpfi> w = es.qdot(q, e, t);
      for (int j = 0; j < n; ++j) {
        e(j) = 1;
        W.col(j) = es.qdot(q, e, t) - w;
        e(j) = 0;
      }
    }
    matrix_t<mpfi> Ah(m, n);
    for (int k = 0; k < m; ++k) Ah.row(k) = A.row(H[static_cast<std::size_t>(k)]);
    const matrix_t<mpfi> D = W * Ah.transpose();
    const matrix_t<mpfi> G = Ah * Ah.transpose();
    const vector_t<mpfi> q0 = q;
    vector_t<mpfi> lambda = vector_t<mpfi>::Zero(m);
    for (int pass = 0; pass < 100; ++pass) {
      q = q0 + D * lambda;
      mids(q);
      const std::vector<mpfi> cv = sys.evaluate(sys.constraint_tape, sys.variables(q, u, t));
      vector_t<mpfi> f(m);
      for (int k = 0; k < m; ++k) f(k) = sys.constraints[static_cast<std::size_t>(H[static_cast<std::size_t>(k)])].f.value.at(cv.data());
      vector_t<mpfi> step;
      try {
        step = solve(G, f);
      } catch (const certification_error&) {
        throw input_error("project: the holonomic constraints are dependent at the state (their gradients)");
      }
      mids(step);
      lambda -= step;
      mids(lambda);
      bool small = true;
      for (int k = 0; k < m; ++k)
        if (abs(mpfi_mid(step(k))) > mpfr("1e-110") * (1 + abs(mpfi_mid(lambda(k))))) small = false;
      if (small) break;
    }
    q = q0 + D * lambda;
    mids(q);
  }
  if (in.solved.empty() && s > 0) {  // the speeds: u - A^T (A A^T)^-1 (A u - a)
    matrix_t<mpfi> A(s, n);
    vector_t<mpfi> a(s);
    expression_constraints<mpfi>{&sys}.eval<mpfi>(q, t, A, a);
    vector_t<mpfi> y;
    try {
      y = solve(matrix_t<mpfi>(A * A.transpose()), vector_t<mpfi>(A * u - a));
    } catch (const certification_error&) {
      throw input_error("project: the constraints are dependent at the state");
    }
    u -= A.transpose() * y;
    mids(u);
  }
  for (int i = 0; i < nq; ++i)
    if (!is_finite(q(i)))
      throw input_error("project: the projection onto the holonomic constraints does not converge from the state "
                        "(too far from them)");
  for (int i = 0; i < nq; ++i) in.q[static_cast<std::size_t>(i)].text = decimal_90(q(i));
  for (int j = 0; j < n; ++j)
    if (std::find(in.solved.begin(), in.solved.end(), j) == in.solved.end())
      in.u[static_cast<std::size_t>(j)].text = decimal_90(u(j));
}

/// The projected state (decimals) read back at the caller's precision, and the moves against
/// "project": refused when the coordinates or the speeds move farther than it.
void check_projection_moves(const system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u) {
  const system_definition& d = *in.def;
  const int nq = d.vars.coordinates, n = d.vars.speeds;
  const mpfi tol = value<mpfi>(*in.project);
  mpfi dq2 = 0, du2 = 0;
  for (int i = 0; i < nq; ++i) {
    q(i) = value<mpfi>(in.q[static_cast<std::size_t>(i)]);
    dq2 += sqr(mpfi(q(i) - value<mpfi>(in.q_given[static_cast<std::size_t>(i)])));
  }
  for (int j = 0; j < n; ++j) {
    if (std::find(in.solved.begin(), in.solved.end(), j) != in.solved.end()) continue;
    u(j) = value<mpfi>(in.u[static_cast<std::size_t>(j)]);
    du2 += sqr(mpfi(u(j) - value<mpfi>(in.u_given[static_cast<std::size_t>(j)])));
  }
  if (certainly_positive(mpfi(sqrt(dq2) - tol)))
    throw input_error("state: off the constraints; the projection moves the coordinates by about " + short_text(sqrt(dq2)) +
                      ", more than project = " + in.project->text);
  if (certainly_positive(mpfi(sqrt(du2) - tol)))
    throw input_error("state: off the constraints; the projection moves the speeds by about " + short_text(sqrt(du2)) +
                      ", more than project = " + in.project->text);
}

void project_state(system_input& in, vector_t<mpfi>& q, vector_t<mpfi>& u) {
  project_at_400_bits(in);
  check_projection_moves(in, q, u);
}

void set_reference_motion(linearize_input& li, const system_input& in) {
  li.q = in.q;
  li.u = in.u;
  for (const auto& [i, v] : li.about_q) li.q[static_cast<std::size_t>(i)] = v;
  for (const auto& [j, v] : li.about_u) li.u[static_cast<std::size_t>(j)] = v;
}

}  // namespace appell::system_reading
