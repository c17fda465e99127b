// Tile maps: making a map's boxes (tile_boxes.hpp).
#include "tile_boxes.hpp"

namespace jostle {

Run runThrough(const TileMapData& map, int column, int row) {
    Run run{column, column + 1};
    while (run.begin > 0 && map.isSolid(run.begin - 1, row))
        --run.begin;
    while (run.end < map.columns && map.isSolid(run.end, row))
        ++run.end;
    return run;
}

bool hasRun(const TileMapData& map, int row, Run run) {
    if (row < 0 || row >= map.rows)
        return false;
    for (int column = run.begin; column < run.end; ++column)
        if (!map.isSolid(column, row))
            return false;
    return (run.begin == 0 || !map.isSolid(run.begin - 1, row)) &&
           (run.end == map.columns || !map.isSolid(run.end, row));
}

void buildRamps(World& world, TileMapId id, int row) {
    const TileMapData& map = WorldAccess::state(world).tileMaps.maps[id.index];
    Boxes boxes(world, id);
    boxes.removeRamps(row);
    for (int column = 0; column < map.columns; ++column) {
        const RampTile* kind = rampTile(map.tiles[map.at(column, row)]);
        if (!kind)
            continue;
        const bool paired = kind->partner != 0 && column + 1 < map.columns &&
                            map.tiles[map.at(column + 1, row)] == kind->partner;
        boxes.addRamp({column, row, paired ? 2 : 1, {}, {}}, *kind);
        if (paired)
            ++column;
    }
}

void buildAll(World& world, TileMapId id) {
    const TileMapData& map = WorldAccess::state(world).tileMaps.maps[id.index];
    Boxes boxes(world, id);
    for (int row = 0; row < map.rows; ++row) {
        int column = 0;
        while (column < map.columns) {
            if (!map.isSolid(column, row)) {
                ++column;
                continue;
            }
            const Run run = runThrough(map, column, row);
            // A run already labelled belongs to a stack begun in a row above.
            if (map.boxAt[map.at(column, row)] == TileMapData::kNoBox) {
                int bottom = row;
                while (hasRun(map, bottom + 1, run))
                    ++bottom;
                boxes.add({run.begin, row, run.width(), bottom - row + 1, {}});
            }
            column = run.end;
        }
    }
    for (int row = 0; row < map.rows; ++row)
        buildRamps(world, id, row);
}

} // namespace jostle
