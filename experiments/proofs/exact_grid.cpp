#include "experiments/proofs/exact_grid.hpp"

#include "experiments/proofs/ginac_polynomial.hpp"
#include "theory/exact/rational.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {
namespace {

using exact::Integer;

/// An expression tree compiled to a postfix program over the fraction pairs (n, d), with a structural bound of
/// the degree of n and of d in each variable.
struct Node {
  enum class Op { constant, variable, sum, product, power } op = Op::constant;
  std::vector<std::size_t> children;       ///< earlier nodes
  long exponent = 0;                       ///< power
  Integer numerator = 0, denominator = 1;  ///< constant
  std::size_t variable = 0;                ///< variable
  std::vector<unsigned> numerator_degree, denominator_degree;
  bool denominator_is_one = true;  ///< structurally: d is the constant 1
};

/// Symbols and functions (read as variables), indexed in the order they are first asked for.
class Variables {
 public:
  std::size_t index(const GiNaC::ex& e) {
    const auto [at, added] = index_.emplace(e, names_.size());
    if (added) {
      std::ostringstream name;
      name << e;
      names_.push_back(name.str());
    }
    return at->second;
  }
  std::size_t size() const { return names_.size(); }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index_;
  std::vector<std::string> names_;
};

/// The symbols and functions of `e`, by name.
void collect(const GiNaC::ex& e, std::map<std::string, GiNaC::ex>& found) {
  if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::function>(e)) {
    std::ostringstream name;
    name << e;
    found.emplace(name.str(), e);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i), found);
}

Integer to_integer(const GiNaC::numeric& n) {
  std::ostringstream text;
  text << n;
  return Integer(text.str());
}

class Program {
 public:
  Program(const GiNaC::ex& e, Variables& variables) : variables_(variables) { root_ = compile(e); }
  const std::vector<Node>& nodes() const { return nodes_; }
  std::size_t root() const { return root_; }

 private:
  std::size_t push(Node node) {
    nodes_.push_back(std::move(node));
    return nodes_.size() - 1;
  }
  std::vector<unsigned> zeros() const { return std::vector<unsigned>(variables_.size(), 0); }

  std::size_t compile(const GiNaC::ex& e) {
    Node node;
    node.numerator_degree = node.denominator_degree = zeros();
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      if (!n.is_rational()) throw std::invalid_argument("grid check: not a rational number: " + text_of(e));
      node.numerator = to_integer(n.numer());
      node.denominator = to_integer(n.denom());
      node.denominator_is_one = node.denominator == 1;
      return push(std::move(node));
    }
    if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::function>(e)) {
      node.op = Node::Op::variable;
      node.variable = variables_.index(e);
      node.numerator_degree[node.variable] = 1;
      return push(std::move(node));
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      const bool sum = GiNaC::is_a<GiNaC::add>(e);
      node.op = sum ? Node::Op::sum : Node::Op::product;
      for (std::size_t i = 0; i < e.nops(); ++i) node.children.push_back(compile(e.op(i)));
      // Degrees follow the evaluation below: (n1 d2 + n2 d1) / (d1 d2) for a sum, (n1 n2) / (d1 d2) for a product.
      const Node& first = nodes_[node.children.front()];
      node.numerator_degree = first.numerator_degree;
      node.denominator_degree = first.denominator_degree;
      node.denominator_is_one = first.denominator_is_one;
      for (std::size_t k = 1; k < node.children.size(); ++k) {
        const Node& c = nodes_[node.children[k]];
        for (std::size_t v = 0; v < variables_.size(); ++v) {
          if (sum)
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
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const GiNaC::ex exponent = e.op(1);
      if (!GiNaC::is_a<GiNaC::numeric>(exponent) || !GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer())
        throw std::invalid_argument("grid check: not an integer power: " + text_of(e));
      node.op = Node::Op::power;
      node.exponent = GiNaC::ex_to<GiNaC::numeric>(exponent).to_long();
      node.children.push_back(compile(e.op(0)));
      const Node& base = nodes_[node.children.front()];
      const unsigned n = static_cast<unsigned>(node.exponent < 0 ? -node.exponent : node.exponent);
      for (std::size_t v = 0; v < variables_.size(); ++v) {
        node.numerator_degree[v] = n * (node.exponent < 0 ? base.denominator_degree[v] : base.numerator_degree[v]);
        node.denominator_degree[v] = n * (node.exponent < 0 ? base.numerator_degree[v] : base.denominator_degree[v]);
      }
      node.denominator_is_one = node.exponent >= 0 ? base.denominator_is_one : false;
      return push(std::move(node));
    }
    throw std::invalid_argument("grid check: not a rational expression: " + text_of(e));
  }

  Variables& variables_;
  std::vector<Node> nodes_;
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

template <class Int>
struct Fraction {
  Int n, d;
};

/// The fraction (n, d) of the program's root at the integer point `at`, without cancelling.
template <class Int>
Fraction<Int> evaluate(const Program& program, const std::vector<unsigned>& at, std::vector<Fraction<Int>>& values) {
  const std::vector<Node>& nodes = program.nodes();
  values.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& node = nodes[i];
    Fraction<Int>& value = values[i];
    switch (node.op) {
      case Node::Op::constant:
        value = {from_integer<Int>(node.numerator), from_integer<Int>(node.denominator)};
        break;
      case Node::Op::variable:
        value = {Int(at[node.variable]), Int(1)};
        break;
      case Node::Op::sum:
      case Node::Op::product: {
        value = values[node.children.front()];
        for (std::size_t k = 1; k < node.children.size(); ++k) {
          const Fraction<Int>& c = values[node.children[k]];
          if (node.op == Node::Op::product)
            value = {mul(value.n, c.n), mul(value.d, c.d)};
          else if (nodes[node.children[k]].denominator_is_one)
            value = {add(value.n, mul(c.n, value.d)), value.d};
          else
            value = {add(mul(value.n, c.d), mul(c.n, value.d)), mul(value.d, c.d)};
        }
        break;
      }
      case Node::Op::power: {
        const Fraction<Int>& base = values[node.children.front()];
        Fraction<Int> p{Int(1), Int(1)};
        for (long k = 0; k < (node.exponent < 0 ? -node.exponent : node.exponent); ++k)
          p = {mul(p.n, base.n), mul(p.d, base.d)};
        value = node.exponent < 0 ? Fraction<Int>{p.d, p.n} : p;
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
    const Fraction<Int> l = evaluate<Int>(lhs, at, values), r = evaluate<Int>(rhs, at, values);
    lhs_denominator_seen_nonzero = lhs_denominator_seen_nonzero || l.d != Int(0);
    rhs_denominator_seen_nonzero = rhs_denominator_seen_nonzero || r.d != Int(0);
    defined_here = l.d != Int(0) && r.d != Int(0);
    return add(mul(l.n, r.d), -mul(r.n, l.d));
  }
};

std::string int_text(const Integer& n) { return n.str(); }

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
  std::map<std::string, GiNaC::ex> found;  // by name, so that the grid's variables come in alphabetical order
  for (const auto& [l, r] : entries) collect(l, found), collect(r, found);
  Variables variables;
  for (const auto& [name, e] : found) variables.index(e);
  std::vector<EntryCheck> checks;
  for (const auto& [l, r] : entries)
    checks.push_back({Program(l, variables), Program(r, variables), {}, {}, {}, {}, {}});

  // d_i: the bound of N's degree, the largest over the entries.
  std::vector<unsigned> bound(variables.size(), 0);
  for (const EntryCheck& c : checks) {
    const Node &l = c.lhs.nodes()[c.lhs.root()], &r = c.rhs.nodes()[c.rhs.root()];
    for (std::size_t v = 0; v < variables.size(); ++v)
      bound[v] = std::max(
          {bound[v], l.numerator_degree[v] + r.denominator_degree[v], r.numerator_degree[v] + l.denominator_degree[v]});
  }
  GridVerdict verdict;
  verdict.grid_points = 1;
  for (std::size_t v = 0; v < variables.size(); ++v) {
    verdict.degree_bounds.emplace_back(variables.names()[v], bound[v]);
    verdict.grid_points *= bound[v] + 1;
    if (verdict.grid_points > max_points)
      throw std::invalid_argument("grid check: more than " + std::to_string(max_points) + " grid points");
  }

  // A point where N ≠ 0 and both sides are defined is a point where they differ: the identity fails. N vanishing
  // on the whole grid with neither denominator the zero polynomial proves it.
  bool nonzero_somewhere = false;
  std::vector<unsigned> at(variables.size(), 0);
  for (std::uint64_t k = 0; k < verdict.grid_points; ++k) {
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
    for (std::size_t v = 0; v < at.size() && ++at[v] > bound[v]; ++v) at[v] = 0;  // next point
  }
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
  out << "# exact-grid: lhs - rhs as one fraction N/D without cancelling; N evaluated exactly on the grid\n"
      << "# prod_i {0..d_i}, d_i a structural bound of deg_i N (Alon, Combinatorial Nullstellensatz, Lemma 2.1:\n"
      << "# a polynomial of degree <= d_i in each x_i vanishing on such a grid is zero).\n";
  for (const auto& [name, d] : verdict.degree_bounds) out << "d(" << name << ") = " << d << "\n";
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
