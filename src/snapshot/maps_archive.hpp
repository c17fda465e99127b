// Section M of a snapshot: the tile maps, their tiles and the pieces their bodies are
// (archive.hpp's two directions, as in world_archive.cpp). Tiles and the per-tile piece
// indices are saved as runs of equal values; which tiles are solid follows from the tiles.
#pragma once

#include "../body_properties.hpp"
#include "../tile_chars.hpp"
#include "../world_state.hpp"
#include "access.hpp"
#include "values.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace jostle::snapshot {

/// The most tiles the maps of a snapshot may have together: what a reader allocates for
/// maps is bounded by it (2^26, one map of 8,192 × 8,192).
inline constexpr std::uint64_t kMaxSnapshotTiles = std::uint64_t{1} << 26;

/// `items` as runs of equal values: the count, then (value, run length) pairs.
template <class Ar, class T, class Value>
void runs(Ar& ar, std::vector<T>& items, std::size_t expected, Value&& value) {
    if constexpr (Ar::kReading)
        items.resize(expected);
    for (std::size_t k = 0; k < items.size();) {
        std::uint32_t run = 1;
        if constexpr (!Ar::kReading)
            while (k + run < items.size() && items[k + run] == items[k])
                ++run;
        value(items[k]);
        ar.var(run);
        ar.check(run >= 1 && run <= items.size() - k, "a run of tiles is too long");
        if constexpr (Ar::kReading)
            std::fill(items.begin() + static_cast<std::ptrdiff_t>(k),
                      items.begin() + static_cast<std::ptrdiff_t>(k + run), items[k]);
        k += run;
    }
}

/// A piece index of a tile (kNoBox, or an index below `pieces`), as var(index + 1).
template <class Ar> void pieceIndex(Ar& ar, std::int32_t& index, std::size_t pieces) {
    std::uint32_t plusOne = static_cast<std::uint32_t>(index + 1);
    ar.var(plusOne);
    ar.check(plusOne <= pieces, "a tile's piece is out of range");
    index = static_cast<std::int32_t>(plusOne) - 1;
}

template <class Ar> void whole(Ar& ar, int& v, int limit) {
    std::uint32_t u = static_cast<std::uint32_t>(v);
    ar.var(u);
    ar.check(u <= static_cast<std::uint32_t>(limit), "a tile map's piece is out of the map");
    v = static_cast<int>(u);
}

/// One live map; `tilesLeft`: how many tiles the maps read after the last may still have.
template <class Ar>
void tileMap(Ar& ar, TileMapData& map, std::uint32_t serial, std::uint32_t slots,
             std::uint64_t& tilesLeft) {
    for (const properties::TileMapField& field : properties::kTileMapFields)
        std::visit([&](auto member) { value(ar, map.settings.*member); }, field.member);
    if constexpr (Ar::kReading) {
        const std::optional<FieldError> problem =
            properties::ruleProblem(map.settings, properties::kTileMapFields);
        ar.checkOr(!problem,
                   [&] { return "a tile map's " + problem->field + ": " + problem->problem; });
    }
    whole(ar, map.columns, 1 << 30);
    whole(ar, map.rows, 1 << 30);
    const std::uint64_t tiles = std::uint64_t(map.columns) * std::uint64_t(map.rows);
    ar.check(tiles >= 1 && tiles <= tilesLeft, "a tile map's size");
    tilesLeft -= tiles;
    const auto tileCount = static_cast<std::size_t>(tiles); // at most kMaxSnapshotTiles
    runs(ar, map.tiles, tileCount, [&](char& tile) {
        std::uint8_t byte = static_cast<std::uint8_t>(tile);
        ar.u8(byte);
        tile = static_cast<char>(byte);
        ar.check(isTileChar(tile), "a tile is not one of a map's characters");
    });
    if constexpr (Ar::kReading) {
        map.solid.resize(map.tiles.size());
        std::transform(map.tiles.begin(), map.tiles.end(), map.solid.begin(),
                       [](char tile) { return std::uint8_t(tile == '#' ? 1 : 0); });
    }

    sequence(ar, map.boxes, 6, [&](TileBox& box) {
        whole(ar, box.column, map.columns - 1);
        whole(ar, box.row, map.rows - 1);
        whole(ar, box.columns, map.columns - box.column);
        whole(ar, box.rows, map.rows - box.row);
        handle(ar, box.body, serial, slots);
        ar.var(box.ticket);
    });
    const auto boxes = static_cast<std::uint32_t>(map.boxes.size());
    slotList(ar, map.freeBoxes, boxes, [](std::uint32_t) {});
    runs(ar, map.boxAt, tileCount, [&](std::int32_t& index) { pieceIndex(ar, index, boxes); });

    sequence(ar, map.ramps, 7, [&](RampPiece& ramp) {
        whole(ar, ramp.column, map.columns - 1);
        whole(ar, ramp.row, map.rows - 1);
        whole(ar, ramp.columns, std::min(2, map.columns - ramp.column));
        handle(ar, ramp.ramp, serial, slots);
        handle(ar, ramp.under, serial, slots);
        ar.var(ramp.rampTicket);
        ar.var(ramp.underTicket);
    });
    const auto ramps = static_cast<std::uint32_t>(map.ramps.size());
    slotList(ar, map.freeRamps, ramps, [](std::uint32_t) {});
    runs(ar, map.rampAt, tileCount, [&](std::int32_t& index) { pieceIndex(ar, index, ramps); });
    Access::listedBodies(ar, map.bodies, serial, slots);
}

/// Rebuilds the owners table (which map a body is of) from the maps' pieces: it holds
/// each piece's body that is alive (a lookup of any other body finds none either way).
inline void ownersOf(WorldState& w) {
    TileMaps& maps = w.tileMaps;
    maps.owners.clear();
    for (std::uint32_t index = 0; index < maps.maps.size(); ++index) {
        const TileMapData& map = maps.maps[index];
        if (!map.alive)
            continue;
        const TileMapId id{index, map.generation, w.serial};
        auto own = [&](BodyId body) {
            if (w.isCurrent(body))
                maps.owners[body.index] = {body, id};
        };
        for (const TileBox& box : map.boxes)
            own(box.body);
        for (const RampPiece& ramp : map.ramps) {
            own(ramp.ramp);
            own(ramp.under);
        }
    }
}

template <class Ar> void tileMaps(Ar& ar, WorldState& w) {
    TileMaps& maps = w.tileMaps;
    const std::uint32_t slots = static_cast<std::uint32_t>(w.slots.size());
    std::uint32_t count = static_cast<std::uint32_t>(maps.maps.size());
    ar.count(count, 1);
    if constexpr (Ar::kReading)
        maps.maps.resize(count);
    std::uint64_t tilesLeft = kMaxSnapshotTiles;
    for (TileMapData& map : maps.maps) {
        std::uint64_t word = std::uint64_t{map.generation} << 1 | (map.alive ? 1 : 0);
        ar.var(word);
        if constexpr (Ar::kReading) {
            ar.check(word >> 1 != 0 && word >> 1 <= UINT32_MAX, "a tile map's generation");
            map.generation = static_cast<std::uint32_t>(word >> 1);
            map.alive = (word & 1) != 0;
        }
        if (map.alive) {
            std::lock_guard<std::mutex> lock(maps.listLock);
            tileMap(ar, map, w.serial, slots, tilesLeft);
        }
    }
    slotList(ar, maps.freeMaps, count,
             [&](std::uint32_t index) { ar.check(!maps.maps[index].alive, "the free tile maps"); });

    if constexpr (Ar::kReading)
        ownersOf(w);
}

} // namespace jostle::snapshot
