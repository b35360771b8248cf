#pragma once
// Reading and writing 2D triangle meshes as Wavefront OBJ or OFF, and reading the 3D surfaces of the
// deformation application (thesis Fig. 3.3) from OFF.
//
// Why our own reader: tinyobjloader (Debian 2.0.0rc10) triangulates polygons silently and reports
// problems as free-text warnings without the element, and CGAL 5.5's IO::read_OBJ / IO::read_OFF
// return only a bool. Meshes here are inputs of a command, so every refusal must be one line naming
// the file and the line. The formats' subset accepted:
//   OBJ: `v x y [z]` (z must be 0), `f a b c` with 1-based or negative (relative, as the OBJ
//        specification defines) indices, `a/b/c` and `a//c` forms (only the vertex index is used);
//        `vt vn vp g o s usemtl mtllib` and `#` comments are ignored; any other statement is refused.
//   OFF: an `OFF` header (counts may follow on the same line), `nv nf [ne]`, nv lines `x y z` (z must
//        be 0), nf lines `3 a b c [colour]` with 0-based indices; `#` starts a comment.
// Faces with more than three vertices are refused (not triangulated): a triangulation chosen by the
// reader could differ between source and target. NUL bytes, non-numbers, counts beyond 2^31 − 1 or
// beyond the file's end are refused. Structural checks (indices in range, finiteness) are
// global::check_well_formed's.
// A 3D surface (OFF only, the same reader): z is kept and must be finite, a face of N ≥ 3 vertices is
// split into the fan of triangles (a, b_k, b_{k+1}) of its first corner, and an empty mesh is refused.
#include "theory/deformation/mesh3.hpp"
#include "theory/global/mesh.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace affinterp::io {

/// A file that cannot be read as a mesh; what() is one line "NAME:LINE: problem" or "NAME: problem".
struct MeshFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The whole of `file`; MeshFileError when it is missing or cannot be read.
std::string file_text(const std::filesystem::path& file);

/// Parses OBJ text; `name` prefixes error messages.
global::Mesh parse_obj(std::string_view text, const std::string& name);
/// Parses OFF text; `name` prefixes error messages.
global::Mesh parse_off(std::string_view text, const std::string& name);

/// Reads `file` as OBJ (.obj) or OFF (.off), by its extension (case-insensitive); .ply, .stl and .ts through
/// CGAL's polygon-soup reader (polygon_soup_file.hpp).
global::Mesh read_mesh(const std::filesystem::path& file);

/// Parses OFF text as a 3D surface; `name` prefixes error messages.
sym3::Mesh3 parse_off_surface(std::string_view text, const std::string& name);
/// Reads `file` as an OFF 3D surface, whatever its extension.
sym3::Mesh3 read_off_surface(const std::filesystem::path& file);

/// OBJ text of the mesh: `v x y 0` with 17 significant digits, `f a b c` 1-based.
std::string obj_text(const global::Mesh& mesh);
/// Writes obj_text(mesh) to `file`; throws MeshFileError when it cannot be written.
void write_obj(const global::Mesh& mesh, const std::filesystem::path& file);

}  // namespace affinterp::io
