#include "experiments/inputs/shapes3d/demo_poses.hpp"

#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/sym3/demo_mesh.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>

namespace affinterp::shapes3d {

namespace fs = std::filesystem;
using global3::Mesh3;

Mesh3 from_surface(const sym3::Mesh3& surface) { return {surface.vertices, surface.triangles}; }

Mesh3 subdivided(const Mesh3& surface) {
  const sym3::Mesh3 finer = sym3::midpoint_subdivision({surface.vertices, surface.elements});
  return from_surface(finer);
}

namespace {

/// The bounding box's centre, its sides' axes from the longest to the shortest, half the longest side.
struct BoxAxes {
  Eigen::Vector3d centre, longest, middle, shortest;
  double half_length = 0;
};

BoxAxes box_axes(const Eigen::Matrix3Xd& v) {
  const Eigen::Vector3d lo = v.rowwise().minCoeff(), hi = v.rowwise().maxCoeff(), side = hi - lo;
  Eigen::Index longest = 0, shortest = 0;
  side.maxCoeff(&longest);
  side.minCoeff(&shortest);
  if (shortest == longest) shortest = (longest + 1) % 3;  // a cube: any two distinct axes
  const Eigen::Index middle = 3 - longest - shortest;
  return {(lo + hi) / 2, Eigen::Vector3d::Unit(longest), Eigen::Vector3d::Unit(middle), Eigen::Vector3d::Unit(shortest),
          side[longest] / 2};
}

}  // namespace

Mesh3 bent_about_centre(const Mesh3& mesh, double angle) {
  // p − c = u L + n N + w S (the box's axes) goes to the arc of radius R = half_length / angle in the L–N plane:
  // θ = u / R, ρ = R − n, q = c + ρ sin θ L + (R − ρ cos θ) N + w S. Its Jacobian has determinant ρ / R, positive
  // while every n < R: the bend keeps each element's orientation.
  const BoxAxes box = box_axes(mesh.vertices);
  const double R = box.half_length / angle;
  Mesh3 out = mesh;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const Eigen::Vector3d d = mesh.vertices.col(k) - box.centre;
    const double u = d.dot(box.longest), n = d.dot(box.middle), w = d.dot(box.shortest);
    const double theta = u / R, rho = R - n;
    out.vertices.col(k) =
        box.centre + rho * std::sin(theta) * box.longest + (R - rho * std::cos(theta)) * box.middle + w * box.shortest;
  }
  return out;
}

Mesh3 twisted_about_long_axis(const Mesh3& mesh, double turn) {
  const BoxAxes box = box_axes(mesh.vertices);
  Mesh3 out = mesh;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const Eigen::Vector3d d = mesh.vertices.col(k) - box.centre;
    const double s = d.dot(box.longest) / box.half_length;
    out.vertices.col(k) = box.centre + Eigen::AngleAxisd(s * turn, box.longest) * d;
  }
  return out;
}

std::optional<std::vector<Mesh3>> elephant_poses(const fs::path& folder) {
  const auto surface = sym3::cgal_demo_mesh("elephant.off", folder);
  if (!surface) return std::nullopt;
  const Mesh3 rest = from_surface(*surface);
  const double pi = std::numbers::pi;
  return std::vector<Mesh3>{rest, bent_about_centre(rest, pi / 3), twisted_about_long_axis(rest, pi / 2)};
}

std::optional<fs::path> cat_folder() {
  for (const char* candidate : {"/work/shared/data/meshes3d/cat", "../shared/data/meshes3d/cat"})
    if (fs::exists(fs::path(candidate) / "cat-0.off")) return fs::path(candidate);
  return std::nullopt;
}

std::optional<std::vector<Mesh3>> cat_poses(const std::vector<int>& which) {
  const auto folder = cat_folder();
  if (!folder) return std::nullopt;
  std::vector<Mesh3> poses;
  for (const int k : which)
    poses.push_back(from_surface(io::read_off_surface(*folder / ("cat-" + std::to_string(k) + ".off"))));
  return poses;
}

}  // namespace affinterp::shapes3d
