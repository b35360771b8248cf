#pragma once
// What a caller chooses for the global interpolation of Kaji §4: the local homotopy A_i(t) (§3), the
// local error function E_i, the rotation branch of each θ_i, the blend and symmetrisation
// ("Improvements"), the constraint function C and the time range. The bottom of theory/global: every other
// header of the engine reads these types from here, and the facade interpolation.hpp includes this file.
#include <Eigen/Core>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
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
/// Named as the paper names them: E^F, E^S, E^R. E^S and E^R are both invariant under similarity; E^S compares
/// the triangle's points, E^R the linear maps.
enum class Energy {
  F,  ///< E^F = ‖A − B‖²_F  [ACOL00]
  S,  ///< E^S = min_{s,δ} Σ_{k∈τ} ‖s R_δ A p_k − B p_k‖²  [WW95], p_k taken from the triangle's centroid
  R,  ///< E^R = min_{s,δ} ‖s R_δ A − B‖²_F, eq. (4), in the Appendix's closed form
  blend,  ///< w_i E^F + (1 − w_i) E^R ("Improvements")
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
  Energy energy = Energy::R;
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

/// One value of an option enum, the one name the CLI, the Python module and metrics.json give it, and what it
/// means (for help texts).
template <class Enum>
struct NamedValue {
  Enum value;
  std::string_view name;
  std::string_view meaning;
};

/// What an option enum is called and its values' names: the one table to_string, parse_option and the front
/// ends' choices read.
template <class Enum>
struct OptionNames;

template <>
struct OptionNames<LocalHomotopy> {
  static constexpr std::string_view what = "local homotopy";
  static constexpr std::array<NamedValue<LocalHomotopy>, 4> values{{
      {LocalHomotopy::exp, "exp", "R^t S^t, Kaji eq. (3)"},
      {LocalHomotopy::polar, "polar", "R^t ((1-t) I + t S), Kaji eq. (2) [ACOL00]"},
      {LocalHomotopy::linear, "linear", "(1-t) I + t A"},
      {LocalHomotopy::svd, "svd", "R_{t alpha} ((1-t) I + t D) R_{t beta} for A = R_alpha D R_beta"},
  }};
};

template <>
struct OptionNames<Energy> {
  static constexpr std::string_view what = "energy";
  static constexpr std::array<NamedValue<Energy>, 4> values{{
      {Energy::F, "F", "E^F, the Frobenius distance of A and B [ACOL00]"},
      {Energy::S, "S", "E^S, the triangle's points up to similarity [WW95]"},
      {Energy::R, "R", "E^R, the linear maps up to similarity, Kaji eq. (4)"},
      {Energy::blend, "blend", "w E^F + (1 - w) E^R"},
  }};
};

template <>
struct OptionNames<RotationBranch> {
  static constexpr std::string_view what = "rotation branch";
  static constexpr std::array<NamedValue<RotationBranch>, 2> values{{
      {RotationBranch::consistent, "consistent", "each angle within pi of its neighbour's, so it may exceed pi"},
      {RotationBranch::principal, "principal", "each angle in (-pi, pi]"},
  }};
};

template <class Enum>
concept OptionEnum = requires {
  OptionNames<Enum>::values;
};

template <OptionEnum Enum>
std::string to_string(Enum value) {
  for (const auto& named : OptionNames<Enum>::values)
    if (named.value == value) return std::string(named.name);
  return "?";
}

/// The names of `Enum`'s values in the table's order, comma separated ("exp, polar, linear, svd").
template <OptionEnum Enum>
std::string option_choices() {
  std::string list;
  for (const auto& named : OptionNames<Enum>::values) list += (list.empty() ? "" : ", ") + std::string(named.name);
  return list;
}

/// The value named `name` (exactly as to_string writes it). Throws std::invalid_argument naming the choices.
template <OptionEnum Enum>
Enum parse_option(std::string_view name) {
  for (const auto& named : OptionNames<Enum>::values)
    if (named.name == name) return named.value;
  throw std::invalid_argument("unknown " + std::string(OptionNames<Enum>::what) + " '" + std::string(name) +
                              "' (expected " + option_choices<Enum>() + ")");
}

/// Throws RefusedProblem (mesh_validation.hpp) unless the options are ones the engine accepts for a mesh of
/// `triangles` triangles: the one place their rules live (a finite time range with t_begin <= t_end; blend
/// weights in [0, 1], one per triangle when given per triangle). The front ends leave these checks to it.
void require_valid_options(const InterpolationOptions& options, Eigen::Index triangles);

}  // namespace affinterp::global
