#pragma once
// What a caller chooses for the global interpolation of Kaji §4: the local homotopy A_i(t) (§3), the
// local error function E_i, the rotation branch of each θ_i, the blend and symmetrisation
// ("Improvements"), the constraint function C and the time range. The bottom of theory/global: every other
// header of the engine reads these types from here, and the facade interpolation.hpp includes this file.
#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace affinterp::global {

/// The local homotopy A_i(t) between I and A_i (Kaji §3).
enum class LocalHomotopy {
  exp,     ///< A^E(t) = R_θ^t S^t, eq. (3) (Kaji's proposal; the default)
  polar,   ///< A^P(t) = R_{tθ}((1−t)I + tS)  [ACOL00]
  linear,  ///< A^L(t) = (1−t)I + tA
  svd,     ///< R_{tα}((1−t)I + tD)R_{tβ} for A = R_α D R_β
};

/// The local error function E_i(A_i(t), B_i(t)) (Kaji §4).
enum class Energy {
  frobenius,  ///< E^F = ‖A − B‖²_F  [ACOL00]
  procrustes,  ///< E^S = min_{s,δ} Σ_{k∈τ} ‖s R_δ A p_k − B p_k‖²  [WW95], p_k taken from the triangle's centroid
  similarity,  ///< E^R = min_{s,δ} ‖s R_δ A − B‖²_F, eq. (4), in the Appendix's closed form
  blend,       ///< w_i E^F + (1 − w_i) E^R ("Improvements")
};

/// How the polar angle θ_i of each A_i is chosen among θ_i + 2πk (the rotation consistency problem).
enum class RotationBranch {
  principal,   ///< θ_i ∈ (−π, π] independently per triangle (what a plain polar decomposition gives)
  consistent,  ///< breadth-first over the dual graph from triangle 0: θ_j + 2πk_j within π of its parent's
};

/// Vertex `vertex` should trace u(t): the interpolating B-spline through `points` at t = 0, 1/(N−1), …, 1
/// (locus.hpp; two points: the straight segment). Adds c ‖u(t) − v(t)‖² (Kaji §4).
struct VertexLocus {
  Eigen::Index vertex = 0;
  Eigen::Matrix2Xd points;
  double weight = 1.0;  ///< c_i > 0
};

/// Vertex `vertex` should move on the straight line (1−t)p_k + t q_k: the [ACOL00] constraint in its
/// intended form. Adds c ‖(1−t)p_k + t q_k − v_k(t)‖².
struct PinnedVertex {
  Eigen::Index vertex = 0;
  double weight = 1.0;
};

/// The direction of the edge v_i − v_j should follow e_ij(t). Adds c ‖v_i(t) − v_j(t) − e_ij(t)‖² (Kaji §4).
struct EdgeDirection {
  enum class Path {
    local_homotopy,  ///< e(t) = A_τ(t)(p_i − p_j) for the first triangle τ holding the edge
    linear,          ///< e(t) = (1−t)(p_i − p_j) + t(q_i − q_j)
  };
  Eigen::Index i = 0, j = 0;
  Path path = Path::local_homotopy;
  double weight = 1.0;
};

/// The barycentre Σ v_k / n should trace u_o(t): the B-spline through `points` as for VertexLocus; no
/// points means the straight line from the source's to the target's barycentre. Adds c_o ‖Σv/n − u_o‖².
struct BarycentreLocus {
  Eigen::Matrix2Xd points;
  double weight = 1.0;
};

/// The constraint function C (Kaji §4): a sum of the terms above.
struct Constraints {
  std::vector<PinnedVertex> pinned;
  std::vector<VertexLocus> loci;
  std::vector<EdgeDirection> edges;
  std::optional<BarycentreLocus> barycentre;
};

/// The sparse Cholesky back-end (sparse_factor.hpp).
enum class SparseBackEnd {
  simplicial,  ///< our up-looking LDLᴴ (simplicial_factor.hpp)
  cholmod,     ///< CHOLMOD's supernodal LLᴴ (when built in)
};

struct InterpolationOptions {
  LocalHomotopy homotopy = LocalHomotopy::exp;
  Energy energy = Energy::similarity;
  RotationBranch rotation_branch = RotationBranch::consistent;
  /// w_i of the blend, one per triangle; empty means `blend_weight` for every triangle.
  Eigen::VectorXd blend_weights;
  double blend_weight = 0.5;
  /// E_i ← Area(p_{i1}, p_{i2}, p_{i3}) E_i ("Improvements"): on by default, as Kaji recommend it ("it is
  /// reasonable to weight by the areas of the initial triangles", Fig. 7 against the unweighted Fig. 6) and
  /// as it makes the global error a sum over the shape's area, not over its triangles, so that refining a
  /// region does not make it stiffer. False gives the plain sum of Kaji §4 (Figs. 2–6).
  bool area_weighted = true;
  /// E′(t) = E(t) + E^{−1}(1 − t): the reverse problem's energy in the same unknowns ("Improvements").
  bool symmetric = false;
  Constraints constraints;
  /// The times vertices_at accepts (loci are parameterised on [0, 1] and extended by their end cubics).
  double t_begin = 0.0, t_end = 1.0;
  /// The sparse back-end; none: chosen by the mesh's size (sparse_factor.hpp). Same minimiser either way,
  /// to rounding; for benchmarks comparing them.
  std::optional<SparseBackEnd> back_end;
};

std::string to_string(LocalHomotopy homotopy);
std::string to_string(Energy energy);
std::string to_string(RotationBranch branch);
/// Parses the names used by to_string ("exp", "polar", "linear", "svd"; "F", "S", "R", "blend";
/// "principal", "consistent"). Throws std::invalid_argument on anything else.
LocalHomotopy parse_local_homotopy(const std::string& name);
Energy parse_energy(const std::string& name);
RotationBranch parse_rotation_branch(const std::string& name);

}  // namespace affinterp::global
