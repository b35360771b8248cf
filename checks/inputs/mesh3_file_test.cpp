// experiments/inputs/mesh3_file.hpp's look at a file before the 3D read: surely_flat on OBJ and OFF text (z absent,
// 0 in any spelling, comments, counts on the header's line), anything it cannot follow left to the full read, and
// read_if_3d's answers on files of each kind.
#include "experiments/inputs/mesh3_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace affinterp::io::mesh3_file_test {
namespace {

TEST(SurelyFlat, ObjVerticesWithZAbsentOrZero) {
  EXPECT_TRUE(surely_flat("v 0 0\nv 1 0 0\nv 0 1 -0.0 # a comment\nvt 0.5 0.5 2\nf 1 2 3\n", false));
  EXPECT_TRUE(surely_flat("# nothing but a comment\n", false));
  EXPECT_FALSE(surely_flat("v 0 0 0\nv 1 0 1e-300\nv 0 1 0\nf 1 2 3\n", false));
  EXPECT_FALSE(surely_flat("v 0 0 zero\n", false));  // not a number: the full read decides
}

TEST(SurelyFlat, OffCoordinatesAfterTheCounts) {
  EXPECT_TRUE(surely_flat("OFF\n# comment\n3 1 0\n0 0 0\n1 0 0.0\n0 1 0\n3 0 1 2\n", true));
  EXPECT_TRUE(surely_flat("OFF 3 1 0\n0 0 0 1 0 0 0 1 0\n3 0 1 2\n", true));
  EXPECT_FALSE(surely_flat("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n", true));
  EXPECT_FALSE(surely_flat("COFF\n3 1 0\n0 0 0 1 1 1 1\n", true));  // another header: left to the full read
  EXPECT_FALSE(surely_flat("OFF\n3 1 0\n0 0 0\n1 0\n", true));      // cut short
}

TEST(ReadIf3d, AnswersForFlatAndSpatialFiles) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "mesh3_file_test";
  std::filesystem::create_directories(folder);
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(folder / name) << text;
    return folder / name;
  };
  EXPECT_FALSE(read_if_3d(write("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).has_value());
  EXPECT_FALSE(read_if_3d(write("flat.OFF", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).has_value());
  const auto spatial = read_if_3d(write("tilted.obj", "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n"));
  ASSERT_TRUE(spatial.has_value());
  EXPECT_EQ(spatial->vertices(2, 2), 1);
  EXPECT_FALSE(read_if_3d(folder / "missing.obj").has_value());  // the 2D reader names what is wrong
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace affinterp::io::mesh3_file_test
