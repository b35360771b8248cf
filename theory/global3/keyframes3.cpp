#include "theory/global3/keyframes3.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace affinterp::global3 {

namespace {

std::vector<double> checked_times(std::vector<double> key_times, std::size_t poses) {
  if (key_times.size() != poses)
    throw global::RefusedProblem("keyframes need one key time a pose: " + std::to_string(poses) + " poses, " +
                                 std::to_string(key_times.size()) + " times");
  for (std::size_t k = 0; k < key_times.size(); ++k) {
    if (!std::isfinite(key_times[k])) throw global::RefusedProblem("key time " + std::to_string(k) + " is not finite");
    if (k > 0 && !(key_times[k] > key_times[k - 1]))
      throw global::RefusedProblem("key times must increase strictly (key " + std::to_string(k) + ")");
  }
  return key_times;
}

Blend3Options on_simplex(Blend3Options options) {
  options.allow_extrapolation = false;
  return options;
}

}  // namespace

Keyframes3::Keyframes3(const std::vector<Mesh3>& poses, std::vector<double> key_times, Blend3Options options)
    : key_times_(checked_times(std::move(key_times), poses.size())), blend_(poses, on_simplex(std::move(options))) {}

Eigen::VectorXd Keyframes3::weights_at(double t) const {
  if (!(t >= key_times_.front() && t <= key_times_.back()))
    throw std::out_of_range("the time " + std::to_string(t) + " is outside the key times [" +
                            std::to_string(key_times_.front()) + ", " + std::to_string(key_times_.back()) + "]");
  // k: the last key at or before t, at most K − 2, so that t_k ≤ t ≤ t_{k+1}.
  const auto after = std::upper_bound(key_times_.begin(), key_times_.end() - 1, t);
  const auto k = static_cast<Eigen::Index>(std::max<std::ptrdiff_t>(after - key_times_.begin() - 1, 0));
  const double s = (t - key_times_[static_cast<std::size_t>(k)]) /
                   (key_times_[static_cast<std::size_t>(k) + 1] - key_times_[static_cast<std::size_t>(k)]);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(key_times_.size()));
  w[k] = 1 - s;
  w[k + 1] = s;
  return w;
}

Eigen::Matrix3Xd Keyframes3::vertices_at(double t) const { return blend_.vertices_at(weights_at(t)); }

std::vector<Eigen::Matrix3Xd> Keyframes3::vertices_at(const std::vector<double>& times) const {
  std::vector<Eigen::VectorXd> weights;
  for (double t : times) weights.push_back(weights_at(t));
  return blend_.vertices_at(weights);
}

}  // namespace affinterp::global3
