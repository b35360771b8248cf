#pragma once
// Where a 3D interpolation's frame inverts, seen up close, for the report beside quality_3d's table
// (engine3_quality.hpp): the piece of surface within a few vertex rings of one inverted triangle, in the source, the
// frame and the target, with the target's folds (target_folds3.hpp) and the frame's inverted triangles marked. It
// shows whether a frame's inversions sit on the folds the input itself has, or away from them.
#include "experiments/claims/context.hpp"
#include "plots/mesh3/mesh3_render.hpp"
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// The vertex rings around the centre triangle that the piece holds: enough to see a fold's neighbours.
inline constexpr int closeup_rings = 4;

struct Engine3Closeup {
  std::string pair;            ///< the pose pair's name
  double t = 0;                ///< the frame's time
  long inverted = 0;           ///< the frame's inverted triangles (frame_metrics3.hpp, against the frame's local maps)
  long inverted_away = 0;      ///< of those, the ones neither a fold of the target nor sharing a vertex with one
  long centre = 0;             ///< the triangle the piece is centred on, in the pair's numbering
  Eigen::Matrix3Xi triangles;  ///< the piece's triangles, indices into the columns of the vertices below
  Eigen::Matrix3Xd source, frame, target;   ///< the piece's vertices in each
  std::vector<plots::FaceMark> fold_marks;  ///< per triangle of the piece: the target's folds (source and target)
  /// Per triangle of the piece in the frame: the inverted ones (at or beside a fold, or away), and the folds that
  /// are not inverted.
  std::vector<plots::FaceMark> frame_marks;
};

/// The piece of `source`'s surface within `rings` vertex rings of one triangle that `frame` (at time t, judged
/// against `local_maps`) inverts: the first inverted away from the target's folds, else the first inverted;
/// nullopt when the frame inverts none or the meshes are tetrahedra.
std::optional<Engine3Closeup> closeup_of_frame(const std::string& pair, const global3::Mesh3& source,
                                               const global3::Mesh3& target, double t, const Eigen::Matrix3Xd& frame,
                                               std::span<const Eigen::Matrix3d> local_maps, int rings = closeup_rings);

/// Draws the piece in the source, the frame and the target side by side (plots::draw_patches3) as
/// sequel-3d-inversion-closeup.png and .svg under the settings' figure folder; returns their references.
std::vector<std::string> draw_engine3_closeup(const claims::RunSettings& settings, const Engine3Closeup& closeup);

/// {"pair", "t", "inverted", "inverted_away", "centre", "triangles", "source", "frame", "target", "fold_marks",
/// "frame_marks"}; matrices as arrays of their columns, marks as small integers (FaceMark).
void to_json(nlohmann::json& json, const Engine3Closeup& closeup);
void from_json(const nlohmann::json& json, Engine3Closeup& closeup);

}  // namespace affinterp::measurements
