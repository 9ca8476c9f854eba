#pragma once
// The frame stream's scheduling: each connection's newest request is the only one that
// counts. A request that arrives while an older one of its connection waits replaces it, and
// one that arrives while the older is being rendered makes that frame worthless: it is
// dropped at the next stage instead of being sent.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "shadowkit/app/viewer.h"

namespace shadowkit::viewer {

/// \brief One worker that renders the connections' newest requests in turn.
class StreamSessions {
 public:
  using Connection = std::uint64_t;
  /// \p send receives each answer: encode_answer()'s bytes.
  StreamSessions(FrameRenderer& renderer, std::function<void(Connection, std::string)> send);
  ~StreamSessions();
  StreamSessions(const StreamSessions&) = delete;
  StreamSessions& operator=(const StreamSessions&) = delete;

  /// \p text, a frame request, replaces \p connection's waiting one.
  void request(Connection connection, std::string text);
  /// Forgets \p connection and what it asked for.
  void closed(Connection connection);
  /// Frames rendered and then dropped because a newer request came: a figure for the docs and
  /// the tests.
  std::uint64_t superseded_frames() const;

 private:
  struct Session {
    std::string waiting;       ///< the newest request not yet taken; empty: none
    std::uint64_t newest = 0;  ///< counts the connection's requests
  };
  void work();
  void answer(Connection connection, const std::string& text, std::uint64_t number);

  FrameRenderer& renderer_;
  std::function<void(Connection, std::string)> send_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<Connection, Session> sessions_;
  Connection last_served_ = 0;
  std::uint64_t superseded_ = 0;
  bool stopping_ = false;
  std::thread worker_;
};

/// The stream's binary message: the info's JSON length (uint32, little-endian), the JSON, then
/// the PNG (none for an error, whose JSON is {"id":..., "error": "one line"}).
std::string encode_answer(const std::string& json, const std::string& png);

}  // namespace shadowkit::viewer
