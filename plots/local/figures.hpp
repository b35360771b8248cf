#pragma once
// Figure drivers of the local theory: the data and gnuplot scripts of the papers' figures, recomputed
// from theory/local. Each draws into the folder `dir` and returns the names of the files it drew.
#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

/// Kaji Fig. 1: a triangle extrapolated over t in [0, 1.35] by the polar homotopy (eq. 2; it collapses at
/// t = 1.1 and turns over) and by the exp-log homotopy (eq. 3; it never collapses), with det A(t).
std::vector<std::string> draw_kaji_figure_1(const std::filesystem::path& dir);

/// thesis Figs 2.2–2.4 (the example triangle of §2.2.4 under linear, SVD and polar interpolation, with the
/// printed angles) and Fig. 2.5 (det A_l(t), with det A_s(t) = det A_p(t) for comparison).
std::vector<std::string> draw_thesis_figures_2_2_to_2_5(const std::filesystem::path& dir);

}  // namespace affinterp::plots
