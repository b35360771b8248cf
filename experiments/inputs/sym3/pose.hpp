#pragma once
// The target pose of the deformation application: a known smooth deformation of the source mesh.
#include "theory/deformation/mesh3.hpp"

namespace affinterp::sym3 {

/// The source mesh twisted, tapered and stretched along the longest axis of its bounding box: with
/// s ∈ [−1, 1] the position along that axis, a point is rotated about the axis by s·π/2, its distance
/// from the axis scaled by 1 + s/4 and its axial coordinate by 6/5. The map is smooth and preserves
/// orientation, so every triangle has a deformation gradient with positive determinant.
Mesh3 twisted_pose(const Mesh3& source);

}  // namespace affinterp::sym3
