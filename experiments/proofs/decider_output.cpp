#include "experiments/proofs/decider_output.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {

namespace {

using exact::Rational;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// "12", "-3/4", "1.25", "-0.0495097568-" (QEPCAD marks a truncated decimal with a trailing sign).
std::optional<Rational> parse_number(std::string text) {
  text = trim(text);
  if (text.size() > 1 && (text.back() == '+' || text.back() == '-')) text.pop_back();
  try {
    if (text.find('.') == std::string::npos) return exact::parse_rational(text);
    const bool negative = !text.empty() && text.front() == '-';
    if (negative) text.erase(0, 1);
    const std::size_t dot = text.find('.');
    const std::string digits = text.substr(0, dot) + text.substr(dot + 1);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    Rational value{exact::Integer(digits)};
    for (std::size_t k = dot + 1; k < text.size(); ++k) value /= 10;
    return negative ? -value : value;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// ------------------------------------------------------------------------------------------- s-expressions
struct Sexp {
  std::string atom;  ///< empty for a list
  std::vector<Sexp> list;
};

Sexp read_sexp(const std::vector<std::string>& tokens, std::size_t& i) {
  if (i >= tokens.size()) throw std::invalid_argument("unexpected end of a Z3 model");
  if (tokens[i] != "(") return {tokens[i++], {}};
  Sexp s;
  for (++i; i < tokens.size() && tokens[i] != ")";) s.list.push_back(read_sexp(tokens, i));
  if (i >= tokens.size()) throw std::invalid_argument("unbalanced Z3 model");
  ++i;
  return s;
}

std::vector<std::string> sexp_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '(' || c == ')') {
      tokens.emplace_back(1, c);
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '"') {
      const std::size_t end = text.find('"', i + 1);
      tokens.push_back(text.substr(i, end == std::string::npos ? std::string::npos : end + 1 - i));
      i = end == std::string::npos ? text.size() : end + 1;
    } else {
      std::size_t j = i;
      while (j < text.size() && text[j] != '(' && text[j] != ')' && !std::isspace(static_cast<unsigned char>(text[j])))
        ++j;
      tokens.push_back(text.substr(i, j - i));
      i = j;
    }
  }
  return tokens;
}

/// A polynomial in Z3's notation: numbers, the variable, (+ …), (- …), (* …), (^ p n), (/ a b).
logic::Polynomial sexp_polynomial(const Sexp& s) {
  using logic::Polynomial;
  if (s.list.empty()) {
    if (const std::optional<Rational> r = parse_number(s.atom)) return Polynomial(*r);
    return Polynomial::variable(s.atom);
  }
  const std::string& op = s.list.front().atom;
  std::vector<Polynomial> args;
  for (std::size_t k = 1; k < s.list.size(); ++k) args.push_back(sexp_polynomial(s.list[k]));
  if (args.empty()) throw std::invalid_argument("empty Z3 term");
  Polynomial r = args.front();
  if (op == "+") {
    for (std::size_t k = 1; k < args.size(); ++k) r += args[k];
  } else if (op == "-") {
    if (args.size() == 1) return -r;
    for (std::size_t k = 1; k < args.size(); ++k) r -= args[k];
  } else if (op == "*") {
    for (std::size_t k = 1; k < args.size(); ++k) r *= args[k];
  } else if (op == "^" && args.size() == 2 && args[1].is_constant()) {
    r = pow(r, static_cast<unsigned>(args[1].constant_term()));
  } else if (op == "/" && args.size() == 2 && args[1].is_constant() && args[1].constant_term() != 0) {
    r = r * Polynomial(Rational(1) / args[1].constant_term());
  } else {
    throw std::invalid_argument("unsupported Z3 term " + op);
  }
  return r;
}

/// The k-th real root (1-based, ascending) of a square-free univariate polynomial, approximately: sign
/// changes on a fine grid inside Cauchy's bound, refined by bisection.
std::optional<double> real_root(const logic::Polynomial& p, int k) {
  const std::set<std::string> vars = p.variables();
  if (vars.size() != 1) return std::nullopt;
  const std::string x = *vars.begin();
  const unsigned n = p.degree_in(x);
  std::vector<double> c(n + 1, 0.0);
  for (const auto& [m, coefficient] : p.terms())
    c[m.empty() ? 0 : m.begin()->second] = static_cast<double>(coefficient);
  double bound = 0;
  for (unsigned i = 0; i < n; ++i) bound = std::max(bound, std::abs(c[i] / c[n]));
  bound += 1;
  const auto f = [&](double t) {
    double v = 0;
    for (unsigned i = n + 1; i-- > 0;) v = v * t + c[i];
    return v;
  };
  constexpr int steps = 1 << 16;
  int found = 0;
  double left = -bound, f_left = f(left);
  for (int i = 1; i <= steps; ++i) {
    const double right = -bound + 2 * bound * i / steps, f_right = f(right);
    if (f_left == 0 || (f_left < 0) != (f_right < 0)) {
      double lo = left, hi = right;
      for (int b = 0; b < 200 && f_left != 0; ++b) {
        const double mid = (lo + hi) / 2;
        ((f(mid) < 0) == (f(lo) < 0) ? lo : hi) = mid;
      }
      if (++found == k) return f_left == 0 ? left : (lo + hi) / 2;
      if (f_right == 0) {  // counted at the next step as its left end
        left = right, f_left = f_right;
        continue;
      }
    }
    left = right, f_left = f_right;
  }
  return std::nullopt;
}

/// A model value: exact for numbers, (- a) and (/ a b); approximate for root-obj; nullopt otherwise.
std::optional<std::pair<Rational, bool>> model_value(const Sexp& s) {
  if (s.list.empty()) {
    const std::optional<Rational> r = parse_number(s.atom);
    return r ? std::optional(std::pair(*r, true)) : std::nullopt;
  }
  const std::string& op = s.list.front().atom;
  if (op == "root-obj" && s.list.size() == 3) {
    const std::optional<double> root = real_root(sexp_polynomial(s.list[1]), std::stoi(s.list[2].atom));
    return root ? std::optional(std::pair(exact::from_double(*root), false)) : std::nullopt;
  }
  std::vector<std::pair<Rational, bool>> args;
  for (std::size_t k = 1; k < s.list.size(); ++k) {
    const auto v = model_value(s.list[k]);
    if (!v) return std::nullopt;
    args.push_back(*v);
  }
  if (op == "-" && args.size() == 1) return std::pair(Rational(-args[0].first), args[0].second);
  if (op == "/" && args.size() == 2 && args[1].first != 0)
    return std::pair(Rational(args[0].first / args[1].first), args[0].second && args[1].second);
  return std::nullopt;
}

}  // namespace

std::string_view to_string(SetResult r) {
  switch (r) {
    case SetResult::empty:
      return "empty";
    case SetResult::non_empty:
      return "non-empty";
    case SetResult::unknown:
      return "unknown";
  }
  return "unknown";
}

DeciderAnswer parse_qepcad(const std::string& output, const std::vector<std::string>& variables) {
  DeciderAnswer answer;
  const std::vector<std::string> lines = lines_of(output);
  // A run that printed an error, a warning or a failure answered nothing, whatever formula it printed:
  // "Error! Delineating polynomial should be added over cell(…)!", the McCallum projection's "may not be valid"
  // warning (the projection is complete only for well-oriented input: Collins and Hong, J. Symb. Comput. 12,
  // 1991; Brown, QEPCAD B user manual), "Failure occurred in …", "Prime list exhausted", "Too few cells
  // reclaimed", std::bad_alloc at the address-space cap.
  for (const std::string& line : lines)
    for (const char* flag : {"Error", "Warning", "WARNING", "Failure", "McCallum projection", "Prime list exhausted",
                             "Too few cells reclaimed", "bad_alloc"})
      if (line.find(flag) != std::string::npos) {
        answer.reason =
            std::string(flag) == "bad_alloc" ? "qepcad: out of memory (address-space cap)" : "qepcad: " + trim(line);
        return answer;
      }
  std::size_t i = 0;
  while (i < lines.size() && lines[i].find("An equivalent quantifier-free formula:") == std::string::npos) ++i;
  if (i == lines.size()) {
    answer.reason = "qepcad: no answer";
    return answer;
  }
  std::string formula;
  for (++i; i < lines.size() && trim(lines[i]).empty(); ++i) {
  }
  for (; i < lines.size() && !trim(lines[i]).empty(); ++i) formula += (formula.empty() ? "" : " ") + trim(lines[i]);
  if (formula == "TRUE") {
    answer.result = SetResult::non_empty;
  } else if (formula == "FALSE") {
    answer.result = SetResult::empty;
    return answer;
  } else {
    answer.reason = "qepcad: a formula, not TRUE/FALSE: " + formula;
    return answer;
  }
  // The first sample point d-witness-list printed.
  Witness witness;
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const std::string line = trim(lines[j]);
    if (line.rfind("Coordinate ", 0) != 0) {
      if (!witness.point.empty() && line.find("Information about the cell") != std::string::npos) break;
      continue;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::size_t index = std::stoul(line.substr(11, eq - 11));
    if (index < 1 || index > variables.size()) continue;
    std::optional<Rational> value = parse_number(line.substr(eq + 1));
    if (!value && j + 1 < lines.size() && trim(lines[j + 1]).rfind("=", 0) == 0) {
      value = parse_number(trim(lines[j + 1]).substr(1));  // an algebraic coordinate: its decimal approximation
      witness.exact = false;
    }
    if (value) witness.point[variables[index - 1]] = *value;
  }
  if (witness.point.size() == variables.size()) answer.witness = witness;
  return answer;
}

DeciderAnswer parse_smt(const std::string& output, std::string_view tool) {
  DeciderAnswer answer;
  const std::vector<std::string> lines = lines_of(output);
  std::string first;
  for (const std::string& line : lines)
    if (!trim(line).empty()) {
      first = trim(line);
      break;
    }
  const std::string name(tool);
  if (first != "sat" && first != "unsat") {
    answer.reason = first.empty() ? name + ": no answer" : name + ": " + first;
    return answer;
  }
  // An error, a warning or a resource message anywhere: the run answered nothing.
  for (const std::string& line : lines)
    for (const char* flag : {"(error", "warning", "WARNING", "unknown", "timeout", "resource", "interrupted"})
      if (line.find(flag) != std::string::npos) {
        answer.reason = name + ": " + trim(line);
        return answer;
      }
  if (first == "unsat") {
    answer.result = SetResult::empty;
    return answer;
  }
  answer.result = SetResult::non_empty;
  const std::size_t start = output.find("sat") + 3;
  try {
    const std::vector<std::string> tokens = sexp_tokens(output.substr(start));
    std::size_t i = 0;
    if (tokens.empty() || tokens[0] != "(") return answer;
    const Sexp model = read_sexp(tokens, i);
    Witness witness;
    for (const Sexp& def : model.list) {
      if (def.list.size() != 5 || def.list[0].atom != "define-fun" || def.list[3].atom != "Real") continue;
      if (const auto v = model_value(def.list[4])) {
        witness.point[def.list[1].atom] = v->first;
        witness.exact = witness.exact && v->second;
      }
    }
    answer.witness = witness;
  } catch (const std::exception&) {
    // a model we cannot read: non-empty without a witness
  }
  return answer;
}

std::string without_timings(const std::string& output) {
  std::string kept;
  for (const std::string& line : lines_of(output))
    if (line.find("System time") == std::string::npos && line.find("milliseconds") == std::string::npos)
      kept += line + "\n";
  return kept;
}

}  // namespace affinterp::proofs
