#include "shadowkit/app/commands.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/progress.h"
#include "shadowkit/app/report.h"
#include "shadowkit/app/shading.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

const MethodOptions& settings_for(const CommandOptions& options, const std::string& method) {
  static const MethodOptions none;
  const auto it = options.settings.find(method);
  return it == options.settings.end() ? none : it->second;
}

std::vector<std::string> checked_methods(std::vector<std::string> methods) {
  if (methods.empty()) return method_names();
  const std::vector<std::string> known = method_names();
  for (const std::string& m : methods) {
    if (std::find(known.begin(), known.end(), m) == known.end()) make_method(m, {});  // throws
  }
  return methods;
}

// Every method run in a command, after the reference raytrace.
std::vector<std::string> with_reference_first(std::vector<std::string> methods) {
  methods.erase(std::remove(methods.begin(), methods.end(), "raytrace"), methods.end());
  methods.insert(methods.begin(), "raytrace");
  return methods;
}

// The scene and how long loading it took: parsing, welding, triangulating, the working frame.
struct LoadedScene {
  Scene scene;
  double load_ms = 0;
};

LoadedScene timed_load(const std::string& spec, const Context& ctx) {
  const double start = now_ms();
  Scene scene = load_scene(spec, ctx);
  return {std::move(scene), now_ms() - start};
}

nlohmann::json run_json(const MethodRun& run, double load_ms, double scan_ms) {
  if (run.failed()) return {{"method", run.method}, {"light", run.light}, {"failed", run.failure}};
  nlohmann::json j = {{"method", run.method},         {"light", run.light},
                      {"prepare_ms", run.prepare_ms}, {"build_ms", run.build_ms},
                      {"shade_ms", run.shade_ms},     {"load_ms", load_ms},
                      {"scan_ms", scan_ms},           {"memory_bytes", run.memory_bytes}};
  for (const auto& [key, value] : run.counters) j["counters"][key] = value;
  return j;
}

// The comparison keys of a compare row; null where the reference failed on the light.
void add_comparison_json(nlohmann::json& j, const std::optional<MaskComparison>& c) {
  j["mismatch_raw_pct"] = c ? nlohmann::json(c->raw_pct()) : nlohmann::json();
  j["mismatch_interior_pct"] = c ? nlohmann::json(c->interior_pct()) : nlohmann::json();
  j["surface_pixels"] = c ? nlohmann::json(c->surface_pixels) : nlohmann::json();
  j["interior_pixels"] = c ? nlohmann::json(c->interior_pixels) : nlohmann::json();
}

// One table row: times and memory, then \p comparison (compare's mismatch columns); or why
// the method could not do the light.
void print_row(const MethodRun& run, const std::string& comparison) {
  if (run.failed()) {
    std::printf("%-10s L%-3zu failed: %s\n", run.method.c_str(), run.light, run.failure.c_str());
    return;
  }
  std::printf("%-10s L%-3zu %10.2f %10.2f %10.2f %10.1f%s\n", run.method.c_str(), run.light,
              run.prepare_ms, run.build_ms, run.shade_ms, double(run.memory_bytes) / 1e6,
              comparison.c_str());
}

std::string comparison_columns(const std::optional<MaskComparison>& c) {
  if (!c) return "  no reference";
  char buf[64];
  std::snprintf(buf, sizeof buf, " %11.4f %11.4f", c->raw_pct(), c->interior_pct());
  return buf;
}

void print_header(const LoadedScene& loaded, const CameraPass& pass, bool with_mismatch) {
  const Scene& scene = loaded.scene;
  std::printf(
      "scene %s: %u polygons, %zu triangles, %zu light(s), %dx%d; loading %.2f ms, scan "
      "conversion %.2f ms\n",
      scene.name.c_str(), scene.face_count(), scene.triangles().triangles.size(),
      scene.lights.size(), pass.surfaces.width, pass.surfaces.height, loaded.load_ms, pass.scan_ms);
  std::printf("%-10s %-4s %10s %10s %10s %10s", "method", "light", "prepare_ms", "build_ms",
              "shade_ms", "memory_MB");
  if (with_mismatch) std::printf(" %11s %11s", "mismatch_%", "interior_%");
  std::printf("\n");
}

bool any_failed(const std::vector<MethodRun>& runs) {
  return std::any_of(runs.begin(), runs.end(), [](const MethodRun& r) { return r.failed(); });
}

}  // namespace

std::map<std::string, MethodOptions> parse_settings(const std::vector<std::string>& settings) {
  std::map<std::string, std::map<std::string, std::string>> values;
  for (const std::string& s : settings) {
    const std::size_t dot = s.find('.'), eq = s.find('=');
    if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 ||
        eq == dot + 1) {
      throw InputError("--set '" + s + "'", "expected METHOD.KEY=VALUE");
    }
    values[s.substr(0, dot)][s.substr(dot + 1, eq - dot - 1)] = s.substr(eq + 1);
  }
  std::map<std::string, MethodOptions> out;
  for (auto& [method, kv] : values) {
    MethodOptions options(method, std::move(kv));
    // An unknown method, key or value is an error here, also for a method the command does
    // not run, rather than silently ignored.
    make_method(method, options);
    out.emplace(method, std::move(options));
  }
  return out;
}

int run_render(const RenderOptions& options, const Context& ctx) {
  make_method(options.method, settings_for(options, options.method));  // validate first
  const Scene scene = load_scene(options.scene, ctx);
  const CameraPass pass = run_camera_pass(scene, {}, ctx);
  const std::vector<MethodRun> runs =
      run_method(scene, pass.surfaces, options.method, settings_for(options, options.method), {},
                 ctx, OnFailure::stop);
  for (const MethodRun& run : runs) {
    write_png(options.mask_prefix + ".L" + std::to_string(run.light) + ".png", run.mask);
  }
  if (!options.image.empty()) {
    write_png(options.image, shade_image(scene, pass.surfaces, masks_of(runs)));
  }
  return 0;
}

int run_compare(const CompareOptions& options, const Context& ctx) {
  const std::vector<std::string> methods = with_reference_first(checked_methods(options.methods));
  for (const std::string& m : methods) make_method(m, settings_for(options, m));
  const LoadedScene loaded = timed_load(options.scene, ctx);
  const Scene& scene = loaded.scene;
  Progress progress;
  progress.step("scan conversion");
  const CameraPass pass = run_camera_pass(scene, {}, ctx);

  const std::vector<std::uint32_t> object_ids = pass.surfaces.object_ids();
  std::vector<ComparedMethod> compared;
  for (const std::string& m : methods) {
    progress.step("method " + m);
    ComparedMethod cm{
        m,
        run_method(scene, pass.surfaces, m, settings_for(options, m), {}, ctx, OnFailure::record),
        {}};
    const ComparedMethod& reference = compared.empty() ? cm : compared.front();
    for (std::size_t l = 0; l < cm.runs.size(); ++l) {
      const MethodRun &ref = reference.runs[l], &run = cm.runs[l];
      cm.against_reference.push_back(
          ref.failed() || run.failed()
              ? std::nullopt
              : std::optional(compare_masks(ref.mask, run.mask, object_ids)));
    }
    compared.push_back(std::move(cm));
  }
  for (const MethodRun& ref : compared.front().runs) {
    if (!ref.failed()) continue;
    std::fprintf(stderr,
                 "shadowkit: raytrace, the reference, failed on light %zu: %s; no mask of that "
                 "light is compared\n",
                 ref.light, ref.failure.c_str());
  }
  if (!options.report_dir.empty()) {
    progress.step("writing report");
    write_report(options.report_dir, scene, pass, compared);
  }
  progress.step("");

  const bool wanted_reference =
      options.methods.empty() || std::find(options.methods.begin(), options.methods.end(),
                                           "raytrace") != options.methods.end();
  nlohmann::json out = nlohmann::json::array();
  if (!options.json) print_header(loaded, pass, true);
  bool failed = false;
  for (const ComparedMethod& cm : compared) {
    failed = failed || any_failed(cm.runs);
    if (cm.name == "raytrace" && !wanted_reference) continue;
    for (std::size_t l = 0; l < cm.runs.size(); ++l) {
      const MethodRun& run = cm.runs[l];
      const std::optional<MaskComparison>& c = cm.against_reference[l];
      if (!options.json) {
        print_row(run, comparison_columns(c));
        continue;
      }
      nlohmann::json j = run_json(run, loaded.load_ms, pass.scan_ms);
      if (!run.failed()) add_comparison_json(j, c);
      out.push_back(std::move(j));
    }
  }
  if (options.json) std::cout << out.dump(2) << "\n";
  if (!options.report_dir.empty() && !options.json) {
    std::printf("report: %s/index.html\n", options.report_dir.c_str());
  }
  return failed ? kExitRunFailed : 0;
}

int run_bench(const BenchOptions& options, const Context& ctx) {
  const std::vector<std::string> methods = checked_methods(options.methods);
  for (const std::string& m : methods) make_method(m, settings_for(options, m));
  // Each timed run keeps its times: a bound keeps a mistyped count from filling memory.
  constexpr int kMostRuns = 100000;
  if (options.repeats < 1 || options.repeats > kMostRuns) {
    throw InputError("--repeats", "needs 1 to 100000 timed runs");
  }
  if (options.warmup < 0 || options.warmup > kMostRuns) {
    throw InputError("--warmup", "needs 0 to 100000 untimed runs");
  }
  const LoadedScene loaded = timed_load(options.scene, ctx);
  const Scene& scene = loaded.scene;
  const Repetitions reps{options.warmup, options.repeats};
  Progress progress;
  progress.step("scan conversion");
  const CameraPass pass = run_camera_pass(scene, reps, ctx);
  nlohmann::json out = nlohmann::json::array();
  if (!options.json) print_header(loaded, pass, false);
  bool failed = false;
  for (const std::string& m : methods) {
    progress.step("method " + m);
    const std::vector<MethodRun> runs =
        run_method(scene, pass.surfaces, m, settings_for(options, m), reps, ctx, OnFailure::record);
    failed = failed || any_failed(runs);
    for (const MethodRun& run : runs) {
      if (options.json) {
        out.push_back(run_json(run, loaded.load_ms, pass.scan_ms));
      } else {
        print_row(run, "");
      }
    }
  }
  progress.step("");
  if (options.json) std::cout << out.dump(2) << "\n";
  return failed ? kExitRunFailed : 0;
}

}  // namespace shadowkit
