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

/// Reads `file` (.ply, .stl, .ts); throws MeshFileError.
global::Mesh read_polygon_soup_mesh(const std::filesystem::path& file);

}  // namespace affinterp::io
