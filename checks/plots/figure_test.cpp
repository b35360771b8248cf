#include "plots/figure.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;
using affinterp::plots::Figure;

TEST(Figure, RendersPngAndSvgFromDatablocks) {
  const fs::path stem = fs::temp_directory_path() / "affinterp_figure_test";
  const auto files = Figure(stem)
                         .size(300, 200)
                         .data("line", {{0, 0}, {1, 1}, {}, {0, 1}, {1, 0}})
                         .script("plot $line using 1:2 with lines")
                         .render();
  ASSERT_EQ(files.size(), 2u);
  EXPECT_GT(fs::file_size(stem.string() + ".png"), 0u);
  EXPECT_GT(fs::file_size(stem.string() + ".svg"), 0u);
}

TEST(Figure, ReportsGnuplotErrors) {
  const fs::path stem = fs::temp_directory_path() / "affinterp_figure_bad";
  EXPECT_THROW(Figure(stem).script("plot $missing using 1:2").render(), std::runtime_error);
}

TEST(Figure, ReportsErrorsThatStillLeaveFilesBehind) {
  // The first plot succeeds and writes the file; the second command is garbage.
  const fs::path stem = fs::temp_directory_path() / "affinterp_figure_partial";
  EXPECT_THROW(Figure(stem).script("plot x\nset nonsense_option 3").render(), std::runtime_error);
}

TEST(Figure, WarningsAreNotErrors) {
  const fs::path stem = fs::temp_directory_path() / "affinterp_figure_warning";
  EXPECT_NO_THROW(Figure(stem).script("plot [0:1] 1").render());  // "Warning: empty y range"
}

TEST(Figure, MissingGnuplotIsAClearErrorNotACrash) {
  const char* saved = std::getenv("PATH");
  const std::string path = saved ? saved : "";
  setenv("PATH", "/nonexistent", 1);
  const fs::path stem = fs::temp_directory_path() / "affinterp_figure_nognuplot";
  EXPECT_THROW(Figure(stem).script("plot x").render(), std::runtime_error);
  setenv("PATH", path.c_str(), 1);
}
