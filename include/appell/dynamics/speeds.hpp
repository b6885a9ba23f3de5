// appell/dynamics/speeds.hpp -- changes of generalized speeds (quasi-velocities).
//
// A change u = T(q,t) v + t(q,t), integrable or not, is a library operation:
// with_speeds<Base, Change> is the same mechanical system described with the
// speeds v, and gibbs_appell() differentiates it like any other (so the
// velocity-product terms of T' v + t' come for free).  Eq. (4) says
// P_v = T^T P_u; tests check it with random invertible T.
//
// adapted_speeds builds, from frictionless constraints A(q,t) u = a(q,t)
// (s rows), speeds v = (v_a, v_c) in which the constraints read v_c = 0
// (Cotton sec. 5): v_a are k = n - s components of u chosen at the state
// (column pivoting on the midpoint of A), and v_c = A u - a.
#pragma once

#include <initializer_list>

#include <algorithm>
#include <numeric>

#include "appell/dynamics/gibbs_appell.hpp"
#include "appell/linalg/scratch.hpp"

namespace appell {

namespace detail {
/// with_speeds inherits its base's bound on the number of speeds, if it has one.
template <class Base>
struct speeds_bound {};
template <bounded_speeds Base>
struct speeds_bound<Base> {
  static constexpr int max_speeds = Base::max_speeds;
};
}  // namespace detail

template <class Base, class Change>
struct with_speeds : detail::speeds_bound<Base> {
  const Base* base;
  Change change;  ///< change.template apply<S>(q, v, t) -> u, affine in v
  int k;          ///< dim v
  int speeds() const { return k; }
  template <class S>
  vector_t<S> qdot(const vector_t<S>& q, const vector_t<S>& v, const S& t) const {
    const scratch<vector_t<S>, with_speeds> u;
    apply_change(q, v, t, *u);
    return base->template qdot<S>(q, *u, t);
  }
  /// q' into qd, where the base system offers qdot_into (no vector made: linalg/scratch.hpp).
  template <class S>
  void qdot_into(const vector_t<S>& q, const vector_t<S>& v, const S& t, vector_t<S>& qd) const
    requires requires(const Base& b, const vector_t<S>& x, const S& time, vector_t<S>& r) {
      b.template qdot_into<S>(x, x, time, r);
    }
  {
    const scratch<vector_t<S>, with_speeds> u;
    apply_change(q, v, t, *u);
    base->template qdot_into<S>(q, *u, t, qd);
  }
  template <class S>
  void bodies(const vector_t<S>& q, const vector_t<S>& v, const S& t, std::vector<body_state<S>>& out) const {
    const scratch<vector_t<S>, with_speeds> u;  // borrowed: no vector per call (linalg/scratch.hpp)
    apply_change(q, v, t, *u);
    base->template bodies<S>(q, *u, t, out);
  }

 private:
  template <class S>
  void apply_change(const vector_t<S>& q, const vector_t<S>& v, const S& t, vector_t<S>& u) const {
    if constexpr (requires { change.template apply_into<S>(q, v, t, u); })
      change.template apply_into<S>(q, v, t, u);
    else
      u = change.template apply<S>(q, v, t);
  }
};

/// u = T v + t with constant T, t.
template <Scalar T>
struct constant_change {
  matrix_t<T> Tm;
  vector_t<T> tv;
  template <class S>
  vector_t<S> apply(const vector_t<S>&, const vector_t<S>& v, const S&) const {
    vector_t<S> u(Tm.rows());
    for (Eigen::Index i = 0; i < Tm.rows(); ++i) {
      S s = S(tv(i));
      for (Eigen::Index j = 0; j < Tm.cols(); ++j) s += S(Tm(i, j)) * v(j);
      u(i) = s;
    }
    return u;
  }
};

template <class Base, class Change>
with_speeds<Base, Change> change_speeds(const Base& base, Change change, int k) {
  return {{}, &base, std::move(change), k};
}

/// Frictionless constraints A(q,t) u = a(q,t) given by a templated callable:
///   con.count() -> s;   con.template eval<S>(q, t, A (s x n), a (s)).
/// The speeds v = (u_free (k of them), A u - a (s of them)).
template <class Constraint>
struct adapted_change {
  Constraint con;
  std::vector<int> free_columns;  ///< the k components of u kept as speeds
  std::vector<int> bound_columns;  ///< the s components solved from the constraints

  template <class S>
  vector_t<S> apply(const vector_t<S>& q, const vector_t<S>& v, const S& t) const {
    vector_t<S> u;
    apply_into(q, v, t, u);
    return u;
  }
  /// The same into u; the working matrices borrowed (linalg/scratch.hpp).
  template <class S>
  void apply_into(const vector_t<S>& q, const vector_t<S>& v, const S& t, vector_t<S>& u) const {
    const int s = con.count(), k = static_cast<int>(free_columns.size()), n = k + s;
    struct site;  // this function's pools (linalg/scratch.hpp: an Eigen object keeps one size)
    const scratch<matrix_t<S>, site> A_held, Ab_held;
    const scratch<vector_t<S>, site> a_held, rhs_held;
    matrix_t<S>&A = *A_held, &Ab = *Ab_held;
    vector_t<S>&a = *a_held, &rhs = *rhs_held;
    A.resize(s, n), a.resize(s), Ab.resize(s, s), rhs.resize(s);
    con.template eval<S>(q, t, A, a);
    u.resize(n);
    for (int i = 0; i < k; ++i) u(free_columns[i]) = v(i);
    // A_b u_b = v_c + a - A_f u_f, by elimination in the order fixed at the state.
    // Entries that are exactly 0 (or pivots exactly 1) are skipped: constraint
    // matrices are sparse (the rolling sphere's A_b is the identity), and the
    // skipped operations would give the same values (0 * x = 0, x / 1 = x).
    for (int r = 0; r < s; ++r) {
      S x = v(k + r) + a(r);
      for (int i = 0; i < k; ++i)
        if (!structurally_zero(A(r, free_columns[i]))) x -= A(r, free_columns[i]) * v(i);
      rhs(r) = x;
      for (int c = 0; c < s; ++c) Ab(r, c) = A(r, bound_columns[c]);
    }
    for (int p = 0; p < s; ++p)
      for (int r = p + 1; r < s; ++r) {
        if (structurally_zero(Ab(r, p))) continue;
        const S f = Ab(r, p) / Ab(p, p);
        for (int c = p; c < s; ++c) Ab(r, c) -= f * Ab(p, c);
        rhs(r) -= f * rhs(p);
      }
    for (int p = s - 1; p >= 0; --p) {
      S x = rhs(p);
      for (int c = p + 1; c < s; ++c)
        if (!structurally_zero(Ab(p, c))) x -= Ab(p, c) * u(bound_columns[c]);
      u(bound_columns[p]) = structurally_one(Ab(p, p)) ? x : S(x / Ab(p, p));
    }
  }
};

/// Adapted speeds keeping the given components of u as the free speeds (e.g.
/// the paper's choice, eq. 23 for the rolling sphere); the other columns of A
/// must form a nonsingular block at the state.  Into out, its column lists reused.
template <class Constraint>
void adapt_speeds_keeping_into(const Constraint& con, int n, std::initializer_list<int> free_columns,
                               adapted_change<Constraint>& out) {
  out.con = con;
  out.free_columns.assign(free_columns);
  out.bound_columns.clear();
  for (int j = 0; j < n; ++j)
    if (std::find(free_columns.begin(), free_columns.end(), j) == free_columns.end()) out.bound_columns.push_back(j);
  if (static_cast<int>(out.bound_columns.size()) != con.count())
    throw std::invalid_argument("adapt_speeds_keeping: n - (free speeds) must equal the number of constraints");
}
/// The same returned.
template <class Constraint>
adapted_change<Constraint> adapt_speeds_keeping(const Constraint& con, int n, std::initializer_list<int> free_columns) {
  adapted_change<Constraint> out{con, {}, {}};
  adapt_speeds_keeping_into(con, n, free_columns, out);
  return out;
}

/// Chooses the bound columns by pivoting on mid(A) at (q, t), largest pivot
/// first; with `free_columns` given, among the other columns only (they are
/// then the free speeds, in that order; the elimination of adapted_change needs
/// the bound columns in pivot order).
namespace detail {
/// adapt_speeds' choice into the lists `bound` and `free` (their storage reused).
template <Scalar T, class Constraint>
void choose_speeds(const Constraint& con, const vector_t<T>& q, const T& t, int n, const std::vector<int>* free_columns,
                   std::vector<int>& bound, std::vector<int>& free) {
  const int s = con.count();
  // working storage borrowed (linalg/scratch.hpp); out's column lists reused
  struct site;
  const scratch<matrix_t<T>, site> A_held;
  const scratch<vector_t<T>, site> a_held;
  const scratch<Eigen::MatrixXd, site> Am_held;
  const scratch<std::vector<bool>, site> used_held;
  matrix_t<T>& A = *A_held;
  vector_t<T>& a = *a_held;
  Eigen::MatrixXd& Am = *Am_held;
  std::vector<bool>& used = *used_held;
  A.resize(s, n), a.resize(s), Am.resize(s, n);
  con.template eval<T>(q, t, A, a);
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < n; ++j) Am(i, j) = approx_double(A(i, j));
  bound.clear();
  used.assign(static_cast<std::size_t>(n), false);
  if (free_columns)
    for (int j : *free_columns) used[static_cast<std::size_t>(j)] = true;
  for (int r = 0; r < s; ++r) {  // Gaussian elimination with full column choice, on doubles
    int best = -1;
    double best_abs = 0;
    for (int j = 0; j < n; ++j)
      if (!used[static_cast<std::size_t>(j)] && std::abs(Am(r, j)) > best_abs) {
        best_abs = std::abs(Am(r, j));
        best = j;
      }
    if (best < 0) throw certification_error("constraints: the rows of A are dependent at this state");
    used[static_cast<std::size_t>(best)] = true;
    bound.push_back(best);
    for (int r2 = r + 1; r2 < s; ++r2) {
      const double f = Am(r2, best) / Am(r, best);
      Am.row(r2) -= f * Am.row(r);
    }
  }
  if (free_columns) {
    free.assign(free_columns->begin(), free_columns->end());
    return;
  }
  free.clear();
  for (int j = 0; j < n; ++j)
    if (!used[static_cast<std::size_t>(j)]) free.push_back(j);
}
}  // namespace detail
template <Scalar T, class Constraint>
adapted_change<Constraint> adapt_speeds(const Constraint& con, const vector_t<T>& q, const T& t, int n,
                                        const std::vector<int>* free_columns = nullptr) {
  std::vector<int> bound, free;
  detail::choose_speeds<T>(con, q, t, n, free_columns, bound, free);
  return {con, std::move(free), std::move(bound)};
}
/// The same into `out` (an assignable Constraint), its column lists reused.
template <Scalar T, class Constraint>
void adapt_speeds_into(const Constraint& con, const vector_t<T>& q, const T& t, int n, adapted_change<Constraint>& out,
                       const std::vector<int>* free_columns = nullptr) {
  detail::choose_speeds<T>(con, q, t, n, free_columns, out.bound_columns, out.free_columns);
  out.con = con;
}

namespace detail {
/// A change of speeds by reference: change_speeds(sys, change_ref{&change}, n) is the system in
/// the new speeds without a copy of the change (an adapted_change's column lists).
template <class Change>
struct change_ref {
  const Change* change;
  template <class S>
  vector_t<S> apply(const vector_t<S>& q, const vector_t<S>& v, const S& t) const {
    return change->template apply<S>(q, v, t);
  }
  template <class S>
  void apply_into(const vector_t<S>& q, const vector_t<S>& v, const S& t, vector_t<S>& u) const {
    if constexpr (requires { change->template apply_into<S>(q, v, t, u); })
      change->template apply_into<S>(q, v, t, u);
    else
      u = change->template apply<S>(q, v, t);
  }
};
template <class Change>
change_ref(const Change*) -> change_ref<Change>;
}  // namespace detail

}  // namespace appell
