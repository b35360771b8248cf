// The 3D viewer in a real browser: `affinterp interpolate` on a tetrahedral bar and `affinterp blend` on a tube
// write OUT/viewer.html (three.js inlined); headless Chromium opens them from disk and this checks that the page
// draws the mesh (a WebGL canvas that is not blank), that scrubbing the slider with the keyboard changes the
// frame and the drawing, that the colouring by inverted elements shows in every frame the elements metrics.json
// counts (none on a tube turned by 3 rad, whose far faces face away from their rest normals; two on a bar twisted
// by 4.5 rad on principal branches), that a run without quality metrics offers no such colouring, that nothing is
// fetched and that the console stays free of errors.
// Exits 77 (CTest: skipped) when Chromium is missing; the set-up installs it and libjs-three.
#include "checks/apps/chromium_session.hpp"
#include "checks/apps/cli_harness.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iostream>

namespace {

namespace fs = std::filesystem;
using affinterp::checks::ChromiumSession;
using affinterp::checks::run_cli;

std::optional<fs::path> chromium;

const fs::path& scratch() {
  static const fs::path folder = fs::temp_directory_path() / ("affinterp_viewer3_test_" + std::to_string(getpid()));
  return folder;
}

std::string url(const fs::path& file) { return "file://" + fs::absolute(file).string(); }

/// The WebGL canvas's frame, a hash of its pixels and how many are not background, read through a 2D copy.
const char* const canvas = R"js((() => {
    const c = document.querySelector("canvas");
    const copy = document.createElement("canvas");
    copy.width = c.width, copy.height = c.height;
    const ctx = copy.getContext("2d", { willReadFrequently: true });
    ctx.drawImage(c, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let hash = 0, drawn = 0;
    for (let i = 0; i < d.length; i += 4) {
      hash = (Math.imul(hash, 31) + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) >>> 0;
      drawn += d[i] < 245 || d[i + 1] < 245 || d[i + 2] < 245;
    }
    return { frame: Number(document.body.dataset.frame), hash, drawn, pixels: d.length / 4 };
  })())js";

/// Writes a generated mesh (checks/apps/meshes3_files.py) into the scratch folder.
std::string mesh(const std::string& kind, double turn, const std::string& name) {
  const fs::path file = scratch() / name;
  const std::string command = "python3 " + std::string(AFFINTERP_SOURCE_DIR) + "/checks/apps/meshes3_files.py " + kind +
                              " " + std::to_string(turn) + " " + file.string();
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return file.string();
}

class Viewer3InBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(scratch());
    fs::create_directories(scratch());
    auto result = run_cli("interpolate --source " + mesh("bar", 0, "bar.mesh") + " --target " +
                          mesh("bar", 3, "bar170.mesh") + " --frames 5 --out " + (scratch() / "bar").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("blend --poses " + mesh("tube", 0, "tube.off") + " " + mesh("tube", 1, "tube1.off") +
                     " --weights 1,0 --weights 0.5,0.5 --weights 0,1 --out " + (scratch() / "tube").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("interpolate --source " + (scratch() / "tube.off").string() + " --target " +
                     mesh("tube", 3, "tube3.off") + " --frames 5 --out " + (scratch() / "tube3").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("interpolate --source " + (scratch() / "bar.mesh").string() + " --target " +
                     mesh("bar", 4.5, "bar4.5.mesh") + " --frames 5 --rotation-branch principal --out " +
                     (scratch() / "bar4.5").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("interpolate --source " + (scratch() / "tube.off").string() + " --target " +
                     (scratch() / "tube3.off").string() + " --frames 3 --metrics none --out " +
                     (scratch() / "unmeasured").string());
    ASSERT_EQ(result.status, 0) << result.error;
  }

  void SetUp() override { browser_.emplace(*chromium, scratch() / ("profile-" + std::to_string(++tabs_))); }

  void TearDown() override {
    EXPECT_TRUE(browser_->errors().empty()) << ::testing::PrintToString(browser_->errors());
    for (const auto& warning : browser_->warnings()) std::cout << "browser warning: " << warning << "\n";
    for (const auto& requested : browser_->requests())
      EXPECT_TRUE(requested.starts_with("file://" + scratch().string()) || requested.starts_with("data:"))
          << "fetched " << requested;
    browser_.reset();
  }

  /// Opens `page`, checks the first frame is drawn, then presses End: the last frame, drawn differently.
  void scrub(const fs::path& page, int last) {
    browser_->open(url(page));
    const nlohmann::json first = browser_->evaluate(canvas);
    EXPECT_EQ(first["frame"], 0);
    EXPECT_GT(first["drawn"].get<double>(), 0.02 * first["pixels"].get<double>()) << "the mesh is drawn";
    browser_->evaluate("document.getElementById('frame').focus()");
    browser_->press("End", 35);
    const nlohmann::json end = browser_->evaluate(canvas);
    EXPECT_EQ(end["frame"], last);
    EXPECT_NE(end["hash"], first["hash"]) << "the first and last frames look alike";
    browser_->press("Home", 36);
    EXPECT_EQ(browser_->evaluate(canvas)["frame"], 0);
  }

  std::optional<ChromiumSession> browser_;
  static inline int tabs_ = 0;
};

TEST_F(Viewer3InBrowser, TetrahedraAreDrawnAndScrubbed) { scrub(scratch() / "bar" / "viewer.html", 4); }

TEST_F(Viewer3InBrowser, ABlendIsDrawnAndScrubbed) { scrub(scratch() / "tube" / "viewer.html", 2); }

/// Per frame of `run`'s viewer coloured by inverted elements, the count its legend gives, against metrics.json's.
void expect_legend_counts_as_metrics(ChromiumSession& browser, const fs::path& run) {
  const nlohmann::json metrics = nlohmann::json::parse(std::ifstream(run / "metrics.json"));
  browser.open(url(run / "viewer.html"));
  browser.evaluate(
      "const c = document.getElementById('colour'); c.value = 'inverted'; "
      "c.dispatchEvent(new Event('change'))");
  for (const auto& frame : metrics["frames"]) {
    const std::string legend = browser.evaluate("document.getElementById('legend').textContent");
    EXPECT_EQ(legend.substr(0, legend.find(' ')), std::to_string(frame["inverted_elements"].get<int>()))
        << run << " frame " << frame["index"] << ": " << legend;
    browser.evaluate("document.getElementById('frame').focus()");
    browser.press("ArrowRight", 39);
  }
}

TEST_F(Viewer3InBrowser, InvertedColouringShowsWhatMetricsCount) {
  expect_legend_counts_as_metrics(*browser_, scratch() / "bar");
  expect_legend_counts_as_metrics(*browser_, scratch() / "tube3");
  expect_legend_counts_as_metrics(*browser_, scratch() / "bar4.5");
}

TEST_F(Viewer3InBrowser, NoInvertedColouringWithoutQualityMetrics) {
  browser_->open(url(scratch() / "unmeasured" / "viewer.html"));
  EXPECT_EQ(browser_->evaluate("document.querySelectorAll('#colour option[value=\"inverted\"]').length"), 0);
  EXPECT_EQ(browser_->evaluate("document.getElementById('colour').options.length"), 2);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  chromium = ChromiumSession::find();
  if (!chromium) {
    std::cout << "skipped: chromium not found (experiments/setup.sh installs Debian's chromium)\n";
    return 77;
  }
  std::signal(SIGPIPE, SIG_IGN);  // a browser that dies is reported by the session, not by a signal
  const int status = RUN_ALL_TESTS();
  fs::remove_all(scratch());
  return status;
}
