#pragma once
// The study's site: each site option given on the command line in place of the same key of
// the scene file's `site` (docs/scene-format.md, "Site").
#include <optional>

#include "shadowkit/app/commands.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun_study {

/// Throws InputError naming the first of --lat, --lon, --utc-offset and --north that is given
/// and out of range (sun::validate); the scene file checks its own.
void check_site_options(const SunStudyOptions& options);

/// Each field of the study's site from its option when given, else from \p scene_site, else
/// (north only) 0. InputError names the first option that neither gives ("--lat: not given
/// and the scene has no site.latitude").
sun::Site study_site(const SunStudyOptions& options, const std::optional<sun::Site>& scene_site);

}  // namespace shadowkit::sun_study
