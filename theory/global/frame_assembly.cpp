#include "theory/global/frame_assembly.hpp"

#include "theory/global/hermitian_local_error.hpp"
#include "theory/global/parallel_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace affinterp::global {
namespace {

Corners<double> corners_of(const Mesh& mesh, Eigen::Index i) {
  Corners<double> p;
  for (int c = 0; c < 3; ++c) p.col(c) = mesh.corner(i, c);
  return p;
}

std::vector<TriangleTerm> triangle_terms(const Mesh& reference, const InterpolationOptions& options) {
  std::vector<TriangleTerm> terms(static_cast<std::size_t>(reference.triangle_count()));
  for_each_range(
      terms.size(), ranges_for(terms.size(), triangles_per_thread), [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
          const auto i = static_cast<Eigen::Index>(k);
          TriangleTerm& term = terms[k];
          for (int c = 0; c < 3; ++c) term.vertex[static_cast<std::size_t>(c)] = reference.triangles(c, i);
          term.corners = corners_of(reference, i);
          term.D = linear_part_operator(term.corners);
          term.weight = options.area_weighted ? std::abs(reference.doubled_signed_area(i)) / 2 : 1.0;
          if (options.energy == Energy::blend)
            term.frobenius_share = options.blend_weights.size() > 0 ? options.blend_weights[i] : options.blend_weight;
        }
      });
  return terms;
}

/// E_i(A, B(x)) of one term, times its weight.
TriangleQuadratic<double> local_error(Energy energy, const TriangleTerm& term, const Eigen::Matrix2d& A) {
  switch (energy) {
    case Energy::F:
      return frobenius_quadratic(term.D, A) * term.weight;
    case Energy::R:
      return similarity_quadratic(term.D, A) * term.weight;
    case Energy::blend:
      return blend_quadratic(term.D, A, term.frobenius_share) * term.weight;
    case Energy::S:
      return procrustes_quadratic(term.corners, A) * term.weight;
  }
  return {};
}

/// ‖Y − (⟨X, Y⟩ X + ⟨JX, Y⟩ JX)/‖X‖²‖²: the residual of projecting Y onto span{X, JX} (⟨X, JX⟩ = 0,
/// ‖JX‖ = ‖X‖), which is min_{s,δ} ‖s R_δ X − Y‖² (Kaji Appendix). Written as a residual rather than as
/// ‖Y‖² − (⟨X, Y⟩² + ⟨JX, Y⟩²)/‖X‖², it is never negative, also where Y is nearly a similarity of X.
template <class Matrix>
double similarity_residual(const Matrix& X, const Matrix& Y) {
  const Matrix JX = rotation_J<double>() * X;
  return (Y - (frobenius_inner(X, Y) * X + frobenius_inner(JX, Y) * JX) / X.squaredNorm()).squaredNorm();
}

/// E_i(A, B) of one term split into its E^F part and the rest, times the term's weight: E^F = ‖A − B‖², eq. (4)'s
/// E^R = min ‖s R_δ A − B‖², and E^S = min ‖s R_δ X − Y‖² with X = A P̃, Y = V Π (procrustes_quadratic).
std::pair<double, double> local_error_value(Energy energy, const TriangleTerm& term, const Eigen::Matrix2d& A,
                                            const Eigen::Matrix<double, 2, 3>& V) {
  if (energy == Energy::S) {
    const Eigen::Matrix<double, 2, 3> X = A * (term.corners.colwise() - term.corners.rowwise().mean());
    const Eigen::Matrix<double, 2, 3> Y = V.colwise() - V.rowwise().mean();
    return {0.0, term.weight * similarity_residual(X, Y)};
  }
  const Eigen::Matrix2d B = V * term.D;  // eq. (1)
  const double w = detail::frobenius_share(energy, term.frobenius_share);
  const double frobenius = w > 0 ? w * frobenius_error(A, B) : 0.0;
  const double similarity = w < 1 ? (1 - w) * similarity_residual(A, B) : 0.0;
  return {term.weight * frobenius, term.weight * similarity};
}

}  // namespace

FrameAssembly::FrameAssembly(const Mesh& source, const Mesh& target, const InterpolationOptions& options,
                             const LocalPaths& forward, const LocalPaths* reverse,
                             std::vector<ConstraintTerm> constraints)
    : energy_(options.energy),
      n_(source.vertex_count()),
      forward_(forward),
      reverse_(reverse),
      forward_terms_(triangle_terms(source, options)),
      constraints_(std::move(constraints)),
      stars_(vertex_stars(source.triangles, source.vertex_count())) {
  if (reverse_) reverse_terms_ = triangle_terms(target, options);
  isotropic_ =
      energy_ == Energy::F ||
      (energy_ == Energy::blend && std::all_of(forward_terms_.begin(), forward_terms_.end(),
                                               [](const TriangleTerm& term) { return term.frobenius_share == 1.0; }));
  build_pattern();
}

TriangleQuadratic<double> FrameAssembly::triangle_quadratic(Eigen::Index i, double t) const {
  const auto k = static_cast<std::size_t>(i);
  TriangleQuadratic<double> q = local_error(energy_, forward_terms_[k], forward_.at(i, t));
  if (reverse_) q += local_error(energy_, reverse_terms_[k], reverse_->at(i, 1 - t));  // E^{-1}(1 − t)
  return q;
}

void FrameAssembly::build_pattern() {
  // Column l of the lower triangle: l itself and the vertices k > l that share a triangle of l's star or a
  // sparse constraint term with it.
  std::vector<std::pair<int, int>> coupled;  // (l, k), k > l, of the sparse constraint terms
  for (const ConstraintTerm& term : constraints_)
    if (!term.dense())
      for (const auto& [k, alpha_k] : term.coefficients)
        for (const auto& [l, alpha_l] : term.coefficients)
          if (k > l) coupled.emplace_back(static_cast<int>(l), static_cast<int>(k));
  std::sort(coupled.begin(), coupled.end());
  std::vector<int> outer(static_cast<std::size_t>(n_) + 1, 0), inner, rows;
  inner.reserve(4 * static_cast<std::size_t>(n_));
  auto next_coupled = coupled.begin();
  for (int l = 0; l < n_; ++l) {
    rows.assign(1, l);
    for (int s = stars_.start[static_cast<std::size_t>(l)]; s < stars_.start[static_cast<std::size_t>(l) + 1]; ++s)
      for (const Eigen::Index k :
           forward_terms_[static_cast<std::size_t>(stars_.triangle[static_cast<std::size_t>(s)])].vertex)
        if (k > l) rows.push_back(static_cast<int>(k));
    for (; next_coupled != coupled.end() && next_coupled->first == l; ++next_coupled)
      rows.push_back(next_coupled->second);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    inner.insert(inner.end(), rows.begin(), rows.end());
    outer[static_cast<std::size_t>(l) + 1] = static_cast<int>(inner.size());
  }
  pattern_.resize(n_, n_);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill_n(pattern_.valuePtr(), inner.size(), std::complex<double>(0.0));

  auto slot = [&](Eigen::Index row, Eigen::Index col) -> int {
    const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
    const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, static_cast<int>(row)) - pattern_.innerIndexPtr());
  };
  triangle_slots_.assign(9 * forward_terms_.size(), -1);
  const std::size_t m = forward_terms_.size();
  for_each_range(m, ranges_for(m, triangles_per_thread), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b)
          if (const Eigen::Index row = forward_terms_[i].vertex[a], col = forward_terms_[i].vertex[b]; row >= col)
            triangle_slots_[9 * i + 3 * a + b] = slot(row, col);
  });

  constant_values_.assign(static_cast<std::size_t>(pattern_.nonZeros()), 0.0);
  for (const ConstraintTerm& term : constraints_)
    if (!term.dense())
      for (const auto& [k, alpha_k] : term.coefficients)
        for (const auto& [l, alpha_l] : term.coefficients)
          if (k >= l) constant_values_[static_cast<std::size_t>(slot(k, l))] += term.weight * alpha_k * alpha_l;
  // every triangle's H₀, which does not change with t (hermitian_local_error.hpp), in triangle order
  for (std::size_t i = 0; i < m; ++i) {
    const int* slots = triangle_slots_.data() + 9 * i;
    for (const std::vector<TriangleTerm>* terms : {&forward_terms_, &reverse_terms_})
      if (!terms->empty()) {
        const TriangleTerm& term = (*terms)[i];
        const Eigen::Matrix3d H_0 = hermitian_constant_part(energy_, term.D) * term.weight;
        for (int e = 0; e < 9; ++e)
          if (slots[e] >= 0) constant_values_[static_cast<std::size_t>(slots[e])] += H_0(e / 3, e % 3);
      }
  }

  // A dense term c |Σ α_k z_k − r|² (the barycentre) is c α αᵀ, left to the minimiser. It is grounded when
  // it alone fixes translation: every triangle's error is translation invariant, and so is a sparse term
  // whose coefficients sum to 0 (an edge direction), so H 1 = 0 exactly when every sparse term's do.
  bool translation_invariant = true;
  for (const ConstraintTerm& term : constraints_) {
    double sum = 0;
    for (const auto& [k, alpha_k] : term.coefficients) sum += alpha_k;
    if (term.dense()) {
      eigen_assert(!dense_ && "one dense term, the barycentre");
      dense_ = DenseTerm{Eigen::VectorXd::Zero(n_), term.weight, sum != 0};
      for (const auto& [k, alpha_k] : term.coefficients) dense_->alpha[k] = alpha_k;
    } else if (sum != 0) {
      translation_invariant = false;
    }
  }
  if (dense_) dense_->grounded = dense_->grounded && translation_invariant;
}

void FrameAssembly::matrix_at(double t, SparseMatrix& H, std::size_t threads) const {
  eigen_assert(H.nonZeros() == pattern_.nonZeros() && "H must have the structure of pattern()");
  // H(t) = the constraints + Σ H₀ (constant_values_) − Σ c v v*, each triangle's rank-one term at its A_i(t).
  // On `threads` threads, chunk by chunk of triangles: first the chunk's terms (the local paths' A_i(t)) by
  // ranges of triangles, then their sums by ranges of H's entries, each thread subtracting the terms that fall
  // in its range in triangle order: each entry's sum the same whatever their number. The chunks bound the terms
  // kept (at 1M triangles all of them took 64 MB a worker, which put a batch over 2 GB: bench_scale)
  std::complex<double>* values = H.valuePtr();
  const auto entries = static_cast<std::size_t>(H.nonZeros());
  for_each_range(entries, threads, [&](std::size_t first, std::size_t last) {
    std::copy(constant_values_.begin() + static_cast<std::ptrdiff_t>(first),
              constant_values_.begin() + static_cast<std::ptrdiff_t>(last), values + first);
  });
  const std::size_t m = isotropic_ ? 0 : forward_terms_.size(), chunk = std::size_t{1} << 17;
  // kept by the calling thread from frame to frame, as right_hand_side_at's
  thread_local std::vector<HermitianRankOne> forward_kept, backward_kept;
  std::vector<HermitianRankOne>&forward = forward_kept, &backward = backward_kept;
  forward.resize(std::min(m, chunk)), backward.resize(reverse_ ? std::min(m, chunk) : 0);
  auto rank_one_of = [&](const TriangleTerm& term, const Eigen::Matrix2d& A) {
    HermitianRankOne rank_one = hermitian_rank_one_part(energy_, term.D, term.corners, A, term.frobenius_share);
    rank_one.c *= term.weight;
    return rank_one;
  };
  for (std::size_t begin = 0; begin < m; begin += chunk) {
    const std::size_t end = std::min(m, begin + chunk);
    for_each_range(end - begin, threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = begin + first; i < begin + last; ++i) {
        forward[i - begin] = rank_one_of(forward_terms_[i], forward_.at(static_cast<Eigen::Index>(i), t));
        if (reverse_)  // E^{-1}(1 − t)
          backward[i - begin] = rank_one_of(reverse_terms_[i], reverse_->at(static_cast<Eigen::Index>(i), 1 - t));
      }
    });
    for_each_range(entries, threads, [&](std::size_t first, std::size_t last) {
      auto subtract = [&](const HermitianRankOne& rank_one, const int* slots) {
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            if (const auto s = static_cast<std::size_t>(slots[3 * a + b]); s >= first && s < last)  // −1: none
              values[s] -= rank_one.c * (rank_one.v[a] * std::conj(rank_one.v[b]));
      };
      for (std::size_t i = begin; i < end; ++i) {
        const int* slots = triangle_slots_.data() + 9 * i;
        subtract(forward[i - begin], slots);
        if (reverse_) subtract(backward[i - begin], slots);
      }
    });
  }
  // grounded at vertex 0: column 0 of the lower triangle is (H_00, 0, …, 0), the diagonal first
  if (dense_ && dense_->grounded)
    for (int s = H.outerIndexPtr()[0] + 1; s < H.outerIndexPtr()[1]; ++s) values[s] = 0.0;
}

Eigen::VectorXcd FrameAssembly::right_hand_side_at(double t, std::size_t threads) const {
  Eigen::VectorXcd u = Eigen::VectorXcd::Zero(n_);
  if (energy_ == Energy::F || energy_ == Energy::blend) {  // E^R and E^S have no linear part
    // Each triangle's terms of ũ, then each vertex's sum over its star in triangle order (the order of a
    // plain loop over the triangles): the same sums whatever the number of threads.
    const std::size_t m = forward_terms_.size();
    // kept by the calling thread from frame to frame (fresh pages for each frame cost page faults), and named
    // by references that the threads below share (a thread_local's name means each thread's own)
    thread_local std::vector<Eigen::Vector3cd> forward_kept, backward_kept;
    std::vector<Eigen::Vector3cd>&forward = forward_kept, &backward = backward_kept;
    forward.resize(m), backward.resize(reverse_ ? m : 0);
    auto terms_of = [](const TriangleTerm& term, const Eigen::Matrix2d& A) -> Eigen::Vector3cd {
      return term.weight * term.frobenius_share * hermitian_frobenius_linear_term(term.D, A);
    };
    for_each_range(m, threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) {
        forward[i] = terms_of(forward_terms_[i], forward_.at(static_cast<Eigen::Index>(i), t));
        if (reverse_) backward[i] = terms_of(reverse_terms_[i], reverse_->at(static_cast<Eigen::Index>(i), 1 - t));
      }
    });
    for_each_range(static_cast<std::size_t>(n_), threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        std::complex<double> sum = 0;
        for (const std::vector<Eigen::Vector3cd>* terms : {&forward, &backward})
          if (!terms->empty())
            for (int s = stars_.start[k]; s < stars_.start[k + 1]; ++s)
              sum += (*terms)[static_cast<std::size_t>(stars_.triangle[static_cast<std::size_t>(s)])]
                             [stars_.corner[static_cast<std::size_t>(s)]];
        u[static_cast<Eigen::Index>(k)] = sum;
      }
    });
  }
  for (const ConstraintTerm& term : constraints_) {  // c |Σ α_k z_k − r|²: linear part Re((−2 c α_k r)* z_k)
    const Eigen::Vector2d r = term.target(t);
    for (const auto& [k, alpha_k] : term.coefficients)
      u[k] -= 2 * term.weight * alpha_k * std::complex<double>(r.x(), r.y());
  }
  return u * -0.5;
}

FrameEnergy FrameAssembly::energy_at(double t, const Eigen::Matrix2Xd& v) const {
  FrameEnergy energy;
  auto add = [&](const TriangleTerm& term, const Eigen::Matrix2d& A, double& direction) {
    Eigen::Matrix<double, 2, 3> V;
    for (std::size_t c = 0; c < 3; ++c) V.col(static_cast<Eigen::Index>(c)) = v.col(term.vertex[c]);
    const auto [frobenius, similarity] = local_error_value(energy_, term, A, V);
    energy.frobenius += frobenius, energy.similarity += similarity, direction += frobenius + similarity;
  };
  for (std::size_t i = 0; i < forward_terms_.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    add(forward_terms_[i], forward_.at(k, t), energy.forward);
    if (reverse_) add(reverse_terms_[i], reverse_->at(k, 1 - t), energy.backward);  // E^{-1}(1 − t)
  }
  for (const ConstraintTerm& term : constraints_) {  // c ‖Σ α_k v_k − r(t)‖²
    Eigen::Vector2d l = -term.target(t);
    for (const auto& [k, alpha_k] : term.coefficients) l += alpha_k * v.col(k);
    energy.constraints += term.weight * l.squaredNorm();
  }
  energy.total = energy.forward + energy.backward + energy.constraints;
  return energy;
}

FrameQuadratic FrameAssembly::dense_quadratic_at(double t) const {
  FrameQuadratic form{Eigen::MatrixXd::Zero(2 * n_, 2 * n_), Eigen::VectorXd::Zero(2 * n_), 0.0};
  for (std::size_t i = 0; i < forward_terms_.size(); ++i) {
    const TriangleQuadratic<double> q = triangle_quadratic(static_cast<Eigen::Index>(i), t);
    const auto& vertex = forward_terms_[i].vertex;
    for (int a = 0; a < 3; ++a) {
      form.u.segment<2>(2 * vertex[static_cast<std::size_t>(a)]) += q.g.segment<2>(2 * a);
      for (int b = 0; b < 3; ++b)
        form.G.block<2, 2>(2 * vertex[static_cast<std::size_t>(a)], 2 * vertex[static_cast<std::size_t>(b)]) +=
            q.H.block<2, 2>(2 * a, 2 * b);
    }
    form.c += q.c;
  }
  for (const ConstraintTerm& term : constraints_) {
    const Eigen::Vector2d r = term.target(t);
    for (const auto& [k, alpha_k] : term.coefficients) {
      form.u.segment<2>(2 * k) -= 2 * term.weight * alpha_k * r;
      for (const auto& [l, alpha_l] : term.coefficients)
        form.G.block<2, 2>(2 * k, 2 * l) += term.weight * alpha_k * alpha_l * Eigen::Matrix2d::Identity();
    }
    form.c += term.weight * r.squaredNorm();
  }
  return form;
}

}  // namespace affinterp::global
