// appell/derivatives/jet.hpp -- truncated Taylor series over any scalar.
//
// A jet x(t) = x_0 + x_1 t + ... + x_n t^n carries the Taylor coefficients of a
// quantity along a motion.  The existing templated dynamics (the generic
// Gibbs-Appell path, Cotton's reactions, the scenes) run on jet<T> unchanged:
// evaluated on the jet of the state, a scene's accelerations come out as the
// jet of the accelerations, and the ODE's coefficients follow by
// x_{k+1} = f(x)_k / (k + 1) (ode/taylor.hpp).
//
// The order n is the same for every jet of one evaluation: a thread-local set
// by jet_order_scope.  A jet stores only its leading coefficients; the ones it
// does not store are exact zeros (a constant stores one coefficient), so
// constants cost what a scalar costs, and a product's length is the sum of
// its factors' lengths, capped at n + 1.  Every rule is the classical
// recurrence (Moore 1966; Griewank & Walther, ch. 13), one loop each; with
// interval coefficients each coefficient is enclosed as rigorously as the
// scalar operations it is made of.
//
// Comparisons are not defined on jets: library code uses the predicates of
// scalar/traits.hpp, which on a jet decide on its constant term (the value
// at t = 0).  Linear solves go order by order with the constant-term matrix
// factorized once (solve_spd below).
#pragma once

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <deque>
#include <new>
#include <utility>
#include <optional>
#include <stdexcept>
#include <vector>

#include "appell/derivatives/dual.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/scalar/eigen.hpp"
#include "appell/scalar/functions.hpp"
#include "appell/scalar/traits.hpp"

namespace appell {

namespace detail {
inline thread_local int jet_current_order = 0;
}

/// The order of the jets made in this thread (the highest power kept).
inline int jet_order() { return detail::jet_current_order; }

/// Sets the order of the jets for a scope.
class jet_order_scope {
 public:
  explicit jet_order_scope(int n) : saved_(detail::jet_current_order) {
    if (n < 0) throw std::invalid_argument("jet order must be nonnegative");
    detail::jet_current_order = n;
  }
  ~jet_order_scope() { detail::jet_current_order = saved_; }
  jet_order_scope(const jet_order_scope&) = delete;
  jet_order_scope& operator=(const jet_order_scope&) = delete;

 private:
  int saved_;
};

namespace detail {
/// a and b are the same number, bit for bit (a sign of zero included for the native floating
/// types; an interval's two bounds): an operation repeated on identical operands gives identical
/// results, which is all the memo below relies on.
template <class T>
bool identical(const T& a, const T& b) {
  if constexpr (std::is_floating_point_v<T>) {
    return a == b && std::signbit(a) == std::signbit(b);
  } else if constexpr (std::is_same_v<T, mpfi>) {
    const mpfi_srcptr x = a.backend().data(), y = b.backend().data();
    return mpfr_equal_p(&x->left, &y->left) && mpfr_equal_p(&x->right, &y->right) &&
           mpfr_signbit(&x->left) == mpfr_signbit(&y->left) && mpfr_signbit(&x->right) == mpfr_signbit(&y->right);
  } else if constexpr (std::is_same_v<T, arb>) {
    return ball_identical(a, b);
  } else if constexpr (scalar_traits<T>::is_interval) {
    return identical(scalar_traits<T>::lower(a), scalar_traits<T>::lower(b)) &&
           identical(scalar_traits<T>::upper(a), scalar_traits<T>::upper(b));
  } else if constexpr (std::is_same_v<T, dd>) {
    return a.x[0] == b.x[0] && a.x[1] == b.x[1] && std::signbit(a.x[0]) == std::signbit(b.x[0]);
  } else {
    using std::signbit;
    using boost::multiprecision::signbit;
    return a == b && signbit(a) == signbit(b);
  }
}

/// The memo of one Taylor-series computation (ode/taylor.hpp: the right-hand side evaluated on
/// jets of order 0, 1, ..., p - 1, each pass one order higher).  Coefficient j of a product,
/// quotient, sin, cos, sqrt, exp, log or order-by-order solve depends only on the operands'
/// coefficients 0..j, so a pass may take the previous pass's coefficients 0..n_prev of an
/// operation's result, provided that operation's operands agree, bit for bit, with the ones the
/// previous pass gave it on their coefficients 0..n_prev; only the new coefficients are computed:
/// O(p^2) per operation over the whole series instead of O(p^3).  The operations of a pass are
/// matched to the previous pass's by their rank; the operands are compared every time, so a pass
/// whose operations differ from the previous one's (a branch taken the other way) computes the
/// differing ones in full: the memo can cost time, never change a digit (tests/motion_scenes.cpp
/// compares every series with the memo against the series without it, bit for bit).
template <class T>
struct jet_memo {
  struct entry {
    int kind = -1;
    int order = -1;  ///< the jet order of the pass that stored it
    // Each operand's coefficients as used, each result's, one vector each: a pass that took
    // the first k from the previous one appends only the new ones (the vectors in use are the
    // first n_in and n_out; the others keep their capacity for a later operation of more).
    boost::container::small_vector<std::vector<T>, 2> in, out;
    std::size_t n_in = 0, n_out = 0;
    std::vector<T> extra;  ///< what an operation keeps besides (a solve: A_0^-1, enclosed)
  };
  std::deque<entry> entries;  // a deque: an entry stays where it is while later ones are added
  std::size_t next = 0;
  long reused = 0, computed = 0;  ///< operations that took coefficients from the memo, or not

  void begin_pass() { next = 0; }
  entry& take() {
    if (next == entries.size()) entries.emplace_back();
    return entries[next++];
  }
};
template <class T>
inline thread_local jet_memo<T>* active_jet_memo = nullptr;

/// Installs a memo for the jets over T made in this thread, for a scope.
template <class T>
class jet_memo_scope {
 public:
  explicit jet_memo_scope(jet_memo<T>* m) : saved_(active_jet_memo<T>) { active_jet_memo<T> = m; }
  ~jet_memo_scope() { active_jet_memo<T> = saved_; }
  jet_memo_scope(const jet_memo_scope&) = delete;
  jet_memo_scope& operator=(const jet_memo_scope&) = delete;

 private:
  jet_memo<T>* saved_;
};

/// Whether coefficients 0..n-1 at a and b are identical (identical() on each): compared as
/// bytes where equal bytes mean identical numbers and identical numbers equal bytes (double, and
/// intervals of doubles: two doubles each; equal bytes also take two NaNs of the same bits as
/// one, and the same operation on the same bits gives the same result, so the memo stays exact),
/// one by one otherwise (long double's padding, the multiprecision types' limbs on the heap).
template <class T>
bool identical_prefix(const T* a, const T* b, int n) {
  if (n <= 0) return true;
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, interval>) {
    return std::memcmp(a, b, static_cast<std::size_t>(n) * sizeof(T)) == 0;
  } else {
    for (int i = 0; i < n; ++i)
      if (!identical(a[i], b[i])) return false;
    return true;
  }
}

/// One operation's dealings with the memo.  `operand(data, len)` for each operand (its
/// coefficients as the operation uses them, len <= order + 1), then `reuse(i, ...)`: the stored
/// result i's coefficients that may be taken; `store` (or `store_all`) after computing.
template <class T>
class memo_op {
 public:
  memo_op(int kind, int order) : memo_(active_jet_memo<T>), order_(order) {
    if (!memo_) return;
    e_ = &memo_->take();
    keep_ = e_->kind == kind ? std::min(e_->order, order) + 1 : 0;
    e_->kind = kind;
  }
  explicit operator bool() const { return memo_ != nullptr; }
  /// Compares an operand's coefficients 0..keep-1 with the stored ones; store() records it
  /// (the operand must live until then).
  void operand(const T* data, int len) {
    if (!memo_) return;
    if (keep_ > 0) {
      if (operands_.size() >= e_->n_in) {
        keep_ = 0;
      } else {
        const std::vector<T>& stored = e_->in[operands_.size()];
        const int a = std::min(len, keep_), b = std::min(static_cast<int>(stored.size()), keep_);
        if (a == b && a > 0 && !identical_prefix(data + (a - 1), stored.data() + (a - 1), 1)) {
          // The last differs: the first keep_ - 1 may still be taken where the rest agree (a pass
          // after one that changed the last coefficient alone: ode::taylor_series_split's pass at
          // x_k = 0 before the whole one).  Compared last first, so that such a pass scans each
          // operand once.
          keep_ = a == keep_ && keep_ > 1 && identical_prefix(data, stored.data(), a - 1) ? keep_ - 1 : 0;
        } else if (a != b || !identical_prefix(data, stored.data(), a - 1)) {
          keep_ = 0;
        }
      }
    }
    operands_.emplace_back(data, len);
  }
  /// Coefficients 0..usable()-1 of every result may be taken from the memo (0: none).
  int usable() {
    if (!memo_) return 0;
    if (operands_.size() != e_->n_in) keep_ = 0;
    return keep_;
  }
  /// Copies into out[0..) the coefficients of stored result i that may be reused (at most
  /// len); returns their number (0: none).
  int reuse(std::size_t i, T* out, int len) {
    const int keep = usable();
    if (keep == 0 || i >= e_->n_out) return 0;
    const std::vector<T>& r = e_->out[i];
    const int n = std::min({keep, static_cast<int>(r.size()), len});
    std::copy(r.data(), r.data() + n, out);
    return n;
  }
  std::vector<T>& extra() { return e_->extra; }
  /// Records this pass's operands and results (call once, after computing).  Where the
  /// operands agreed on their first keep coefficients, those are kept and only the rest is
  /// copied; the results' first keep coefficients are the stored ones (taken by reuse, or
  /// computed again from identical operands: the same numbers).
  template <class... R>
  void store(const R&... results) {
    if (!memo_) return;
    const int keep = usable();
    if (keep > 0) ++memo_->reused;
    else ++memo_->computed;
    e_->order = order_;
    if (e_->in.size() < operands_.size()) e_->in.resize(operands_.size());
    for (std::size_t j = 0; j < operands_.size(); ++j) {
      const auto& [data, len] = operands_[j];
      assign_after(e_->in[j], keep, data, len);
    }
    e_->n_in = operands_.size();
    e_->n_out = 0;
    (append(results, keep), ...);
  }

  /// store() for a number of results known at run time: fill(append) calls append(c) on each.
  template <class F>
  void store_all(F&& fill) {
    if (!memo_) return;
    const int keep = usable();
    store();
    fill([this, keep](const auto& c) { append(c, keep); });
  }

 private:
  /// v := data[0..len), where v's first `keep` entries (as far as both reach) already are
  /// data's.
  static void assign_after(std::vector<T>& v, int keep, const T* data, int len) {
    const std::size_t same = static_cast<std::size_t>(std::max(0, std::min({keep, len, static_cast<int>(v.size())})));
    v.resize(same);
    v.insert(v.end(), data + same, data + len);
  }
  template <class C>
  void append(const C& c, int keep) {
    if (e_->out.size() <= e_->n_out) e_->out.resize(e_->n_out + 1);
    assign_after(e_->out[e_->n_out], keep, c.data(), static_cast<int>(c.size()));
    ++e_->n_out;
  }
  jet_memo<T>* memo_;
  typename jet_memo<T>::entry* e_ = nullptr;
  int order_;
  int keep_ = 0;
  boost::container::small_vector<std::pair<const T*, int>, 2> operands_;
};

enum memo_kind : int { memo_mul = 1, memo_div, memo_sin_cos, memo_sqrt, memo_exp, memo_log, memo_solve_spd, memo_solve };
}  // namespace detail

namespace detail {
/// Blocks of jet coefficients, per thread: free lists by size class (64 << c bytes), reused
/// without going back to malloc.  An evaluation on jets makes and drops thousands of short-lived
/// series (measured: malloc and free took 30% of an enclosure's time).  A block freed in another
/// thread joins that thread's lists; each thread's blocks go back to the system at its exit.
/// Jets that outlive their thread's pool (held in another thread_local object, such as a
/// scratch pool of linalg/scratch.hpp, destroyed after it) take and give back their blocks
/// through the system's allocator: jet_pool_gone says so, and is itself trivially destroyed.
inline thread_local bool jet_pool_gone = false;
class jet_block_pool {
 public:
  static constexpr int classes = 26;
  jet_block_pool() = default;
  jet_block_pool(const jet_block_pool&) = delete;
  jet_block_pool& operator=(const jet_block_pool&) = delete;
  ~jet_block_pool() {
    for (auto& list : free_)
      for (void* p : list) ::operator delete(p);
    jet_pool_gone = true;
  }
  void* get(std::size_t bytes) {
    const int c = size_class(bytes);
    std::vector<void*>& list = free_[c];
    if (list.empty()) return ::operator new(std::size_t(64) << c);
    void* p = list.back();
    list.pop_back();
    return p;
  }
  void put(void* p, std::size_t bytes) { free_[size_class(bytes)].push_back(p); }

 private:
  static int size_class(std::size_t bytes) {
    int c = 0;
    while ((std::size_t(64) << c) < bytes) ++c;
    if (c >= classes) throw std::bad_alloc();
    return c;
  }
  std::vector<void*> free_[classes];
};
inline jet_block_pool& jet_pool() {
  thread_local jet_block_pool pool;
  return pool;
}
template <class T>
struct jet_allocator {
  using value_type = T;
  jet_allocator() = default;
  template <class U>
  jet_allocator(const jet_allocator<U>&) {}  // NOLINT
  T* allocate(std::size_t n) {
    if (jet_pool_gone) return static_cast<T*>(::operator new(n * sizeof(T)));
    return static_cast<T*>(jet_pool().get(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) {
    if (jet_pool_gone) return ::operator delete(p);  // a pool block or one taken since: both from operator new
    jet_pool().put(p, n * sizeof(T));
  }
  friend bool operator==(const jet_allocator&, const jet_allocator&) { return true; }
  friend bool operator!=(const jet_allocator&, const jet_allocator&) { return false; }
};
}  // namespace detail

namespace detail {
/// s += x y and s -= x y in a recurrence's inner loop, the same numbers bit for bit as those
/// expressions.  For appell's MPFR and MPFI numbers (Boost numbers without expression
/// templates) the expression makes a temporary for x y, under Boost's precision guard, and
/// drops it; here the product goes into one scratch value kept for the whole recurrence,
/// through the backend's own eval_multiply and eval_add/eval_subtract (what the expression
/// calls), whenever the guard would change nothing (s, x and y at the default precision).
/// Otherwise, and for every other scalar, the expression itself.
template <class T>
struct product_sum {
  void add(T& s, const T& x, const T& y) { s += x * y; }
  void subtract(T& s, const T& x, const T& y) { s -= x * y; }
};
/// interval<double> inside an upward-rounding scope (interval.hpp: every jet of enclose): x y as
/// the pair (-lower, upper) of its bounds rounded up (product_pair, as `multiply` forms it) added
/// to s's pair lane by lane: the same bounds, bit for bit, as s += x y, whose product and sum each
/// check their operands and form an interval (the jets' products were 29% of the WAM's
/// enclosure, perf).  Outside a scope, or where a bound is not finite, the expression itself.
template <>
struct product_sum<interval> {
  void add(interval& s, const interval& x, const interval& y) {
    if (!fast(s, x, y)) [[unlikely]] {
      s += x * y;
      return;
    }
    s = from_pair(_mm_add_pd(pair_of(s), product_pair(x, y)));
  }
  void subtract(interval& s, const interval& x, const interval& y) {
    if (!fast(s, x, y)) [[unlikely]] {
      s -= x * y;
      return;
    }
    const __m128d q = product_pair(x, y);
    s = from_pair(_mm_add_pd(pair_of(s), _mm_shuffle_pd(q, q, 1)));  // + (-upper, lower) of x y
  }

 private:
  static bool fast(const interval& s, const interval& x, const interval& y) {
    return ::appell::detail::upward_known && ordinary_pair(x, y) && s.lower() <= s.upper();
  }
  static __m128d pair_of(const interval& s) { return opaque_pd(_mm_set_pd(s.upper(), -s.lower())); }
};
/// arb: Arb's addmul and submul (one call, one rounding), into s at its own precision.
template <>
struct product_sum<arb> {
  void add(arb& s, const arb& x, const arb& y) { mp::arb_add_product(s.backend(), x.backend(), y.backend()); }
  void subtract(arb& s, const arb& x, const arb& y) { mp::arb_subtract_product(s.backend(), x.backend(), y.backend()); }
};
template <class Backend>
  requires(std::is_same_v<Backend, mp::mpfr_backend> || std::is_same_v<Backend, mp::mpfi_backend>)
struct product_sum<boost::multiprecision::number<Backend, boost::multiprecision::et_off>> {
  using number = boost::multiprecision::number<Backend, boost::multiprecision::et_off>;
  number t;  ///< at the default precision when made; checked before each use
  bool in_place(const number& s, const number& x, const number& y) const {
    const auto p = static_cast<mpfr_prec_t>(Backend::default_bits());
    return s.backend().prec() == p && x.backend().prec() == p && y.backend().prec() == p && t.backend().prec() == p;
  }
  void add(number& s, const number& x, const number& y) {
    if (!in_place(s, x, y)) {
      s += x * y;
      return;
    }
    eval_multiply(t.backend(), x.backend(), y.backend());
    eval_add(s.backend(), t.backend());
  }
  void subtract(number& s, const number& x, const number& y) {
    if (!in_place(s, x, y)) {
      s -= x * y;
      return;
    }
    eval_multiply(t.backend(), x.backend(), y.backend());
    eval_subtract(s.backend(), t.backend());
  }
};
}  // namespace detail

template <class T>
struct jet {
  /// c[k] = coefficient of t^k; those past c.size() are exact zeros.  A constant keeps its one
  /// coefficient inline (no allocation): most jets of a scene's evaluation are constants.
  ///
  /// Coefficients of a fixed-size scalar (double, long double, interval, dd, float128) are kept
  /// inline up to order 7, longer ones in blocks of the thread's pool (detail::jet_block_pool);
  /// mpfr and mpfi keep one inline (a value of theirs is 64 bytes or more).
  static constexpr std::size_t inline_coefficients = scalar_traits<T>::runtime_precision ? 1 : 8;
  boost::container::small_vector<T, inline_coefficients, detail::jet_allocator<T>> c;

  // One coefficient by emplace_back: small_vector's (count, value) constructor goes through its
  // generic resize, which was 14% of an enclosure of Euler's body (perf; most jets of an
  // evaluation are constants: every zero of a body_state<multi_dual<slope<jet>>>).
  jet() { c.emplace_back(T(0)); }
  jet(const T& v) { c.emplace_back(v); }  // NOLINT: constants convert implicitly
  jet(T&& v) { c.emplace_back(std::move(v)); }  // NOLINT
  template <class N>
    requires std::is_arithmetic_v<N>
  jet(N n) {  // NOLINT
    c.emplace_back(T(n));
  }
  explicit jet(const std::vector<T>& coefficients) : c(coefficients.begin(), coefficients.end()) {
    if (c.empty()) c.assign(1, T(0));
    truncate();
  }

  /// Coefficient k (an exact zero past the stored ones).
  T operator[](int k) const { return k < size() ? c[static_cast<std::size_t>(k)] : T(0); }
  int size() const { return static_cast<int>(c.size()); }
  const T& value() const { return c[0]; }
  void truncate() {
    const auto cap = static_cast<std::size_t>(jet_order() + 1);
    if (c.size() > cap) c.resize(cap);
  }

  jet& operator+=(const jet& o) {
    if (o.c.size() > c.size()) c.resize(std::min(o.c.size(), static_cast<std::size_t>(jet_order() + 1)), T(0));
    for (std::size_t k = 0; k < c.size() && k < o.c.size(); ++k) c[k] += o.c[k];
    return *this;
  }
  jet& operator-=(const jet& o) {
    if (o.c.size() > c.size()) c.resize(std::min(o.c.size(), static_cast<std::size_t>(jet_order() + 1)), T(0));
    for (std::size_t k = 0; k < c.size() && k < o.c.size(); ++k) c[k] -= o.c[k];
    return *this;
  }
  jet& operator*=(const jet& o) { return *this = *this * o; }
  jet& operator/=(const jet& o) { return *this = *this / o; }

  friend jet operator+(const jet& a) { return a; }
  friend jet operator-(const jet& a) {
    jet r = a;
    for (T& x : r.c) x = -x;
    return r;
  }
  friend jet operator+(const jet& a, const jet& b) {
    if (b.c.size() > a.c.size()) return b + a;
    jet r(a);
    for (std::size_t k = 0; k < b.c.size(); ++k) r.c[k] += b.c[k];
    return r;
  }
  friend jet operator-(const jet& a, const jet& b) {
    if (b.c.size() > a.c.size()) {
      jet r(-b);
      for (std::size_t k = 0; k < a.c.size(); ++k) r.c[k] += a.c[k];
      return r;
    }
    jet r(a);
    for (std::size_t k = 0; k < b.c.size(); ++k) r.c[k] -= b.c[k];
    return r;
  }
  friend jet operator*(const jet& a, const jet& b) {
    const int n = jet_order();
    const int la = std::min(a.size(), n + 1), lb = std::min(b.size(), n + 1);
    if (lb == 1) {
      jet r;
      r.c.resize(static_cast<std::size_t>(la));
      for (int k = 0; k < la; ++k) r.c[static_cast<std::size_t>(k)] = a.c[static_cast<std::size_t>(k)] * b.c[0];
      return r;
    }
    if (la == 1) return b * a;
    const int lr = std::min(la + lb - 1, n + 1);
    jet r;
    r.c.assign(static_cast<std::size_t>(lr), T(0));
    detail::memo_op<T> memo(detail::memo_mul, n);
    memo.operand(a.c.data(), la);
    memo.operand(b.c.data(), lb);
    const int first = memo.reuse(0, r.c.data(), lr);
    detail::product_sum<T> sum;
    for (int k = first; k < lr; ++k) {
      T s = T(0);
      const int lo = std::max(0, k - lb + 1), hi = std::min(k, la - 1);
      for (int i = lo; i <= hi; ++i) sum.add(s, a.c[static_cast<std::size_t>(i)], b.c[static_cast<std::size_t>(k - i)]);
      r.c[static_cast<std::size_t>(k)] = std::move(s);
    }
    memo.store(r.c);
    return r;
  }
  /// q = a / b: q_k = (a_k - sum_{j=1..k} b_j q_{k-j}) / b_0.
  friend jet operator/(const jet& a, const jet& b) {
    const int n = jet_order();
    const int lb = std::min(b.size(), n + 1);
    if (lb == 1) {
      jet r = a;
      r.truncate();
      for (T& x : r.c) x /= b.c[0];
      return r;
    }
    jet r;
    r.c.assign(static_cast<std::size_t>(n + 1), T(0));
    detail::memo_op<T> memo(detail::memo_div, n);
    memo.operand(a.c.data(), std::min(a.size(), n + 1));
    memo.operand(b.c.data(), lb);
    const int first = memo.reuse(0, r.c.data(), n + 1);
    detail::product_sum<T> sum;
    for (int k = first; k <= n; ++k) {
      T s = a[k];
      for (int j = 1; j <= std::min(k, lb - 1); ++j)
        sum.subtract(s, b.c[static_cast<std::size_t>(j)], r.c[static_cast<std::size_t>(k - j)]);
      r.c[static_cast<std::size_t>(k)] = s / b.c[0];
    }
    memo.store(r.c);
    return r;
  }
};


/// s = sin x, c = cos x together: k s_k = sum_j j x_j c_{k-j}, k c_k = -sum_j j x_j s_{k-j}.
template <class T>
void sin_cos(const jet<T>& x, jet<T>& s, jet<T>& c) {
  const int n = x.size() == 1 ? 0 : jet_order();
  s.c.assign(static_cast<std::size_t>(n + 1), T(0));
  c.c.assign(static_cast<std::size_t>(n + 1), T(0));
  const int lx = std::min(x.size(), n + 1);
  detail::memo_op<T> memo(detail::memo_sin_cos, n);
  memo.operand(x.c.data(), lx);
  int first = memo.reuse(0, s.c.data(), n + 1);
  first = std::min(first, memo.reuse(1, c.c.data(), n + 1));
  if (first == 0) {
    T s0, c0;
    sin_cos(x.c[0], s0, c0);
    s.c[0] = s0;
    c.c[0] = c0;
    first = 1;
  }
  detail::product_sum<T> sum;
  for (int k = first; k <= n; ++k) {
    T a = T(0), b = T(0);
    for (int j = 1; j <= std::min(k, lx - 1); ++j) {
      const T jx = T(j) * x.c[static_cast<std::size_t>(j)];
      sum.add(a, jx, c.c[static_cast<std::size_t>(k - j)]);
      sum.add(b, jx, s.c[static_cast<std::size_t>(k - j)]);
    }
    s.c[static_cast<std::size_t>(k)] = a / T(k);
    c.c[static_cast<std::size_t>(k)] = -b / T(k);
  }
  memo.store(s.c, c.c);
}
template <class T> jet<T> sin(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return s; }
template <class T> jet<T> cos(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return c; }
template <class T> jet<T> tan(const jet<T>& x) { jet<T> s, c; sin_cos(x, s, c); return s / c; }
namespace detail {
/// The start of a one-operand recurrence under the memo: records x, takes r's coefficients
/// from the previous pass where it may, else r_0 = f(x_0).  Returns the first coefficient to compute.
template <class T, class F>
int unary_start(memo_op<T>& memo, const jet<T>& x, jet<T>& r, int n, F&& f) {
  memo.operand(x.c.data(), std::min(x.size(), n + 1));
  const int first = memo.reuse(0, r.c.data(), n + 1);
  if (first > 0) return first;
  r.c[0] = f(x.c[0]);
  return 1;
}
}  // namespace detail

/// r = sqrt(x): r_0 = sqrt(x_0), r_k = (x_k - sum_{j=1..k-1} r_j r_{k-j}) / (2 r_0).
template <class T> jet<T> sqrt(const jet<T>& x) {
  using std::sqrt;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  detail::memo_op<T> memo(detail::memo_sqrt, n);
  const int first = detail::unary_start(memo, x, r, n, [](const T& v) { return sqrt(v); });
  const T two_r0 = T(2) * r.c[0];
  detail::product_sum<T> sum;
  for (int k = first; k <= n; ++k) {
    T s = x[k];
    for (int j = 1; j < k; ++j) sum.subtract(s, r.c[static_cast<std::size_t>(j)], r.c[static_cast<std::size_t>(k - j)]);
    r.c[static_cast<std::size_t>(k)] = s / two_r0;
  }
  memo.store(r.c);
  return r;
}
/// e = exp(x): k e_k = sum_j j x_j e_{k-j}.
template <class T> jet<T> exp(const jet<T>& x) {
  using std::exp;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> e;
  e.c.assign(static_cast<std::size_t>(n + 1), T(0));
  detail::memo_op<T> memo(detail::memo_exp, n);
  const int first = detail::unary_start(memo, x, e, n, [](const T& v) { return exp(v); });
  for (int k = first; k <= n; ++k) {
    T s = T(0);
    for (int j = 1; j <= std::min(k, x.size() - 1); ++j) s += T(j) * x.c[static_cast<std::size_t>(j)] * e.c[static_cast<std::size_t>(k - j)];
    e.c[static_cast<std::size_t>(k)] = s / T(k);
  }
  memo.store(e.c);
  return e;
}
/// l = log(x): x_0 k l_k = k x_k - sum_{j=1..k-1} j l_j x_{k-j}.
template <class T> jet<T> log(const jet<T>& x) {
  using std::log;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> l;
  l.c.assign(static_cast<std::size_t>(n + 1), T(0));
  detail::memo_op<T> memo(detail::memo_log, n);
  const int first = detail::unary_start(memo, x, l, n, [](const T& v) { return log(v); });
  for (int k = first; k <= n; ++k) {
    T s = T(k) * x[k];
    for (int j = 1; j < k; ++j) s -= T(j) * l.c[static_cast<std::size_t>(j)] * x[k - j];
    l.c[static_cast<std::size_t>(k)] = s / (T(k) * x.c[0]);
  }
  memo.store(l.c);
  return l;
}
/// atan(x) = integral of x' / (1 + x^2).
template <class T> jet<T> atan(const jet<T>& x) {
  using std::atan;
  const int n = std::min(jet_order(), x.size() == 1 ? 0 : jet_order());
  jet<T> r;
  r.c.assign(static_cast<std::size_t>(n + 1), T(0));
  r.c[0] = atan(x.c[0]);
  if (n == 0) return r;
  jet<T> dx;  // x'
  dx.c.assign(static_cast<std::size_t>(n), T(0));
  for (int k = 1; k <= n; ++k) dx.c[static_cast<std::size_t>(k - 1)] = T(k) * x[k];
  const jet<T> q = dx / (jet<T>(T(1)) + x * x);
  for (int k = 1; k <= n; ++k) r.c[static_cast<std::size_t>(k)] = q[k - 1] / T(k);
  return r;
}
template <class T> jet<T> pown(const jet<T>& x, int n) {
  if (n < 0) return jet<T>(T(1)) / pown(x, -n);
  jet<T> r(T(1)), b = x;
  while (n > 0) {  // x^n by squaring: exact powers of the series
    if (n & 1) r = r * b;
    n >>= 1;
    if (n > 0) b = b * b;
  }
  return r;
}
template <class T> jet<T> sqr(const jet<T>& x) { return x * x; }

template <class T>
  requires Scalar<T>
struct scalar_traits<jet<T>> {
  static constexpr const char* name = "jet";
  static constexpr bool is_interval = false;  // a jet is not a set: predicates decide on its constant term
  static constexpr bool is_rigorous = scalar_traits<T>::is_rigorous;
  static constexpr bool runtime_precision = scalar_traits<T>::runtime_precision;
  static constexpr bool needs_upward_rounding = scalar_traits<T>::needs_upward_rounding;
  using bound_type = bound_t<T>;
  static unsigned precision_bits() { return scalar_traits<T>::precision_bits(); }
  static bound_type lower(const jet<T>& x) { return scalar_traits<T>::lower(x.c[0]); }
  static bound_type upper(const jet<T>& x) { return scalar_traits<T>::upper(x.c[0]); }
  static bound_type mid(const jet<T>& x) { return scalar_traits<T>::mid(x.c[0]); }
  static bound_type width(const jet<T>& x) { return scalar_traits<T>::width(x.c[0]); }
};

template <class T> bool exactly_zero(const jet<T>& x) {
  for (const T& v : x.c)
    if (!exactly_zero(v)) return false;
  return true;
}
template <class T> bool exactly_one(const jet<T>& x) {
  if (!exactly_one(x.c[0])) return false;
  for (std::size_t k = 1; k < x.c.size(); ++k)
    if (!exactly_zero(x.c[k])) return false;
  return true;
}
template <class T> bool is_finite(const jet<T>& x) {
  for (const T& v : x.c)
    if (!is_finite(v)) return false;
  return true;
}

/// Coefficient k of every entry of a matrix of jets.
template <class T, int R, int C>
Eigen::Matrix<T, R, C> coefficient(const Eigen::Matrix<jet<T>, R, C>& m, int k) {
  Eigen::Matrix<T, R, C> r(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) r(i, j) = m(i, j)[k];
  return r;
}

namespace detail {
/// A x = b on jets, order by order: A_0 x_k = b_k - sum_{j=1..k} A_j x_{k-j},
/// A_0 factorized once (point types: Cholesky when spd, else LU with partial
/// pivoting); for interval coefficients the value is a verified solve with A_0
/// (linalg/solve.hpp) and the higher orders are products with a verified
/// enclosure of A_0^-1 (its columns solved once), so every coefficient encloses
/// the exact one.
template <class T>
vector_t<jet<T>> jet_solve(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b, bool spd) {
  check_square(A, b.rows());
  const Eigen::Index m = A.rows();
  const int n = jet_order();
  int la = 1;
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) la = std::max(la, std::min(A(i, j).size(), n + 1));
  const matrix_t<T> A0 = coefficient(A, 0);
  std::vector<matrix_t<T>> Aj(static_cast<std::size_t>(la));
  for (int j = 1; j < la; ++j) Aj[static_cast<std::size_t>(j)] = coefficient(A, j);
  vector_t<jet<T>> x(m);
  for (Eigen::Index i = 0; i < m; ++i) x(i).c.assign(static_cast<std::size_t>(n + 1), T(0));
  // The memo (a Taylor series in progress): x's coefficients 0..first-1 from the previous pass
  // when A's and b's agree with its operands; A_0^-1 (interval) with them.
  memo_op<T> memo(spd ? memo_solve_spd : memo_solve, n);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) memo.operand(A(i, j).c.data(), std::min(A(i, j).size(), n + 1));
  for (Eigen::Index i = 0; i < m; ++i) memo.operand(b(i).c.data(), std::min(b(i).size(), n + 1));
  int first = n + 1;
  for (Eigen::Index i = 0; i < m; ++i) first = std::min(first, memo.reuse(static_cast<std::size_t>(i), x(i).c.data(), n + 1));
  std::optional<Eigen::LLT<matrix_t<T>>> llt;
  std::optional<Eigen::PartialPivLU<matrix_t<T>>> lu;
  matrix_t<T> inverse;  // interval: the columns enclose A^-1 e_j for every A in [A_0]
  if constexpr (!scalar_traits<T>::is_interval) {
    if (spd) {
      llt.emplace(A0);
      if (llt->info() != Eigen::Success) throw certification_error("Cholesky: the matrix is not positive definite");
    } else {
      lu.emplace(A0);
      using std::abs;
      for (Eigen::Index i = 0; i < m; ++i)
        if (!(abs(lu->matrixLU()(i, i)) > 0)) throw certification_error("LU: the matrix is singular");
    }
  } else if (n > 0) {
    inverse.resize(m, m);
    std::vector<T>* kept = memo ? &memo.extra() : nullptr;
    if (kept && first > 0 && kept->size() == static_cast<std::size_t>(m * m)) {  // the same A_0: the same enclosure
      for (Eigen::Index i = 0; i < m; ++i)
        for (Eigen::Index j = 0; j < m; ++j) inverse(i, j) = (*kept)[static_cast<std::size_t>(i * m + j)];
    } else {
      for (Eigen::Index j = 0; j < m; ++j) {
        vector_t<T> e = vector_t<T>::Zero(m);
        e(j) = T(1);
        inverse.col(j) = verified_solve(A0, e);
      }
      if (kept) {
        kept->resize(static_cast<std::size_t>(m * m));
        for (Eigen::Index i = 0; i < m; ++i)
          for (Eigen::Index j = 0; j < m; ++j) (*kept)[static_cast<std::size_t>(i * m + j)] = inverse(i, j);
      }
    }
  }
  for (int k = first; k <= n; ++k) {
    vector_t<T> r(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      T s = b(i)[k];
      for (int j = 1; j <= std::min(k, la - 1); ++j)
        for (Eigen::Index l = 0; l < m; ++l) {
          const T& a = Aj[static_cast<std::size_t>(j)](i, l);
          if (!exactly_zero(a)) s -= a * x(l).c[static_cast<std::size_t>(k - j)];
        }
      r(i) = s;
    }
    vector_t<T> xk;
    if constexpr (scalar_traits<T>::is_interval) {
      // x_k = A_0^-1 r_k with the true A_0 and the true r_k: sum_j (r_k)_j A_0^-1 e_j lies in
      // inverse * r_k.  The value (k = 0) keeps the tighter direct verified solve.
      xk = (k == 0 || n == 0) ? verified_solve(A0, r) : vector_t<T>(detail::product(inverse, r));
    } else {
      xk = spd ? vector_t<T>(llt->solve(r)) : vector_t<T>(lu->solve(r));
    }
    for (Eigen::Index i = 0; i < m; ++i) x(i).c[static_cast<std::size_t>(k)] = xk(i);
  }
  if (memo) {
    memo.store_all([&](auto&& append) {
      for (Eigen::Index i = 0; i < m; ++i) append(x(i).c);
    });
  }
  return x;
}
}  // namespace detail

/// A x = b on jets, A symmetric positive definite (detail::jet_solve).
template <class T>
vector_t<jet<T>> solve_spd(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b) {
  return detail::jet_solve(A, b, true);
}
/// A x = b on jets, A general (detail::jet_solve): Lagrange's saddle-point systems.
template <class T>
vector_t<jet<T>> solve(const matrix_t<jet<T>>& A, const vector_t<jet<T>>& b) {
  return detail::jet_solve(A, b, false);
}

}  // namespace appell
