#include "experiments/inputs/shapes/man.hpp"

#include "experiments/inputs/shapes/outline.hpp"
#include "experiments/inputs/shapes/triangulate.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace affinterp::shapes {

namespace {

using Eigen::Vector2d;
using std::numbers::pi;

/// The right half of the outline, clockwise from the top of the head to the crotch (x ≥ 0).
Outline right_half() {
  Outline half;
  const Vector2d head(0, 1.55);
  const double head_radius = 0.3, neck = 0.12;
  const double neck_angle = std::atan2(-std::sqrt(head_radius * head_radius - neck * neck), neck);
  append_arc(half, head, head_radius, pi / 2, neck_angle, 8);  // from the crown down to the neck
  half.emplace_back(neck, 1.22);
  half.emplace_back(0.3, 1.15);                                    // shoulder
  append_arc(half, Vector2d(1.2, 1.0), 0.15, pi / 2, -pi / 2, 6);  // top of the arm, then the hand
  half.emplace_back(0.35, 0.85);                                   // armpit
  half.emplace_back(0.35, 0.15);                                   // hip
  append_arc(half, Vector2d(0.4, -0.95), 0.15, 0, -pi, 6);         // outer ankle, then the foot
  half.emplace_back(0.0, -0.1);                                    // crotch
  return half;
}

/// A joint of a limb: along the limb's axis the bend angle grows linearly from 0 at `start` to the pose's
/// angle at `end` (a circular bend of the axis between them).
struct Joint {
  double start, end;
  double Pose::*angle;
};

/// A limb: the points of `region` bend about the axis from `origin` along the unit vector `axis`.
struct Limb {
  Vector2d origin, axis;
  std::vector<Joint> joints;  ///< in order along the axis, not overlapping; angles add up
  bool (*region)(const Vector2d&);
};

const std::vector<Limb>& limbs() {
  static const std::vector<Limb> list = [] {
    const Vector2d right_leg = Vector2d(0.2, -1.1).normalized(), left_leg(-right_leg.x(), right_leg.y());
    return std::vector<Limb>{
        {{0, 1.15},
         {0, 1},
         {{0.07, 0.2, &Pose::neck}},
         [](const Vector2d& p) { return p.y() > 1.15 && std::abs(p.x()) < 0.3; }},
        {{0.35, 1.0},
         {1, 0},
         {{0.1, 0.45, &Pose::right_shoulder}, {0.5, 0.75, &Pose::right_elbow}},
         [](const Vector2d& p) { return p.x() > 0.35 && p.y() > 0.8; }},
        {{-0.35, 1.0},
         {-1, 0},
         {{0.1, 0.45, &Pose::left_shoulder}, {0.5, 0.75, &Pose::left_elbow}},
         [](const Vector2d& p) { return p.x() < -0.35 && p.y() > 0.8; }},
        {{0.2, 0.15},
         right_leg,
         {{0.3, 0.6, &Pose::right_hip}, {0.65, 0.9, &Pose::right_knee}},
         [](const Vector2d& p) { return p.x() >= 0 && p.y() < 0.15; }},
        {{-0.2, 0.15},
         left_leg,
         {{0.3, 0.6, &Pose::left_hip}, {0.65, 0.9, &Pose::left_knee}},
         [](const Vector2d& p) { return p.x() < 0 && p.y() < 0.15; }},
    };
  }();
  return list;
}

using Complex = std::complex<double>;

/// ∫_a^b e^{iφ(s)} ds for φ linear on [a, b]: (b − a) e^{i(φa+φb)/2} sinc((φb − φa)/2), free of cancellation.
Complex integral_of_direction(double a, double b, double phi_a, double phi_b) {
  const double half = (phi_b - phi_a) / 2;
  const double sinc = half == 0 ? 1 : std::sin(half) / half;
  return (b - a) * sinc * std::polar(1.0, (phi_a + phi_b) / 2);
}

/// The bent image of p (in the limb's region): the axis point at distance u turns by φ(u) and moves to
/// the end of the bent axis, c(u) = origin + axis·∫_0^u e^{iφ}; the offset v across the axis turns with it.
/// Orientation is kept while |v|·φ' < 1 (Kaji's det > 0 for every triangle of the limb).
Vector2d bend(const Limb& limb, const Pose& pose, const Vector2d& p) {
  const Vector2d normal(-limb.axis.y(), limb.axis.x());
  const double u = (p - limb.origin).dot(limb.axis), v = (p - limb.origin).dot(normal);
  // φ is piecewise linear with knots 0, start1, end1, start2, end2.
  std::vector<std::pair<double, double>> knots = {{0.0, 0.0}};  // (s, φ(s))
  double angle = 0;
  for (const Joint& joint : limb.joints) {
    knots.emplace_back(joint.start, angle);
    angle += pose.*joint.angle;
    knots.emplace_back(joint.end, angle);
  }
  Complex centre = 0;
  double phi = 0;
  for (std::size_t j = 1; j < knots.size() && knots[j - 1].first < u; ++j) {
    const auto [a, phi_a] = knots[j - 1];
    const auto [b, phi_b] = knots[j];
    const double end = std::min(b, u);
    phi = phi_a + (phi_b - phi_a) * (end - a) / (b - a);
    centre += integral_of_direction(a, end, phi_a, phi);
  }
  if (u > knots.back().first) {
    phi = knots.back().second;
    centre += (u - knots.back().first) * std::polar(1.0, phi);
  }
  const Complex axis(limb.axis.x(), limb.axis.y());
  const Complex image =
      Complex(limb.origin.x(), limb.origin.y()) + axis * (centre + Complex(0, v) * std::polar(1.0, phi));
  return {image.real(), image.imag()};
}

}  // namespace

global::Mesh man(double max_edge) {
  Outline outline = right_half();
  Outline left = outline;  // mirror image, in reverse order so the polygon stays simple
  for (auto it = left.rbegin(); it != left.rend(); ++it)
    if (it->x() > 1e-12) outline.emplace_back(-it->x(), it->y());
  return triangulate(outline, max_edge);
}

const std::vector<Pose>& man_poses() {
  static const std::vector<Pose> poses = [] {
    Pose wave{.name = "wave"};
    wave.neck = 0.2, wave.right_shoulder = 1.1, wave.right_elbow = 0.9, wave.left_shoulder = 0.7;
    Pose stride{.name = "stride"};
    stride.right_shoulder = -0.5, stride.left_shoulder = 0.5;
    stride.right_hip = 0.35, stride.right_knee = -0.4, stride.left_hip = -0.35, stride.left_knee = 0.4;
    Pose cheer{.name = "cheer"};
    cheer.right_shoulder = 1.2, cheer.right_elbow = 0.5, cheer.left_shoulder = -1.2, cheer.left_elbow = -0.5;
    cheer.right_hip = 0.3, cheer.right_knee = -0.6, cheer.left_hip = -0.3, cheer.left_knee = 0.6;
    Pose twirl{.name = "twirl"};
    twirl.neck = -0.25, twirl.right_shoulder = 1.9, twirl.right_elbow = 1.4, twirl.left_shoulder = 0.9;
    twirl.left_elbow = -0.6;
    return std::vector<Pose>{wave, stride, cheer, twirl};
  }();
  return poses;
}

Eigen::Matrix2Xd pose_vertices(const Eigen::Matrix2Xd& rest, const Pose& pose) {
  Eigen::Matrix2Xd posed = rest;
  for (Eigen::Index k = 0; k < rest.cols(); ++k)
    for (const Limb& limb : limbs())
      if (limb.region(rest.col(k))) {
        posed.col(k) = bend(limb, pose, rest.col(k));
        break;
      }
  return posed;
}

}  // namespace affinterp::shapes
