#pragma once
// The viewer's frame stream: a WebSocket server (websocketpp over standalone Asio). Text
// messages come in, binary frames go out. This header and frame_stream.cpp are C++17, the
// newest standard websocketpp 0.8 compiles under, so they see nothing of the rest.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace shadowkit::viewer {

/// \brief A WebSocket server on its own thread. Thread-safe: send() and close() may be called
/// from any thread while it runs.
class FrameStream {
 public:
  using Connection = std::uint64_t;
  struct Handlers {
    std::function<void(Connection, std::string)> message;  ///< a text message arrived
    std::function<void(Connection)> closed;                ///< the connection is gone
  };

  /// Listens on \p host at a free port (see port()), taking messages up to \p max_message
  /// bytes (a larger one closes its connection with "message too big"). Throws
  /// std::runtime_error when it cannot listen.
  FrameStream(const std::string& host, std::size_t max_message, Handlers handlers);
  ~FrameStream();
  FrameStream(const FrameStream&) = delete;
  FrameStream& operator=(const FrameStream&) = delete;

  int port() const;
  /// Closes every connection and stops the thread; send() does nothing afterwards. The
  /// destructor stops it too.
  void stop();
  /// Sends \p bytes as one binary message; a connection already gone is ignored.
  void send(Connection connection, std::string bytes);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowkit::viewer
