#pragma once
// How a cost grows with size: the exponent p of cost ≈ c · size^p, the least-squares slope of log cost against
// log size (the straight line of a log-log plot), for the engine's scale table (bench_scale).
#include <utility>
#include <vector>

namespace affinterp::bench {

/// p fitted to the (size, cost) points whose size is at least `from`, both positive; NaN when fewer
/// than two such points (or equal sizes) leave the slope undetermined.
double power_law_exponent(const std::vector<std::pair<double, double>>& points, double from = 0);

}  // namespace affinterp::bench
