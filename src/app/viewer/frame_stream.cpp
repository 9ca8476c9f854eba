#include "frame_stream.h"

#define ASIO_STANDALONE
// Asio's scheduler, inlined here, trips GCC's -Wnull-dereference on a pointer it has checked.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace shadowkit::viewer {

using Server = websocketpp::server<websocketpp::config::asio>;

// Frames a connection may have waiting to be sent: a few seconds of 1280x720 frames.
constexpr std::size_t kMaxBufferedBytes = 64 << 20;

struct FrameStream::Impl {
  Server server;
  Handlers handlers;
  std::mutex mutex;  // guards handles and next
  std::map<Connection, websocketpp::connection_hdl> handles;
  std::map<websocketpp::connection_hdl, Connection, std::owner_less<websocketpp::connection_hdl>>
      ids;
  Connection next = 1;
  int port = 0;
  std::thread thread;

  void opened(websocketpp::connection_hdl hdl) {
    std::lock_guard<std::mutex> lock(mutex);
    handles[next] = hdl;
    ids[hdl] = next++;
  }

  Connection id_of(websocketpp::connection_hdl hdl) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = ids.find(hdl);
    return it == ids.end() ? 0 : it->second;
  }

  void closed(websocketpp::connection_hdl hdl) {
    Connection id = 0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      const auto it = ids.find(hdl);
      if (it == ids.end()) return;
      id = it->second;
      handles.erase(id);
      ids.erase(it);
    }
    handlers.closed(id);
  }
};

FrameStream::FrameStream(const std::string& host, std::size_t max_message, Handlers handlers)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.handlers = std::move(handlers);
  s.server.clear_access_channels(websocketpp::log::alevel::all);
  s.server.clear_error_channels(websocketpp::log::elevel::all);
  s.server.init_asio();
  s.server.set_max_message_size(max_message);
  // A frame goes out as soon as it is written, not after the client's delayed ACK.
  s.server.set_socket_init_handler([](websocketpp::connection_hdl, asio::ip::tcp::socket& socket) {
    std::error_code ignored;
    socket.set_option(asio::ip::tcp::no_delay(true), ignored);
  });
  s.server.set_open_handler([&s](websocketpp::connection_hdl hdl) { s.opened(hdl); });
  s.server.set_close_handler([&s](websocketpp::connection_hdl hdl) { s.closed(hdl); });
  s.server.set_fail_handler([&s](websocketpp::connection_hdl hdl) { s.closed(hdl); });
  s.server.set_message_handler([&s](websocketpp::connection_hdl hdl, Server::message_ptr msg) {
    if (msg->get_opcode() != websocketpp::frame::opcode::text) return;
    if (const Connection id = s.id_of(hdl)) s.handlers.message(id, msg->get_payload());
  });
  std::error_code ec;
  const asio::ip::address address = asio::ip::make_address(host, ec);
  if (ec) throw std::runtime_error("'" + host + "' is not an IP address");
  s.server.listen(asio::ip::tcp::endpoint(address, 0), ec);
  if (!ec) s.port = s.server.get_local_endpoint(ec).port();
  if (ec) throw std::runtime_error("cannot listen on " + host + ": " + ec.message());
  s.server.start_accept(ec);
  if (ec) throw std::runtime_error("cannot accept on " + host + ": " + ec.message());
  s.thread = std::thread([&s] { s.server.run(); });
}

FrameStream::~FrameStream() {
  stop();
}

void FrameStream::stop() {
  Impl& s = *impl_;
  if (!s.thread.joinable()) return;
  std::error_code ec;
  s.server.stop_listening(ec);
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    for (const auto& [id, hdl] : s.handles) {
      s.server.close(hdl, websocketpp::close::status::going_away, "server stopping", ec);
    }
    s.handles.clear();
  }
  s.server.stop();
  s.thread.join();
}

int FrameStream::port() const {
  return impl_->port;
}

void FrameStream::send(Connection connection, std::string bytes) {
  Impl& s = *impl_;
  websocketpp::connection_hdl hdl;
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    const auto it = s.handles.find(connection);
    if (it == s.handles.end()) return;
    hdl = it->second;
  }
  std::error_code ec;  // a connection closing meanwhile is no error of ours
  const Server::connection_ptr con = s.server.get_con_from_hdl(hdl, ec);
  if (ec) return;
  // A client that asks and never reads would have its frames pile up here without bound.
  if (con->get_buffered_amount() > kMaxBufferedBytes) {
    con->close(websocketpp::close::status::policy_violation, "frames not read", ec);
    return;
  }
  con->send(bytes.data(), bytes.size(), websocketpp::frame::opcode::binary);
}

}  // namespace shadowkit::viewer
