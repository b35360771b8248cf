#include "experiments/claims/global3/figures3.hpp"

#include "plots/mesh3/mesh3_figures.hpp"
#include "theory/global3/blend3.hpp"

#include <cstdio>

namespace affinterp::claims::global3_figures {

std::filesystem::path demo_folder() { return std::filesystem::temp_directory_path() / "affinterp-cgal-demo"; }

std::vector<std::string> interpolation_filmstrip(const std::filesystem::path& stem, const global3::Mesh3& source,
                                                 const global3::Interpolation3& engine, const std::string& title) {
  std::vector<plots::Mesh3Frame> frames;
  for (int k = 0; k <= 4; ++k) {
    char label[32];
    std::snprintf(label, sizeof label, "t = %.2f", k / 4.0);
    frames.push_back({engine.vertices_at(k / 4.0), label});
  }
  return plots::draw_filmstrip3(stem, source, frames, title);
}

std::vector<std::string> blend_triangle(const std::filesystem::path& stem, const std::vector<global3::Mesh3>& poses,
                                        const std::vector<std::string>& names, const std::string& title) {
  const global3::Blend3 blend(poses);
  std::vector<plots::BlendThumbnail> thumbnails;
  constexpr int steps = 3;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j) {
      const Eigen::Vector3d w(i, j, steps - i - j);
      thumbnails.push_back({w / steps, blend.vertices_at(Eigen::VectorXd(w / steps))});
    }
  return plots::draw_blend_triangle3(stem, poses.front(), thumbnails, names, title);
}

}  // namespace affinterp::claims::global3_figures
