#pragma once
// The 3D side of the affinterp module: Interpolation on (n, 3) vertices with (m, 3) triangles or (m, 4)
// tetrahedra runs global3::Interpolation3 (interpolation_binding.cpp hands it over), and affinterp.Blend blends K
// poses (global3::Blend3). Inputs are checked as the CLI checks them (experiments/inputs/mesh3_poses.hpp).
#include "experiments/python/arrays.hpp"
#include "theory/global3/blend3.hpp"
#include "theory/global3/interpolation3.hpp"

#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::python {

/// Interpolation's keywords that carry over to 3D (the others are refused before).
struct SpaceKeywords {
  std::string homotopy, rotation_branch;
  bool area_weighted = true, symmetric = false;
  int arap_iterations = 0;
  std::vector<std::string> pins, loci;
  std::string barycentre_locus;
  std::pair<double, double> time_range;
};

/// Whether V0 is an array of points in space, (n, 3).
bool is_space_points(const py::object& V0);

/// The poses of a blend or of keyframes, with their elements F, as meshes in space checked as the CLI checks them
/// (at least two; a one-line ValueError naming "poses[k]" otherwise). Poses given as (n, 2) arrays (all of them, or
/// none) lie in the plane z = 0 and set `planar`: the 3D engine keeps such a blend flat, and on two poses at
/// (1 − t, t) gives the 2D engine's E^F exp-log frames (checks/python/test_3d.py).
std::vector<global3::Mesh3> pose_meshes(const py::iterable& poses, const py::object& F, bool& planar);
/// A blend's options from the Python keywords they share with keyframes.
global3::Blend3Options blend_options(const std::string& rotation_branch, bool area_weighted, int arap_iterations);
/// (frames.size(), n, d) holding the first d = 2 or 3 coordinates of `frames`.
py::array_t<double> stacked(const std::vector<Eigen::Matrix3Xd>& frames, Eigen::Index vertex_count, Eigen::Index d);
/// The frame as (n, 2) points when `planar`, else (n, 3).
py::array_t<double> frame_points(Eigen::Matrix3Xd&& v, bool planar);

class SpaceInterpolation {
 public:
  /// Throws ValueError (one line) for bad arrays, meshes or keywords.
  SpaceInterpolation(const py::object& V0, const py::object& V1, const py::object& F, const SpaceKeywords& keywords);
  py::array_t<double> vertices_at(double t) const;            ///< (n, 3)
  py::array_t<double> frames(const py::object& times) const;  ///< (k, n, 3)
  double energy_at(double t) const;
  py::object metrics_at(double t) const;      ///< metrics.json's entry of the frame at t, as a dict
  py::array_t<double> rotation_logs() const;  ///< (m, 3): ω_i on its branch (Interpolation3::rotation_logs)
  py::tuple rotation_split() const;           ///< ((m, 3) carrier, (m, 3) remainder): Interpolation3::rotation_split

 private:
  void check_time(double t) const;

  std::unique_ptr<global3::Interpolation3> engine_;
  global3::Mesh3 source_, target_;  ///< for the metrics
  /// The elements at or beside the target's folds (target_folds3.hpp), found on the first metrics_at; empty when
  /// it folds none.
  mutable std::vector<unsigned char> near_folds_;
  mutable std::once_flag folds_found_;
  Eigen::Index vertex_count_ = 0;
  std::pair<double, double> time_range_;
};

}  // namespace affinterp::python
