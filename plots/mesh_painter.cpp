#include "plots/mesh_painter.hpp"

#include <cairo.h>

#include <algorithm>
#include <cstdint>

namespace affinterp::plots {

namespace {

/// The triangles' directed edges, sorted, each as one number: the smaller vertex, the larger, and a last
/// bit set when the edge runs from the smaller to the larger.
std::vector<std::uint64_t> directed_edges(const Eigen::Matrix3Xi& triangles) {
  std::vector<std::uint64_t> edges;
  edges.reserve(static_cast<std::size_t>(3 * triangles.cols()));
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)
    for (int c = 0; c < 3; ++c) {
      const auto a = static_cast<std::uint64_t>(triangles(c, i)),
                 b = static_cast<std::uint64_t>(triangles((c + 1) % 3, i));
      edges.push_back(std::min(a, b) << 33 | std::max(a, b) << 1 | (a < b ? 1 : 0));
    }
  std::sort(edges.begin(), edges.end());
  return edges;
}

/// Splits a chain whose every vertex has as many edges in as out (a boundary ∂c, since ∂∂ = 0) into
/// closed cycles: a walk along unused edges can only stop where it started.
std::vector<std::vector<int>> cycles(const std::vector<std::pair<int, int>>& chain, Eigen::Index vertex_count) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(vertex_count));
  for (const auto& [a, b] : chain) out[static_cast<std::size_t>(a)].push_back(b);
  std::vector<std::vector<int>> result;
  for (std::size_t start = 0; start < out.size(); ++start)
    while (!out[start].empty()) {
      std::vector<int> cycle{static_cast<int>(start)};
      for (auto at = start; !out[at].empty();) {
        const int next = out[at].back();
        out[at].pop_back();
        cycle.push_back(next);
        at = static_cast<std::size_t>(next);
      }
      result.push_back(std::move(cycle));
    }
  return result;
}

}  // namespace

Colour mix(const Colour& a, const Colour& b, double s) {
  return {a.r + s * (b.r - a.r), a.g + s * (b.g - a.g), a.b + s * (b.b - a.b)};
}

double fitting_scale(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double width, double height) {
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-12);
  return std::min(width / extent.x(), height / extent.y());
}

View centred(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double scale, double x, double y) {
  return {scale, x - scale * (lo.x() + hi.x()) / 2, y + scale * (lo.y() + hi.y()) / 2};
}

MeshPainter::MeshPainter(const Eigen::Matrix3Xi& triangles)
    : triangles_(triangles), all_edges_(triangles.cols() <= all_edges_limit) {
  const auto edges = directed_edges(triangles);
  std::vector<std::pair<int, int>> chain;
  for (std::size_t j = 0; j < edges.size();) {
    const std::uint64_t pair = edges[j] >> 1;
    const int a = static_cast<int>(pair >> 32), b = static_cast<int>(pair & 0xffffffff);
    int net = 0;
    for (; j < edges.size() && edges[j] >> 1 == pair; ++j) net += edges[j] & 1 ? 1 : -1;
    for (int k = 0; k < std::abs(net); ++k) chain.emplace_back(net > 0 ? a : b, net > 0 ? b : a);
    if (all_edges_) edges_.emplace_back(a, b);
  }
  boundary_cycles_ = cycles(chain, triangles.size() == 0 ? 0 : triangles.maxCoeff() + 1);
}

std::vector<Eigen::Index> MeshPainter::flipped(const Eigen::Matrix2Xd& v) const {
  std::vector<Eigen::Index> result;
  for (Eigen::Index i = 0; i < triangles_.cols(); ++i) {
    const Eigen::Vector2d e1 = v.col(triangles_(1, i)) - v.col(triangles_(0, i)),
                          e2 = v.col(triangles_(2, i)) - v.col(triangles_(0, i));
    if (e1.x() * e2.y() - e1.y() * e2.x() <= 0) result.push_back(i);
  }
  return result;
}

void MeshPainter::paint(cairo_t* cr, const Eigen::Matrix2Xd& vertices, const View& view, const MeshColours& colours,
                        double line_width) const {
  const auto x = [&](int k) { return view.x0 + view.scale * vertices(0, k); };
  const auto y = [&](int k) { return view.y0 - view.scale * vertices(1, k); };
  cairo_save(cr);
  cairo_new_path(cr);
  for (const auto& cycle : boundary_cycles_) {
    cairo_move_to(cr, x(cycle.front()), y(cycle.front()));
    for (std::size_t j = 1; j < cycle.size(); ++j) cairo_line_to(cr, x(cycle[j]), y(cycle[j]));
    cairo_close_path(cr);
  }
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_set_source_rgb(cr, colours.fill.r, colours.fill.g, colours.fill.b);
  if (all_edges_) {
    cairo_fill(cr);
    for (const auto& [a, b] : edges_) {
      cairo_move_to(cr, x(a), y(a));
      cairo_line_to(cr, x(b), y(b));
    }
  } else {
    cairo_fill_preserve(cr);  // the outline: the boundary cycles, stroked faster than edge by edge
  }
  cairo_set_line_width(cr, line_width);
  cairo_set_source_rgb(cr, colours.edge.r, colours.edge.g, colours.edge.b);
  cairo_stroke(cr);

  const auto flipped_triangles = flipped(vertices);
  if (!flipped_triangles.empty()) {
    for (const Eigen::Index i : flipped_triangles) {
      cairo_move_to(cr, x(triangles_(0, i)), y(triangles_(0, i)));
      cairo_line_to(cr, x(triangles_(1, i)), y(triangles_(1, i)));
      cairo_line_to(cr, x(triangles_(2, i)), y(triangles_(2, i)));
      cairo_close_path(cr);
    }
    cairo_set_source_rgb(cr, colours.flipped.r, colours.flipped.g, colours.flipped.b);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 1.5);  // an outline keeps triangles smaller than a pixel in sight
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

}  // namespace affinterp::plots
