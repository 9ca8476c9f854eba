#include "shadowkit/app/commands.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "progress.h"
#include "shadowkit/app/mask_compare.h"
#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/report.h"
#include "shadowkit/app/shading.h"
#include "shadowkit/core/error.h"
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

nlohmann::json run_json(const MethodRun& run, double scan_ms) {
  nlohmann::json j = {{"method", run.method},
                      {"light", run.light},
                      {"prepare_ms", run.prepare_ms},
                      {"build_ms", run.build_ms},
                      {"shade_ms", run.shade_ms},
                      {"scan_ms", scan_ms},
                      {"memory_bytes", run.memory_bytes}};
  for (const auto& [key, value] : run.counters) j["counters"][key] = value;
  return j;
}

void print_row(const MethodRun& run, const MaskComparison* c) {
  std::printf("%-10s L%-3zu %10.2f %10.2f %10.2f %10.1f", run.method.c_str(), run.light,
              run.prepare_ms, run.build_ms, run.shade_ms, double(run.memory_bytes) / 1e6);
  if (c) std::printf(" %11.4f %11.4f", c->raw_pct(), c->interior_pct());
  std::printf("\n");
}

void print_header(const Scene& scene, const CameraPass& pass, bool with_mismatch) {
  std::printf(
      "scene %s: %u polygons, %zu triangles, %zu light(s), %dx%d; scan conversion %.2f ms\n",
      scene.name.c_str(), scene.face_count(), scene.triangles().triangles.size(),
      scene.lights.size(), pass.surfaces.width, pass.surfaces.height, pass.scan_ms);
  std::printf("%-10s %-4s %10s %10s %10s %10s", "method", "light", "prepare_ms", "build_ms",
              "shade_ms", "memory_MB");
  if (with_mismatch) std::printf(" %11s %11s", "mismatch_%", "interior_%");
  std::printf("\n");
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
    make_method(method, {});  // an unknown method name is an error here, not silently ignored
    out.emplace(method, MethodOptions(method, std::move(kv)));
  }
  return out;
}

int run_render(const RenderOptions& options, const Context& ctx) {
  make_method(options.method, settings_for(options, options.method));  // validate first
  const Scene scene = load_scene(options.scene, ctx);
  const CameraPass pass = run_camera_pass(scene, {}, ctx);
  const std::vector<MethodRun> runs = run_method(scene, pass.surfaces, options.method,
                                                 settings_for(options, options.method), {}, ctx);
  std::vector<const ShadowMask*> masks;
  for (const MethodRun& run : runs) {
    write_png(options.mask_prefix + ".L" + std::to_string(run.light) + ".png", run.mask);
    masks.push_back(&run.mask);
  }
  if (!options.image.empty()) write_png(options.image, shade_image(scene, pass.surfaces, masks));
  return 0;
}

int run_compare(const CompareOptions& options, const Context& ctx) {
  const std::vector<std::string> methods = with_reference_first(checked_methods(options.methods));
  for (const std::string& m : methods) make_method(m, settings_for(options, m));
  const Scene scene = load_scene(options.scene, ctx);
  Progress progress;
  progress.step("scan conversion");
  const CameraPass pass = run_camera_pass(scene, {}, ctx);

  const std::vector<std::uint32_t> object_ids = pass.surfaces.object_ids();
  std::vector<ComparedMethod> compared;
  for (const std::string& m : methods) {
    progress.step("method " + m);
    ComparedMethod cm{
        m, run_method(scene, pass.surfaces, m, settings_for(options, m), {}, ctx), {}};
    for (std::size_t l = 0; l < cm.runs.size(); ++l) {
      const ShadowMask& ref = compared.empty() ? cm.runs[l].mask : compared.front().runs[l].mask;
      cm.against_reference.push_back(compare_masks(ref, cm.runs[l].mask, object_ids));
    }
    compared.push_back(std::move(cm));
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
  if (!options.json) print_header(scene, pass, true);
  for (const ComparedMethod& cm : compared) {
    if (cm.name == "raytrace" && !wanted_reference) continue;
    for (std::size_t l = 0; l < cm.runs.size(); ++l) {
      const MaskComparison& c = cm.against_reference[l];
      if (!options.json) {
        print_row(cm.runs[l], &c);
        continue;
      }
      nlohmann::json j = run_json(cm.runs[l], pass.scan_ms);
      j["mismatch_raw_pct"] = c.raw_pct();
      j["mismatch_interior_pct"] = c.interior_pct();
      j["surface_pixels"] = c.surface_pixels;
      j["interior_pixels"] = c.interior_pixels;
      out.push_back(std::move(j));
    }
  }
  if (options.json) std::cout << out.dump(2) << "\n";
  if (!options.report_dir.empty() && !options.json) {
    std::printf("report: %s/index.html\n", options.report_dir.c_str());
  }
  return 0;
}

int run_bench(const BenchOptions& options, const Context& ctx) {
  const std::vector<std::string> methods = checked_methods(options.methods);
  for (const std::string& m : methods) make_method(m, settings_for(options, m));
  if (options.repeats < 1) throw InputError("--repeats", "needs at least one timed run");
  if (options.warmup < 0) throw InputError("--warmup", "cannot be negative");
  const Scene scene = load_scene(options.scene, ctx);
  const Repetitions reps{options.warmup, options.repeats};
  Progress progress;
  progress.step("scan conversion");
  const CameraPass pass = run_camera_pass(scene, reps, ctx);
  nlohmann::json out = nlohmann::json::array();
  if (!options.json) print_header(scene, pass, false);
  for (const std::string& m : methods) {
    progress.step("method " + m);
    for (const MethodRun& run :
         run_method(scene, pass.surfaces, m, settings_for(options, m), reps, ctx)) {
      if (options.json) {
        out.push_back(run_json(run, pass.scan_ms));
      } else {
        print_row(run, nullptr);
      }
    }
  }
  progress.step("");
  if (options.json) std::cout << out.dump(2) << "\n";
  return 0;
}

}  // namespace shadowkit
