#include "experiments/proofs/exact_grid.hpp"

#include "experiments/proofs/expanded_polynomial.hpp"
#include "experiments/proofs/ginac_polynomial.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/exact/rational.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {
namespace {

using exact::Integer;

/// An expression tree compiled to a postfix program over the fraction pairs (n, d), with a structural bound of
/// the degree of n and of d in each variable. n and d are jets (see Jet below): the bounds hold for each of their
/// coefficients.
struct Node {
  enum class Op { constant, variable, bound, sum, product, power, derivative, function } op = Op::constant;
  std::vector<std::size_t> children;       ///< earlier nodes
  long exponent = 0;                       ///< power
  Integer numerator = 0, denominator = 1;  ///< constant
  std::size_t variable = 0;                ///< variable
  std::size_t source = 0;                  ///< bound: the node of the value substituted
  unsigned slots = 0;                      ///< variable, bound: the derivatives that shift it (bit j: ε_j)
  unsigned slot = 0;                       ///< derivative: its ε_j
  /// function: f(g) for f = cos, sin or exp, `variable` its value's grid variable, `partner` that of sin(g),
  /// cos(g) or exp(g) (f's derivative up to sign), children = {g}.
  enum class Function { cos, sin, exp } function = Function::cos;
  std::size_t partner = 0;
  std::vector<unsigned> numerator_degree, denominator_degree;
  bool denominator_is_one = true;  ///< structurally: d is the constant 1
};

/// The grid's variables by name: symbols, and functions such as cos(g) (named by g expanded), indexed in the order
/// they are first asked for. A first compilation discovers them (up to `capacity`); the second is given them in
/// alphabetical order, so that the grid and its record do not depend on GiNaC's order of terms.
class Variables {
 public:
  explicit Variables(std::size_t capacity) : capacity_(capacity) {}
  explicit Variables(const std::vector<std::string>& names) : capacity_(names.size()) {
    for (const std::string& name : names) index(name);
  }
  std::size_t index(const std::string& name) {
    const auto [at, added] = index_.emplace(name, names_.size());
    if (added) {
      if (names_.size() == capacity_) throw std::invalid_argument("grid check: too many variables");
      names_.push_back(name);
    }
    return at->second;
  }
  std::size_t size() const { return names_.size(); }
  /// The length of the degree vectors: the variables there can be.
  std::size_t capacity() const { return capacity_; }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::size_t capacity_;
  std::map<std::string, std::size_t> index_;
  std::vector<std::string> names_;
};

/// The names of the symbols of `e`.
void symbols_of(const GiNaC::ex& e, std::set<std::string>& found) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) found.insert(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
  for (std::size_t i = 0; i < e.nops(); ++i) symbols_of(e.op(i), found);
}

std::string symbol_name(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::symbol>(e).get_name(); }

Integer to_integer(const GiNaC::numeric& n) {
  std::ostringstream text;
  text << n;
  return Integer(text.str());
}

/// The derivatives nested in one side, at most: each nesting level is one ε_j of the jets.
constexpr unsigned max_derivative_depth = 2;
/// The variables of one identity, at most (the first compilation's degree vectors are this long).
constexpr std::size_t max_variables = 256;

class Program {
 public:
  Program(const GiNaC::ex& e, Variables& variables) : variables_(variables) { root_ = compile(e); }
  const std::vector<Node>& nodes() const { return nodes_; }
  std::size_t root() const { return root_; }
  /// The jets' number of coefficients, 2^(deepest nesting of derivatives).
  unsigned jet_size() const { return 1u << depth_used_; }

 private:
  /// An open derivative d/dx (its ε slot) or substitution x = value, from the root down to the node compiled.
  struct Scope {
    bool derivative;
    std::size_t variable;
    unsigned slot = 0;                             ///< derivative
    std::size_t value = 0;                         ///< substitution
    std::optional<ExpandedPolynomial> polynomial;  ///< substitution: the value expanded, when it is a polynomial
  };

  std::size_t push(Node node) {
    nodes_.push_back(std::move(node));
    return nodes_.size() - 1;
  }
  /// A degree bound per variable, and last the bound of the total degree, which follows the same rules.
  std::size_t degree_slots() const { return variables_.capacity() + 1; }
  std::size_t total() const { return variables_.capacity(); }
  std::vector<unsigned> zeros() const { return std::vector<unsigned>(degree_slots(), 0); }
  unsigned derivative_depth() const {
    return static_cast<unsigned>(
        std::count_if(scopes_.begin(), scopes_.end(), [](const Scope& s) { return s.derivative; }));
  }

  std::size_t constant(const Integer& numerator, const Integer& denominator) {
    Node node;
    node.numerator_degree = node.denominator_degree = zeros();
    node.numerator = numerator;
    node.denominator = denominator;
    node.denominator_is_one = denominator == 1;
    return push(std::move(node));
  }

  /// A sum or product of earlier nodes. Degrees follow the evaluation below: (n1 d2 + n2 d1) / (d1 d2) for a sum,
  /// (n1 n2) / (d1 d2) for a product.
  std::size_t combine(Node::Op op, std::vector<std::size_t> children) {
    Node node;
    node.op = op;
    node.children = std::move(children);
    const Node& first = nodes_[node.children.front()];
    node.numerator_degree = first.numerator_degree;
    node.denominator_degree = first.denominator_degree;
    node.denominator_is_one = first.denominator_is_one;
    for (std::size_t k = 1; k < node.children.size(); ++k) {
      const Node& c = nodes_[node.children[k]];
      for (std::size_t v = 0; v < degree_slots(); ++v) {
        if (op == Node::Op::sum)
          node.numerator_degree[v] = std::max(node.numerator_degree[v] + c.denominator_degree[v],
                                              c.numerator_degree[v] + node.denominator_degree[v]);
        else
          node.numerator_degree[v] += c.numerator_degree[v];
        node.denominator_degree[v] += c.denominator_degree[v];
      }
      node.denominator_is_one = node.denominator_is_one && c.denominator_is_one;
    }
    return push(std::move(node));
  }

  /// A symbol: the grid's coordinate, or the value of the innermost substitution of it; shifted by ε_j for each
  /// derivative d/dx between that and here (dual numbers: f(x + ε) = f(x) + ε f'(x)).
  std::size_t leaf(const GiNaC::ex& e) {
    Node node;
    node.variable = variables_.index(symbol_name(e));
    node.op = Node::Op::variable;
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
      if (s->variable != node.variable) continue;
      if (s->derivative) {
        node.slots |= 1u << s->slot;
        continue;
      }
      node.op = Node::Op::bound;
      node.source = s->value;
      break;
    }
    if (node.op == Node::Op::variable) {
      node.numerator_degree = node.denominator_degree = zeros();
      node.numerator_degree[node.variable] = node.numerator_degree[total()] = 1;
      return push(std::move(node));
    }
    // (n + ε d)/d: each coefficient of the numerator is bounded by n's or d's bound.
    const Node& value = nodes_[node.source];
    node.numerator_degree = value.numerator_degree;
    node.denominator_degree = value.denominator_degree;
    node.denominator_is_one = value.denominator_is_one;
    if (node.slots != 0)
      for (std::size_t v = 0; v < degree_slots(); ++v)
        node.numerator_degree[v] = std::max(node.numerator_degree[v], node.denominator_degree[v]);
    return push(std::move(node));
  }

  /// A function f(g) is an independent variable of the grid (an identity in it holds for f(g) in particular),
  /// named by f and g expanded with the open substitutions applied, so that cos(φ + tβ) at t = 0 is cos(φ). Under
  /// a derivative d/dt with t in g, f = cos, sin, exp follow the chain rule (function_of_jet); any other function,
  /// or an argument that is not a polynomial, is refused.
  std::size_t function_leaf(const GiNaC::ex& e) {
    std::set<std::string> symbols;
    symbols_of(e, symbols);
    std::map<std::string, ExpandedPolynomial> values;
    bool stepped = false;  // a derivative or substitution acts on a symbol of the argument
    for (const Scope& s : scopes_) {
      const std::string& name = variables_.names()[s.variable];
      if (!symbols.count(name)) continue;
      stepped = true;
      if (!s.derivative && !s.polynomial)
        throw std::invalid_argument("grid check: a substitution of a non-polynomial into " + text_of(e));
      if (!s.derivative) values[name] = *s.polynomial;
    }
    const std::string f = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (stepped && (e.nops() != 1 || (f != "cos" && f != "sin" && f != "exp")))
      throw std::invalid_argument("grid check: a step on a symbol inside " + text_of(e));
    const auto name = [&](const std::string& function) {
      return function + "(" + to_text(expanded(e.op(0), values)) + ")";
    };
    const auto argument_error = [&] {
      return std::invalid_argument("grid check: not a polynomial argument: " + text_of(e));
    };
    Node node;
    node.op = Node::Op::variable;
    node.numerator_degree = node.denominator_degree = zeros();
    try {
      node.variable = variables_.index(stepped || e.nops() == 1 ? name(f) : text_of(e));
    } catch (const std::invalid_argument&) {
      if (stepped) throw argument_error();
      node.variable = variables_.index(text_of(e));  // a function of no polynomial argument, stepped by nothing
    }
    if (!stepped) {
      node.numerator_degree[node.variable] = node.numerator_degree[total()] = 1;
      return push(std::move(node));
    }
    if (expanded(e.op(0), values).terms.count({}) == expanded(e.op(0), values).terms.size())
      throw std::invalid_argument("grid check: " + f + " of a number after a substitution: " + text_of(e));
    node.op = Node::Op::function;
    node.function = f == "cos" ? Node::Function::cos : f == "sin" ? Node::Function::sin : Node::Function::exp;
    node.partner = variables_.index(name(f == "cos" ? "sin" : f == "sin" ? "cos" : "exp"));
    node.children = {compile(e.op(0))};
    const Node& g = nodes_[node.children.front()];
    if (!g.denominator_is_one) throw argument_error();
    // f(g0 + h) = F (1 − h²/2) ∓ P h for cos and sin, E (1 + h + h²/2) for exp, h = g − g0 (h³ = 0): each coefficient
    // is bounded by F's, P's or E's degree 1 plus twice g's bound.
    for (std::size_t v = 0; v < degree_slots(); ++v)
      node.numerator_degree[v] =
          2 * g.numerator_degree[v] + (v == node.variable || v == node.partner || v == total() ? 1 : 0);
    // d/dt of f(g) is not ∂/∂t of the grid variable F: no derivative around this one lowers its degree.
    for (const Scope& s : scopes_)
      if (s.derivative && symbols.count(variables_.names()[s.variable])) chain_rule_in_slot_ |= 1u << s.slot;
    return push(std::move(node));
  }

  /// d/dx of the child, the quotient rule on its jets: (n/d)' = (n' d − n d')/d². Degree bounds: n' d − n d' is
  /// bounded by deg n + deg d, less one in x and in total when every dependence on the grid's x inside passes
  /// through ε_j (x free here, and no open substitution brings x in by its value): then n' = ∂n/∂x.
  std::size_t derivative(const GiNaC::ex& e) {
    if (!GiNaC::is_a<GiNaC::symbol>(e.op(1))) throw std::invalid_argument("grid check: d/d of a non-symbol");
    const unsigned depth = derivative_depth();
    if (depth >= max_derivative_depth)
      throw std::invalid_argument("grid check: derivatives nested deeper than " + std::to_string(max_derivative_depth));
    depth_used_ = std::max(depth_used_, depth + 1);
    const std::size_t x = variables_.index(symbol_name(e.op(1)));
    bool lowers = true;
    for (const Scope& s : scopes_)
      if (!s.derivative &&
          (s.variable == x || nodes_[s.value].numerator_degree[x] > 0 || nodes_[s.value].denominator_degree[x] > 0))
        lowers = false;
    scopes_.push_back({true, x, depth, 0, {}});
    chain_rule_in_slot_ &= ~(1u << depth);
    const std::size_t child = compile(e.op(0));
    scopes_.pop_back();
    lowers = lowers && !(chain_rule_in_slot_ & (1u << depth));

    const Node& c = nodes_[child];
    Node node;
    node.op = Node::Op::derivative;
    node.children = {child};
    node.slot = depth;
    node.denominator_is_one = c.denominator_is_one;
    node.numerator_degree = c.numerator_degree;
    node.denominator_degree = c.denominator_degree;
    if (!c.denominator_is_one)
      for (std::size_t v = 0; v < degree_slots(); ++v) {
        node.numerator_degree[v] += c.denominator_degree[v];
        node.denominator_degree[v] *= 2;
      }
    if (lowers && node.numerator_degree[x] > 0) --node.numerator_degree[x];
    if (lowers && node.numerator_degree[total()] > 0) --node.numerator_degree[total()];
    return push(std::move(node));
  }

  /// The open substitutions' polynomial values, innermost first for each symbol.
  std::map<std::string, ExpandedPolynomial> bound_values() const {
    std::map<std::string, ExpandedPolynomial> values;
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s)
      if (!s->derivative && s->polynomial) values.emplace(variables_.names()[s->variable], *s->polynomial);
    return values;
  }

  /// e with x = v: v compiled here, then e with x bound to it.
  std::size_t substitution(const GiNaC::ex& e) {
    const GiNaC::ex x = e.op(1).op(0);
    if (!GiNaC::is_a<GiNaC::lst>(e.op(1)) || e.op(1).nops() != 1 || !GiNaC::is_a<GiNaC::symbol>(x) ||
        !GiNaC::is_a<GiNaC::lst>(e.op(2)) || e.op(2).nops() != 1)
      throw std::invalid_argument("grid check: a substitution not of one symbol");
    const std::size_t value = compile(e.op(2).op(0));
    std::optional<ExpandedPolynomial> polynomial;
    try {
      polynomial = expanded(e.op(2).op(0), bound_values());
    } catch (const std::invalid_argument&) {
      // not a polynomial: only a function of x inside would need it, and refuses then
    }
    scopes_.push_back({false, variables_.index(symbol_name(x)), 0, value, polynomial});
    const std::size_t result = compile(e.op(0));
    scopes_.pop_back();
    return result;
  }

  /// A matrix of nodes, row by row.
  struct MatrixNodes {
    unsigned rows = 0, cols = 0;
    std::vector<std::size_t> entries;
    std::size_t at(unsigned i, unsigned j) const { return entries[i * cols + j]; }
  };

  MatrixNodes compile_matrix(const GiNaC::ex& e) {
    MatrixNodes m;
    if (GiNaC::is_a<GiNaC::matrix>(e)) {
      const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(e);
      m.rows = M.rows(), m.cols = M.cols();
      for (std::size_t k = 0; k < M.nops(); ++k) m.entries.push_back(compile(M.op(k)));
      return m;
    }
    if (step_of(e) == Step::transpose) {
      const MatrixNodes a = compile_matrix(e.op(0));
      m.rows = a.cols, m.cols = a.rows;
      for (unsigned i = 0; i < m.rows; ++i)
        for (unsigned j = 0; j < m.cols; ++j) m.entries.push_back(a.at(j, i));
      return m;
    }
    if (step_of(e) == Step::product) {
      const MatrixNodes a = compile_matrix(e.op(0)), b = compile_matrix(e.op(1));
      if (a.cols != b.rows) throw std::invalid_argument("grid check: a product of matrices that do not fit");
      m.rows = a.rows, m.cols = b.cols;
      for (unsigned i = 0; i < m.rows; ++i)
        for (unsigned j = 0; j < m.cols; ++j) {
          std::vector<std::size_t> terms;  // (AB)_ij = Σ_k A_ik B_kj
          for (unsigned k = 0; k < a.cols; ++k) terms.push_back(combine(Node::Op::product, {a.at(i, k), b.at(k, j)}));
          m.entries.push_back(combine(Node::Op::sum, terms));
        }
      return m;
    }
    throw std::invalid_argument("grid check: not a matrix: " + text_of(e));
  }

  /// det M = Σ_σ sgn σ Π_i M_{i σ(i)} (Leibniz), for a square matrix of at most 4 rows.
  std::size_t determinant(const GiNaC::ex& e) {
    const MatrixNodes m = compile_matrix(e.op(0));
    if (m.rows != m.cols || m.rows == 0 || m.rows > 4)
      throw std::invalid_argument("grid check: determinant of a matrix not square of at most 4 rows");
    std::vector<unsigned> sigma(m.rows);
    for (unsigned i = 0; i < m.rows; ++i) sigma[i] = i;
    const std::size_t minus_one = constant(-1, 1);
    std::vector<std::size_t> terms;
    do {
      unsigned inversions = 0;
      for (unsigned i = 0; i < m.rows; ++i)
        for (unsigned j = i + 1; j < m.rows; ++j) inversions += sigma[i] > sigma[j];
      std::vector<std::size_t> factors;
      if (inversions % 2 == 1) factors.push_back(minus_one);
      for (unsigned i = 0; i < m.rows; ++i) factors.push_back(m.at(i, sigma[i]));
      terms.push_back(combine(Node::Op::product, factors));
    } while (std::next_permutation(sigma.begin(), sigma.end()));
    return combine(Node::Op::sum, terms);
  }

  std::size_t compile(const GiNaC::ex& e) {
    switch (step_of(e)) {
      case Step::derivative:
        return derivative(e);
      case Step::substitution:
        return substitution(e);
      case Step::determinant:
        return determinant(e);
      case Step::entry: {
        const MatrixNodes m = compile_matrix(e.op(0));
        const GiNaC::ex k = e.op(1);
        if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_nonneg_integer() ||
            GiNaC::ex_to<GiNaC::numeric>(k).to_long() >= static_cast<long>(m.entries.size()))
          throw std::invalid_argument("grid check: entry out of range: " + text_of(e));
        return m.entries[GiNaC::ex_to<GiNaC::numeric>(k).to_long()];
      }
      case Step::transpose:
      case Step::product:
        throw std::invalid_argument("grid check: a matrix where a scalar is expected: " + text_of(e));
      case Step::none:
        break;
    }
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      if (!n.is_rational()) throw std::invalid_argument("grid check: not a rational number: " + text_of(e));
      return constant(to_integer(n.numer()), to_integer(n.denom()));
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) return leaf(e);
    if (GiNaC::is_a<GiNaC::function>(e)) return function_leaf(e);
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      std::vector<std::size_t> children;
      for (std::size_t i = 0; i < e.nops(); ++i) children.push_back(compile(e.op(i)));
      return combine(GiNaC::is_a<GiNaC::add>(e) ? Node::Op::sum : Node::Op::product, std::move(children));
    }
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e);
    throw std::invalid_argument("grid check: not a rational expression: " + text_of(e));
  }

  std::size_t power(const GiNaC::ex& e) {
    const GiNaC::ex exponent = e.op(1);
    if (!GiNaC::is_a<GiNaC::numeric>(exponent) || !GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer())
      throw std::invalid_argument("grid check: not an integer power: " + text_of(e));
    Node node;
    node.op = Node::Op::power;
    node.exponent = GiNaC::ex_to<GiNaC::numeric>(exponent).to_long();
    node.children.push_back(compile(e.op(0)));
    const Node& base = nodes_[node.children.front()];
    const unsigned n = static_cast<unsigned>(node.exponent < 0 ? -node.exponent : node.exponent);
    node.numerator_degree = node.denominator_degree = zeros();
    for (std::size_t v = 0; v < degree_slots(); ++v) {
      node.numerator_degree[v] = n * (node.exponent < 0 ? base.denominator_degree[v] : base.numerator_degree[v]);
      node.denominator_degree[v] = n * (node.exponent < 0 ? base.numerator_degree[v] : base.denominator_degree[v]);
    }
    node.denominator_is_one = node.exponent >= 0 ? base.denominator_is_one : false;
    return push(std::move(node));
  }

  Variables& variables_;
  std::vector<Node> nodes_;
  std::vector<Scope> scopes_;
  unsigned chain_rule_in_slot_ = 0;  ///< bit j: a function leaf follows the chain rule under derivative j
  unsigned depth_used_ = 0;
  std::size_t root_ = 0;
};

struct Overflow {};

/// Checked 128-bit arithmetic: the fast path; a point that overflows is redone in cpp_int.
__int128 add(__int128 a, __int128 b) {
  __int128 r;
  if (__builtin_add_overflow(a, b, &r)) throw Overflow{};
  return r;
}
__int128 mul(__int128 a, __int128 b) {
  __int128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw Overflow{};
  return r;
}
Integer add(const Integer& a, const Integer& b) { return a + b; }
Integer mul(const Integer& a, const Integer& b) { return a * b; }

template <class Int>
Int from_integer(const Integer& n) {
  if constexpr (std::is_same_v<Int, Integer>) {
    return n;
  } else {
    if (n > Integer(INT64_MAX) || n < Integer(INT64_MIN)) throw Overflow{};
    return static_cast<__int128>(static_cast<long long>(n));
  }
}

/// A value and its derivatives along the nested steps d/dx: a polynomial in ε_0, ε_1 with ε_j² = 0, coefficient m
/// the one of Π_{j in m} ε_j (hyper-dual numbers). Integer coefficients: exact like the values.
template <class Int>
struct Jet {
  std::array<Int, 1u << max_derivative_depth> c{};
  unsigned size = 1;
};

template <class Int>
Jet<Int> jet(const Int& value, unsigned size) {
  Jet<Int> j;
  j.size = size;
  j.c[0] = value;
  return j;
}
template <class Int>
Jet<Int> add(const Jet<Int>& a, const Jet<Int>& b) {
  Jet<Int> r = a;
  for (unsigned m = 0; m < r.size; ++m) r.c[m] = add(a.c[m], b.c[m]);
  return r;
}
template <class Int>
Jet<Int> negate(const Jet<Int>& a) {
  Jet<Int> r = a;
  for (unsigned m = 0; m < r.size; ++m) r.c[m] = mul(a.c[m], Int(-1));
  return r;
}
/// (a b)_m = Σ_{s ⊆ m} a_s b_{m∖s}.
template <class Int>
Jet<Int> mul(const Jet<Int>& a, const Jet<Int>& b) {
  Jet<Int> r = jet(Int(0), a.size);
  for (unsigned m = 0; m < a.size; ++m)
    for (unsigned s = m;; s = (s - 1) & m) {
      r.c[m] = add(r.c[m], mul(a.c[s], b.c[m ^ s]));
      if (s == 0) break;
    }
  return r;
}
/// ε_j a.
template <class Int>
Jet<Int> shift(const Jet<Int>& a, unsigned j) {
  Jet<Int> r = jet(Int(0), a.size);
  for (unsigned m = 0; m < a.size; ++m)
    if (m & (1u << j)) r.c[m] = a.c[m ^ (1u << j)];
  return r;
}
/// The parts of a without ε_j and at ε_j: a = a0 + ε_j a1.
template <class Int>
std::pair<Jet<Int>, Jet<Int>> split(const Jet<Int>& a, unsigned j) {
  Jet<Int> a0 = jet(Int(0), a.size), a1 = jet(Int(0), a.size);
  for (unsigned m = 0; m < a.size; ++m)
    if (!(m & (1u << j))) a0.c[m] = a.c[m], a1.c[m] = a.c[m | (1u << j)];
  return {a0, a1};
}

/// f(g) as a jet, F and P the grid's values of f(g0) and of its partner (sin for cos, cos for sin, exp for exp):
/// with h = g − g0, h³ = 0 (at most two ε), so cos(g0 + h) = F (1 − h²/2) − P h, sin(g0 + h) = F (1 − h²/2) + P h,
/// exp(g0 + h) = F (1 + h + h²/2), h²/2 = h_{ε0} h_{ε1} ε0 ε1 (the chain rule, to second order).
template <class Int>
Jet<Int> function_of_jet(const Node& node, const Int& F, const Int& P, const Jet<Int>& g) {
  Jet<Int> h = g, half_h2 = jet(Int(0), g.size);
  h.c[0] = Int(0);
  if (g.size == 4) half_h2.c[3] = mul(h.c[1], h.c[2]);
  const Jet<Int> f = jet(F, g.size), p = jet(P, g.size);
  switch (node.function) {
    case Node::Function::cos:
      return add(add(f, negate(mul(f, half_h2))), negate(mul(p, h)));
    case Node::Function::sin:
      return add(add(f, negate(mul(f, half_h2))), mul(p, h));
    case Node::Function::exp:
      break;
  }
  return add(add(f, mul(f, h)), mul(f, half_h2));
}

template <class Int>
struct Fraction {
  Jet<Int> n, d;
};

template <class Int>
Fraction<Int> combine(const Node& node, const std::vector<Node>& nodes, const std::vector<Fraction<Int>>& values) {
  Fraction<Int> value = values[node.children.front()];
  for (std::size_t k = 1; k < node.children.size(); ++k) {
    const Fraction<Int>& c = values[node.children[k]];
    if (node.op == Node::Op::product)
      value = {mul(value.n, c.n), mul(value.d, c.d)};
    else if (nodes[node.children[k]].denominator_is_one)
      value = {add(value.n, mul(c.n, value.d)), value.d};
    else
      value = {add(mul(value.n, c.d), mul(c.n, value.d)), mul(value.d, c.d)};
  }
  return value;
}

/// The fraction (n, d) of the program's root at the integer point `at`, without cancelling.
template <class Int>
Fraction<Int> evaluate(const Program& program, const std::vector<unsigned>& at, std::vector<Fraction<Int>>& values) {
  const std::vector<Node>& nodes = program.nodes();
  const unsigned size = program.jet_size();
  values.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& node = nodes[i];
    Fraction<Int>& value = values[i];
    switch (node.op) {
      case Node::Op::constant:
        value = {jet(from_integer<Int>(node.numerator), size), jet(from_integer<Int>(node.denominator), size)};
        break;
      case Node::Op::variable:
      case Node::Op::bound: {
        value = node.op == Node::Op::bound ? values[node.source]
                                           : Fraction<Int>{jet(Int(at[node.variable]), size), jet(Int(1), size)};
        const Jet<Int> d = value.d;  // x + ε_j: (n + ε_j d)/d
        for (unsigned j = 0; j < max_derivative_depth; ++j)
          if (node.slots & (1u << j)) value.n = add(value.n, shift(d, j));
        break;
      }
      case Node::Op::sum:
      case Node::Op::product:
        value = combine(node, nodes, values);
        break;
      case Node::Op::power: {
        const Fraction<Int>& base = values[node.children.front()];
        Fraction<Int> p{jet(Int(1), size), jet(Int(1), size)};
        for (long k = 0; k < (node.exponent < 0 ? -node.exponent : node.exponent); ++k)
          p = {mul(p.n, base.n), mul(p.d, base.d)};
        value = node.exponent < 0 ? Fraction<Int>{p.d, p.n} : p;
        break;
      }
      case Node::Op::function:
        value = {function_of_jet(node, Int(at[node.variable]), Int(at[node.partner]), values[node.children.front()].n),
                 jet(Int(1), size)};
        break;
      case Node::Op::derivative: {
        const Fraction<Int>& c = values[node.children.front()];
        const auto [n0, n1] = split(c.n, node.slot);
        const auto [d0, d1] = split(c.d, node.slot);
        if (nodes[node.children.front()].denominator_is_one)
          value = {n1, d0};
        else
          value = {add(mul(n1, d0), negate(mul(n0, d1))), mul(d0, d0)};
        break;
      }
    }
  }
  return values[program.root()];
}

/// One entry's pair of programs and the numerator N = n_l d_r − n_r d_l of their difference at a point.
struct EntryCheck {
  Program lhs, rhs;
  bool lhs_denominator_seen_nonzero = false, rhs_denominator_seen_nonzero = false;

  std::vector<Fraction<__int128>> fast_values;
  std::vector<Fraction<Integer>> exact_values;

  bool defined_here = false;  ///< both denominators ≠ 0 at the last point evaluated

  template <class Int>
  Int numerator(const std::vector<unsigned>& at) {
    auto& values = [this]() -> auto& {
      if constexpr (std::is_same_v<Int, Integer>)
        return exact_values;
      else
        return fast_values;
    }
    ();
    // The values proper: the jets' coefficients without ε.
    const Fraction<Int> l = evaluate<Int>(lhs, at, values);
    const Int ln = l.n.c[0], ld = l.d.c[0];
    const Fraction<Int> r = evaluate<Int>(rhs, at, values);
    const Int rn = r.n.c[0], rd = r.d.c[0];
    lhs_denominator_seen_nonzero = lhs_denominator_seen_nonzero || ld != Int(0);
    rhs_denominator_seen_nonzero = rhs_denominator_seen_nonzero || rd != Int(0);
    defined_here = ld != Int(0) && rd != Int(0);
    return add(mul(ln, rd), -mul(rn, ld));
  }
};

std::string int_text(const Integer& n) { return n.str(); }

/// The number of points of S = {a : 0 ≤ a_i ≤ d_i, Σ a_i ≤ T}; throws above `max_points`.
std::uint64_t count_points(const std::vector<unsigned>& bound, unsigned T, std::uint64_t max_points) {
  std::vector<std::uint64_t> ways(T + 1, 0);  // ways[s]: points of the variables so far with Σ a_i = s
  ways[0] = 1;
  for (const unsigned d : bound) {
    std::vector<std::uint64_t> next(T + 1, 0);
    for (unsigned s = 0; s <= T; ++s)
      for (unsigned a = 0; a <= std::min(d, s); ++a) next[s] = std::min(next[s] + ways[s - a], max_points + 1);
    ways = std::move(next);
  }
  std::uint64_t points = 0;
  for (const std::uint64_t w : ways) points = std::min(points + w, max_points + 1);
  if (points > max_points)
    throw std::invalid_argument("grid check: more than " + std::to_string(max_points) + " grid points");
  return points;
}

/// The next point of S after `at` (an odometer that carries when a coordinate passes d_i or the sum passes T; S
/// being closed downwards, it visits every point of S once). False after the last.
bool next_point(std::vector<unsigned>& at, unsigned& sum, const std::vector<unsigned>& bound, unsigned T) {
  for (std::size_t v = 0; v < at.size(); ++v) {
    ++at[v], ++sum;
    if (at[v] <= bound[v] && sum <= T) return true;
    sum -= at[v];
    at[v] = 0;
  }
  return false;
}

}  // namespace

GridVerdict grid_check(const GiNaC::ex& lhs, const GiNaC::ex& rhs, std::uint64_t max_points) {
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> entries;
  if (GiNaC::is_a<GiNaC::matrix>(lhs) || GiNaC::is_a<GiNaC::matrix>(rhs)) {
    if (!GiNaC::is_a<GiNaC::matrix>(lhs) || !GiNaC::is_a<GiNaC::matrix>(rhs) || lhs.nops() != rhs.nops())
      throw std::invalid_argument("grid check: sides of different shapes");
    for (std::size_t i = 0; i < lhs.nops(); ++i) entries.emplace_back(lhs.op(i), rhs.op(i));
  } else {
    entries.emplace_back(lhs, rhs);
  }
  Variables discovered(max_variables);
  for (const auto& [l, r] : entries) Program(l, discovered), Program(r, discovered);
  std::vector<std::string> names = discovered.names();
  std::sort(names.begin(), names.end());
  Variables variables(names);
  std::vector<EntryCheck> checks;
  for (const auto& [l, r] : entries)
    checks.push_back({Program(l, variables), Program(r, variables), {}, {}, {}, {}, {}});

  // d_i: the bound of N's degree in x_i, and T of its total degree, the largest over the entries.
  std::vector<unsigned> bound(variables.size() + 1, 0);
  for (const EntryCheck& c : checks) {
    const Node &l = c.lhs.nodes()[c.lhs.root()], &r = c.rhs.nodes()[c.rhs.root()];
    for (std::size_t v = 0; v <= variables.size(); ++v)
      bound[v] = std::max(
          {bound[v], l.numerator_degree[v] + r.denominator_degree[v], r.numerator_degree[v] + l.denominator_degree[v]});
  }
  const unsigned T = bound.back();
  bound.pop_back();
  GridVerdict verdict;
  verdict.total_degree = T;
  for (std::size_t v = 0; v < variables.size(); ++v) verdict.degree_bounds.emplace_back(variables.names()[v], bound[v]);
  verdict.grid_points = count_points(bound, T, max_points);

  // A point where N ≠ 0 and both sides are defined is a point where they differ: the identity fails. N vanishing
  // on the whole grid with neither denominator the zero polynomial proves it.
  bool nonzero_somewhere = false;
  std::vector<unsigned> at(variables.size(), 0);
  unsigned sum = 0;
  do {
    ++verdict.evaluated;
    for (EntryCheck& c : checks) {
      Integer N;
      try {
        N = Integer(c.numerator<__int128>(at) != 0 ? 1 : 0);
        if (N != 0) N = c.numerator<Integer>(at);  // the exact value, for the record
      } catch (const Overflow&) {
        N = c.numerator<Integer>(at);
      }
      nonzero_somewhere = nonzero_somewhere || N != 0;
      if (N != 0 && c.defined_here) {
        for (std::size_t v = 0; v < variables.size(); ++v) verdict.witness[variables.names()[v]] = at[v];
        verdict.witness_value = int_text(N);
        return verdict;
      }
    }
  } while (next_point(at, sum, bound, T));
  for (const EntryCheck& c : checks)
    if (!c.lhs_denominator_seen_nonzero || !c.rhs_denominator_seen_nonzero)
      throw std::invalid_argument("grid check: a denominator is the zero polynomial");
  if (nonzero_somewhere)
    throw std::invalid_argument("grid check: the sides differ only where one is undefined on this grid");
  verdict.zero = true;
  return verdict;
}

std::string to_text(const GridVerdict& verdict) {
  std::ostringstream out;
  out << "# exact-grid: lhs - rhs as one fraction N/D without cancelling, its steps performed; N evaluated exactly\n"
      << "# on S = {a : 0 <= a_i <= d_i, sum a_i <= T}, d_i and T structural bounds of deg_i N and of its total\n"
      << "# degree (a polynomial with its monomials in S vanishing on S is zero: Alon, Combinatorial\n"
      << "# Nullstellensatz, Lemma 2.1, for the box; exact_grid.hpp for S).\n";
  for (const auto& [name, d] : verdict.degree_bounds) out << "d(" << name << ") = " << d << "\n";
  out << "T = " << verdict.total_degree << "\n";
  out << "grid points: " << verdict.grid_points << "\n";
  out << "evaluated: " << verdict.evaluated << "\n";
  if (verdict.zero) {
    out << "result: zero\n";
  } else {
    out << "result: non-zero\nat:";
    for (const auto& [name, d] : verdict.degree_bounds) out << " " << name << " = " << verdict.witness.at(name);
    out << "\nN = " << verdict.witness_value << "\n";
  }
  return out.str();
}

}  // namespace affinterp::proofs
