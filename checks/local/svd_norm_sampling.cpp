#include "checks/local/svd_norm_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace affinterp::local {

double svd_norm_squared(double x, double y, double beta, double phi, double t) {
  const double e1 = 1 + t * (x - 1), e2 = 1 + t * (y - 1);
  const double c = std::cos(phi + t * beta), s = std::sin(phi + t * beta);
  return e1 * e1 * c * c + e2 * e2 * s * s;
}

std::optional<NormWitness> svd_norm_failure(double x, double y, double beta, const SamplingResolution& resolution) {
  const std::size_t n = resolution.times;
  std::vector<double> f(n + 1);
  for (std::size_t k = 0; k < resolution.directions; ++k) {
    const double phi = std::numbers::pi * static_cast<double>(k) / static_cast<double>(resolution.directions);
    for (std::size_t j = 0; j <= n; ++j) f[j] = svd_norm_squared(x, y, beta, phi, static_cast<double>(j) / n);
    const double tolerance = resolution.relative_tolerance * *std::max_element(f.begin(), f.end());
    std::optional<std::size_t> rise, fall;  // first step up, first step down
    for (std::size_t j = 0; j < n; ++j) {
      if (!rise && f[j + 1] - f[j] > tolerance) rise = j;
      if (!fall && f[j] - f[j + 1] > tolerance) fall = j;
    }
    if (!rise || !fall) continue;
    // Between the first rise and the first fall lies an extreme that beats both ends by the tolerance.
    const bool peak = *rise < *fall;
    const std::size_t first = std::min(*rise, *fall), last = std::max(*rise, *fall) + 1;
    const auto middle = peak ? std::max_element(f.begin() + first + 1, f.begin() + last)
                             : std::min_element(f.begin() + first + 1, f.begin() + last);
    const auto at = [n](std::size_t j) { return static_cast<double>(j) / n; };
    return NormWitness{phi, at(first), at(static_cast<std::size_t>(middle - f.begin())), at(last)};
  }
  return std::nullopt;
}

}  // namespace affinterp::local
