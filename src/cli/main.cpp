// The shadowkit command line: parses arguments and calls the library's commands.
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/generators.h"

namespace {

using namespace shadowkit;

constexpr int kBadInput = 2;

struct Shared {
  int threads = 0;
  std::vector<std::string> settings;
};

// Returns the --set option, so that a command that refuses settings can hide it.
CLI::Option* add_shared(CLI::App* cmd, CommandOptions& options, Shared& shared) {
  std::string scenes;
  for (const std::string& s : builtin_scene_names()) scenes += (scenes.empty() ? "" : ", ") + s;
  cmd->add_option("SCENE", options.scene, "scene file, mesh file or built-in scene: " + scenes)
      ->required();
  cmd->add_option("--threads", shared.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  return cmd->add_option("--set", shared.settings,
                         "method setting METHOD.KEY=VALUE, e.g. shadowmap.resolution=4096");
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size() && !s.empty()) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "shadowkit: classic hard-shadow algorithms side by side, against an exact "
      "Embree reference"};
  app.require_subcommand(1);
  Shared shared;

  RenderOptions render;
  auto* render_cmd = app.add_subcommand("render", "render one method's masks and image");
  add_shared(render_cmd, render, shared);
  render_cmd->add_option("--method", render.method, "method name")->required();
  render_cmd->add_option("--mask", render.mask_prefix, "writes PREFIX.L0.png, PREFIX.L1.png, ...")
      ->required();
  render_cmd->add_option("--image", render.image, "shaded image (PNG)");

  CompareOptions compare;
  std::string compare_methods;
  auto* compare_cmd = app.add_subcommand("compare", "run methods and compare them with raytrace");
  add_shared(compare_cmd, compare, shared);
  compare_cmd->add_option("--methods", compare_methods, "comma-separated (default: all)");
  compare_cmd->add_option("--report", compare.report_dir, "write an HTML report into DIR");
  compare_cmd->add_flag("--json", compare.json, "print one JSON array");

  BenchOptions bench;
  std::string bench_methods;
  auto* bench_cmd = app.add_subcommand("bench", "time methods (median of several runs)");
  add_shared(bench_cmd, bench, shared);
  bench_cmd->add_option("--methods", bench_methods, "comma-separated (default: all)");
  bench_cmd->add_option("--repeats", bench.repeats, "timed runs per stage (default 5)");
  bench_cmd->add_option("--warmup", bench.warmup, "untimed runs first (default 1)");
  bench_cmd->add_flag("--json", bench.json, "print one JSON array");

  CommandOptions info;
  auto* info_cmd = app.add_subcommand("info", "print the scene's statistics");
  add_shared(info_cmd, info, shared);
  info_cmd->add_flag("--json", info.json, "print JSON");

  FragmentsOptions fragments;
  auto* fragments_cmd = app.add_subcommand(
      "fragments", "svbsp: write the scene split into lit and shadowed fragments (PLY + JSON)");
  add_shared(fragments_cmd, fragments, shared);
  fragments_cmd->add_option("--out", fragments.out, "PLY file; areas per polygon go to F.json")
      ->required();

  VoxelRenderOptions voxel_render;
  auto* voxel_render_cmd = app.add_subcommand(
      "voxel-render",
      "voxel: the subpatches shaded from the cubic frame buffer, or on the fly with "
      "voxel.framebuffer=0 (Lai & Cheng §5)");
  add_shared(voxel_render_cmd, voxel_render, shared);
  voxel_render_cmd->add_option("--image", voxel_render.image, "PNG file")->required();
  auto* turned_image =
      voxel_render_cmd->add_option("--turned-image", voxel_render.turned_image,
                                   "PNG file of a second view, with no new shadow work");
  // Without the second view the turn would be silently ignored.
  voxel_render_cmd
      ->add_option("--turn", voxel_render.turn_deg,
                   "degrees the second view turns around the camera's target")
      ->needs(turned_image);

  SunStudyOptions sun_study;
  auto* sun_study_cmd = app.add_subcommand(
      "sun-study",
      "the sunlit fraction of every polygon at each time step, and its sun hours "
      "(the sun-study contract)");
  // sun-study refuses --set (run_sun_study says why), so its help does not list it.
  add_shared(sun_study_cmd, sun_study, shared)->group("");
  // The site's options stand in place of the scene file's site keys, so each is required
  // only when the scene has no site (run_sun_study says which is missing).
  sun_study_cmd->add_option("--lat", sun_study.latitude_deg,
                            "latitude, degrees north (default: the scene's site.latitude)");
  sun_study_cmd->add_option("--lon", sun_study.longitude_deg,
                            "longitude, degrees east (default: the scene's site.longitude)");
  sun_study_cmd->add_option("--utc-offset", sun_study.utc_offset_hours,
                            "hours: local standard time is UTC + this (no daylight saving; "
                            "default: the scene's site.utc_offset)");
  sun_study_cmd->add_option("--from", sun_study.from, "first step, YYYY-MM-DDTHH:MM local time")
      ->required();
  sun_study_cmd->add_option("--to", sun_study.to, "last step at most, YYYY-MM-DDTHH:MM local time")
      ->required();
  sun_study_cmd->add_option("--step", sun_study.step_minutes, "minutes between steps")->required();
  sun_study_cmd->add_option("--out", sun_study.out, "folder of the output files")->required();
  sun_study_cmd->add_option("--north", sun_study.north_deg,
                            "degrees north turns clockwise from -Z, seen from above (default: "
                            "the scene's site.north, else 0)");
  sun_study_cmd->add_option("--shard", sun_study.shard,
                            "I/N: only the I-th of N contiguous blocks of steps");
  sun_study_cmd->add_option("--heat-map-width", sun_study.heat_map_width,
                            "pixels across the heat map from the scene's camera (default 960; "
                            "0: none)");
  sun_study_cmd->add_option("--shading-groups", sun_study.shading_groups,
                            "CSV surface,object,faces: EnergyPlus surfaces made of polygons");
  sun_study_cmd->add_option(
      "--energyplus-timesteps", sun_study.energyplus_timesteps,
      "rows per hour of the EnergyPlus schedule: the IDF's Timestep (default 1)");

  SunStudyMergeOptions sun_study_merge;
  auto* sun_study_merge_cmd = app.add_subcommand(
      "sun-study-merge", "join the folders of a sharded sun study into one study's files");
  sun_study_merge_cmd->add_option("DIR", sun_study_merge.shards, "the shards' folders")->required();
  sun_study_merge_cmd->add_option("--out", sun_study_merge.out, "folder of the merged files")
      ->required();

  ServeOptions serve;
  auto* serve_cmd = app.add_subcommand(
      "serve", "the viewer: move lights and camera in a browser and watch each method follow");
  serve_cmd->add_option("SCENE", serve.scene, "scene file, mesh file or built-in scene")
      ->required();
  serve_cmd->add_option("--host", serve.host, "IP address to listen on (default 127.0.0.1)");
  serve_cmd->add_option("--port", serve.port, "HTTP port (default 8080; 0: any free port)")
      ->check(CLI::Range(0, 65535));
  serve_cmd->add_option("--threads", shared.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "shadowkit: error: %s (run with --help for usage)\n", e.what());
    return kBadInput;
  }

  std::optional<tbb::global_control> threads;
  if (shared.threads > 0) {
    threads.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(shared.threads));
  }
  const Context ctx;
  try {
    const auto settings = parse_settings(shared.settings);
    if (*render_cmd) {
      render.settings = settings;
      return run_render(render, ctx);
    }
    if (*compare_cmd) {
      compare.settings = settings;
      compare.methods = split_list(compare_methods);
      return run_compare(compare, ctx);
    }
    if (*bench_cmd) {
      bench.settings = settings;
      bench.methods = split_list(bench_methods);
      return run_bench(bench, ctx);
    }
    if (*fragments_cmd) {
      fragments.settings = settings;
      return run_fragments(fragments, ctx);
    }
    if (*voxel_render_cmd) {
      voxel_render.settings = settings;
      return run_voxel_render(voxel_render, ctx);
    }
    if (*sun_study_cmd) {
      sun_study.settings = settings;
      return run_sun_study(sun_study, ctx);
    }
    if (*sun_study_merge_cmd) return run_sun_study_merge(sun_study_merge, ctx);
    if (*serve_cmd) return run_serve(serve, ctx);
    info.settings = settings;
    return run_info(info, ctx);
  } catch (const InputError& e) {
    std::fprintf(stderr, "shadowkit: error: %s\n", e.what());
    return kBadInput;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "shadowkit: interrupted; no file was left half-written\n");
    return 128 + e.signal;
  } catch (const std::bad_alloc&) {
    // Only a setting can ask for this much (image size, map resolution): say so.
    std::fprintf(stderr,
                 "shadowkit: error: out of memory; lower the image size or a method's "
                 "resolution setting\n");
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowkit: internal error: %s\n", e.what());
    return 1;
  }
}
