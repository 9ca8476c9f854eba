#pragma once
// Named groups of the study's polygons (--shading-groups FILE.csv): each an EnergyPlus
// surface, whose sunlit fraction is the area-weighted fraction of its polygons.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "study_polygons.h"

namespace shadowkit::sun_study {

/// \brief The groups of a shading-groups file, in the order their names first appear.
struct ShadingGroups {
  struct Group {
    std::string surface;                  ///< the EnergyPlus surface's name, as written
    std::vector<std::uint32_t> polygons;  ///< rows of polygons.csv
  };
  std::vector<Group> groups;
};

/// Reads \p file: a header `surface,object,faces`, then one line per run of polygons: the
/// surface's name, the polygon's `object` as in polygons.csv and its `faces`: `F`, `F-G`
/// (inclusive) or `all`. Lines of one name (in any case) join one group. InputError naming
/// the file and line when a line is malformed or names a polygon \p polygons does not hold.
ShadingGroups read_shading_groups(const std::filesystem::path& file, const Polygons& polygons);

}  // namespace shadowkit::sun_study
