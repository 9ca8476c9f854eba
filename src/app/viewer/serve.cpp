#include <arpa/inet.h>
#include <httplib.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>

#include "frame_stream.h"
#include "page_assets.h"
#include "scene_info.h"
#include "shadowkit/app/commands.h"
#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/viewer.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "stream_sessions.h"
#include "sun_request.h"

namespace shadowkit {
namespace {

using viewer::FrameRenderer;

bool is_loopback(const std::string& host) {
  return host.rfind("127.", 0) == 0 || host == "::1";
}

void check_host(const std::string& host) {
  unsigned char address[16];
  if (inet_pton(AF_INET, host.c_str(), address) != 1 &&
      inet_pton(AF_INET6, host.c_str(), address) != 1) {
    throw InputError("--host '" + host + "'", "expected an IP address, such as 127.0.0.1");
  }
}

// The one line a refused request gets, when its handler gave none.
std::string reason_for(int status) {
  switch (status) {
    case 400:
      return "bad request";
    case 404:
      return "no such page: the viewer serves /, its own files and /api/...";
    case 405:
      return "method not allowed";
    case 413:
      return "request larger than " + std::to_string(viewer::kMaxRequestBytes) + " bytes";
    default:
      return "refused (HTTP " + std::to_string(status) + ")";
  }
}

void refuse(httplib::Response& res, int status, const std::string& reason) {
  res.status = status;
  res.set_content(reason + "\n", "text/plain; charset=utf-8");
}

// Runs \p handle, answering what it throws as the command line words it: 400 for bad input,
// 500 otherwise. Nothing a request does stops the server.
template <class Handle>
httplib::Server::Handler answering(Handle handle) {
  return [handle](const httplib::Request& req, httplib::Response& res) {
    try {
      handle(req, res);
    } catch (const InputError& e) {
      refuse(res, 400, e.what());
    } catch (const std::exception& e) {
      refuse(res, 500, failure_reason(e));
    }
  };
}

void add_routes(httplib::Server& http, FrameRenderer& renderer, const nlohmann::json& info) {
  for (const char* path : {"/", "/viewer.css", "/viewer.js"}) {
    http.Get(path, [](const httplib::Request& req, httplib::Response& res) {
      const viewer::PageAsset* asset = viewer::page_asset(req.path);
      res.set_content(std::string(asset->bytes), std::string(asset->content_type));
    });
  }
  http.Get("/api/scene", [&info](const httplib::Request&, httplib::Response& res) {
    res.set_content(info.dump(), "application/json");
  });
  http.Post("/api/frame",
            answering([&renderer](const httplib::Request& req, httplib::Response& res) {
              const viewer::FrameRequest request =
                  viewer::parse_frame_request(req.body, renderer.scene_view());
              const std::optional<viewer::Frame> frame = renderer.render(request);
              res.set_header("X-Frame-Info", frame->info.dump());
              res.set_content(frame->png, "image/png");
            }));
  http.Post("/api/sun", answering([&renderer](const httplib::Request& req, httplib::Response& res) {
              const nlohmann::json json = viewer::parse_request_json(req.body, {"site", "time"});
              const viewer::SunRequest sun = viewer::parse_sun_request(json, renderer.scene());
              res.set_content(viewer::sun_answer(sun).dump(), "application/json");
            }));
  http.Post(
      "/api/sun-hours", answering([&renderer](const httplib::Request& req, httplib::Response& res) {
        const nlohmann::json json =
            viewer::parse_request_json(req.body, {"site", "time", "step_minutes", "camera"});
        const viewer::SunRequest sun = viewer::parse_sun_request(json, renderer.scene());
        std::vector<std::string> ignored;
        const SceneView view = viewer::parse_request_view(json, renderer.scene_view(), ignored);
        res.set_content(renderer.sun_hours(sun.site, sun.day, view.camera), "image/png");
      }));
  http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) refuse(res, res.status, reason_for(res.status));
  });
}

// SIGINT and SIGTERM stop the server; blocked in every thread but the one that waits for them
// (threads inherit the mask, so this comes before any is started).
class StopSignals {
 public:
  StopSignals() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    sigaddset(&set_, SIGUSR1);
    pthread_sigmask(SIG_BLOCK, &set_, &previous_);
  }
  ~StopSignals() {
    if (waiter_.joinable()) {
      pthread_kill(waiter_.native_handle(), SIGUSR1);
      waiter_.join();
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  void on_signal(std::function<void()> stop) {
    waiter_ = std::thread([this, stop = std::move(stop)] {
      int signal = 0;
      sigwait(&set_, &signal);
      if (signal != SIGUSR1) stop();
    });
  }

 private:
  sigset_t set_{}, previous_{};
  std::thread waiter_;
};

}  // namespace

int run_serve(const ServeOptions& options, const Context& ctx) {
  check_host(options.host);
  StopSignals signals;
  FrameRenderer renderer(load_scene(options.scene, ctx));
  std::unique_ptr<viewer::StreamSessions> sessions;
  const viewer::FrameStream::Handlers handlers = {
      [&](viewer::FrameStream::Connection c, std::string text) {
        sessions->request(c, std::move(text));
      },
      [&](viewer::FrameStream::Connection c) { sessions->closed(c); }};
  std::optional<viewer::FrameStream> stream;
  try {
    stream.emplace(options.host, viewer::kMaxRequestBytes, handlers);
  } catch (const std::runtime_error& e) {
    throw InputError("--host " + options.host, e.what());
  }
  sessions = std::make_unique<viewer::StreamSessions>(
      renderer, [&](viewer::FrameStream::Connection c, std::string bytes) {
        stream->send(c, std::move(bytes));
      });

  httplib::Server http;
  http.set_payload_max_length(viewer::kMaxRequestBytes);
  http.set_tcp_nodelay(true);  // a frame's answer goes out whole, not after a delayed ACK
  http.set_keep_alive_timeout(2);
  http.set_read_timeout(5, 0);
  const int port = options.port == 0
                       ? http.bind_to_any_port(options.host)
                       : (http.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    throw InputError("--port " + std::to_string(options.port),
                     "cannot listen on " + options.host + " (in use, or not this machine's)");
  }
  const std::string host =
      options.host.find(':') == std::string::npos ? options.host : "[" + options.host + "]";
  const nlohmann::json info =
      viewer::scene_info(renderer, "ws://" + host + ":" + std::to_string(stream->port()) + "/");
  add_routes(http, renderer, info);
  if (!is_loopback(options.host)) {
    ctx.warning("--host " + options.host +
                ": the viewer is open to every machine that can reach this address; it has no "
                "password");
  }
  std::atomic<bool> listening_over = false;
  signals.on_signal([&http, &listening_over] {
    // A signal may come before listen_after_bind() runs, when stop() would be lost.
    while (!http.is_running() && !listening_over) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    http.stop();
  });
  std::printf("shadowkit serve: http://%s:%d/ (frame stream ws://%s:%d/; Ctrl-C stops)\n",
              host.c_str(), port, host.c_str(), stream->port());
  std::fflush(stdout);
  http.listen_after_bind();
  listening_over = true;
  stream->stop();
  sessions.reset();
  return 0;
}

}  // namespace shadowkit
