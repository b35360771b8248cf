#include "experiments/claims/catalogue.hpp"

#include <array>

namespace affinterp::claims {

namespace {

constexpr std::string_view local = "Local interpolation (Kaji §3 and Appendix; thesis §2.2)";
constexpr std::string_view global = "Global interpolation (Kaji §4 and Appendix; thesis §2.3)";
constexpr std::string_view sym3 = "Exponential of 3×3 symmetric matrices (thesis ch. 3)";

constexpr std::array<ClaimInfo, 41> claims{{
    // Local interpolation
    {"kaji.eq1.affine-map", local, "Kaji eq. (1)",
     "The product of the target-vertex matrix and the inverse source-vertex matrix sends each source "
     "vertex to its target vertex and has bottom row (0, 0, 1)."},
    {"kaji.linear.collapse", local, "Kaji §3",
     "For A = −I the linear homotopy (1−t)I + tA is the zero matrix at t = 1/2."},
    {"kaji.polar.det", local, "Kaji §3",
     "The determinant of the polar (Alexa) homotopy R_{tθ}((1−t)I + tS) factors as "
     "((λ1−1)t+1)((λ2−1)t+1), with λ1, λ2 the singular values of A."},
    {"kaji.polar.degenerate", local, "Kaji §3",
     "Unless both singular values equal 1, the polar homotopy's determinant is negative at some real t."},
    {"kaji.svd.degenerate", local, "Kaji §3",
     "The SVD-based homotopies of Alexa et al. can also reach a zero determinant at some real t."},
    {"kaji.exp.endpoints", local, "Kaji eq. (3)",
     "The exp-log homotopy R_θ^t S^t equals I at t = 0 and A at t = 1."},
    {"kaji.exp.det-positive", local, "Kaji §3",
     "The exp-log homotopy has positive determinant for every real t."},
    {"kaji.exp.det-monotone", local, "Kaji §3",
     "The exp-log homotopy's determinant is monotone in t: its derivative is identically zero when "
     "λ1λ2 = 1 and nowhere zero otherwise."},
    {"kaji.appendix.polar-from-svd", local, "Kaji Appendix",
     "Given the SVD A = R_α D R_β, the polar factors are R_θ = R_{α+β} and S = R_{−β} D R_β, and "
     "S^t = R_{−β} D^t R_β."},
    {"thesis.thm-2.2.1", local, "thesis Thm 2.2.1",
     "Linear interpolation is good for area exactly when tr A ≥ det A + 1, or 2 det A ≤ tr A < 2, or "
     "2 ≤ tr A < 2 det A."},
    {"thesis.thm-2.2.2", local, "thesis Thm 2.2.2",
     "SVD interpolation is good for area exactly when Thm 2.2.1's condition holds with tr D for tr A."},
    {"thesis.thm-2.2.3", local, "thesis Thm 2.2.3",
     "SVD interpolation R_{tα}((1−t)I + tD)R_{tβ}, D = diag(x, y), is good for norm exactly when x, y "
     "are both ≥ 1 or both in (0, 1]."},
    {"thesis.thm-2.2.4", local, "thesis Thm 2.2.4",
     "Polar interpolation is good for area exactly when Thm 2.2.1's condition holds with tr S for tr A."},
    {"thesis.thm-2.2.5", local, "thesis Thm 2.2.5",
     "Polar interpolation with S = [[x, h], [h, y]] is good for norm exactly when (x−1)(y−1) ≥ h² and "
     "(x + y ≥ 2 or both x, y in (0, 1])."},
    {"thesis.thm-2.2.6", local, "thesis Thm 2.2.6",
     "SVD interpolation is good for area if and only if polar interpolation is."},
    {"thesis.ex-2.2.4", local, "thesis §2.2.4",
     "The worked example's A, its SVD R_{π/3} diag(2,1) R_{−5π/3} and polar form R_{−4π/3} S are "
     "correct; linear interpolation is good for neither area nor norm, SVD for area, polar for both."},
    // Global interpolation
    {"kaji.er.closed-form", global, "Kaji Appendix",
     "min over s, δ of ‖s R_δ A − B‖²_F equals ‖B‖² − (‖B Aᵀ‖² + 2 det(B Aᵀ)) / ‖A‖²."},
    {"kaji.er.positive-definite", global, "Kaji §4, Appendix",
     "E^R is a positive definite quadratic form in the entries of B."},
    {"kaji.er.similarity-invariant", global, "Kaji §4",
     "E^R(A, B) does not change when A is replaced by s R_δ A."},
    {"kaji.ef.translation-invariant", global, "Kaji §4",
     "The global E^F error is translation invariant, and a constraint of two dimensions makes its "
     "minimiser unique."},
    {"kaji.acol.constraint", global, "Kaji §4",
     "The Alexa et al. constraint as printed, ‖(1−t)p1 + t p1 − v1(t)‖², with E^F yields an "
     "interpolation that reaches the target, B(1) p_k = q_k."},
    {"kaji.global.G-time-independent", global, "Kaji Appendix",
     "The matrix G of the global quadratic form is the same at every t, so one factorisation serves "
     "all frames; decided separately for E^F, E^R, their blend and the symmetrised energy."},
    {"kaji.symmetrization", global, "Kaji §4",
     "With E′(t) = E(t) + E^{−1}(1−t), exchanging source and target and t with 1−t gives the same "
     "vertex paths."},
    {"kaji.fig2-vs-fig4", global, "Kaji Figs 2, 4",
     "Under vertex-locus constraints, E^F shrinks and flips triangles in intermediate frames where E^R "
     "does not."},
    {"kaji.fig3-vs-fig5", global, "Kaji Figs 3, 5",
     "When local rotations must exceed π, E^F does not interpolate smoothly while E^R does."},
    {"kaji.fig6-vs-fig7", global, "Kaji Figs 6, 7",
     "Weighting E^R by triangle area keeps large triangles more rigid than unweighted E^R."},
    {"kaji.blend.suppresses", global, "Kaji §4",
     "In the blend w E^F + (1−w) E^R, a large w suppresses a triangle's rotation and scaling."},
    {"kaji.global.flips", global, "Kaji §5",
     "Unlike the local exp-log homotopy, the global interpolation can flip triangles."},
    {"thesis.sec-2.3.matrices", global, "thesis §2.3",
     "The printed A1, A2 (origin o = (x, y)) and B1, B2 describe the two-triangle configuration."},
    {"thesis.sec-2.3.minimiser", global, "thesis §2.3",
     "The printed minimiser v1 … v4 as functions of (x, y) is correct."},
    {"thesis.sec-2.3.min-energy", global, "thesis §2.3",
     "min E2(o, o) = (2 + (x−1)x + (y−1)y) / (x² + 2xy + y² − 2x − 2y + 3)."},
    {"thesis.sec-2.3.conic", global, "thesis §2.3, Fig 2.6",
     "The origins o = (x, y) at which min E1 = min E2(o, o) lie on the conic "
     "x² − 4xy + y² + x + y − 1/4 = 0."},
    // 3x3 symmetric matrix functions
    {"thesis.eq-3.charpoly", sym3, "thesis §3.2",
     "For symmetric 3×3 S the characteristic polynomial is x³ − (tr S)x² + ((tr S)² − ‖S‖²_F)/2 · x − "
     "det S."},
    {"thesis.viete", sym3, "thesis §3.2",
     "Viète's trigonometric formula with the printed r, k, p, q gives the eigenvalues λ_k."},
    {"thesis.sd.case1", sym3, "thesis §3.1.2",
     "With a triple eigenvalue, exp S = e^{λ1} I."},
    {"thesis.sd.case2", sym3, "thesis §3.1.2",
     "With exactly two equal eigenvalues, the printed coefficients x = 0, y = s − t, z = tλ2 − sλ3 give "
     "exp S = xS² + yS + zI."},
    {"thesis.sd.case3", sym3, "thesis §3.1.2",
     "With distinct eigenvalues, the printed x = s + t + u, y, z (and s, t, u) give exp S = xS² + yS + zI."},
    {"thesis.exp.accuracy", sym3, "thesis §3.4",
     "Treating eigenvalues closer than 10⁻⁶ as equal, the improved spectral decomposition is accurate to "
     "10⁻⁶ for eigenvalues in [0, 3]."},
    {"thesis.eig.speedup", sym3, "thesis §3.4, Fig 3.1",
     "Viète eigenvalues are about 3.2× faster than Eigen's QR-based solver on S = MᵀM, M uniform in "
     "[−1, 1]."},
    {"thesis.exp.speedup", sym3, "thesis §3.4, Fig 3.2",
     "Improved SD is about 4.2× faster than diagonalisation, with plain SD in between."},
    {"thesis.app.speedup", sym3, "thesis §3.4, Fig 3.3",
     "In a deformation application on a mesh of about 100,000 triangles, the improved algorithm is about "
     "1.2× faster overall."},
}};

}  // namespace

std::span<const ClaimInfo> catalogue() { return claims; }

const ClaimInfo* find_claim(std::string_view id) {
  for (const auto& c : claims)
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace affinterp::claims
