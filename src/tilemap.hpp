// Tile maps as a world stores them (the API: include/jostle/tilemap.hpp; the code:
// tilemap.cpp). WorldState holds one TileMaps.
#pragma once

#include "jostle/tilemap.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace jostle {

/// A rectangle of solid tiles made into one static body.
struct TileBox {
    int column = 0; ///< its top-left tile (smallest column and row)
    int row = 0;
    int columns = 0; ///< its size, in tiles
    int rows = 0;
    BodyId body;
};

/// The bodies of one ramp tile, or of a pair of 2:1 ramp tiles merged into one triangle:
/// a ramp, and for the high half of a lone 2:1 tile the box under it.
struct RampPiece {
    int column = 0; ///< its leftmost tile
    int row = 0;
    int columns = 1; ///< 1, or 2 for a merged pair
    BodyId ramp;
    BodyId under; ///< null unless a lone high half
};

/// One tile map.
///
/// Its boxes are the canonical decomposition of its solid tiles: each row is cut into
/// runs (maximal spans of solid tiles), and runs of the same extent in consecutive rows
/// are stacked into one box, as far up and down as they go. Every run belongs to exactly
/// one box, so the decomposition depends on the tiles alone, not on the order in which
/// they were set: that is what lets setTile rebuild only around the tile it changes.
struct TileMapData {
    /// The settings of its bodies, and x, y and tile; `rows` is left empty (the tiles
    /// are in `solid`).
    TileMapDef settings;
    int columns = 0;
    int rows = 0;
    /// Row by row, 1 for a solid tile ('#': ramps are not, they have their own bodies).
    std::vector<std::uint8_t> solid;
    /// Row by row, each tile's character (tilemap.hpp: '#', '.' or a ramp).
    std::vector<char> tiles;
    /// The ramp pieces, row by row, left to right within a row.
    std::vector<RampPiece> ramps;
    /// Row by row, the index in `boxes` of the box holding each solid tile; kNoBox for
    /// empty tiles.
    std::vector<std::int32_t> boxAt;
    /// Box slots; freeBoxes lists the unused ones.
    std::vector<TileBox> boxes;
    std::vector<std::int32_t> freeBoxes;
    /// The bodies of the boxes, in creation order (tileMapBodies).
    std::vector<BodyId> bodies;

    bool alive = false;
    /// Counts the slot's reuses, as Body::generation does.
    std::uint32_t generation = 1;

    static constexpr std::int32_t kNoBox = -1;

    std::size_t at(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(column);
    }
    bool isSolid(int column, int row) const { return solid[at(column, row)] != 0; }
};

/// The body of a tile map's box, and its map.
struct TileMapOwner {
    BodyId body;
    TileMapId map;
};

/// All the tile maps of a world.
struct TileMaps {
    /// Map slots; a TileMapId's index points here.
    std::vector<TileMapData> maps;
    std::vector<std::uint32_t> freeMaps;
    /// The map of each tile map body, by body slot (tileMapOf). Only looked up, never
    /// iterated, so its hash order cannot leak into the results.
    std::unordered_map<std::uint32_t, TileMapOwner> owners;
};

} // namespace jostle
