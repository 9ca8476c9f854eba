#include "stream_sessions.h"

#include <exception>

#include "shadowkit/app/pipeline.h"

namespace shadowkit::viewer {

std::string encode_answer(const std::string& json, const std::string& png) {
  std::string bytes(4, '\0');
  const auto n = std::uint32_t(json.size());
  for (int b = 0; b < 4; ++b) bytes[std::size_t(b)] = char((n >> (8 * b)) & 0xff);
  return bytes + json + png;
}

StreamSessions::StreamSessions(FrameRenderer& renderer,
                               std::function<void(Connection, std::string)> send)
    : renderer_(renderer), send_(std::move(send)), worker_([this] { work(); }) {}

StreamSessions::~StreamSessions() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void StreamSessions::request(Connection connection, std::string text) {
  {
    std::lock_guard lock(mutex_);
    Session& session = sessions_[connection];
    session.waiting = std::move(text);
    ++session.newest;
  }
  wake_.notify_all();
}

void StreamSessions::closed(Connection connection) {
  std::lock_guard lock(mutex_);
  sessions_.erase(connection);
}

std::uint64_t StreamSessions::superseded_frames() const {
  std::lock_guard lock(mutex_);
  return superseded_;
}

void StreamSessions::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    // Round robin: the first connection after the last one served that has a request.
    auto next = [&] {
      auto it = sessions_.upper_bound(last_served_);
      for (std::size_t n = 0; n < sessions_.size(); ++n, ++it) {
        if (it == sessions_.end()) it = sessions_.begin();
        if (!it->second.waiting.empty()) return it;
      }
      return sessions_.end();
    };
    wake_.wait(lock, [&] { return stopping_ || next() != sessions_.end(); });
    if (stopping_) return;
    const auto it = next();
    last_served_ = it->first;
    const std::string text = std::move(it->second.waiting);
    it->second.waiting.clear();
    const std::uint64_t number = it->second.newest;
    lock.unlock();
    answer(last_served_, text, number);
    lock.lock();
  }
}

void StreamSessions::answer(Connection connection, const std::string& text, std::uint64_t number) {
  const auto superseded = [&] {
    std::lock_guard lock(mutex_);
    const auto it = sessions_.find(connection);
    return it == sessions_.end() || it->second.newest != number;
  };
  nlohmann::json id;
  try {
    const FrameRequest request = parse_frame_request(text, renderer_.scene_view());
    id = request.id;
    std::optional<Frame> frame = renderer_.render(request, superseded);
    if (!frame) {
      std::lock_guard lock(mutex_);
      ++superseded_;
      return;
    }
    send_(connection, encode_answer(frame->info.dump(), frame->png));
  } catch (const std::exception& e) {
    // The server's answer to any failure is a message to its client; it goes on serving.
    const nlohmann::json error = {{"id", id}, {"error", failure_reason(e)}};
    send_(connection, encode_answer(error.dump(), ""));
  }
}

}  // namespace shadowkit::viewer
