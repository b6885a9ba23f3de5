// Parsing and symbolic differentiation of scene expressions.
#include "appell/expr/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace appell {
namespace {

/// A breakpoint or a time in a message: the shortest decimal that reads back as the double.
std::string time_text(double x) {
  char b[40];
  const auto r = std::to_chars(b, b + sizeof b, x);
  return std::string(b, r.ptr);
}

class parser {
 public:
  parser(const std::string& text, const std::vector<std::string>& variables, const std::string& where,
         std::vector<expression::node>& nodes, const expression_tables& tables)
      : s_(text), vars_(variables), where_(where), nodes_(nodes), tables_(tables) {}

  int parse_all() {
    const int r = expr();
    skip();
    if (i_ != s_.size()) fail("unexpected '" + std::string(1, s_[i_]) + "'");
    return r;
  }

 private:
  using op = expression::op;
  [[noreturn]] void fail(const std::string& why) const {
    throw input_error(where_ + ": " + why + " at position " + std::to_string(i_ + 1) + " of '" + printable(s_) + "'");
  }
  // Counts the parser's recursion (parentheses, function arguments, unary
  // signs, exponents) so that no input can exhaust the stack.
  struct nesting {
    explicit nesting(parser& p) : p_(p) {
      if (++p_.depth_ > expression::limits::nesting)
        p_.fail("nested deeper than " + std::to_string(expression::limits::nesting));
    }
    ~nesting() { --p_.depth_; }
    parser& p_;
  };
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  int make(op k, int a = -1, int b = -1, std::string number = {}, int var = 0) {
    nodes_.push_back({k, a, b, std::move(number), var});
    return static_cast<int>(nodes_.size()) - 1;
  }
  int expr() {
    const nesting guard(*this);
    int left = term();
    for (;;) {
      if (eat('+')) left = make(op::add, left, term());
      else if (eat('-')) left = make(op::sub, left, term());
      else return left;
    }
  }
  int term() {
    int left = unary();
    for (;;) {
      if (eat('*')) left = make(op::mul, left, unary());
      else if (eat('/')) left = make(op::div, left, unary());
      else return left;
    }
  }
  int unary() {
    const nesting guard(*this);
    if (eat('-')) return make(op::neg, unary());
    if (eat('+')) return unary();
    return power();
  }
  int power() {
    const int base = primary();
    if (eat('^')) return make(op::pow, base, unary());  // right-associative
    return base;
  }
  int primary() {
    skip();
    if (i_ >= s_.size()) fail("unexpected end");
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const std::size_t start = i_;
      while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) ++i_;
      if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
        std::size_t j = i_ + 1;
        if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
        if (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) {
          i_ = j;
          while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
        }
      }
      const std::string number = s_.substr(start, i_ - start);
      if (!is_decimal_literal(number)) fail("bad number '" + number + "'");
      return make(op::number, -1, -1, number);
    }
    if (eat('(')) {
      const int r = expr();
      if (!eat(')')) fail("missing ')'");
      return r;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = i_;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      const std::string name = s_.substr(start, i_ - start);
      for (std::size_t v = 0; v < vars_.size(); ++v)
        if (name == vars_[v]) return make(op::variable, -1, -1, {}, static_cast<int>(v));
      if (name == "pi") return make(op::pi);
      static const std::pair<const char*, op> functions[] = {{"sin", op::sin}, {"cos", op::cos}, {"tan", op::tan},
                                                             {"exp", op::exp}, {"log", op::log}, {"sqrt", op::sqrt}};
      for (const auto& [fname, kind] : functions) {
        if (name == fname) {
          if (!eat('(')) fail("expected '(' after " + name);
          const int arg = expr();
          if (!eat(')')) fail("missing ')'");
          return make(kind, arg);
        }
      }
      if (tables_.tables)
        for (std::size_t k = 0; k < tables_.tables->size(); ++k) {
          const piecewise_linear& table = *(*tables_.tables)[k];
          if (name != table.name) continue;
          if (!tables_.refusal.empty()) {
            i_ = start;
            fail("the table '" + name + "' " + tables_.refusal);
          }
          if (!eat('(')) fail("expected '(' after the table " + name);
          const std::size_t argument_at = i_;
          const int arg = expr();
          if (!eat(')')) fail("missing ')'");
          const expression::node& a = nodes_[static_cast<std::size_t>(arg)];
          if (a.kind != op::variable || a.var != tables_.time) {
            i_ = argument_at;
            fail("a table is a function of the time alone: " + name + "(t)");
          }
          return make(op::table, arg, -1, name, static_cast<int>(k));
        }
      i_ = start;
      std::string known;
      for (const std::string& v : vars_) known += v + ", ";
      if (tables_.tables)
        for (const auto& table : *tables_.tables) known += table->name + "(t), ";
      fail("unknown name '" + name + "' (known: " + printable(known, 200) + "pi, sin, cos, tan, exp, log, sqrt)");
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }

  std::string s_;
  const std::vector<std::string>& vars_;
  std::string where_;
  std::size_t i_ = 0, depth_ = 0;
  std::vector<expression::node>& nodes_;
  const expression_tables& tables_;
};

}  // namespace

int expression::add_node(op k, int a, int b, std::string number, int var) {
  nodes_.push_back({k, a, b, std::move(number), var});
  return static_cast<int>(nodes_.size()) - 1;
}

expression expression::parse(const std::string& text, const std::string& variable, const std::string& where) {
  return parse(text, std::vector<std::string>{variable}, where);
}

expression expression::parse(const std::string& text, const std::vector<std::string>& variables,
                             const std::string& where) {
  return parse(text, variables, where, expression_tables{});
}

expression expression::parse(const std::string& text, const std::vector<std::string>& variables,
                             const std::string& where, const expression_tables& tables) {
  if (text.size() > limits::characters)
    throw input_error(where + ": longer than " + std::to_string(limits::characters) + " characters");
  expression e;
  e.where_ = where;
  e.variables_ = variables;
  parser p(text, e.variables_, where, e.nodes_, tables);
  e.root_ = p.parse_all();
  e.check_limits();
  if (e.calls_table()) e.tables_ = *tables.tables;
  return e;
}

bool expression::calls_table() const {
  return std::any_of(nodes_.begin(), nodes_.end(), [](const node& n) { return n.kind == op::table || n.kind == op::table_rate; });
}

int table_piece_of_segment(const piecewise_linear& table, const time_segment& s, const std::string& where) {
  const auto& t = table.times;
  if (s.lo < t.front() || s.hi > t.back())
    throw input_error(where + ": the table '" + table.name + "' is given for t in [" + time_text(t.front()) + ", " +
                      time_text(t.back()) + "]; the motion reaches t in [" + time_text(s.lo) + ", " +
                      time_text(s.hi) + "]");
  auto k = static_cast<int>(std::upper_bound(t.begin(), t.end(), s.lo) - t.begin()) - 1;
  k = std::min(k, static_cast<int>(t.size()) - 2);
  if (s.hi > t[static_cast<std::size_t>(k + 1)])
    throw std::logic_error("table_piece_of_segment: a step across the breakpoint " +
                           time_text(t[static_cast<std::size_t>(k + 1)]) + " of the table '" + table.name + "'");
  return k;
}

namespace detail {
void table_outside(const piecewise_linear& table, const std::string& at, bool certainly, const std::string& where) {
  const std::string text = where + ": " + (certainly ? "" : "cannot exclude that ") + "t = " + at +
                           (certainly ? " is" : " be") + " outside the times of the table '" + table.name + "' [" +
                           time_text(table.times.front()) + ", " + time_text(table.times.back()) + "]";
  if (certainly) throw input_error(text);
  throw certification_error(text);
}
void table_across(const piecewise_linear& table, double breakpoint, const std::string& at, const std::string& where) {
  throw certification_error(where + ": t = " + at + " may lie on either side of the breakpoint " +
                            time_text(breakpoint) + " of the table '" + table.name +
                            "' (no derivative there: the integrators end a step at each breakpoint)");
}
}  // namespace detail

bool expression::depends_on(int variable) const {
  std::vector<char> reached(nodes_.size(), 0);
  reached[static_cast<std::size_t>(root_)] = 1;
  for (std::size_t i = nodes_.size(); i-- > 0;) {  // operands have smaller indices
    if (!reached[i]) continue;
    const node& n = nodes_[i];
    if (n.kind == op::variable && n.var == variable) return true;
    for (int c : {n.a, n.b})
      if (c >= 0) reached[static_cast<std::size_t>(c)] = 1;
  }
  return false;
}

bool expression::is_zero() const {
  const node& n = nodes_[static_cast<std::size_t>(root_)];
  return n.kind == op::number && n.number.find_first_not_of("0.") == std::string::npos;
}

bool expression::vanishes_when_zero(const std::vector<int>& zero) const {
  // z[i]: node i is 0 wherever the listed variables are, children first (smaller indices).
  std::vector<char> z(nodes_.size(), 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const node& n = nodes_[i];
    const auto at = [&](int k) { return k >= 0 && z[static_cast<std::size_t>(k)]; };
    long k = 0;
    switch (n.kind) {
      case op::number: z[i] = n.number.find_first_not_of("0.") == std::string::npos; break;
      case op::variable: z[i] = std::find(zero.begin(), zero.end(), n.var) != zero.end(); break;
      case op::add:
      case op::sub: z[i] = at(n.a) && at(n.b); break;
      case op::mul: z[i] = at(n.a) || at(n.b); break;
      case op::div:  // 0 / d is 0 where d is not 0 (where d is 0 the expression is refused anyway)
      case op::neg:
      case op::sin:
      case op::tan:
      case op::sqrt: z[i] = at(n.a); break;
      case op::pow: z[i] = at(n.a) && is_integer(n.b, k) && k > 0; break;
      default: z[i] = 0;
    }
  }
  return z[static_cast<std::size_t>(root_)] != 0;
}

// Depth and unfolded size of every node, children first (a node's operands
// always have smaller indices), saturating: linear in the number of nodes.
void expression::check_limits() const {
  std::vector<std::size_t> depth(nodes_.size(), 0), size(nodes_.size(), 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const node& n = nodes_[i];
    std::size_t d = 0, s = 1;
    for (int c : {n.a, n.b})
      if (c >= 0) {
        d = std::max(d, depth[static_cast<std::size_t>(c)]);
        s = std::min(s + size[static_cast<std::size_t>(c)], limits::size + 1);
      }
    depth[i] = d + 1;
    size[i] = s;
  }
  const auto r = static_cast<std::size_t>(root_);
  operations_ = size[r];
  if (depth[r] > limits::depth)
    throw input_error(where_ + ": a tree deeper than " + std::to_string(limits::depth) + " (a sum of too many terms?)");
  if (size[r] > limits::size)
    throw input_error(where_ + ": more than " + std::to_string(limits::size) + " operations when unfolded");
}

bool expression::is_integer(int i, long& value) const {
  const node& n = nodes_[static_cast<std::size_t>(i)];
  if (n.kind == op::neg && is_integer(n.a, value)) {
    value = -value;
    return true;
  }
  if (n.kind != op::number) return false;
  if (n.number.find_first_not_of("0123456789") != std::string::npos || n.number.size() > 9) return false;
  value = std::stol(n.number);
  return true;
}

int expression::copy_into(int i, expression& out, std::vector<int>& copied) const {
  if (copied[static_cast<std::size_t>(i)] >= 0) return copied[static_cast<std::size_t>(i)];
  const node& n = nodes_[static_cast<std::size_t>(i)];
  const int a = n.a >= 0 ? copy_into(n.a, out, copied) : -1;
  const int b = n.b >= 0 ? copy_into(n.b, out, copied) : -1;
  return copied[static_cast<std::size_t>(i)] = out.add_node(n.kind, a, b, n.number, n.var);
}

// d(node i)/d(variable) into `out`; -1 stands for the derivative 0 (kept out of the tree).
int expression::derive(int i, int variable, expression& out, std::vector<int>& copied) const {
  const node& n = nodes_[static_cast<std::size_t>(i)];
  auto copy = [&](int j) { return copy_into(j, out, copied); };
  auto num = [&](const char* text) { return out.add_node(op::number, -1, -1, text); };
  auto mul = [&](int a, int b) { return out.add_node(op::mul, a, b); };
  auto add = [&](int a, int b) { return a < 0 ? b : b < 0 ? a : out.add_node(op::add, a, b); };
  auto neg = [&](int a) { return a < 0 ? -1 : out.add_node(op::neg, a); };
  auto chain = [&](int outer, int da) { return da < 0 ? -1 : mul(outer, da); };  // f'(a) a'
  switch (n.kind) {
    case op::number:
    case op::pi: return -1;
    case op::variable: return n.var == variable ? num("1") : -1;
    case op::add: return add(derive(n.a, variable, out, copied), derive(n.b, variable, out, copied));
    case op::sub: return add(derive(n.a, variable, out, copied), neg(derive(n.b, variable, out, copied)));
    case op::neg: return neg(derive(n.a, variable, out, copied));
    case op::mul: {  // (ab)' = a'b + ab'
      const int da = derive(n.a, variable, out, copied), db = derive(n.b, variable, out, copied);
      return add(da < 0 ? -1 : mul(da, copy(n.b)), db < 0 ? -1 : mul(copy(n.a), db));
    }
    case op::div: {  // (a/b)' = a'/b - a b' / b^2
      const int da = derive(n.a, variable, out, copied), db = derive(n.b, variable, out, copied);
      const int first = da < 0 ? -1 : out.add_node(op::div, da, copy(n.b));
      const int second =
          db < 0 ? -1
                 : out.add_node(op::div, mul(copy(n.a), db), out.add_node(op::pow, copy(n.b), num("2")));
      return add(first, neg(second));
    }
    case op::pow: {
      long k = 0;
      const int da = derive(n.a, variable, out, copied);
      if (is_integer(n.b, k)) {  // (a^k)' = k a^(k-1) a'
        if (k == 0 || da < 0) return -1;
        const int km1 = out.add_node(op::number, -1, -1, std::to_string(std::labs(k - 1)));
        const int exponent = k - 1 < 0 ? out.add_node(op::neg, km1) : km1;
        const int kk = out.add_node(op::number, -1, -1, std::to_string(std::labs(k)));
        const int coeff = k < 0 ? out.add_node(op::neg, kk) : kk;
        return mul(mul(coeff, out.add_node(op::pow, copy(n.a), exponent)), da);
      }
      // (a^b)' = a^b (b' log a + b a'/a)
      const int db = derive(n.b, variable, out, copied);
      const int t1 = db < 0 ? -1 : mul(db, out.add_node(op::log, copy(n.a)));
      const int t2 = da < 0 ? -1 : out.add_node(op::div, mul(copy(n.b), da), copy(n.a));
      const int inner = add(t1, t2);
      return inner < 0 ? -1 : mul(copy(i), inner);
    }
    case op::sin: return chain(out.add_node(op::cos, copy(n.a)), derive(n.a, variable, out, copied));
    case op::cos: return chain(neg(out.add_node(op::sin, copy(n.a))), derive(n.a, variable, out, copied));
    case op::tan:  // 1 + tan^2
      return chain(add(num("1"), out.add_node(op::pow, out.add_node(op::tan, copy(n.a)), num("2"))),
                   derive(n.a, variable, out, copied));
    case op::exp: return chain(copy(i), derive(n.a, variable, out, copied));
    case op::log: {
      const int da = derive(n.a, variable, out, copied);
      return da < 0 ? -1 : out.add_node(op::div, da, copy(n.a));
    }
    case op::sqrt: {  // 1 / (2 sqrt a)
      const int da = derive(n.a, variable, out, copied);
      return da < 0 ? -1 : out.add_node(op::div, da, mul(num("2"), copy(i)));
    }
    case op::table: {  // the argument is t alone: the piece's slope where t is the variable
      const int da = derive(n.a, variable, out, copied);
      return da < 0 ? -1 : out.add_node(op::table_rate, copy(n.a), -1, n.number, n.var);
    }
    case op::table_rate:  // constant on each piece (a step never crosses a breakpoint)
      return -1;
  }
  throw std::logic_error("expression: unknown node");
}

expression expression::derivative(int variable) const {
  expression out;
  out.where_ = variables_.size() > 1 ? "d(" + where_ + ")/d" + variables_[static_cast<std::size_t>(variable)] : where_ + "'";
  out.variables_ = variables_;
  out.tables_ = tables_;
  std::vector<int> copied(nodes_.size(), -1);
  const int r = derive(root_, variable, out, copied);
  out.root_ = r < 0 ? out.add_node(op::number, -1, -1, "0") : r;
  out.check_limits();
  return out;
}

expression expression::difference(const expression& a, const expression& b, const std::string& where) {
  if (a.variables_ != b.variables_) throw std::logic_error("expression::difference: operands in different variables");
  expression out;
  out.where_ = where;
  out.variables_ = a.variables_;
  if (!a.tables_.empty() && !b.tables_.empty() && a.tables_ != b.tables_)
    throw std::logic_error("expression::difference: operands with different tables");
  out.tables_ = a.tables_.empty() ? b.tables_ : a.tables_;
  // Both copied into out with structurally equal subtrees merged into one node, so that a
  // term's node index is its identity.
  std::map<std::tuple<int, int, int, int, std::string>, int> index;
  auto copy_all = [&](const expression& e) {
    std::vector<int> mapped(e.nodes_.size(), -1);
    std::vector<char> reached(e.nodes_.size(), 0);
    reached[static_cast<std::size_t>(e.root_)] = 1;
    for (std::size_t i = e.nodes_.size(); i-- > 0;)
      if (reached[i])
        for (int c : {e.nodes_[i].a, e.nodes_[i].b})
          if (c >= 0) reached[static_cast<std::size_t>(c)] = 1;
    for (std::size_t i = 0; i < e.nodes_.size(); ++i) {  // operands have smaller indices
      if (!reached[i]) continue;
      const node& n = e.nodes_[i];
      const int x = n.a >= 0 ? mapped[static_cast<std::size_t>(n.a)] : -1;
      const int y = n.b >= 0 ? mapped[static_cast<std::size_t>(n.b)] : -1;
      const int var = n.kind == op::variable || n.kind == op::table || n.kind == op::table_rate ? n.var : 0;
      const auto key = std::make_tuple(static_cast<int>(n.kind), x, y, var, n.number);
      const auto found = index.find(key);
      mapped[i] = found != index.end() ? found->second : index.emplace(key, out.add_node(n.kind, x, y, n.number, var)).first->second;
    }
    return mapped[static_cast<std::size_t>(e.root_)];
  };
  const int ra = copy_all(a), rb = copy_all(b);
  // zero[i]: node i is 0 as written (a number 0, or a product with such a factor).
  std::vector<char> zero(out.nodes_.size(), 0);
  for (std::size_t i = 0; i < out.nodes_.size(); ++i) {
    const node& n = out.nodes_[i];
    if (n.kind == op::number) zero[i] = n.number.find_first_not_of("0.") == std::string::npos;
    if (n.kind == op::mul) zero[i] = zero[static_cast<std::size_t>(n.a)] || zero[static_cast<std::size_t>(n.b)];
    if (n.kind == op::neg) zero[i] = zero[static_cast<std::size_t>(n.a)];
  }
  // The signed terms of a node, through +, - and unary - (an explicit stack: sums may be long).
  auto terms_of = [&](int root, int sign) {
    std::vector<std::pair<int, int>> terms, todo{{root, sign}};
    while (!todo.empty()) {
      const auto [i, s] = todo.back();
      todo.pop_back();
      const node& n = out.nodes_[static_cast<std::size_t>(i)];
      if (n.kind == op::add) {
        todo.push_back({n.b, s});
        todo.push_back({n.a, s});
      } else if (n.kind == op::sub) {
        todo.push_back({n.b, -s});
        todo.push_back({n.a, s});
      } else if (n.kind == op::neg) {
        todo.push_back({n.a, -s});
      } else if (!zero[static_cast<std::size_t>(i)]) {
        terms.push_back({i, s});
      }
    }
    return terms;
  };
  std::vector<std::pair<int, int>> kept = terms_of(ra, 1);
  std::vector<char> cancelled(kept.size(), 0);
  for (const auto& [i, s] : terms_of(rb, -1)) {
    std::size_t k = 0;
    while (k < kept.size() && (cancelled[k] || kept[k].first != i || kept[k].second != -s)) ++k;
    if (k < kept.size()) cancelled[k] = 1;
    else kept.push_back({i, s}), cancelled.push_back(0);
  }
  int root = -1;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (cancelled[k]) continue;
    const auto [i, s] = kept[k];
    if (root < 0) root = s > 0 ? i : out.add_node(op::neg, i);
    else root = out.add_node(s > 0 ? op::add : op::sub, root, i);
  }
  out.root_ = root < 0 ? out.add_node(op::number, -1, -1, "0") : root;
  out.check_limits();
  return out;
}

std::string expression::node_string(int i) const {
  const node& n = nodes_[static_cast<std::size_t>(i)];
  switch (n.kind) {
    case op::number: return n.number;
    case op::pi: return "pi";
    case op::variable: return variables_.empty() ? "x" : variables_[static_cast<std::size_t>(n.var)];
    case op::add: return "(" + node_string(n.a) + " + " + node_string(n.b) + ")";
    case op::sub: return "(" + node_string(n.a) + " - " + node_string(n.b) + ")";
    case op::mul: return "(" + node_string(n.a) + " * " + node_string(n.b) + ")";
    case op::div: return "(" + node_string(n.a) + " / " + node_string(n.b) + ")";
    case op::pow: return "(" + node_string(n.a) + " ^ " + node_string(n.b) + ")";
    case op::neg: return "(-" + node_string(n.a) + ")";
    case op::sin: return "sin(" + node_string(n.a) + ")";
    case op::cos: return "cos(" + node_string(n.a) + ")";
    case op::tan: return "tan(" + node_string(n.a) + ")";
    case op::exp: return "exp(" + node_string(n.a) + ")";
    case op::log: return "log(" + node_string(n.a) + ")";
    case op::sqrt: return "sqrt(" + node_string(n.a) + ")";
    case op::table: return n.number + "(" + node_string(n.a) + ")";
    case op::table_rate: return "d" + n.number + "/dt(" + node_string(n.a) + ")";
  }
  return "?";
}

std::string expression::to_string() const { return node_string(root_); }

}  // namespace appell
