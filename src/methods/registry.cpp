#include "angular/angular_method.h"
#include "raytrace/raytrace_method.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowmap/shadow_map_method.h"
#include "svbsp/svbsp_method.h"
#include "volume/volume_method.h"
#include "voxel/voxel_method.h"

namespace shadowkit {

std::vector<std::string> method_names() {
  return {"raytrace", "shadowmap", "volume", "svbsp", "angular", "voxel"};
}

std::unique_ptr<ShadowMethod> make_method(std::string_view name, const MethodOptions& options) {
  if (name == "raytrace") return std::make_unique<RaytraceMethod>(options);
  if (name == "shadowmap") return std::make_unique<ShadowMapMethod>(options);
  if (name == "volume") return std::make_unique<VolumeMethod>(options);
  if (name == "svbsp") return std::make_unique<SvbspMethod>(options);
  if (name == "angular") return std::make_unique<AngularMethod>(options);
  if (name == "voxel") return std::make_unique<VoxelMethod>(options);
  std::string list;
  for (const auto& m : method_names()) list += (list.empty() ? "" : ", ") + m;
  throw InputError("method '" + std::string(name) + "'",
                   "unknown method (available: " + list + ")");
}

}  // namespace shadowkit
