#pragma once
/// \brief The built-in scenes, each a function from validated parameters to geometry, lights
/// and a camera. generators.cpp dispatches to them by name.
#include <vector>

#include "params.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::generators {

/// \brief A built-in scene before meshing: named polygon soups, lights and a camera.
struct SceneParts {
  std::vector<GeneratedObject> objects;
  std::vector<Light> lights;
  Camera camera;
};

/// Thakur, Cheng & Miura §9 scalability simulation: "count" cubes in a fixed volume.
SceneParts cube_field_scene(const ParamReader& params);
/// A height field of "cells" x "cells" cells, two triangles each, under a low sun.
SceneParts terrain_scene(const ParamReader& params);
/// Haines's SPD recursive tetrahedron of "level" levels over a two-triangle ground.
SceneParts tetra_scene(const ParamReader& params);
/// A closed room with the light and the camera inside it.
SceneParts room_scene(const ParamReader& params);
/// Chin & Feiner Fig. 10: a table and four chairs, a point and a directional light.
SceneParts table_scene(const ParamReader& params);
/// Chin & Feiner Figs. 5–8: a few solids under three lights.
SceneParts three_lights_scene(const ParamReader& params);
/// The analytic test: a square above a plane under a point light on its axis.
SceneParts square_scene(const ParamReader& params);
/// Thakur et al. Figs. 2b / 3: a helical band of "turns" turns whose RE loop is coiled.
SceneParts coil_scene(const ParamReader& params);
/// Thakur et al. Figs. 13 / 25: a thick square frame, an object with a hole.
SceneParts holed_scene(const ParamReader& params);
/// Thakur et al. Figs. 26 / 27: a standing U, a hole-like notch with equal adjacent peaks.
SceneParts hole_like_scene(const ParamReader& params);

/// A camera at \p position looking at \p look_at with +y up, 1920×1080.
Camera camera_looking_at(Vec3 position, Vec3 look_at, double fov_y_deg = 45);
/// A ground quad object "ground": the plane y = 0 over [-half, half]².
GeneratedObject ground_object(double half_size);

}  // namespace shadowkit::generators
