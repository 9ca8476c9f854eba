// The command line end to end: exit statuses, error messages, files written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "shadowkit/core/image.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Result {
  int status = -1;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("shadowkit_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  Result run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd =
        std::string(SHADOWKIT_EXE) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int raw = std::system(cmd.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  }
  // A tiny valid scene whose objects entry is `objects`.
  fs::path scene(const std::string& objects,
                 const std::string& camera = R"("position": [0, 6, 8], "look_at": [0, 0, 0])") {
    return write("scene.json", "{\"camera\": {" + camera +
                                   ", \"width\": 80, \"height\": 60},\n\"lights\": [{\"type\": "
                                   "\"point\", \"position\": [1, 5, 1]}],\n\"objects\": [" +
                                   objects + "]}\n");
  }
  void expect_bad_input(const std::string& args, const std::string& message) {
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(message)) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }

  fs::path dir_;
};

constexpr const char* kGround = "v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\nf 1 4 3 2\n";

TEST_F(Cli, RenderWritesOneContractMaskPerLight) {
  write("ground.obj", kGround);
  const fs::path s = scene(R"({"mesh": "ground.obj"}, {"generator": "box", "size": [1, 1, 1]})");
  const Result r = run("render " + s.string() + " --method raytrace --mask " +
                       (dir_ / "m").string() + " --image " + (dir_ / "img.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const shadowkit::Image<std::uint8_t> mask = shadowkit::read_png_gray(dir_ / "m.L0.png");
  EXPECT_EQ(mask.width, 80);
  EXPECT_EQ(mask.height, 60);
  int counts[256] = {};
  for (auto v : mask.pixels) ++counts[v];
  EXPECT_EQ(counts[0] + counts[128] + counts[255], 80 * 60);
  EXPECT_GT(counts[128], 0);
  EXPECT_GT(counts[255], 0);
  EXPECT_TRUE(fs::exists(dir_ / "img.png"));
}

TEST_F(Cli, CompareJsonHasTheContractKeys) {
  write("ground.obj", kGround);
  const Result r = run("compare " + scene(R"({"mesh": "ground.obj"})").string() +
                       " --methods raytrace --json --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 1u);
  for (const char* key : {"method", "light", "build_ms", "shade_ms", "memory_bytes",
                          "mismatch_raw_pct", "mismatch_interior_pct"}) {
    EXPECT_TRUE(j[0].contains(key)) << key;
  }
  EXPECT_EQ(j[0]["mismatch_raw_pct"], 0.0);
}

TEST_F(Cli, BuiltInSceneNamesStandWhereAFileWould) {
  const Result r = run("info tetra:2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["polygons"], 64 + 2);
}

TEST_F(Cli, BadInputIsOneLineAndExitStatusTwo) {
  write("ground.obj", kGround);
  write("bad-line.obj", "v 0 0 0\nv 1 0 0\nv 0 0 one\nf 1 2 3\n");
  write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 0 nan\nf 1 2 3\n");
  write("broken.json", "{\"camera\": {\"position\": [0, 1, 2]\n\"look_at\": [0, 0, 0]}}\n");
  expect_bad_input("info " + (dir_ / "missing.json").string(), "missing.json");
  expect_bad_input("info " + (dir_ / "broken.json").string(), "broken.json:2: malformed JSON");
  expect_bad_input(
      "info " + scene(R"({"mesh": "ground.obj"})",
                      R"("position": [0, 6, 8], "look_at": [0, 0, 0], "fov_y_deg": "x")")
                    .string(),
      "key 'camera.fov_y_deg': expected a number");
  expect_bad_input("info " + scene(R"({"mesh": "bad-line.obj"})").string(), "bad-line.obj:3");
  expect_bad_input("info " + scene(R"({"mesh": "nan.obj"})").string(), "nan.obj:3");
  expect_bad_input(
      "info " + scene(R"({"mesh": "ground.obj"})", R"("position": [0, 6, 8], "look_at": [0, 6, 8])")
                    .string(),
      "key 'camera.look_at': equals camera.position");
  expect_bad_input("render " + scene(R"({"mesh": "ground.obj"})").string() +
                       " --method nosuch --mask " + (dir_ / "m").string(),
                   "method 'nosuch': unknown method");
  expect_bad_input(
      "compare " + scene(R"({"mesh": "ground.obj"})").string() + " --methods raytrace,x",
      "method 'x': unknown method");
  expect_bad_input("render " + scene(R"({"mesh": "ground.obj"})").string() +
                       " --method shadowmap --set shadowmap.nosuch=1 --mask " +
                       (dir_ / "m").string(),
                   "shadowmap.nosuch");
  expect_bad_input("bench", "SCENE");
  expect_bad_input("bench tetra:1 --repeats 1000000000", "--repeats: needs 1 to 100000 timed runs");
  expect_bad_input("bench tetra:1 --warmup -1", "--warmup: needs 0 to 100000 untimed runs");
}

TEST_F(Cli, VoxelRenderWritesBothViews) {
  write("ground.obj", kGround);
  const std::string args = "voxel-render " + scene(R"({"mesh": "ground.obj"})").string() +
                           " --set voxel.resolution=32 --image " + (dir_ / "a.png").string() +
                           " --turned-image " + (dir_ / "b.png").string();
  const Result r = run(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("no shadow work"));
  EXPECT_TRUE(fs::exists(dir_ / "a.png"));
  EXPECT_TRUE(fs::exists(dir_ / "b.png"));
  expect_bad_input(
      "voxel-render square --set voxel.resolution=30 --image " + (dir_ / "c.png").string(),
      "voxel.resolution");
  expect_bad_input(
      "voxel-render square --set voxel.max_subpatches=1000 --image " + (dir_ / "c.png").string(),
      "scene 'square': the voxel method at voxel.resolution=256 makes more than 1000 subpatches");
  expect_bad_input(
      "voxel-render square --set voxel.test=offset --set voxel.framebuffer=0 "
      "--image " +
          (dir_ / "c.png").string() + " --turned-image " + (dir_ / "d.png").string(),
      "--turned-image");
  expect_bad_input("voxel-render square --image " + (dir_ / "c.png").string() + " --turn 30",
                   "--turn requires --turned-image");
}

TEST_F(Cli, VoxelRenderRefusesATurnThatIsNoNumber) {
  for (const char* turn : {"nan", "inf"}) {
    expect_bad_input(
        "voxel-render square --set voxel.resolution=32 --image " + (dir_ / "a.png").string() +
            " --turned-image " + (dir_ / "b.png").string() + " --turn " + turn,
        std::string("option '--turn': expected a finite number of degrees, got ") + turn);
    EXPECT_FALSE(fs::exists(dir_ / "a.png"));
  }
}

// §5.1: one still image, the tessellation drawn in batches as it is made.
TEST_F(Cli, VoxelRenderWithoutFrameBufferWritesTheStillImage) {
  write("ground.obj", kGround);
  const Result r = run("voxel-render " + scene(R"({"mesh": "ground.obj"})").string() +
                       " --set voxel.resolution=32 --set voxel.test=offset --set "
                       "voxel.framebuffer=0 --image " +
                       (dir_ / "still.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr(" batches; "));
  EXPECT_GT(fs::file_size(dir_ / "still.png"), 0u);
}

// The voxel method refuses the scene (more subpatches than voxel.max_subpatches allows):
// its rows say why, every other method's rows are there, and the exit status is 3.
TEST_F(Cli, AMethodThatRefusesTheSceneDoesNotStopTheOthers) {
  write("ground.obj", kGround);
  const std::string s =
      write("two-lights.json",
            R"({"camera": {"position": [0, 6, 8], "look_at": [0, 0, 0], "width": 80, "height": 60},
                "lights": [{"type": "point", "position": [1, 5, 1]},
                           {"type": "directional", "direction": [1, -3, 0.5]}],
                "objects": [{"mesh": "ground.obj"}, {"generator": "box", "size": 1}]})")
          .string();
  const std::string refusal =
      "scene 'two-lights': the voxel method at voxel.resolution=256 makes more than 1000 "
      "subpatches (voxel.max_subpatches); lower voxel.resolution or raise voxel.max_subpatches";
  const std::string bound = " --set voxel.max_subpatches=1000 --threads 1";

  const Result json = run("compare " + s + " --methods voxel,shadowmap --json" + bound);
  ASSERT_EQ(json.status, 3) << json.err;
  const auto rows = nlohmann::json::parse(json.out);
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t light = 0; light < 2; ++light) {
    const auto& voxel = rows[light];
    EXPECT_EQ(voxel, (nlohmann::json{{"method", "voxel"}, {"light", light}, {"failed", refusal}}));
    const auto& shadowmap = rows[2 + light];
    EXPECT_EQ(shadowmap["method"], "shadowmap");
    EXPECT_EQ(shadowmap["light"], light);
    EXPECT_FALSE(shadowmap.contains("failed"));
    EXPECT_LT(double(shadowmap["mismatch_interior_pct"]), 1.0);
  }

  const fs::path report = dir_ / "report";
  const Result table =
      run("compare " + s + " --methods voxel,shadowmap --report " + report.string() + bound);
  EXPECT_EQ(table.status, 3) << table.err;
  EXPECT_THAT(table.out, HasSubstr("voxel      L0   failed: " + refusal + "\n"));
  EXPECT_THAT(table.out, HasSubstr("voxel      L1   failed: " + refusal + "\n"));
  EXPECT_THAT(table.out, HasSubstr("\nshadowmap  L1 "));
  EXPECT_THAT(slurp(report / "index.html"), HasSubstr("failed: " + refusal));
  EXPECT_TRUE(fs::exists(report / "shadowmap.png"));
  EXPECT_FALSE(fs::exists(report / "voxel.png"));

  const Result bench =
      run("bench " + s + " --methods voxel,volume --repeats 1 --warmup 0 --json" + bound);
  EXPECT_EQ(bench.status, 3) << bench.err;
  const auto timed = nlohmann::json::parse(bench.out);
  ASSERT_EQ(timed.size(), 4u);
  EXPECT_EQ(timed[1]["failed"], refusal);
  EXPECT_EQ(timed[3]["method"], "volume");
  EXPECT_TRUE(timed[3].contains("shade_ms"));

  // One method: its refusal is the command's error.
  expect_bad_input("render " + s + " --method voxel --mask " + (dir_ / "m").string() + bound,
                   refusal);
}

TEST_F(Cli, FragmentsWritesPlyAndAreasThatSumToEachPolygon) {
  const fs::path ply = dir_ / "new" / "folder" / "square.ply";  // folders made as for PNGs
  const Result r = run("fragments square --threads 1 --out " + ply.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(ply).rfind("ply\nformat ascii 1.0\n", 0), 0u);
  EXPECT_THAT(slurp(ply), HasSubstr("property uint polygon\nproperty uchar lit_L0\n"));
  const auto j = nlohmann::json::parse(slurp(ply.parent_path() / "square.json"));
  double ground_shadowed = 0;
  for (const auto& p : j["polygons"]) {
    const double area = p["area"];
    ASSERT_EQ(p["lit_area"].size(), 1u);
    EXPECT_NEAR(double(p["lit_area"][0]) + double(p["shadowed_area"][0]), area, 1e-9 * area);
    if (p["object"] == "ground") ground_shadowed += double(p["shadowed_area"][0]);
  }
  // The 2x2 square 1 above the ground, the light 4 above: a shadow square of side 8/3.
  const double expected = (8.0 / 3.0) * (8.0 / 3.0);
  EXPECT_NEAR(ground_shadowed, expected, 1e-9 * expected);
  expect_bad_input("fragments square --out " + (dir_ / "areas.json").string(),
                   "cannot end in .json");
  expect_bad_input("fragments square", "--out");
  expect_bad_input("fragments square --set svbsp.nosuch=1 --out " + ply.string(), "svbsp.nosuch");
  expect_bad_input("fragments square --set svbsp.shadowed_only=1 --out " + ply.string(),
                   "svbsp.shadowed_only");
}

// /dev/full opens and refuses every byte; a small file's bytes leave only as it is closed.
TEST_F(Cli, AFullDiskIsBadInputNotASilentlyShortFile) {
  fs::create_symlink("/dev/full", dir_ / "full.ply");
  expect_bad_input("fragments square --out " + (dir_ / "full.ply").string(),
                   (dir_ / "full.ply").string() + ": write failed");
  fs::create_symlink("/dev/full", dir_ / "areas.json");
  expect_bad_input("fragments square --out " + (dir_ / "areas.ply").string(),
                   (dir_ / "areas.json").string() + ": cannot write");
  fs::create_directory(dir_ / "report");
  fs::create_symlink("/dev/full", dir_ / "report" / "index.html");
  expect_bad_input("compare square --methods raytrace --report " + (dir_ / "report").string(),
                   (dir_ / "report" / "index.html").string() + ": cannot write the report");
}

TEST_F(Cli, DegenerateFacesAreAWarningNotAnError) {
  write("degenerate.obj", std::string(kGround) + "v 9 9 9\nf 5 5 5\n");
  const Result r = run("info " + scene(R"({"mesh": "degenerate.obj"})").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("warning"));
  EXPECT_THAT(r.err, HasSubstr("degenerate"));
}

// The sun-study contract's command line: the four files, shards joined by sun-study-merge
// into the same bytes with any thread count, and bad options named in one line (exit 2).
TEST_F(Cli, SunStudyShardsMergeIntoOneRunsFiles) {
  const std::string study =
      "sun-study table --lat 48.1 --lon 11.6 --utc-offset 1 --from 2025-06-21T04:00 "
      "--to 2025-06-21T21:30 --step 90 --north 20 --heat-map-width 64 --out ";
  const Result whole = run(study + (dir_ / "whole").string() + " --threads 2");
  ASSERT_EQ(whole.status, 0) << whole.err;
  std::string merge = "sun-study-merge";
  for (int i = 0; i < 3; ++i) {
    const fs::path out = dir_ / ("shard" + std::to_string(i));
    const Result r = run(study + out.string() + " --threads 1 --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(r.status, 0) << r.err;
    merge += " " + out.string();
  }
  const Result merged = run(merge + " --out " + (dir_ / "merged").string());
  ASSERT_EQ(merged.status, 0) << merged.err;
  for (const char* f : {"times.csv", "polygons.csv", "sunlit_fraction.f32", "sun_hours.csv"}) {
    const std::string bytes = slurp(dir_ / "whole" / f);
    EXPECT_FALSE(bytes.empty()) << f;
    EXPECT_TRUE(bytes == slurp(dir_ / "merged" / f)) << f;
  }
  const std::string times = slurp(dir_ / "whole" / "times.csv");
  EXPECT_EQ(times.rfind("index,time_utc,azimuth_deg,elevation_deg\n0,2025-06-21T03:00:00Z,", 0),
            0u);
  // 12 steps of 90 minutes from 04:00 to 20:30 local time.
  EXPECT_EQ(fs::file_size(dir_ / "whole" / "sunlit_fraction.f32") % (12 * 4), 0u);
  expect_bad_input(merge + " --out " + (dir_ / "m2").string() + " " + (dir_ / "shard0").string(),
                   "shard");
}

// The help says what SCENE may be, and sun-study's does not offer the --set it refuses.
TEST_F(Cli, HelpNamesMeshFilesAndSunStudyHidesSet) {
  const Result render = run("render --help");
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_THAT(render.out, HasSubstr("scene file, mesh file or built-in scene"));
  EXPECT_THAT(render.out, HasSubstr("--set"));
  const Result study = run("sun-study --help");
  ASSERT_EQ(study.status, 0) << study.err;
  EXPECT_THAT(study.out, HasSubstr("scene file, mesh file or built-in scene"));
  EXPECT_THAT(study.out, ::testing::Not(HasSubstr("--set")));
}

TEST_F(Cli, SunStudyBadOptionsExitWith2NamingTheOption) {
  const std::string out = " --out " + (dir_ / "out").string();
  auto study = [&](const std::string& lat, const std::string& from, const std::string& to,
                   const std::string& step) {
    return "sun-study square --lat " + lat + " --lon 0 --utc-offset 0 --from " + from + " --to " +
           to + " --step " + step + out;
  };
  const std::string day = "2025-06-01T00:00", noon = "2025-06-01T12:00";
  expect_bad_input(study("95", day, noon, "60"), "--lat");
  expect_bad_input(study("45", noon, day, "60"), "--from");
  expect_bad_input(study("45", day, noon, "0"), "--step");
  expect_bad_input(study("45", day, noon, "-5"), "--step");
  expect_bad_input(study("45", day, noon, "60") + " --shard 3/3", "--shard");
  expect_bad_input(study("45", day, noon, "60") + " --shard 1/0", "--shard");
  expect_bad_input(study("45", "2025-02-30T10:00", noon, "60"), "--from");
  expect_bad_input(study("45", day, "'2025-06-01 12:00'", "60"), "--to");
  expect_bad_input(study("45", day, "2025-13-01T12:00", "60"), "--to");
  expect_bad_input(study("45", day, noon, "60") + " --north 400", "--north");
  expect_bad_input(study("45", day, noon, "60") + " --heat-map-width -1", "--heat-map-width");
  expect_bad_input(study("45", day, noon, "60") + " --heat-map-width 9000", "--heat-map-width");
  expect_bad_input(study("45", day, noon, "60") + " --set svbsp.paper=1", "--set");
  expect_bad_input(
      study("45", day, noon, "60").substr(0, study("45", day, noon, "60").find(" --out")), "--out");
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // refused before the folder is made
}

// --lat, --lon and --utc-offset may come from the scene file's site instead; from neither,
// the study is refused naming the option.
TEST_F(Cli, SunStudySiteFromTheSceneOrRefusedNamingTheOption) {
  const std::string period =
      " --from 2025-06-21T04:00 --to 2025-06-21T20:00 --step 240 --out " + (dir_ / "out").string();
  const Result missing = run("sun-study square --lon 0 --utc-offset 0" + period);
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err, "shadowkit: error: --lat: not given and the scene has no site.latitude\n");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const fs::path sited =
      write("sited.json", R"({"camera": {"position": [0, 6, 8], "look_at": [0, 0, 0]},
    "site": {"latitude": 48.85, "longitude": 2.35, "utc_offset": 1},
    "objects": [{"generator": "ground", "size": 4}, {"generator": "box"}]})");
  const Result r = run("sun-study " + sited.string() + period);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "out" / "times.csv")
                .rfind("index,time_utc,azimuth_deg,elevation_deg\n0,2025-06-21T03:00:00Z,", 0),
            0u);
}

}  // namespace
