// appell/expr/expression.hpp -- the scene expression language (SCENES.md):
// numbers, pi, named variables (one for a cone's f(theta), many for a system
// file's), + - * / ^, parentheses, sin cos tan exp log sqrt, and a system file's
// tables: functions of time given by values at breakpoints, joined by straight
// lines (a torque a controller logged), called by name: push(t).
//
// An expression is parsed once into a tree; derivative() differentiates it
// symbolically (f' and f'' of the cone psi = f(theta) come from here, not from
// hand-written formulas).  eval() runs on any scalar and on dual numbers of
// it; decimal constants are enclosed exactly like every other input (they are
// converted by from_decimal<T>, never through a double).  Division by zero, log
// or sqrt outside the domain, sin/cos/tan beyond 2^40 rad, at the evaluation point are errors naming the
// expression: input_error when they certainly happen, certification_error when
// an interval merely cannot exclude them.
#pragma once

#include <map>
#include <memory>
#include <tuple>
#include <string>
#include <vector>

#include "appell/derivatives/dual.hpp"
#include "appell/errors.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "appell/expr/time_segment.hpp"

namespace appell {

/// A function of time given by a table (SCENES.md, "tables"): its values at strictly increasing
/// times, joined by straight lines, defined on [times.front(), times.back()].  The breakpoints
/// are doubles (the times as written, rounded to the nearest double: a controller logs doubles);
/// the values are decimals, enclosed exactly in every scalar.  It is smooth between breakpoints
/// only: a rigorous step must not cross one (enclose and simulate end their steps there, and
/// say which piece the step lies in through a time_segment_scope).
struct piecewise_linear {
  std::string name;
  std::vector<double> times;
  std::vector<std::string> values;
};
using table_list = std::vector<std::shared_ptr<const piecewise_linear>>;

/// The tables an expression may call, and where: a table's argument is the time alone
/// (variable number `time`), and where `refusal` is not empty tables are refused with it (a
/// position or a constraint given by a table would have no derivative at its breakpoints).
struct expression_tables {
  const table_list* tables = nullptr;
  int time = -1;
  std::string refusal;
};

/// The piece k (its line from times[k] to times[k+1]) of `table` that holds the segment;
/// input_error (naming `where`) when the segment leaves the table's times.
int table_piece_of_segment(const piecewise_linear& table, const time_segment& s, const std::string& where);

/// The time `at` as text, for the messages below.
namespace detail {
[[noreturn]] void table_outside(const piecewise_linear& table, const std::string& at, bool certainly,
                                const std::string& where);
[[noreturn]] void table_across(const piecewise_linear& table, double breakpoint, const std::string& at,
                               const std::string& where);
}  // namespace detail

class expression {
 public:
  enum class op { number, pi, variable, add, sub, mul, div, pow, neg, sin, cos, tan, exp, log, sqrt,
                  table, table_rate };
  /// What parse and derivative accept (bounded time and stack on any input):
  /// longer text, deeper nesting, or an expression or derivative whose tree
  /// (shared subexpressions counted each time they are used) is larger or
  /// deeper is bad input.
  struct limits {
    static constexpr std::size_t characters = 10000;
    static constexpr std::size_t nesting = 100;      ///< parentheses, unary signs, ^
    static constexpr std::size_t depth = 1000;       ///< of the tree
    static constexpr std::size_t size = 20000;       ///< nodes of the unfolded tree
    /// unfolded nodes x bits of the scalar it is compiled for (compiled_expression):
    /// 20,000 nodes up to 1000 bits, 200 at 100,000 bits
    static constexpr std::size_t operation_bits = 20000000;
  };
  /// Nodes of the unfolded tree (shared subexpressions counted each time used).
  std::size_t operations() const { return operations_; }
  struct node {
    op kind;
    int a = -1, b = -1;  ///< operands (indices into nodes)
    std::string number;  ///< the decimal text of a number
    int var = 0;         ///< a variable's index in the list it was parsed with
  };

  /// Parses `text` in the variable `variable`; throws input_error("where: ...").
  static expression parse(const std::string& text, const std::string& variable, const std::string& where);
  /// Parses `text` in the named variables (a name's index is its place in the list).
  static expression parse(const std::string& text, const std::vector<std::string>& variables,
                          const std::string& where);
  /// The same, with the tables a call may name (name(t)).
  static expression parse(const std::string& text, const std::vector<std::string>& variables,
                          const std::string& where, const expression_tables& tables);
  /// d/d(variable), symbolically (the only variable, or variable number `variable`).
  expression derivative(int variable = 0) const;
  /// a - b, symbolically, with the terms that a and b share cancelled: both are
  /// read as signed sums of terms (through +, - and unary -), a term of b equal
  /// as a tree to a term of a with the same sign cancels it, and terms that are
  /// 0 as written (a number 0, a product with one) are left out.  The value is
  /// a - b exactly; an interval evaluation no longer carries what the two share
  /// (a body's centre and a point of it both written from the frame's origin
  /// (x + ...): their difference over a box is as wide as x twice, the
  /// cancelled one as wide as the offset alone).  Both must be in the same
  /// variables.
  static expression difference(const expression& a, const expression& b, const std::string& where);
  /// Whether variable number `variable` occurs in the expression (its tree as
  /// written: x - x depends on x).
  bool depends_on(int variable) const;
  /// Whether the expression is the number 0 as written (a derivative that vanishes
  /// structurally is written so).
  bool is_zero() const;
  /// Whether the expression is 0, as written, wherever the variables `zero` are 0
  /// (a proof from the tree, never from values: false when unsure).  Used to tell
  /// that a constraint or a kinematic equation is homogeneous in the speeds.
  bool vanishes_when_zero(const std::vector<int>& zero) const;
  std::string to_string() const;
  const std::string& where() const { return where_; }
  const std::vector<std::string>& variables() const { return variables_; }
  /// Whether a table is called (the expression is then smooth between breakpoints only).
  bool calls_table() const;

  /// The value at x (S a scalar or a dual of one); decimal constants and pi
  /// are converted to the scalar at each call.  For repeated evaluation use a
  /// compiled_expression<T> (below), which converts them once.
  template <class S>
  S eval(const S& x) const {
    return eval_node<S>(root_, &x, nullptr);
  }
  /// The value at the variables `x[0], x[1], ...` (in the order parsed).
  template <class S>
  S eval_at(const S* x) const {
    return eval_node<S>(root_, x, nullptr);
  }
  /// The constants converted to T, one slot per node (the value for a number or
  /// pi node, 0 for the others): what compiled_expression<T> holds.
  template <class T>
  std::vector<T> constants() const {
    std::vector<T> c(nodes_.size(), T(0));
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (nodes_[i].kind == op::number) c[i] = from_decimal<T>(nodes_[i].number);
      if (nodes_[i].kind == op::pi) c[i] = constant_pi<T>();
    }
    return c;
  }
  /// The value at x with the constants taken from `constants` (as returned by
  /// constants<base_scalar_t<S>>()) instead of converted again.
  template <class S>
  S eval_bound(const S& x, const std::vector<base_scalar_t<S>>& constants) const {
    return eval_node<S>(root_, &x, &constants);
  }
  template <class S>
  S eval_bound_at(const S* x, const std::vector<base_scalar_t<S>>& constants) const {
    return eval_node<S>(root_, x, &constants);
  }

 private:
  int add_node(op k, int a = -1, int b = -1, std::string number = {}, int var = 0);
  int derive(int i, int variable, expression& out, std::vector<int>& copied) const;
  int copy_into(int i, expression& out, std::vector<int>& copied) const;
  std::string node_string(int i) const;
  bool is_integer(int i, long& value) const;
  void check_limits() const;

  template <class S>
  S eval_node(int i, const S* x, const std::vector<base_scalar_t<S>>* constants) const;

 public:
  /// One operation on evaluated operands, with its domain checks (errors name
  /// `where`); for pow, `integer` is the exponent when it is an integer literal
  /// (b is then unused).  eval and expression_tape both go through it.
  template <class S>
  static S apply(op kind, const S& a, const S& b, const long* integer, const std::string& where);

 private:
  template <Scalar T>
  friend class expression_tape;

  std::vector<node> nodes_;
  int root_ = -1;
  std::string where_;
  std::vector<std::string> variables_;
  table_list tables_;  ///< the tables a table node names (its var: the index here)
  mutable std::size_t operations_ = 0;  ///< set by check_limits
};

/// A table's value (or its rate: the piece's slope) at x, S a scalar or a dual or jet of one:
/// on the piece an integrator's step lies in (time_segment_scope), otherwise on the piece that
/// holds x (right-continuous at a breakpoint: a forward step starts there).  An x that may lie
/// on both sides of a breakpoint is refused (certification_error): no derivative there.
/// `converted`: the values in T (null: converted here).
template <class S>
S table_value(const piecewise_linear& table, const base_scalar_t<S>* converted, const S& x, bool rate,
              const std::string& where) {
  using T = base_scalar_t<S>;
  const int n = static_cast<int>(table.times.size());
  int k = 0;
  if (detail::active_time_segment) {
    k = table_piece_of_segment(table, *detail::active_time_segment, where);
  } else {
    const T& d = detail::value_of(x);
    auto at_or_after = [&](int i) { return certainly_nonnegative(T(d - T(table.times[static_cast<std::size_t>(i)]))); };
    auto at_or_before = [&](int i) { return certainly_nonpositive(T(d - T(table.times[static_cast<std::size_t>(i)]))); };
    if (!at_or_after(0))
      detail::table_outside(table, to_string(d), certainly_negative(T(d - T(table.times.front()))), where);
    if (!at_or_before(n - 1))
      detail::table_outside(table, to_string(d), certainly_positive(T(d - T(table.times.back()))), where);
    int lo = 0, hi = n - 2;  // the last piece whose start d certainly reaches
    while (lo < hi) {
      const int mid = (lo + hi + 1) / 2;
      if (at_or_after(mid)) lo = mid;
      else hi = mid - 1;
    }
    if (!at_or_before(lo + 1)) detail::table_across(table, table.times[static_cast<std::size_t>(lo + 1)], to_string(d), where);
    k = lo;
  }
  const auto kk = static_cast<std::size_t>(k);
  const T v0 = converted ? converted[kk] : from_decimal<T>(table.values[kk]);
  const T v1 = converted ? converted[kk + 1] : from_decimal<T>(table.values[kk + 1]);
  const T t0(table.times[kk]), t1(table.times[kk + 1]);
  const T slope = (v1 - v0) / (t1 - t0);
  if (rate) return detail::from_base<S>(slope);
  return detail::from_base<S>(v0) + (x - detail::from_base<S>(t0)) * detail::from_base<S>(slope);
}

namespace detail {
template <class T>
std::string describe(const T& x) { return to_string(x); }
}  // namespace detail

template <class S>
S expression::apply(op kind, const S& a, const S& b, const long* integer, const std::string& where) {
  using T = base_scalar_t<S>;
  using std::sin, std::cos, std::tan, std::exp, std::log, std::sqrt;
  // `what` a C string, its message built only when it is thrown: an evaluation makes no string
  // per division, root or angle (tests/allocations.cpp counts the heap's calls)
  auto domain = [&](bool certainly_bad, bool possibly_bad, const char* what, const T& at, const char* prefix = "") {
    if (certainly_bad)
      throw input_error(where + ": " + prefix + what + " at the state (" + detail::describe(at) + ")");
    if (possibly_bad)
      throw certification_error(where + ": cannot exclude " + prefix + what + " at the state (" +
                                detail::describe(at) + ")");
  };
  // sin, cos, tan of |y| > 2^40 rad: no physical angle, and an argument
  // reduction that costs time in the exponent (MPFR, MPFI) or loses every digit (QD)
  auto angle = [&](const S& y, const char* fn) {
    const T& d = detail::value_of(y);
    const T limit(1099511627776.0);  // 2^40, exact in every scalar
    domain(certainly_positive(T(d - limit)) || certainly_negative(T(d + limit)),
           !(certainly_nonpositive(T(d - limit)) && certainly_nonnegative(T(d + limit))),
           " of an angle beyond 2^40 rad", d, fn);
  };
  switch (kind) {
    case op::add: return a + b;
    case op::sub: return a - b;
    case op::mul: return a * b;
    case op::neg: return -a;
    case op::div: {
      const T& d = detail::value_of(b);
      domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "division by zero", d);
      return a / b;
    }
    case op::pow: {
      const T& d = detail::value_of(a);
      if (integer) {
        if (*integer < 0)
          domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "0 to a negative power", d);
        return power(a, static_cast<int>(*integer));
      }
      // a^b = exp(b log a), a > 0
      domain(certainly_nonpositive(d), !certainly_positive(d), "a non-integer power of a number <= 0", d);
      return exp(b * log(a));
    }
    case op::sin: angle(a, "sin"); return sin(a);
    case op::cos: angle(a, "cos"); return cos(a);
    case op::tan: {
      angle(a, "tan");
      const S c = cos(a);
      const T& d = detail::value_of(c);
      domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "tan at a pole", d);
      return tan(a);
    }
    case op::exp: return exp(a);
    case op::log: {
      const T& d = detail::value_of(a);
      domain(certainly_nonpositive(d), !certainly_positive(d), "log of a number <= 0", d);
      return log(a);
    }
    case op::sqrt: {
      const T& d = detail::value_of(a);
      // sqrt is not differentiable at 0: a dual or jet argument must be > 0
      if constexpr (is_dual<S>::value || is_jet<S>::value)
        domain(certainly_nonpositive(d), !certainly_positive(d), "sqrt of a number <= 0 (its derivative)", d);
      else
        domain(certainly_negative(d), possibly_negative(d), "sqrt of a negative number", d);
      return sqrt(a);
    }
    default: break;
  }
  throw std::logic_error("expression: not an operation");
}

template <class S>
S expression::eval_node(int i, const S* x, const std::vector<base_scalar_t<S>>* constants) const {
  using T = base_scalar_t<S>;
  const node& n = nodes_[static_cast<std::size_t>(i)];
  switch (n.kind) {
    case op::number: return detail::from_base<S>(constants ? (*constants)[static_cast<std::size_t>(i)] : from_decimal<T>(n.number));
    case op::pi: return detail::from_base<S>(constants ? (*constants)[static_cast<std::size_t>(i)] : constant_pi<T>());
    case op::variable: return x[n.var];
    case op::table:
    case op::table_rate:
      return table_value<S>(*tables_[static_cast<std::size_t>(n.var)], nullptr, eval_node(n.a, x, constants),
                            n.kind == op::table_rate, where_);
    case op::div: {  // the denominator first: its check comes before the numerator's
      const S den = eval_node(n.b, x, constants);
      const S num = eval_node(n.a, x, constants);
      return apply(n.kind, num, den, nullptr, where_);
    }
    case op::pow: {
      long k = 0;
      const S base = eval_node(n.a, x, constants);
      if (is_integer(n.b, k) && k > -1000000 && k < 1000000) return apply(n.kind, base, base, &k, where_);
      return apply(n.kind, base, eval_node(n.b, x, constants), nullptr, where_);
    }
    default: {
      const S a = eval_node(n.a, x, constants);
      return apply(n.kind, a, n.b >= 0 ? eval_node(n.b, x, constants) : a, nullptr, where_);
    }
  }
}

namespace detail {
/// The operation budget of an expression compiled for T (expression::limits).
template <Scalar T>
void check_operation_budget(const expression& e) {
  const std::size_t bits = scalar_traits<T>::precision_bits();
  if (e.operations() * bits > expression::limits::operation_bits)
    throw input_error(e.where() + ": " + std::to_string(e.operations()) + " operations at " + std::to_string(bits) +
                      " bits, more than the budget of " + std::to_string(expression::limits::operation_bits) +
                      " operation-bits (a simpler expression, or fewer bits)");
}
}  // namespace detail

/// An expression with its constants in T, for repeated evaluation on T and
/// dual<T>.  It refers to the expression, which must outlive it.
template <Scalar T>
class compiled_expression {
 public:
  compiled_expression() = default;
  explicit compiled_expression(const expression& e) : e_(&e), constants_(e.constants<T>()) {
    detail::check_operation_budget<T>(e);
  }
  template <class S>
  S eval(const S& x) const {
    return e_->eval_bound(x, constants_);
  }
  /// At the variables x[0], x[1], ... (in the order the expression was parsed with).
  template <class S>
  S eval_at(const S* x) const {
    return e_->eval_bound_at(x, constants_);
  }
  const expression& source() const { return *e_; }

 private:
  const expression* e_ = nullptr;
  std::vector<T> constants_;
};

/// Expressions in the same variables merged into one graph, for evaluation in
/// one pass: a subexpression that occurs in several of them, or several times
/// in one (symbolic derivatives repeat their operands), is one node, evaluated
/// once.  Each node applies the operation and the domain checks of
/// expression::eval (errors name the first expression that brought the node).
template <Scalar T>
class expression_tape {
 public:
  /// Adds e; returns the index of its value among the node values eval() fills.
  int add(const expression& e) {
    detail::check_operation_budget<T>(e);
    const auto& en = e.nodes_;
    std::vector<char> reached(en.size(), 0);
    reached[static_cast<std::size_t>(e.root_)] = 1;
    for (std::size_t i = en.size(); i-- > 0;)
      if (reached[i])
        for (int c : {en[i].a, en[i].b})
          if (c >= 0) reached[static_cast<std::size_t>(c)] = 1;
    std::vector<int> mapped(en.size(), -1);
    for (std::size_t i = 0; i < en.size(); ++i) {
      if (!reached[i]) continue;
      const expression::node& n = en[i];
      const int a = n.a >= 0 ? mapped[static_cast<std::size_t>(n.a)] : -1;
      const int b = n.b >= 0 ? mapped[static_cast<std::size_t>(n.b)] : -1;
      const int var = n.kind == expression::op::variable ? n.var : 0;
      const auto key = std::make_tuple(static_cast<int>(n.kind), a, b, var, n.number);
      const auto found = index_.find(key);
      if (found != index_.end()) {
        mapped[i] = found->second;
        continue;
      }
      entry t{n.kind, a, b, var, 0, false, static_cast<int>(wheres_.size()), nullptr, -1};
      if (n.kind == expression::op::table || n.kind == expression::op::table_rate) {
        t.table = e.tables_[static_cast<std::size_t>(n.var)].get();
        t.table_values = static_cast<int>(table_values_.size());
        std::vector<T> v;
        v.reserve(t.table->values.size());
        for (const std::string& x : t.table->values) v.push_back(from_decimal<T>(x));
        table_values_.push_back(std::move(v));
      }
      long k = 0;
      if (n.kind == expression::op::pow && e.is_integer(n.b, k) && k > -1000000 && k < 1000000) {
        t.integer = k;
        t.has_integer = true;
      }
      T c(0);
      if (n.kind == expression::op::number) c = from_decimal<T>(n.number);
      if (n.kind == expression::op::pi) c = constant_pi<T>();
      mapped[i] = static_cast<int>(nodes_.size());
      nodes_.push_back(t);
      constants_.push_back(c);
      index_.emplace(key, mapped[i]);
    }
    wheres_.push_back(e.where());
    return mapped[static_cast<std::size_t>(e.root_)];
  }
  std::size_t size() const { return nodes_.size(); }

  /// How many nodes read the table `name` (0: none does).
  int table_readers(const std::string& name) const {
    int n = 0;
    for (const entry& e : nodes_) n += e.table && e.table->name == name;
    return n;
  }
  /// Value k of the table named `name`, in every node that reads the table, set to v in place of
  /// the decimal the table gives (`appell validity --vary tables.NAME.value[K]`: v a range).
  /// Returns how many nodes read the table (0: v reaches nothing on this tape).
  int set_table_value(const std::string& name, std::size_t k, const T& v) {
    int n = 0;
    for (const entry& e : nodes_)
      if (e.table && e.table->name == name) {
        table_values_[static_cast<std::size_t>(e.table_values)].at(k) = v;
        ++n;
      }
    return n;
  }

  /// Every node's value at the variables x (S: T or a dual of T), into `values`.
  template <class S>
  void eval(const S* x, std::vector<S>& values) const {
    values.resize(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const entry& n = nodes_[i];
      switch (n.kind) {
        case expression::op::number:
        case expression::op::pi: values[i] = detail::from_base<S>(constants_[i]); break;
        case expression::op::variable: values[i] = x[n.var]; break;
        case expression::op::table:
        case expression::op::table_rate:
          values[i] = table_value<S>(*n.table, table_values_[static_cast<std::size_t>(n.table_values)].data(),
                                     values[static_cast<std::size_t>(n.a)], n.kind == expression::op::table_rate,
                                     wheres_[static_cast<std::size_t>(n.where)]);
          break;
        default: {
          const S& a = values[static_cast<std::size_t>(n.a)];
          const S& b = n.b >= 0 ? values[static_cast<std::size_t>(n.b)] : a;
          values[i] = expression::apply(n.kind, a, b, n.has_integer ? &n.integer : nullptr,
                                        wheres_[static_cast<std::size_t>(n.where)]);
        }
      }
    }
  }

 private:
  struct entry {
    expression::op kind;
    int a, b, var;
    long integer;
    bool has_integer;
    int where;  ///< index into wheres_
    const piecewise_linear* table;  ///< a table node's table (its expression's, which outlives the tape)
    int table_values;               ///< its values in T: index into table_values_
  };
  std::vector<entry> nodes_;
  std::vector<T> constants_;
  std::vector<std::vector<T>> table_values_;
  std::vector<std::string> wheres_;
  std::map<std::tuple<int, int, int, int, std::string>, int> index_;
};

}  // namespace appell
