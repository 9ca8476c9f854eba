// energyplus_shading.csv against fractions chosen by hand: its layout (a calendar year of rows
// of EnergyPlus timesteps), area weighting per object and per group, the mean of the steps
// within a row, and the shading-groups file's errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "report_test_study.h"
#include "shading_groups.h"
#include "shadowkit/core/error.h"
#include "study_reports.h"

namespace shadowkit::sun_study {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Rows of the year before June 1 in 2025: 151 days of 24 hours.
constexpr int kJune1 = 151 * 24;

// Eight fractions: polygon 0 (area 1) takes \p roof_small, polygon 1 (area 3) \p roof_large;
// the others are constant so that each column's expected value is easy to state.
std::vector<float> step(float roof_small, float roof_large = 1.0f) {
  return {roof_small, roof_large, 0.5f, 0.0f, 0.25f, 0.0f, 1.0f, 0.0f};
}

// The cells of line \p n of the schedule.
std::vector<std::string> cells(const std::vector<std::string>& lines, std::size_t n) {
  std::vector<std::string> out;
  std::stringstream in(lines.at(n));
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

class EnergyPlusSchedule : public ::testing::Test {
 protected:
  std::vector<std::string> schedule(const StudyRecord& record) {
    write_reports(record);
    return study_.lines(kEnergyPlusShading);
  }
  HandStudy study_{::testing::UnitTest::GetInstance()->current_test_info()->name()};
};

TEST_F(EnergyPlusSchedule, HeaderNamesEachObjectSafelyAndUniquely) {
  study_.write_study("2025-06-01T06:15", 15, {step(1)});
  const std::vector<std::string> lines = schedule(study_.record());
  // "wall,east" loses its comma; the second "roof" is the first's name in another case; the
  // blank name gets the object's index.
  EXPECT_EQ(lines.at(0), "Surface Name,Roof,wall_east,roof_2,object_3");
}

TEST_F(EnergyPlusSchedule, AYearOfHourlyRowsStampedAtTheirEnd) {
  study_.write_study("2025-06-01T06:15", 15, {step(1)});
  const std::vector<std::string> lines = schedule(study_.record());
  ASSERT_EQ(lines.size(), 8760u + 1);
  EXPECT_EQ(cells(lines, 1).at(0), "01/01 01:00");
  EXPECT_EQ(cells(lines, 24).at(0), "01/01 24:00");
  EXPECT_EQ(cells(lines, 25).at(0), "01/02 01:00");
  EXPECT_EQ(cells(lines, 8760).at(0), "12/31 24:00");
  EXPECT_EQ(cells(lines, kJune1 + 7).at(0), "06/01 07:00");
}

TEST_F(EnergyPlusSchedule, FifteenMinuteStepsAverageIntoTheHourTheyEnd) {
  // Steps at 06:15, 06:30, 06:45, 07:00 stand for (06:00, 07:00]; 07:15 starts the next hour.
  study_.write_study(
      "2025-06-01T06:15", 15,
      {step(0), step(0.25f), step(0.5f), step(1), step(1, 0), step(1, 0), step(1, 0), step(1, 0)});
  const std::vector<std::string> lines = schedule(study_.record());
  // Roof: (1 x mean(0, 0.25, 0.5, 1) + 3 x 1) / 4 = 0.859375. The wall is polygon 2's 0.5
  // (its other polygon has no area), the second roof polygon 4's 0.25, object 3 (1 x 1 +
  // 3 x 0) / 4.
  EXPECT_EQ(cells(lines, kJune1 + 7),
            (std::vector<std::string>{"06/01 07:00", "0.8594", "0.5", "0.25", "0.25"}));
  EXPECT_EQ(cells(lines, kJune1 + 8),
            (std::vector<std::string>{"06/01 08:00", "0.25", "0.5", "0.25", "0.25"}));
  // Outside the study: 0.
  EXPECT_EQ(cells(lines, kJune1 + 6),
            (std::vector<std::string>{"06/01 06:00", "0", "0", "0", "0"}));
  EXPECT_EQ(cells(lines, kJune1 + 9),
            (std::vector<std::string>{"06/01 09:00", "0", "0", "0", "0"}));
}

TEST_F(EnergyPlusSchedule, TimestepsMatchingTheStepsCopyEachStep) {
  study_.write_study("2025-06-01T06:15", 15, {step(0), step(0.25f), step(0.5f), step(1)});
  StudyRecord record = study_.record();
  record.energyplus_timesteps = 4;
  const std::vector<std::string> lines = schedule(record);
  ASSERT_EQ(lines.size(), 4u * 8760 + 1);
  const std::size_t six = 4 * (kJune1 + 6);  // the row ending 06:00
  EXPECT_EQ(cells(lines, six).at(0), "06/01 06:00");
  EXPECT_EQ(cells(lines, six + 1),
            (std::vector<std::string>{"06/01 06:15", "0.75", "0.5", "0.25", "0.25"}));
  EXPECT_EQ(cells(lines, six + 2).at(1), "0.8125");  // (0.25 + 3) / 4
  EXPECT_EQ(cells(lines, six + 4),
            (std::vector<std::string>{"06/01 07:00", "1", "0.5", "0.25", "0.25"}));
}

TEST_F(EnergyPlusSchedule, ACoarseStepFillsEveryRowOfItsSpan) {
  // Two-hour steps at 08:00 and 10:00 stand for (06:00, 08:00] and (08:00, 10:00].
  study_.write_study("2025-06-01T08:00", 120, {step(0, 0), step(1, 1)});
  const std::vector<std::string> lines = schedule(study_.record());
  for (int hour : {7, 8}) EXPECT_EQ(cells(lines, kJune1 + hour).at(1), "0") << hour;
  for (int hour : {9, 10}) EXPECT_EQ(cells(lines, kJune1 + hour).at(1), "1") << hour;
  EXPECT_EQ(cells(lines, kJune1 + 7).at(2), "0.5");
  EXPECT_EQ(cells(lines, kJune1 + 6).at(2), "0");
  EXPECT_EQ(cells(lines, kJune1 + 11).at(2), "0");
}

TEST_F(EnergyPlusSchedule, OneStepFillsTheRowItCoversInPart) {
  // One 30-minute step at 06:30 covers half of (06:00, 07:00]: the row is its value.
  study_.write_study("2025-06-01T06:30", 30, {step(0.5f, 0.5f)});
  const std::vector<std::string> lines = schedule(study_.record());
  EXPECT_EQ(cells(lines, kJune1 + 7),
            (std::vector<std::string>{"06/01 07:00", "0.5", "0.5", "0.25", "0.25"}));
  EXPECT_EQ(cells(lines, kJune1 + 8).at(1), "0");
}

TEST_F(EnergyPlusSchedule, RowsAreLocalStandardTimeOfTheFirstStepsYear) {
  // 23:30 UTC on 2023-12-31 is 00:30 on 2024-01-01 at UTC+1: a leap year, 8784 rows.
  study_.write_study("2023-12-31T23:30", 30, {step(1, 1)}, 1);
  const std::vector<std::string> lines = schedule(study_.record());
  ASSERT_EQ(lines.size(), 8784u + 1);
  EXPECT_EQ(cells(lines, 1), (std::vector<std::string>{"01/01 01:00", "1", "0.5", "0.25", "0.25"}));
  EXPECT_EQ(cells(lines, 60 * 24).at(0), "02/29 24:00");
}

TEST_F(EnergyPlusSchedule, StepsOutsideTheYearAreLeftOut) {
  // 30-minute steps from 23:30 on 2025-12-31: 00:00 closes the year's last hour, 00:30 is
  // 2026's.
  study_.write_study("2025-12-31T23:30", 30, {step(1, 1), step(1, 1), step(0, 0)});
  const std::vector<std::string> lines = schedule(study_.record());
  ASSERT_EQ(lines.size(), 8760u + 1);
  EXPECT_EQ(cells(lines, 8760),
            (std::vector<std::string>{"12/31 24:00", "1", "0.5", "0.25", "0.25"}));
}

TEST_F(EnergyPlusSchedule, AStudyAtNightIsZeroThroughout) {
  study_.write_study("2025-12-21T00:00", 60,
                     std::vector<std::vector<float>>(6, std::vector<float>(8)));
  for (const std::string& line : schedule(study_.record())) {
    if (line.starts_with("Surface")) continue;
    EXPECT_EQ(line.substr(11), ",0,0,0,0") << line;
  }
}

TEST_F(EnergyPlusSchedule, ObjectsWithoutAreaAreZero) {
  study_.write_study("2025-06-01T07:00", 60, {step(1, 1)});
  for (Polygons::Row& row : study_.polygons().rows) row.area = 0;
  const std::vector<std::string> lines = schedule(study_.record());
  EXPECT_EQ(cells(lines, kJune1 + 7),
            (std::vector<std::string>{"06/01 07:00", "0", "0", "0", "0"}));
}

TEST_F(EnergyPlusSchedule, UnsupportedTimestepsAreAnInputError) {
  study_.write_study("2025-06-01T07:00", 60, {step(1)});
  StudyRecord record = study_.record();
  record.energyplus_timesteps = 7;
  EXPECT_THAT([&] { write_reports(record); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("--energyplus-timesteps")));
  EXPECT_FALSE(fs::exists(study_.dir() / kEnergyPlusShading));
}

// A shading-groups file in the study's folder.
fs::path groups_file(const HandStudy& study, const std::string& text) {
  const fs::path path = study.dir() / "groups.csv";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST_F(EnergyPlusSchedule, GroupsAreAreaWeightedColumnsAfterTheObjects) {
  study_.write_study("2025-06-01T07:00", 60, {step(0.5f, 1)});
  const ShadingGroups groups = read_shading_groups(
      groups_file(study_, "surface,object,faces\nROOF,0,1\nSouth Wall,1,all\n\nroof,2,0\n"),
      study_.polygons());
  ASSERT_EQ(groups.groups.size(), 2u);
  EXPECT_EQ(groups.groups[0].surface, "ROOF");
  EXPECT_EQ(groups.groups[0].polygons, (std::vector<std::uint32_t>{1, 4}));
  StudyRecord record = study_.record();
  record.shading_groups = &groups;
  const std::vector<std::string> lines = schedule(record);
  // The objects named like the group "ROOF" give way to it.
  EXPECT_EQ(lines.at(0), "Surface Name,Roof_2,wall_east,roof_3,object_3,ROOF,South Wall");
  // ROOF: (3 x 1 + 2 x 0.25) / 5; South Wall: polygon 2's 0.5.
  EXPECT_EQ(cells(lines, kJune1 + 7), (std::vector<std::string>{"06/01 07:00", "0.875", "0.5",
                                                                "0.25", "0.25", "0.7", "0.5"}));
}

TEST_F(EnergyPlusSchedule, GroupFileMayStartWithAByteOrderMark) {
  const ShadingGroups groups = read_shading_groups(
      groups_file(study_, "\xEF\xBB\xBFsurface,object,faces\nA,0,all\n"), study_.polygons());
  ASSERT_EQ(groups.groups.size(), 1u);
  EXPECT_EQ(groups.groups[0].surface, "A");
}

TEST_F(EnergyPlusSchedule, GroupFileErrorsNameTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"surface,faces\n", "groups.csv:1: expected the header"},
      {"surface,object,faces\nA,0\n", "groups.csv:2: expected 3 fields"},
      {"surface,object,faces\n,0,0\n", "groups.csv:2: no surface name"},
      {"surface,object,faces\nA;B,0,0\n", "groups.csv:2: surface 'A;B'"},
      {"surface,object,faces\nA\rB,0,0\n", "groups.csv:2: the surface name holds a control"},
      {"surface,object,faces\nA\tB,0,0\n", "groups.csv:2: the surface name holds a control"},
      {"surface,object,faces\nA,9,0\n", "groups.csv:2: object '9' is no object"},
      {"surface,object,faces\nA,x,0\n", "groups.csv:2: object 'x'"},
      {"surface,object,faces\nA,0,2\n", "groups.csv:2: faces '2': the object has faces 0 to 1"},
      {"surface,object,faces\nA,0,1-0\n", "groups.csv:2: faces '1-0'"},
      {"surface,object,faces\nA,0,0-1\n\na,0,1\n", "groups.csv:4: object 0 face 1 is already"},
      {"", "groups.csv: empty"}};
  for (const auto& [text, message] : cases) {
    EXPECT_THAT([&] { read_shading_groups(groups_file(study_, text), study_.polygons()); },
                ::testing::ThrowsMessage<InputError>(HasSubstr(message)))
        << text;
  }
}

}  // namespace
}  // namespace shadowkit::sun_study
