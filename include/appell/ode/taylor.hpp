// appell/ode/taylor.hpp -- Taylor coefficients of a motion, and the point
// integrator of `appell simulate`.
//
// taylor_series(P, x0, p): the coefficients x_0 .. x_p of the solution of
// x' = f(x) through x0, by the recursion x_{k+1} = f(x)_k / (k + 1), f being
// the problem's right-hand side evaluated on jets (derivatives/jet.hpp) holding the
// coefficients known so far.  With interval coefficients each is enclosed.
//
// taylor_series_jacobian(P, X, p): the same coefficients over a box X, and
// their derivatives d x_k / d x0 over X (the right-hand side on
// multi_dual<jet<I>, dim>: the variational equation by the same recursion).
//
// simulate(): adaptive Taylor steps for point scalars.  Step size from the
// last two coefficients (Jorba & Zou 2005): h = min_k (tol / |x_k|)^(1/k),
// k = p - 1, p, times exp(-0.7 / (p - 1)); tol relative to max(1, |x|).
// The state is summed with Kahan's compensation, so that round-off may grow
// like sqrt(t) (Brouwer's law) rather than t.  Output times i * every are
// hit exactly (the step is cut there, not interpolated).
#pragma once

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "appell/errors.hpp"
#include "appell/expr/time_segment.hpp"
#include "appell/derivatives/slope.hpp"
#include "appell/derivatives/jet.hpp"
#include "appell/linalg/scratch.hpp"
#include "appell/scalar/standard_scalars.hpp"

namespace appell::ode {

/// A named list of values along a motion: a problem's results or invariants at a state.
template <class S>
struct named_values {
  std::string name;
  std::vector<S> values;
  bool zero_in_truth = false;  ///< an invariant that is 0 along the motion (a constraint's residual): drift absolute
};


/// A time or a step in a message: 9 significant digits, in exponent form when small or large
/// (std::to_string's fixed six decimals printed a step of 1.6e-9 as 0.000000).
inline std::string number_text(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

template <class S>
using series = std::vector<vector_t<S>>;  // series[k](i): coefficient k of component i

/// Whether the memo pays in S: it saves arithmetic and costs copies and comparisons.  Measured
/// (bench/taylor.cpp, appell_bench_taylor): 0.7 to 1.0 times as fast in double and long double,
/// 1.3 to 1.5 times faster in interval, 1.7 to 2.8 in dd, 2.2 to 4.2 in float128, 3.1 to 5.9 in
/// mpfr at 256 bits (order 91).
template <class S>
inline constexpr bool jet_memo_pays = !std::is_floating_point_v<S>;

/// Component i of the coefficients c[0..k] as a jet of order k: sum_m c[m](i) t^m.
template <class S>
jet<S> component_jet(const series<S>& c, Eigen::Index i, int k) {
  std::vector<S> a(static_cast<std::size_t>(k + 1));
  for (int m = 0; m <= k; ++m) a[static_cast<std::size_t>(m)] = c[static_cast<std::size_t>(m)](i);
  return jet<S>(std::move(a));
}

/// A series' memo, borrowed from the thread's pool (linalg/scratch.hpp) and emptied: every entry
/// forgotten (kind -1: nothing is reused from another series), its vectors' capacity kept, so
/// that a step's passes take nothing from the heap for the memo (a memo made afresh each step
/// grew every entry's vectors pass after pass: malloc and free were a quarter of the KR5's
/// enclosure, perf).
template <class S>
class fresh_memo {
 public:
  fresh_memo() {
    held_->begin_pass();
    held_->reused = held_->computed = 0;
    for (auto& e : held_->entries) e.kind = -1;
  }
  ::appell::detail::jet_memo<S>& operator*() { return *held_; }

 private:
  scratch<::appell::detail::jet_memo<S>, fresh_memo> held_;
};

/// Coefficients 0 .. p of the solution through x0.  Pass k evaluates the right-hand side on jets
/// of order k; with `memo` each operation takes its coefficients 0..k-1 from pass k - 1 and
/// computes only coefficient k (jet.hpp, detail::jet_memo): the same numbers, bit for bit, in
/// O(p^2) operations on coefficients instead of O(p^3).  `stats`, if given, receives the memo's
/// counts.
template <class P, class S>
series<S> taylor_series(const P& prob, const vector_t<S>& x0, int p, bool memo = jet_memo_pays<S>,
                        detail::jet_memo<S>* stats = nullptr) {
  const Eigen::Index n = x0.size();
  series<S> c(static_cast<std::size_t>(p + 1), vector_t<S>(n));
  c[0] = x0;
  vector_t<jet<S>> X(n);
  fresh_memo<S> local;
  detail::jet_memo<S>& m = stats ? *stats : *local;
  const detail::jet_memo_scope<S> scope(memo ? &m : nullptr);
  for (int k = 0; k < p; ++k) {
    const jet_order_scope order(k);
    m.begin_pass();
    for (Eigen::Index i = 0; i < n; ++i) X(i) = component_jet(c, i, k);
    const vector_t<jet<S>> F = prob.template rhs<jet<S>>(X);
    for (Eigen::Index i = 0; i < n; ++i) c[static_cast<std::size_t>(k + 1)](i) = F(i)[k] / S(k + 1);
  }
  return c;
}

/// taylor_series over a box X0 (interval scalars), each order's linear part separated
/// (docs/motion.md, "The series' linear part").  Coefficient k >= 1 of f(x(t)) is affine in
/// x_k:  f_k = f'(x_0) x_k + G_k,  G_k = f_k at x_k = 0, a function of x_0 .. x_{k-1}.  Evaluated
/// whole, x_k's width passes through every operation of the right-hand side and comes out times
/// the product of their magnitudes (an interval solve's |A^-1| times a stiffness: a held humanoid's
/// coefficients widened 1.6e6 times every two orders, where its true rates grow 5e3 times); with
/// A0 enclosing f' over a box that holds X0, f_k lies in  A0 x_k + G_k,  the width multiplied once,
/// by |A0|.  Each coefficient is the intersection of that enclosure and the whole pass's.  Two
/// passes an order: x_k = 0 first (its G_k), then the whole one, which takes the first k
/// coefficients of every operation from the memo (the operand comparison's fallback to one fewer,
/// jet.hpp): 2 to 2.5 times taylor_series's time.  Coefficient 1, f(x_0), is also taken in its
/// mean-value form f(xm) + A0 (x_0 - xm) about x_0's midpoint xm (one more evaluation, at a
/// point): evaluated over the box, the dependency of the right-hand side's operations made it
/// 1e2 to 1e3 times the width |A0| gives, and every later coefficient carries x_1.
/// std::logic_error if the two enclosures of a coefficient are disjoint (one of them would not
/// hold the truth).
template <class P, class S>
series<S> taylor_series_split(const P& prob, const vector_t<S>& x0, int p, const matrix_t<S>& A0) {
  static_assert(scalar_traits<S>::is_interval, "taylor_series_split: an enclosure's method");
  const Eigen::Index n = x0.size();
  if (A0.rows() != n || A0.cols() != n) throw std::logic_error("taylor_series_split: A0 is not n x n");
  series<S> c(static_cast<std::size_t>(p + 1), vector_t<S>(n));
  c[0] = x0;
  vector_t<jet<S>> X(n);
  vector_t<S> G(n);
  fresh_memo<S> local;
  detail::jet_memo<S>& m = *local;
  const detail::jet_memo_scope<S> scope(&m);
  for (int k = 0; k < p; ++k) {
    const jet_order_scope order(k);
    const auto sk = static_cast<std::size_t>(k);
    if (k >= 1) {
      m.begin_pass();
      for (Eigen::Index i = 0; i < n; ++i) {
        X(i) = component_jet(c, i, k);
        X(i).c[sk] = S(0);
      }
      const vector_t<jet<S>> F0 = prob.template rhs<jet<S>>(X);
      for (Eigen::Index i = 0; i < n; ++i) G(i) = F0(i)[k];
    }
    m.begin_pass();
    for (Eigen::Index i = 0; i < n; ++i) X(i) = component_jet(c, i, k);
    const vector_t<jet<S>> F = prob.template rhs<jet<S>>(X);
    const S kp1(k + 1);
    if (k == 0) {
      // f(x_0) by its mean-value form about x_0's midpoint xm as well:  f(x_0) in f(xm) + A0 (x_0 - xm)
      // (A0 holds f' over a box that holds x_0, which is convex and holds xm).
      vector_t<jet<S>> Xm(n);
      for (Eigen::Index i = 0; i < n; ++i) Xm(i) = jet<S>(appell::detail::thin<S>(scalar_traits<S>::mid(x0(i))));
      vector_t<jet<S>> Fm;
      {
        const appell::detail::jet_memo_scope<S> none(nullptr);
        Fm = prob.template rhs<jet<S>>(Xm);
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        S lin = Fm(i)[0];
        for (Eigen::Index j = 0; j < n; ++j)
          if (!exactly_zero(A0(i, j))) lin += A0(i, j) * (x0(j) - Xm(j)[0]);
        const S v = F(i)[0];
        if (upper(lin) < lower(v) || upper(v) < lower(lin))
          throw std::logic_error("taylor_series_split: the two enclosures of f(x_0) are disjoint");
        c[1](i) = appell::detail::intersect(v, lin);
      }
      continue;
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      S v = F(i)[k];
      if (k >= 1) {
        S lin = G(i);
        for (Eigen::Index j = 0; j < n; ++j)
          if (!exactly_zero(A0(i, j))) lin += A0(i, j) * c[sk](j);
        if (upper(lin) < lower(v) || upper(v) < lower(lin))
          throw std::logic_error("taylor_series_split: the two enclosures of a coefficient are disjoint");
        v = appell::detail::intersect(v, lin);
      }
      c[sk + 1](i) = v / kp1;
    }
  }
  return c;
}

/// Row i of the matrices D[0..k] as n jets of order k: out[j] = sum_m D[m](i, j) t^m.
template <class I, class Out>
void derivative_jets(const std::vector<matrix_t<I>>& D, int i, int k, Out& out) {
  for (std::size_t j = 0; j < out.size(); ++j) {
    std::vector<I> d(static_cast<std::size_t>(k + 1));
    for (int m = 0; m <= k; ++m) d[static_cast<std::size_t>(m)] = D[static_cast<std::size_t>(m)](i, static_cast<Eigen::Index>(j));
    out[j] = jet<I>(std::move(d));
  }
}

/// Coefficients over the box X and their Jacobians d x_k / d x0 (dim x dim), k = 0 .. p.
template <class P, class I>
void taylor_series_jacobian(const P& prob, const vector_t<I>& X0, int p, series<I>& c, std::vector<matrix_t<I>>& D,
                            bool memo = true) {
  constexpr int n = P::dim;
  using MD = multi_dual<jet<I>, n>;
  c.assign(static_cast<std::size_t>(p + 1), vector_t<I>(n));
  D.assign(static_cast<std::size_t>(p + 1), matrix_t<I>(n, n));
  c[0] = X0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) D[0](i, j) = I(i == j ? 1 : 0);
  vector_t<MD> X(n);
  fresh_memo<I> held;
  detail::jet_memo<I>& m = *held;
  const detail::jet_memo_scope<I> scope(memo ? &m : nullptr);
  for (int k = 0; k < p; ++k) {
    const jet_order_scope order(k);
    m.begin_pass();
    for (int i = 0; i < n; ++i) {
      X(i).v = component_jet(c, i, k);
      derivative_jets(D, i, k, X(i).d);
    }
    const vector_t<MD> F = prob.template rhs<MD>(X);
    const I kp1(k + 1);
    for (int i = 0; i < n; ++i) {
      c[static_cast<std::size_t>(k + 1)](i) = F(i).v[k] / kp1;
      for (int j = 0; j < n; ++j) D[static_cast<std::size_t>(k + 1)](i, j) = F(i).d[static_cast<std::size_t>(j)][k] / kp1;
    }
  }
}

/// The slopes of the coefficients over the box X0 about its point xh (derivatives/slope.hpp): for
/// every x in X0 and k = 0 .. p, x_k(x) - x_k(xh) = S* (x - xh) for some S* in D[k].  The right-hand
/// side on slope<jet<I>, dim>: the recursion of taylor_series_jacobian, with each quantity carried
/// over the box, at the centre and by its slopes.  xh must lie in X0 (enclose passes their hull).
/// D[k] lies inside the Jacobian d x_k / d x0 (X0) and has about half its width where the
/// right-hand side is quadratic (Euler's equations).  `centre`, if given, receives the coefficients
/// at xh, k = 0 .. p (the slopes' centre values: the evaluation computes them anyway).
/// A problem of a run-time size may ask for the columns first_col .. first_col + cols - 1 only
/// (D[k] then n x cols): a slope along one variable is computed apart from the others (each rule
/// above acts on each variable's slope alone), so the columns are those of the whole matrix, bit
/// for bit, and enclose computes them in two parts on two threads.
template <class P, class I>
void taylor_series_slopes(const P& prob, const vector_t<I>& xh, const vector_t<I>& X0, int p,
                          std::vector<matrix_t<I>>& D, bool memo = true, series<I>* centre = nullptr,
                          int first_col = 0, int cols = -1) {
  // a problem of a run-time size (P::dim == runtime_slopes) carries as many slopes as X0 has components
  const int n = P::dim == runtime_slopes ? static_cast<int>(X0.size()) : P::dim;
  if (cols < 0) cols = n - first_col;
  if (first_col < 0 || cols < 0 || first_col + cols > n || ((first_col != 0 || cols != n) && P::dim != runtime_slopes))
    throw std::logic_error("taylor_series_slopes: columns outside the state, or a part of a fixed size's");
  using SL = slope<jet<I>, P::dim>;
  series<I> cv(static_cast<std::size_t>(p + 1), vector_t<I>(n)), cc(static_cast<std::size_t>(p + 1), vector_t<I>(n));
  D.assign(static_cast<std::size_t>(p + 1), matrix_t<I>(n, cols));
  cv[0] = X0;
  cc[0] = xh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < cols; ++j) D[0](i, j) = I(i == first_col + j ? 1 : 0);
  vector_t<SL> X(n);
  fresh_memo<I> held;
  detail::jet_memo<I>& m = *held;
  const detail::jet_memo_scope<I> scope(memo ? &m : nullptr);
  for (int k = 0; k < p; ++k) {
    const jet_order_scope order(k);
    m.begin_pass();
    for (int i = 0; i < n; ++i) {
      X(i).v = component_jet(cv, i, k);
      X(i).c = component_jet(cc, i, k);
      if constexpr (P::dim == runtime_slopes) X(i).d.resize(static_cast<std::size_t>(cols));
      derivative_jets(D, i, k, X(i).d);
    }
    const vector_t<SL> F = prob.template rhs<SL>(X);
    const I kp1(k + 1);
    for (int i = 0; i < n; ++i) {
      cv[static_cast<std::size_t>(k + 1)](i) = F(i).v[k] / kp1;
      cc[static_cast<std::size_t>(k + 1)](i) = F(i).c[k] / kp1;
      for (int j = 0; j < cols; ++j) {
        const auto sj = static_cast<std::size_t>(j);
        if constexpr (P::dim == runtime_slopes)
          D[static_cast<std::size_t>(k + 1)](i, j) = sj < F(i).d.size() ? I(F(i).d[sj][k] / kp1) : I(0);
        else
          D[static_cast<std::size_t>(k + 1)](i, j) = F(i).d[sj][k] / kp1;
      }
    }
  }
  if (centre) *centre = std::move(cc);
}

/// sum_k c_k tau^k, k = first .. last (Horner).
template <class S>
vector_t<S> horner(const series<S>& c, const S& tau, int first, int last) {
  vector_t<S> r = c[static_cast<std::size_t>(last)];
  for (int k = last - 1; k >= first; --k) r = vector_t<S>(r * tau + c[static_cast<std::size_t>(k)]);
  if (first > 0)
    for (int k = 0; k < first; ++k) r = vector_t<S>(r * tau);
  return r;
}

/// The step size from the last two coefficients (point magnitudes).
template <class S>
double step_from_coefficients(const series<S>& c, double tol) {
  // Component by component: each with the tolerance tol max(1, |x_i|).  One scale for the
  // whole state (its largest component) let an angle that grows without bound (a top's spin
  // angle, 40 t) loosen the tolerance of every other component as t grows: the heavy top's
  // long-horizon error then grew as t^3 (appell horizon, docs/motion.md).
  const int p = static_cast<int>(c.size()) - 1;
  double h = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < c[0].size(); ++i) {
    const double eps = tol * std::max(1.0, std::fabs(approx_double(c[0](i))));
    for (int k = p - 1; k <= p; ++k) {
      const double m = std::fabs(approx_double(c[static_cast<std::size_t>(k)](i)));
      if (m > 0) h = std::min(h, std::pow(eps / m, 1.0 / k));
    }
  }
  return h * std::exp(-0.7 / (p - 1));
}

/// The largest step over which no term of the series moves a component by more than `growth`
/// times its size: |c_k(i)| h^k <= growth max(1, |x_i|) for k >= 1 (point magnitudes).  A bound
/// that step_from_coefficients lacks where the series ends (a motion of constant acceleration:
/// every coefficient past the second is 0, and the tolerance allows any step); infinity for a
/// state that does not move.
template <class S>
double step_within_growth(const series<S>& c, double growth) {
  double h = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < c[0].size(); ++i) {
    const double size = growth * std::max(1.0, std::fabs(approx_double(c[0](i))));
    for (std::size_t k = 1; k < c.size(); ++k) {
      const double m = std::fabs(approx_double(c[k](i)));
      if (m > 0) h = std::min(h, std::pow(size / m, 1.0 / static_cast<double>(k)));
    }
  }
  return h;
}

struct simulate_options {
  std::string t_end;       ///< decimal
  std::string every;       ///< decimal; empty: the horizon / 100
  int order = 20;
  double tol = 0;          ///< per-step tolerance; 0: the scalar's unit round-off
  bool progress = true;    ///< a progress line on stderr for runs longer than a second
};

/// One output row of a point run.
template <class T>
struct sample {
  T t;
  vector_t<T> x;
  std::vector<named_values<T>> results, invariants;
};

struct simulate_stats {
  long steps = 0;
  double seconds = 0;
  double min_step = 0, max_step = 0;
};

/// Integrates prob from x0 over [0, t_end]; calls `emit` at t = 0, every, 2 every, ..., t_end.
template <class P, class T>
simulate_stats simulate(const P& prob, const vector_t<T>& x0, const T& t_end, const T& every, int order, double tol,
                        const std::type_identity_t<std::function<void(const sample<T>&)>>& emit,
                        const std::function<void(double)>& progress = {}) {
  using std::abs;
  const auto start = std::chrono::steady_clock::now();
  simulate_stats st;
  st.min_step = std::numeric_limits<double>::infinity();
  const Eigen::Index n = x0.size();
  vector_t<T> x = x0, comp = vector_t<T>::Zero(n);
  // The time with Kahan's compensation too: the elapsed time is t - tc.  Without it each step's
  // t + h rounds, and over a long run the recorded time drifts from the time integrated (the
  // error of a double run then jumped at every power of two of t: appell horizon, docs/motion.md).
  T t = T(0), tc = T(0);
  long next_index = 1;
  auto record = [&](const T& time) {
    sample<T> s{time, x, {}, {}};
    prob.results(x, s.results);
    prob.invariants(x, s.invariants);
    emit(s);
  };
  record(t);
  const double horizon = approx_double(t_end);
  // 16 units in the last place of the scalar, relative to max(1, |t|)
  const double h_floor = std::ldexp(16.0, -static_cast<int>(std::min(1000u, scalar_traits<T>::precision_bits())));
  // A table's breakpoints (times of the scene; t here is the time elapsed): a step ends at each,
  // and takes the piece it lies in (expr/time_segment.hpp), as enclose's steps do.
  std::vector<double> breaks;
  T start_time = T(0);
  if constexpr (requires { prob.breakpoints(); prob.time_component(); }) {
    breaks = prob.breakpoints();
    if (!breaks.empty()) {
      if (prob.time_component() < 0) throw std::logic_error("simulate: breakpoints in a motion that does not carry t");
      start_time = x0(prob.time_component());
    }
  }
  if constexpr (requires { prob.check_tables_cover(start_time, t_end); })
    if (!breaks.empty()) prob.check_tables_cover(start_time, t_end);
  std::size_t next_break = 0;
  double segment_start = -std::numeric_limits<double>::infinity();
  while (true) {
    T t_next = T(static_cast<double>(next_index)) * every;  // exact: next_index < 2^53
    bool last = false;
    if (!(t_next < t_end)) {
      t_next = t_end;
      last = true;
    }
    while (t < t_next) {
      while (next_break < breaks.size() && !(T(T(breaks[next_break]) - start_time) > t))
        segment_start = breaks[next_break++];
      T stop = t_next;
      bool at_break = false;
      if (next_break < breaks.size()) {
        const T b = T(breaks[next_break]) - start_time;
        if (b < t_next) stop = b, at_break = true;
      }
      std::optional<time_segment_scope> segment;
      if (!breaks.empty())
        segment.emplace(time_segment{segment_start, next_break < breaks.size() ? breaks[next_break]
                                                                                 : std::numeric_limits<double>::infinity()});
      const series<T> c = taylor_series(prob, x, order);
      T h = T(step_from_coefficients(c, tol));
      bool hits = false;
      if (!(t + h < stop)) {
        h = (stop - t) + tc;  // lands on stop: elapsed (t - tc) + h
        hits = true;
      } else if (!(approx_double(h) > h_floor * std::max(1.0, std::fabs(approx_double(t))))) {
        // Steps that no longer advance the time: the motion nears a singularity of its
        // right-hand side (a square root's branch point, a division by 0), which it cannot pass.
        throw certification_error("step-size collapse at t = " + number_text(approx_double(t)) +
                                  " (the series allow no step above " + number_text(h_floor) +
                                  " relative: a singularity of the motion)");
      }
      const vector_t<T> delta = horner(c, h, 1, order);
      for (Eigen::Index i = 0; i < n; ++i) {  // Kahan: x += delta with the carried error
        const T y = delta(i) - comp(i);
        const T s = x(i) + y;
        comp(i) = (s - x(i)) - y;
        x(i) = s;
      }
      if (hits) {
        t = stop;
        tc = T(0);
        if (at_break) segment_start = breaks[next_break++];
      } else {
        const T y = h - tc;
        const T s = t + y;
        tc = (s - t) - y;
        t = s;
      }
      ++st.steps;
      const double hd = approx_double(h);
      if (!hits) st.min_step = std::min(st.min_step, hd);
      st.max_step = std::max(st.max_step, hd);
      for (Eigen::Index i = 0; i < n; ++i)
        if (!is_finite(x(i))) throw certification_error("the state is no longer finite at t = " + number_text(approx_double(t)));
      if (progress) progress(approx_double(t) / horizon);
    }
    record(t);
    if (last) break;
    ++next_index;
  }
  if (!std::isfinite(st.min_step)) st.min_step = st.max_step;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return st;
}

// ---------------------------------------------------------------------------
// taylor_series and simulate of a problem P in scalar T, declared (EXTERN extern) or defined:
// the built-in models' problems are compiled once by the library (each model's home: APPELL_EXTERN_MODEL_MOTION), the
// system model's in models/system.hpp.
/// taylor_series and simulate of problem P in T; EXTERN is `extern` (declared) or empty (defined).
/// Expanded inside namespace appell::ode (an explicit instantiation names its template unqualified there).
#define APPELL_ODE_SERIES_INSTANCE(EXTERN, P, T)                                                     \
  EXTERN template series<T> taylor_series<P, T>(                       \
      const P&, const vector_t<T>&, int, bool, ::appell::detail::jet_memo<T>*);
#define APPELL_ODE_SIMULATE_INSTANCE(EXTERN, P, T)                                                   \
  EXTERN template simulate_stats simulate<P, T>(                       \
      const P&, const vector_t<T>&, const T&, const T&, int, double,                       \
      const std::function<void(const sample<T>&)>&, const std::function<void(double)>&);
#define APPELL_ODE_EXTERN_SERIES(P, T) APPELL_ODE_SERIES_INSTANCE(extern, P, T)
#define APPELL_ODE_EXTERN_SIMULATE(P, T) APPELL_ODE_SIMULATE_INSTANCE(extern, P, T)
#define APPELL_ODE_DEFINE_SERIES(P, T) APPELL_ODE_SERIES_INSTANCE(, P, T)
#define APPELL_ODE_DEFINE_SIMULATE(P, T) APPELL_ODE_SIMULATE_INSTANCE(, P, T)
}  // namespace appell::ode
