#pragma once
/// \brief The command-line commands as library functions: the executable only parses
/// arguments. Each returns the process exit status; bad input throws InputError.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit {

/// Exit status of compare and bench when a method could not do a light: its rows say why,
/// the other rows ran.
inline constexpr int kExitRunFailed = 3;

/// \brief What every command shares.
struct CommandOptions {
  std::string scene;                              ///< file or built-in scene name
  std::map<std::string, MethodOptions> settings;  ///< per method name
  bool json = false;
};

struct RenderOptions : CommandOptions {
  std::string method;
  std::string mask_prefix;
  std::string image;  ///< empty: no shaded image
};

struct CompareOptions : CommandOptions {
  std::vector<std::string> methods;  ///< empty: all; raytrace is always the reference
  std::string report_dir;            ///< empty: no report
};

struct BenchOptions : CommandOptions {
  std::vector<std::string> methods;
  int warmup = 1;
  int repeats = 5;
};

/// \brief svbsp's object-space output (Chin & Feiner §5): the fragmented scene over all
/// lights.
struct FragmentsOptions : CommandOptions {
  std::string out;  ///< the PLY file; the areas go to the same path with extension .json
};

/// \brief voxel's own image (Lai & Cheng §5): the subpatches shaded from the cubic frame
/// buffer, optionally a second view turned around the camera's target.
struct VoxelRenderOptions : CommandOptions {
  std::string image;
  std::string turned_image;  ///< empty: no second view
  double turn_deg = 30;
};

/// \brief The sun study (the sun-study contract, sun-study.md): the sunlit fraction of every
/// input polygon at each time step, with the sun as the only light, and its sun hours.
struct SunStudyOptions : CommandOptions {
  // The site: each option given stands in place of the scene file's `site` key; the study
  // needs the first three from one or the other, north defaults to 0.
  std::optional<double> latitude_deg;      ///< `--lat`, else `site.latitude`
  std::optional<double> longitude_deg;     ///< `--lon`, else `site.longitude`
  std::optional<double> utc_offset_hours;  ///< `--utc-offset`, else `site.utc_offset`
  std::optional<double> north_deg;         ///< `--north`, else `site.north`, else 0
  std::string from, to;      ///< `--from`, `--to`: YYYY-MM-DDTHH:MM, local standard time
  double step_minutes = 0;   ///< `--step`
  std::string out;           ///< `--out`: the folder of the four files
  std::string shard;         ///< `--shard I/N`; empty: every step
  int heat_map_width = 960;  ///< `--heat-map-width`, the camera's aspect; 0: no heat map
  /// `--shading-groups FILE.csv`: EnergyPlus surfaces made of polygons; empty: none
  std::string shading_groups;
  /// `--energyplus-timesteps N`: rows per hour of the EnergyPlus schedule
  int energyplus_timesteps = 1;
};

/// \brief A command stopped by a signal (Ctrl-C) before it completed; the shell's convention
/// gives exit status 128 + the signal's number.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int signal_number)
      : std::runtime_error("interrupted"), signal(signal_number) {}
  int signal;
};

/// \brief Joins the folders of a sharded sun study into the files one unsharded run writes.
struct SunStudyMergeOptions {
  std::vector<std::string> shards;  ///< the shards' folders, in any order
  std::string out;
};

/// \brief The viewer (`shadowkit serve`): a local web page that renders the scene as its camera,
/// lights, method and view change.
struct ServeOptions {
  std::string scene;
  std::string host = "127.0.0.1";  ///< an IP address; anything but loopback is warned of
  int port = 8080;                 ///< 0: a free port, printed
};

/// Parses "method.key=value" settings into per-method options; InputError if malformed.
std::map<std::string, MethodOptions> parse_settings(const std::vector<std::string>& settings);

int run_render(const RenderOptions& options, const Context& ctx);
int run_compare(const CompareOptions& options, const Context& ctx);
int run_bench(const BenchOptions& options, const Context& ctx);
int run_info(const CommandOptions& options, const Context& ctx);
int run_fragments(const FragmentsOptions& options, const Context& ctx);
int run_voxel_render(const VoxelRenderOptions& options, const Context& ctx);
int run_sun_study(const SunStudyOptions& options, const Context& ctx);
int run_sun_study_merge(const SunStudyMergeOptions& options, const Context& ctx);
/// Serves until SIGINT or SIGTERM, then returns 0.
int run_serve(const ServeOptions& options, const Context& ctx);

}  // namespace shadowkit
