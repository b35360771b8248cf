#include "experiments/claims/origin/rational_origins.hpp"
#include "theory/origin/symbols.hpp"

#include <vector>

namespace affinterp::claims {

GiNaC::lst random_rational_origin(Rng& rng) {
  const auto coordinate = [&rng] {
    const auto p = rng.integer(-12, 12);
    const auto q = rng.integer(1, 9);
    return GiNaC::numeric(static_cast<long>(p), static_cast<long>(q));
  };
  const GiNaC::numeric x = coordinate(), y = coordinate();
  return GiNaC::lst{origin::symbols().x == x, origin::symbols().y == y};
}

std::optional<GiNaC::lst> small_origin_where_differ(const GiNaC::ex& a, const GiNaC::ex& b) {
  const std::vector<GiNaC::numeric> values = {0, 1, -1, GiNaC::numeric(1, 2), GiNaC::numeric(-1, 2), 2, -2};
  const GiNaC::ex difference = (a - b).normal();
  const GiNaC::ex denominator = GiNaC::denom(a.normal()) * GiNaC::denom(b.normal());
  for (const GiNaC::numeric& x : values)
    for (const GiNaC::numeric& y : values) {
      const GiNaC::lst o{origin::symbols().x == x, origin::symbols().y == y};
      if (!denominator.subs(o).is_zero() && !GiNaC::numer(difference).subs(o).is_zero()) return o;
    }
  return std::nullopt;
}

}  // namespace affinterp::claims
