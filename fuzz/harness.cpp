#include "harness.h"

#include <pthread.h>
#include <stdlib.h>  // mkdtemp
#include <sys/prctl.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadowkit/app/commands.h"
#include "shadowkit/app/viewer.h"
#include "shadowkit/core/context.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_assembly.h"
#include "shadowkit/scene/scene_file.h"

// The sanitizers' hook for their fatal reports (libFuzzer sets it to save the input); weak, as
// the release fuzz build has no sanitizer runtime.
extern "C" __attribute__((weak)) void __sanitizer_set_death_callback(void (*callback)());

namespace shadowkit::fuzz {
namespace {

namespace fs = std::filesystem;

// The rendering budget of the render targets: a frame whose long side has at most this many
// pixels (the scene's aspect ratio kept), at most this many lights (the first ones), and no
// rendering at all for scenes with more faces (those are about scale, not odd geometry; the
// load targets still load them).
constexpr int kFrameLongSide = 48;
constexpr std::size_t kMaxRenderLights = 3;
constexpr std::uint32_t kMaxRenderFaces = 1000;

// The sun study the shading-groups target runs on each input: the built-in scene "table" (6
// objects of 30, 36 (x4) and 1 faces: a table, four chairs and a ground), one step at noon near
// the June solstice at 45 deg N, a heat map 16 pixels wide. Every report is written, the
// EnergyPlus schedule's year of rows included.
SunStudyOptions study_options(const fs::path& groups, const fs::path& out) {
  SunStudyOptions options;
  options.scene = "table";
  options.latitude_deg = 45;
  options.longitude_deg = 0;
  options.utc_offset_hours = 0;
  options.from = "2025-06-21T12:00";
  options.to = "2025-06-21T12:00";
  options.step_minutes = 60;
  options.heat_map_width = 16;
  options.shading_groups = groups.string();
  options.out = out.string();
  return options;
}

using Settings = std::map<std::string, std::string>;

// Settings per method that keep a tiny frame fast; a method runs once per entry. Methods not
// listed (a new one included) run once with their defaults.
const std::map<std::string, std::vector<Settings>>& method_settings() {
  static const std::map<std::string, std::vector<Settings>> settings = {
      {"shadowmap", {{{"resolution", "64"}}}},
      {"volume", {{{"count", "pass"}}, {{"count", "fail"}}}},
      {"voxel", {{{"resolution", "16"}}}},
  };
  return settings;
}

struct Run {
  std::string method;
  MethodOptions options;
  std::string label;  // "volume count=fail", for messages
};

// The fixed scene a mesh input is loaded into: a ground to receive shadows, a point and a
// directional light, and the mesh, as it is or (second file) as a Catmull-Clark control mesh.
std::string mesh_scene(const std::string& mesh_file, bool subdivision) {
  const std::string mesh =
      "{\"mesh\": \"" + mesh_file + "\"" +
      (subdivision ? ", \"subdivision\": \"catmull-clark\", \"tessellation\": 2}" : "}");
  return R"({
  "camera": {"position": [0, 3, 7], "look_at": [0, 0.5, 0], "width": 48, "height": 32},
  "lights": [
    {"type": "point", "position": [2.5, 6, 3]},
    {"type": "directional", "direction": [-0.4, -1, -0.3]}
  ],
  "objects": [{"generator": "ground", "size": 10}, )" +
         mesh + "]\n}\n";
}

// Whether a shading-groups input starts with the header line read_shading_groups() expects.
bool has_groups_header(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kHeader = "surface,object,faces";
  if (!text.starts_with(kHeader)) return false;
  const std::string_view rest = text.substr(kHeader.size());
  return rest.empty() || rest.starts_with("\n") || rest.starts_with("\r\n");
}

struct State {
  std::string kind;
  bool render = false;
  bool verbose = false;
  fs::path dir;                  // the per-process temporary directory
  fs::path input;                // where each input is written
  std::vector<fs::path> scenes;  // the scene files loaded per input, in order
  Context ctx;
  std::vector<Run> runs;
  // The shading-groups target's study, whose groups file is the input; none for other kinds.
  std::optional<SunStudyOptions> study;
  // The frame-request target's viewer, whose requests are the input; none for other kinds.
  std::unique_ptr<viewer::FrameRenderer> viewer;
  std::unique_ptr<tbb::global_control> threads;
};

State& state() {
  static State s;
  return s;
}

[[noreturn]] void harness_failure(const std::string& what) {
  std::fprintf(stderr, "shadowkit fuzz harness: %s\n", what.c_str());
  std::abort();
}

void write_file(const fs::path& path, const void* data, std::size_t size) {
  // A new file rather than a truncated one: ext4 flushes a file truncated and rewritten
  // (auto_da_alloc) and each input would wait for the disk.
  std::error_code ignored;
  fs::remove(path, ignored);
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) harness_failure("cannot write " + path.string());
  const bool ok = std::fwrite(data, 1, size, file) == size;
  if (std::fclose(file) != 0 || !ok) harness_failure("cannot write " + path.string());
}

void write_text(const fs::path& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

// A reader that parses in a child process (the formats assimp reads) expects that child to die
// as it would outside the fuzzer, which the reader then reports as an InputError. fork()
// passes libFuzzer's and the sanitizers' crash handlers on to the child, which would report
// the importer's crash as the target's own and save the input as a crash; this puts the
// defaults back. The child also dies with its parent, whom libFuzzer may stop for a timeout.
void in_forked_child() {
  for (int signal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) std::signal(signal, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
}

void remove_directory() {
  std::error_code ignored;
  fs::remove_all(state().dir, ignored);
}

fs::path make_temporary_directory() {
  std::error_code error;
  const fs::path base = fs::temp_directory_path(error);
  std::string pattern = ((error ? fs::path("/tmp") : base) / "shadowkit-fuzz-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) harness_failure("cannot create " + pattern);
  return pattern;
}

// Scene inputs resolve "models/...", "meshes/..." and "../models/..." as the files of
// examples/ and examples/sweep/ do, so the examples load whole as seeds.
void link_examples(const fs::path& scene_dir) {
  const char* env = std::getenv("SHADOWKIT_FUZZ_EXAMPLES");
  const fs::path examples =
      env != nullptr ? fs::path(env) : fs::path(SHADOWKIT_SOURCE_DIR) / "examples";
  const std::pair<fs::path, fs::path> links[] = {
      {scene_dir / "models", examples / "models"},
      {scene_dir / "meshes", examples / "sweep" / "meshes"},
      {scene_dir.parent_path() / "models", examples / "models"},
  };
  for (const auto& [link, target] : links) {
    std::error_code error;
    fs::create_directory_symlink(target, link, error);
    if (error) harness_failure("cannot link " + link.string() + ": " + error.message());
  }
}

// SHADOWKIT_FUZZ_SKIP: comma-separated runs to leave out, named as in make_runs()
// ("volume count=pass,svbsp"), to look past a known bug until it is fixed.
bool skipped(const std::string& label) {
  const char* env = std::getenv("SHADOWKIT_FUZZ_SKIP");
  if (env == nullptr) return false;
  const std::string list = std::string(",") + env + ",";
  return list.find("," + label + ",") != std::string::npos;
}

std::vector<Run> make_runs() {
  std::vector<Run> runs;
  for (const std::string& name : method_names()) {
    const auto it = method_settings().find(name);
    const std::vector<Settings> variants =
        it == method_settings().end() ? std::vector<Settings>{Settings{}} : it->second;
    for (const Settings& settings : variants) {
      std::string label = name;
      for (const auto& [key, value] : settings) label += " " + key + "=" + value;
      MethodOptions options(name, settings);
      // The harness's own settings must stay valid, or the method would silently never run.
      try {
        make_method(name, options);
      } catch (const InputError& e) {
        harness_failure("method " + label + " rejects the harness's settings: " + e.what());
      }
      if (!skipped(label)) runs.push_back({name, std::move(options), label});
    }
  }
  return runs;
}

std::optional<Scene> load(const fs::path& path) {
  State& s = state();
  try {
    return load_scene_file(path, s.ctx);
  } catch (const InputError& e) {
    if (s.verbose) std::fprintf(stderr, "input error: %s\n", e.what());
    return std::nullopt;
  }
}

// Scales the frame down to the rendering budget, keeping its aspect ratio.
void shrink_frame(Camera& camera) {
  const int long_side = std::max(camera.width, camera.height);
  if (long_side <= kFrameLongSide) return;
  const double f = double(kFrameLongSide) / long_side;
  camera.width = std::max(1, int(std::lround(camera.width * f)));
  camera.height = std::max(1, int(std::lround(camera.height * f)));
}

// ShadowMethod::shade's contract: lit or shadow at every covered pixel, background elsewhere.
void check_mask(const ShadowMask& mask, const VisibleSurfaceBuffer& surfaces,
                const std::string& what) {
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    const std::uint8_t v = mask.pixels[i];
    const bool ok =
        surfaces.covered(i) ? (v == kMaskLit || v == kMaskShadow) : v == kMaskBackground;
    if (!ok) {
      harness_failure(what + ": mask value " + std::to_string(v) + " at pixel " +
                      std::to_string(i) + (surfaces.covered(i) ? " (covered)" : " (background)"));
    }
  }
}

// One method over every light, through the ShadowMethod interface itself: prepare, then
// build and shade per light.
void run_method(const Run& run, const Scene& scene, const VisibleSurfaceBuffer& surfaces) {
  const Context& ctx = state().ctx;
  const std::unique_ptr<ShadowMethod> method = make_method(run.method, run.options);
  method->prepare(scene, ctx);
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    method->build(scene, light, ctx);
    ShadowMask mask(surfaces.width, surfaces.height, kMaskBackground);
    method->shade(scene, surfaces, mask, ctx);
    check_mask(mask, surfaces, run.label + ", light " + std::to_string(light));
    static_cast<void>(method->memory_bytes());
    static_cast<void>(method->counters());
  }
}

double now_ms() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
}

// Renders \p scene unless it is beyond the rendering budget; true if it did.
bool render(Scene& scene) {
  State& s = state();
  if (scene.face_count() > kMaxRenderFaces) return false;
  if (scene.lights.size() > kMaxRenderLights) scene.lights.resize(kMaxRenderLights);
  shrink_frame(scene.camera);
  VisibleSurfaceBuffer surfaces;
  try {
    render_visible_surfaces(scene, s.ctx, surfaces);
  } catch (const InputError& e) {
    if (s.verbose) std::fprintf(stderr, "input error (camera pass): %s\n", e.what());
    return false;
  }
  for (const Run& run : s.runs) {
    const double start = now_ms();
    try {
      run_method(run, scene, surfaces);
    } catch (const InputError& e) {
      if (s.verbose) std::fprintf(stderr, "input error (%s): %s\n", run.label.c_str(), e.what());
    }
    if (s.verbose) std::fprintf(stderr, "%s: %.1f ms\n", run.label.c_str(), now_ms() - start);
  }
  return true;
}

// The viewer's scene: a small cube field at a small size, so that a request that keeps the
// scene's camera renders quickly.
Scene viewer_scene() {
  Scene scene = load_scene("cubes:27", state().ctx);
  SceneView view = world_view(scene);
  view.camera.width = 48;
  view.camera.height = 27;
  place_view(scene, view, "fuzz");
  return scene;
}

// A request is read as the server reads it; one small enough to render in a moment (the
// fuzzer's hang limit is not a property of the parser) is rendered too.
int run_frame_request(viewer::FrameRenderer& renderer, const std::uint8_t* data, std::size_t size) {
  try {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const viewer::FrameRequest request = viewer::parse_frame_request(text, renderer.scene_view());
    const Camera& camera = request.view.camera;
    const bool quick = std::int64_t{camera.width} * camera.height <= 64 * 64 &&
                       (request.method == "raytrace" || request.method == "volume" ||
                        request.method == "svbsp" || request.method == "angular");
    if (quick) renderer.render(request);
  } catch (const InputError& e) {
    if (state().verbose) std::fprintf(stderr, "input error: %s\n", e.what());
  }
  return 0;
}

}  // namespace

void initialize(std::string_view kind, bool render) {
  State& s = state();
  s.kind = kind;
  s.render = render;
  const char* verbose = std::getenv("SHADOWKIT_FUZZ_VERBOSE");
  s.verbose = verbose != nullptr && *verbose != '\0' && *verbose != '0';
  s.ctx.warn = [](const std::string& message) {
    if (state().verbose) std::fprintf(stderr, "warning: %s\n", message.c_str());
  };
  // One worker thread: coverage and timing then depend on the input alone; parallel fuzzing
  // runs whole processes side by side (-fork=N, -jobs=N).
  const char* threads = std::getenv("SHADOWKIT_FUZZ_THREADS");
  const int n = threads != nullptr ? std::max(1, std::atoi(threads)) : 1;
  s.threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    std::size_t(n));

  pthread_atfork(nullptr, nullptr, in_forked_child);
  // No import cache (docs/formats.md): each input is new, however alike its path, size and
  // time are to the last one's, and a run must not fill the user's cache with its inputs.
  setenv("SHADOWKIT_CACHE_DIR", "", 1);

  s.dir = make_temporary_directory();
  std::atexit(remove_directory);
  if (kind == "frame_request") {
    s.viewer = std::make_unique<viewer::FrameRenderer>(viewer_scene());
    return;
  }
  if (kind == "shading_groups") {
    s.input = s.dir / "groups.csv";
    s.study = study_options(s.input, s.dir / "study");
    // Each study prints a line on stdout; libFuzzer reports on stderr.
    if (!s.verbose && std::freopen("/dev/null", "w", stdout) == nullptr) {
      harness_failure("cannot send stdout to /dev/null");
    }
    // The harness's study must run without groups, or every input would end in its error.
    SunStudyOptions without_groups = *s.study;
    without_groups.shading_groups.clear();
    try {
      run_sun_study(without_groups, s.ctx);
    } catch (const InputError& e) {
      harness_failure(std::string("the study without groups fails: ") + e.what());
    }
  } else if (kind == "scene") {
    const fs::path scene_dir = s.dir / "scene";
    fs::create_directory(scene_dir);
    link_examples(scene_dir);
    s.input = scene_dir / "scene.json";
    s.scenes = {s.input};
  } else {
    const std::string mesh_file = "input." + std::string(kind);
    s.input = s.dir / mesh_file;
    s.scenes = {s.dir / "scene.json", s.dir / "subdivision.json"};
    write_text(s.scenes[0], mesh_scene(mesh_file, false));
    write_text(s.scenes[1], mesh_scene(mesh_file, true));
  }
  if (render) s.runs = make_runs();
}

int run_one(const std::uint8_t* data, std::size_t size) {
  State& s = state();
  if (s.viewer) return run_frame_request(*s.viewer, data, size);
  write_file(s.input, data, size);
  if (s.study) {
    try {
      run_sun_study(*s.study, s.ctx);
    } catch (const InputError& e) {
      if (s.verbose) std::fprintf(stderr, "input error: %s\n", e.what());
    }
    // An input whose first line is not the header stops there; a corpus of those would leave
    // few mutations that reach the lines (libFuzzer: -1 keeps it out of the corpus).
    return has_groups_header(data, size) ? 0 : -1;
  }
  // A mesh is tried as a control mesh only when it loads as a plain mesh: a reader's error
  // would only repeat.
  bool rendered = false;
  for (const fs::path& path : s.scenes) {
    std::optional<Scene> scene = load(path);
    if (!scene) break;
    if (s.render) rendered = render(*scene) || rendered;
  }
  // A render target keeps only inputs it rendered in its corpus (libFuzzer: -1 rejects an
  // input): what no method sees is the load targets' business, and a corpus of broken scene
  // files would leave few mutations that reach the methods.
  return s.render && !rendered ? -1 : 0;
}

}  // namespace shadowkit::fuzz
