// Checking a tile map's definition (jostle/tilemap.hpp's checkTileMapDef).
#include "body_properties.hpp"
#include "jostle/tilemap.hpp"
#include "tile_rows.hpp"
#include "tilemap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace jostle {

namespace {

/// The narrowest half extent createTileMap gives a body of `parts` parts of a tile along an
/// axis from `origin` (edges in double, then a float, as it works them out): away from the
/// origin the edges of a small tile round towards each other, differently for each one.
float narrowest(float origin, float tile, std::size_t count, int parts) {
    const double step = static_cast<double>(tile) / parts;
    float smallest = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < count * static_cast<std::size_t>(parts); ++i) {
        const double low = static_cast<double>(origin) + static_cast<double>(i) * step;
        const double high = static_cast<double>(origin) + static_cast<double>(i + 1) * step;
        smallest = std::min(smallest, static_cast<float>((high - low) / 2));
    }
    return smallest;
}

} // namespace

bool halfTilesFit(const TileMapDef& def, std::size_t rows) {
    return narrowest(def.y, def.tile, rows, 2) >= kMinMagnitude;
}

std::optional<FieldError> checkTileMapDef(const TileMapDef& def) {
    if (auto problem = properties::formProblem(def, properties::kTileMapFields))
        return problem;
    if (!(def.tile > 0.0f))
        return FieldError{"tile", "must be > 0"};
    // Half a tile is the smallest half extent a box gets: a body's smallest size.
    if (def.tile / 2.0f < kMinMagnitude)
        return FieldError{"tile", "must be >= 2e-9"};

    if (auto problem = rowsProblem(def.rows, Notation::Cpp))
        return problem;
    const std::size_t columns = def.rows[0].size();

    // The far corner must be in the range jostle works in (math.hpp), like every body.
    const double width = static_cast<double>(columns) * static_cast<double>(def.tile);
    const double height = static_cast<double>(def.rows.size()) * static_cast<double>(def.tile);
    constexpr double kLargest = static_cast<double>(kMaxMagnitude);
    if (!(std::fabs(static_cast<double>(def.x) + width) <= kLargest &&
          std::fabs(static_cast<double>(def.y) + height) <= kLargest))
        return FieldError{"tile", "puts the map's far corner beyond 1e9 (math.hpp)"};
    // Each body's half extent must be a size createBody accepts: a box of one tile is the
    // narrowest, a half of a 2:1 ramp half a tile high.
    if (narrowest(def.x, def.tile, columns, 1) < kMinMagnitude ||
        narrowest(def.y, def.tile, def.rows.size(), 1) < kMinMagnitude)
        return FieldError{"tile", "is too small for the map's position: its boxes would be "
                                  "narrower than 2e-9 (math.hpp)"};
    if (hasHalfTiles(def.rows) && !halfTilesFit(def, def.rows.size()))
        return FieldError{"tile", kHalfTilesTooSmall};

    // The rules the map shares with bodies (friction, bounce, oneWay), then ramps.
    if (auto problem = properties::ruleProblem(def, properties::kTileMapFields))
        return problem;
    return oneWayRampProblem(def.rows, def.oneWay, Notation::Cpp);
}

} // namespace jostle
