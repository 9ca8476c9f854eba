// The settings catalogue the viewer offers against what the methods accept and the docs list.
#include "shadowkit/methods/registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

MethodOptions one_setting(const std::string& method, const std::string& key,
                          const std::string& value) {
  return MethodOptions(method, {{key, value}});
}

bool names_another_setting(const std::string& message, const std::string& method,
                           const std::string& key) {
  for (const SettingInfo& other : method_settings(method)) {
    if (other.key != key && message.find(method + "." + other.key) != std::string::npos) {
      return true;
    }
  }
  return false;
}

TEST(MethodSettings, EveryDefaultAndChoiceIsAccepted) {
  for (const std::string& method : method_names()) {
    for (const SettingInfo& s : method_settings(method)) {
      SCOPED_TRACE(method + "." + s.key);
      if (!s.fallback.empty()) {
        EXPECT_NO_THROW(make_method(method, one_setting(method, s.key, s.fallback)));
      }
      // A choice is taken alone, or refused only for what another setting says
      // (voxel.framebuffer=0 wants voxel.test=offset).
      for (const std::string& choice : s.choices) {
        try {
          make_method(method, one_setting(method, s.key, choice));
        } catch (const InputError& e) {
          EXPECT_TRUE(names_another_setting(e.what(), method, s.key)) << choice << ": " << e.what();
        }
      }
      if (!s.choices.empty()) {
        EXPECT_THROW(make_method(method, one_setting(method, s.key, "not-a-choice")), InputError);
      }
      EXPECT_TRUE(s.choices.empty() != s.range.empty()) << "a setting has choices or a range";
    }
  }
}

TEST(MethodSettings, UnknownMethodHasNone) {
  EXPECT_TRUE(method_settings("").empty());
  EXPECT_TRUE(method_settings("raytrace").empty());
  EXPECT_TRUE(method_settings("nosuch").empty());
}

// docs/commands.md's table of method settings lists exactly the catalogue, in its order.
TEST(MethodSettings, MatchTheDocsTable) {
  std::ifstream in(std::string(SHADOWKIT_SOURCE_DIR) + "/docs/commands.md");
  ASSERT_TRUE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const std::size_t start = all.find("\n## Method settings\n");
  ASSERT_NE(start, std::string::npos);
  const std::string docs = all.substr(start, all.find("\n## ", start + 1) - start);
  std::vector<std::string> documented;
  const std::regex row(R"(\n\| `([a-z]+\.[a-z_]+)` \|)");
  for (auto it = std::sregex_iterator(docs.begin(), docs.end(), row); it != std::sregex_iterator();
       ++it) {
    documented.push_back((*it)[1]);
  }
  std::vector<std::string> catalogued;
  for (const std::string& method : method_names()) {
    for (const SettingInfo& s : method_settings(method)) catalogued.push_back(method + "." + s.key);
  }
  EXPECT_EQ(documented, catalogued);
}

}  // namespace
}  // namespace shadowkit
