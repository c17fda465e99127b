// A Tiled map turned into a Level (tiled_level.cpp).
#pragma once

#include "tiled_map.hpp"

namespace jostle::tiled {

/// The level of `map`; `file` names it in errors. Throws SceneError.
Level toLevel(const Map& map, const std::string& file);

} // namespace jostle::tiled
