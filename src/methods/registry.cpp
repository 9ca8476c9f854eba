#include "shadowkit/methods/registry.h"

#include "shadowkit/core/error.h"
#include "shadowkit/methods/angular.h"
#include "shadowkit/methods/raytrace.h"
#include "shadowkit/methods/shadowmap.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/methods/volume.h"
#include "shadowkit/methods/voxel.h"

namespace shadowkit {

std::vector<std::string> method_names() {
  return {"raytrace", "shadowmap", "volume", "svbsp", "angular", "voxel"};
}

std::vector<SettingInfo> method_settings(std::string_view method) {
  const std::vector<std::string> flag = {"0", "1"};
  if (method == "shadowmap") {
    return {{"resolution", "2048", {}, "16..16384"},
            {"bias", "", {}, ">= 0, world units (automatic: 1e-3 x scene diagonal)"},
            {"slope_bias", "1", {}, ">= 0"},
            {"pcf", "1", {}, "odd kernel width"},
            {"tiles", "looked_up", {"looked_up", "all"}, ""}};
  }
  if (method == "volume") return {{"count", "auto", {"auto", "pass", "fail"}, ""}};
  if (method == "angular") {
    return {{"resolution", "0", {}, "0 (automatic), eq4, or entries up to 1e6"},
            {"saturated", "1", flag, ""},
            {"exact", "1", flag, ""},
            {"light_inside", "turn", {"turn", "hemispheres"}, ""},
            {"pairing", "walk", {"walk", "paper"}, ""},
            {"fallback", "1", flag, ""}};
  }
  if (method == "svbsp") {  // "": 1, or 0 with paper=1
    return {{"paper", "0", flag, ""},         {"contour_planes", "0", flag, ""},
            {"far_side", "", flag, ""},       {"skip_edges_in_tree", "", flag, ""},
            {"shadowed_only", "0", flag, ""}, {"merge_siblings", "", flag, ""},
            {"whole_pieces", "", flag, ""},   {"balance", "", flag, ""},
            {"footprints", "", flag, ""}};
  }
  if (method == "voxel") {
    return {{"resolution", "256", {}, "a power of two, 16..2048"},
            {"adjacency", "26", {"6", "18", "26"}, ""},
            {"test", "topology", {"topology", "offset"}, ""},
            {"bound", "view", {"view", "scene"}, ""},
            {"max_subpatches", "33554432", {}, "1..2^28"},
            {"framebuffer", "1", flag, ""},
            {"paper", "0", flag, ""}};
  }
  return {};
}

std::unique_ptr<ShadowMethod> make_method(std::string_view name, const MethodOptions& options) {
  if (name == "raytrace") return raytrace::make_method(options);
  if (name == "shadowmap") return shadowmap::make_method(options);
  if (name == "volume") return volume::make_method(options);
  if (name == "svbsp") return svbsp::make_method(options);
  if (name == "angular") return angular::make_method(options);
  if (name == "voxel") return voxel::make_method(options);
  std::string list;
  for (const auto& m : method_names()) list += (list.empty() ? "" : ", ") + m;
  throw InputError("method '" + std::string(name) + "'",
                   "unknown method (available: " + list + ")");
}

}  // namespace shadowkit
