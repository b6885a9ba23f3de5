// appell/expr/expression.hpp -- the scene expression language (SCENES.md):
// numbers, pi, named variables (one for a cone's f(theta), many for a system
// file's), + - * / ^, parentheses, sin cos tan exp log sqrt.
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

#include <memory>
#include <string>
#include <vector>

#include "appell/dynamics/dual.hpp"
#include "appell/io/json.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"

namespace appell {

class expression {
 public:
  enum class op { number, pi, variable, add, sub, mul, div, pow, neg, sin, cos, tan, exp, log, sqrt };
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
  /// d/d(variable), symbolically (the only variable, or variable number `variable`).
  expression derivative(int variable = 0) const;
  /// Whether variable number `variable` occurs in the expression (its tree as
  /// written: x - x depends on x).
  bool depends_on(int variable) const;
  /// Whether the expression is the number 0 as written (a derivative that vanishes
  /// structurally is written so).
  bool is_zero() const;
  std::string to_string() const;
  const std::string& where() const { return where_; }
  const std::vector<std::string>& variables() const { return variables_; }

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

  std::vector<node> nodes_;
  int root_ = -1;
  std::string where_;
  std::vector<std::string> variables_;
  mutable std::size_t operations_ = 0;  ///< set by check_limits
};

namespace detail {
template <class S>
const base_scalar_t<S>& value_of(const S& x) {
  if constexpr (is_dual<S>::value) return value_of(x.v);
  else return x;
}
template <class T>
std::string describe(const T& x) { return to_string(x); }
}  // namespace detail

template <class S>
S expression::eval_node(int i, const S* x, const std::vector<base_scalar_t<S>>* constants) const {
  using T = base_scalar_t<S>;
  using std::sin, std::cos, std::tan, std::exp, std::log, std::sqrt;
  const node& n = nodes_[static_cast<std::size_t>(i)];
  auto domain = [&](bool certainly_bad, bool possibly_bad, const std::string& what, const T& at) {
    if (certainly_bad) throw input_error(where_ + ": " + what + " at the state (" + detail::describe(at) + ")");
    if (possibly_bad)
      throw certification_error(where_ + ": cannot exclude " + what + " at the state (" + detail::describe(at) + ")");
  };
  // sin, cos, tan of |y| > 2^40 rad: no physical angle, and an argument
  // reduction that costs time in the exponent (MPFR, MPFI) or loses every digit (QD)
  auto angle = [&](const S& y, const char* fn) {
    const T& d = detail::value_of(y);
    const T limit(1099511627776.0);  // 2^40, exact in every scalar
    domain(certainly_positive(T(d - limit)) || certainly_negative(T(d + limit)),
           !(certainly_nonpositive(T(d - limit)) && certainly_nonnegative(T(d + limit))),
           std::string(fn) + " of an angle beyond 2^40 rad", d);
  };
  switch (n.kind) {
    case op::number: return S(constants ? (*constants)[static_cast<std::size_t>(i)] : from_decimal<T>(n.number));
    case op::pi: return S(constants ? (*constants)[static_cast<std::size_t>(i)] : constant_pi<T>());
    case op::variable: return x[n.var];
    case op::add: return eval_node(n.a, x, constants) + eval_node(n.b, x, constants);
    case op::sub: return eval_node(n.a, x, constants) - eval_node(n.b, x, constants);
    case op::mul: return eval_node(n.a, x, constants) * eval_node(n.b, x, constants);
    case op::neg: return -eval_node(n.a, x, constants);
    case op::div: {
      const S den = eval_node(n.b, x, constants);
      const T& d = detail::value_of(den);
      domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "division by zero", d);
      return eval_node(n.a, x, constants) / den;
    }
    case op::pow: {
      long k = 0;
      const S base = eval_node(n.a, x, constants);
      if (is_integer(n.b, k) && k > -1000000 && k < 1000000) {
        if (k < 0) {
          const T& d = detail::value_of(base);
          domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "0 to a negative power", d);
        }
        return power(base, static_cast<int>(k));
      }
      const T& d = detail::value_of(base);  // a^b = exp(b log a), a > 0
      domain(certainly_nonpositive(d), !certainly_positive(d), "a non-integer power of a number <= 0", d);
      return exp(eval_node(n.b, x, constants) * log(base));
    }
    case op::sin: {
      const S y = eval_node(n.a, x, constants);
      angle(y, "sin");
      return sin(y);
    }
    case op::cos: {
      const S y = eval_node(n.a, x, constants);
      angle(y, "cos");
      return cos(y);
    }
    case op::tan: {
      const S y = eval_node(n.a, x, constants);
      angle(y, "tan");
      const S c = cos(y);
      const T& d = detail::value_of(c);
      domain(certainly_nonnegative(d) && certainly_nonpositive(d), possibly_zero(d), "tan at a pole", d);
      return tan(y);
    }
    case op::exp: return exp(eval_node(n.a, x, constants));
    case op::log: {
      const S y = eval_node(n.a, x, constants);
      const T& d = detail::value_of(y);
      domain(certainly_nonpositive(d), !certainly_positive(d), "log of a number <= 0", d);
      return log(y);
    }
    case op::sqrt: {
      const S y = eval_node(n.a, x, constants);
      const T& d = detail::value_of(y);
      // sqrt is not differentiable at 0: a dual argument must be > 0
      if constexpr (is_dual<S>::value)
        domain(certainly_nonpositive(d), !certainly_positive(d), "sqrt of a number <= 0 (its derivative)", d);
      else
        domain(certainly_negative(d), possibly_negative(d), "sqrt of a negative number", d);
      return sqrt(y);
    }
  }
  throw std::logic_error("expression: unknown node");
}

/// An expression with its constants in T, for repeated evaluation on T and
/// dual<T>.  It refers to the expression, which must outlive it.
template <Scalar T>
class compiled_expression {
 public:
  compiled_expression() = default;
  explicit compiled_expression(const expression& e) : e_(&e), constants_(e.constants<T>()) {
    const std::size_t bits = scalar_traits<T>::precision_bits();
    if (e.operations() * bits > expression::limits::operation_bits)
      throw input_error(e.where() + ": " + std::to_string(e.operations()) + " operations at " + std::to_string(bits) +
                        " bits, more than the budget of " + std::to_string(expression::limits::operation_bits) +
                        " operation-bits (a simpler expression, or fewer bits)");
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

}  // namespace appell
