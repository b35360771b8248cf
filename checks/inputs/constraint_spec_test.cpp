// The command-line syntax of constraints (experiments/inputs/constraint_spec): what each form means and a
// one-line refusal quoting the specification for malformed ones.
#include "experiments/inputs/constraint_spec.hpp"
#include "experiments/inputs/mesh_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace constraint_spec_test {

namespace {

using namespace affinterp;

std::string refusal(void (*parse)(const std::string&), const std::string& spec) {
  try {
    parse(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ConstraintSpec, PinAndWeight) {
  EXPECT_EQ(io::parse_pin("12").vertex, 12);
  EXPECT_EQ(io::parse_pin("12").weight, 1.0);
  EXPECT_EQ(io::parse_pin("3@2.5").weight, 2.5);
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_pin(s); }, "-1"),
            "--pin '-1': '-1' is not a vertex index (0, 1, 2, ...)");
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_pin(s); }, "3@0"),
            "--pin '3@0': the weight after '@' must be a positive number");
}

TEST(ConstraintSpec, LocusThroughPoints) {
  const global::VertexLocus locus = io::parse_locus("7@4:0,0;1.5,-2;3,1");
  EXPECT_EQ(locus.vertex, 7);
  EXPECT_EQ(locus.weight, 4.0);
  ASSERT_EQ(locus.points.cols(), 3);
  EXPECT_EQ(locus.points.col(1), Eigen::Vector2d(1.5, -2));
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_locus(s); }, "7"),
            "--locus '7': expected 'V[@C]:x1,y1;x2,y2;...'");
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_locus(s); }, "7:0,0;1"),
            "--locus '7:0,0;1': '1' is not a point 'x,y'");
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_locus(s); }, "7:0,0;nan,1"),
            "--locus '7:0,0;nan,1': 'nan,1' is not a point 'x,y'");
}

TEST(ConstraintSpec, EdgeDirectionAndPath) {
  const global::EdgeDirection edge = io::parse_edge_direction("1:2:linear@3");
  EXPECT_EQ(edge.i, 1);
  EXPECT_EQ(edge.j, 2);
  EXPECT_EQ(edge.path, global::EdgeDirection::Path::linear);
  EXPECT_EQ(edge.weight, 3.0);
  EXPECT_EQ(io::parse_edge_direction("4:5").path, global::EdgeDirection::Path::local_homotopy);
  EXPECT_EQ(refusal([](const std::string& s) { io::parse_edge_direction(s); }, "4:5:curvy"),
            "--edge-direction '4:5:curvy': the path must be 'homotopy' or 'linear'");
}

TEST(ConstraintSpec, BarycentreLinearNoneOrPoints) {
  EXPECT_EQ(io::parse_barycentre("linear")->points.cols(), 0);
  EXPECT_EQ(io::parse_barycentre("linear@5")->weight, 5.0);
  EXPECT_FALSE(io::parse_barycentre("none"));
  EXPECT_EQ(io::parse_barycentre("0,0;1,1;2,0@2")->points.cols(), 3);
}

TEST(ConstraintSpec, VertexIndicesAreCheckedAgainstTheMesh) {
  global::Constraints constraints;
  constraints.edges.push_back(io::parse_edge_direction("0:9"));
  EXPECT_NO_THROW(io::check_constraint_vertices(constraints, 10));
  EXPECT_THROW(io::check_constraint_vertices(constraints, 9), std::invalid_argument);
}

TEST(ConstraintSpec, WeightsFileOneNumberPerLine) {
  const auto file = std::filesystem::temp_directory_path() / "affinterp_weights_test.txt";
  std::ofstream(file) << "# w_i\n0.25\n\n1 # last\n";
  EXPECT_EQ(io::read_weights(file), Eigen::Vector2d(0.25, 1));
  std::ofstream(file) << "0.5\nhalf\n";
  try {
    io::read_weights(file);
    FAIL();
  } catch (const io::MeshFileError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ":2: not a finite number");
  }
}

}  // namespace

}  // namespace constraint_spec_test
