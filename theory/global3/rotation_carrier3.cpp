#include "theory/global3/rotation_carrier3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/local3/rotation3.hpp"

#include <utility>

namespace affinterp::global3 {

using Eigen::Index;
using Eigen::Vector3d;

RotationSplit3 split_rotations(const DualGraph3& graph, const ConsistentLogs& logs) {
  const auto m = static_cast<std::size_t>(logs.omega.cols());
  const std::size_t threads = global::ranges_for(m, decompositions_per_thread);
  Eigen::Matrix3Xd carrier = logs.seed, next(3, logs.omega.cols());
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
      split.remainder.col(i) =
          local3::rotation_log<double>(Eigen::Matrix3d(local3::rotation_exp<double>(Vector3d(-split.carrier.col(i))) *
                                                       local3::rotation_exp<double>(Vector3d(omega.col(i)))));
  });
  return split;
}

RotationSplit3 unsplit_rotations(const Eigen::Matrix3Xd& omega) {
  return {omega, Eigen::Matrix3Xd::Zero(3, omega.cols())};
}

}  // namespace affinterp::global3
