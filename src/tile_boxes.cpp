// Tile maps: making a map's boxes (tile_boxes.hpp).
#include "tile_boxes.hpp"

#include <algorithm>

namespace jostle {

Run runThrough(const TileMapData& map, int column, int row) {
    Run run{column, column + 1};
    while (run.begin > 0 && map.isSolid(run.begin - 1, row))
        --run.begin;
    while (run.end < map.columns && map.isSolid(run.end, row))
        ++run.end;
    map.work += static_cast<std::uint64_t>(run.width());
    return run;
}

bool hasRun(const TileMapData& map, int row, Run run) {
    if (row < 0 || row >= map.rows)
        return false;
    map.work += static_cast<std::uint64_t>(run.width());
    for (int column = run.begin; column < run.end; ++column)
        if (!map.isSolid(column, row))
            return false;
    return (run.begin == 0 || !map.isSolid(run.begin - 1, row)) &&
           (run.end == map.columns || !map.isSolid(run.end, row));
}

std::optional<Run> rampRun(const TileMapData& map, int column, int row) {
    const RampTile* kind = rampTile(map.tiles[map.at(column, row)]);
    if (!kind)
        return std::nullopt;
    if (kind->partner != 0 && column + 1 < map.columns &&
        map.tiles[map.at(column + 1, row)] == kind->partner)
        return Run{column, column + 2};
    if (column > 0)
        if (const RampTile* left = rampTile(map.tiles[map.at(column - 1, row)]);
            left && left->partner == kind->tile)
            return Run{column - 1, column + 1};
    return Run{column, column + 1};
}

void rebuildRampsAround(World& world, TileMapId id, int column, int row) {
    const TileMapData& map = WorldAccess::state(world).tileMaps.maps[id.index];
    Boxes boxes(world, id);
    // A piece holds two tiles at most, and pairs only with its neighbour: the pieces the
    // change can touch hold column - 1, column or column + 1, before and after.
    const int from = std::max(column - 1, 0);
    const int to = std::min(column + 1, map.columns - 1);
    Run before[3];
    Run after[3];
    int beforeCount = 0;
    int afterCount = 0;
    for (int c = from; c <= to; ++c) {
        const std::optional<Run> was = boxes.rampPieceAt(c, row);
        if (was && (beforeCount == 0 || before[beforeCount - 1].begin != was->begin))
            before[beforeCount++] = *was;
        const std::optional<Run> is = rampRun(map, c, row);
        if (is && (afterCount == 0 || after[afterCount - 1].begin != is->begin))
            after[afterCount++] = *is;
    }
    // A piece through `column` changed with its tile; one beside it stays if the tiles
    // still make it, with the same columns.
    const auto stays = [&](Run piece, const Run* others, int count) {
        if (piece.begin <= column && column < piece.end)
            return false;
        for (int i = 0; i < count; ++i)
            if (others[i].begin == piece.begin && others[i].end == piece.end)
                return true;
        return false;
    };
    for (int i = 0; i < beforeCount; ++i)
        if (!stays(before[i], after, afterCount))
            boxes.removeRamp(before[i].begin, row);
    for (int i = 0; i < afterCount; ++i)
        if (!stays(after[i], before, beforeCount))
            boxes.addRamp(after[i], row);
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
        map.work += static_cast<std::uint64_t>(map.columns);
    }
    for (int row = 0; row < map.rows; ++row) {
        int column = 0;
        while (column < map.columns) {
            const std::optional<Run> piece = rampRun(map, column, row);
            if (!piece) {
                ++column;
                continue;
            }
            boxes.addRamp(*piece, row);
            column = piece->end;
        }
        map.work += static_cast<std::uint64_t>(map.columns);
    }
}

} // namespace jostle
