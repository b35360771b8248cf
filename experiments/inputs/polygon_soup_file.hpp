#pragma once
// 2D triangle meshes in the other common formats — PLY (ASCII or binary), STL (ASCII or binary; its repeated
// corners merged into shared vertices) and GOCAD TS — read by CGAL's polygon-soup reader
// (CGAL::IO::read_polygon_soup), then held to the rules of mesh_file.hpp: triangles only, z = 0, finite
// coordinates; every refusal one line naming the file and the element (CGAL says only whether it could
// read the file). OBJ and OFF keep their own reader (mesh_file.hpp), which names the line.
#include "theory/global/mesh.hpp"

#include <filesystem>
#include <string>

namespace affinterp::io {

/// Whether `extension` (lower case, with the dot) is one read_polygon_soup_mesh reads.
bool is_polygon_soup_extension(const std::string& extension);

/// The triangles of a file CGAL's polygon-soup reader reads (OBJ, OFF, PLY, STL, TS), in 3D: finite coordinates,
/// triangles only (a triangulation chosen by the reader could differ between two meshes of one connectivity),
/// every corner a vertex of the file; throws MeshFileError naming the file and the element.
struct TriangleSoup {
  Eigen::Matrix3Xd vertices;   ///< column k is vertex k
  Eigen::Matrix3Xi triangles;  ///< column i holds triangle i's vertex indices (0-based)
};
TriangleSoup read_triangle_soup(const std::filesystem::path& file);

/// Reads `file` (.ply, .stl, .ts) as a 2D mesh: read_triangle_soup with z = 0; throws MeshFileError.
global::Mesh read_polygon_soup_mesh(const std::filesystem::path& file);

}  // namespace affinterp::io
