#pragma once
// One frame's local maps in one batched pass: A_i = exp([Ω_i]×) exp([H_i]×) exp(Λ_i) for every element i, with
// Ω_i, H_i ∈ ℝ³ and Λ_i symmetric — the exp-log homotopy R_i(t) S_i^t (Ω_i = t ω̄_i, H_i = t η_i: the rotation's
// carrier and remainder, rotation_carrier3.hpp; Λ_i = t log S_i: Kaji eq. (3)) and the N-way blend
// exp(Σ_k w_k [ω̄_{k,i}]×) exp(Σ_k w_k [η_{k,i}]×) exp(Σ_k w_k log S_{k,i}) (the Lie-algebra parametrisation of the
// thesis's reference [6], Kaji et al.) alike. The symmetric exponentials go through sym3::exp_batched (the thesis's
// chapter 3 exponential, SIMD-batched), the rotations through Rodrigues' formula (local3/rotation3.hpp).
#include "theory/sym3/exp_batch.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <span>

namespace affinterp::global3 {

/// Elements per exp_batched call. Fixed (a multiple of every SIMD width's batch pair), so that a frame makes
/// the same calls on the same matrices whatever the number of threads, and its maps are the same bits.
inline constexpr Eigen::Index exp_chunk = 1024;

/// Writes Ω_i into Omega[i − first], H_i into Eta[i − first] and Λ_i into Lambda[i − first] for the elements
/// first … last − 1.
using LogFill = std::function<void(Eigen::Index first, Eigen::Index last, std::span<Eigen::Vector3d> Omega,
                                   std::span<Eigen::Vector3d> Eta, std::span<Eigen::Matrix3d> Lambda)>;

/// out[i] = exp([Ω_i]×) exp([H_i]×) exp(Λ_i) for i < out.size(), the elements taken exp_chunk at a time, the chunks
/// shared among up to `threads` threads (1: the caller's alone). The same bits on any number of threads.
/// `exp` computes the symmetric exponentials (empty: sym3::exp_batched), so that benchmarks can price another
/// algorithm of thesis ch. 3 inside a real frame.
void exp_log_maps(const LogFill& fill, std::span<Eigen::Matrix3d> out, std::size_t threads,
                  const sym3::SymExpBatch& exp = {});

}  // namespace affinterp::global3
