// Checking a tile map's definition (jostle/tilemap.hpp's checkTileMapDef).
#include "body_properties.hpp"
#include "jostle/tilemap.hpp"
#include "tile_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace jostle {

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
    // Each box's half extent, worked out as createTileMap does (edges in double, then a
    // float), must be a size createBody accepts: away from the origin the edges of a small
    // tile round towards each other. A box of one tile is the narrowest; every column and
    // every row is looked at, since the rounding differs from one to the next.
    auto narrowest = [&](float origin, std::size_t count) {
        const double tile = static_cast<double>(def.tile);
        float smallest = std::numeric_limits<float>::infinity();
        for (std::size_t i = 0; i < count; ++i) {
            const double low = static_cast<double>(origin) + static_cast<double>(i) * tile;
            const double high = static_cast<double>(origin) + static_cast<double>(i + 1) * tile;
            smallest = std::min(smallest, static_cast<float>((high - low) / 2));
        }
        return smallest;
    };
    if (narrowest(def.x, columns) < kMinMagnitude ||
        narrowest(def.y, def.rows.size()) < kMinMagnitude)
        return FieldError{"tile", "is too small for the map's position: its boxes would be "
                                  "narrower than 2e-9 (math.hpp)"};

    // The rules the map shares with bodies (friction, bounce, oneWay).
    return properties::ruleProblem(def, properties::kTileMapFields);
}

} // namespace jostle
