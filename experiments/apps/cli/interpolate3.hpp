#pragma once
// `affinterp interpolate` on 3D meshes (triangle surfaces or MEDIT tetrahedra): global3::Interpolation3 with E^F,
// under the 2D command's option names. cmd_interpolate.cpp reads the options and chooses this path when a mesh
// is 3D; the options that have no 3D counterpart are refused there (refuse_planar_only_options).
#include "experiments/inputs/interpolation_request.hpp"
#include "theory/global3/mesh3.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace affinterp::cli {

struct Interpolate3Run {
  std::string source, target, out;
  /// The meshes when already read (cmd_interpolate.cpp reads them to tell 3D from 2D), else read from the files.
  std::optional<global3::Mesh3> source_mesh, target_mesh;
  /// homotopy, rotation_branch, area_weighted, t_begin, t_end from the options; pins and barycentre_locus
  io::InterpolationRequest request;
  std::vector<double> times;  ///< the frames' times, in order
  bool times_given = false;   ///< --times rather than --frames (metrics.json's "times")
  std::string format = "obj", metrics = "all";
  bool figures = true;  ///< OUT/viewer.html (plots/viewer/viewer3.hpp)
};

/// Throws CommandFailed (usage) naming the first option `command` was given that the 3D engine does not take:
/// an energy other than F asked for (2D's default, R, is not asked for), blend weights, vertex loci, edge directions, a
/// flipped target, a barycentre locus through points.
void refuse_planar_only_options(const CLI::App& command, const io::InterpolationRequest& request);

/// Reads, checks, interpolates and writes OUT (frames, metrics.json, the viewer); throws CommandFailed.
void run_interpolate3(const Interpolate3Run& run);

}  // namespace affinterp::cli
