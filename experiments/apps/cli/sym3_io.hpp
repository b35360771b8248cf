#pragma once
// Line-oriented I/O of 3×3 symmetric matrices for `affinterp exp3` and `affinterp eig3`.
#include "theory/sym3/algorithms.hpp"

#include <functional>
#include <istream>
#include <ostream>
#include <span>

namespace affinterp::cli {

/// Calls `each(S, N)` on every matrix S of `in`, N its line number: one per line, 9 whitespace-separated
/// numbers, row-major. Blank lines are skipped. The first line that is not 9 finite numbers forming a
/// symmetric matrix throws CommandFailed("line N: ...", 1), after `each` has run on every line before it.
void for_each_symmetric_matrix(std::istream& in, const std::function<void(const sym3::Mat3&, std::size_t)>& each);

/// Writes the values on one line with 17 significant digits, and flushes.
void write_line(std::ostream& out, std::span<const double> values);

}  // namespace affinterp::cli
