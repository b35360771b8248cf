#include "plots/mesh3/mesh3_figures.hpp"

#include "plots/cairo_page.hpp"
#include "plots/mesh3/mesh3_render.hpp"

#include "theory/local3/nearest_rotation3.hpp"

#include <cairo.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace affinterp::plots {

std::vector<std::string> draw_filmstrip3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                         const std::vector<Mesh3Frame>& frames, const std::string& title) {
  const Eigen::Matrix3Xi triangles = boundary_triangles(mesh);
  ProjectedBox box;
  for (const auto& frame : frames) box.include(frame.vertices);
  const double cell = 200, top = 30, bottom = 24;
  const int width = static_cast<int>(cell * static_cast<double>(frames.size()));
  return render_png_and_svg(stem, width, static_cast<int>(top + cell + bottom), [&](cairo_t* cr) {
    centred_text(cr, title, width / 2.0, 20, 14);
    const double last = std::max<double>(1, static_cast<double>(frames.size()) - 1);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const double x = cell * static_cast<double>(f);
      draw_mesh3(cr, triangles, frames[f].vertices, box, x, top, cell, static_cast<double>(f) / last);
      centred_text(cr, frames[f].label, x + cell / 2, top + cell + 16, 12);
    }
  });
}

std::vector<std::string> draw_blend_triangle3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                              const std::vector<BlendThumbnail>& thumbnails,
                                              const std::vector<std::string>& pose_names, const std::string& title) {
  const Eigen::Matrix3Xi triangles = boundary_triangles(mesh);
  ProjectedBox box;
  for (const auto& thumb : thumbnails) box.include(thumb.vertices);
  const double cell = 150, side = 4 * cell, margin = 40;
  const double height_of_triangle = side * std::sqrt(3.0) / 2;
  // Corner k's page position (centre of its thumbnail): pose 0 at the top, 1 bottom left, 2 bottom right.
  const double left = margin + cell / 2, top = margin + cell / 2;
  const Eigen::Vector2d c0(left + side / 2, top), c1(left, top + height_of_triangle),
      c2(left + side, top + height_of_triangle);
  const int width = static_cast<int>(side + cell + 2 * margin);
  const int height = static_cast<int>(height_of_triangle + cell + 2 * margin);
  return render_png_and_svg(stem, width, height, [&](cairo_t* cr) {
    centred_text(cr, title, width / 2.0, 20, 14);
    for (const auto& thumb : thumbnails) {
      const Eigen::Vector2d at = thumb.weights[0] * c0 + thumb.weights[1] * c1 + thumb.weights[2] * c2;
      const double tint = thumb.weights[1] * 0.5 + thumb.weights[2];
      draw_mesh3(cr, triangles, thumb.vertices, box, at.x() - cell / 2 + margin / 2, at.y() - cell / 2, cell - margin,
                 tint);
    }
    const std::array<Eigen::Vector2d, 3> corners{c0, c1, c2};
    for (std::size_t k = 0; k < std::min<std::size_t>(3, pose_names.size()); ++k)
      centred_text(cr, pose_names[k], corners[k].x(), corners[k].y() + cell / 2 - 4, 12);
  });
}

namespace {

/// The patch's vertices centred on their mean and turned by the rotation that best maps them onto `onto`'s
/// (local3::fitted_rotation).
Eigen::Matrix3Xd turned_onto(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xd& onto) {
  return local3::fitted_rotation<double>(vertices, onto) * (vertices.colwise() - vertices.rowwise().mean());
}

/// The rotation that takes the area-weighted normal of `triangles` at `vertices` to the viewer's direction (after
/// view_rotation), by the shortest turn.
Eigen::Matrix3d facing_the_viewer(const Eigen::Matrix3Xi& triangles, const Eigen::Matrix3Xd& vertices) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < triangles.cols(); ++i) {
    const Eigen::Vector3d a = vertices.col(triangles(0, i));
    normal += (vertices.col(triangles(1, i)) - a).cross(vertices.col(triangles(2, i)) - a);
  }
  const Eigen::Vector3d towards = view_rotation().transpose() * Eigen::Vector3d::UnitZ();
  if (normal.norm() == 0) return Eigen::Matrix3d::Identity();
  return Eigen::Quaterniond::FromTwoVectors(normal, towards).toRotationMatrix();
}

}  // namespace

std::vector<std::string> draw_patches3(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                       const std::vector<MarkedPatch>& patches,
                                       const std::vector<std::pair<FaceMark, std::string>>& key,
                                       const std::string& title) {
  std::vector<Eigen::Matrix3Xd> shown;
  for (const MarkedPatch& patch : patches) shown.push_back(turned_onto(patch.vertices, patches.front().vertices));
  const Eigen::Matrix3d facing = patches.empty() ? Eigen::Matrix3d::Identity() : facing_the_viewer(triangles, shown[0]);
  ProjectedBox box;
  for (Eigen::Matrix3Xd& vertices : shown) box.include(vertices = facing * vertices);
  const double cell = 260, top = 30, labels = 24, key_height = 24, tint = 0.2;
  const int width = static_cast<int>(cell * static_cast<double>(patches.size()));
  return render_png_and_svg(stem, width, static_cast<int>(top + cell + labels + key_height), [&](cairo_t* cr) {
    centred_text(cr, title, width / 2.0, 20, 14);
    for (std::size_t k = 0; k < patches.size(); ++k) {
      const double x = cell * static_cast<double>(k);
      draw_mesh3(cr, triangles, shown[k], box, x, top, cell, tint, patches[k].marks);
      centred_text(cr, patches[k].label, x + cell / 2, top + cell + 16, 12);
    }
    const double y = top + cell + labels + 12, column = width / std::max<double>(1, static_cast<double>(key.size()));
    for (std::size_t k = 0; k < key.size(); ++k) {
      const double x = 12 + column * static_cast<double>(k);
      const Eigen::Vector3d colour = face_colour(key[k].first, tint);
      cairo_set_source_rgb(cr, colour.x(), colour.y(), colour.z());
      cairo_rectangle(cr, x, y - 9, 10, 10);
      cairo_fill(cr);
      left_text(cr, key[k].second, x + 14, y, 11);
    }
  });
}

}  // namespace affinterp::plots
