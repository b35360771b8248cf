#include "experiments/bench/power_law.hpp"

#include <cmath>
#include <limits>

namespace affinterp::bench {

double power_law_exponent(const std::vector<std::pair<double, double>>& points, double from) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [size, cost] : points) {
    if (!(size >= from && size > 0 && cost > 0)) continue;
    const double x = std::log(size), y = std::log(cost);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double spread = n * sxx - sx * sx;
  if (n < 2 || !(spread > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / spread;
}

}  // namespace affinterp::bench
