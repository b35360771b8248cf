#include "theory/global3/rotation_carrier3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global/sparse_factor.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/local3/rotation3.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace affinterp::global3 {

using Eigen::Index;
using Eigen::Vector3d;

double seed_fidelity(double angle) {
  if (angle <= std::numbers::pi) return max_seed_fidelity;
  const double gain = std::abs(std::sin(angle / 2)) / (angle / 2) / (2 / std::numbers::pi), w = std::pow(gain, 4);
  return w >= 1 ? max_seed_fidelity : std::clamp(w / (1 - w), min_seed_fidelity, max_seed_fidelity);
}

namespace {

/// The fill's unknowns: the elements whose seed is held less than max_seed_fidelity, numbered in increasing order.
struct Unknowns {
  std::vector<Index> number;     ///< per element, its number among the unknowns, or −1 when it is held
  std::vector<Index> element;    ///< per unknown, its element
  std::vector<double> fidelity;  ///< per unknown, ρ_i
};

Unknowns unknowns_of(const Eigen::Matrix3Xd& seed) {
  Unknowns u{std::vector<Index>(static_cast<std::size_t>(seed.cols()), -1), {}, {}};
  for (Index i = 0; i < seed.cols(); ++i)
    if (const double rho = seed_fidelity(seed.col(i).norm()); rho < max_seed_fidelity) {
      u.number[static_cast<std::size_t>(i)] = static_cast<Index>(u.element.size());
      u.element.push_back(i);
      u.fidelity.push_back(rho);
    }
  return u;
}

}  // namespace

Eigen::Matrix3Xd filled_seeds(const DualGraph3& graph, const ConsistentLogs& logs) {
  const Eigen::Matrix3Xd& seed = logs.seed;
  const Unknowns unknowns = unknowns_of(seed);
  Eigen::Matrix3Xd filled = seed;
  if (unknowns.element.empty()) return filled;
  // d_ij from the pair in increasing order, negated for the other: the same edges kept from both ends, so that K
  // is symmetric.
  const auto d = [&](Index i, Index j) -> Vector3d {
    return i < j ? relative_turn(logs.omega.col(i), logs.omega.col(j))
                 : Vector3d(-relative_turn(logs.omega.col(j), logs.omega.col(i)));
  };
  // Row u (element i), over its neighbours j with |d_ij| ≤ reliable_step (n_i of them):
  //     (ρ_i + n_i) f_i − Σ_{unknown j} f_j = ρ_i s_i + Σ_{held j} s_j − Σ_j d_ij.
  const auto n = static_cast<Index>(unknowns.element.size());
  std::vector<Eigen::Triplet<double>> entries;
  global::SparseFactor<double>::Block rhs(n, 3);
  for (Index u = 0; u < n; ++u) {
    const Index i = unknowns.element[static_cast<std::size_t>(u)];
    const double rho = unknowns.fidelity[static_cast<std::size_t>(u)];
    rhs.row(u) = rho * seed.col(i).transpose();
    double diagonal = rho;
    for (int s = graph.start[static_cast<std::size_t>(i)]; s < graph.start[static_cast<std::size_t>(i) + 1]; ++s) {
      const int j = graph.neighbour[static_cast<std::size_t>(s)];
      const Vector3d d_ij = d(i, j);
      if (d_ij.norm() > reliable_step) continue;  // a crease or a fold: no small turn to integrate
      diagonal += 1;
      rhs.row(u) -= d_ij.transpose();
      if (const Index v = unknowns.number[static_cast<std::size_t>(j)]; v >= 0)
        entries.emplace_back(u, v, -1.0);
      else
        rhs.row(u) += seed.col(j).transpose();
    }
    entries.emplace_back(u, u, diagonal);
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  const auto factor = global::make_sparse_factor<double>(n);
  factor->analyse(K);
  // K is strictly diagonally dominant (every ρ_i ≥ min_seed_fidelity), so positive definite, its pivots at least
  // min_seed_fidelity and at most max_seed_fidelity plus a degree.
  factor->factorise(K, 1);
  factor->solve_in_place(rhs, 1);
  for (Index u = 0; u < n; ++u) filled.col(unknowns.element[static_cast<std::size_t>(u)]) = rhs.row(u).transpose();
  return filled;
}

RotationSplit3 split_rotations(const DualGraph3& graph, const ConsistentLogs& logs) {
  const auto m = static_cast<std::size_t>(logs.omega.cols());
  const std::size_t threads = global::ranges_for(m, decompositions_per_thread);
  Eigen::Matrix3Xd carrier = filled_seeds(graph, logs), next(3, logs.omega.cols());
  for (int step = 0; step < carrier_steps; ++step) {
    global::for_each_range(m, threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) {
        const int begin = graph.start[i], end = graph.start[i + 1];
        const auto own = static_cast<Index>(i);
        if (begin == end) {
          next.col(own) = carrier.col(own);
          continue;
        }
        Vector3d sum = Vector3d::Zero();
        for (int s = begin; s < end; ++s) sum += carrier.col(graph.neighbour[static_cast<std::size_t>(s)]);
        next.col(own) = 0.5 * carrier.col(own) + (0.5 / (end - begin)) * sum;
      }
    });
    std::swap(carrier, next);
  }
  return split_along(std::move(carrier), logs.omega);
}

RotationSplit3 split_along(Eigen::Matrix3Xd carrier, const Eigen::Matrix3Xd& omega) {
  RotationSplit3 split{std::move(carrier), Eigen::Matrix3Xd(3, omega.cols())};
  const auto m = static_cast<std::size_t>(omega.cols());
  global::for_each_range(m, global::ranges_for(m, decompositions_per_thread), [&](std::size_t first, std::size_t last) {
    for (auto i = static_cast<Index>(first); i < static_cast<Index>(last); ++i)
      split.remainder.col(i) = local3::rotation_log<double>(
          local3::rotation_exp_product<double>(Vector3d(-split.carrier.col(i)), Vector3d(omega.col(i))));
  });
  return split;
}

RotationSplit3 unsplit_rotations(const Eigen::Matrix3Xd& omega) {
  return {omega, Eigen::Matrix3Xd::Zero(3, omega.cols())};
}

}  // namespace affinterp::global3
