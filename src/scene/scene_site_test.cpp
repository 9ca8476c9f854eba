// The scene file's `site`, which the sun study reads: its keys, default and checks, each
// error naming the file and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene_file_test_fixture.h"

namespace shadowkit {
namespace {

using ::testing::HasSubstr;

// The fixture's valid scene with a `site` of \p keys.
std::string with_site(std::string scene, const std::string& keys) {
  return scene.insert(1, "\"site\": {" + keys + "},");
}

constexpr const char* kParis = R"("latitude": 48.85, "longitude": 2.35, "utc_offset": 1)";

TEST_F(SceneFileTest, SiteIsReadWithNorthDefaultingToZero) {
  const Scene paris = load_scene_file(write("scene.json", with_site(scene(), kParis)), quiet_);
  ASSERT_TRUE(paris.site.has_value());
  EXPECT_EQ(paris.site->latitude_deg, 48.85);
  EXPECT_EQ(paris.site->longitude_deg, 2.35);
  EXPECT_EQ(paris.site->utc_offset_hours, 1);
  EXPECT_EQ(paris.site->north_deg, 0);

  const std::string turned = std::string(kParis) + R"(, "north": -12.5)";
  EXPECT_EQ(
      load_scene_file(write("scene.json", with_site(scene(), turned)), quiet_).site->north_deg,
      -12.5);
  EXPECT_EQ(paris.site_name, "");
  const std::string named = std::string(kParis) + R"(, "name": "Paris, France")";
  EXPECT_EQ(load_scene_file(write("scene.json", with_site(scene(), named)), quiet_).site_name,
            "Paris, France");
  EXPECT_FALSE(load_scene_file(write("scene.json", scene()), quiet_).site.has_value());
}

TEST_F(SceneFileTest, SiteOutOfRangeNamesTheFileAndKey) {
  const std::string file = (dir_ / "scene.json").string();
  auto error = [&](const std::string& keys) { return error_of(with_site(scene(), keys)); };
  EXPECT_EQ(error(R"("latitude": 95, "longitude": 2.35, "utc_offset": 1)"),
            file + ": key 'site.latitude': must be between -90 and 90 degrees, got 95");
  EXPECT_THAT(error(R"("latitude": 48, "longitude": -181, "utc_offset": 1)"),
              HasSubstr("key 'site.longitude': must be between -180 and 180 degrees"));
  EXPECT_THAT(error(R"("latitude": 48, "longitude": 2, "utc_offset": 15)"),
              HasSubstr("key 'site.utc_offset': must be between -14 and 14 hours"));
  EXPECT_THAT(error(R"("latitude": 48, "longitude": 2, "utc_offset": 1.01)"),
              HasSubstr("key 'site.utc_offset': must be a whole number of minutes"));
  EXPECT_THAT(error(std::string(kParis) + R"(, "north": 400)"),
              HasSubstr("key 'site.north': must be between -360 and 360 degrees"));
}

TEST_F(SceneFileTest, SiteWithAMissingKeyOrAWrongTypeNamesTheKey) {
  const std::string file = (dir_ / "scene.json").string();
  auto error = [&](const std::string& keys) { return error_of(with_site(scene(), keys)); };
  EXPECT_EQ(error(R"("latitude": 48, "utc_offset": 1)"),
            file + ": key 'site.longitude': is missing");
  EXPECT_THAT(error(R"("longitude": 2, "utc_offset": 1)"),
              HasSubstr("key 'site.latitude': is missing"));
  EXPECT_THAT(error(R"("latitude": 48, "longitude": 2)"),
              HasSubstr("key 'site.utc_offset': is missing"));
  EXPECT_EQ(error(R"("latitude": "48.85N", "longitude": 2.35, "utc_offset": 1)"),
            file + ": key 'site.latitude': expected a number, got string");
  EXPECT_THAT(error(std::string(kParis) + R"(, "north": [0])"),
              HasSubstr("key 'site.north': expected a number, got array"));
  std::string listed = scene();
  listed.insert(1, R"("site": [48.85, 2.35, 1],)");
  EXPECT_EQ(error_of(listed), file + ": key 'site': expected an object, got array");
}

// As everywhere in the scene file: a misspelt key would otherwise be silently ignored.
TEST_F(SceneFileTest, UnknownSiteKeyIsWarnedAbout) {
  std::vector<std::string> warnings;
  const Context ctx{0, [&](const std::string& m) { warnings.push_back(m); }};
  const std::string keys = std::string(kParis) + R"(, "nort": 10)";
  const Scene s = load_scene_file(write("scene.json", with_site(scene(), keys)), ctx);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("key 'site.nort' is not part of the scene format"));
  EXPECT_EQ(s.site->north_deg, 0);
}

// A root generator takes the file's other keys as its parameters, but not the site.
TEST_F(SceneFileTest, SiteBesideARootGeneratorIsTheScenesNotAParameter) {
  const std::string text =
      std::string(R"({"generator": "cubes", "count": 8, "site": {)") + kParis + "}}";
  const Scene s = load_scene_file(write("scene.json", text), quiet_);
  EXPECT_EQ(s.face_count(), 8u * 6 + 1);
  ASSERT_TRUE(s.site.has_value());
  EXPECT_EQ(s.site->latitude_deg, 48.85);
}

}  // namespace
}  // namespace shadowkit
