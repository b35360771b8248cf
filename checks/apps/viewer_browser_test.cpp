// The viewer in a real browser: `affinterp interpolate` writes OUT/viewer.html and `affinterp view` a
// comparison page; headless Chromium opens them from disk and this checks, as a user would see it, that
// the mesh is drawn, that frames differ, that the slider (moved by key presses) and play button change the
// drawing, that #frame=K opens at frame K, that the triangles drawn flipped are the frames' flipped
// triangles of metrics.json, that nothing is fetched and that the console stays free of errors.
// Exits 77 (CTest: skipped) when Chromium is missing; the set-up installs it.
#include "checks/apps/chromium_session.hpp"
#include "checks/apps/cli_harness.hpp"
#include "checks/inputs/shared_meshes.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/curl.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iostream>
#include <numbers>
#include <set>

namespace {

namespace fs = std::filesystem;
using namespace affinterp;
using checks::ChromiumSession;
using checks::run_cli;

std::optional<fs::path> chromium;

const fs::path& scratch() {
  static const fs::path folder = fs::temp_directory_path() / ("affinterp_viewer_test_" + std::to_string(getpid()));
  return folder;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::string url(const fs::path& file, const std::string& fragment = "") {
  return "file://" + fs::absolute(file).string() + fragment;
}

/// Per mesh canvas: its frame, its count of triangles drawn flipped, a hash of its pixels and how many
/// pixels are not background, read through a copy made for reading.
const char* const canvases = R"js(
  [...document.querySelectorAll("canvas.mesh")].map((c) => {
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
    return { frame: Number(c.dataset.frame), flipped: Number(c.dataset.flipped), hash, drawn, pixels: d.length / 4 };
  }))js";

class ViewerInBrowser : public ::testing::Test {
 protected:
  /// Two runs on one generated shape (the linear homotopy flips triangles on the way) and their comparison.
  static void SetUpTestSuite() {
    fs::remove_all(scratch());
    fs::create_directories(scratch());
    ASSERT_EQ(run_cli("shapes man-twirl --out " + (scratch() / "shape").string()).status, 0);
    const std::string io = " --source " + (scratch() / "shape" / "source.obj").string() + " --target " +
                           (scratch() / "shape" / "target.obj").string() + " --frames 7";
    auto result = run_cli("interpolate" + io + " --out " + (scratch() / "exp").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("interpolate" + io + " --homotopy linear --energy F --out " + (scratch() / "linear").string());
    ASSERT_EQ(result.status, 0) << result.error;
    result = run_cli("view " + (scratch() / "exp").string() + " " + (scratch() / "linear").string() + " -o " +
                     (scratch() / "compare.html").string());
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

  nlohmann::json drawing() { return browser_->evaluate(canvases); }
  int slider() { return std::stoi(browser_->evaluate("document.getElementById('frame').value").get<std::string>()); }

  std::optional<ChromiumSession> browser_;
  static inline int tabs_ = 0;
};

TEST_F(ViewerInBrowser, DrawsTheMeshAndFramesDiffer) {
  browser_->open(url(scratch() / "exp" / "viewer.html"));
  const auto first = drawing();
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0]["frame"], 0);
  EXPECT_GT(first[0]["drawn"].get<double>(), 0.05 * first[0]["pixels"].get<double>()) << "the mesh covers the canvas";
  browser_->evaluate("document.getElementById('frame').focus()");
  browser_->press("End", 35);
  const auto last = drawing();
  EXPECT_EQ(last[0]["frame"], 6);
  EXPECT_NE(last[0]["hash"], first[0]["hash"]) << "the first and last frames look alike";
}

TEST_F(ViewerInBrowser, TheSliderChangesTheDrawingAndTheLink) {
  browser_->open(url(scratch() / "exp" / "viewer.html"));
  browser_->evaluate("document.getElementById('frame').focus()");
  auto before = drawing()[0]["hash"];
  for (int k = 1; k <= 3; ++k) {
    browser_->press("ArrowRight", 39);
    EXPECT_EQ(slider(), k);
    const auto now = drawing()[0];
    EXPECT_EQ(now["frame"], k);
    EXPECT_NE(now["hash"], before) << "frame " << k << " looks like the one before";
    before = now["hash"];
  }
  EXPECT_EQ(browser_->evaluate("location.hash"), "#frame=3");
  EXPECT_NE(browser_->evaluate("document.title").get<std::string>().find("frame 3"), std::string::npos);
}

TEST_F(ViewerInBrowser, AFrameLinkOpensAtThatFrame) {
  browser_->open(url(scratch() / "exp" / "viewer.html"));
  browser_->evaluate("document.getElementById('frame').focus()");
  for (int k = 0; k < 4; ++k) browser_->press("ArrowRight", 39);
  const auto scrolled = drawing()[0];
  browser_->open(url(scratch() / "exp" / "viewer.html", "#frame=4"));
  EXPECT_EQ(slider(), 4);
  const auto opened = drawing()[0];
  EXPECT_EQ(opened["frame"], 4);
  EXPECT_EQ(opened["hash"], scrolled["hash"]) << "#frame=4 draws what the slider at 4 draws";
  browser_->open(url(scratch() / "exp" / "viewer.html", "#frame=99"));
  EXPECT_EQ(slider(), 6) << "a frame past the end opens at the last";
}

TEST_F(ViewerInBrowser, PlayAdvancesAndPauseStops) {
  browser_->open(url(scratch() / "exp" / "viewer.html"));
  browser_->click("#play");
  std::set<int> shown;
  for (int k = 0; k < 20; ++k) browser_->wait(50), shown.insert(slider());
  EXPECT_GE(shown.size(), 4u) << "playing for a second at 12 frames a second shows frame after frame";
  browser_->click("#play");
  const int paused = slider();
  browser_->wait(400);
  EXPECT_EQ(slider(), paused) << "paused";
}

TEST_F(ViewerInBrowser, FlippedTrianglesAreThoseOfTheMetrics) {
  const auto metrics = read_json(scratch() / "linear" / "metrics.json")["frames"];
  int flipped_somewhere = 0;
  for (std::size_t k = 0; k < metrics.size(); ++k) {
    browser_->open(url(scratch() / "linear" / "viewer.html", "#frame=" + std::to_string(k)));
    EXPECT_EQ(drawing()[0]["flipped"], metrics[k]["flipped_triangles"]) << "frame " << k;
    flipped_somewhere += metrics[k]["flipped_triangles"].get<int>();
  }
  EXPECT_GT(flipped_somewhere, 0) << "the linear homotopy on man-twirl flips triangles";
}

TEST_F(ViewerInBrowser, ColoursFollowTheChosenMetric) {
  browser_->open(url(scratch() / "linear" / "viewer.html", "#frame=3"));
  std::set<std::uint32_t> hashes;
  for (const char* metric : {"area", "distortion", "flipped", "none"}) {
    browser_->evaluate(std::string("(() => { const s = document.getElementById('metric'); s.value = '") + metric +
                       "'; s.dispatchEvent(new Event('change')); })()");
    hashes.insert(drawing()[0]["hash"].get<std::uint32_t>());
  }
  EXPECT_EQ(hashes.size(), 4u) << "each metric colours the triangles differently";
  EXPECT_EQ(browser_->evaluate("document.getElementById('series').options.length"), 7)
      << "the minimised energy, then the six per-frame metrics over time";
  EXPECT_EQ(browser_->evaluate("document.getElementById('series').options[0].value"), "energy:E^F")
      << "interpolate records the energy of each frame (metrics.json's \"energy\")";
  EXPECT_EQ(browser_->evaluate("document.getElementById('chart-note').textContent"), "");
}

TEST_F(ViewerInBrowser, CompareShowsTwoRunsOnOneSlider) {
  browser_->open(url(scratch() / "compare.html"));
  const auto before = drawing();
  ASSERT_EQ(before.size(), 2u);
  EXPECT_NE(before[0]["hash"], before[1]["hash"]) << "two different runs";
  browser_->evaluate("document.getElementById('frame').focus()");
  browser_->press("ArrowRight", 39);
  const auto after = drawing();
  for (int r = 0; r < 2; ++r) {
    EXPECT_EQ(after[r]["frame"], 1);
    EXPECT_NE(after[r]["hash"], before[r]["hash"]) << "run " << r + 1 << " moved with the slider";
  }
}

TEST_F(ViewerInBrowser, AnOctopusStaysResponsive) {
  const auto shared = checks::shared_meshes();
  if (!shared || !fs::exists(*shared / "octopus.obj")) GTEST_SKIP() << "skipped: ../shared not present";
  const global::Mesh octopus = io::read_mesh(*shared / "octopus.obj");
  const Eigen::Vector2d lo = octopus.vertices.rowwise().minCoeff(), hi = octopus.vertices.rowwise().maxCoeff();
  global::Mesh target = octopus;
  // Half a turn about the top edge: every point on the outer side of the curl, so none flips.
  target.vertices = shapes::Curl{hi.x() - lo.x(), std::numbers::pi, 1}.apply(
      Eigen::Matrix2Xd(octopus.vertices.colwise() - Eigen::Vector2d(lo.x(), hi.y())), 1);
  io::write_obj(target, scratch() / "octopus-curled.obj");
  const auto result =
      run_cli("interpolate --source " + (*shared / "octopus.obj").string() + " --target " +
              (scratch() / "octopus-curled.obj").string() + " --frames 9 --out " + (scratch() / "octopus").string());
  ASSERT_EQ(result.status, 0) << result.error;
  browser_->open(url(scratch() / "octopus" / "viewer.html"));
  const double ms = browser_
                        ->evaluate(R"js((() => {
      const s = document.getElementById("frame"), start = performance.now();
      for (let k = 1; k <= 8; ++k) (s.value = String(k)), s.dispatchEvent(new Event("input"));
      return (performance.now() - start) / 8;
    })())js")
                        .get<double>();
  std::cout << "octopus (66,527 triangles): " << ms << " ms a frame change\n";
  EXPECT_LT(ms, 1000) << "a frame change of an octopus-sized mesh takes under a second";
  EXPECT_EQ(drawing()[0]["frame"], 8);
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
