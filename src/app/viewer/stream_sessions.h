#pragma once
// The frame stream's scheduling: each connection's newest request is the only one that
// counts. A request that arrives while an older one of its connection waits replaces it, so no
// stale frame is ever rendered. A frame already being rendered is finished and sent, since it
// is newer than what its client shows: abandoning it for each newer request would leave a
// client that sends faster than frames are made (a dragged light) without any frame until it
// stops (docs/viewer.md measures it). Only a closed connection abandons its frame.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
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
  /// Requests replaced by a newer one of their connection before they were rendered.
  std::uint64_t replaced_requests() const;

 private:
  void work();
  void answer(Connection connection, const std::string& text);

  FrameRenderer& renderer_;
  std::function<void(Connection, std::string)> send_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  /// Each open connection's newest request not yet taken, if any.
  std::map<Connection, std::optional<std::string>> waiting_;
  Connection last_served_ = 0;
  std::uint64_t replaced_ = 0;
  bool stopping_ = false;
  std::thread worker_;
};

/// The stream's binary message: the info's JSON length (uint32, little-endian), the JSON, then
/// the PNG (none for an error, whose JSON is {"id":..., "error": "one line"}).
std::string encode_answer(const std::string& json, const std::string& png);

}  // namespace shadowkit::viewer
