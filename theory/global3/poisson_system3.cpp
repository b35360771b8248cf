#include "theory/global3/poisson_system3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/global3/element_maps3.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <string>

namespace affinterp::global3 {

using Eigen::Index;
using Eigen::Matrix3d;
using global::RefusedProblem;

struct PoissonSystem3::Data {
  Eigen::MatrixXi elements;
  Index n = 0;
  Eigen::VectorXd weights;
  std::vector<Eigen::Matrix<double, 4, 3>> W;  ///< W_i = w_i C E_i⁺ (rows beyond d + 1 zero)
  std::vector<Matrix3d> edges;                 ///< E_i (columns beyond d zero)
  std::vector<Matrix3d> pinv;                  ///< E_i⁺ (rows beyond d zero)
  Constraints3 constraints;
  std::vector<global::PinnedVertex> vertex_terms;  ///< the pins, then the loci (constraints3.hpp)
  std::unique_ptr<global::SparseFactor<double>> factor;
  Eigen::VectorXd z;  ///< K⁻¹ 1, for Sherman–Morrison (pins and barycentre)
};

namespace {

/// C: the (d+1) × d map from an element's edges to its corners (row 0 all −1, then the identity).
Eigen::MatrixXd edges_to_corners(int d) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(d + 1, d);
  C.row(0).setConstant(-1);
  C.bottomRows(d).setIdentity();
  return C;
}

/// Unless a locus's points are at least two and finite (`what` names it).
void require_points(const Eigen::Matrix3Xd& points, const std::string& what) {
  if (points.cols() < 2) throw RefusedProblem(what + ": a locus needs at least two points");
  if (!points.allFinite()) throw RefusedProblem(what + ": a locus point is not finite");
}

void require_constraints(const Constraints3& constraints, Index n) {
  for (const global::PinnedVertex& pin : constraints.pinned) {
    if (pin.vertex < 0 || pin.vertex >= n)
      throw RefusedProblem("pinned vertex " + std::to_string(pin.vertex) + " is out of range");
    if (!(pin.weight > 0) || !std::isfinite(pin.weight))
      throw RefusedProblem("pinned vertex " + std::to_string(pin.vertex) + ": the weight must be positive and finite");
  }
  for (const VertexLocus3& locus : constraints.loci) {
    const std::string what = "locus of vertex " + std::to_string(locus.vertex);
    if (locus.vertex < 0 || locus.vertex >= n) throw RefusedProblem(what + ": no such vertex");
    if (!(locus.weight > 0) || !std::isfinite(locus.weight))
      throw RefusedProblem(what + ": the weight must be positive and finite");
    require_points(locus.points, what);
  }
  if (constraints.barycentre) {
    if (!(constraints.barycentre->weight > 0) || !std::isfinite(constraints.barycentre->weight))
      throw RefusedProblem("barycentre locus: the weight must be positive and finite");
    if (constraints.barycentre->points.cols() > 0) require_points(constraints.barycentre->points, "barycentre locus");
  }
  if (constraints.pinned.empty() && constraints.loci.empty() && !constraints.barycentre)
    throw RefusedProblem("nothing fixes the translation: give a barycentre locus, a pinned vertex or a vertex locus");
}

/// W_s, E_s⁺ and L's triplets (w_s C M_s Cᵀ) of every term s = r·m + i, element i of rests[r].
std::vector<Eigen::Triplet<double>> element_terms(std::span<const Mesh3* const> rests, PoissonSystem3::Data& data) {
  const Mesh3& first = *rests.front();
  const Index m = first.element_count();
  const int d = first.corners() - 1;
  // Fixed-capacity types (no heap allocation per element): d ≤ 3.
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
  const Small C = edges_to_corners(d);
  const auto terms = static_cast<std::size_t>(data.elements.cols());
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(terms * static_cast<std::size_t>((d + 1) * (d + 1)));
  data.W.assign(terms, Eigen::Matrix<double, 4, 3>::Zero());
  data.pinv.assign(terms, Matrix3d::Zero());
  data.edges.assign(terms, Matrix3d::Zero());
  for (std::size_t r = 0; r < rests.size(); ++r)
    for (Index i = 0; i < m; ++i) {
      const Index s = static_cast<Index>(r) * m + i;
      const Small E = element_edges(*rests[r], i);
      const Small M = Small(E.transpose() * E).inverse();
      const Small pinv = M * E.transpose();
      const double w = data.weights[s];
      data.pinv[static_cast<std::size_t>(s)].topRows(d) = pinv;
      data.edges[static_cast<std::size_t>(s)].leftCols(d) = E;
      data.W[static_cast<std::size_t>(s)].topRows(d + 1) = w * C * pinv;
      const Small K = w * C * M * C.transpose();
      for (int a = 0; a <= d; ++a)
        for (int b = 0; b <= d; ++b) triplets.emplace_back(first.elements(a, i), first.elements(b, i), K(a, b));
    }
  return triplets;
}

/// K = L + Σ c_k e_k e_kᵀ (+ s e_0 e_0ᵀ without pins), analysed and factorised.
void factorise_system(PoissonSystem3::Data& data, std::vector<Eigen::Triplet<double>> triplets,
                      std::optional<global::SparseBackEnd> back_end) {
  for (const global::PinnedVertex& term : data.vertex_terms)
    triplets.emplace_back(term.vertex, term.vertex, term.weight);
  Eigen::SparseMatrix<double> K(data.n, data.n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  if (data.vertex_terms.empty()) K.coeffRef(0, 0) += K.diagonal().mean();  // the gauge: v_0 = 0
  data.factor = back_end ? global::make_sparse_factor<double>(*back_end) : global::make_sparse_factor<double>(data.n);
  data.factor->analyse(K);
  if (!data.factor->factorise(K, global::frame_threads(static_cast<std::size_t>(data.n), true)))
    throw RefusedProblem("the E^F system is singular: its minimiser is not unique");
  if (!data.vertex_terms.empty() && data.constraints.barycentre) {
    PoissonSystem3::Block ones = PoissonSystem3::Block::Ones(data.n, 1);
    data.factor->solve_in_place(ones, 1);
    data.z = ones.col(0);
  }
}

}  // namespace

PoissonSystem3::PoissonSystem3(const Mesh3& rest, bool area_weighted, const Constraints3& constraints,
                               std::optional<global::SparseBackEnd> back_end)
    : PoissonSystem3(std::array{&rest}, area_weighted, constraints, back_end) {}

PoissonSystem3::PoissonSystem3(std::span<const Mesh3* const> rests, bool area_weighted, const Constraints3& constraints,
                               std::optional<global::SparseBackEnd> back_end)
    : data_(std::make_unique<Data>()) {
  const Mesh3& first = *rests.front();
  const Index m = first.element_count(), terms = m * static_cast<Index>(rests.size());
  require_constraints(constraints, first.vertex_count());
  data_->elements = first.elements.replicate(1, static_cast<Index>(rests.size()));
  data_->n = first.vertex_count();
  data_->constraints = constraints;
  data_->vertex_terms = vertex_terms(constraints);
  data_->weights = Eigen::VectorXd::Ones(terms);
  if (area_weighted)
    for (std::size_t r = 0; r < rests.size(); ++r)
      data_->weights.segment(static_cast<Index>(r) * m, m) = element_measures(*rests[r]);
  factorise_system(*data_, element_terms(rests, *data_), back_end);
}

PoissonSystem3::~PoissonSystem3() = default;
PoissonSystem3::PoissonSystem3(PoissonSystem3&&) noexcept = default;
PoissonSystem3& PoissonSystem3::operator=(PoissonSystem3&&) noexcept = default;

PoissonSystem3::Block PoissonSystem3::right_hand_side(std::span<const Matrix3d> A, std::size_t threads) const {
  const Data& data = *data_;
  Block b = Block::Zero(data.n, 3);
  // Scattered term by term, in order, each thread adding only the corners of its own range of vertices: every
  // vertex sums its terms in increasing order whatever the number of threads, and the terms are read as they are
  // stored (where gathering each vertex's star jumped between them).
  global::for_each_range(static_cast<std::size_t>(data.n), threads, [&](std::size_t first, std::size_t last) {
    for (Index s = 0; s < data.elements.cols(); ++s)
      for (Index c = 0; c < data.elements.rows(); ++c) {
        const auto k = static_cast<std::size_t>(data.elements(c, s));
        if (k < first || k >= last) continue;
        const auto& W = data.W[static_cast<std::size_t>(s)];
        const Matrix3d& A_s = A[static_cast<std::size_t>(s)];
        double* b_k = b.data() + 3 * k;  // (W_s A_sᵀ)(c, j) = Σ_l W_s(c, l) A_s(j, l)
        for (Index j = 0; j < 3; ++j) b_k[j] += W(c, 0) * A_s(j, 0) + W(c, 1) * A_s(j, 1) + W(c, 2) * A_s(j, 2);
      }
  });
  return b;
}

Eigen::Matrix3Xd PoissonSystem3::solve(Block b, const ConstraintTargets3& targets, std::size_t threads) const {
  const Data& data = *data_;
  const auto& pinned = data.vertex_terms;
  for (std::size_t j = 0; j < pinned.size(); ++j)
    b.row(pinned[j].vertex) += pinned[j].weight * targets.vertices.col(static_cast<Index>(j)).transpose();
  const bool sherman_morrison = !pinned.empty() && data.constraints.barycentre;
  const double n = static_cast<double>(data.n);
  if (sherman_morrison) b.rowwise() += (data.constraints.barycentre->weight / n) * targets.barycentre.transpose();
  data.factor->solve_in_place(b, threads);
  if (sherman_morrison) {  // (K + c 11ᵀ)⁻¹ r = y − z c (1ᵀy) / (1 + c 1ᵀz), c = c_o/n²
    const double c = data.constraints.barycentre->weight / (n * n);
    const Eigen::RowVector3d sum_y = b.colwise().sum();
    b -= data.z * (c * sum_y / (1 + c * data.z.sum()));
  } else if (pinned.empty()) {
    const Eigen::RowVector3d shift = targets.barycentre.transpose() - b.colwise().mean();
    b.rowwise() += shift;
  }
  return b.transpose();
}

namespace {

/// X_s: term s's edges in the frame v, the columns beyond d zero as E_s⁺'s rows are.
Matrix3d frame_edges(const PoissonSystem3::Data& data, const Eigen::Matrix3Xd& v, Index s) {
  Matrix3d X = Matrix3d::Zero();
  for (Index c = 1; c < data.elements.rows(); ++c)
    X.col(c - 1) = v.col(data.elements(c, s)) - v.col(data.elements(0, s));
  return X;
}

}  // namespace

std::vector<Matrix3d> PoissonSystem3::gradients(const Eigen::Matrix3Xd& v, std::size_t threads) const {
  const Data& data = *data_;
  std::vector<Matrix3d> B(static_cast<std::size_t>(data.elements.cols()));
  global::for_each_range(B.size(), threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) B[s] = frame_edges(data, v, static_cast<Index>(s)) * data.pinv[s];
  });
  return B;
}

double PoissonSystem3::energy(std::span<const Matrix3d> A, const Eigen::Matrix3Xd& v,
                              const ConstraintTargets3& targets) const {
  const Data& data = *data_;
  double E = 0;
  for (Index i = 0; i < data.elements.cols(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    E += data.weights[i] * ((frame_edges(data, v, i) - A[s] * data.edges[s]) * data.pinv[s]).squaredNorm();
  }
  const auto& pinned = data.vertex_terms;
  for (std::size_t j = 0; j < pinned.size(); ++j)
    E += pinned[j].weight * (v.col(pinned[j].vertex) - targets.vertices.col(static_cast<Index>(j))).squaredNorm();
  if (data.constraints.barycentre)
    E += data.constraints.barycentre->weight * (v.rowwise().mean() - targets.barycentre).squaredNorm();
  return E;
}

Index PoissonSystem3::vertex_count() const { return data_->n; }
int PoissonSystem3::corners() const { return static_cast<int>(data_->elements.rows()); }
const Eigen::VectorXd& PoissonSystem3::weights() const { return data_->weights; }
const Constraints3& PoissonSystem3::constraints() const { return data_->constraints; }
global::SparseBackEnd PoissonSystem3::back_end() const { return data_->factor->back_end(); }

}  // namespace affinterp::global3
