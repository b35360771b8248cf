#pragma once
// Every 3×3 symmetric exponential of theory/sym3 in one batch form, so that sweeps and the deformation
// application treat scalar and SIMD-batched algorithms alike.
#include <Eigen/Core>

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace affinterp::sym3 {

/// out[i] = exp(in[i]) for symmetric 3×3 matrices; in.size() == out.size().
using SymExpBatch = std::function<void(std::span<const Eigen::Matrix3d>, std::span<Eigen::Matrix3d>)>;

/// A batch exponential applying a scalar exponential to each matrix in turn.
SymExpBatch elementwise(Eigen::Matrix3d (*exp)(const Eigen::Matrix3d&));

struct NamedExpBatch {
  std::string name;
  SymExpBatch exp;
};

/// Every registered exponential (exp_algorithms(), element-wise, under its own name) followed by the
/// batched ones ("affinterp-batched": exp_batched).
std::vector<NamedExpBatch> exp_variants();

}  // namespace affinterp::sym3
