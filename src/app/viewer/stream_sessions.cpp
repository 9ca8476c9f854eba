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
    std::optional<std::string>& waiting = waiting_[connection];
    replaced_ += waiting.has_value();
    waiting = std::move(text);
  }
  wake_.notify_all();
}

void StreamSessions::closed(Connection connection) {
  std::lock_guard lock(mutex_);
  waiting_.erase(connection);
}

std::uint64_t StreamSessions::replaced_requests() const {
  std::lock_guard lock(mutex_);
  return replaced_;
}

void StreamSessions::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    // Round robin: the first connection after the last one served that has a request.
    auto next = [&] {
      auto it = waiting_.upper_bound(last_served_);
      for (std::size_t n = 0; n < waiting_.size(); ++n, ++it) {
        if (it == waiting_.end()) it = waiting_.begin();
        if (it->second) return it;
      }
      return waiting_.end();
    };
    wake_.wait(lock, [&] { return stopping_ || next() != waiting_.end(); });
    if (stopping_) return;
    const auto it = next();
    last_served_ = it->first;
    const std::string text = std::move(*it->second);
    it->second.reset();
    lock.unlock();
    answer(last_served_, text);
    lock.lock();
  }
}

void StreamSessions::answer(Connection connection, const std::string& text) {
  const auto closed = [&] {
    std::lock_guard lock(mutex_);
    return waiting_.find(connection) == waiting_.end();
  };
  nlohmann::json id;
  try {
    const FrameRequest request = parse_frame_request(text, renderer_.scene_view());
    id = request.id;
    std::optional<Frame> frame = renderer_.render(request, closed);
    if (frame) send_(connection, encode_answer(frame->info.dump(), frame->png));
  } catch (const std::exception& e) {
    // The server's answer to any failure is a message to its client; it goes on serving.
    const nlohmann::json error = {{"id", id}, {"error", failure_reason(e)}};
    send_(connection, encode_answer(error.dump(), ""));
  }
}

}  // namespace shadowkit::viewer
