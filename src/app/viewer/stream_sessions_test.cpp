// The frame stream's scheduling: every connection gets the frame of its newest request, in
// order, and a frame made stale by a newer request is not sent.
#include "stream_sessions.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>

#include "shadowkit/scene/scene_file.h"

namespace shadowkit::viewer {
namespace {

using Connection = StreamSessions::Connection;

// The answers the sessions send, decoded.
class Answers {
 public:
  void add(Connection c, const std::string& bytes) {
    std::uint32_t n = 0;
    for (int b = 0; b < 4; ++b) n |= std::uint32_t(std::uint8_t(bytes[std::size_t(b)])) << (8 * b);
    std::lock_guard lock(mutex_);
    received_.push_back({c, nlohmann::json::parse(bytes.substr(4, n)), bytes.size() - 4 - n});
    arrived_.notify_all();
  }
  struct Answer {
    Connection connection;
    nlohmann::json info;
    std::size_t png_bytes;
  };
  // Waits until \p done holds of the answers so far.
  template <class Done>
  std::vector<Answer> wait(Done done) {
    std::unique_lock lock(mutex_);
    const bool ok =
        arrived_.wait_for(lock, std::chrono::seconds(60), [&] { return done(received_); });
    EXPECT_TRUE(ok) << "no such answers within 60 s";
    return received_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<Answer> received_;
};

std::string request(int id, int width = 64) {
  return R"({"method": "volume", "camera": {"width": )" + std::to_string(width) +
         R"(, "height": 36}, "id": )" + std::to_string(id) + "}";
}

bool answered(const std::vector<Answers::Answer>& answers, Connection c, int id) {
  for (const auto& a : answers) {
    if (a.connection == c && a.info["id"] == id) return true;
  }
  return false;
}

class StreamSessionsTest : public ::testing::Test {
 protected:
  FrameRenderer renderer{load_scene("cubes:27", {})};
  Answers answers;
  StreamSessions sessions{renderer,
                          [this](Connection c, std::string bytes) { answers.add(c, bytes); }};
};

TEST_F(StreamSessionsTest, AnswersARequestWithItsFrame) {
  sessions.request(1, request(5));
  const auto got = answers.wait([](const auto& a) { return !a.empty(); });
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].connection, 1u);
  EXPECT_EQ(got[0].info["id"], 5);
  EXPECT_EQ(got[0].info["width"], 64);
  EXPECT_GT(got[0].png_bytes, 100u);
}

TEST_F(StreamSessionsTest, TheNewestRequestWinsAndFramesComeInOrder) {
  constexpr int kRequests = 200;
  for (int id = 1; id <= kRequests; ++id) sessions.request(7, request(id, 320));
  const auto got = answers.wait([](const auto& a) { return answered(a, 7, kRequests); });
  double last = 0;
  for (const auto& a : got) {
    EXPECT_GT(a.info["id"].get<double>(), last) << "a stale frame after a newer one";
    last = a.info["id"];
  }
  EXPECT_LT(got.size(), std::size_t(kRequests)) << "stale requests were rendered";
  EXPECT_EQ(sessions.replaced_requests() + got.size(), std::size_t(kRequests));
}

TEST_F(StreamSessionsTest, ABadRequestIsAnsweredWithItsReason) {
  sessions.request(1, "{\"id\": 3, \"view\": \"x-ray\"}");
  auto got = answers.wait([](const auto& a) { return !a.empty(); });
  EXPECT_EQ(got[0].info["error"],
            "request: key 'view': unknown view 'x-ray' (expected shaded, "
            "mask or difference)");
  EXPECT_EQ(got[0].png_bytes, 0u);
  sessions.request(1, "not json");
  got = answers.wait([](const auto& a) { return a.size() == 2; });
  EXPECT_EQ(got[1].info["error"], "request: is not valid JSON");
  EXPECT_TRUE(got[1].info["id"].is_null());
  sessions.request(1, "");
  got = answers.wait([](const auto& a) { return a.size() == 3; });
  EXPECT_EQ(got[2].info["error"], "request: is not valid JSON");
  sessions.request(1, request(4));
  got = answers.wait([](const auto& a) { return a.size() == 4; });
  EXPECT_EQ(got[3].info["id"], 4);
}

TEST_F(StreamSessionsTest, EveryConnectionIsServed) {
  for (int round = 1; round <= 20; ++round) {
    for (Connection c = 1; c <= 3; ++c) sessions.request(c, request(round));
  }
  answers.wait(
      [](const auto& a) { return answered(a, 1, 20) && answered(a, 2, 20) && answered(a, 3, 20); });
}

TEST(EncodeAnswer, LengthThenJsonThenPng) {
  const std::string bytes = encode_answer("{}", "PNG");
  EXPECT_EQ(bytes, std::string("\x02\x00\x00\x00{}PNG", 9));
}

}  // namespace
}  // namespace shadowkit::viewer
