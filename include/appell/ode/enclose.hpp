// appell/ode/enclose.hpp -- a rigorous enclosure of the motion over [0, T]:
// the interval Taylor method with a high-order a priori enclosure and Lohner's
// QR wrapping control, for interval<double> and MPFI.
//
// One step from t_j, with the set of states held as  x in X_j  and
// x - xh_j in A_j r_j  (xh_j a point, A_j an exact point matrix, r_j a box):
//  1. A priori enclosure (Nedialkov, Jackson & Corliss 1999, "HOE"): if
//        Y = sum_{k<p} x_k(X_j) [0,h]^k + x_p(B) [0,h]^p  lies in B,
//     every solution from X_j exists on [0, h] and stays in Y.  B is found by
//     iteration from Y with x_p(B) := 0, inflated.
//  2. Step end: the flow is T(x) + (remainder), T(x) = sum_{k<p} x_k(x) h^k;
//     the remainder lies in R = x_p(B) h^p (Lagrange's form, coefficient p of
//     the solution at some state of B).  By the slopes of T about xh_j over X_j
//     (derivatives/slope.hpp; they lie inside the Jacobian over X_j, the mean-value
//     form, and have half its spread on a quadratic right-hand side)
//        x_{j+1} in T(xh_j) + J (x_j - xh_j) + R,  J = sum_{k<p} slope of x_k about xh_j over X_j h^k,
//     and with S = J A_j:  X_{j+1} = T(xh_j) + R + S r_j  (the box), and the
//     parallelepiped  xh_{j+1} + A_{j+1} r_{j+1},  r_{j+1} =
//     (A_{j+1}^-1 S) r_j + A_{j+1}^-1 (T(xh_j) + R - xh_{j+1}); A^-1 enclosed by
//     a verified solve.  On a problem of run-time size (a tree of links, a
//     large system) the linear part J is first taken from the variational
//     equation instead: Phi' = f'(x(t)) Phi with f'(x(t)) in A = f'(B), the
//     right-hand side's Jacobian over the step's box (one evaluation, where the
//     slopes of the series take q), and Phi(h) in sum_{k<=m} h^k/k! A^k plus
//     Picard's bound on the rest (detail::flow_jacobian), about the centre's
//     series T(xh) to p - 1; kept where its spread over X is within the slopes'
//     allowance (a standing robot: 8 times faster), else the slopes (a robot
//     arm that moves: A over the box it sweeps is of width 1).
//     Two such frames travel side by side, since neither
//     wins everywhere (measured: the QR frame is 10x tighter on Euler's body,
//     the parallelepiped 40x tighter on the heavy top): A_{j+1} the Q of a QR
//     factorization of mid(S) (columns ordered by length: Lohner's method),
//     and A_{j+1} = mid(S) itself (the parallelepiped method; replaced by the
//     Q when mid(S) has condition number above 1e8).  A third representation,
//     an affine form x in xh_j + shift_j + C_j e, e in [-1, 1]^N, shift_j a
//     point (detail::affine_set, as Kashiwagi's kv), keeps each step's error
//     (zr - xh_{j+1}) + J shift_j about its midpoint (the new shift) and the
//     width of J C_j as new symbols, carried by later Jacobians without
//     wrapping; beyond
//     3000 symbols per component the smaller half is merged into a
//     parallelotope.  Measured (bench/enclose_vs_kv.cpp): 1.2 to 18 times
//     tighter than the two frames alone on Euler's body, the heavy top and the
//     pendulum.  The box kept is the intersection of the box, of both
//     parallelepipeds, of the affine set's box, and of Y.
//  3. Over the whole step, the state lies in Y, and any quantity g(x) (the
//     scene's reactions, its energy) in  sum_{k<p} g_k(X_j) [0,h]^k + g_p(B) [0,h]^p:
//     g evaluated on the jets of the solution (its Taylor coefficients at
//     t_j, over X_j), and its coefficient p at the states of B (Lagrange's
//     remainder of g(x(t))).  Evaluating g on the box Y instead is wider by
//     orders of magnitude (docs/design.md §5).
// Steps whose a priori enclosure fails are halved; below a floor (or if a
// width exceeds the limit) the run stops: the enclosure up to there is kept
// and marked incomplete, with the reason.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "appell/expr/time_segment.hpp"
#include "appell/ode/enclose_threads.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/ode/taylor.hpp"

namespace appell::ode {

template <class I>
struct enclosed_step {
  I t0, t1;                                  ///< the step [t0, t1] (thin bounds unless the end is inexact)
  vector_t<I> end;                           ///< the state at t1
  vector_t<I> over;                          ///< the state over [t0, t1]
  std::vector<named_values<I>> results;      ///< the scene's results over [t0, t1]
  std::vector<named_values<I>> invariants;   ///< its invariants over [t0, t1]
};

struct enclose_stats {
  long steps = 0, rejected = 0;
  long variational = 0;  ///< steps whose linear part came from the variational equation (the rest: the slopes)
  double seconds = 0;
  bool complete = true;
  std::string reason;  ///< why it stopped, when incomplete
  double t_reached = 0;
};

namespace detail {
template <class I>
bool subset(const vector_t<I>& a, const vector_t<I>& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!(lower(b(i)) <= lower(a(i)) && upper(a(i)) <= upper(b(i)))) return false;
  return true;
}
template <class I>
I hull2(const I& a, const I& b) {
  return scalar_traits<I>::hull(a, b);
}
/// [-d, d] for d >= 0.
template <class I>
I from_bounds_sym(const I& d) {
  return scalar_traits<I>::hull(-d, d);
}
template <class I>
I inflate(const I& a, double rel, double abs_) {
  const auto r = scalar_traits<I>::width(a);
  using std::abs;
  const I d = I(rel) * I(r) + I(abs_);
  return a + from_bounds_sym<I>(d);
}
template <class I>
I thin_of(const bound_t<I>& v) {
  return appell::detail::thin<I>(v);
}
template <class I>
double max_width(const vector_t<I>& x) {
  double w = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) w = std::max(w, approx_double(I(scalar_traits<I>::width(x(i)))));
  return w;
}

/// One representation of the set of states: x - xh in A r.
template <class I>
struct frame {
  matrix_t<I> A;  ///< exact point matrix
  vector_t<I> r;
  bool qr;        ///< Lohner's QR frame (true) or the parallelepiped mid(S) (false)
};

/// The next frame's matrix from S = J A: the Q of mid(S) with columns ordered by length scaled
/// by r's widths (Lohner), or mid(S) itself while its condition number stays below 1e8.
template <class I>
matrix_t<I> next_frame_matrix(const matrix_t<I>& S, const vector_t<I>& r, bool qr) {
  const Eigen::Index n = S.rows();
  Eigen::MatrixXd Sm(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) Sm(i, j) = approx_double(S(i, j));
  Eigen::MatrixXd M;
  bool use_qr = qr;
  if (!qr) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Sm);
    const auto sv = svd.singularValues();
    use_qr = !(sv(n - 1) > 0) || !(sv(0) / sv(n - 1) < 1e8);
    if (!use_qr) M = Sm;
  }
  if (use_qr) {
    std::vector<std::pair<double, Eigen::Index>> len(static_cast<std::size_t>(n));
    for (Eigen::Index j = 0; j < n; ++j)
      len[static_cast<std::size_t>(j)] = {-Sm.col(j).norm() * std::max(approx_double(I(scalar_traits<I>::width(r(j)))), 1e-300), j};
    std::sort(len.begin(), len.end());
    Eigen::MatrixXd Sp(n, n);
    for (Eigen::Index j = 0; j < n; ++j) Sp.col(j) = Sm.col(len[static_cast<std::size_t>(j)].second);
    M = Eigen::HouseholderQR<Eigen::MatrixXd>(Sp).householderQ();
  }
  matrix_t<I> A(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) A(i, j) = I(M(i, j));
  return A;
}
/// max(|lower x|, |upper x|): exact in the bound type.
template <class I>
bound_t<I> mag(const I& x) {
  using std::abs;
  const bound_t<I> a = abs(lower(x)), b = abs(upper(x));
  return a < b ? b : a;
}

/// For the affine set's step in interval<double>: with J in [Jm - Jr, Jm + Jr] and a point
/// matrix C, G = RU(Jm C) and, for row i, e_i >= sum_c (|G - J* C|)_ic for every J* in J:
/// G - Jm C <= RU(Jm C) + RU((-Jm) C) and |Jm C - J* C| <= |Jr| |C|; abs_sum_i >= sum_c |G_ic|.  Products by
/// the sums of rump_products, fused over the columns of C, every operation rounded up in one scope; 2 n^2 N
/// double operations where interval products would take n^2 N interval ones.
[[gnu::noinline]] inline void affine_product_up(const Eigen::MatrixXd& Jm, const Eigen::MatrixXd& Jr,
                                                const Eigen::MatrixXd& C, Eigen::MatrixXd& G, Eigen::VectorXd& e,
                                                Eigen::VectorXd& abs_sum) {
  // rump_products' three sums (linalg/solve.hpp), fused, column by column of C: no N x n
  // temporaries (five of them, 0.6 MB a step at 16000 symbols, cost more than the products).
  const Eigen::Index n = C.rows(), N = C.cols();
  G.resize(n, N);
  e.setZero(n);
  abs_sum.setZero(n);
  {
    const upward_rounding mode;
    for (Eigen::Index c = 0; c < N; ++c)
      for (Eigen::Index i = 0; i < n; ++i) {
        double u = 0, d = 0, r = 0;  // RU(Jm C), RU((-Jm) C) = -RD(Jm C), RU(Jr |C|): each rounded up
        for (Eigen::Index k = 0; k < n; ++k) {
          const double a = C(k, c);
          u += a * Jm(i, k);
          d += (-a) * Jm(i, k);
          r += std::abs(a) * Jr(i, k);
        }
        G(i, c) = u;
        e(i) += interval_arith::opaque(u + d) + r;
        abs_sum(i) += std::fabs(u);
      }
    asm volatile("" : : "r"(G.data()), "r"(e.data()), "r"(abs_sum.data()) : "memory");
  }
}

/// The set of states as an affine form (affine arithmetic, as in Kashiwagi's kv):
///   x in xh + shift + C e,  e in [-1, 1]^N,  C an exact point matrix (n x N), shift a point
///   vector (both in the bound type).
/// A step maps it, by the slope form x' in zr + J (x - xh), to
///   xh' + shift' + G e + diag(d) e',  e' in [-1, 1]^n new symbols,
/// with g = (zr - xh') + J shift enclosed, shift' = mid(g), G a point matrix near J C and
/// d_i >= sum_c |J* C - G|_ic + |g_i - shift'_i| for every J* in J.  The step's own errors
/// become symbols that later steps' Jacobians carry as columns, never wrapped into a box and
/// turned back (the loss of the QR frame).  Beyond
/// max_cols symbols the smaller half is merged into a parallelotope (condense).
template <class I>
struct affine_set {
  using B = bound_t<I>;
  Eigen::Matrix<B, Eigen::Dynamic, Eigen::Dynamic> C;
  std::vector<I> abs_sum;  ///< upper bounds of sum_c |C_ic|, row by row
  /// The set's centre less xh, a point of the bound type: the set is xh + shift + C e.  The new
  /// centre xh' of a step is a number of the bound type, up to half an ulp of the state from the
  /// motion's own centre; kept here as a point, that offset is not a symbol of its own.  (As one,
  /// every step added half an ulp of each component: the heavy top's spin angle, 5 t, gained
  /// 2.8e-14 a step at T = 100, where the step's own error is about 1e-16.)
  std::vector<B> shift;

  static affine_set from_box(const vector_t<I>& X, const vector_t<I>& xh) {
    const Eigen::Index n = X.size();
    affine_set a{Eigen::Matrix<B, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n), {},
                 std::vector<B>(static_cast<std::size_t>(n), B(0))};
    for (Eigen::Index i = 0; i < n; ++i) a.C(i, i) = mag<I>(I(X(i) - xh(i)));
    a.sum_rows();
    return a;
  }

  /// J shift: where a step's slope form takes the set's centre, less the image of xh.
  vector_t<I> shift_image(const matrix_t<I>& J) const {
    const Eigen::Index n = C.rows();
    vector_t<I> g(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      I gi = J(i, 0) * thin_of<I>(shift[0]);
      for (Eigen::Index k = 1; k < n; ++k) gi += J(i, k) * thin_of<I>(shift[static_cast<std::size_t>(k)]);
      g(i) = gi;
    }
    return g;
  }

  void sum_rows() {
    abs_sum.assign(static_cast<std::size_t>(C.rows()), I(0));
    for (Eigen::Index i = 0; i < C.rows(); ++i)
      for (Eigen::Index c = 0; c < C.cols(); ++c) {
        using std::abs;
        const B a = abs(C(i, c));
        abs_sum[static_cast<std::size_t>(i)] += thin_of<I>(a);
      }
  }

  /// dz: an enclosure of zr - xh' (the step's own error about the new centre).  The new set is
  /// xh' + (dz + J shift) + J C e: its shift the midpoint of dz + J shift, the rest a new symbol.
  /// (enclose computes J shift once more, to choose xh' near the new centre: n^2 products.)
  void step(const matrix_t<I>& J, const vector_t<I>& dz, Eigen::Index max_cols) {
    const Eigen::Index n = C.rows(), N = C.cols();
    const vector_t<I> centre = vector_t<I>(dz + shift_image(J));  // the new set's centre, less xh
    Eigen::Matrix<B, Eigen::Dynamic, Eigen::Dynamic> Cn(n, N + n);
    Cn.setZero();
    std::vector<I> d(static_cast<std::size_t>(n));
    std::vector<I> sums(static_cast<std::size_t>(n), I(0));  // of |G_ic| over c
    if constexpr (std::is_same_v<I, interval>) {
      Eigen::MatrixXd Jm(n, n), Jr(n, n), G;
      Eigen::VectorXd e, a;
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) {
          const double lo = J(i, j).lower(), hi = J(i, j).upper();
          Jm(i, j) = scalar_traits<I>::mid(J(i, j));
          Jr(i, j) = std::max(upper(I(hi) - I(Jm(i, j))), upper(I(Jm(i, j)) - I(lo)));
        }
      affine_product_up(Jm, Jr, C, G, e, a);
      Cn.leftCols(N) = G;
      for (Eigen::Index i = 0; i < n; ++i) {
        d[static_cast<std::size_t>(i)] = I(e(i));
        sums[static_cast<std::size_t>(i)] = I(a(i));
      }
    } else {
      for (Eigen::Index i = 0; i < n; ++i) {
        I di = I(0);
        for (Eigen::Index c = 0; c < N; ++c) {
          I g = J(i, 0) * thin_of<I>(C(0, c));
          for (Eigen::Index k = 1; k < n; ++k) g += J(i, k) * thin_of<I>(C(k, c));
          Cn(i, c) = scalar_traits<I>::mid(g);
          di += thin_of<I>(mag<I>(I(g - thin_of<I>(Cn(i, c)))));
          using std::abs;
          const B a = abs(Cn(i, c));
          sums[static_cast<std::size_t>(i)] += thin_of<I>(a);
        }
        d[static_cast<std::size_t>(i)] = di;
      }
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      const B m = scalar_traits<I>::mid(centre(i));
      shift[static_cast<std::size_t>(i)] = m;
      const I di = d[static_cast<std::size_t>(i)] + thin_of<I>(mag<I>(I(centre(i) - thin_of<I>(m))));
      Cn(i, N + i) = upper(di);
      sums[static_cast<std::size_t>(i)] += thin_of<I>(Cn(i, N + i));
    }
    C = std::move(Cn);
    abs_sum = std::move(sums);
    if (C.cols() > max_cols) condense(C.cols() - max_cols / 2);
  }

  /// Merges the m smallest columns (by sum of |C_ic|) into a parallelotope: with P the Q of a QR
  /// factorization of those columns (longest first, as Lohner's frame), C_K e_K = P (P^-1 C_K) e_K
  /// lies in P diag(s) e', s_j >= sum_c |(P^-1 C_K)_jc| (P^-1 enclosed by verified solves).  The
  /// columns P(:, j) s_j are rounded to points and their rounding errors form one more diagonal.
  void condense(Eigen::Index m) {
    const Eigen::Index n = C.rows(), N = C.cols();
    std::vector<std::pair<double, Eigen::Index>> size(static_cast<std::size_t>(N));
    for (Eigen::Index c = 0; c < N; ++c) {
      double s = 0;
      for (Eigen::Index i = 0; i < n; ++i) s += std::fabs(approx_double(I(thin_of<I>(C(i, c)))));
      size[static_cast<std::size_t>(c)] = {s, c};
    }
    std::sort(size.begin(), size.end());
    std::vector<bool> merged(static_cast<std::size_t>(N), false);
    Eigen::MatrixXd Km(n, m);  // the merged columns, longest first
    matrix_t<I> K(n, m);
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Index c = size[static_cast<std::size_t>(m - 1 - j)].second;
      merged[static_cast<std::size_t>(c)] = true;
      for (Eigen::Index i = 0; i < n; ++i) {
        K(i, j) = thin_of<I>(C(i, c));
        Km(i, j) = approx_double(K(i, j));
      }
    }
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Km).householderQ();
    matrix_t<I> P(n, n), Pinv(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) P(i, j) = I(Q(i, j));
    for (Eigen::Index j = 0; j < n; ++j) {
      vector_t<I> ej = vector_t<I>::Zero(n);
      ej(j) = I(1);
      Pinv.col(j) = verified_solve(P, ej);
    }
    const matrix_t<I> D = appell::detail::product(Pinv, K);
    Eigen::Matrix<B, Eigen::Dynamic, Eigen::Dynamic> Cn(n, N - m + 2 * n);
    Cn.setZero();
    Eigen::Index kept = 0;
    for (Eigen::Index c = 0; c < N; ++c)
      if (!merged[static_cast<std::size_t>(c)]) Cn.col(kept++) = C.col(c);
    std::vector<I> err(static_cast<std::size_t>(n), I(0));
    for (Eigen::Index j = 0; j < n; ++j) {
      I s = I(0);
      for (Eigen::Index c = 0; c < m; ++c) s += thin_of<I>(mag<I>(D(j, c)));
      const I sj = thin_of<I>(upper(s));
      for (Eigen::Index i = 0; i < n; ++i) {
        const I g = P(i, j) * sj;
        Cn(i, kept + j) = scalar_traits<I>::mid(g);
        err[static_cast<std::size_t>(i)] += thin_of<I>(mag<I>(I(g - thin_of<I>(Cn(i, kept + j)))));
      }
    }
    for (Eigen::Index i = 0; i < n; ++i) Cn(i, kept + n + i) = upper(err[static_cast<std::size_t>(i)]);
    C = std::move(Cn);
    sum_rows();
  }

  /// The box xh + shift + C [-1, 1]^N.
  vector_t<I> box(const vector_t<I>& xh) const {
    vector_t<I> X(xh.size());
    for (Eigen::Index i = 0; i < C.rows(); ++i)
      X(i) = xh(i) + (thin_of<I>(shift[static_cast<std::size_t>(i)]) + from_bounds_sym<I>(abs_sum[static_cast<std::size_t>(i)]));
    return X;
  }
};
}  // namespace detail

namespace detail {
/// A second thread for one enclose: one job at a time, run with upward rounding (the job's
/// interval operations assume it, as the caller's do) and the caller's time segment; its
/// thread-local pools (the memo, the jets' blocks, scratch) persist from step to step.
class side_thread {
 public:
  side_thread() : thread_([this] { loop(); }) {}
  ~side_thread() {
    {
      const std::lock_guard l(m_);
      quit_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  side_thread(const side_thread&) = delete;
  side_thread& operator=(const side_thread&) = delete;

  /// Starts job on the thread (the previous one must have been waited for).
  void start(std::function<void()> job) {
    const time_segment* segment = ::appell::detail::active_time_segment;
    {
      const std::lock_guard l(m_);
      job_ = [job = std::move(job), segment] {
        const upward_rounding mode;
        std::optional<time_segment_scope> in_segment;
        if (segment) in_segment.emplace(*segment);
        job();
      };
      done_ = false;
      error_ = nullptr;
    }
    cv_.notify_all();
  }
  /// Waits for the job; returns what it threw (null if nothing).
  std::exception_ptr wait() {
    std::unique_lock l(m_);
    cv_.wait(l, [&] { return done_; });
    return std::exchange(error_, nullptr);
  }

 private:
  void loop() {
    std::unique_lock l(m_);
    for (;;) {
      cv_.wait(l, [&] { return quit_ || static_cast<bool>(job_); });
      if (!job_) {
        // MPFR keeps caches per thread (the interval functions' certified values); its manual
        // asks a thread to free them before it ends.
        mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
        return;
      }
      std::function<void()> job = std::move(job_);
      job_ = nullptr;
      l.unlock();
      std::exception_ptr error;
      try {
        job();
      } catch (...) {
        error = std::current_exception();
      }
      l.lock();
      error_ = error;
      done_ = true;
      cv_.notify_all();
    }
  }
  std::mutex m_;
  std::condition_variable cv_;
  std::function<void()> job_;
  bool done_ = true, quit_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once the members it reads are made
};

/// How many of a step's slope columns the side thread takes: k with its time (k + 2) c equal to
/// this thread's, the search s and the other columns (n - k + 2) c (each part also computes the
/// values over the box and at the centre, about two columns' work), c the time per column the
/// side thread measured at the last step: k = (s / c + n) / 2, at least 1, at most n (n: no
/// split).  Only the time is at stake: the columns are the same whatever the split.
struct column_split {
  int k = -1;  // -1: not measured yet (the first step: all on the side thread)
  int columns(int n) const { return k < 0 ? n : std::clamp(k, 1, n); }
  void learn(int n, int side_cols, double side_seconds, double search_seconds) {
    if (!(side_seconds > 0)) return;
    const double c = side_seconds / (side_cols + 2);
    const double best = 0.5 * (search_seconds / c + n);
    k = best >= n ? n : std::max(1, static_cast<int>(std::lround(best)));
  }
};

/// A job on the side thread if there is one, else run at once; wait() rethrows what it threw.
/// Leaving the scope waits (an exception of the caller's own goes on; the job's is dropped).
class side_job {
 public:
  side_job(side_thread* side, std::function<void()> job) : side_(side) {
    if (side_) {
      side_->start(std::move(job));
    } else {
      try {
        job();
      } catch (...) {
        error_ = std::current_exception();
      }
    }
  }
  ~side_job() {
    if (side_ && pending_) (void)side_->wait();
  }
  side_job(const side_job&) = delete;
  side_job& operator=(const side_job&) = delete;
  /// What the job threw, null if nothing (waits for it first).
  std::exception_ptr finish() {
    if (side_ && pending_) {
      pending_ = false;
      error_ = side_->wait();
    }
    return error_;
  }

 private:
  side_thread* side_;
  bool pending_ = true;
  std::exception_ptr error_;
};
}  // namespace detail

/// How many affine symbols a step keeps, per state component (enclose's affine set): fewer
/// widen long runs, more cost time (docs/motion.md, "The affine set", has the measurements).
inline constexpr int affine_symbols_per_component = 3000;

namespace detail {
/// On a step whose series take their linear part apart (enclose, taylor_series_split): a
/// component's remainder may also be split_remainder_share of its width (the step adds at most
/// that share of the width it has; 1e-4 took 16% fewer steps than the tolerance alone on the held
/// humanoid to t = 0.2, its width 6% more), and the variational part's spread the step's share
/// of the horizon, h / T, times split_spread_run_share of the state's largest width: over the whole
/// run the spreads taken so multiply the width by at most e^split_spread_run_share (the held
/// humanoid's steps of 5 to 30 ms to T = 1: 0.5% to 3% a step; a fixed 1% a step let the WAM's
/// thousands of short steps multiply it by 2e3 to t = 0.48).
inline constexpr double split_remainder_share = 1e-4;
inline constexpr double split_spread_run_share = 3.0;
/// A split step is near rest where its a priori box B is at most this many times as wide as the
/// state (the held humanoid's: 30 to 600 times; the WAM's, an arm that moves, 1e9): only there
/// is the spread's allowance the run's share, and a step refused by it taken again, shorter.
inline constexpr double split_near_rest = 1e5;
/// On those steps the variational part's Jacobian is the product of the flow's over this many
/// equal pieces of the step, each from the right-hand side's Jacobian over the piece's own box
/// (enclose's step end).
inline constexpr int split_variational_pieces = 4;

/// The least order of a step's slopes at series order p: 6, or p - 1 below it.
inline int lowest_slope_order(int p) { return std::min(6, p - 1); }

/// The width a step's linear part may add beyond the exact one's: `share` of the state's largest
/// width, or, where X is thinner, a tenth of the least remainder tolerance.  The slopes' omitted
/// terms (slope_order) and the variational part's spread (enclose's step end) are held to it.
template <class I>
double slope_allowance(const vector_t<I>& X, const std::vector<double>& remainder_tol, double share) {
  double least_tol = std::numeric_limits<double>::infinity();
  for (double r : remainder_tol) least_tol = std::min(least_tol, r);
  return std::max(share * max_width(X), 0.1 * least_tol);
}

/// The order q of a step's slopes (see the step end): the least, from lowest_slope_order(p),
/// whose neglected terms over a step of length h, sum_{q<k<p} x_k(X) h^k taken over the box X as
/// they stand, are within `share` of the state's largest width in every component (or, where X
/// is thinner, a tenth of the least remainder tolerance): the terms a step leaves out of the
/// slope form widen the state by at most that share a step.  A motion that moves fast for its steps
/// (the standing humanoid's, a step of 3 ms) needs 13 to 15 where a robot arm's needs 6
/// (docs/motion.md, "The slopes' order").
template <class I>
int slope_order(const series<I>& cX, const vector_t<I>& X, const std::vector<double>& remainder_tol, double h, int p,
                double share) {
  const int lowest = lowest_slope_order(p);
  const double allowed = slope_allowance(X, remainder_tol, share);
  // tail[q]: the largest over the components of sum_{q<k<p} width(x_k(X)) h^k
  std::vector<double> tail(static_cast<std::size_t>(p), 0.0);
  for (Eigen::Index i = 0; i < X.size(); ++i) {
    double sum = 0;
    for (int k = p - 1; k > lowest; --k) {
      const double w = approx_double(I(scalar_traits<I>::width(cX[static_cast<std::size_t>(k)](i))));
      if (w != 0) sum += w * std::pow(h, k);  // (an exact 0 times an overflowing h^k is no term)
      tail[static_cast<std::size_t>(k - 1)] = std::max(tail[static_cast<std::size_t>(k - 1)], sum);
    }
  }
  int q = p - 1;
  while (q > lowest && tail[static_cast<std::size_t>(q - 1)] <= allowed) --q;  // (NaN: no lower)
  return q;
}

/// The share of the state's width the terms a step leaves out of its slopes may add a step
/// (slope_order): 10^-3 on a tree of links (a problem whose recursion() says so), whose width
/// the motion's own growth sets (10^-7 gave the WAM the same width in 44% more time), 10^-7
/// elsewhere: a share that compounds over thousands of steps (Euler's body to T = 1000 ended
/// 500 times wider at 10^-3; docs/motion.md, "The slopes' order").
template <class P>
double slope_share(const P& prob) {
  if constexpr (requires { bool(prob.recursion()); })
    if (prob.recursion()) return 1e-3;
  return 1e-7;
}

/// The next step's length relative to the last whole step's, from the share `used` of its
/// remainder's tolerance that step took (its largest over the components): the remainder grows
/// about as h^(p + 6) (x_p over the step's box widens with the box, which grows with h), so the
/// next step aims at a tenth of the tolerance, within half and twice the last step.  A tenth,
/// not more: what a step leaves is carried, and grown, to T (the WAM to T = 1 ended 4 times
/// wider aiming at 0.3, and no faster: a step that needs no pieces of its box costs less).
inline double step_growth(double used, int p) {
  if (!(used > 0)) return 2.0;
  return std::clamp(std::pow(0.1 / used, 1.0 / (p + 6)), 0.5, 2.0);
}

/// Exponents e_i of a diagonal scaling D = diag(2^e_i) that balances |A| in the infinity norm:
/// the row sums of D |A| D^-1, |A_ij| 2^(e_i - e_j), near |A|'s Perron root, the least any
/// scaling gives.  Found in double (any scaling is sound: it only chooses the norm the remainder
/// is bounded in) from |A|'s Perron vector v, 2^-20 added to it at each iteration (every v_i >=
/// 2^-20, the exponents from 0 to 20), d_i = 1 / v_i rounded to a power of 2 (exact in every
/// interval type); all 0 where the iteration does not give finite numbers.  A state's derivative
/// that depends on the others at very different scales (a speed whose rate is a stiffness times
/// an angle: rows of |A| of 10^4 where its eigenvalues are 10^2) has an unbalanced norm far above
/// its spectral radius; balanced, the norm comes near it.
template <class I>
std::vector<int> balancing_exponents(const matrix_t<I>& A) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd M(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) M(i, j) = approx_double(thin_of<I>(mag<I>(A(i, j))));
  std::vector<int> e(static_cast<std::size_t>(n), 0);
  if (!M.allFinite()) return e;
  // Power iteration on |A| + r 1 (r the Collatz-Wielandt bound max_i (|A| v)_i / v_i, which
  // tends to the root): a state's rates and second derivatives make |A| cyclic (eigenvalues +-
  // the root), on which the plain iteration would not settle.
  Eigen::VectorXd v = Eigen::VectorXd::Ones(n);
  for (int it = 0; it < 100; ++it) {
    const Eigen::VectorXd w = M * v;
    const double r = (w.array() / v.array()).maxCoeff();
    if (!(r > 0) || !std::isfinite(r)) return e;  // A = 0: no scaling
    v = w + r * v;
    v = (v / v.maxCoeff()).array() + std::ldexp(1.0, -20);
  }
  if (!v.allFinite()) return e;
  for (Eigen::Index i = 0; i < n; ++i)
    e[static_cast<std::size_t>(i)] = std::clamp(-static_cast<int>(std::lround(std::log2(v(i)))), 0, 20);
  return e;
}

/// The flow's Jacobian over a step from the right-hand side's Jacobian over the step's a priori
/// box B (the variational equation's own enclosure): with A(t) = f'(x(t)) in A for t in [0, h]
/// (x(t) stays in B), Phi' = A(t) Phi, Phi(0) = 1, and Picard's iterates give
///     Phi(h) = sum_{k<=m} (iterated integral of A(s_1) ... A(s_k) over the simplex) + R_m,
/// each iterated integral h^k / k! times a mean of products of k members of A, so inside
/// h^k / k! A^k (interval products: each term from the last, T_k = (h / k) A T_(k-1), never a
/// Horner form, whose shared factor would not enclose the independent means).  The remainder in
/// a balanced norm (balancing_exponents): D Phi D^-1 solves the same equation with D A(t) D^-1,
/// so ||D R_m D^-1||_inf <= (h a)^(m+1) / (m+1)! e^(h a), a = ||D A D^-1||_inf (Gronwall), and
/// |R_m,ij| <= that bound times d_j / d_i.  Terms are added until the bound times the largest
/// d_j / d_i is below 2^-(bits + 16); entry (i, j) gets the bound times its own d_j / d_i.
/// Refused (false) where h a >= 30 (the terms would wrap, and the series would need too many).
/// docs/motion.md, "The linear part from the variational equation".
template <class I>
bool flow_jacobian(const matrix_t<I>& A, const I& h, matrix_t<I>& J) {
  const Eigen::Index n = A.rows();
  if (n == 0) {  // no state: Phi is 0 x 0
    J.resize(0, 0);
    return true;
  }
  auto bounded = [](const I& x) { return is_finite(x) && !(upper(x) < lower(x)); };
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      if (!bounded(A(i, j))) return false;  // an empty or unbounded entry: refused, never carried
  const std::vector<int> e = balancing_exponents(A);
  auto scale = [&](Eigen::Index i, Eigen::Index j) {  // d_i / d_j = 2^(e_i - e_j), exact
    return I(std::ldexp(1.0, e[static_cast<std::size_t>(i)] - e[static_cast<std::size_t>(j)]));
  };
  I alpha(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    I row(0);
    for (Eigen::Index j = 0; j < n; ++j) row += thin_of<I>(mag<I>(A(i, j))) * scale(i, j);
    alpha = thin_of<I>(upper(hull2(alpha, row)));
  }
  const I ha = thin_of<I>(upper(I(h * alpha)));
  if (!(upper(ha) < 30)) return false;
  const int range = *std::max_element(e.begin(), e.end()) - *std::min_element(e.begin(), e.end());
  const int bits = static_cast<int>(std::min(1000u, scalar_traits<I>::precision_bits()));
  const double target = std::ldexp(1.0, -(bits + 16 + range));
  matrix_t<I> T = matrix_t<I>::Identity(n, n);
  J = T;
  I bound = ha * exp(ha);  // (h a)^(k+1) / (k+1)! e^(h a) at k = 0
  int k = 0;
  while (!(upper(bound) < target)) {
    if (++k > 200) return false;
    T = appell::detail::product(A, T);
    const I c = h / I(k);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        T(i, j) *= c;
        J(i, j) += T(i, j);
      }
    bound = bound * ha / I(k + 1);
  }
  const I rho = thin_of<I>(upper(bound));
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      J(i, j) += from_bounds_sym<I>(thin_of<I>(upper(I(rho * scale(j, i)))));
      if (!bounded(J(i, j))) return false;
    }
  return true;
}

/// The width a Jacobian's enclosure J adds to the image J (x - xh) of a box X about xh: the
/// largest over the rows of sum_j width(J_ij) |X_j - xh_j|.
template <class I>
double jacobian_spread(const matrix_t<I>& J, const vector_t<I>& X, const vector_t<I>& xh) {
  double e = 0;
  for (Eigen::Index i = 0; i < J.rows(); ++i) {
    double row = 0;
    for (Eigen::Index j = 0; j < J.cols(); ++j)
      row += approx_double(I(scalar_traits<I>::width(J(i, j)))) * approx_double(thin_of<I>(mag<I>(I(X(j) - xh(j)))));
    if (std::isnan(row)) return row;  // a NaN spread: the variational part refused
    e = std::max(e, row);
  }
  return e;
}

/// Which linear part a step of a problem of run-time size takes (see enclose's step end): the
/// variational equation's (flow_jacobian), one evaluation of the right-hand side's Jacobian over
/// the step's box, while its enclosure adds no more width than the slopes' omitted terms may
/// (slope_order's allowance); otherwise the slopes, and the variational part is tried again after
/// 8 steps, then 16, ... up to 256 (a robot arm that moves: its box spans the motion, and the
/// Jacobian over it is of width 1).
struct linear_part_choice {
  int wait = 0, backoff = 8;
  bool try_variational() const { return wait == 0; }
  void step_taken(bool tried, bool held) {
    if (tried && held) {
      backoff = 8;
    } else if (tried) {
      wait = backoff;
      backoff = std::min(2 * backoff, 256);
    } else if (wait > 0) {
      --wait;
    }
  }
};
}  // namespace detail

/// A horizon (time elapsed from the start) that may lie on either side of the breakpoint b
/// (elapsed from the start too): the two overlap and are not the same one number.  enclose
/// refuses such a horizon; a refinement piece ending there runs a hair past it
/// (motion/engine.hpp, run_refinement_piece).
template <class I>
bool may_straddle(const I& b, const I& horizon) {
  const bool same = lower(b) == upper(b) && lower(horizon) == upper(horizon) && lower(b) == lower(horizon);
  return !same && !(upper(b) < lower(horizon)) && !(upper(horizon) < lower(b));
}

/// Encloses the motion of prob from the box x0 over [0, t_end]; calls `emit` for every step.
template <class P, class I>
enclose_stats enclose(const P& prob, const vector_t<I>& x0, const I& t_end, int p, double tol, double max_width,
                      int pieces,
                      const std::type_identity_t<std::function<void(const enclosed_step<I>&)>>& emit,
                      const std::function<void(double)>& progress = {}) {
  const int n = P::dim == runtime_slopes ? static_cast<int>(x0.size()) : P::dim;  // run-time size: x0's
  const auto start = std::chrono::steady_clock::now();
  enclose_stats st;
  vector_t<I> X = x0;
  vector_t<I> xh(n), r(n);
  for (int i = 0; i < n; ++i) {
    xh(i) = detail::thin_of<I>(scalar_traits<I>::mid(X(i)));
    r(i) = X(i) - xh(i);
  }
  std::array<detail::frame<I>, 2> frames{detail::frame<I>{matrix_t<I>::Identity(n, n), r, true},
                                         detail::frame<I>{matrix_t<I>::Identity(n, n), r, false}};
  detail::affine_set<I> affine = detail::affine_set<I>::from_box(X, xh);
  I t = I(0);
  const double horizon = approx_double(t_end);
  std::optional<detail::side_thread> side;  // enclose_threads: the slopes' thread
  detail::column_split split;
  if constexpr (std::is_same_v<I, interval>)
    if (enclose_threads > 1) side.emplace();
  double h_last = 0, used_last = 0;  // the last whole step's length and share of the remainder's tolerance
  // On the steps with the series split, near rest (see the step end): a step whose variational
  // part spread more than allowed is taken again, shorter (h_retry), and the next steps grow no
  // faster than the spread allows (h_spread_cap).
  double h_retry = 0, h_spread_cap = std::numeric_limits<double>::infinity();
  int spread_retries = 0;
  detail::linear_part_choice linear_part;  // a problem of run-time size: the variational part or the slopes
  const I zero_h = I(0);
  // Where the right-hand side is not smooth in t (a table's breakpoints: expr/expression.hpp):
  // a step ends at the next one, and its evaluations take the piece between the last one passed
  // and the next (time_segment_scope): the step's a priori box reaches past both.
  // The breakpoints are times of the scene (the state's t, component time_index of x0: a run may
  // start anywhere along a motion, as --locate's do), this loop's t the time elapsed.
  std::vector<double> breaks;
  I start_time = I(0);
  int time_index = -1;
  if constexpr (requires { prob.breakpoints(); prob.time_component(); }) {
    breaks = prob.breakpoints();
    time_index = prob.time_component();
    if (!breaks.empty() && time_index < 0) throw std::logic_error("enclose: breakpoints in a motion that does not carry t");
    if (!breaks.empty()) start_time = x0(time_index);
  }
  if constexpr (requires { prob.check_tables_cover(start_time, t_end); })
    if (!breaks.empty()) prob.check_tables_cover(start_time, t_end);
  std::size_t next_break = 0;
  while (next_break < breaks.size() && breaks[next_break] <= upper(start_time)) {
    if (lower(start_time) < breaks[next_break]) {  // passed only if the whole start is at or after it
      st.complete = false;
      st.reason = "the motion cannot be started: its t in " + to_string(start_time) +
                  " may lie on either side of the breakpoint " + number_text(breaks[next_break]) + " of a table";
      return st;
    }
    ++next_break;
  }
  double segment_start = next_break > 0 ? breaks[next_break - 1] : approx_double(I(lower(start_time)));
  for (std::size_t k = next_break; k < breaks.size(); ++k)  // a horizon on a breakpoint: exactly, or refused
    if (may_straddle(I(I(breaks[k]) - start_time), t_end))
      throw input_error("the horizon " + to_string(t_end) + " may lie on either side of the breakpoint " +
                        number_text(breaks[k]) + " of a table, measured from the start (end the motion before it, "
                        "after it, or exactly on it)");
  while (true) {
    if (!(upper(t) < lower(t_end))) break;  // t_end reached
    const bool break_left = next_break < breaks.size();
    const double break_ahead = break_left ? breaks[next_break] : std::numeric_limits<double>::infinity();
    const I break_elapsed = break_left ? I(I(break_ahead) - start_time) : t_end;  // in this loop's time
    std::optional<time_segment_scope> segment;
    if (!breaks.empty()) segment.emplace(time_segment{segment_start, break_ahead});
    bool at_break = false;  // the step ends at break_ahead
    // Inside an upward_rounding scope (evaluation_scope<interval>) the interval operations trust
    // the mode: a caller's callback or other library that switched it refuses the run here, before
    // a step computed in the wrong mode (kv's own switches did so: docs/motion.md, "Against kv").
    verify_upward_rounding("enclose");
    // Over X: the coefficients to p (the a priori enclosure's polynomial to p - 1; the step size
    // from the last two), and the slopes of the first q only (see the step end).
    // A step that cannot be completed ends the run there, what was enclosed kept: the motion may
    // leave the right-hand side's domain (a square root of a negative, constraints that become
    // dependent) or a quantity of the step may not be finite.
    try {
    // The linear part of the step (see the step end): on a problem of run-time size, the
    // variational equation's first (detail::linear_part_choice), its series over the hull Xs of X
    // and xh (the segments from xh to X's points lie in Xs, and so does their motion in B);
    // otherwise the slopes about xh over Xs.
    const bool try_variational = P::dim == runtime_slopes && linear_part.try_variational();
    vector_t<I> Xs(n);
    for (int i = 0; i < n; ++i) Xs(i) = detail::hull2(X(i), xh(i));
    // The series' linear part (ode::taylor_series_split; docs/motion.md, "The series' linear
    // part"): on the steps that try the variational part, every series of the step (over X, over
    // B and its pieces, at the centre) takes each coefficient's linear part through A0, the
    // right-hand side's Jacobian over a box Bg meant to hold them all: the hull of Xs and its motion
    // over 2.5 times the last step by the series to order 2, inflated by its own width (one
    // Jacobian a step).  A series over a box Bg does not hold takes the Jacobian over its own box.
    const bool split_series = try_variational;
    auto jacobian_over = [&](const vector_t<I>& box) {  // the slopes about the box itself
      std::vector<matrix_t<I>> D;
      taylor_series_slopes(prob, box, box, 1, D, true, static_cast<series<I>*>(nullptr), 0, n);
      return std::move(D[1]);
    };
    vector_t<I> Bg;
    matrix_t<I> Ag;
    if constexpr (P::dim == runtime_slopes) {
      if (split_series && h_last > 0) {
        try {
          const series<I> c2 = taylor_series(prob, Xs, 2);
          const I reach = scalar_traits<I>::hull(zero_h, I(2.5 * h_last));
          Bg.resize(n);
          for (int i = 0; i < n; ++i) {
            const I moved = Xs(i) + reach * (c2[1](i) + reach * c2[2](i));
            Bg(i) = detail::inflate(detail::hull2(Xs(i), moved), 1.0, 1e-12 * std::max(1.0, std::fabs(approx_double(Xs(i)))));
          }
          Ag = jacobian_over(Bg);
        } catch (const std::exception& e) {
          if (!motion_refusal(e)) throw;
          Bg.resize(0);  // each series the Jacobian over its own box
        }
      }
    }
    auto series_over = [&](const vector_t<I>& box, int order) -> series<I> {
      if (split_series) {
        if (Bg.size() == n && detail::subset(box, Bg)) return taylor_series_split(prob, box, order, Ag);
        if constexpr (P::dim == runtime_slopes) return taylor_series_split(prob, box, order, jacobian_over(box));
      }
      return taylor_series(prob, box, order);
    };
    const series<I> cX = series_over(try_variational ? Xs : X, p);
    // The step: from the last coefficients at the centre, at most what the last whole step's
    // remainder allows (detail::step_growth), then shrunk until the a priori enclosure holds and
    // the remainder x_p(B) h^p is within the tolerance (over a wide B the interval coefficient
    // x_p(B) is overestimated far beyond the centre's: the last step's share, not the
    // coefficients, sets the length; docs/motion.md, "The step's length").
    // The remainder's width is added to the state at every step and carried to T: half the
    // tolerance, component by component, as the step size: tol max(1, |x_i|) (one scale for the
    // whole state would let a growing angle loosen every other component; docs/motion.md, "The
    // remainder tolerance").
    std::vector<double> remainder_tol(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      remainder_tol[static_cast<std::size_t>(i)] =
          std::max(0.5 * tol * std::max(1.0, std::fabs(approx_double(xh(i)))),
                   split_series ? detail::split_remainder_share * approx_double(I(scalar_traits<I>::width(X(i)))) : 0.0);
    // The step from the last coefficients over X (X is thin: they are the centre's to a few ulps,
    // and give the steps a separate series at xh would).
    double hd = step_from_coefficients(cX, tol);
    if (h_last > 0) hd = std::min(hd, h_last * detail::step_growth(used_last, p));
    if (split_series) hd = std::min(hd, h_spread_cap);
    if (h_retry > 0) hd = std::min(hd, h_retry);
    h_retry = 0;
    // Where the series ends (constant acceleration: the coefficients vanish past order 2) the
    // tolerance allows any step: no step grows a component more than 2^10 times its size, and
    // none is longer than the horizon (the sphere on a plane to t = 1e300 tried one step of
    // infinite length, and its matrices overflowed).
    hd = std::min({hd, step_within_growth(cX, 1024.0), horizon});
    // The slopes' order (detail::slope_order), from the coefficients over X and the length of the
    // last whole step (the steps change slowly; the proposal may be up to twice it).  Before a
    // step is known the proposal is the coefficients' alone, often ten times what the remainder
    // allows: the order then comes from the step found, the slopes computed after the search.
    // The share they may add a step (detail::slope_share).
    const double slope_share = detail::slope_share(prob);
    const bool step_known = h_last > 0;
    int q = step_known && !try_variational ? detail::slope_order(cX, X, remainder_tol, std::min(hd, h_last), p, slope_share) : 0;
    std::vector<matrix_t<I>> DX;
    series<I> cc;  // the coefficients at the centre xh, to q: T_q(xh)
    // The slopes about xh over X (hull with xh: the midpoint of the last step's enclosure need
    // not lie in the intersection of its boxes).  Their evaluation carries the series at xh along
    // (each slope's centre value), so it is not computed apart.  They are needed at the step's
    // end only: on the side thread, if there is one, while this one finds the step below.
    // A tree of many components (slopes sized at run time: their columns apart, bit for bit) splits
    // them: the side thread the first side_cols columns, this one the rest after its search, the
    // split moved step by step toward equal times (detail::column_split).
    int side_cols = n;
    if constexpr (P::dim == runtime_slopes)
      if (side) side_cols = split.columns(n);
    double side_seconds = 0, search_seconds = 0;
    std::optional<detail::side_job> slopes;
    auto start_slopes = [&] {
      slopes.emplace(side ? &*side : nullptr, [&] {
        const auto t0 = std::chrono::steady_clock::now();
        // after a search with the series' linear part separated the centre is that series' (the
        // slopes' own centre values would be the whole passes', far wider over a long step)
        taylor_series_slopes(prob, xh, Xs, q, DX, true, split_series ? static_cast<series<I>*>(nullptr) : &cc, 0, side_cols);
        side_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      });
    };
    // The variational part needs the series at xh to p - 1 (the step's centre), while this
    // thread finds the step.
    std::optional<detail::side_job> centre;
    if (try_variational)
      centre.emplace(side ? &*side : nullptr, [&] { cc = series_over(xh, p - 1); });
    else if (step_known)
      start_slopes();
    const auto search_start = std::chrono::steady_clock::now();
    // What the step's search throws is held until the slopes are done: their error, if any,
    // goes first, as it did when they were computed before the search (the same outcome and
    // reason either way).
    std::exception_ptr search_error;
    const long rejected_before = st.rejected;
    if (std::exception_ptr e = step_known && !try_variational && !side ? slopes->finish() : nullptr) std::rethrow_exception(e);
    // The smallest step: relative to the time reached (a floor relative to the horizon would
    // stop a long run, to t = 1e300, before its first step), 1e-9 max(1, |t|), or less where the
    // scalar's precision allows: a step of 20 significant bits at 2^(24 - bits) max(1, |t|) still
    // moves t by whole units of its last place (2^-104 in mpfi at 128 bits, where --locate
    // narrows a failure's time far below 1e-9), down to 2^-120: a motion that runs into a
    // singularity steps toward it until the floor, about one step per bit of the floor (and
    // 2^(24 - bits) itself underflows to 0 above about 1100 bits).
    const double h_floor =
        std::max(1.0, std::fabs(approx_double(t))) *
        std::min(1e-9, std::ldexp(1.0, std::max(24 - static_cast<int>(scalar_traits<I>::precision_bits()), -120)));
    bool accepted = false;
    double over_share = 0;  // a refused remainder's largest share of its tolerance (0: none)
    double used = 0;  // the accepted step's largest share of a remainder tolerance
    std::string refusal;  // why the last a priori enclosure was refused, if a solve or a domain refused it
    vector_t<I> Y(n), cpB(n), B(n);
    series<I> cB;
    I h;
    bool last = false;
    try {
    while (!accepted) {
      if (hd < h_floor) {
        st.complete = false;
        st.reason = "step-size collapse at t = " + number_text(approx_double(t)) + " (no a priori enclosure with h >= " +
                    number_text(h_floor) + (refusal.empty() ? ")" : "; the last refusal: " + refusal + ")");
        break;
      }
      // h is a double with at most 20 significant bits: t + h stays exact for t on the same grid.
      const int e = std::ilogb(hd);
      const double q = std::ldexp(1.0, e - 20);
      const double hq = std::floor(hd / q) * q;
      h = I(hq);
      last = !(upper(t + h) < lower(t_end));
      at_break = break_left && upper(break_elapsed) < lower(t_end) && !(upper(t + h) < lower(break_elapsed));
      if (at_break) {
        h = break_elapsed - t;  // ends at the breakpoint (an interval if the difference is not a double)
        last = false;
      } else if (last) {
        h = t_end - t;  // the last step ends at t_end exactly (an interval if t_end is not a double)
      }
      const I tau = scalar_traits<I>::hull(zero_h, h);
      const vector_t<I> base = horner(cX, tau, 0, p - 1);
      // Iterate B = base + x_p(B) tau^p from x_p := 0, inflated.
      for (int i = 0; i < n; ++i) B(i) = detail::inflate(base(i), 0.1, 1e-300);
      bool ok = false;
      const I taup = pown(tau, p);
      for (int it = 0; it < 8 && !ok; ++it) {
        try {  // over a box too wide the series may not be enclosed (a solve refuses): a smaller step
          cB = series_over(B, p);
        } catch (const certification_error& e) {
          refusal = e.what();
          break;
        } catch (const domain_error& e) {
          refusal = e.what();
          break;
        }
        cpB = cB[static_cast<std::size_t>(p)];
        for (int i = 0; i < n; ++i) Y(i) = base(i) + cpB(i) * taup;
        if (detail::subset(Y, B)) {
          ok = true;
        } else {
          for (int i = 0; i < n; ++i) B(i) = detail::inflate(detail::hull2(B(i), Y(i)), 0.5, 1e-300);
        }
      }
      if (ok) {
        // The remainder's coefficient: x_p at the states the motion passes through.  Over the
        // whole B it is overestimated (interval dependency grows with the box); the motion over
        // [tau_i, tau_i+1] stays in B_i = sum_k x_k(X) [tau_i, tau_i+1]^k + x_p(B) [tau_i, tau_i+1]^p
        // (within B), so x_p over the hull of the B_i's coefficients holds it, far tighter.
        const I hp = pown(h, p);
        auto remainder_width = [&](int i) { return approx_double(I(scalar_traits<I>::width(I(cpB(i) * hp)))); };
        auto remainder_within = [&] {  // every component's remainder within its tolerance
          for (int i = 0; i < n; ++i)
            if (!(remainder_width(i) <= remainder_tol[static_cast<std::size_t>(i)])) return false;
          return true;
        };
        auto largest_share = [&] {  // of a remainder tolerance, over the components
          double r = 0;
          for (int i = 0; i < n; ++i) r = std::max(r, remainder_width(i) / remainder_tol[static_cast<std::size_t>(i)]);
          return r;
        };
        // With the linear part separated x_p(B) is about proportional to B's width: pieces, at
        // best half as wide, cannot bring a remainder 10^4 times its tolerance within it.
        if (!remainder_within() && pieces > 1 && !(split_series && largest_share() > 1e4)) {
          vector_t<I> tight(n);
          bool refined = true;
          for (int piece = 0; piece < pieces && refined; ++piece) {
            const I tau_i = scalar_traits<I>::hull(h * I(piece) / I(pieces), h * I(piece + 1) / I(pieces));
            const vector_t<I> base_i = horner(cX, tau_i, 0, p - 1);
            vector_t<I> Bi(n);
            for (int i = 0; i < n; ++i)
              Bi(i) = appell::detail::intersect(I(base_i(i) + cpB(i) * pown(tau_i, p)), B(i));
            try {
              const vector_t<I> ci = series_over(Bi, p)[static_cast<std::size_t>(p)];
              for (int i = 0; i < n; ++i) tight(i) = piece == 0 ? ci(i) : detail::hull2(tight(i), ci(i));
            } catch (const certification_error&) {
              refined = false;
            } catch (const domain_error&) {
              refined = false;
            }
          }
          if (refined)
            for (int i = 0; i < n; ++i) cpB(i) = appell::detail::intersect(cpB(i), tight(i));
        }
        ok = remainder_within();
        const double share = largest_share();
        if (ok) used = share;
        else over_share = share;
      }
      if (ok) {
        accepted = true;
      } else {
        // A remainder too wide: with the linear part separated it grows about as h^32 (the
        // held humanoid's), so the step shrinks toward 0.3 of its tolerance, by 0.5 to 0.9;
        // otherwise (and where the a priori enclosure failed) by 0.7.
        hd *= split_series && over_share > 1 && std::isfinite(over_share)
                  ? std::clamp(std::pow(0.3 / over_share, 1.0 / 32), 0.5, 0.9)
                  : 0.7;
        over_share = 0;
        ++st.rejected;
      }
    }
    } catch (...) {
      search_error = std::current_exception();
    }
    search_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - search_start).count();
    // The variational part over the step found: the Jacobian of the right-hand side over B (the
    // columns in two parts, on two threads: each column apart, bit for bit), then
    // detail::flow_jacobian; kept if it widens the image of X by no more than the slopes'
    // omitted terms may (slope_order's allowance), else the slopes below.
    bool variational = false;
    double spread_share = 0;  // the variational part's spread over its allowance (split steps near rest)
    bool near_rest = false;
    matrix_t<I> Jv;
    if (try_variational) {
      std::exception_ptr centre_error = centre->finish();
      if (accepted && !search_error && !centre_error) {
        try {
          auto jacobian_over_box = [&](const vector_t<I>& box) {  // the columns in two parts, on two threads
            const int half = side ? n / 2 : n;
            std::vector<matrix_t<I>> DA, DB;
            std::optional<detail::side_job> part;
            if (half < n)
              part.emplace(&*side, [&] { taylor_series_slopes(prob, box, box, 1, DB, false, static_cast<series<I>*>(nullptr), half, n - half); });
            taylor_series_slopes(prob, box, box, 1, DA, false, static_cast<series<I>*>(nullptr), 0, half);
            if (part)
              if (std::exception_ptr e = part->finish()) std::rethrow_exception(e);
            matrix_t<I> A(n, n);
            A.leftCols(half) = DA[1];
            if (half < n) A.rightCols(n - half) = DB[1];
            return A;
          };
          const double allowed = detail::slope_allowance(X, remainder_tol, slope_share);
          // With the series' linear part separated the steps are 3 to 4 times longer and the
          // spread exceeds that allowance, where the slopes over such a step are far wider (their
          // Jacobian's entries 0.3 to 0.5 wide against 0.02 on the held humanoid): near rest (B
          // within split_near_rest times X's width) the step's share of the run's allowance is
          // taken (detail::split_spread_run_share; docs/motion.md).  A robot arm that moves spans
          // its motion with B, and the slopes serve it better: the allowance is theirs.
          near_rest = split_series && detail::max_width(B) <= detail::split_near_rest * detail::max_width(X);
          const double spread_allowed =
              near_rest ? std::max(allowed, detail::split_spread_run_share * approx_double(h) / horizon * detail::max_width(X))
                        : allowed;
          // With the series split, B is far wider than X (the motion over the step: 1e3 times on the
          // held humanoid), and so is the Jacobian over it: the flow's Jacobian is the product of
          // the flow's over split_variational_pieces pieces, each from the Jacobian over the piece's
          // box B_i (the series over X to p - 1 and x_p(B) over the piece's times, within B: the
          // remainder's pieces above).  The states at the piece's start lie in B_i and stay there
          // over the piece, so the flow from piece start to end lies in flow_jacobian(A(B_i), h / m);
          // their product holds the whole step's (the chain rule along each motion).
          const int m = split_series ? detail::split_variational_pieces : 1;
          bool held = true;
          for (int piece = 0; piece < m && held; ++piece) {
            vector_t<I> Bi = B;
            if (m > 1) {
              const I tau_i = scalar_traits<I>::hull(h * I(piece) / I(m), h * I(piece + 1) / I(m));
              const vector_t<I> base_i = horner(cX, tau_i, 0, p - 1);
              const I taup_i = pown(tau_i, p);
              for (int i = 0; i < n; ++i) Bi(i) = appell::detail::intersect(I(base_i(i) + cpB(i) * taup_i), B(i));
            }
            matrix_t<I> Ji;
            held = detail::flow_jacobian(jacobian_over_box(Bi), m > 1 ? I(h / I(m)) : h, Ji);
            if (held) Jv = piece == 0 ? std::move(Ji) : matrix_t<I>(appell::detail::product(Ji, Jv));
          }
          const double spread = held ? detail::jacobian_spread(Jv, Xs, xh) : std::numeric_limits<double>::quiet_NaN();
          variational = held && spread <= spread_allowed;
          if (held && near_rest) spread_share = spread / spread_allowed;
        } catch (const std::exception& e) {
          // the Jacobian over B not enclosed, or outside a domain: the slopes, which are over Xs
          if (!motion_refusal(e)) throw;
          variational = false;
        }
      }
      // A step near rest whose spread is up to 4 times its allowance, its Jacobians held: the
      // same step again, shorter (the spread grows about as h^3, the pieces' Jacobians each about
      // h wide over boxes about h wide; its allowance as h), rather than the slopes, which over
      // such a step are far wider and cost ten steps' time (the held humanoid's: 2e3 times wider
      // in one).  Further over it, the slopes, as on any other step.
      if (near_rest && !variational && spread_share > 1 && spread_share <= 4 && !centre_error && spread_retries < 8) {
        ++spread_retries;
        ++st.rejected;
        h_retry = approx_double(h) * std::clamp(std::sqrt(0.7 / spread_share), 0.25, 0.8);
        continue;
      }
      spread_retries = 0;
      // and the next steps no longer than the spread allows (twice this one at most)
      h_spread_cap = variational && near_rest && spread_share > 0
                         ? approx_double(h) * std::clamp(std::sqrt(0.8 / spread_share), 0.5, 2.0)
                         : std::numeric_limits<double>::infinity();
      linear_part.step_taken(true, variational);
      // A centre that failed as the motion may (a domain, a solve, an expression's branch point):
      // the slopes compute it again and say why; anything else is a bug and leaves the run.
      if (centre_error) {
        try {
          std::rethrow_exception(centre_error);
        } catch (const std::exception& e) {
          if (!motion_refusal(e)) throw;
        }
      }
    } else if (P::dim == runtime_slopes) {
      linear_part.step_taken(false, false);
    }
    if (variational) {
      q = p - 1;  // the step's centre series to p - 1 (cc), nothing left out
    } else if (!step_known || try_variational) {  // the order from the step found (none found: half the series' order)
      q = accepted && !search_error ? detail::slope_order(cX, X, remainder_tol, approx_double(h), p, slope_share)
                                    : std::max(detail::lowest_slope_order(p), p / 2);
      start_slopes();
    }
    // This thread's columns of the slopes (where split), after a search that found the step (an
    // error of the slopes comes from their values at the box and the centre, which the side
    // thread's part computes too).
    std::vector<matrix_t<I>> DXrest;
    std::exception_ptr own_error;
    if (!variational && side_cols < n && accepted && !search_error) {
      try {
        taylor_series_slopes(prob, xh, Xs, q, DXrest, true, static_cast<series<I>*>(nullptr), side_cols, n - side_cols);
      } catch (...) {
        own_error = std::current_exception();
      }
    }
    std::exception_ptr slopes_error = slopes ? slopes->finish() : nullptr;  // the side thread's part first
    if (!slopes_error) slopes_error = own_error;
    if (slopes_error) {  // as if the slopes had been computed before the search
      st.rejected = rejected_before;
      std::rethrow_exception(slopes_error);
    }
    if (search_error) std::rethrow_exception(search_error);
    if (side && step_known && !try_variational) split.learn(n, side_cols, side_seconds, search_seconds);
    if (!DXrest.empty())
      for (std::size_t k = 0; k < DX.size(); ++k) {
        matrix_t<I> whole(n, n);
        whole.leftCols(side_cols) = DX[k];
        whole.rightCols(n - side_cols) = DXrest[k];
        DX[k] = std::move(whole);
      }
    if (!accepted) break;
    if (!last && (!at_break || h_last == 0)) {  // a step cut short at a breakpoint says little of the next
      h_last = approx_double(h);
      used_last = used;
    }
    // Step end (Lohner, QR).
    const I hp = pown(h, p);
    vector_t<I> R(n);
    for (int i = 0; i < n; ++i) R(i) = cpB(i) * hp;
    // T(x) = T_q(x) + H(x), H(x) = sum_{q<k<p} x_k(x) h^k: the slope form on T_q only
    // (J = sum_{k<=q} S_k h^k, S_k the slope of x_k about xh over X), and H over X as it stands,
    // H(X) from the coefficients over X: its width, about width(X) |d x_k/dx0| h^k for k > q, is
    // negligible, and the slopes cost O(q^3) instead of O(p^3).
    // The linear part J: the variational one (Jv), or J = sum_{k<=q} S_k h^k.
    matrix_t<I> J;
    if (variational) {
      J = std::move(Jv);
    } else {
      J = DX[static_cast<std::size_t>(q)];
      for (int k = q - 1; k >= 0; --k) J = matrix_t<I>(J * h + DX[static_cast<std::size_t>(k)]);
    }
    // zr = xh + rest, rest = (T_q(xh) - xh) + H(X) + R: the motion from the point xh lies in zr.
    // The step's error about the new centre xhn is kept as dz = (xh - xhn) + rest, not zr - xhn:
    // xh - xhn is exact (or one rounding of a tiny number), so dz is about as wide as rest, where
    // zr - xhn carries zr's own rounding, an ulp of the state on each side (docs/motion.md, "The
    // step's own error").
    const vector_t<I> tail = horner(series<I>(cc.begin(), cc.begin() + q + 1), h, 1, q);  // T_q(xh) - xh
    const vector_t<I> H = q < p - 1 ? horner(cX, h, q + 1, p - 1) : vector_t<I>(vector_t<I>::Zero(n));
    const vector_t<I> rest = tail + H + R;
    vector_t<I> zr = xh + rest, Xn(n), xhn(n), dzr(n);
    const vector_t<I> moved = rest + affine.shift_image(J);  // the affine set's centre, less xh
    for (int i = 0; i < n; ++i) {
      Xn(i) = zr(i);
      // The new centre: of the two numbers of the bound type around the affine set's next
      // centre xh + mid(rest + J shift), the one nearer: within half an ulp of it (the rest is
      // the set's shift), where mid(zr) is up to one ulp off (zr's bounds each rounded outward).
      const I around = xh(i) + detail::thin_of<I>(scalar_traits<I>::mid(moved(i)));
      const I lo = detail::thin_of<I>(lower(around)), hi = detail::thin_of<I>(upper(around));
      const bool take_hi = detail::mag<I>(I((xh(i) - hi) + moved(i))) < detail::mag<I>(I((xh(i) - lo) + moved(i)));
      xhn(i) = take_hi ? hi : lo;
      dzr(i) = (xh(i) - xhn(i)) + rest(i);
    }
    bool first_frame = true;
    for (detail::frame<I>& f : frames) {
      const matrix_t<I> S = appell::detail::product(J, f.A);
      const vector_t<I> Sr = appell::detail::product(S, f.r);
      for (int i = 0; i < n; ++i) {
        const I box = zr(i) + Sr(i);
        Xn(i) = first_frame ? box : appell::detail::intersect(Xn(i), box);
      }
      first_frame = false;
      const matrix_t<I> An = detail::next_frame_matrix(S, f.r, f.qr);
      // A^-1 S and A^-1 (zr - xhn) (as dzr), each by verified solves with the exact point matrix An.
      matrix_t<I> AiS(n, n);
      for (int j = 0; j < n; ++j) AiS.col(j) = verified_solve(An, vector_t<I>(S.col(j)));
      const vector_t<I> dz = verified_solve(An, dzr);
      f.A = An;
      f.r = appell::detail::product(AiS, f.r) + dz;
    }
    for (const detail::frame<I>& f : frames) {
      const vector_t<I> par = xhn + appell::detail::product(f.A, f.r);
      for (int i = 0; i < n; ++i) Xn(i) = appell::detail::intersect(Xn(i), par(i));
    }
    affine.step(J, dzr, Eigen::Index(n) * affine_symbols_per_component);
    {
      const vector_t<I> aff = affine.box(xhn);
      for (int i = 0; i < n; ++i) Xn(i) = appell::detail::intersect(Xn(i), aff(i));
    }
    for (int i = 0; i < n; ++i) Xn(i) = appell::detail::intersect(Xn(i), Y(i));
    // With breakpoints, t (t' = 1) is the start's time plus the time elapsed, exactly: the frames'
    // rounding would leave a step that ends on a breakpoint within ulps around it, and a run that
    // starts from that state (--locate's) could not tell on which side it starts.
    if (!breaks.empty()) {
      const I now = start_time + I(t + h);
      if (upper(now) < lower(Xn(time_index)) || upper(Xn(time_index)) < lower(now))
        throw std::logic_error("enclose: the time component left the time elapsed");
      Xn(time_index) = appell::detail::intersect(Xn(time_index), now);
    }
    // Over the whole step: the state and the scene's quantities by their jets.
    enclosed_step<I> step;
    step.t0 = t;
    step.t1 = t + h;
    step.end = Xn;
    step.over = Y;
    {
      const I tau = scalar_traits<I>::hull(zero_h, h);
      const jet_order_scope order(p);
      vector_t<jet<I>> jX(n), jB(n);
      for (int i = 0; i < n; ++i) {
        std::vector<I> a(static_cast<std::size_t>(p + 1)), b(static_cast<std::size_t>(p + 1));
        for (int k = 0; k <= p; ++k) {
          a[static_cast<std::size_t>(k)] = k < p ? cX[static_cast<std::size_t>(k)](i) : I(0);
          b[static_cast<std::size_t>(k)] = cB[static_cast<std::size_t>(k)](i);
        }
        jX(i) = jet<I>(std::move(a));
        jB(i) = jet<I>(std::move(b));
      }
      auto over_step = [&](auto&& fill, std::vector<named_values<I>>& out) {
        std::vector<named_values<jet<I>>> gX, gB;
        fill(jX, gX);
        fill(jB, gB);
        for (std::size_t q = 0; q < gX.size(); ++q) {
          named_values<I> nv{gX[q].name, {}};
          for (std::size_t v = 0; v < gX[q].values.size(); ++v) {
            const jet<I>& a = gX[q].values[v];
            I s = gB[q].values[v][p];
            for (int k = p - 1; k >= 0; --k) s = s * tau + a[k];
            nv.values.push_back(s);
          }
          out.push_back(std::move(nv));
        }
      };
      over_step([&](const vector_t<jet<I>>& x, std::vector<named_values<jet<I>>>& o) { prob.results(x, o); }, step.results);
      over_step([&](const vector_t<jet<I>>& x, std::vector<named_values<jet<I>>>& o) { prob.invariants(x, o); },
                step.invariants);
    }
    verify_upward_rounding("enclose");  // the right-hand side's own code may have switched it
    emit(step);
    ++st.steps;
    if (variational) ++st.variational;
    t = step.t1;
    if (at_break) segment_start = breaks[next_break++];
    X = Xn;
    xh = xhn;
    st.t_reached = approx_double(t);
    if (progress) progress(st.t_reached / horizon);
    if (detail::max_width(X) > max_width) {
      st.complete = false;
      st.reason = "width blow-up at t = " + number_text(st.t_reached) + " (a state's width exceeds " +
                  number_text(max_width) + ")";
      break;
    }
    if (last) break;
    } catch (const std::exception& e) {
      // a rounding mode lost is the caller's error, not the motion's: it leaves the run
      if (::appell::detail::upward_known && !::appell::detail::mxcsr_is_upward()) throw;
      // a refusal of the right-hand side's own (an expression's derivative at a branch point is
      // std::invalid_argument) ends the motion as a domain error does; other errors are bugs
      if (dynamic_cast<const run_stopped*>(&e)) {  // on request (--max-seconds): not a failure of the motion
        st.complete = false;
        st.reason = e.what();
        break;
      }
      if (!motion_refusal(e)) throw;
      st.complete = false;
      st.reason = "the motion cannot be continued at t = " + number_text(approx_double(t)) + ": " + e.what();
      break;
    }
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return st;
}

// ---------------------------------------------------------------------------
// The slopes and enclose of a problem P in interval scalar I, declared (EXTERN extern) or
// defined: the built-in models' problems are compiled once (each model's home: APPELL_EXTERN_MODEL_MOTION).
#define APPELL_ODE_ENCLOSE_INSTANCE(EXTERN, P, I)                                                        \
  EXTERN template void taylor_series_slopes<P, I>(                                        \
      const P&, const vector_t<I>&, const vector_t<I>&, int,                         \
      std::vector<matrix_t<I>>&, bool, series<I>*, int, int);                  \
  EXTERN template enclose_stats enclose<P, I>(                             \
      const P&, const vector_t<I>&, const I&, int, double, double, int,                        \
      const std::function<void(const enclosed_step<I>&)>&, const std::function<void(double)>&);
#define APPELL_ODE_EXTERN_ENCLOSE(P, I) APPELL_ODE_ENCLOSE_INSTANCE(extern, P, I)
#define APPELL_ODE_DEFINE_ENCLOSE(P, I) APPELL_ODE_ENCLOSE_INSTANCE(, P, I)
}  // namespace appell::ode
