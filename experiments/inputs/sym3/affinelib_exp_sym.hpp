#pragma once
// A peer: Kaji's AffineLib expSym, the symmetric exponential by spectral decomposition that accompanies
// Kaji et al. SCA 2012 (github.com/shizuo-kaji/AffineLib, affinelib.h, AffineLib::expSym, version 0.20,
// Nov. 2013, MIT licence; read at commit 2bb531a0faeb748de30664ebd064aa06abaa163d), re-implemented step by
// step from its published algorithm for the peer table of the accuracy sweep (thesis §3.4).
//
// The algorithm, as published: with ‖S‖²_F < 10⁻⁵ it returns I + S. Otherwise it takes the eigenvalues
// λ₀ ≤ λ₁ ≤ λ₂ from Eigen's closed-form solver (computeDirect, eigenvalues only) and, treating eigenvalues
// closer than 10⁻⁵ (its EPSILON, written 10e-6) as equal, evaluates Sylvester's formula:
//  - all three equal:       e^{λ₁} I;
//  - λ₀ ≈ λ₁ (λ₂ apart):   (a − b) S + (λ₁ b − λ₂ a) I,  a = e^{λ₁}/(λ₁ − λ₂),  b = e^{λ₂}/(λ₁ − λ₂);
//  - λ₁ ≈ λ₂ (λ₀ apart):   (a − b) S + (λ₀ b − λ₁ a) I,  a = e^{λ₀}/(λ₀ − λ₁),  b = e^{λ₁}/(λ₀ − λ₁);
//  - distinct:  (a + b + c) S² − (a(λ₁ + λ₂) + b(λ₂ + λ₀) + c(λ₀ + λ₁)) S + (a λ₁λ₂ + b λ₂λ₀ + c λ₀λ₁) I,
//    a = e^{λ₀}/((λ₀ − λ₁)(λ₀ − λ₂)), b = −e^{λ₁}/((λ₁ − λ₂)(λ₀ − λ₁)), c = e^{λ₂}/((λ₀ − λ₂)(λ₁ − λ₂)).
// The operations are evaluated in the published order, so that its rounding (and its overflow, e.g.
// e^{λ₂} ≈ 10³⁰⁸ multiplied into S² before the cancellation) is the peer's own.
#include <Eigen/Core>

namespace affinterp::sym3 {

/// AffineLib::expSym(S) with its eigenvalues computed (the library's default argument).
Eigen::Matrix3d exp_affinelib(const Eigen::Matrix3d& S);

}  // namespace affinterp::sym3
