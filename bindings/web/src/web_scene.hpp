// The scene last read for JavaScript, kept in jostle.h's definitions until the next read
// (web_c_api.cpp): what the readers of scene files and levels hand the package to create.
#pragma once

#include "jostle/jostle.h"
#include "jostle/scene.hpp"

#include <string>

namespace jostle::web {

/// Keeps `scene` in jostle.h's definitions (jostle_web_scene_tile_map and _body give them
/// in order); returns the world's. The level objects are emptied.
const jostle_world_def* keep(const Scene& scene);

/// The objects of the level last read, as JSON (jostle_web_level_objects): "[]" after a
/// scene file.
std::string& levelObjects();

} // namespace jostle::web
