// The sun-study command against the contract (sun-study.md): exact fractions where the
// geometry makes them exact, Embree shadow rays elsewhere, and files that do not depend on
// threads or shards.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/raytrace.h"
#include "shadowkit/scene/scene_file.h"
#include "shadowkit/scene/sun_position.h"
#include "testing/sampled_shadow.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

// The contract's four files, and the heat map's counts.
const char* const kFiles[] = {"times.csv", "polygons.csv", "sunlit_fraction.f32", "sun_hours.csv",
                              "sun_steps.u32"};

using Table = std::vector<std::vector<std::string>>;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The rows of a CSV file, its header first.
Table read_csv(const fs::path& p) {
  Table rows;
  std::istringstream in(slurp(p));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cells_in(line);
    std::string cell;
    while (std::getline(cells_in, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::vector<float> read_fractions(const fs::path& p) {
  const std::string bytes = slurp(p);
  std::vector<float> values(bytes.size() / 4);
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint32_t bits = 0;
    for (int b = 0; b < 4; ++b) bits |= std::uint32_t(std::uint8_t(bytes[4 * i + b])) << (8 * b);
    std::memcpy(&values[i], &bits, 4);
  }
  return values;
}

class SunStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parametrised tests: Name/0
    dir_ = fs::temp_directory_path() / ("shadowkit_sun_study_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  // A scene file holding one OBJ mesh.
  fs::path obj_scene(const std::string& obj) {
    write("mesh.obj", obj);
    return write("scene.json", R"({"camera": {"position": [0, 5, 9], "look_at": [0, 0, 0]},
                                   "objects": [{"mesh": "mesh.obj"}]})");
  }
  SunStudyOptions study(const std::string& scene, double lat, const std::string& from,
                        const std::string& to, double step, const std::string& out) const {
    SunStudyOptions o;
    o.scene = scene;
    o.latitude_deg = lat;
    o.longitude_deg = 0;
    o.utc_offset_hours = 0;
    o.from = from;
    o.to = to;
    o.step_minutes = step;
    o.out = (dir_ / out).string();
    o.heat_map_width = 96;  // small: the sanitizer build draws it every step
    return o;
  }
  static void run(const SunStudyOptions& o, int threads = 0) {
    const Context quiet{0, [](const std::string&) {}};
    if (threads == 0) {
      ASSERT_EQ(run_sun_study(o, quiet), 0);
      return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] { ASSERT_EQ(run_sun_study(o, quiet), 0); });
  }
  void expect_same_files(const std::string& a, const std::string& b) const {
    for (const char* f : kFiles) {
      const std::string x = slurp(dir_ / a / f), y = slurp(dir_ / b / f);
      EXPECT_FALSE(x.empty()) << f;
      EXPECT_TRUE(x == y) << a << " and " << b << " differ in " << f;
    }
  }

  fs::path dir_;
};

// Quads in the plane y = Y, x in [x0, x1], z in [z0, z1], facing up (+y) unless reversed.
std::string quad(int first_vertex, double y, double x0, double x1, double z0, double z1,
                 bool up = true) {
  std::ostringstream s;
  s.precision(17);
  s << "v " << x0 << ' ' << y << ' ' << z0 << "\nv " << x0 << ' ' << y << ' ' << z1 << "\nv " << x1
    << ' ' << y << ' ' << z1 << "\nv " << x1 << ' ' << y << ' ' << z0 << "\n";
  const int v = first_vertex;
  s << (up ? "f " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + 2) +
                 " " + std::to_string(v + 3)
           : "f " + std::to_string(v + 3) + " " + std::to_string(v + 2) + " " +
                 std::to_string(v + 1) + " " + std::to_string(v))
    << "\n";
  return s.str();
}

// On the equator at the March equinox the sun runs through the zenith from east to west, so
// the shadow of an east-west edge barely moves north or south. A roof 40 long (x) and 2 wide
// (z) one unit above tiles: one under its middle (fraction 0), one straddling its edge at
// z = 1 (0.5), one clear of it (1). The edge's shadow lies at z = 1 - tz / ty for the
// program's own sun toward (tx, ty, tz), within 0.002 of z = 1.
TEST_F(SunStudy, SquareAboveTilesAtEquinoxNoonOnTheEquator) {
  const fs::path scene = obj_scene(quad(1, 1, -20, 20, -1, 1) +        // 0: roof
                                   quad(5, 0, -0.5, 0.5, -0.5, 0.5) +  // 1: under it
                                   quad(9, 0, -0.5, 0.5, 0.5, 1.5) +   // 2: half under it
                                   quad(13, 0, -0.5, 0.5, 5, 6) +      // 3: clear
                                   quad(17, 0, 3, 4, 3, 4, false) +    // 4: facing down
                                   "f 1 2\n");                         // 5: degenerate
  // Solar noon at longitude 0 on 2025-03-20 is near 12:07 UTC (equation of time).
  run(study(scene.string(), 0, "2025-03-20T12:07", "2025-03-20T12:07", 60, "out"));
  const Table times = read_csv(dir_ / "out" / "times.csv");
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0],
            (std::vector<std::string>{"index", "time_utc", "azimuth_deg", "elevation_deg"}));
  EXPECT_EQ(times[1][1], "2025-03-20T12:07:00Z");
  const sun::SunAngles angles{std::stod(times[1][2]), std::stod(times[1][3])};
  EXPECT_GT(angles.elevation_deg, 89);
  const Vec3 t = sun::toward_sun(angles, 0);

  const Table polygons = read_csv(dir_ / "out" / "polygons.csv");
  ASSERT_EQ(polygons.size(), 7u);
  EXPECT_EQ(polygons[1], (std::vector<std::string>{"0", "0", "0", "80.0000"}));
  EXPECT_EQ(polygons[2], (std::vector<std::string>{"1", "0", "1", "1.00000"}));
  EXPECT_EQ(polygons[6], (std::vector<std::string>{"5", "0", "5", "0.000000"}));

  const std::vector<float> f = read_fractions(dir_ / "out" / "sunlit_fraction.f32");
  ASSERT_EQ(f.size(), 6u);
  EXPECT_EQ(f[0], 1.0f);
  EXPECT_EQ(f[1], 0.0f);
  EXPECT_NEAR(f[2], 0.5 + t.z / t.y, 1e-6);
  EXPECT_NEAR(f[2], 0.5, 2e-3);
  EXPECT_EQ(f[3], 1.0f);
  EXPECT_EQ(f[4], 0.0f);  // the sun is behind it
  EXPECT_EQ(f[5], 0.0f);  // degenerate

  const Table hours = read_csv(dir_ / "out" / "sun_hours.csv");
  ASSERT_EQ(hours.size(), 7u);
  EXPECT_EQ(hours[1], (std::vector<std::string>{"0", "0", "0", "1.00000"}));
  EXPECT_EQ(hours[2][3], "0.000000");
}

// At 50 degrees north on the December solstice the sun never leaves the southern sky: a
// wall facing north gets none of it, the same wall facing south some.
TEST_F(SunStudy, WallFacingNorthInNorthernWinterGetsNoSun) {
  const fs::path scene = obj_scene(
      "v 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nf 1 2 3 4\n"    // normal -z: north
      "v 3 0 0\nv 3 1 0\nv 4 1 0\nv 4 0 0\nf 8 7 6 5\n");  // normal +z: south
  run(study(scene.string(), 50, "2025-12-21T00:00", "2025-12-21T23:30", 30, "out"));
  const std::vector<float> f = read_fractions(dir_ / "out" / "sunlit_fraction.f32");
  ASSERT_EQ(f.size(), 2u * 48);
  double south = 0;
  for (std::size_t k = 0; k < 48; ++k) {
    EXPECT_EQ(f[2 * k], 0.0f) << "step " << k;
    south += f[2 * k + 1];
  }
  EXPECT_GT(south, 10);  // about 8 hours of sun, at 30-minute steps
  const Table hours = read_csv(dir_ / "out" / "sun_hours.csv");
  EXPECT_EQ(hours[1][3], "0.000000");
  EXPECT_GT(std::stod(hours[2][3]), 5);
}

// Nothing shades a lone roof: its fraction is 1 while the sun is up and its sun hours are
// the step length times the steps with the sun up.
TEST_F(SunStudy, UnobstructedRoofSunHoursAreTheDaylightSteps) {
  const fs::path scene = obj_scene(quad(1, 3, 0, 10, 0, 10));
  run(study(scene.string(), 40, "2025-06-21T00:00", "2025-06-21T23:45", 15, "out"));
  const Table times = read_csv(dir_ / "out" / "times.csv");
  const std::vector<float> f = read_fractions(dir_ / "out" / "sunlit_fraction.f32");
  ASSERT_EQ(times.size(), 97u);
  ASSERT_EQ(f.size(), 96u);
  double expected = 0;
  int up = 0;
  for (std::size_t k = 0; k < 96; ++k) {
    EXPECT_EQ(times[k + 1][0], std::to_string(k));
    const bool sun_up = std::stod(times[k + 1][3]) > 0;
    EXPECT_EQ(f[k], sun_up ? 1.0f : 0.0f) << "step " << k;
    expected += sun_up ? 0.25 : 0.0;
    up += sun_up;
  }
  EXPECT_GT(up, 50);  // about 15 hours of day at 40 degrees north in June
  EXPECT_DOUBLE_EQ(std::stod(read_csv(dir_ / "out" / "sun_hours.csv")[1][3]), expected);
  // The heat map's counts: every pixel that sees the roof (from above) saw the sun each step
  // it was up; the others see nothing.
  const std::string counts = slurp(dir_ / "out" / "sun_steps.u32");
  const int width = 96, height = 54;  // the default scene camera's 16:9 at 96 across
  ASSERT_EQ(counts.size(), std::size_t(width) * height * 4);
  std::size_t roof = 0;
  for (std::size_t i = 0; i < counts.size() / 4; ++i) {
    std::uint32_t c = 0;
    std::memcpy(&c, &counts[4 * i], 4);  // little-endian, as this machine
    if (c == 0xffffffffu) continue;
    ASSERT_EQ(c, std::uint32_t(up)) << "pixel " << i;
    ++roof;
  }
  EXPECT_GT(roof, 100u);
}

// "A polygon never shades itself", also when it is warped: a saddle roof, kept as two
// triangles folded along a diagonal that hide each other from a low sun, is wholly sunlit
// while the sun is up (its Newell normal is +y).
TEST_F(SunStudy, AWarpedRoofDoesNotShadeItself) {
  const fs::path scene = obj_scene("v 0 2 -3\nv 3 4 0\nv 0 2 3\nv -3 4 0\nf 1 4 3 2\n");
  run(study(scene.string(), 40, "2025-06-21T00:00", "2025-06-21T23:45", 15, "out"));
  const Table times = read_csv(dir_ / "out" / "times.csv");
  const std::vector<float> f = read_fractions(dir_ / "out" / "sunlit_fraction.f32");
  ASSERT_EQ(f.size(), 96u);
  int low = 0;
  for (std::size_t k = 0; k < 96; ++k) {
    const double elevation = std::stod(times[k + 1][3]);
    EXPECT_NEAR(f[k], elevation > 0 ? 1.0 : 0.0, 1e-6) << "step " << k;
    low += elevation > 0 && elevation < 20;
  }
  EXPECT_GT(low, 8);  // suns low enough for the fold to hide one triangle from them
}

TEST_F(SunStudy, FilesDoNotDependOnThreads) {
  const SunStudyOptions one = study("table", 48, "2025-06-01T04:00", "2025-06-01T20:00", 60, "one");
  SunStudyOptions two = one;
  two.out = (dir_ / "two").string();
  run(one, 1);
  run(two, 2);
  expect_same_files("one", "two");
}

TEST_F(SunStudy, MergedShardsEqualOneRun) {
  const SunStudyOptions whole =
      study("table", 48, "2025-06-01T00:00", "2025-06-01T23:00", 60, "whole");
  run(whole);
  SunStudyMergeOptions merge{{}, (dir_ / "merged").string()};
  for (const int i : {2, 0, 1}) {  // any order
    SunStudyOptions shard = whole;
    shard.shard = std::to_string(i) + "/3";
    shard.out = (dir_ / ("shard" + std::to_string(i))).string();
    run(shard);
    merge.shards.push_back(shard.out);
  }
  EXPECT_EQ(read_csv(dir_ / "shard1" / "times.csv").size(), 9u);  // 8 of the 24 steps
  ASSERT_EQ(run_sun_study_merge(merge, {}), 0);
  expect_same_files("whole", "merged");
  // The merge writes the study's reports too, from the scene its manifest names.
  for (const char* report : {"energyplus_shading.csv", "sun_hours.ply", "sun_hours_map.png"}) {
    const std::string x = slurp(dir_ / "whole" / report), y = slurp(dir_ / "merged" / report);
    EXPECT_FALSE(x.empty()) << report;
    EXPECT_TRUE(x == y) << report << " differs";
    EXPECT_FALSE(fs::exists(dir_ / "shard0" / report)) << "a shard writes no " << report;
  }
}

// A damaged shard's NaN would otherwise reach sun_hours.csv as "nan".
TEST_F(SunStudy, MergeRefusesAShardValueThatIsNoFraction) {
  SunStudyMergeOptions merge{{}, (dir_ / "merged").string()};
  for (const int i : {0, 1}) {
    SunStudyOptions shard =
        study("table", 48, "2025-06-01T10:00", "2025-06-01T12:00", 60, "shard" + std::to_string(i));
    shard.shard = std::to_string(i) + "/2";
    run(shard);
    merge.shards.push_back(shard.out);
  }
  const fs::path f32 = dir_ / "shard1" / "sunlit_fraction.f32";
  {
    std::fstream file(f32, std::ios::binary | std::ios::in | std::ios::out);
    file.seekp(4 * 2);  // step 0, polygon 2
    const float nan = std::numeric_limits<float>::quiet_NaN();
    file.write(reinterpret_cast<const char*>(&nan), 4);
  }
  try {
    run_sun_study_merge(merge, {});
    FAIL() << "merged";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(f32.string() + ": step 0, polygon 2: "), std::string::npos) << what;
    EXPECT_NE(what.find("is not a fraction from 0 to 1"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir_ / "merged" / "sun_hours.csv"));
}

// Fractions against an independent estimate (testing/sampled_shadow.h), toward the
// program's own sun: the sampled points are lifted off the polygon's front, which faces it.
double sampled_sunlit_fraction(const Scene& scene, const raytrace::ShadowRays& rays,
                               std::uint32_t face, Vec3 toward) {
  return 1 - testing::sampled_shadowed_fraction(scene, rays, face, Light::directional(-toward));
}

class SunStudyAgainstShadowRays : public SunStudy,
                                  public ::testing::WithParamInterface<const char*> {};

TEST_P(SunStudyAgainstShadowRays, FractionsAgreeUnderOverhangs) {
  const SunStudyOptions o =
      study(GetParam(), 35, "2025-09-10T07:00", "2025-09-10T17:00", 150, "out");
  run(o);
  const Scene scene = load_scene(GetParam(), {});
  // The polygons made of exactly one scene face, which the samples are drawn on.
  std::vector<std::int64_t> face_of_row;
  for (const SceneObject& object : scene.objects) {
    const std::size_t base = face_of_row.size();
    face_of_row.resize(base + object.mesh.input_face_count(), -1);
    for (std::size_t f = 0; f < object.mesh.face_count(); ++f) {
      std::int64_t& face = face_of_row[base + object.mesh.input_faces[f]];
      face = face == -1 ? std::int64_t(object.first_face + f) : -2;
    }
  }
  const raytrace::ShadowRays rays(scene);
  const Table times = read_csv(dir_ / "out" / "times.csv");
  const std::vector<float> f = read_fractions(dir_ / "out" / "sunlit_fraction.f32");
  const std::size_t P = face_of_row.size();
  ASSERT_EQ(f.size(), (times.size() - 1) * P);
  std::size_t checked = 0;
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const Vec3 t = sun::toward_sun({std::stod(times[k + 1][2]), std::stod(times[k + 1][3])}, 0);
    std::size_t this_step = 0;
    for (std::size_t p = 0; p < P && this_step < 6; ++p) {
      const float fraction = f[k * P + p];
      if (face_of_row[p] < 0 || fraction < 0.05f || fraction > 0.95f) continue;
      ++this_step;
      EXPECT_NEAR(fraction, sampled_sunlit_fraction(scene, rays, std::uint32_t(face_of_row[p]), t),
                  0.005)
          << GetParam() << " step " << k << " polygon " << p;
    }
    checked += this_step;
  }
  EXPECT_GE(checked, 6u);
}

// The table's top overhangs its legs, the chairs and the floor; default.json holds a torus
// knot, an open sheet, a box, a sphere and a pebble on a ground.
INSTANTIATE_TEST_SUITE_P(Scenes, SunStudyAgainstShadowRays,
                         ::testing::Values("table", SHADOWKIT_SOURCE_DIR "/examples/default.json"));

// The contract's numbers: plain decimals with a dot, no exponent, at least 6 significant
// digits, for tiny and huge areas alike.
TEST_F(SunStudy, CsvNumbersArePlainDecimalsWithSixSignificantDigits) {
  write("tiny.obj", quad(1, 0, 0, 0.001, 0, 0.0001));
  write("huge.obj", quad(1, 0, 0, 10000, 0, 1234.56789));
  const fs::path scene =
      write("scene.json", R"({"camera": {"position": [0, 5, 9], "look_at": [0, 0, 0]},
      "objects": [{"mesh": "tiny.obj", "transform": {"translate": [0, 5, 0]}},
                  {"mesh": "huge.obj"}]})");
  run(study(scene.string(), 10, "2025-06-21T05:00", "2025-06-21T19:00", 120, "out"));
  const Table polygons = read_csv(dir_ / "out" / "polygons.csv");
  ASSERT_EQ(polygons.size(), 3u);
  // Within rounding of the working frame, which is centred on both objects.
  EXPECT_NEAR(std::stod(polygons[1][3]), 1e-7, 1e-16);
  EXPECT_NEAR(std::stod(polygons[2][3]), 12345678.9, 1e-6);
  auto check = [](const std::string& cell) {
    ASSERT_FALSE(cell.empty());
    std::size_t significant = 0, dots = 0;
    bool started = false;
    for (std::size_t i = 0; i < cell.size(); ++i) {
      const char c = cell[i];
      if (c == '.') {
        ++dots;
        continue;
      }
      if (c == '-' && i == 0) continue;
      ASSERT_TRUE(c >= '0' && c <= '9') << cell;
      started = started || c != '0';
      significant += started;
    }
    EXPECT_LE(dots, 1u) << cell;
    EXPECT_TRUE(significant >= 6 ||
                (cell.find_first_not_of("-0.") == std::string::npos && cell.size() >= 8))
        << cell;
  };
  for (const char* file : {"times.csv", "polygons.csv", "sun_hours.csv"}) {
    const Table rows = read_csv(dir_ / "out" / file);
    for (std::size_t r = 1; r < rows.size(); ++r) {
      for (std::size_t c = 0; c < rows[r].size(); ++c) {
        if (c == 3 || (std::string(file) == "times.csv" && c == 2)) check(rows[r][c]);
      }
    }
  }
}

}  // namespace
}  // namespace shadowkit
