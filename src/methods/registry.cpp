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
