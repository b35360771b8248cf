#include "plots/mesh3/mesh3_render.hpp"

#include <cairo.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <vector>

namespace affinterp::plots {

Eigen::Matrix3Xi boundary_triangles(const global3::Mesh3& mesh) {
  if (mesh.kind() == global3::ElementKind::triangle) return mesh.elements;
  // Face c of a positively oriented tetrahedron (p0, p1, p2, p3) is the one without corner c; these orders
  // make each face's normal point away from the missing corner.
  const std::array<std::array<int, 3>, 4> faces{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
  std::map<std::array<int, 3>, std::array<int, 3>> once;  // sorted corners -> oriented face, if seen once
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i)
    for (const auto& f : faces) {
      const std::array<int, 3> face{mesh.elements(f[0], i), mesh.elements(f[1], i), mesh.elements(f[2], i)};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      if (const auto it = once.find(key); it != once.end())
        once.erase(it);
      else
        once.emplace(key, face);
    }
  Eigen::Matrix3Xi out(3, static_cast<Eigen::Index>(once.size()));
  Eigen::Index j = 0;
  for (const auto& [key, face] : once) out.col(j++) << face[0], face[1], face[2];
  return out;
}

Eigen::Matrix3d view_rotation() {
  const double degree = std::numbers::pi / 180;
  return (Eigen::AngleAxisd(25 * degree, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(-35 * degree, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

void ProjectedBox::include(const Eigen::Matrix3Xd& vertices) {
  const Eigen::Matrix3Xd seen = view_rotation() * vertices;
  lo = lo.cwiseMin(seen.topRows<2>().rowwise().minCoeff());
  hi = hi.cwiseMax(seen.topRows<2>().rowwise().maxCoeff());
}

Eigen::Vector3d face_colour(FaceMark mark, double tint) {
  switch (mark) {
    case FaceMark::fold:
      return {0.6, 0.3, 0.85};
    case FaceMark::inverted_near_fold:
      return {0.95, 0.55, 0.1};
    case FaceMark::inverted:
      return {0.85, 0.1, 0.1};
    case FaceMark::none:
      break;
  }
  return {0.75 - 0.55 * tint, 0.85 - 0.45 * tint, 1.0 - 0.2 * tint};
}

void draw_mesh3(cairo_t* cr, const Eigen::Matrix3Xi& triangles, const Eigen::Matrix3Xd& vertices,
                const ProjectedBox& box, double x, double y, double size, double tint,
                std::span<const FaceMark> marks) {
  const Eigen::Matrix3Xd seen = view_rotation() * vertices;  // x right, y up, z towards the viewer
  const Eigen::Vector2d extent = box.hi - box.lo;
  const double scale = 0.92 * size / std::max(extent.maxCoeff(), 1e-300);
  const Eigen::Vector2d middle = (box.lo + box.hi) / 2;
  const auto page = [&](int k) {
    return Eigen::Vector2d(x + size / 2 + scale * (seen(0, k) - middle.x()),
                           y + size / 2 - scale * (seen(1, k) - middle.y()));
  };
  std::vector<Eigen::Index> order(static_cast<std::size_t>(triangles.cols()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  const auto depth = [&](Eigen::Index i) {
    return seen(2, triangles(0, i)) + seen(2, triangles(1, i)) + seen(2, triangles(2, i));
  };
  const auto marked = [&](Eigen::Index i) {
    return !marks.empty() && marks[static_cast<std::size_t>(i)] != FaceMark::none;
  };
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::pair(marked(a), depth(a)) < std::pair(marked(b), depth(b));
  });
  const Eigen::Vector3d light = Eigen::Vector3d(-0.3, 0.5, 1).normalized();
  cairo_set_line_width(cr, 0.25);
  for (const Eigen::Index i : order) {
    const Eigen::Vector3d a = seen.col(triangles(0, i)), b = seen.col(triangles(1, i)), c = seen.col(triangles(2, i));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    // Two-sided: a face seen from behind (an open surface, a fold) is lit as its front would be.
    const double lambert = normal.norm() > 0 ? std::abs(normal.normalized().dot(light)) : 0;
    const double shade = 0.25 + 0.75 * lambert;
    cairo_move_to(cr, page(triangles(0, i)).x(), page(triangles(0, i)).y());
    cairo_line_to(cr, page(triangles(1, i)).x(), page(triangles(1, i)).y());
    cairo_line_to(cr, page(triangles(2, i)).x(), page(triangles(2, i)).y());
    cairo_close_path(cr);
    const Eigen::Vector3d colour =
        face_colour(marks.empty() ? FaceMark::none : marks[static_cast<std::size_t>(i)], tint);
    cairo_set_source_rgb(cr, shade * colour.x(), shade * colour.y(), shade * colour.z());
    cairo_fill_preserve(cr);
    if (marked(i)) {  // outlined in its own colour, wide enough to show a triangle seen edge-on
      cairo_set_source_rgb(cr, colour.x(), colour.y(), colour.z());
      cairo_set_line_width(cr, 2);
      cairo_stroke(cr);
      cairo_set_line_width(cr, 0.25);
      continue;
    }
    cairo_set_source_rgba(cr, 0.1, 0.1, 0.2, 0.35);
    cairo_stroke(cr);
  }
}

}  // namespace affinterp::plots
