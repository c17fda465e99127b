// Tile maps: a map's solid tiles as few static boxes (runs of a row stacked into
// rectangles) and its ramps as triangles, made and unmade through World's API
// (tile_boxes.cpp); tilemap.cpp keeps them in step with the tiles.
#pragma once

#include "body_properties.hpp"
#include "tile_chars.hpp"
#include "tilemap.hpp"
#include "world_access.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

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

/// The ramp piece the tiles of `row` make through (column, row) now, as its columns, if
/// that tile is a ramp: each ramp tile its own, but a 2:1 ramp's two halves side by side
/// in their order ("rR", "Ll", "cC", "Dd") one piece. A half that pairs (r L c D) is never
/// the half it pairs with (R l C d), so a tile's piece depends on its neighbours alone.
std::optional<Run> rampRun(const TileMapData& map, int column, int row);

/// Makes and unmakes the boxes and ramps of one map, keeping its bookkeeping (boxAt,
/// rampAt, bodies, the world's owners table) in step with the world's bodies. Each call
/// costs the same whatever the map's size, but for labelling a box's tiles (its area).
class Boxes {
public:
    Boxes(World& world, TileMapId id)
        : world_(world), state_(WorldAccess::state(world)), map_(state_.tileMaps.maps[id.index]),
          id_(id) {}

    void add(TileBox box) {
        box.body = world_.createBody(bodyDefOf(box));
        box.ticket = own(box.body);
        const std::int32_t slot = pieceSlot(map_.boxes, map_.freeBoxes);
        map_.boxes[static_cast<std::size_t>(slot)] = box;
        label(map_.boxAt, box.column, box.row, box.columns, box.rows, slot);
        ++map_.work;
    }

    /// Removes the box holding the solid tile (column, row); returns what it was.
    TileBox remove(int column, int row) {
        const std::int32_t slot = map_.boxAt[map_.at(column, row)];
        const TileBox box = map_.boxes[static_cast<std::size_t>(slot)];
        label(map_.boxAt, box.column, box.row, box.columns, box.rows, TileMapData::kNoBox);
        map_.freeBoxes.push_back(slot);
        forget(box.body, box.ticket);
        ++map_.work;
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

    /// Makes the bodies of the ramp piece over `run` of `row` (rampRun): its triangle,
    /// and the box under a lone high half of a 2:1 ramp (a floor's high half sits on the
    /// lower half of its tile; a ceiling's hangs from the upper half).
    void addRamp(Run run, int row) {
        const RampTile& kind = *rampTile(map_.tiles[map_.at(run.begin, row)]);
        RampPiece piece{run.begin, row, run.width(), {}, {}};
        const bool floor = kind.slope.y < 0.0f; // its slope faces up: solid below
        double top = piece.row, bottom = piece.row + 1.0;
        if (piece.columns == 1 && kind.height != 0) {
            const bool lowerHalf = (kind.height == 1) == floor;
            (lowerHalf ? top : bottom) = piece.row + 0.5;
        }
        BodyDef def = defOf(piece.column, piece.column + piece.columns, top, bottom);
        def.slope = kind.slope;
        piece.ramp = world_.createBody(def);
        piece.rampTicket = own(piece.ramp);
        if (piece.columns == 1 && kind.height == 2) {
            const double halfTop = floor ? piece.row + 0.5 : piece.row;
            piece.under =
                world_.createBody(defOf(piece.column, piece.column + 1, halfTop, halfTop + 0.5));
            piece.underTicket = own(piece.under);
        }
        const std::int32_t slot = pieceSlot(map_.ramps, map_.freeRamps);
        map_.ramps[static_cast<std::size_t>(slot)] = piece;
        label(map_.rampAt, piece.column, piece.row, piece.columns, 1, slot);
        ++map_.work;
    }

    /// Destroys the bodies of the ramp piece holding the ramp tile (column, row), the
    /// triangle first.
    void removeRamp(int column, int row) {
        const std::int32_t slot = map_.rampAt[map_.at(column, row)];
        const RampPiece piece = map_.ramps[static_cast<std::size_t>(slot)];
        label(map_.rampAt, piece.column, piece.row, piece.columns, 1, TileMapData::kNoBox);
        map_.freeRamps.push_back(slot);
        forget(piece.ramp, piece.rampTicket);
        if (!piece.under.isNull())
            forget(piece.under, piece.underTicket);
        ++map_.work;
    }

    /// The columns of the ramp piece whose bodies hold (column, row), if one does: what
    /// the tiles made, which a change may have unmade (rampRun: what they make now).
    std::optional<Run> rampPieceAt(int column, int row) const {
        const std::int32_t slot = map_.rampAt[map_.at(column, row)];
        if (slot == TileMapData::kNoBox)
            return std::nullopt;
        const RampPiece& piece = map_.ramps[static_cast<std::size_t>(slot)];
        return Run{piece.column, piece.column + piece.columns};
    }

    /// Destroys every body of the map, in creation order.
    void removeAll() {
        const std::span<const BodyId> listed = map_.bodies.live();
        for (BodyId body : std::vector<BodyId>(listed.begin(), listed.end()))
            destroy(body);
        map_.bodies = ListedBodies{};
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
        BodyDef def{.type = BodyType::Static,
                    .x = static_cast<float>((left + right) / 2),
                    .y = static_cast<float>((top + bottom) / 2),
                    .hw = static_cast<float>((right - left) / 2),
                    .hh = static_cast<float>((bottom - top) / 2)};
        properties::shareWithBody(s, def);
        return def;
    }

    /// Lists `body` as the map's, created last; returns its ticket in the list.
    std::uint32_t own(BodyId body) {
        state_.tileMaps.owners[body.index] = {body, id_};
        return map_.bodies.append(body);
    }

    /// A free slot of `pieces` (freed lists the free ones), or a new one.
    template <class Piece>
    static std::int32_t pieceSlot(std::vector<Piece>& pieces, std::vector<std::int32_t>& freed) {
        if (freed.empty()) {
            pieces.emplace_back();
            return static_cast<std::int32_t>(pieces.size() - 1);
        }
        const std::int32_t slot = freed.back();
        freed.pop_back();
        return slot;
    }

    /// Sets `at` to `slot` over the tiles of a piece.
    void label(std::vector<std::int32_t>& at, int column, int row, int columns, int rows,
               std::int32_t slot) {
        for (int r = row; r < row + rows; ++r)
            std::fill_n(at.begin() + static_cast<std::ptrdiff_t>(map_.at(column, r)), columns,
                        slot);
        map_.work += static_cast<std::uint64_t>(columns) * static_cast<std::uint64_t>(rows);
    }

    /// Destroys the body (unless the game already did) and drops it from the records.
    void forget(BodyId body, std::uint32_t ticket) {
        destroy(body);
        map_.bodies.remove(ticket);
    }

    /// Destroys the body (unless the game already did) and drops it from the owners.
    void destroy(BodyId body) {
        if (world_.isValid(body))
            world_.destroyBody(body);
        const auto owner = state_.tileMaps.owners.find(body.index);
        if (owner != state_.tileMaps.owners.end() && owner->second.body == body)
            state_.tileMaps.owners.erase(owner);
    }

    World& world_;
    WorldState& state_;
    TileMapData& map_;
    TileMapId id_;
};

/// Makes the ramp pieces of `row` right after (column, row) was changed: the pieces
/// through its neighbours that the change unmade or made. Pieces that stay keep their
/// bodies.
void rebuildRampsAround(World& world, TileMapId id, int column, int row);

/// The canonical decomposition of the whole map, top row first, left to right: the boxes,
/// then the ramps.
void buildAll(World& world, TileMapId id);

} // namespace jostle
