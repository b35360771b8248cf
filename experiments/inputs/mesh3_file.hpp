#pragma once
// 3D meshes from files, for the 3D engine (theory/global3): triangle surfaces in OBJ, OFF, PLY or STL (CGAL's
// polygon-soup reader, CGAL::IO::read_polygon_soup; STL's repeated corners merged) and tetrahedral meshes in
// MEDIT's .mesh (our own reader of its Vertices and Tetrahedra sections; the Triangles, Edges and other sections
// a mesher adds for the boundary are skipped). Triangles only on surfaces: a triangulation of polygons chosen by
// the reader could differ between poses. Every refusal is one line naming the file, and the line, face or vertex.
//
// Frames are written back in the same two families: a surface as OBJ, a tetrahedral mesh as .mesh (OBJ has no
// tetrahedra), each readable by read_mesh3.
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace affinterp::io {

/// Reads `file` (.obj, .off, .ply, .stl: triangles; .mesh: tetrahedra); throws MeshFileError.
global3::Mesh3 read_mesh3(const std::filesystem::path& file);

/// The MEDIT text `text` (named `name` in messages): its Vertices and Tetrahedra (1-based indices), or its
/// Triangles when it has no tetrahedra; throws MeshFileError naming the line.
global3::Mesh3 parse_medit(std::string_view text, const std::string& name);

/// The mesh in `file` when it holds a 3D shape (a .mesh file, or a surface with some z ≠ 0), read once for the 3D
/// engine; nullopt otherwise. A file the 3D reader cannot read counts as 2D, so that the 2D reader reports what is
/// wrong with it. An OBJ or OFF file is first looked at with surely_flat, so that a flat one is not parsed twice.
std::optional<global3::Mesh3> read_if_3d(const std::filesystem::path& file);

/// Whether OBJ (`off` false) or OFF text is surely flat: every vertex's z is a number equal to 0 (or, in OBJ, absent),
/// read from its vertex records alone (OBJ's `v` lines; OFF's coordinates after its `OFF` header and counts, `#`
/// comments skipped), a cheap look before a full 3D read. Text it cannot follow is not surely flat: the full read
/// decides.
bool surely_flat(std::string_view text, bool off);

/// `mesh` with `vertices` as OBJ (triangles) or MEDIT (tetrahedra) text, full double precision.
std::string mesh3_text(const global3::Mesh3& mesh);
/// The extension mesh3_text's format takes: ".obj" or ".mesh".
const char* mesh3_extension(const global3::Mesh3& mesh);
/// Writes mesh3_text to `file`; throws MeshFileError when it cannot be written.
void write_mesh3(const global3::Mesh3& mesh, const std::filesystem::path& file);

}  // namespace affinterp::io
