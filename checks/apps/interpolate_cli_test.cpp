// `affinterp shapes` and `affinterp interpolate` end to end: outputs on generated shapes and the shared
// meshes, and for each kind of bad input a one-line error, a non-zero exit and an untouched OUT.
#include "checks/apps/cli_harness.hpp"
#include "checks/inputs/shared_meshes.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"
#include "theory/global/options.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <numbers>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace affinterp;
using checks::cli_output;
using checks::one_line;
using checks::read_text;
using checks::run_cli;
using checks::write_text;

fs::path scratch(const std::string& name) { return checks::scratch_folder("affinterp_cli_test", name); }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

/// Checks OUT after a successful run of `frames` frames from `source`.
void expect_frames(const fs::path& out, const fs::path& source, int frames, double t0 = 0, double t1 = 1) {
  const global::Mesh mesh = io::read_mesh(source);
  const nlohmann::json metrics = read_json(out / "metrics.json");
  ASSERT_EQ(metrics["frames"].size(), static_cast<std::size_t>(frames));
  for (int k = 0; k < frames; ++k) {
    const auto& frame = metrics["frames"][static_cast<std::size_t>(k)];
    EXPECT_NEAR(frame["t"].get<double>(), t0 + (t1 - t0) * k / (frames - 1), 1e-12);
    const global::Mesh read = io::read_mesh(out / frame["file"].get<std::string>());
    EXPECT_EQ(read.vertex_count(), mesh.vertex_count());
    EXPECT_EQ(read.triangles.cols(), mesh.triangles.cols());
    for (const char* key :
         {"flipped_triangles", "min_det", "max_det", "max_distortion", "mean_distortion", "area_ratio"})
      EXPECT_TRUE(frame.contains(key)) << key;
  }
  EXPECT_FALSE(fs::exists(out / ("frame_" + std::to_string(10000 + frames).substr(1) + ".obj"))) << "no stale frames";
}

TEST(ShapesCli, ListsAndWritesEveryPair) {
  EXPECT_EQ(run_cli("shapes --list").status, 0);
  for (const auto& info : shapes::shape_catalogue()) {
    const fs::path out = scratch("shapes") / info.name;
    ASSERT_EQ(run_cli("shapes " + info.name + " --out " + out.string()).status, 0) << info.name;
    EXPECT_EQ(io::read_mesh(out / "source.obj").triangles, io::read_mesh(out / "target.obj").triangles);
  }
  const auto unknown = run_cli("shapes teapot --out " + scratch("teapot").string());
  EXPECT_EQ(unknown.status, 2);
  EXPECT_TRUE(one_line(unknown.error)) << unknown.error;
  const fs::path strip = scratch("shapes") / "strip-40x5";
  ASSERT_EQ(run_cli("shapes strip-spiral --quads 40x5 --out " + strip.string()).status, 0);
  EXPECT_EQ(io::read_mesh(strip / "source.obj").triangle_count(), 2 * 40 * 5);
  for (const std::string bad : {"strip-spiral --quads 0x5", "strip-spiral --quads 40", "strip-spiral --quads 40x5x2",
                                "strip-spiral --quads 100000x1000", "man-wave --quads 40x5"}) {
    const auto refused = run_cli("shapes " + bad + " --out " + scratch("refused").string());
    EXPECT_EQ(refused.status, 2) << bad;
    EXPECT_TRUE(one_line(refused.error)) << bad << ": " << refused.error;
  }
}

TEST(InterpolateCli, RunsOnEveryGeneratedShape) {
  for (const auto& info : shapes::shape_catalogue()) {
    SCOPED_TRACE(info.name);
    const fs::path folder = scratch("generated") / info.name;
    ASSERT_EQ(run_cli("shapes " + info.name + " --out " + folder.string()).status, 0);
    const auto result =
        run_cli("interpolate --source " + (folder / "source.obj").string() + " --target " +
                (folder / "target.obj").string() + " --frames 5 --no-figures --out " + (folder / "out").string());
    ASSERT_EQ(result.status, 0) << result.error;
    expect_frames(folder / "out", folder / "source.obj", 5);
  }
}

TEST(InterpolateCli, DrawsAFilmstripAnAnimationAndAViewer) {
  const fs::path folder = scratch("figures");
  ASSERT_EQ(run_cli("shapes man-wave --out " + folder.string()).status, 0);
  const fs::path out = folder / "out";
  const auto result =
      run_cli("interpolate --source " + (folder / "source.obj").string() + " --target " +
              (folder / "target.obj").string() + " --frames 6 --time-range -0.25:1.25 --out " + out.string());
  ASSERT_EQ(result.status, 0) << result.error;
  expect_frames(out, folder / "source.obj", 6, -0.25, 1.25);
  EXPECT_GT(fs::file_size(out / "filmstrip.png"), 1000u);
  EXPECT_GT(fs::file_size(out / "filmstrip.svg"), 1000u);
  const std::string gif = read_text(out / "animation.gif");
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  EXPECT_NE(gif.find("NETSCAPE2.0"), std::string::npos) << "loops";
  EXPECT_EQ(gif.back(), ';') << "a complete GIF ends with its trailer";
  const std::string page = read_text(out / "viewer.html");
  EXPECT_NE(page.find("id=\"affinterp-data\""), std::string::npos);
  for (const char* external : {"src=\"http", "href=\"http", "fetch(", "XMLHttpRequest", "import("})
    EXPECT_EQ(page.find(external), std::string::npos) << "the page is self-contained: " << external;
  const nlohmann::json metrics = read_json(out / "metrics.json");
  EXPECT_EQ(metrics["animation"], "animation.gif");
  EXPECT_EQ(metrics["viewer"], "viewer.html");
}

TEST(ViewCli, ComparesRunsAndRefusesWhatIsNotARun) {
  const fs::path folder = scratch("view");
  ASSERT_EQ(run_cli("shapes man-wave --out " + folder.string()).status, 0);
  const std::string io =
      " --source " + (folder / "source.obj").string() + " --target " + (folder / "target.obj").string();
  ASSERT_EQ(run_cli("interpolate" + io + " --frames 4 --no-figures --out " + (folder / "a").string()).status, 0);
  ASSERT_EQ(run_cli("interpolate" + io + " --frames 5 --energy F --no-figures --out " + (folder / "b").string()).status,
            0);
  const auto result = run_cli("view " + (folder / "a").string() + " " + (folder / "b").string() + " -o " +
                              (folder / "compare.html").string());
  ASSERT_EQ(result.status, 0) << result.error;
  EXPECT_GT(fs::file_size(folder / "compare.html"), 1000u);

  write_text(folder / "compare.html", "earlier\n");
  fs::create_directories(folder / "empty");
  fs::create_directories(folder / "broken");
  write_text(folder / "broken" / "metrics.json", "{\"source\": 1");
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {(folder / "empty").string(), "no metrics.json"},
           {(folder / "broken").string(), "metrics.json: [json.exception.parse_error"},
           {(folder / "missing").string(), "missing"},
           {(folder / "a").string() + " --nonsense", "--nonsense"}}) {
    const auto refused = run_cli("view " + args + " -o " + (folder / "compare.html").string());
    EXPECT_NE(refused.status, 0) << args;
    EXPECT_TRUE(one_line(refused.error)) << refused.error;
    EXPECT_NE(refused.error.find(message), std::string::npos) << refused.error;
    EXPECT_EQ(read_text(folder / "compare.html"), "earlier\n");
  }
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(folder))
    files += entry.path().filename().string().find(".partial-") != std::string::npos;
  EXPECT_EQ(files, 0u) << "no partial page left";
}

TEST(InterpolateCli, AcceptsEveryOptionFamily) {
  const fs::path folder = scratch("options");
  ASSERT_EQ(run_cli("shapes random --out " + folder.string()).status, 0);
  const global::Mesh source = io::read_mesh(folder / "source.obj");
  std::string weights;
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) weights += std::to_string(i % 2) + "\n";
  write_text(folder / "weights.txt", weights);
  const std::string io = " --source " + (folder / "source.obj").string() + " --target " +
                         (folder / "target.obj").string() + " --frames 3 --no-figures --out " +
                         (folder / "out").string();
  for (const std::string& options : std::vector<std::string>{
           "--homotopy polar --energy F --no-area-weighted --pin 0 --pin 3@10", "--homotopy svd --energy S --symmetric",
           "--homotopy linear --energy blend --blend-weights " + (folder / "weights.txt").string(),
           "--energy blend --blend-weight 0.2 --rotation-branch principal",
           "--locus '1@5:0,0;0.5,2;1,1' --edge-direction 0:1 --edge-direction 1:2:linear@3 --barycentre-locus none",
           "--barycentre-locus '0,0;1,1;2,0@2'"}) {
    const auto result = run_cli("interpolate " + options + io);
    EXPECT_EQ(result.status, 0) << options << ": " << result.error;
  }
}

// One place decides each default (theory/global/options.hpp): `interpolate` with no option runs what
// global::InterpolationOptions{} says, as metrics.json records it under the options' names.
TEST(InterpolateCli, DefaultsAreTheEnginesDefaults) {
  const fs::path folder = scratch("defaults");
  ASSERT_EQ(run_cli("shapes random --out " + folder.string()).status, 0);
  const auto result = run_cli("interpolate --source " + (folder / "source.obj").string() + " --target " +
                              (folder / "target.obj").string() + " --no-figures --out " + (folder / "out").string());
  ASSERT_EQ(result.status, 0) << result.error;
  const nlohmann::json used = read_json(folder / "out" / "metrics.json")["options"];
  const global::InterpolationOptions defaults{};
  EXPECT_EQ(used["homotopy"], global::to_string(defaults.homotopy));
  EXPECT_EQ(used["energy"], global::to_string(defaults.energy));
  EXPECT_EQ(used["rotation_branch"], global::to_string(defaults.rotation_branch));
  EXPECT_EQ(used["area_weighted"], defaults.area_weighted);
  EXPECT_EQ(used["symmetric"], defaults.symmetric);
  EXPECT_EQ(used["blend_weight"], defaults.blend_weight);
  EXPECT_EQ(used["time_range"], nlohmann::json({defaults.t_begin, defaults.t_end}));
  EXPECT_TRUE(used["pins"].empty() && used["loci"].empty() && used["edge_directions"].empty());
}

/// `interpolate --help`'s line for `flag`, with the choices and default CLI11 prints after it.
std::string help_line(const std::string& help, const std::string& flag) {
  const auto at = help.find("  " + flag + " ");
  return at == std::string::npos ? "" : help.substr(at, help.find('\n', at) - at);
}

template <global::OptionEnum Enum>
void expect_names_and_default_of(const std::string& flag, Enum engine_default, const fs::path& folder) {
  const std::string line = help_line(cli_output("interpolate --help"), flag);
  EXPECT_NE(line.find("{" + global::option_choices<Enum>() + "}=" + global::to_string(engine_default)),
            std::string::npos)
      << flag << ": " << line;
  const std::string io = " --source " + (folder / "source.obj").string() + " --target " +
                         (folder / "target.obj").string() + " --frames 2 --no-figures --out " +
                         (folder / "names").string();
  for (const auto& named : global::OptionNames<Enum>::values) {
    const auto result = run_cli("interpolate " + flag + " " + std::string(named.name) + io);
    ASSERT_EQ(result.status, 0) << flag << " " << named.name << ": " << result.error;
  }
  const auto unknown = run_cli("interpolate " + flag + " not-a-name" + io);
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.error.find("(expected " + global::option_choices<Enum>() + ")"), std::string::npos)
      << unknown.error;
}

// The CLI offers exactly the engine's names for each option enum, with the engine's default, and refuses
// others with the engine's message: a front end that lists or defaults a name of its own fails here.
TEST(InterpolateCli, EnumOptionsAreTheEnginesNamesAndDefaults) {
  const fs::path folder = scratch("names");
  ASSERT_EQ(run_cli("shapes random --out " + folder.string()).status, 0);
  const global::InterpolationOptions defaults{};
  expect_names_and_default_of("--homotopy", defaults.homotopy, folder);
  expect_names_and_default_of("--energy", defaults.energy, folder);
  expect_names_and_default_of("--rotation-branch", defaults.rotation_branch, folder);
}

TEST(InterpolateCli, ClockwiseFilesAreReorientedAndFramesKeepTheirFaceList) {
  const fs::path d = scratch("clockwise");
  write_text(d / "s.obj", "v 0 0\nv 0 1\nv 1 0\nv 1 1\nf 1 2 3\nf 3 2 4\n");
  write_text(d / "t.obj", "v 0 0\nv 0 2\nv 2 0\nv 2 2\nf 1 2 3\nf 3 2 4\n");
  const auto result = run_cli("interpolate --source " + (d / "s.obj").string() + " --target " + (d / "t.obj").string() +
                              " --frames 3 --no-figures --out " + (d / "out").string());
  ASSERT_EQ(result.status, 0) << result.error;
  EXPECT_NE(result.error.find("clockwise"), std::string::npos);
  EXPECT_EQ(io::read_mesh(d / "out" / "frame_0001.obj").triangles, io::read_mesh(d / "s.obj").triangles);
  EXPECT_TRUE(read_json(d / "out" / "metrics.json")["reoriented"].get<bool>());
  EXPECT_EQ(read_json(d / "out" / "metrics.json")["frames"][1]["flipped_triangles"].get<int>(), 0);
}

/// Runs `interpolate ARGS --out OUT` on a folder holding earlier output; expects a refusal that leaves it.
/// `frames` is appended to ARGS (the default --frames 3 would clash with --times).
void expect_refused(const std::string& args, int status, const std::string& message_part,
                    const std::string& frames = " --frames 3") {
  SCOPED_TRACE(args);
  const fs::path out = scratch("refused") / "out";
  fs::create_directories(out);
  write_text(out / "frame_0000.obj", "earlier\n");
  write_text(out / "metrics.json", "{}\n");
  const auto result = run_cli("interpolate " + args + frames + " --out " + out.string());
  EXPECT_EQ(result.status, status) << result.error;
  EXPECT_TRUE(one_line(result.error)) << result.error;
  EXPECT_EQ(result.error.rfind("affinterp: ", 0), 0u) << result.error;
  EXPECT_NE(result.error.find(message_part), std::string::npos) << result.error;
  EXPECT_EQ(read_text(out / "frame_0000.obj"), "earlier\n");
  EXPECT_EQ(read_text(out / "metrics.json"), "{}\n");
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(out.parent_path())) files += entry.path() != out;
  EXPECT_EQ(files, 0u) << "no staging folder left beside OUT";
}

TEST(InterpolateCli, RefusesBadInputsLeavingOutUntouched) {
  const fs::path d = scratch("bad");
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  write_text(d / "s.obj", tri);
  write_text(d / "t.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nf 1 2 3\nf 2 4 3\n");
  write_text(d / "z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0.5\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  write_text(d / "quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\n");
  write_text(d / "fewer.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_text(d / "faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 1\n");
  write_text(d / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  write_text(d / "flipped.obj", "v 0 0 0\nv -1 0 0\nv 0 1 0\nv -1 1 0\nf 1 2 3\nf 2 4 3\n");
  write_text(d / "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  write_text(d / "empty.obj", "# nothing\n");
  write_text(d / "garbled.obj", std::string("v 0 0 0\nv 1\0\x7f 0\n", 16));
  write_text(d / "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 5 3\n");
  write_text(d / "w.txt", "0.5\n");
  const std::string s = (d / "s.obj").string(), t = (d / "t.obj").string();
  const auto pair = [&](const std::string& source, const std::string& target) {
    return "--source " + (d / source).string() + " --target " + (d / target).string();
  };
  expect_refused(pair("s.obj", "missing.obj"), 1, "missing.obj: no such file");
  // a target out of the plane makes a 3D pair (interpolate3_cli_test.sh), which takes no 2D-only option
  expect_refused(pair("s.obj", "z.obj") + " --edge-direction 0:1", 2,
                 "--edge-direction: a 2D option, not available for 3D meshes");
  expect_refused(pair("quad.obj", "quad.obj"), 1, "quad.obj:5: face with 4 vertices");
  expect_refused(pair("s.obj", "fewer.obj"), 1, "fewer.obj: the target has 3 vertices, the source 4");
  expect_refused(pair("s.obj", "faces.obj"), 1, "faces.obj: triangle 1 differs");
  expect_refused(pair("flat.obj", "t.obj"), 1, "flat.obj: source triangle 0 has zero area");
  expect_refused(pair("s.obj", "flipped.obj"), 1, "flipped.obj: 2 target triangle(s) flipped");
  expect_refused(pair("s.obj", "nan.obj"), 1, "nan.obj: vertex 2 has a non-finite coordinate");
  expect_refused(pair("empty.obj", "empty.obj"), 1, "empty.obj: the mesh has no vertices");
  expect_refused(pair("garbled.obj", "t.obj"), 1, "garbled.obj:2: NUL byte");
  expect_refused(pair("range.obj", "t.obj"), 1, "range.obj:6: vertex index 5 is out of range");
  expect_refused(pair("s.obj", "t.obj") + " --pin 4", 2, "--pin names vertex 4");
  expect_refused(pair("s.obj", "t.obj") + " --locus 1:0,0", 2, "--locus '1:0,0'");
  expect_refused(pair("s.obj", "t.obj") + " --edge-direction 1", 2, "--edge-direction '1'");
  expect_refused(pair("s.obj", "t.obj") + " --barycentre-locus 'x'", 2, "--barycentre-locus 'x'");
  expect_refused(pair("s.obj", "t.obj") + " --time-range 1:", 2, "--time-range '1:'");
  expect_refused(pair("s.obj", "t.obj") + " --time-range 1:0", 1, "t_begin <= t_end");
  expect_refused(pair("s.obj", "t.obj") + " --homotopy slerp", 2, "--homotopy: unknown local homotopy 'slerp'");
  expect_refused(pair("s.obj", "t.obj") + " --blend-weight 1.5", 1, "the blend weight w must lie in [0, 1]");
  expect_refused(pair("s.obj", "t.obj") + " --energy blend --blend-weights " + (d / "w.txt").string(), 1,
                 "one weight w_i per triangle (2), got 1");
  expect_refused(pair("s.obj", "t.obj") + " --frames 1", 2, "--frames");
  for (const std::string list : {"''", "0,,1", "0,1,", "a", "'0;1'", "1e999", "0.5x", "nan"})
    expect_refused(pair("s.obj", "t.obj") + " --times " + list, 2,
                   "expected finite reals separated by commas (e.g. 0,0.1,0.5,1)", "");
  expect_refused(pair("s.obj", "t.obj") + " --times 0,1", 2, "--times", " --frames 3");
  expect_refused(pair("s.obj", "t.obj") + " --times 0,1 --time-range 0:2", 2, "--times", "");
  // A flipped target is accepted when allowed (and reported).
  const auto allowed = run_cli("interpolate " + pair("s.obj", "flipped.obj") +
                               " --allow-flipped-target --no-figures --frames 3 --out " + (d / "allowed").string());
  EXPECT_NE(allowed.error.find("flipped"), std::string::npos) << allowed.error;
}

TEST(InterpolateCli, TimesWritesExactlyThoseFramesWithTheirEnergies) {
  const fs::path folder = scratch("times");
  ASSERT_EQ(run_cli("shapes man-wave --out " + folder.string()).status, 0);
  const std::string io =
      " --source " + (folder / "source.obj").string() + " --target " + (folder / "target.obj").string();
  const std::vector<double> times = {0, 0.1, 0.5, 1, -0.25, 1.5, 0.5};
  for (const std::string options :
       {"--energy R", "--energy F", "--energy blend --symmetric", "--energy S --symmetric"}) {
    SCOPED_TRACE(options);
    const fs::path out = folder / "out";
    const auto result =
        run_cli("interpolate " + options + io + " --times 0,0.1,.5,1,-0.25,1.5,0.5 --out " + out.string());
    ASSERT_EQ(result.status, 0) << result.error;
    const nlohmann::json metrics = read_json(out / "metrics.json");
    ASSERT_EQ(metrics["frames"].size(), times.size());
    EXPECT_FALSE(fs::exists(out / "frame_0007.obj"));
    std::vector<double> energies;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const auto& frame = metrics["frames"][k];
      EXPECT_EQ(frame["t"].get<double>(), times[k]);
      ASSERT_TRUE(frame["energy"].is_number());
      const double energy = frame["energy"].get<double>();
      EXPECT_GE(energy, 0.0);
      energies.push_back(energy);
      const bool blend = options.find("blend") != std::string::npos,
                 symmetric = options.find("symm") != std::string::npos;
      EXPECT_EQ(frame.contains("energy_parts"), blend || symmetric);
      if (!frame.contains("energy_parts")) continue;
      const auto& parts = frame["energy_parts"];
      const double C = parts["C"].get<double>();
      if (blend) {
        EXPECT_NEAR(parts["E_F"].get<double>() + parts["E_R"].get<double>() + C, energy, 1e-9 * (1 + energy));
      }
      if (symmetric) {
        EXPECT_NEAR(parts["forward"].get<double>() + parts["backward"].get<double>() + C, energy, 1e-9 * (1 + energy));
      }
    }
    EXPECT_EQ(energies[2], energies[6]) << "the same t, the same frame";
    EXPECT_LT(energies[0], 1e-9 * (1 + energies[2])) << "t = 0 is the source itself";
    // the viewer plots the energy and its parts, and `view` reads them back from metrics.json
    const fs::path page = folder / "view.html";
    ASSERT_EQ(run_cli("view " + out.string() + " -o " + page.string()).status, 0);
    std::vector<std::string> series = {"E^" + options.substr(9, options.find(' ', 9) - 9)};
    if (metrics["frames"][0].contains("energy_parts"))
      for (const auto& [name, value] : metrics["frames"][0]["energy_parts"].items()) series.push_back(name);
    for (const fs::path& html : {out / "viewer.html", page})
      for (const std::string& name : series)
        EXPECT_NE(read_text(html).find("{\"name\":\"" + name), std::string::npos) << html << ": " << name;
  }
}

TEST(InterpolateCli, MetricsListsOnlyWhatIsAskedFor) {
  const fs::path folder = scratch("metrics");
  ASSERT_EQ(run_cli("shapes worm-curl --out " + folder.string()).status, 0);
  const std::string io =
      " --source " + (folder / "source.obj").string() + " --target " + (folder / "target.obj").string();
  for (const auto& [choice, energy, quality] :
       {std::tuple{"energy", true, false}, {"quality", false, true}, {"none", false, false}, {"all", true, true}}) {
    const fs::path out = folder / choice;
    const auto result =
        run_cli("interpolate" + io + " --frames 3 --no-figures --metrics " + choice + " --out " + out.string());
    ASSERT_EQ(result.status, 0) << result.error;
    const nlohmann::json metrics = read_json(out / "metrics.json");
    EXPECT_EQ(metrics["options"]["metrics"], choice);
    for (const auto& frame : metrics["frames"]) {
      EXPECT_EQ(frame.contains("energy"), energy) << choice;
      EXPECT_EQ(frame.contains("min_det"), quality) << choice;
    }
  }
  // `view` computes the quality that such a run left out
  ASSERT_EQ(run_cli("view " + (folder / "none").string() + " -o " + (folder / "view.html").string()).status, 0);
  const auto bad = run_cli("interpolate" + io + " --metrics some --out " + (folder / "bad").string());
  EXPECT_NE(bad.status, 0);
  EXPECT_TRUE(one_line(bad.error)) << bad.error;
}

/// The largest distance between the vertices of frame k of `a` and frame k of `b`, over the bounding box
/// diagonal of `a`'s first frame.
double largest_gap(const fs::path& a, const fs::path& b, std::size_t frames) {
  double gap = 0;
  const global::Mesh first = io::read_mesh(a / "frame_0000.obj");
  const double diagonal = (first.vertices.rowwise().maxCoeff() - first.vertices.rowwise().minCoeff()).norm();
  for (std::size_t k = 0; k < frames; ++k) {
    const std::string name = "frame_" + std::to_string(10000 + k).substr(1) + ".obj";
    const global::Mesh u = io::read_mesh(a / name), v = io::read_mesh(b / name);
    gap = std::max(gap, (u.vertices - v.vertices).colwise().norm().maxCoeff() / diagonal);
  }
  return gap;
}

TEST(InterpolateCli, SymmetricIsSwapInvariantWithDefaultOptions) {
  const fs::path folder = scratch("swap");
  ASSERT_EQ(run_cli("shapes man-wave --out " + folder.string()).status, 0);
  const std::string P = (folder / "source.obj").string(), Q = (folder / "target.obj").string();
  for (const std::string energy : {"F", "S", "R", "blend"}) {
    SCOPED_TRACE(energy);
    const std::string options = " --symmetric --no-figures --energy " + energy;
    ASSERT_EQ(run_cli("interpolate --source " + P + " --target " + Q + options + " --times 0,0.3,0.5,1.2 --out " +
                      (folder / "PQ").string())
                  .status,
              0);
    ASSERT_EQ(run_cli("interpolate --source " + Q + " --target " + P + options + " --times 1,0.7,0.5,-0.2 --out " +
                      (folder / "QP").string())
                  .status,
              0);
    // "To rounding": within the engine's own accuracy, which its frame at t = 0 shows (it should be P
    // exactly; E^S's solves on this mesh are off by about 1e-9 of the diagonal, the others by about 1e-12).
    // A source-dependent gauge edge gave 8e-4 on man0/man1.
    fs::create_directories(folder / "P");
    fs::copy_file(folder / "source.obj", folder / "P" / "frame_0000.obj", fs::copy_options::overwrite_existing);
    const double accuracy = largest_gap(folder / "PQ", folder / "P", 1);
    EXPECT_LT(largest_gap(folder / "PQ", folder / "QP", 4), 1e-11 + 10 * accuracy) << "engine accuracy " << accuracy;
    const nlohmann::json a = read_json(folder / "PQ" / "metrics.json"), b = read_json(folder / "QP" / "metrics.json");
    if (energy != "F") {
      EXPECT_EQ(a["options"]["default_edge_direction"], b["options"]["default_edge_direction"]);
    }
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_NEAR(a["frames"][k]["energy"].get<double>(), b["frames"][k]["energy"].get<double>(),
                  1e-9 * (1 + a["frames"][k]["energy"].get<double>()));
  }
}

/// The target of a single shared mesh: its long axis bent by π/2 (shapes::Curl), a known deformation.
global::Mesh bent(const global::Mesh& mesh) {
  const Eigen::Vector2d lo = mesh.vertices.rowwise().minCoeff(), hi = mesh.vertices.rowwise().maxCoeff();
  const bool along_x = hi.x() - lo.x() >= hi.y() - lo.y();
  const int s = along_x ? 0 : 1;
  Eigen::Matrix2Xd local(2, mesh.vertex_count());
  local.row(0) = mesh.vertices.row(s).array() - lo(s);
  local.row(1) = mesh.vertices.row(1 - s).array() - (lo(1 - s) + hi(1 - s)) / 2;
  global::Mesh target = mesh;
  target.vertices = shapes::Curl{hi(s) - lo(s), std::numbers::pi / 2, 1}.apply(local, 1);
  if (!along_x) target.vertices.row(0) *= -1;  // keep the orientation of the swapped axes
  return target;
}

TEST(InterpolateCli, RunsOnTheSharedMeshes) {
  const auto shared = checks::shared_meshes();
  if (!shared) GTEST_SKIP() << "skipped: ../shared not present";
  for (const char* pose : {"man1.obj", "man2.obj", "man3.obj"}) {
    const fs::path out = scratch("shared") / pose;
    const auto result = run_cli("interpolate --source " + (*shared / "man0.obj").string() + " --target " +
                                (*shared / pose).string() + " --frames 4 --no-figures --out " + out.string());
    ASSERT_EQ(result.status, 0) << result.error;
    expect_frames(out, *shared / "man0.obj", 4);
  }
  for (const char* name : {"arm.obj", "worm.obj", "octopus.obj"}) {
    const fs::path folder = scratch(std::string("shared_") + name);
    io::write_obj(bent(io::read_mesh(*shared / name)), folder / "bent.obj");
    const auto result =
        run_cli("interpolate --source " + (*shared / name).string() + " --target " + (folder / "bent.obj").string() +
                " --frames 3 --no-figures --out " + (folder / "out").string());
    ASSERT_EQ(result.status, 0) << name << ": " << result.error;
    expect_frames(folder / "out", *shared / name, 3);
  }
}

}  // namespace
