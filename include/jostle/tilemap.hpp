// jostle/tilemap.hpp: tile maps, a grid of solid and empty square tiles made into
// static bodies. docs/tilemaps.md.
//
//     jostle::TileMapDef def;
//     def.x = 0; def.y = 0;     // the top-left corner of tile (0, 0)
//     def.tile = 16;            // each tile is 16 × 16
//     def.rows = {"........",
//                 "#......#",
//                 "########"};  // '#' solid, '.' empty
//     jostle::TileMapId map = jostle::createTileMap(world, def);
//     jostle::setTile(world, map, 3, 2, false);   // dig a hole in the floor
//
// The solid tiles become a few static boxes, not one per tile: each row's runs of solid
// tiles are merged, then runs of the same extent stacked in consecutive rows. So a floor,
// a ceiling, or a wall whose rows end alike, is one box, with no seam for a box sliding
// along it to catch on. setTile rebuilds only the boxes around the tile it changes.
#pragma once

#include "jostle/body.hpp"
#include "jostle/math.hpp"
#include "jostle/visibility.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace jostle {
JOSTLE_EXPORT_BEGIN

class World;

/// A handle to a tile map of one world, checked like a BodyId: using one after its map
/// is destroyed, or in another world, throws jostle::Error. A default-constructed
/// TileMapId is the null handle.
struct TileMapId {
    std::uint32_t index = 0;
    std::uint32_t generation = 0; ///< 0 only in the null handle
    std::uint32_t world = 0;      ///< the world that made it, as in BodyId

    constexpr bool isNull() const { return generation == 0; }
    friend constexpr bool operator==(TileMapId a, TileMapId b) = default;
};

/// Everything that describes a tile map. The member names are the field names of scene
/// files (docs/scene-format.md).
///
/// Tile (column, row) covers x + column × tile to x + (column + 1) × tile, and
/// y + row × tile to y + (row + 1) × tile. In a y-down world the rows read as on
/// screen, top first; in a y-up world row 0 is the bottom one.
struct TileMapDef {
    float x = 0.0f; ///< the corner of tile (0, 0) with the smallest x and y
    float y = 0.0f;
    /// The side of a square tile, > 0.
    float tile = 0.0f;
    /// One string per row, all of the same length (the number of columns), at least one
    /// row and one column: '#' is a solid tile, '.' an empty one, and the ramps (as read
    /// on screen in a y-down world; docs/slopes-and-shapes.md has pictures):
    ///
    ///     /  \    45° floors rising to the right, to the left  (solid below the slope)
    ///     7  F    45° ceilings: solid top-right, top-left      (solid above the slope)
    ///     rR Ll   2:1 floors, two tiles each: r low and R high rising to the right,
    ///             L high and l low rising to the left
    ///     cC Dd   2:1 ceilings: thick at the right (C), thick at the left (D)
    ///
    /// Each ramp tile is its own static body (a ramp: BodyDef::slope), the two halves of a
    /// 2:1 ramp side by side one triangle. Where a ramp meets the floor or the next ramp,
    /// nothing catches: the faces the level covers do not push.
    std::vector<std::string> rows{};

    // Every box of the map is a static body with these settings (body.hpp explains
    // each). They are fixed when the map is created.
    float friction = 0.5f;
    float bounce = 0.0f;
    std::uint32_t category = 1;
    std::uint32_t mask = 0xFFFFFFFF;
    /// A one-way map: each box blocks only on this face, e.g. {0, -1} for jump-through
    /// platforms in a y-down world.
    Vec2 oneWay{};
    /// A sensor map (water, lava, a trigger zone drawn in tiles): it reports overlaps
    /// and pushes nothing.
    bool sensor = false;
    /// Given to every body of the map: World::userData tells a game which map it hit.
    void* userData = nullptr;
};

/// The first problem with `def`, or nothing if createTileMap will accept it. The rules:
/// x, y finite and tile > 0, with the whole map within float range; at least one row,
/// rows all as long as the first, at least one column, and only '#', '.' and the ramps in
/// them (the field is named like "rows[2][5]"); no ramp in a one-way map (a ramp blocks
/// from every side); every body's half extent at least 1e-9 where the map lies (math.hpp),
/// the halves of 2:1 ramps, half a tile high, included; friction and bounce in [0, 1];
/// oneWay {0, 0} or a unit vector along x or y.
std::optional<FieldError> checkTileMapDef(const TileMapDef& def);

/// Creates a tile map and the static bodies of its solid tiles, in order, top row first
/// (the smallest y), left to right, then those of its ramps in the same order, in time
/// proportional to its tiles. Throws jostle::Error if checkTileMapDef(def) finds a problem
/// ("createTileMap: TileMapDef.rows[2][5]: expected '#', '.' or a ramp, got 'x'"), and for
/// a ramp in a world of the classic model, whose bodies are sharp boxes only; then nothing
/// is created.
TileMapId createTileMap(World& world, const TileMapDef& def);

/// Destroys the map and all its bodies (as World::destroyBody does: what rests on them
/// wakes up and falls). World::isValid(map) is false from then on.
void destroyTileMap(World& world, TileMapId map);

/// Makes the tile at (column, row) solid or empty. Column and row must be inside the map,
/// else jostle::Error. Only the boxes that contain the tile or would merge with it are
/// destroyed and created again: a few bodies, whatever the map's size. Bodies resting
/// on a box that goes wake up, so a box on a tile that is removed falls. A tile made
/// solid where a dynamic body is pushes the body out, as any overlap does.
void setTile(World& world, TileMapId map, int column, int row, bool solid);
/// Sets the tile at (column, row) to any character `rows` may hold ('#', '.', a ramp);
/// jostle::Error, with nothing changed, for another, and for a ramp where createTileMap
/// would refuse it: in the classic model, in a one-way map, and a half of a 2:1 ramp in a
/// map whose tiles are too small for it (checkTileMapDef). Of the ramps, only the
/// bodies of the tile and of a 2:1 half beside it that pairs or unpairs with it are
/// destroyed and created again: a few bodies, whatever the map's size.
void setTile(World& world, TileMapId map, int column, int row, char tile);

/// The character of the tile at (column, row), as in TileMapDef::rows; '.' outside.
char tileOf(const World& world, TileMapId map, int column, int row);

/// True if the tile at (column, row) is solid ('#'; a ramp is not). Outside the map: false, as if
/// the map went on empty forever, so a game can look at the neighbours of an edge tile freely.
bool isSolid(const World& world, TileMapId map, int column, int row);

/// A tile's place in its map.
struct TileCoord {
    int column = 0;
    int row = 0;
    friend constexpr bool operator==(TileCoord a, TileCoord b) = default;
};

/// The tile that contains `point`, or nothing outside the map. A point on the edge
/// between two tiles belongs to the one with the larger column (or row).
std::optional<TileCoord> tileAt(const World& world, TileMapId map, Vec2 point);

/// The number of columns and rows.
int tileMapColumns(const World& world, TileMapId map);
int tileMapRows(const World& world, TileMapId map);

/// The map as a definition: its settings and its tiles as they are now.
TileMapDef tileMapDef(const World& world, TileMapId map);

/// The static bodies the map is made of now, in creation order. Invalidated by setTile
/// and destroyTileMap. They belong to the map: do not destroy or change them yourself
/// (a body you destroy is forgotten; one you change is replaced by a fresh one when
/// setTile rebuilds around it).
std::span<const BodyId> tileMapBodies(const World& world, TileMapId map);

/// The map that `body` is part of, or the null TileMapId if it is not part of one.
TileMapId tileMapOf(const World& world, BodyId body);

JOSTLE_EXPORT_END
} // namespace jostle
