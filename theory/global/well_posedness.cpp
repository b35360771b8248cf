#include "theory/global/well_posedness.hpp"

#include "theory/global/refused_problem.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace affinterp::global {
namespace {

/// Σ c LᵀL over the terms, L the 2×4 map (x, y, d) ↦ ℓ((xI + yJ)p + d) = x P + y JP + s d with
/// P = Σ α_k p_k, s = Σ α_k, p_k measured from the barycentre in units of the mesh's spread (the same
/// motions, parameterised so that the form does not depend on the mesh's position or units).
Eigen::MatrixXd constraint_on_similarity_motions(const Mesh& source, const std::vector<ConstraintTerm>& terms) {
  const Eigen::Vector2d barycentre = source.vertices.rowwise().mean();
  const double spread =
      std::sqrt((source.vertices.colwise() - barycentre).squaredNorm() / static_cast<double>(source.vertex_count()));
  Eigen::MatrixXd form = Eigen::MatrixXd::Zero(4, 4);
  for (const ConstraintTerm& term : terms) {
    Eigen::Vector2d P = Eigen::Vector2d::Zero();
    double s = 0;
    for (const auto& [k, alpha] : term.coefficients)
      P += alpha * (source.vertices.col(k) - barycentre) / spread, s += alpha;
    Eigen::Matrix<double, 2, 4> L;
    L << P.x(), -P.y(), s, 0, P.y(), P.x(), 0, s;
    form += term.weight * L.transpose() * L;
  }
  return form;
}

/// A ratio of eigenvalues, so that it does not depend on the constraints' common weight.
bool definite(const Eigen::MatrixXd& form) {
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(form).eigenvalues();
  return eigenvalues.minCoeff() > 1e-12 * eigenvalues.maxCoeff();
}

}  // namespace

void require_well_posed(const Mesh& source, const std::vector<ConstraintTerm>& terms, bool similarity_invariant,
                        const std::string& energy_name) {
  const Eigen::MatrixXd form = constraint_on_similarity_motions(source, terms);
  const bool fixes_translation = definite(form.bottomRightCorner(2, 2));
  if (!fixes_translation)
    throw RefusedProblem("the global error with " + energy_name +
                         " is translation invariant and no constraint fixes translation, so its minimiser is not "
                         "unique: add a pinned vertex, a vertex locus or a barycentre locus");
  if (similarity_invariant && !definite(form))
    throw RefusedProblem(energy_name +
                         " is invariant under rotation and scale and the constraints fix only translation, so the "
                         "minimum is the collapse of the shape onto a point: add a second pinned vertex or vertex "
                         "locus, or an edge direction");
}

}  // namespace affinterp::global
