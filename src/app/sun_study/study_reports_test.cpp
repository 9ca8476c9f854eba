// The reports other than the EnergyPlus schedule: the PLY of sun hours read back, the heat
// map's image and legend, the HTML page, and a whole study run through the command.
#include "study_reports.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>

#include "contract_files.h"
#include "report_test_study.h"
#include "shadowkit/app/commands.h"
#include "shadowkit/core/colour_map.h"
#include "shadowkit/core/error.h"
#include "shadowkit/core/palette.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::sun_study {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// \brief A binary little-endian PLY as write_sun_hours_ply() lays it out.
struct SunHoursPly {
  std::vector<std::string> header;
  std::vector<Vec3> vertices;
  struct Face {
    std::vector<std::int32_t> corners;
    Rgb8 colour;
    float sun_hours = 0;
    std::int32_t polygon = 0;
  };
  std::vector<Face> faces;
};

template <class T>
T read_le(const std::string& bytes, std::size_t& at) {
  static_assert(std::endian::native == std::endian::little);
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

SunHoursPly read_ply(const fs::path& path) {
  const std::string bytes = slurp(path);
  SunHoursPly ply;
  std::size_t at = 0, vertices = 0, faces = 0;
  while (ply.header.empty() || ply.header.back() != "end_header") {
    const std::size_t end = bytes.find('\n', at);
    ply.header.push_back(bytes.substr(at, end - at));
    at = end + 1;
    std::sscanf(ply.header.back().c_str(), "element vertex %zu", &vertices);
    std::sscanf(ply.header.back().c_str(), "element face %zu", &faces);
  }
  for (std::size_t v = 0; v < vertices; ++v) {
    const double x = read_le<double>(bytes, at), y = read_le<double>(bytes, at);
    ply.vertices.push_back({x, y, read_le<double>(bytes, at)});
  }
  for (std::size_t f = 0; f < faces; ++f) {
    SunHoursPly::Face face;
    face.corners.resize(read_le<std::uint8_t>(bytes, at));
    for (std::int32_t& corner : face.corners) corner = read_le<std::int32_t>(bytes, at);
    face.colour.r = read_le<std::uint8_t>(bytes, at);
    face.colour.g = read_le<std::uint8_t>(bytes, at);
    face.colour.b = read_le<std::uint8_t>(bytes, at);
    face.sun_hours = read_le<float>(bytes, at);
    face.polygon = read_le<std::int32_t>(bytes, at);
    ply.faces.push_back(face);
  }
  EXPECT_EQ(at, bytes.size());
  return ply;
}

class StudyReports : public ::testing::Test {
 protected:
  // Three hours of one-hour steps: polygon 0 half lit, 1 lit, 2 half, 4 a quarter, 6 lit.
  void write_three_hours() {
    study_.write_study("2025-06-01T10:00", 60,
                       std::vector<std::vector<float>>(3, {0.5f, 1, 0.5f, 0, 0.25f, 0, 1, 0}));
  }
  HandStudy study_{::testing::UnitTest::GetInstance()->current_test_info()->name()};
};

TEST_F(StudyReports, WritesEveryReportAndLeavesTheContractsFilesAlone) {
  write_three_hours();
  std::vector<std::string> before;
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest}) {
    before.push_back(slurp(study_.dir() / name));
  }
  const SunHoursImage map{1, 1, {2}, {1}};
  StudyRecord record = study_.record();
  record.heat_map = &map;
  EXPECT_EQ(write_reports(record), report_file_names());
  std::size_t i = 0;
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest}) {
    EXPECT_TRUE(slurp(study_.dir() / name) == before[i++]) << name;
  }
  for (const auto& entry : fs::directory_iterator(study_.dir())) {
    EXPECT_NE(entry.path().extension(), ".partial") << entry.path();
  }
}

TEST_F(StudyReports, PlyHoldsTheFacesInWorldCoordinatesWithTheirSunHours) {
  write_three_hours();
  EXPECT_EQ(write_reports(study_.record()),
            (std::vector<std::string>{kEnergyPlusShading, kSunHoursPly, kStudyPage}));
  const SunHoursPly ply = read_ply(study_.dir() / kSunHoursPly);
  EXPECT_EQ(ply.header.at(1), "format binary_little_endian 1.0");
  EXPECT_NE(std::find(ply.header.begin(), ply.header.end(), "property float sun_hours"),
            ply.header.end());
  // 8 + 4 + 4 + 8 vertices; every face but the two degenerate ones, in scene order.
  ASSERT_EQ(ply.vertices.size(), 24u);
  ASSERT_EQ(ply.faces.size(), 6u);
  const std::vector<std::int32_t> polygons{0, 1, 2, 4, 6, 7};
  const std::vector<float> hours{1.5f, 3, 1.5f, 0.75f, 3, 0};
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(ply.faces[f].polygon, polygons[f]);
    EXPECT_FLOAT_EQ(ply.faces[f].sun_hours, hours[f]);
    EXPECT_EQ(ply.faces[f].colour, sequential_colour(hours[f] / 3)) << f;
  }
  // Polygon 4 is the wall moved 5 along z: its corners as the file gives them, moved.
  std::vector<Vec3> corners;
  for (const std::int32_t v : ply.faces[3].corners) corners.push_back(ply.vertices.at(v));
  const std::vector<Vec3> expected{{0, 1, 5}, {0, 1, 6}, {2, 1, 6}, {2, 1, 5}};
  ASSERT_EQ(corners.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(length(corners[k] - expected[k]), 1e-12) << k;
}

TEST_F(StudyReports, HeatMapPaintsHoursAndDrawsItsLegend) {
  write_three_hours();
  // 4 x 3 pixels: hours 0 to 4 on the top row, the rest background but one pixel of 2 hours.
  SunHoursImage map{4, 3, std::vector<double>(12, 0.0), std::vector<std::uint8_t>(12, 0)};
  for (int x = 0; x < 4; ++x) map.hours[x] = x + 1, map.covered[x] = 1;
  map.hours[9] = 2, map.covered[9] = 1;
  StudyRecord record = study_.record();
  record.heat_map = &map;
  write_reports(record);
  const Image<Rgb8> image = read_png_rgb(study_.dir() / kHeatMap);
  EXPECT_EQ(image.height, 220);
  EXPECT_GT(image.width, 4 + 100);
  EXPECT_EQ(image.at(3, 0), sequential_colour(1));
  EXPECT_EQ(image.at(1, 2), sequential_colour(0.5));
  EXPECT_EQ(image.at(0, 1), kBackground);
  EXPECT_EQ(image.at(2, 100), kBackground);
  std::size_t text = 0, top = 0, bottom = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 4; x < image.width; ++x) {
      text += image.at(x, y) == kLegendText;
      top += image.at(x, y) == sequential_colour(1);
      bottom += image.at(x, y) == sequential_colour(0);
    }
  }
  EXPECT_GT(text, 200u);  // the title, five tick labels and the maximum
  EXPECT_GT(top, 10u);    // the colour bar's ends
  EXPECT_GT(bottom, 10u);
}

TEST_F(StudyReports, PageLinksTheFilesAndPlotsTheLargestPolygons) {
  write_three_hours();
  const SunHoursImage map{1, 1, {2}, {1}};
  StudyRecord record = study_.record();
  record.heat_map = &map;
  write_reports(record);
  const std::string page = slurp(study_.dir() / kStudyPage);
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest, kEnergyPlusShading,
                           kSunHoursPly, kHeatMap}) {
    EXPECT_NE(page.find("href=\"" + std::string(name) + "\""), std::string::npos) << name;
  }
  EXPECT_NE(page.find("<img src=\"sun_hours_map.png\""), std::string::npos);
  EXPECT_NE(page.find("wall,east"), std::string::npos);
  EXPECT_NE(page.find("48&deg; N"), std::string::npos);
  EXPECT_EQ(count(page, "<polyline"), 6u);  // the six polygons with area
  EXPECT_EQ(count(page, "<svg"), 1u);
  EXPECT_EQ(count(page, "http"), 1u) << "only the SVG namespace: nothing fetched";
}

TEST_F(StudyReports, LongStudiesPlotAtMost2000PointsALine) {
  study_.write_study("2025-01-01T00:00", 15,
                     std::vector<std::vector<float>>(5000, {1, 1, 1, 1, 1, 1, 1, 1}));
  write_reports(study_.record());
  const std::string page = slurp(study_.dir() / kStudyPage);
  const std::size_t first = page.find("points=\"") + 8;
  const std::string points = page.substr(first, page.find('"', first) - first);
  EXPECT_EQ(count(points, " ") + 1, 1667u);  // runs of 3 steps
}

TEST_F(StudyReports, AYearOfHoursPlotsDailyMeansOfTheStepsWithTheSunUp) {
  // Twelve hours of sun a day; polygon 1, the largest, half lit throughout them.
  std::vector<std::vector<float>> fractions(8760, std::vector<float>(8, 0.0f));
  for (std::size_t k = 0; k < fractions.size(); ++k) {
    if (k % 24 >= 6 && k % 24 < 18) fractions[k] = {1, 0.5f, 1, 0, 1, 0, 1, 1};
  }
  study_.write_study("2025-01-01T00:00", 60, fractions);
  write_reports(study_.record());
  const std::string page = slurp(study_.dir() / kStudyPage);
  EXPECT_NE(page.find("a run of 24 consecutive steps"), std::string::npos);
  const std::size_t first = page.find("points=\"") + 8;
  const std::string points = page.substr(first, page.find('"', first) - first);
  EXPECT_EQ(count(points, " ") + 1, 365u);
  EXPECT_EQ(count(points, ",166.0"), 365u);  // y of 0.5: the nights left out of the mean
}

TEST_F(StudyReports, WithoutPolygonsOfAreaThePageSaysSo) {
  write_three_hours();
  for (Polygons::Row& row : study_.polygons().rows) row.area = 0;
  write_reports(study_.record());
  const std::string page = slurp(study_.dir() / kStudyPage);
  EXPECT_NE(page.find("No polygon has an area."), std::string::npos);
  EXPECT_EQ(count(page, "<svg"), 0u);
  EXPECT_EQ(read_ply(study_.dir() / kSunHoursPly).faces.size(), 6u);
}

TEST_F(StudyReports, AStudyWithoutTheStepsTheRecordSaysIsAnInputError) {
  write_three_hours();
  StudyRecord record = study_.record();
  record.steps = 4;
  EXPECT_THROW(write_reports(record), InputError);
  EXPECT_FALSE(fs::exists(study_.dir() / (std::string(kEnergyPlusShading) + ".partial")));
}

// A whole study through the command: the schedule's noon row is the objects' area-weighted
// fractions of the noon step in sunlit_fraction.f32.
TEST(StudyReportsOfACommand, NoonRowIsTheNoonStepWeightedByArea) {
  const fs::path dir = fs::temp_directory_path() / "shadowkit_reports_command";
  fs::remove_all(dir);
  SunStudyOptions options;
  options.scene = "table";
  options.latitude_deg = 45;
  options.longitude_deg = 0;
  options.utc_offset_hours = 0;
  options.from = "2025-06-21T00:00";
  options.to = "2025-06-21T23:00";
  options.step_minutes = 60;
  options.out = dir.string();
  options.heat_map_width = 64;
  ASSERT_EQ(run_sun_study(options, {0, [](const std::string&) {}}), 0);
  const Scene scene = load_scene("table", {0, [](const std::string&) {}});
  const Polygons polygons = input_polygons(scene);
  write_reports({scene, polygons, dir, 1.0, 24, 0});
  const std::string f32 = slurp(dir / kFractions);
  const auto fraction = [&](std::size_t k, std::size_t p) {
    return read_float32_le(reinterpret_cast<const unsigned char*>(f32.data()) +
                           4 * (k * polygons.rows.size() + p));
  };
  std::ifstream in(dir / kEnergyPlusShading);
  std::string line;
  for (int row = 0; row <= 171 * 24 + 12; ++row) std::getline(in, line);  // June 21, 12:00
  ASSERT_EQ(line.substr(0, 12), "06/21 12:00,");
  std::stringstream cells(line.substr(12));
  std::size_t first_row = 0;
  for (const SceneObject& object : scene.objects) {
    double weighted = 0, area = 0;
    for (std::size_t p = first_row; p < first_row + object.mesh.input_face_count(); ++p) {
      weighted += polygons.rows[p].area * fraction(12, p);
      area += polygons.rows[p].area;
    }
    first_row += object.mesh.input_face_count();
    std::string cell;
    std::getline(cells, cell, ',');
    EXPECT_NEAR(std::stod(cell), area > 0 ? weighted / area : 0, 6e-5) << object.name;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shadowkit::sun_study
