#include "theory/sym3/exp_batch.hpp"

#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

SymExpBatch elementwise(Eigen::Matrix3d (*exp)(const Eigen::Matrix3d&)) {
  return [exp](std::span<const Eigen::Matrix3d> in, std::span<Eigen::Matrix3d> out) {
    for (std::size_t i = 0; i < in.size(); ++i) out[i] = exp(in[i]);
  };
}

std::vector<NamedExpBatch> exp_variants() {
  std::vector<NamedExpBatch> variants;
  for (const ExpAlgorithm& algorithm : exp_algorithms())
    variants.push_back({std::string(algorithm.name), elementwise(algorithm.exp)});
  variants.push_back({"affinterp-batched", exp_batched});
  return variants;
}

}  // namespace affinterp::sym3
