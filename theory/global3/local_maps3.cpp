#include "theory/global3/local_maps3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/local3/rotation3.hpp"
#include "theory/sym3/algorithms.hpp"

#include <algorithm>
#include <vector>

namespace affinterp::global3 {

void exp_log_maps(const LogFill& fill, std::span<Eigen::Matrix3d> out, std::size_t threads,
                  const sym3::SymExpBatch& exp) {
  const auto m = static_cast<Eigen::Index>(out.size());
  const auto chunks = static_cast<std::size_t>((m + exp_chunk - 1) / exp_chunk);
  global::for_each_range(chunks, std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(chunks, 1)),
                         [&](std::size_t first_chunk, std::size_t last_chunk) {
                           std::vector<Eigen::Vector3d> Omega(static_cast<std::size_t>(exp_chunk)), Eta(Omega.size());
                           std::vector<Eigen::Matrix3d> Lambda(Omega.size()), stretch(Omega.size());
                           for (std::size_t c = first_chunk; c < last_chunk; ++c) {
                             const Eigen::Index first = static_cast<Eigen::Index>(c) * exp_chunk;
                             const Eigen::Index last = std::min(m, first + exp_chunk);
                             const auto size = static_cast<std::size_t>(last - first);
                             fill(first, last, std::span(Omega).first(size), std::span(Eta).first(size),
                                  std::span(Lambda).first(size));
                             if (exp)
                               exp(std::span(Lambda).first(size), std::span(stretch).first(size));
                             else
                               sym3::exp_batched(std::span(Lambda).first(size), std::span(stretch).first(size));
                             for (std::size_t j = 0; j < size; ++j)
                               out[static_cast<std::size_t>(first) + j] =
                                   local3::rotation_exp_product<double>(Omega[j], Eta[j]) * stretch[j];
                           }
                         });
}

}  // namespace affinterp::global3
