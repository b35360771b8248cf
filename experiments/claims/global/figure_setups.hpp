#pragma once
// What the figure claims of Kaji §4–5 (Figs 2–7) share: their inputs, built from the project's generated
// shapes (experiments/inputs/shapes), and the rule that decides, never by looking, whether an interpolation
// shrinks or flips triangles.
#include "experiments/claims/global/animation.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"
#include "theory/global/interpolation.hpp"

#include <nlohmann/json.hpp>

namespace affinterp::claims::global_figures {

/// "Extreme shrink": some triangle keeps at most this fraction of its area.
constexpr double extreme_shrink = 0.1;
/// Constraint weight c of the vertex loci and pinned vertices: strong against the sum of local errors.
constexpr double constraint_weight = 1000;

/// Default options with the given energy and constraints, the local errors summed without weights (§4).
global::InterpolationOptions options_for(global::Energy energy, global::Constraints constraints);

/// Fig 2 / Fig 4's input: the man (rest → "wave") with the loci of the head's top and the lowest foot
/// vertex swung a quarter turn about the shape's centre half-way: u_k(t) through p_k, R_{π/2}-turned
/// midpoint, q_k (the interpolating B-spline of locus.hpp).
struct LociSetup {
  shapes::MeshPairShapes pair;
  global::Constraints constraints;
};
LociSetup swung_loci();

/// The worm (and the graded bar): its two vertices at the fixed end (x = 0) pinned.
global::Constraints worm_base_pins(const global::Mesh& P);

/// An interpolation fails when a triangle flips or shrinks to below extreme_shrink of its area in some frame.
bool fails(const Animation& a);

/// The numbers `fails` decides on, for the evidence.
nlohmann::json summary_of(const Animation& a);

}  // namespace affinterp::claims::global_figures
