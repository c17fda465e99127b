// Tile maps: a map's solid tiles as few static boxes (runs of a row stacked into
// rectangles) and its ramps as triangles, made and unmade through World's API
// (tile_boxes.cpp); tilemap.cpp keeps them in step with the tiles.
#pragma once

#include "tile_chars.hpp"
#include "tilemap.hpp"
#include "world_access.hpp"

#include <cstdint>

namespace jostle {

/// Columns [begin, end) of one row.
struct Run {
    int begin;
    int end;
    int width() const { return end - begin; }
};

/// The run of `row` through `column`, a solid tile.
Run runThrough(const TileMapData& map, int column, int row);

/// True if `row` exists and `run` is one of its runs, exactly.
bool hasRun(const TileMapData& map, int row, Run run);

/// Makes and unmakes the boxes of one map, keeping its bookkeeping (boxAt, bodies, the
/// world's owners table) in step with the world's bodies.
class Boxes {
public:
    Boxes(World& world, TileMapId id)
        : world_(world), state_(WorldAccess::state(world)), map_(state_.tileMaps.maps[id.index]),
          id_(id) {}

    void add(TileBox box) {
        box.body = world_.createBody(bodyDefOf(box));
        std::int32_t slot;
        if (!map_.freeBoxes.empty()) {
            slot = map_.freeBoxes.back();
            map_.freeBoxes.pop_back();
        } else {
            slot = static_cast<std::int32_t>(map_.boxes.size());
            map_.boxes.emplace_back();
        }
        map_.boxes[static_cast<std::size_t>(slot)] = box;
        label(box, slot);
        map_.bodies.push_back(box.body);
        state_.tileMaps.owners[box.body.index] = {box.body, id_};
    }

    /// Removes the box holding the solid tile (column, row); returns what it was.
    TileBox remove(int column, int row) {
        const std::int32_t slot = map_.boxAt[map_.at(column, row)];
        const TileBox box = map_.boxes[static_cast<std::size_t>(slot)];
        label(box, TileMapData::kNoBox);
        map_.freeBoxes.push_back(slot);
        forget(box.body);
        return box;
    }

    /// The box holding (column, row) if that tile is solid and its box has exactly the
    /// columns of `run`.
    std::optional<TileBox> boxOf(int column, int row, Run run) const {
        if (row < 0 || row >= map_.rows)
            return std::nullopt;
        const std::int32_t slot = map_.boxAt[map_.at(column, row)];
        if (slot == TileMapData::kNoBox)
            return std::nullopt;
        const TileBox& box = map_.boxes[static_cast<std::size_t>(slot)];
        if (box.column != run.begin || box.columns != run.width())
            return std::nullopt;
        return box;
    }

    /// Makes the bodies of a ramp piece: its triangle, and the box under a lone high half
    /// of a 2:1 ramp (a floor's high half sits on the lower half of its tile; a
    /// ceiling's hangs from the upper half).
    void addRamp(RampPiece piece, const RampTile& kind) {
        const bool floor = kind.slope.y < 0.0f; // its slope faces up: solid below
        double top = piece.row, bottom = piece.row + 1.0;
        if (piece.columns == 1 && kind.height != 0) {
            const bool lowerHalf = (kind.height == 1) == floor;
            (lowerHalf ? top : bottom) = piece.row + 0.5;
        }
        BodyDef def = defOf(piece.column, piece.column + piece.columns, top, bottom);
        def.slope = kind.slope;
        piece.ramp = own(world_.createBody(def));
        if (piece.columns == 1 && kind.height == 2) {
            const double halfTop = floor ? piece.row + 0.5 : piece.row;
            piece.under = own(
                world_.createBody(defOf(piece.column, piece.column + 1, halfTop, halfTop + 0.5)));
        }
        map_.ramps.push_back(piece);
    }

    /// Destroys the bodies of the ramp pieces of `row`.
    void removeRamps(int row) {
        for (const RampPiece& piece : map_.ramps) {
            if (piece.row != row)
                continue;
            forget(piece.ramp);
            if (!piece.under.isNull())
                forget(piece.under);
        }
        std::erase_if(map_.ramps, [&](const RampPiece& piece) { return piece.row == row; });
    }

    /// Destroys every box's body, in creation order.
    void removeAll() {
        for (BodyId body : std::vector<BodyId>(map_.bodies))
            forget(body);
    }

private:
    BodyDef bodyDefOf(const TileBox& box) const {
        return defOf(box.column, box.column + box.columns, box.row, box.row + box.rows);
    }

    /// A static body of the map's settings over columns [fromColumn, toColumn) and rows
    /// [fromRow, toRow), in tiles (halves for 2:1 ramps).
    BodyDef defOf(double fromColumn, double toColumn, double fromRow, double toRow) const {
        // Edges in double, from the tile counts, so that boxes of different rows that
        // share an edge get the very same float for it wherever floats allow.
        const TileMapDef& s = map_.settings;
        const double tile = static_cast<double>(s.tile);
        const double left = static_cast<double>(s.x) + fromColumn * tile;
        const double right = static_cast<double>(s.x) + toColumn * tile;
        const double top = static_cast<double>(s.y) + fromRow * tile;
        const double bottom = static_cast<double>(s.y) + toRow * tile;
        return BodyDef{.type = BodyType::Static,
                       .x = static_cast<float>((left + right) / 2),
                       .y = static_cast<float>((top + bottom) / 2),
                       .hw = static_cast<float>((right - left) / 2),
                       .hh = static_cast<float>((bottom - top) / 2),
                       .bounce = s.bounce,
                       .friction = s.friction,
                       .oneWay = s.oneWay,
                       .category = s.category,
                       .mask = s.mask,
                       .sensor = s.sensor,
                       .userData = s.userData};
    }

    BodyId own(BodyId body) {
        map_.bodies.push_back(body);
        state_.tileMaps.owners[body.index] = {body, id_};
        return body;
    }

    void label(const TileBox& box, std::int32_t slot) {
        for (int row = box.row; row < box.row + box.rows; ++row)
            std::fill_n(map_.boxAt.begin() + static_cast<std::ptrdiff_t>(map_.at(box.column, row)),
                        box.columns, slot);
    }

    /// Destroys the body (unless the game already did) and drops it from the records.
    void forget(BodyId body) {
        if (world_.isValid(body))
            world_.destroyBody(body);
        map_.bodies.erase(std::find(map_.bodies.begin(), map_.bodies.end(), body));
        const auto owner = state_.tileMaps.owners.find(body.index);
        if (owner != state_.tileMaps.owners.end() && owner->second.body == body)
            state_.tileMaps.owners.erase(owner);
    }

    World& world_;
    WorldState& state_;
    TileMapData& map_;
    TileMapId id_;
};

/// The ramp pieces of `row`, made afresh: each ramp tile its own, but a 2:1 ramp's two
/// halves side by side in their order ("rR", "Ll", "cC", "Dd") one triangle.
void buildRamps(World& world, TileMapId id, int row);

/// The canonical decomposition of the whole map, top row first, left to right.
void buildAll(World& world, TileMapId id);

} // namespace jostle
