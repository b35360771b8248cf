// Reading and writing OBJ/OFF meshes: the accepted subset, and a one-line error naming the file and the
// line for each kind of bad input.
#include "experiments/inputs/mesh_file.hpp"
#include "checks/inputs/shared_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace mesh_file_test {

namespace {

namespace fs = std::filesystem;
using namespace affinterp;

/// The error message of parsing `text`, or "" when it parses.
template <class Parse>
std::string error_of(Parse parse, const std::string& text) {
  try {
    parse(text, "in.obj");
  } catch (const io::MeshFileError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}
std::string obj_error(const std::string& text) { return error_of(io::parse_obj, text); }
std::string off_error(const std::string& text) { return error_of(io::parse_off, text); }

const std::string square_obj =
    "# a square\nmtllib x.mtl\no square\nv 0 0 0\nv 1 0 0\nv 1 1\nv 0 1 0\nvt 0 0\n"
    "f 1/1 2/1 3/1\nf 1//1 3//1 -1\n";

TEST(ObjReader, ReadsTrianglesWithSlashesAndRelativeIndices) {
  const global::Mesh mesh = io::parse_obj(square_obj, "square.obj");
  ASSERT_EQ(mesh.vertex_count(), 4);
  ASSERT_EQ(mesh.triangle_count(), 2);
  EXPECT_EQ(mesh.vertices.col(2), Eigen::Vector2d(1, 1));
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(0, 2, 3));  // -1: the last vertex read so far
}

TEST(ObjReader, RefusesWhatItCannotRepresentNamingTheLine) {
  EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0.5\n"), "in.obj:2: z = 0.5 is not 0: only planar meshes (z = 0) are read");
  EXPECT_EQ(obj_error("v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3 4\n"),
            "in.obj:5: face with 4 vertices: only triangles are read (polygons are not triangulated)");
  EXPECT_EQ(obj_error("v 0 0\nv 1 0\nv 1 1\nf 1 2 4\n"), "in.obj:4: vertex index 4 is out of range (3 vertices)");
  EXPECT_EQ(obj_error("v 0 0\nf -2 1 1\n"), "in.obj:2: vertex index -2 is out of range (1 vertices)");
  EXPECT_EQ(obj_error("v 0 0\nf 0 1 1\n"),
            "in.obj:2: vertex index 0: OBJ indices start at 1 (negative ones count back)");
  EXPECT_EQ(obj_error("v 0 zero\n"), "in.obj:1: 'zero' is not a number");
  EXPECT_EQ(obj_error("v 0\n"), "in.obj:1: expected 'v x y [z]'");
  EXPECT_EQ(obj_error("l 1 2\n"), "in.obj:1: unsupported statement 'l'");
  EXPECT_EQ(obj_error("v 0 0\nf 1 1 99999999999999999999\n"), "in.obj:2: '99999999999999999999' is out of range");
  EXPECT_EQ(obj_error(std::string("v 0 0\n\nv 1\0 0\n", 14)), "in.obj:3: NUL byte: not a text mesh file");
}

TEST(OffReader, ReadsHeaderCountsVerticesAndFaces) {
  const global::Mesh mesh =
      io::parse_off("OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3 255 0 0\n", "sq.off");
  EXPECT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(io::parse_off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "x").triangle_count(), 1);
}

TEST(OffReader, RefusesBadFilesNamingTheLine) {
  EXPECT_EQ(off_error(""), "in.obj: empty file: expected an 'OFF' header");
  EXPECT_EQ(off_error("PLY\n"), "in.obj:1: expected the 'OFF' header, found 'PLY'");
  EXPECT_EQ(off_error("OFF\n9999999999 1 0\n"), "in.obj:2: count beyond 2^31 - 1");
  EXPECT_EQ(off_error("OFF\n2000000000 1 0\n0 0 0\n"), "in.obj: file ends after 1 of 2000000000 vertices");
  EXPECT_EQ(off_error("OFF\n-1 1 0\n"), "in.obj:2: negative count");
  EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 2\n"),
            "in.obj:6: face 0 has 4 vertices: only triangles are read (polygons are not triangulated)");
  EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "in.obj:6: face 0: vertex index 3 is out of range (3 vertices)");
  EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nextra\n"),
            "in.obj:7: unexpected content after the last face");
  EXPECT_EQ(off_error("OFF\n1 0 0\n0 0 1e-300\n"),
            "in.obj:3: z = 1e-300 is not 0: only planar meshes (z = 0) are read");
}

// The 3D surfaces of thesis Fig. 3.3 go through the same OFF reader: z kept, polygons split into fans.
TEST(OffReader, ReadsSurfacesInSpaceSplittingPolygonsIntoFans) {
  const sym3::Mesh3 square =
      io::parse_off_surface("OFF\n# a unit square\n4 1 0\n0 0 0\n1 0 0\n1 1 0.5\n0 1 0\n4 0 1 2 3\n", "sq.off");
  EXPECT_EQ(square.vertex_count(), 4);
  ASSERT_EQ(square.triangle_count(), 2);
  EXPECT_EQ(square.vertices.col(2), Eigen::Vector3d(1, 1, 0.5));
  EXPECT_EQ(square.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(square.triangles.col(1), Eigen::Vector3i(0, 2, 3));
  const auto surface_error = [](const std::string& text) { return error_of(io::parse_off_surface, text); };
  EXPECT_EQ(surface_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
            "in.obj:6: face 0: vertex index 7 is out of range (3 vertices)");
  EXPECT_EQ(surface_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
            "in.obj:6: face 0 has 2 vertices: at least 3 are needed");
  EXPECT_EQ(surface_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"),
            "in.obj:6: face 0: expected 4 vertex indices after the size");
  EXPECT_EQ(surface_error("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), "in.obj:4: vertex 1: 'nan' is not finite");
  EXPECT_EQ(surface_error("OFF\n0 0 0\n"), "in.obj:2: empty mesh: no vertices or no faces");
  EXPECT_THROW(io::read_off_surface("/nonexistent/dragon.off"), io::MeshFileError);
}

TEST(MeshFile, WritesObjThatReadsBackExactly) {
  global::Mesh mesh;
  mesh.vertices.resize(2, 3);
  mesh.vertices << 0.1, 1.0 / 3, -2e-17, 1e10, 0, 0.7;
  mesh.triangles = Eigen::Vector3i(0, 1, 2);
  const global::Mesh back = io::parse_obj(io::obj_text(mesh), "back.obj");
  EXPECT_EQ(back.vertices, mesh.vertices);
  EXPECT_EQ(back.triangles, mesh.triangles);

  const fs::path file = fs::temp_directory_path() / "affinterp_mesh_file_test.obj";
  io::write_obj(mesh, file);
  EXPECT_EQ(io::read_mesh(file).vertices, mesh.vertices);
}

TEST(MeshFile, ChoosesTheFormatByExtensionAndNamesMissingFiles) {
  const fs::path off = fs::temp_directory_path() / "affinterp_mesh_file_test.OFF";
  std::ofstream(off) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(io::read_mesh(off).triangle_count(), 1);
  EXPECT_THROW(io::read_mesh("/nonexistent/a.obj"), io::MeshFileError);
  try {
    io::read_mesh("shape.xyz");
    FAIL();
  } catch (const io::MeshFileError& e) {
    EXPECT_STREQ(e.what(), "shape.xyz: unknown extension '.xyz': expected .obj, .off, .ply, .stl or .ts");
  }
}

TEST(MeshFile, ReadsTheSharedMeshesWhenPresent) {
  const auto shared = checks::shared_meshes();
  if (!shared) GTEST_SKIP() << "skipped: ../shared not present";
  EXPECT_EQ(io::read_mesh(*shared / "man0.obj").triangle_count(), 332);
  EXPECT_EQ(io::read_mesh(*shared / "arm.obj").vertex_count(), 4206);
}

}  // namespace

}  // namespace mesh_file_test
