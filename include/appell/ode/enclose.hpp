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
//     the solution at some state of B).  By the mean-value theorem
//        x_{j+1} in T(xh_j) + J (x_j - xh_j) + R,  J = sum_{k<p} d x_k/d x0 (X_j) h^k,
//     and with S = J A_j:  X_{j+1} = T(xh_j) + R + S r_j  (the box), and the
//     parallelepiped  xh_{j+1} + A_{j+1} r_{j+1},  r_{j+1} =
//     (A_{j+1}^-1 S) r_j + A_{j+1}^-1 (T(xh_j) + R - xh_{j+1}); A^-1 enclosed by
//     a verified solve.  Two such frames travel side by side, since neither
//     wins everywhere (measured: the QR frame is 10x tighter on Euler's body,
//     the parallelepiped 40x tighter on the heavy top): A_{j+1} the Q of a QR
//     factorization of mid(S) (columns ordered by length: Lohner's method),
//     and A_{j+1} = mid(S) itself (the parallelepiped method; replaced by the
//     Q when mid(S) has condition number above 1e8).  The box kept is the
//     intersection of the box, of both parallelepipeds, and of Y.
//  3. Over the whole step, the state lies in Y, and any quantity g(x) (the
//     scene's reactions, its energy) in  sum_{k<p} g_k(X_j) [0,h]^k + g_p(B) [0,h]^p:
//     g evaluated on the jets of the solution (its Taylor coefficients at
//     t_j, over X_j), and its coefficient p at the states of B (Lagrange's
//     remainder of g(x(t))).  Evaluating g on the box Y instead is wider by
//     orders of magnitude (DESIGN.md sec. 5).
// Steps whose a priori enclosure fails are halved; below a floor (or if a
// width exceeds the limit) the run stops: the enclosure up to there is kept
// and marked incomplete, with the reason.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/QR>
#include <Eigen/SVD>

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
}  // namespace detail

/// Encloses the motion of prob from the box x0 over [0, t_end]; calls `emit` for every step.
template <class P, class I>
enclose_stats enclose(const P& prob, const vector_t<I>& x0, const I& t_end, int p, double tol, double max_width,
                      int pieces,
                      const std::type_identity_t<std::function<void(const enclosed_step<I>&)>>& emit,
                      const std::function<void(double)>& progress = {}) {
  constexpr int n = P::dim;
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
  I t = I(0);
  const double horizon = approx_double(t_end);
  const double h_floor = 1e-9 * std::max(1.0, horizon);
  double h_next = 0, h_factor = 1;
  const I zero_h = I(0);
  while (true) {
    if (!(upper(t) < lower(t_end))) break;  // t_end reached
    // Coefficients at the centre (step size and T(xh)), and over X with their Jacobian.
    const series<I> cc = taylor_series(prob, xh, p);
    // Over X: the coefficients to p - 1 (the a priori enclosure's polynomial), and the
    // Jacobians of the first q only (see the step end).
    const series<I> cX = taylor_series(prob, X, p - 1);
    const int q = std::min(p - 1, std::max(6, p / 2));
    series<I> cXq;
    std::vector<matrix_t<I>> DX;
    taylor_series_jacobian(prob, X, q, cXq, DX);
    // The step: from the last coefficients at the centre, times what the last steps learned
    // (h_factor), then shrunk until the a priori enclosure holds and the remainder x_p(B) h^p is
    // within the tolerance (over a wide B the interval coefficient x_p(B) is overestimated).
    double scale = 1;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::fabs(approx_double(xh(i))));
    const double remainder_tol = 4 * tol * scale;
    double hd = step_from_coefficients(cc, tol) * h_factor;
    if (h_next > 0) hd = std::min(hd, 2 * h_next);
    bool accepted = false, shrunk = false;
    vector_t<I> Y(n), cpB(n), B(n);
    series<I> cB;
    I h;
    bool last = false;
    while (!accepted) {
      if (hd < h_floor) {
        st.complete = false;
        st.reason = "step-size collapse at t = " + std::to_string(approx_double(t)) + " (no a priori enclosure with h >= " +
                    std::to_string(h_floor) + ")";
        break;
      }
      // h is a double with at most 20 significant bits: t + h stays exact for t on the same grid.
      const int e = std::ilogb(hd);
      const double q = std::ldexp(1.0, e - 20);
      const double hq = std::floor(hd / q) * q;
      h = I(hq);
      last = !(upper(t + h) < lower(t_end));
      if (last) h = t_end - t;  // the last step ends at t_end exactly (an interval if t_end is not a double)
      const I tau = scalar_traits<I>::hull(zero_h, h);
      const vector_t<I> base = horner(cX, tau, 0, p - 1);
      // Iterate B = base + x_p(B) tau^p from x_p := 0, inflated.
      for (int i = 0; i < n; ++i) B(i) = detail::inflate(base(i), 0.1, 1e-300);
      bool ok = false;
      const I taup = pown(tau, p);
      for (int it = 0; it < 8 && !ok; ++it) {
        try {  // over a box too wide the series may not be enclosed (a solve refuses): a smaller step
          cB = taylor_series(prob, B, p);
        } catch (const certification_error&) {
          break;
        } catch (const domain_error&) {
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
        auto remainder_width = [&] {
          double rw = 0;
          for (int i = 0; i < n; ++i) rw = std::max(rw, approx_double(I(scalar_traits<I>::width(I(cpB(i) * hp)))));
          return rw;
        };
        if (remainder_width() > remainder_tol && pieces > 1) {
          vector_t<I> tight(n);
          bool refined = true;
          for (int piece = 0; piece < pieces && refined; ++piece) {
            const I tau_i = scalar_traits<I>::hull(h * I(piece) / I(pieces), h * I(piece + 1) / I(pieces));
            const vector_t<I> base_i = horner(cX, tau_i, 0, p - 1);
            vector_t<I> Bi(n);
            for (int i = 0; i < n; ++i)
              Bi(i) = appell::detail::intersect(I(base_i(i) + cpB(i) * pown(tau_i, p)), B(i));
            try {
              const vector_t<I> ci = taylor_series(prob, Bi, p)[static_cast<std::size_t>(p)];
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
        ok = remainder_width() <= remainder_tol;
      }
      if (ok) {
        accepted = true;
      } else {
        hd *= 0.7;
        shrunk = true;
        ++st.rejected;
      }
    }
    h_factor = shrunk ? h_factor * 0.7 : std::min(1.0, h_factor * 1.05);
    if (!accepted) break;
    h_next = approx_double(h);
    // Step end (Lohner, QR).
    const I hp = pown(h, p);
    vector_t<I> R(n);
    for (int i = 0; i < n; ++i) R(i) = cpB(i) * hp;
    // T(x) = T_q(x) + H(x), H(x) = sum_{q<k<p} x_k(x) h^k: the mean-value form on T_q only
    // (J = sum_{k<=q} d x_k/d x0 (X) h^k), and H over X as it stands, H(X) from the coefficients
    // over X: its width, about width(X) |d x_k/dx0| h^k for k > q, is negligible, and the
    // Jacobians cost O(q^3) instead of O(p^3).
    matrix_t<I> J = DX[static_cast<std::size_t>(q)];
    for (int k = q - 1; k >= 0; --k) J = matrix_t<I>(J * h + DX[static_cast<std::size_t>(k)]);
    const vector_t<I> z = horner(series<I>(cc.begin(), cc.begin() + q + 1), h, 0, q);  // T_q(xh)
    const vector_t<I> H = q < p - 1 ? horner(cX, h, q + 1, p - 1) : vector_t<I>(vector_t<I>::Zero(n));
    vector_t<I> zr = z + H + R, Xn(n), xhn(n);
    for (int i = 0; i < n; ++i) {
      Xn(i) = zr(i);
      xhn(i) = detail::thin_of<I>(scalar_traits<I>::mid(zr(i)));
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
      // A^-1 S and A^-1 (zr - xhn), each by verified solves with the exact point matrix An.
      matrix_t<I> AiS(n, n);
      for (int j = 0; j < n; ++j) AiS.col(j) = verified_solve(An, vector_t<I>(S.col(j)));
      const vector_t<I> dz = verified_solve(An, vector_t<I>(zr - xhn));
      f.A = An;
      f.r = appell::detail::product(AiS, f.r) + dz;
    }
    for (const detail::frame<I>& f : frames) {
      const vector_t<I> par = xhn + appell::detail::product(f.A, f.r);
      for (int i = 0; i < n; ++i) Xn(i) = appell::detail::intersect(Xn(i), par(i));
    }
    for (int i = 0; i < n; ++i) Xn(i) = appell::detail::intersect(Xn(i), Y(i));
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
    emit(step);
    ++st.steps;
    t = step.t1;
    X = Xn;
    xh = xhn;
    st.t_reached = approx_double(t);
    if (progress) progress(st.t_reached / horizon);
    if (detail::max_width(X) > max_width) {
      st.complete = false;
      st.reason = "width blow-up at t = " + std::to_string(st.t_reached) + " (a state's width exceeds " +
                  std::to_string(max_width) + ")";
      break;
    }
    if (last) break;
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return st;
}

}  // namespace appell::ode
