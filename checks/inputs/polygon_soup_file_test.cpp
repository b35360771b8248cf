// experiments/inputs/polygon_soup_file: PLY and STL through CGAL's polygon-soup reader, held to the rules of
// the OBJ/OFF reader with one-line errors.
#include "experiments/inputs/mesh_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace affinterp::io::polygon_soup_file_test {
namespace {

namespace fs = std::filesystem;

fs::path written(const std::string& name, const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("affinterp_polygon_soup_test_" + name);
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

std::string ply(const std::string& vertices, const std::string& faces, int nv, int nf) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(nf) +
         "\nproperty list uchar int vertex_indices\nend_header\n" + vertices + faces;
}

const std::string square_vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

std::string error_of(const fs::path& file) {
  try {
    read_mesh(file);
  } catch (const MeshFileError& e) {
    return e.what();
  }
  return "";
}

TEST(PolygonSoupFile, ReadsPlyLikeObj) {
  const global::Mesh ply_mesh = read_mesh(written("square.ply", ply(square_vertices, "3 0 1 2\n3 0 2 3\n", 4, 2)));
  const global::Mesh obj_mesh = read_mesh(written("square.obj", "v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3\nf 1 3 4\n"));
  EXPECT_EQ(ply_mesh.vertices, obj_mesh.vertices);
  EXPECT_EQ(ply_mesh.triangles, obj_mesh.triangles);
}

TEST(PolygonSoupFile, ReadsStlWithSharedCorners) {
  const std::string stl =
      "solid s\n"
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "endsolid s\n";
  const global::Mesh mesh = read_mesh(written("square.stl", stl));
  EXPECT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.triangle_count(), 2);
  EXPECT_GT(mesh.doubled_signed_area(0), 0);
}

TEST(PolygonSoupFile, RefusesWithOneLine) {
  const auto expect = [](const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  expect(error_of(written("quad.ply", ply(square_vertices, "4 0 1 2 3\n", 4, 1))), "face 0 has 4 vertices");
  expect(error_of(written("lifted.ply", ply("0 0 0\n1 0 0\n0 1 0.5\n", "3 0 1 2\n", 3, 1))), "vertex 2 has z = 0.5");
  expect(error_of(written("garbage.ply", "not a ply file\n")), "not a readable ply polygon soup");
  expect(error_of(fs::temp_directory_path() / "affinterp_no_such_file.stl"), "no such file");
}

}  // namespace
}  // namespace affinterp::io::polygon_soup_file_test
