#include "theory/logic/condition_parser.hpp"

#include <cctype>
#include <optional>
#include <stdexcept>

namespace affinterp::logic {

namespace {

struct Token {
  enum class Kind { number, identifier, symbol, end } kind;
  std::string text;
  std::size_t column;  ///< 1-based, for messages
};

std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  const auto digit = [&](std::size_t k) {
    return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]));
  };
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    if (digit(i) || (c == '.' && digit(i + 1))) {
      while (digit(i)) ++i;
      if (i < text.size() && text[i] == '.') {
        ++i;
        while (digit(i)) ++i;
      }
      tokens.push_back({Token::Kind::number, std::string(text.substr(start, i - start)), start + 1});
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
      tokens.push_back({Token::Kind::identifier, std::string(text.substr(start, i - start)), start + 1});
    } else {
      static const std::vector<std::string> two = {"<=", ">=", "!=", "==", "&&", "||"};
      std::string symbol(1, c);
      for (const std::string& s : two)
        if (text.substr(i, 2) == s) symbol = s;
      if (symbol.size() == 1 && std::string_view("+-*/^()<>=!").find(c) == std::string_view::npos)
        throw std::invalid_argument("unexpected character '" + symbol + "' at column " + std::to_string(i + 1));
      i += symbol.size();
      tokens.push_back({Token::Kind::symbol, symbol, start + 1});
    }
  }
  tokens.push_back({Token::Kind::end, "", text.size() + 1});
  return tokens;
}

/// An exact rational-function value N/D met while parsing arithmetic.
struct Fraction {
  Polynomial numerator, denominator = Polynomial(1);
};

Rational decimal(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) return Rational(exact::Integer(text));
  const std::string whole = text.substr(0, dot), fraction = text.substr(dot + 1);
  exact::Integer scale = 1;
  for (std::size_t k = 0; k < fraction.size(); ++k) scale *= 10;
  const exact::Integer digits((whole.empty() ? "0" : whole) + fraction);
  return Rational(digits) / Rational(scale);
}

class Parser {
 public:
  Parser(std::string_view text, const std::vector<std::string>& variables,
         const std::map<std::string, Polynomial>& macros)
      : tokens_(tokenize(text)), variables_(variables), macros_(macros) {}

  Formula parse() {
    Formula f = condition();
    if (peek().kind != Token::Kind::end) fail("unexpected '" + peek().text + "' after a complete condition");
    return f;
  }

 private:
  const Token& peek() const { return tokens_[position_]; }
  bool at(std::string_view text) const { return peek().kind != Token::Kind::number && peek().text == text; }
  bool accept(std::string_view text) {
    if (!at(text)) return false;
    ++position_;
    return true;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw std::invalid_argument(message + " (column " + std::to_string(peek().column) + ")");
  }
  void expect(std::string_view text) {
    if (!accept(text))
      fail("expected '" + std::string(text) + "' but found " +
           (peek().kind == Token::Kind::end ? std::string("the end") : "'" + peek().text + "'"));
  }

  Formula condition() {
    std::vector<Formula> parts{disjunct()};
    while (accept("or") || accept("||")) parts.push_back(disjunct());
    return disjunction(std::move(parts));
  }

  Formula disjunct() {
    std::vector<Formula> parts{literal()};
    while (accept("and") || accept("&&")) parts.push_back(literal());
    return conjunction(std::move(parts));
  }

  Formula literal() {
    if (accept("not") || accept("!")) return negation(literal());
    if (accept("true")) return truth(true);
    if (accept("false")) return truth(false);
    if (at("(")) {
      // "(" opens either a parenthesised condition or the first sum of a comparison: try the comparison.
      const std::size_t saved = position_;
      try {
        return chain();
      } catch (const std::invalid_argument&) {
        position_ = saved;
      }
      expect("(");
      Formula f = condition();
      expect(")");
      return f;
    }
    return chain();
  }

  static Formula compare(const Fraction& left, const Fraction& right, Relation r) {
    // left − right = (Nl·Dr − Nr·Dl) / (Dl·Dr)
    const Polynomial n = left.numerator * right.denominator - right.numerator * left.denominator;
    const Polynomial d = left.denominator * right.denominator;
    if (d.is_constant()) return atom(n * Polynomial(Rational(1) / d.constant_term()), r);
    return atom(d, Relation::not_equal) && atom(n * d, r);
  }

  std::optional<Relation> relation() {
    static const std::vector<std::pair<std::string, Relation>> relations = {
        {"<=", Relation::less_equal}, {">=", Relation::greater_equal}, {"!=", Relation::not_equal},
        {"==", Relation::equal},      {"<", Relation::less},           {">", Relation::greater},
        {"=", Relation::equal}};
    if (peek().kind != Token::Kind::symbol) return std::nullopt;
    for (const auto& [text, r] : relations)
      if (accept(text)) return r;
    return std::nullopt;
  }

  Formula chain() {
    Fraction left = sum();
    std::vector<Formula> atoms;
    while (const std::optional<Relation> r = relation()) {
      Fraction right = sum();
      atoms.push_back(compare(left, right, *r));
      left = std::move(right);
    }
    if (atoms.empty()) fail("expected a comparison (<, <=, >, >=, =, !=)");
    return conjunction(std::move(atoms));
  }

  Fraction sum() {
    Fraction e = product();
    while (at("+") || at("-")) {
      const bool plus = accept("+");
      if (!plus) expect("-");
      const Fraction r = product();
      const Polynomial cross = r.numerator * e.denominator;
      e.numerator = e.numerator * r.denominator + (plus ? cross : -cross);
      e.denominator *= r.denominator;
    }
    return e;
  }

  static Fraction divide(const Fraction& a, const Fraction& b) {
    return {a.numerator * b.denominator, a.denominator * b.numerator};
  }

  Fraction product() {
    Fraction e = unary();
    while (at("*") || at("/")) {
      const bool times = accept("*");
      if (!times) expect("/");
      const Fraction r = unary();
      if (times) {
        e.numerator *= r.numerator;
        e.denominator *= r.denominator;
      } else {
        if (r.numerator.is_zero()) fail("division by zero");
        e = divide(e, r);
        if (e.denominator.is_constant()) e = {e.numerator * Polynomial(Rational(1) / e.denominator.constant_term())};
      }
    }
    return e;
  }

  Fraction unary() {
    if (accept("-")) {
      Fraction e = unary();
      e.numerator = -e.numerator;
      return e;
    }
    if (accept("+")) return unary();
    return power();
  }

  Fraction power() {
    Fraction base = primary();
    if (!accept("^")) return base;
    const bool reciprocal = accept("-");
    if (peek().kind != Token::Kind::number || peek().text.find('.') != std::string::npos)
      fail("exponents must be integers");
    const std::string digits = tokens_[position_++].text;
    if (digits.size() > 4) fail("exponent " + digits + " is too large");
    const unsigned n = static_cast<unsigned>(std::stoul(digits));
    Fraction result{pow(base.numerator, n), pow(base.denominator, n)};
    if (reciprocal) {
      if (result.numerator.is_zero()) fail("division by zero");
      std::swap(result.numerator, result.denominator);
    }
    return result;
  }

  Fraction primary() {
    const Token token = peek();
    if (token.kind == Token::Kind::number) {
      ++position_;
      return {Polynomial(decimal(token.text))};
    }
    if (token.kind == Token::Kind::identifier) {
      ++position_;
      if (const auto it = macros_.find(token.text); it != macros_.end()) return {it->second};
      for (const std::string& v : variables_)
        if (v == token.text) return {Polynomial::variable(v)};
      std::string allowed;
      for (const std::string& v : variables_) allowed += (allowed.empty() ? "" : ", ") + v;
      for (const auto& [name, p] : macros_) allowed += (allowed.empty() ? "" : ", ") + name;
      --position_;
      fail("unknown variable '" + token.text + "' (allowed: " + allowed + ")");
    }
    if (accept("(")) {
      Fraction e = sum();
      expect(")");
      return e;
    }
    fail(token.kind == Token::Kind::end ? "unexpected end of the condition" : "unexpected '" + token.text + "'");
  }

  std::vector<Token> tokens_;
  std::size_t position_ = 0;
  const std::vector<std::string>& variables_;
  const std::map<std::string, Polynomial>& macros_;
};

}  // namespace

Formula parse_condition(std::string_view text, const std::vector<std::string>& variables,
                        const std::map<std::string, Polynomial>& macros) {
  return Parser(text, variables, macros).parse();
}

}  // namespace affinterp::logic
