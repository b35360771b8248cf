#include "theory/logic/formula.hpp"

#include <cctype>
#include <map>
#include <stdexcept>

namespace affinterp::logic {

Relation negated(Relation r) {
  switch (r) {
    case Relation::less:
      return Relation::greater_equal;
    case Relation::less_equal:
      return Relation::greater;
    case Relation::greater:
      return Relation::less_equal;
    case Relation::greater_equal:
      return Relation::less;
    case Relation::equal:
      return Relation::not_equal;
    case Relation::not_equal:
      return Relation::equal;
  }
  throw std::logic_error("unknown relation");
}

bool compare(const Rational& value, Relation r) {
  switch (r) {
    case Relation::less:
      return value < 0;
    case Relation::less_equal:
      return value <= 0;
    case Relation::greater:
      return value > 0;
    case Relation::greater_equal:
      return value >= 0;
    case Relation::equal:
      return value == 0;
    case Relation::not_equal:
      return value != 0;
  }
  throw std::logic_error("unknown relation");
}

std::string_view symbol(Relation r) {
  switch (r) {
    case Relation::less:
      return "<";
    case Relation::less_equal:
      return "<=";
    case Relation::greater:
      return ">";
    case Relation::greater_equal:
      return ">=";
    case Relation::equal:
      return "=";
    case Relation::not_equal:
      return "!=";
  }
  throw std::logic_error("unknown relation");
}

Formula truth(bool value) {
  Formula f;
  f.value = value;
  return f;
}

Formula atom(const Polynomial& p, Relation r) {
  Formula f;
  f.kind = Formula::Kind::atom;
  f.polynomial = p;
  f.relation = r;
  return f;
}

Formula conjunction(std::vector<Formula> parts) {
  if (parts.empty()) return truth(true);
  if (parts.size() == 1) return std::move(parts.front());
  Formula f;
  f.kind = Formula::Kind::conjunction;
  f.parts = std::move(parts);
  return f;
}

Formula disjunction(std::vector<Formula> parts) {
  if (parts.empty()) return truth(false);
  if (parts.size() == 1) return std::move(parts.front());
  Formula f;
  f.kind = Formula::Kind::disjunction;
  f.parts = std::move(parts);
  return f;
}

Formula negation(Formula g) {
  Formula f;
  f.kind = Formula::Kind::negation;
  f.parts.push_back(std::move(g));
  return f;
}

namespace {

Formula quantified(Formula::Kind kind, std::vector<std::string> variables, Formula g) {
  if (variables.empty()) return g;
  Formula f;
  f.kind = kind;
  f.bound = std::move(variables);
  f.parts.push_back(std::move(g));
  return f;
}

}  // namespace

Formula exists(std::vector<std::string> variables, Formula f) {
  return quantified(Formula::Kind::exists, std::move(variables), std::move(f));
}
Formula forall(std::vector<std::string> variables, Formula f) {
  return quantified(Formula::Kind::forall, std::move(variables), std::move(f));
}

Formula less(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::less); }
Formula less_equal(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::less_equal); }
Formula greater(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::greater); }
Formula greater_equal(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::greater_equal); }
Formula equal(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::equal); }
Formula not_equal(const Polynomial& a, const Polynomial& b) { return atom(a - b, Relation::not_equal); }

bool holds(const Formula& f, const Point& at) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
      return f.value;
    case K::atom:
      return compare(f.polynomial.evaluate(at), f.relation);
    case K::conjunction:
      for (const Formula& g : f.parts)
        if (!holds(g, at)) return false;
      return true;
    case K::disjunction:
      for (const Formula& g : f.parts)
        if (holds(g, at)) return true;
      return false;
    case K::negation:
      return !holds(f.parts.front(), at);
    case K::exists:
    case K::forall:
      throw std::invalid_argument("holds(): the formula has a quantifier");
  }
  throw std::logic_error("unknown formula kind");
}

namespace {

void collect_free(const Formula& f, std::set<std::string> bound, std::set<std::string>& out) {
  using K = Formula::Kind;
  if (f.kind == K::atom) {
    for (const std::string& v : f.polynomial.variables())
      if (!bound.contains(v)) out.insert(v);
    return;
  }
  if (f.kind == K::exists || f.kind == K::forall) bound.insert(f.bound.begin(), f.bound.end());
  for (const Formula& g : f.parts) collect_free(g, bound, out);
}

void collect_all_names(const Formula& f, std::set<std::string>& out) {
  if (f.kind == Formula::Kind::atom) {
    const std::set<std::string> vs = f.polynomial.variables();
    out.insert(vs.begin(), vs.end());
  }
  out.insert(f.bound.begin(), f.bound.end());
  for (const Formula& g : f.parts) collect_all_names(g, out);
}

}  // namespace

std::set<std::string> free_variables(const Formula& f) {
  std::set<std::string> out;
  collect_free(f, {}, out);
  return out;
}

Formula substitute(const Formula& f, const std::string& name, const Polynomial& by) {
  Formula g = f;
  if (g.kind == Formula::Kind::atom) g.polynomial = g.polynomial.substitute(name, by);
  for (Formula& part : g.parts) part = substitute(part, name, by);
  return g;
}

bool is_quantifier_free(const Formula& f) {
  if (f.kind == Formula::Kind::exists || f.kind == Formula::Kind::forall) return false;
  for (const Formula& g : f.parts)
    if (!is_quantifier_free(g)) return false;
  return true;
}

Formula simplify_constants(const Formula& f) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
      return f;
    case K::atom:
      return f.polynomial.is_constant() ? truth(compare(f.polynomial.constant_term(), f.relation)) : f;
    case K::negation: {
      Formula g = simplify_constants(f.parts.front());
      return g.kind == K::constant ? truth(!g.value) : negation(std::move(g));
    }
    case K::conjunction:
    case K::disjunction: {
      const bool is_and = f.kind == K::conjunction;
      std::vector<Formula> parts;
      for (const Formula& part : f.parts) {
        Formula g = simplify_constants(part);
        if (g.kind == K::constant) {
          if (g.value != is_and) return g;  // false in a conjunction, true in a disjunction
          continue;
        }
        if (g.kind == f.kind)
          parts.insert(parts.end(), g.parts.begin(), g.parts.end());
        else
          parts.push_back(std::move(g));
      }
      return is_and ? conjunction(std::move(parts)) : disjunction(std::move(parts));
    }
    case K::exists:
    case K::forall: {
      Formula g = simplify_constants(f.parts.front());
      return g.kind == K::constant ? g : quantified(f.kind, f.bound, std::move(g));
    }
  }
  throw std::logic_error("unknown formula kind");
}

namespace {

Formula nnf(const Formula& f, bool negate) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
      return truth(f.value != negate);
    case K::atom:
      return negate ? atom(f.polynomial, negated(f.relation)) : f;
    case K::negation:
      return nnf(f.parts.front(), !negate);
    case K::conjunction:
    case K::disjunction: {
      std::vector<Formula> parts;
      for (const Formula& g : f.parts) parts.push_back(nnf(g, negate));
      return (f.kind == K::conjunction) != negate ? conjunction(std::move(parts)) : disjunction(std::move(parts));
    }
    case K::exists:
    case K::forall: {
      const K kind = negate ? (f.kind == K::exists ? K::forall : K::exists) : f.kind;
      return quantified(kind, f.bound, nnf(f.parts.front(), negate));
    }
  }
  throw std::logic_error("unknown formula kind");
}

/// Fresh names: the name itself the first time, then name1, name2, … (digits of the name dropped first).
class FreshNames {
 public:
  explicit FreshNames(std::set<std::string> taken) : taken_(std::move(taken)) {}
  std::string operator()(const std::string& name) {
    if (taken_.insert(name).second) return name;
    std::string stem = name;
    while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) stem.pop_back();
    if (stem.empty()) stem = "q";
    for (int i = 1;; ++i)
      if (std::string candidate = stem + std::to_string(i); taken_.insert(candidate).second) return candidate;
  }

 private:
  std::set<std::string> taken_;
};

Formula rename(const Formula& f, FreshNames& fresh, const std::map<std::string, std::string>& names) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
      return f;
    case K::atom:
      return atom(f.polynomial.rename(names), f.relation);
    case K::exists:
    case K::forall: {
      std::map<std::string, std::string> inner = names;
      std::vector<std::string> bound;
      for (const std::string& v : f.bound) bound.push_back(inner[v] = fresh(v));
      return quantified(f.kind, std::move(bound), rename(f.parts.front(), fresh, inner));
    }
    default: {
      Formula g = f;
      for (Formula& part : g.parts) part = rename(part, fresh, names);
      return g;
    }
  }
}

}  // namespace

Formula negation_normal_form(const Formula& f) { return nnf(f, false); }

Formula rename_apart(const Formula& f, const std::set<std::string>& taken) {
  std::set<std::string> avoid = taken;
  const std::set<std::string> free = free_variables(f);
  avoid.insert(free.begin(), free.end());
  FreshNames fresh(std::move(avoid));
  return rename(f, fresh, {});
}

bool Prenex::existential() const {
  for (const QuantifierBlock& b : prefix)
    if (b.universal) return false;
  return true;
}

std::vector<std::string> Prenex::bound_variables() const {
  std::vector<std::string> out;
  for (const QuantifierBlock& b : prefix) out.insert(out.end(), b.variables.begin(), b.variables.end());
  return out;
}

namespace {

void append_block(std::vector<QuantifierBlock>& prefix, bool universal, const std::vector<std::string>& vars) {
  if (!prefix.empty() && prefix.back().universal == universal)
    prefix.back().variables.insert(prefix.back().variables.end(), vars.begin(), vars.end());
  else
    prefix.push_back({universal, vars});
}

/// Interleaves the parts' prefixes, each kept in its own order, taking every leading block of the current
/// kind from all parts before switching kind; starts with ∃.
std::vector<QuantifierBlock> merge_prefixes(std::vector<std::vector<QuantifierBlock>> prefixes) {
  std::vector<QuantifierBlock> out;
  std::vector<std::size_t> next(prefixes.size(), 0);
  const auto remaining = [&] {
    for (std::size_t i = 0; i < prefixes.size(); ++i)
      if (next[i] < prefixes[i].size()) return true;
    return false;
  };
  bool universal = false;
  while (remaining()) {
    for (std::size_t i = 0; i < prefixes.size(); ++i)
      while (next[i] < prefixes[i].size() && prefixes[i][next[i]].universal == universal)
        append_block(out, universal, prefixes[i][next[i]++].variables);
    universal = !universal;
  }
  return out;
}

/// Pulls the quantifiers of a renamed-apart formula in negation normal form out.
Prenex pull_out(const Formula& f) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
    case K::atom:
      return {{}, f};
    case K::exists:
    case K::forall: {
      Prenex inner = pull_out(f.parts.front());
      std::vector<QuantifierBlock> prefix;
      append_block(prefix, f.kind == K::forall, f.bound);
      for (const QuantifierBlock& b : inner.prefix) append_block(prefix, b.universal, b.variables);
      return {std::move(prefix), std::move(inner.matrix)};
    }
    case K::conjunction:
    case K::disjunction: {
      std::vector<std::vector<QuantifierBlock>> prefixes;
      std::vector<Formula> matrices;
      for (const Formula& g : f.parts) {
        Prenex p = pull_out(g);
        prefixes.push_back(std::move(p.prefix));
        matrices.push_back(std::move(p.matrix));
      }
      Formula matrix = f.kind == K::conjunction ? conjunction(std::move(matrices)) : disjunction(std::move(matrices));
      return {merge_prefixes(std::move(prefixes)), std::move(matrix)};
    }
    case K::negation:
      throw std::logic_error("pull_out(): not in negation normal form");
  }
  throw std::logic_error("unknown formula kind");
}

}  // namespace

Prenex prenex(const Formula& f) {
  Prenex p = pull_out(rename_apart(simplify_constants(negation_normal_form(f))));
  p.matrix = simplify_constants(p.matrix);
  return p;
}

}  // namespace affinterp::logic
