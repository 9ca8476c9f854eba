// The study's site from the scene file's `site` and the command line's options, each option
// in place of its key: the same site gives the same files whichever of them holds it.
#include "study_site.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const char* const kFiles[] = {"times.csv", "polygons.csv", "sunlit_fraction.f32", "sun_hours.csv"};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Paris, with the scene turned so that north matters too.
constexpr const char* kSceneSite =
    R"("site": {"latitude": 48.85, "longitude": 2.35, "utc_offset": 1, "north": 20},)";

class StudySite : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("shadowkit_study_site_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A turned box on a ground square, with \p site ("" or kSceneSite) at the top.
  std::string scene(const std::string& name, const std::string& site) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << "{" << site << R"(
      "camera": {"position": [0, 5, 9], "look_at": [0, 0, 0]},
      "objects": [{"generator": "ground", "size": 6},
                  {"generator": "box", "size": [1, 2, 1],
                   "transform": {"rotate_deg": [0, 25, 0], "translate": [0.5, 1, 0]}}]})";
    return path.string();
  }
  // A day of two-hour steps; no site option given.
  SunStudyOptions study(const std::string& scene, const std::string& out) const {
    SunStudyOptions o;
    o.scene = scene;
    o.from = "2025-06-21T04:00";
    o.to = "2025-06-21T21:00";
    o.step_minutes = 120;
    o.out = (dir_ / out).string();
    return o;
  }
  static SunStudyOptions at(SunStudyOptions o, double lat, double lon, double utc, double north) {
    o.latitude_deg = lat;
    o.longitude_deg = lon;
    o.utc_offset_hours = utc;
    o.north_deg = north;
    return o;
  }
  static void run(const SunStudyOptions& o) {
    ASSERT_EQ(run_sun_study(o, Context{0, [](const std::string&) {}}), 0);
  }
  std::string error_of(const SunStudyOptions& o) const {
    try {
      run_sun_study(o, Context{0, [](const std::string&) {}});
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  bool same_files(const std::string& a, const std::string& b) const {
    bool same = true;
    for (const char* f : kFiles) {
      const std::string x = slurp(dir_ / a / f);
      EXPECT_FALSE(x.empty()) << a << "/" << f;
      same = same && x == slurp(dir_ / b / f);
    }
    return same;
  }
  nlohmann::json settings(const std::string& out) const {
    return nlohmann::json::parse(slurp(dir_ / out / "sun_study.json"))["study"];
  }

  fs::path dir_;
};

TEST_F(StudySite, SceneSiteGivesTheFilesOfTheSameSiteGivenAsOptions) {
  run(study(scene("sited.json", kSceneSite), "from_scene"));
  run(at(study(scene("plain.json", ""), "from_options"), 48.85, 2.35, 1, 20));
  EXPECT_TRUE(same_files("from_scene", "from_options"));
  // The merge compares shards by these: a site's values, wherever they came from.
  EXPECT_EQ(settings("from_scene"), settings("from_options"));
  EXPECT_EQ(settings("from_scene")["north"], 20.0);
}

// Each option given in turn on the scene with a site: the study is that of the scene's site
// with only that field changed.
TEST_F(StudySite, EachOptionGivenOverridesItsSiteKey) {
  const std::string sited = scene("sited.json", kSceneSite), plain = scene("plain.json", "");
  run(study(sited, "site"));
  struct Case {
    const char* name;
    std::optional<double> SunStudyOptions::*option;
    double value;
    SunStudyOptions expected;
  };
  const Case cases[] = {
      {"lat", &SunStudyOptions::latitude_deg, -33.87, at(study(plain, ""), -33.87, 2.35, 1, 20)},
      {"lon", &SunStudyOptions::longitude_deg, 151.2, at(study(plain, ""), 48.85, 151.2, 1, 20)},
      {"utc", &SunStudyOptions::utc_offset_hours, 3, at(study(plain, ""), 48.85, 2.35, 3, 20)},
      {"north", &SunStudyOptions::north_deg, 0, at(study(plain, ""), 48.85, 2.35, 1, 0)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SunStudyOptions given = study(sited, std::string("given_") + c.name);
    given.*c.option = c.value;
    SunStudyOptions expected = c.expected;
    expected.out = (dir_ / (std::string("expected_") + c.name)).string();
    run(given);
    run(expected);
    EXPECT_TRUE(same_files(std::string("given_") + c.name, std::string("expected_") + c.name));
    EXPECT_FALSE(same_files(std::string("given_") + c.name, "site"));  // the option did count
  }
}

TEST_F(StudySite, ASiteValueGivenNowhereIsAnErrorBeforeTheFolderIsMade) {
  const std::string plain = scene("plain.json", "");
  SunStudyOptions o = study(plain, "out");
  EXPECT_EQ(error_of(o), "--lat: not given and the scene has no site.latitude");
  o.latitude_deg = 48.85;
  EXPECT_EQ(error_of(o), "--lon: not given and the scene has no site.longitude");
  o.longitude_deg = 2.35;
  EXPECT_EQ(error_of(o), "--utc-offset: not given and the scene has no site.utc_offset");
  o.scene = "table";  // a built-in scene has no site either
  o.utc_offset_hours.reset();
  EXPECT_EQ(error_of(o), "--utc-offset: not given and the scene has no site.utc_offset");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  o.utc_offset_hours = 1;  // --north alone may be missing: 0
  run(o);
  EXPECT_EQ(settings("out")["north"], 0.0);
}

// The options given are checked before the scene is read, the scene's site as it is read.
TEST_F(StudySite, OptionsGivenAreCheckedBeforeTheScene) {
  SunStudyOptions o = study((dir_ / "no-such-scene.json").string(), "out");
  o.north_deg = 400;
  EXPECT_THAT(error_of(o), HasSubstr("--north: must be between -360 and 360 degrees"));
  o.north_deg.reset();
  o.from = "2025-06-21";
  EXPECT_THAT(error_of(o), HasSubstr("--from '2025-06-21': expected YYYY-MM-DDTHH:MM"));
  o.from = "2025-06-21T04:00";
  EXPECT_THAT(error_of(o), HasSubstr("no-such-scene.json: no such scene file"));
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// A step whose seconds overflow int64_t would make a step of negative length, which the
// fraction plot's check stops on after the contract's files are half written.
TEST_F(StudySite, AStepLongerThanAnyStudyIsAnErrorBeforeTheFolderIsMade) {
  SunStudyOptions o = at(study(scene("plain.json", ""), "out"), 48.85, 2.35, 1, 0);
  o.step_minutes = 1e300;
  EXPECT_EQ(error_of(o),
            "--step: must be at most 1e10 minutes (19,000 years), longer than any study");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  o.step_minutes = 1e10;  // the longest: one step
  run(o);
  EXPECT_EQ(settings("out")["steps"], 1);
  EXPECT_EQ(settings("out")["step_seconds"], 600'000'000'000);
}

// Local times in the years 0000 and 9999 may fall outside them in UTC, where times.csv has
// no four-digit year to write; the scene's own offset counts as much as --utc-offset.
TEST_F(StudySite, StepsOutsideTheYears0000To9999InUtcAreAnError) {
  SunStudyOptions o = at(study(scene("plain.json", ""), "out"), 48.85, 2.35, 5, 0);
  o.from = "0000-01-01T04:00";
  o.to = "0000-01-01T08:00";
  EXPECT_EQ(error_of(o),
            "--from '0000-01-01T04:00': lies before the year 0000 in UTC, which times.csv "
            "cannot write");
  o.from = "9999-12-31T20:00";
  o.to = "9999-12-31T23:59";
  o.utc_offset_hours = -5;
  EXPECT_EQ(error_of(o),
            "--to '9999-12-31T23:59': lies after the year 9999 in UTC, which times.csv "
            "cannot write");
  o.utc_offset_hours.reset();  // the scene's offset, 1, moves the steps back into range
  o.scene = scene("site.json", kSceneSite);
  o.from = "0000-01-01T00:00";
  o.to = "0000-01-01T02:00";
  EXPECT_EQ(error_of(o),
            "--from '0000-01-01T00:00': lies before the year 0000 in UTC, which times.csv "
            "cannot write");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  o.from = "0000-01-01T01:00";  // 0000-01-01T00:00:00Z
  o.to = "0000-01-01T03:00";    // two-hour steps
  run(o);
  const std::string times = slurp(dir_ / "out" / "times.csv");
  EXPECT_NE(times.find("\n0,0000-01-01T00:00:00Z,"), std::string::npos) << times;
  EXPECT_NE(times.find("\n1,0000-01-01T02:00:00Z,"), std::string::npos) << times;
}

TEST(StudySiteOf, OptionsTakeThePlaceOfTheScenesKeys) {
  const sun::Site scene_site{48.85, 2.35, 1, 20};
  SunStudyOptions o;
  o.longitude_deg = -0.13;
  o.north_deg = 0;
  const sun::Site site = sun_study::study_site(o, scene_site);
  EXPECT_EQ(site.latitude_deg, 48.85);
  EXPECT_EQ(site.longitude_deg, -0.13);
  EXPECT_EQ(site.utc_offset_hours, 1);
  EXPECT_EQ(site.north_deg, 0);
}

}  // namespace
}  // namespace shadowkit
