// Scene files: what a world in the classic model refuses of a scene (shapes, ramp tiles),
// by place; for the reader and for addBodies and addTileMaps.
#pragma once

#include "jostle/scene.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace jostle::scene_file {

/// The first body of `bodies` that a world in the model `solver` refuses, by its place
/// ("bodies[2].radius"). Each body has passed checkBodyDef, so a segment has a slope.
std::optional<FieldError> modelProblem(Solver solver, const std::vector<SceneBody>& bodies);

/// The first ramp tile of `maps` that a world in the model `solver` refuses, by its place:
/// map i is at placeOf(i) ("tilemaps[1]"), its tile at "tilemaps[1].rows[2][5]".
std::optional<FieldError> modelProblem(Solver solver, const std::vector<TileMapDef>& maps,
                                       const std::function<std::string(std::size_t)>& placeOf);

} // namespace jostle::scene_file
