#pragma once
// A gingerbread man and poses of it made by a known skeletal deformation: each limb (head, arms, legs)
// bends about its axis at its joints (neck, shoulder and elbow, hip and knee), the bend angle growing
// linearly across each joint so the limb's axis turns along circular arcs and the parts beyond the
// joints move rigidly; the torso stays. All poses share the rest pose's triangles: compatible by
// construction, and no triangle flips while a joint's bend is gentle enough for the limb's width.
#include "theory/global/mesh.hpp"

#include <string>
#include <vector>

namespace affinterp::shapes {

/// The man in the rest pose (arms out, legs apart), about 2.9 units tall, meshed with edges ≤ max_edge.
global::Mesh man(double max_edge = 0.1);

/// Joint angles (radians, counter-clockwise) of a pose, relative to the parent bone.
struct Pose {
  std::string name;
  double neck = 0;
  double right_shoulder = 0, right_elbow = 0, left_shoulder = 0, left_elbow = 0;
  double right_hip = 0, right_knee = 0, left_hip = 0, left_knee = 0;
};

/// The named poses: "wave", "stride", "cheer", "twirl" (the right hand turns by 3.3 > π).
const std::vector<Pose>& man_poses();

/// The rest pose's vertices moved by `pose` (columns in the order of `rest.vertices`).
Eigen::Matrix2Xd pose_vertices(const Eigen::Matrix2Xd& rest, const Pose& pose);

}  // namespace affinterp::shapes
