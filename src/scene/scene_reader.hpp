// Scene files: the reader that turns the JSON parser's events into a checked Scene
// (docs/scene-format.md), keeping only what the scene keeps.
#pragma once

#include "jostle/scene.hpp"
#include "json.hpp"

namespace jostle::scene_file {

/// The scene `input` holds; a SceneError naming the place of the first problem.
Scene readScene(json::Input& input);

} // namespace jostle::scene_file
