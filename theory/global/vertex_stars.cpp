#include "theory/global/vertex_stars.hpp"

namespace affinterp::global {

VertexStars vertex_stars(const Eigen::Matrix3Xi& triangles, Eigen::Index vertex_count) {
  VertexStars stars;
  stars.start.assign(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)
    for (int c = 0; c < 3; ++c) ++stars.start[static_cast<std::size_t>(triangles(c, i)) + 1];
  for (std::size_t k = 1; k < stars.start.size(); ++k) stars.start[k] += stars.start[k - 1];
  stars.triangle.resize(static_cast<std::size_t>(stars.start.back()));
  stars.corner.resize(stars.triangle.size());
  std::vector<int> next(stars.start.begin(), stars.start.end() - 1);
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)  // increasing i: each star comes out sorted
    for (int c = 0; c < 3; ++c) {
      const auto s = static_cast<std::size_t>(next[static_cast<std::size_t>(triangles(c, i))]++);
      stars.triangle[s] = static_cast<int>(i);
      stars.corner[s] = static_cast<unsigned char>(c);
    }
  return stars;
}

}  // namespace affinterp::global
