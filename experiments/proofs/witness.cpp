#include "experiments/proofs/witness.hpp"

#include <algorithm>

namespace affinterp::proofs {

namespace {

using exact::Integer;
using exact::Rational;

Integer floor_of(const Rational& r) {
  const Integer n = boost::multiprecision::numerator(r), d = boost::multiprecision::denominator(r);
  Integer q = n / d;
  if (q * d != n && n < 0) --q;
  return q;
}

/// The continued-fraction convergents of r, simplest first.
std::vector<Rational> convergents(const Rational& r, int count = 40) {
  std::vector<Rational> out;
  Integer h0 = 1, h1 = 0, k0 = 0, k1 = 1;  // h_{-1}, h_{-2}, ...
  Rational rest = r;
  for (int i = 0; i < count; ++i) {
    const Integer a = floor_of(rest);
    const Integer h = a * h0 + h1, k = a * k0 + k1;
    out.push_back(Rational(h) / Rational(k));
    h1 = h0, h0 = h, k1 = k0, k0 = k;
    const Rational frac = rest - Rational(a);
    if (frac == 0) break;
    rest = Rational(1) / frac;
  }
  return out;
}

/// (q, |p|): the order of simplicity.
bool simpler(const Rational& a, const Rational& b) {
  const Integer qa = boost::multiprecision::denominator(a), qb = boost::multiprecision::denominator(b);
  if (qa != qb) return qa < qb;
  return abs(boost::multiprecision::numerator(a)) < abs(boost::multiprecision::numerator(b));
}

}  // namespace

std::vector<Rational> simple_rationals(const Rational& near, int max_denominator, int span) {
  std::vector<Rational> out;
  for (int q = 1; q <= max_denominator; ++q)
    for (int p = -span * q; p <= span * q; ++p)
      if (boost::multiprecision::gcd(Integer(p), Integer(q)) == 1) out.push_back(Rational(p) / q);
  for (int q = 1; q <= 64; ++q) {
    const Integer p = floor_of(near * q);
    for (const Integer& c : {p, Integer(p + 1)}) out.push_back(Rational(c) / q);
  }
  std::sort(out.begin(), out.end(), [&](const Rational& a, const Rational& b) {
    if (simpler(a, b) || simpler(b, a)) return simpler(a, b);
    return abs(a - near) < abs(b - near);
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::optional<logic::Point> shrink_witness(const logic::Point& start, const Predicate& holds,
                                           const std::vector<logic::Point>& simple_points) {
  logic::Point point = start;
  if (!holds(point)) {
    // An approximate (algebraic) sample point: try its coordinates' continued-fraction convergents, all
    // coordinates at the same depth, until the predicate holds.
    std::map<std::string, std::vector<Rational>> approximations;
    std::size_t depth = 0;
    for (const auto& [name, value] : start) depth = std::max(depth, (approximations[name] = convergents(value)).size());
    bool found = false;
    for (std::size_t i = 0; i < depth && !found; ++i) {
      for (auto& [name, value] : point) value = approximations[name][std::min(i, approximations[name].size() - 1)];
      found = holds(point);
    }
    if (!found) return std::nullopt;
  }
  for (const logic::Point& simple : simple_points) {
    logic::Point trial = point;
    for (const auto& [name, value] : simple)
      if (trial.contains(name)) trial[name] = value;
    if (holds(trial)) {
      point = trial;
      break;
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (auto& [name, value] : point) {
      for (const Rational& candidate : simple_rationals(value)) {
        if (!simpler(candidate, value)) break;
        logic::Point trial = point;
        trial[name] = candidate;
        if (holds(trial)) {
          value = candidate;
          changed = true;
          break;
        }
      }
    }
  }
  return point;
}

}  // namespace affinterp::proofs
