#pragma once
// What the 3D claims share: where the CGAL demo mesh is extracted, and their figures (plots/mesh3/).
#include "theory/global3/interpolation3.hpp"
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::claims::global3_figures {

/// The folder the CGAL demo meshes are extracted into (a fixed folder under the system's temporary one).
std::filesystem::path demo_folder();

/// A filmstrip of `engine`'s frames at t = 0, 1/4, …, 1 drawn to `stem`; returns the file names.
std::vector<std::string> interpolation_filmstrip(const std::filesystem::path& stem, const global3::Mesh3& source,
                                                 const global3::Interpolation3& engine, const std::string& title);

/// A blend triangle of three poses at the weights (i, j, k)/3, i + j + k = 3, drawn to `stem`.
std::vector<std::string> blend_triangle(const std::filesystem::path& stem, const std::vector<global3::Mesh3>& poses,
                                        const std::vector<std::string>& names, const std::string& title);

}  // namespace affinterp::claims::global3_figures
