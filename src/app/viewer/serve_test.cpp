// `shadowkit serve` as a process, over HTTP on loopback: the page's files, the API, and hostile
// requests, each answered with a 4xx and one line while the server goes on serving.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <string>

extern char** environ;

namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// `shadowkit serve ARGS...` with its stdout read until it prints its URL; stopped with SIGTERM.
class ServeProcess {
 public:
  explicit ServeProcess(std::vector<std::string> args) {
    args.insert(args.begin(), {SHADOWKIT_EXE, "serve"});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2];
    EXPECT_EQ(pipe(out), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    EXPECT_EQ(posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    char c;
    while (read(out[0], &c, 1) == 1) {
      output_ += c;
      if (c == '\n' && output_.find("http://") != std::string::npos) break;
    }
    out_ = out[0];
    std::smatch m;
    if (std::regex_search(output_, m, std::regex(R"(http://([0-9.]+):([0-9]+)/)"))) {
      host_ = m[1];
      port_ = std::stoi(m[2]);
    }
  }
  ~ServeProcess() {
    if (pid_ > 0 && !stopped_) stop();
    close(out_);
  }
  /// SIGTERM, then the exit status; -1 when it has not exited 30 s later (it is then killed).
  int stop() {
    stopped_ = true;
    kill(pid_, SIGTERM);
    int status = 0;
    for (int waited_ms = 0; waitpid(pid_, &status, WNOHANG) == 0; waited_ms += 10) {
      if (waited_ms > 30000) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        return -1;
      }
      usleep(10000);
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  /// Exit status of a process that stops by itself (a refused option), with all it printed.
  int wait() {
    stopped_ = true;
    char buffer[4096];
    for (ssize_t n; (n = read(out_, buffer, sizeof buffer)) > 0;)
      output_.append(buffer, std::size_t(n));
    int status = 0;
    waitpid(pid_, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  httplib::Client client() const {
    httplib::Client c(host_, port_);
    c.set_read_timeout(120, 0);
    c.set_tcp_nodelay(true);
    return c;
  }
  bool listening() const { return port_ > 0; }
  const std::string& output() const { return output_; }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  bool stopped_ = false;
  std::string output_, host_;
  int port_ = 0;
};

// The answer is a refusal with \p status and one line holding \p reason.
void expect_refused(const httplib::Result& res, int status, const std::string& reason) {
  ASSERT_TRUE(res) << "no answer";
  EXPECT_EQ(res->status, status);
  EXPECT_THAT(res->body, HasSubstr(reason));
  EXPECT_EQ(res->body.find('\n'), res->body.size() - 1) << "not one line: " << res->body;
}

const std::string kFrame = R"({"method": "volume", "camera": {"width": 64, "height": 36}})";

class Serve : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(server.listening()) << server.output(); }
  ServeProcess server{{"cubes:27", "--port", "0"}};
};

TEST_F(Serve, ServesThePageTheSceneAndFrames) {
  httplib::Client c = server.client();
  auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_THAT(page->body, HasSubstr("<script src=\"/viewer.js\">"));
  EXPECT_EQ(c.Get("/viewer.js")->get_header_value("Content-Type"),
            "text/javascript; charset=utf-8");
  EXPECT_EQ(c.Get("/viewer.css")->status, 200);
  const auto scene = nlohmann::json::parse(c.Get("/api/scene")->body);
  EXPECT_EQ(scene["name"], "cubes:27");
  EXPECT_THAT(scene["stream"].get<std::string>(), StartsWith("ws://127.0.0.1:"));
  EXPECT_EQ(scene["methods"].size(), 6u);
  const auto frame = c.Post("/api/frame", kFrame, "application/json");
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->status, 200);
  EXPECT_EQ(frame->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(frame->body.substr(1, 3), "PNG");
  const auto info = nlohmann::json::parse(frame->get_header_value("X-Frame-Info"));
  EXPECT_EQ(info["width"], 64);
  EXPECT_EQ(info["method"], "volume");
  EXPECT_EQ(server.stop(), 0);
}

TEST_F(Serve, NoRequestPathReachesTheFileSystem) {
  httplib::Client c = server.client();
  for (const char* path :
       {"/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd",
        "//etc/passwd", "/viewer.js/../../../etc/passwd", "/api/../../etc/passwd", "/index.html",
        "/page/viewer.js", "/src/app/viewer/page/viewer.js", "/CMakeLists.txt",
        "/api/scene/../../../../etc/passwd", "/%00", "/api/frame\\..\\..\\etc\\passwd"}) {
    SCOPED_TRACE(path);
    const auto res = c.Get(path);
    ASSERT_TRUE(res);
    EXPECT_THAT(res->status, ::testing::AnyOf(400, 404));
    EXPECT_THAT(res->body, ::testing::Not(HasSubstr("root:")));
  }
  expect_refused(c.Get("/../../etc/passwd"), 404, "no such page");
  EXPECT_EQ(c.Get("/")->status, 200);
}

TEST_F(Serve, RefusesHostileRequestsAndKeepsServing) {
  httplib::Client c = server.client();
  expect_refused(c.Post("/api/frame", std::string(1 << 20, '{'), "application/json"), 413,
                 "request larger than 65536 bytes");
  expect_refused(c.Post("/api/frame", "{\"method\": ", "application/json"), 400,
                 "request: is not valid JSON");
  expect_refused(c.Post("/api/frame", "\xff\xfe{}", "application/json"), 400,
                 "request: is not valid JSON");
  expect_refused(
      c.Post("/api/frame", R"({"camera": {"width": 31623, "height": 31623}})", "application/json"),
      400, "request: key 'camera.width'");
  expect_refused(
      c.Post("/api/frame", R"({"camera": {"width": 4000, "height": 4000}})", "application/json"),
      400, "request: key 'camera': 4000x4000 is more than the viewer's");
  expect_refused(
      c.Post("/api/frame", std::string(5000, '[') + std::string(5000, ']'), "application/json"),
      400, "request: nests deeper than any request");
  expect_refused(c.Post("/api/frame", R"({"method": "voxel", "settings": {"max_subpatches": 1}})",
                        "application/json"),
                 400, "voxel.max_subpatches");
  expect_refused(c.Post("/api/sun", R"({"time": "2026-02-30T12:00"})", "application/json"), 400,
                 "request: key 'site': is missing (the scene has none)");
  expect_refused(c.Post("/api/sun", R"({"time": "2026-02-30T12:00", "site": {"latitude": 91,
                        "longitude": 0, "utc_offset": 0}})",
                        "application/json"),
                 400, "request: key 'site.latitude'");
  expect_refused(c.Post("/api/sun-hours", R"({"time": "2026-06-01T12:00", "step_minutes": 0.5,
                        "site": {"latitude": 50, "longitude": 0, "utc_offset": 0}})",
                        "application/json"),
                 400, "request: key 'step_minutes'");
  expect_refused(c.Get("/api/frame"), 404, "no such page");
  expect_refused(c.Delete("/"), 404, "no such page");
  const auto frame = c.Post("/api/frame", kFrame, "application/json");
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->status, 200);
  EXPECT_EQ(server.stop(), 0);
}

TEST_F(Serve, AThousandRapidRequestsAreEachAnswered) {
  httplib::Client c = server.client();
  c.set_keep_alive(true);
  int frames = 0, refused = 0, pages = 0;
  const auto ok = [](const httplib::Result& res, int status) {
    return res && res->status == status;
  };
  for (int i = 0; i < 1000; ++i) {
    if (i % 4 == 0) {
      const std::string body =
          R"({"camera": {"width": 16, "height": 9}, "id": )" + std::to_string(i) + "}";
      const auto res = c.Post("/api/frame", body, "application/json");
      frames += ok(res, 200) && res->body.substr(1, 3) == "PNG";
    } else if (i % 4 == 1) {
      refused += ok(c.Post("/api/frame", "not json", "application/json"), 400);
    } else if (i % 4 == 2) {
      pages += ok(c.Get("/api/scene"), 200);
    } else {
      refused += ok(c.Get("/../etc/passwd"), 404);
    }
  }
  EXPECT_EQ(frames, 250);
  EXPECT_EQ(refused, 500);
  EXPECT_EQ(pages, 250);
  EXPECT_EQ(c.Post("/api/frame", kFrame, "application/json")->status, 200);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeOptions, RefusesWhatItCannotListenOn) {
  ServeProcess name({"cubes:27", "--host", "localhost"});
  EXPECT_EQ(name.wait(), 2);
  EXPECT_THAT(name.output(), HasSubstr("--host 'localhost': expected an IP address"));
  ServeProcess elsewhere({"cubes:27", "--host", "192.0.2.1", "--port", "0"});
  EXPECT_EQ(elsewhere.wait(), 2);
  EXPECT_THAT(elsewhere.output(), HasSubstr("cannot listen on 192.0.2.1"));
  ServeProcess scene({"no-such-scene.json", "--port", "0"});
  EXPECT_EQ(scene.wait(), 2);
}

// SIGTERM as soon as the URL is printed, before the server may have started listening.
TEST(ServeOptions, StopsOnSigtermAtOnce) {
  for (int i = 0; i < 10; ++i) {
    ServeProcess server({"cubes:27", "--port", "0"});
    ASSERT_TRUE(server.listening()) << server.output();
    EXPECT_EQ(server.stop(), 0);
  }
}

TEST(ServeOptions, WarnsWhenItListensBeyondLoopback) {
  ServeProcess open({"cubes:27", "--host", "0.0.0.0", "--port", "0"});
  ASSERT_TRUE(open.listening()) << open.output();
  EXPECT_THAT(open.output(), HasSubstr("--host 0.0.0.0: the viewer is open to every machine"));
  EXPECT_EQ(open.stop(), 0);
}

}  // namespace
