#include "experiments/proofs/step_nodes.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::proofs {
namespace nodes {

// No eval_func: GiNaC keeps each call as it is written. Each prints as the ginsh command that performs the step.
DECLARE_FUNCTION_2P(step_derivative)
DECLARE_FUNCTION_3P(step_substitution)
DECLARE_FUNCTION_1P(step_determinant)
DECLARE_FUNCTION_1P(step_transpose)
DECLARE_FUNCTION_2P(step_product)
DECLARE_FUNCTION_2P(step_entry)
// Reading only: {{a, b}, {c, d}}, the translation of ginsh's [[a,b],[c,d]], evaluates to the matrix.
DECLARE_FUNCTION_1P(matrix_from_rows)

/// Writes name(arguments…) with the separators given: ginsh's syntax for each step.
void print_call(const GiNaC::print_context& c, const char* open, std::initializer_list<const GiNaC::ex*> arguments,
                std::initializer_list<const char*> separators) {
  c.s << open;
  auto separator = separators.begin();
  for (const GiNaC::ex* argument : arguments) {
    argument->print(c);
    c.s << *separator++;
  }
}
void print_derivative(const GiNaC::ex& e, const GiNaC::ex& x, const GiNaC::print_context& c) {
  print_call(c, "diff(", {&e, &x}, {",", ")"});
}
/// x and v are the one-element lists {x}, {v}: ginsh's subs(e,{x},{v}), which GiNaC's parser reads.
void print_substitution(const GiNaC::ex& e, const GiNaC::ex& x, const GiNaC::ex& v, const GiNaC::print_context& c) {
  print_call(c, "subs(", {&e, &x, &v}, {",", ",", ")"});
}
void print_determinant(const GiNaC::ex& M, const GiNaC::print_context& c) {
  print_call(c, "determinant(", {&M}, {")"});
}
void print_transpose(const GiNaC::ex& M, const GiNaC::print_context& c) { print_call(c, "transpose(", {&M}, {")"}); }
void print_product(const GiNaC::ex& A, const GiNaC::ex& B, const GiNaC::print_context& c) {
  print_call(c, "evalm(", {&A, &B}, {"*", ")"});
}
void print_entry(const GiNaC::ex& M, const GiNaC::ex& k, const GiNaC::print_context& c) {
  print_call(c, "op(", {&M, &k}, {",", ")"});
}

// A function takes its first argument's return type unless told: the scalar-valued steps are commutative
// (an entry of a matrix, a determinant), the matrix-valued ones (transpose, product) keep the matrix's.
constexpr unsigned scalar = GiNaC::return_types::commutative;
REGISTER_FUNCTION(step_derivative, print_func<GiNaC::print_context>(print_derivative).set_return_type(scalar))
REGISTER_FUNCTION(step_substitution, print_func<GiNaC::print_context>(print_substitution).set_return_type(scalar))
REGISTER_FUNCTION(step_determinant, print_func<GiNaC::print_context>(print_determinant).set_return_type(scalar))
REGISTER_FUNCTION(step_transpose, print_func<GiNaC::print_context>(print_transpose))
REGISTER_FUNCTION(step_product, print_func<GiNaC::print_context>(print_product))
REGISTER_FUNCTION(step_entry, print_func<GiNaC::print_context>(print_entry).set_return_type(scalar))

GiNaC::ex rows_to_matrix(const GiNaC::ex& rows) {
  if (!GiNaC::is_a<GiNaC::lst>(rows) || rows.nops() == 0 || !GiNaC::is_a<GiNaC::lst>(rows.op(0)))
    throw std::invalid_argument("matrix: expected [[…],…]");
  const std::size_t columns = rows.op(0).nops();
  GiNaC::matrix M(static_cast<unsigned>(rows.nops()), static_cast<unsigned>(columns));
  for (unsigned i = 0; i < rows.nops(); ++i) {
    if (!GiNaC::is_a<GiNaC::lst>(rows.op(i)) || rows.op(i).nops() != columns)
      throw std::invalid_argument("matrix: rows of different lengths");
    for (unsigned j = 0; j < columns; ++j) M(i, j) = rows.op(i).op(j);
  }
  return M;
}
REGISTER_FUNCTION(matrix_from_rows, eval_func(rows_to_matrix))

}  // namespace nodes
namespace {

bool is_step(const GiNaC::ex& e, unsigned serial) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() == serial;
}

GiNaC::matrix as_matrix(const GiNaC::ex& e, const char* step) {
  if (!GiNaC::is_a<GiNaC::matrix>(e)) throw std::invalid_argument(std::string(step) + " of a scalar");
  return GiNaC::ex_to<GiNaC::matrix>(e);
}

unsigned index_of(const GiNaC::ex& k) {
  if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_nonneg_integer())
    throw std::invalid_argument("entry: the index is not a natural number");
  return static_cast<unsigned>(GiNaC::ex_to<GiNaC::numeric>(k).to_int());
}

struct Perform : GiNaC::map_function {
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    switch (step_of(e)) {
      case Step::none:
        return e.map(*this);
      case Step::derivative:
        return (*this)(e.op(0)).diff(GiNaC::ex_to<GiNaC::symbol>(e.op(1)));
      case Step::substitution:
        return (*this)(e.op(0)).subs(e.op(1).op(0) == (*this)(e.op(2).op(0)));
      case Step::determinant:
        return as_matrix((*this)(e.op(0)), "determinant").determinant();
      case Step::transpose:
        return as_matrix((*this)(e.op(0)), "transpose").transpose();
      case Step::product:
        return as_matrix((*this)(e.op(0)), "product").mul(as_matrix((*this)(e.op(1)), "product"));
      case Step::entry: {
        const GiNaC::matrix M = as_matrix((*this)(e.op(0)), "entry");
        const unsigned k = index_of(e.op(1));
        if (k >= M.nops()) throw std::invalid_argument("entry: index out of range");
        return M.op(k);
      }
    }
    return e;
  }
};

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The position of the bracket closing the one at `open` (any of ( [ {).
std::size_t closing(const std::string& s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    depth += (s[i] == '(' || s[i] == '[' || s[i] == '{') - (s[i] == ')' || s[i] == ']' || s[i] == '}');
    if (depth == 0) return i;
  }
  throw std::invalid_argument("unbalanced brackets in " + s);
}

/// ginsh's syntax that GiNaC's parser lacks, in the readers' terms: a matrix [[a,b],[c,d]] becomes
/// matrix_from_rows({{a,b},{c,d}}) and evalm(A*B) becomes step_product_(A,B).
std::string translate(const std::string& s) {
  std::string out;
  std::vector<char> open;  // 'M' a matrix, 'R' its row, '(' or '{'
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (s.compare(i, 6, "evalm(") == 0 && (i == 0 || !identifier_char(s[i - 1]))) {
      const std::size_t end = closing(s, i + 5);
      const std::string inner = s.substr(i + 6, end - i - 6);
      std::size_t star = std::string::npos;
      for (std::size_t k = 0, depth = 0; k < inner.size(); ++k) {
        depth += (inner[k] == '(' || inner[k] == '[' || inner[k] == '{');
        depth -= (inner[k] == ')' || inner[k] == ']' || inner[k] == '}');
        if (depth == 0 && inner[k] == '*') {
          if (star != std::string::npos) throw std::invalid_argument("evalm: expected evalm(A*B)");
          star = k;
        }
      }
      if (star == std::string::npos) throw std::invalid_argument("evalm: expected evalm(A*B)");
      out += "step_product_(" + translate(inner.substr(0, star)) + "," + translate(inner.substr(star + 1)) + ")";
      i = end;
    } else if (c == '[') {
      const bool row = !open.empty() && open.back() == 'M';
      open.push_back(row ? 'R' : 'M');
      out += row ? "{" : "matrix_from_rows({";
    } else if (c == ']') {
      if (open.empty() || (open.back() != 'M' && open.back() != 'R')) throw std::invalid_argument("unbalanced ]");
      out += open.back() == 'M' ? "})" : "}";
      open.pop_back();
    } else {
      if (c == '(' || c == '{') open.push_back(c);
      if ((c == ')' || c == '}') && !open.empty()) open.pop_back();
      out += c;
    }
  }
  return out;
}

/// A GiNaC function in the parser's table: its serial number, shifted and marked odd, in place of a reader
/// (GiNaC's parser/parser.cpp, decode_serial).
GiNaC::reader_func serial_reader(unsigned serial) {
  return reinterpret_cast<GiNaC::reader_func>((static_cast<std::uintptr_t>(serial) << 1) | 1);
}

const GiNaC::prototype_table& readers() {
  static const GiNaC::prototype_table table = [] {
    GiNaC::prototype_table t = GiNaC::get_default_reader();
    t[{"diff", 2}] = serial_reader(nodes::step_derivative_SERIAL::serial);
    t[{"subs", 3}] = serial_reader(nodes::step_substitution_SERIAL::serial);
    t[{"determinant", 1}] = serial_reader(nodes::step_determinant_SERIAL::serial);
    t[{"transpose", 1}] = serial_reader(nodes::step_transpose_SERIAL::serial);
    t[{"op", 2}] = serial_reader(nodes::step_entry_SERIAL::serial);
    t[{"step_product_", 2}] = serial_reader(nodes::step_product_SERIAL::serial);
    t[{"matrix_from_rows", 1}] = serial_reader(nodes::matrix_from_rows_SERIAL::serial);
    return t;
  }();
  return table;
}

}  // namespace

GiNaC::ex derivative(const GiNaC::ex& e, const GiNaC::symbol& x, unsigned n) {
  GiNaC::ex d = e;
  for (unsigned k = 0; k < n; ++k) d = nodes::step_derivative(d, x);
  return d;
}

GiNaC::ex substitution(const GiNaC::ex& e, const GiNaC::symbol& x, const GiNaC::ex& v) {
  return nodes::step_substitution(e, GiNaC::lst{x}, GiNaC::lst{v});
}

GiNaC::ex substitution(const GiNaC::ex& e, const GiNaC::exmap& values) {
  std::vector<std::pair<std::string, std::pair<GiNaC::symbol, GiNaC::ex>>> by_name;
  for (const auto& [x, v] : values) {
    if (!GiNaC::is_a<GiNaC::symbol>(x)) throw std::invalid_argument("substitution: not a symbol");
    const GiNaC::symbol& symbol = GiNaC::ex_to<GiNaC::symbol>(x);
    by_name.push_back({symbol.get_name(), {symbol, v}});
  }
  std::ranges::sort(by_name, {}, [](const auto& entry) { return entry.first; });
  GiNaC::ex s = e;
  for (const auto& [name, substituted] : by_name) s = substitution(s, substituted.first, substituted.second);
  return s;
}

GiNaC::ex determinant_of(const GiNaC::ex& M) { return nodes::step_determinant(M); }
GiNaC::ex transposed(const GiNaC::ex& M) { return nodes::step_transpose(M); }
GiNaC::ex product(const GiNaC::ex& A, const GiNaC::ex& B) { return nodes::step_product(A, B); }

GiNaC::ex product(const std::vector<GiNaC::ex>& factors) {
  if (factors.empty()) throw std::invalid_argument("product of no matrices");
  GiNaC::ex p = factors.front();
  for (std::size_t k = 1; k < factors.size(); ++k) p = product(p, factors[k]);
  return p;
}

GiNaC::ex entry(const GiNaC::ex& M, unsigned k) { return nodes::step_entry(M, k); }

Step step_of(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::function>(e)) return Step::none;
  if (is_step(e, nodes::step_derivative_SERIAL::serial)) return Step::derivative;
  if (is_step(e, nodes::step_substitution_SERIAL::serial)) return Step::substitution;
  if (is_step(e, nodes::step_determinant_SERIAL::serial)) return Step::determinant;
  if (is_step(e, nodes::step_transpose_SERIAL::serial)) return Step::transpose;
  if (is_step(e, nodes::step_product_SERIAL::serial)) return Step::product;
  if (is_step(e, nodes::step_entry_SERIAL::serial)) return Step::entry;
  return Step::none;
}

std::pair<unsigned, unsigned> shape(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(e);
    return {M.rows(), M.cols()};
  }
  switch (step_of(e)) {
    case Step::transpose: {
      const auto [r, c] = shape(e.op(0));
      return {c, r};
    }
    case Step::product: {
      const auto [r, inner] = shape(e.op(0));
      const auto [inner2, c] = shape(e.op(1));
      if (inner != inner2 || r == 0 || c == 0) throw std::invalid_argument("product of matrices that do not fit");
      return {r, c};
    }
    default:
      return {0, 0};
  }
}

GiNaC::ex perform_steps(const GiNaC::ex& e) {
  Perform perform;
  return perform(e);
}

bool has_steps(const GiNaC::ex& e) {
  if (step_of(e) != Step::none) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_steps(e.op(i))) return true;
  return false;
}

GiNaC::ex read_script_expression(const std::string& text, const GiNaC::symtab& symbols) {
  GiNaC::parser read(symbols, /*strict=*/true, readers());
  return read(translate(text));
}

}  // namespace affinterp::proofs
