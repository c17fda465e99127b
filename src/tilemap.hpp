// Tile maps as a world stores them (the API: include/jostle/tilemap.hpp; the code:
// tilemap.cpp). WorldState holds one TileMaps.
#pragma once

#include "jostle/tilemap.hpp"

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

namespace jostle {

namespace snapshot {
struct Access;
}

/// Whether the halves of 2:1 ramps, half a tile high, are bodies createBody accepts in each
/// of a map's first `rows` rows at def.y with tiles of def.tile (tilemap_def.cpp).
bool halfTilesFit(const TileMapDef& def, std::size_t rows);

/// A map's bodies in creation order (tileMapBodies), with appending and removing in O(1)
/// whatever their number, as CreationOrder does for the world's: removing one leaves a
/// gap (the null handle), found through the ticket its piece keeps, not by a search. The
/// gaps are closed, keeping the order, when they are half the list, and when the list is
/// read (live()).
class ListedBodies {
public:
    /// Appends `body`, created last; returns its ticket, good until remove(ticket).
    std::uint32_t append(BodyId body) {
        std::uint32_t ticket;
        if (!freeTickets_.empty()) {
            ticket = freeTickets_.back();
            freeTickets_.pop_back();
        } else {
            ticket = static_cast<std::uint32_t>(positions_.size());
            positions_.emplace_back();
        }
        positions_[ticket] = static_cast<std::uint32_t>(entries_.size());
        entries_.push_back(body);
        tickets_.push_back(ticket);
        return ticket;
    }

    /// Removes the body of `ticket`.
    void remove(std::uint32_t ticket) {
        entries_[positions_[ticket]] = BodyId{};
        freeTickets_.push_back(ticket);
        ++gaps_;
        while (!entries_.empty() && entries_.back().isNull()) {
            entries_.pop_back();
            tickets_.pop_back();
            --gaps_;
        }
        if (2 * gaps_ > entries_.size())
            close();
    }

    /// The bodies, in creation order, with no gap: closes the gaps first. The caller keeps
    /// two threads from calling it at once (TileMaps::listLock).
    std::span<const BodyId> live() const {
        if (gaps_ != 0)
            close();
        return entries_;
    }

    /// The entries moved so far by closing gaps (TileMapData::work).
    std::uint64_t moved() const { return moved_; }

private:
    friend struct snapshot::Access; // saves and restores the list with its tickets
    /// Moves every body down over the gaps, in order, and notes where each went.
    void close() const {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (!entries_[i].isNull()) {
                positions_[tickets_[i]] = static_cast<std::uint32_t>(kept);
                entries_[kept] = entries_[i];
                tickets_[kept++] = tickets_[i];
            }
        moved_ += entries_.size();
        entries_.resize(kept);
        tickets_.resize(kept);
        gaps_ = 0;
    }

    // Mutable: live() closes the gaps.
    mutable std::vector<BodyId> entries_;
    /// The ticket of each entry, and the entry of each ticket.
    mutable std::vector<std::uint32_t> tickets_;
    mutable std::vector<std::uint32_t> positions_;
    std::vector<std::uint32_t> freeTickets_;
    mutable std::size_t gaps_ = 0;
    mutable std::uint64_t moved_ = 0;
};

/// A rectangle of solid tiles made into one static body.
struct TileBox {
    int column = 0; ///< its top-left tile (smallest column and row)
    int row = 0;
    int columns = 0; ///< its size, in tiles
    int rows = 0;
    BodyId body;
    std::uint32_t ticket = 0; ///< its body's ticket in TileMapData::bodies
};

/// The bodies of one ramp tile, or of a pair of 2:1 ramp tiles merged into one triangle:
/// a ramp, and for the high half of a lone 2:1 tile the box under it.
struct RampPiece {
    int column = 0; ///< its leftmost tile
    int row = 0;
    int columns = 1; ///< 1, or 2 for a merged pair
    BodyId ramp;
    BodyId under;                 ///< null unless a lone high half
    std::uint32_t rampTicket = 0; ///< their bodies' tickets in TileMapData::bodies
    std::uint32_t underTicket = 0;
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
    /// Row by row, the index in `boxes` of the box holding each solid tile; kNoBox for
    /// empty tiles.
    std::vector<std::int32_t> boxAt;
    /// Box slots; freeBoxes lists the unused ones.
    std::vector<TileBox> boxes;
    std::vector<std::int32_t> freeBoxes;
    /// Row by row, the index in `ramps` of the ramp piece holding each ramp tile; kNoBox
    /// for the other tiles.
    std::vector<std::int32_t> rampAt;
    /// Ramp piece slots; freeRamps lists the unused ones.
    std::vector<RampPiece> ramps;
    std::vector<std::int32_t> freeRamps;
    /// The bodies of the boxes and ramps, in creation order (tileMapBodies).
    ListedBodies bodies;
    /// What the map's code has done, for the tests that check what a call costs: one for
    /// each tile it scans or labels and each piece it makes or unmakes (bodies.moved()
    /// adds the list's entries moved). Never read by the library.
    mutable std::uint64_t work = 0;
    /// Whether the halves of 2:1 ramps fit its rows (jostle::halfTilesFit), worked out once,
    /// when first asked: its settings never change.
    bool halfTilesFit() const {
        if (!halfTilesFit_)
            halfTilesFit_ = jostle::halfTilesFit(settings, static_cast<std::size_t>(rows));
        return *halfTilesFit_;
    }
    mutable std::optional<bool> halfTilesFit_;

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
    /// Held by tileMapBodies, a const function several threads may call at once, while it
    /// closes the gaps of a map's list.
    mutable std::mutex listLock;

    /// Whether a live map has a ramp tile (its ramp bodies made, or destroyed by the game).
    bool hasRampTiles() const;
};

} // namespace jostle
