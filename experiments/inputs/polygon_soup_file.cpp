#include "experiments/inputs/polygon_soup_file.hpp"

#include "experiments/inputs/mesh_file.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <array>
#include <cmath>
#include <sstream>

namespace affinterp::io {

namespace {

constexpr std::array<const char*, 3> extensions = {".ply", ".stl", ".ts"};

}  // namespace

bool is_polygon_soup_extension(const std::string& extension) {
  return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

TriangleSoup read_triangle_soup(const std::filesystem::path& file) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) throw MeshFileError(name + ": no such file");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(name, points, polygons))
    throw MeshFileError(name + ": not a readable " + file.extension().string().substr(1) +
                        " polygon soup (CGAL::IO::read_polygon_soup refused it)");
  if (points.size() > 0x7fffffff || polygons.size() > 0x7fffffff)
    throw MeshFileError(name + ": more than 2^31 - 1 vertices or faces");
  TriangleSoup soup;
  soup.vertices.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point& p = points[k];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw MeshFileError(name + ": vertex " + std::to_string(k) + " is not finite");
    soup.vertices.col(static_cast<Eigen::Index>(k)) << p.x(), p.y(), p.z();
  }
  soup.triangles.resize(3, static_cast<Eigen::Index>(polygons.size()));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (polygons[i].size() != 3)
      throw MeshFileError(name + ": face " + std::to_string(i) + " has " + std::to_string(polygons[i].size()) +
                          " vertices (triangles only: a triangulation chosen by the reader could differ between "
                          "two meshes of one connectivity)");
    for (int c = 0; c < 3; ++c) {
      if (polygons[i][c] >= points.size())
        throw MeshFileError(name + ": face " + std::to_string(i) + " names vertex " + std::to_string(polygons[i][c]) +
                            " of " + std::to_string(points.size()));
      soup.triangles(c, static_cast<Eigen::Index>(i)) = static_cast<int>(polygons[i][c]);
    }
  }
  return soup;
}

global::Mesh read_polygon_soup_mesh(const std::filesystem::path& file) {
  TriangleSoup soup = read_triangle_soup(file);
  for (Eigen::Index k = 0; k < soup.vertices.cols(); ++k)
    if (soup.vertices(2, k) != 0) {
      std::ostringstream message;
      message << file.string() << ": vertex " << k << " has z = " << soup.vertices(2, k) << " (2D meshes: z must be 0)";
      throw MeshFileError(message.str());
    }
  return {soup.vertices.topRows<2>(), std::move(soup.triangles)};
}

}  // namespace affinterp::io
