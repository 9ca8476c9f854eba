#include "shadowkit/app/commands.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

using ::testing::HasSubstr;

TEST(Settings, ParsesMethodKeyValue) {
  const auto s = parse_settings({"shadowmap.resolution=512", "shadowmap.bias=0.01"});
  ASSERT_EQ(s.count("shadowmap"), 1u);
  EXPECT_DOUBLE_EQ(s.at("shadowmap").number("resolution", 0), 512);
  EXPECT_DOUBLE_EQ(s.at("shadowmap").number("bias", 0), 0.01);
}

TEST(Settings, RejectsMalformedAndUnknown) {
  EXPECT_THAT([] { parse_settings({"resolution=5"}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("expected METHOD.KEY=VALUE")));
  EXPECT_THAT([] { parse_settings({"nosuch.key=1"}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("unknown method")));
  EXPECT_THAT([] { parse_settings({"shadowmap.resolution=big"}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("expected a number, got 'big'")));
  EXPECT_THAT([] { parse_settings({"volume.nosuch=1"}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("volume.nosuch")));
  EXPECT_THAT([] { parse_settings({"angular.resolution=-3"}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("angular.resolution")));
}

}  // namespace
}  // namespace shadowkit
