// Tile maps: solid tiles merged into few static boxes, and rebuilt around a tile when it
// changes (docs/tilemaps.md). The boxes are made and unmade through World's API, so a
// tile map's bodies are ordinary static bodies to everything else in the library.
#include "tilemap.hpp"

#include "tile_boxes.hpp"

#include "body_properties.hpp"
#include "tile_rows.hpp"
#include "world_access.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

namespace jostle {

namespace {

std::string describe(int column, int row) {
    return "column " + std::to_string(column) + ", row " + std::to_string(row);
}

TileMapData& lookUp(WorldState& world, TileMapId id, const char* function) {
    std::vector<TileMapData>& maps = world.tileMaps.maps;
    if (std::optional<std::string> problem =
            handleProblem(maps, world.serial, id, "TileMapId", "map"))
        fail(function, *problem);
    return maps[id.index];
}

const TileMapData& lookUp(const WorldState& world, TileMapId id, const char* function) {
    return lookUp(const_cast<WorldState&>(world), id, function);
}

} // namespace

bool TileMaps::hasRampTiles() const {
    return std::any_of(maps.begin(), maps.end(), [](const TileMapData& map) {
        return map.alive && std::any_of(map.tiles.begin(), map.tiles.end(),
                                        [](char tile) { return rampTile(tile) != nullptr; });
    });
}

// --- Maps --------------------------------------------------------------------------------

TileMapId createTileMap(World& world, const TileMapDef& def) {
    requireChangeable(WorldAccess::state(world), "createTileMap");
    if (auto problem = checkTileMapDef(def))
        fail("createTileMap", "TileMapDef." + problem->field + ": " + problem->problem);
    // Refused before anything is made: the map's boxes would be made before its ramps.
    if (world.solver() == Solver::Classic)
        if (auto ramp = rampProblem(def.rows, Notation::Cpp))
            fail("createTileMap", "TileMapDef." + ramp->field + ": " + ramp->problem);

    TileMaps& maps = WorldAccess::state(world).tileMaps;
    const std::optional<std::uint32_t> taken = takeSlot(maps.maps, maps.freeMaps);
    if (!taken)
        fail("createTileMap", "too many tile maps");
    const std::uint32_t index = *taken;
    TileMapData& map = maps.maps[index];
    const std::uint32_t generation = map.generation;
    map = TileMapData{};
    map.generation = generation;
    map.alive = true;
    map.settings = def;
    map.settings.rows.clear();
    map.columns = static_cast<int>(def.rows[0].size());
    map.rows = static_cast<int>(def.rows.size());
    map.solid.reserve(static_cast<std::size_t>(map.columns) * def.rows.size());
    for (const std::string& row : def.rows)
        for (char tile : row) {
            map.solid.push_back(tile == '#' ? 1 : 0);
            map.tiles.push_back(tile);
        }
    map.boxAt.assign(map.solid.size(), TileMapData::kNoBox);
    map.rampAt.assign(map.solid.size(), TileMapData::kNoBox);

    const TileMapId id{index, generation, WorldAccess::state(world).serial};
    buildAll(world, id);
    return id;
}

void destroyTileMap(World& world, TileMapId id) {
    requireChangeable(WorldAccess::state(world), "destroyTileMap");
    TileMapData& map = lookUp(WorldAccess::state(world), id, "destroyTileMap");
    Boxes(world, id).removeAll();
    const std::uint32_t generation = map.generation;
    map = TileMapData{};
    map.generation = generation;
    if (moveGenerationOn(map))
        WorldAccess::state(world).tileMaps.freeMaps.push_back(id.index);
}

bool World::isValid(TileMapId id) const {
    const WorldState& state = WorldAccess::state(*this);
    return isCurrent(state.tileMaps.maps, state.serial, id);
}

TileMapId World::adopt(TileMapId id) const {
    const WorldState& state = WorldAccess::state(*this);
    const TileMapId here{id.index, id.generation, state.serial};
    return isCurrent(state.tileMaps.maps, state.serial, here) ? here : TileMapId{};
}

// --- Tiles -------------------------------------------------------------------------------

namespace {

/// Makes (column, row) solid or not in the box decomposition, rebuilding the boxes
/// around it.
void setSolid(World& world, TileMapId id, int column, int row, bool solid) {
    TileMapData& map = WorldAccess::state(world).tileMaps.maps[id.index];

    // Only `row`'s runs change, and only around `column`: the runs that go and the runs
    // that come. Every other run keeps its box, unless a new run joins it.
    Run gone[2];
    Run come[2];
    int goneCount = 0;
    int comeCount = 0;
    if (solid) {
        if (column > 0 && map.isSolid(column - 1, row))
            gone[goneCount++] = runThrough(map, column - 1, row);
        if (column + 1 < map.columns && map.isSolid(column + 1, row))
            gone[goneCount++] = runThrough(map, column + 1, row);
        map.solid[map.at(column, row)] = 1;
        come[comeCount++] = runThrough(map, column, row);
    } else {
        const Run run = runThrough(map, column, row);
        gone[goneCount++] = run;
        map.solid[map.at(column, row)] = 0;
        if (run.begin < column)
            come[comeCount++] = {run.begin, column};
        if (column + 1 < run.end)
            come[comeCount++] = {column + 1, run.end};
    }

    Boxes boxes(world, id);
    // A box holding a run that goes is cut at `row`: its parts above and below stay.
    // They keep their extent, which no run that comes has, so they join nothing.
    for (int i = 0; i < goneCount; ++i) {
        const TileBox box = boxes.remove(gone[i].begin, row);
        const int last = box.row + box.rows - 1;
        if (box.row < row)
            boxes.add({box.column, box.row, box.columns, row - box.row, {}});
        if (last > row)
            boxes.add({box.column, row + 1, box.columns, last - row, {}});
    }
    // A run that comes joins the stacks of the same extent just above and just below.
    for (int i = 0; i < comeCount; ++i) {
        const Run run = come[i];
        int top = row;
        int bottom = row;
        if (std::optional<TileBox> above = boxes.boxOf(run.begin, row - 1, run)) {
            top = above->row;
            boxes.remove(run.begin, row - 1);
        }
        if (std::optional<TileBox> below = boxes.boxOf(run.begin, row + 1, run)) {
            bottom = below->row + below->rows - 1;
            boxes.remove(run.begin, row + 1);
        }
        boxes.add({run.begin, top, run.width(), bottom - top + 1, {}});
    }
}

} // namespace

void setTile(World& world, TileMapId id, int column, int row, bool solid) {
    setTile(world, id, column, row, solid ? '#' : '.');
}

void setTile(World& world, TileMapId id, int column, int row, char tile) {
    requireChangeable(WorldAccess::state(world), "setTile");
    TileMapData& map = lookUp(WorldAccess::state(world), id, "setTile");
    if (column < 0 || column >= map.columns || row < 0 || row >= map.rows)
        fail("setTile", describe(column, row) + " is outside the map (" +
                            std::to_string(map.columns) + " columns, " + std::to_string(map.rows) +
                            " rows)");
    if (!isTileChar(tile))
        fail("setTile", "expected '#', '.' or a ramp, got " + describeChar(tile));
    // A tile createTileMap would refuse in its place is refused before anything changes.
    if (const RampTile* ramp = rampTile(tile)) {
        if (map.settings.oneWay != Vec2{})
            fail("setTile", kNoRampsOneWay);
        if (world.solver() == Solver::Classic)
            fail("setTile", kNoRampsInClassic);
        if (ramp->height != 0 && !map.halfTilesFit())
            fail("setTile", std::string("the map's tile ") + kHalfTilesTooSmall);
    }
    char& here = map.tiles[map.at(column, row)];
    if (here == tile)
        return;
    const bool rampsChange = rampTile(here) || rampTile(tile);
    const bool solid = tile == '#';
    here = tile;
    if (map.isSolid(column, row) != solid)
        setSolid(world, id, column, row, solid);
    if (rampsChange)
        rebuildRampsAround(world, id, column, row);
}

char tileOf(const World& world, TileMapId id, int column, int row) {
    const TileMapData& map = lookUp(WorldAccess::state(world), id, "tileOf");
    if (column < 0 || column >= map.columns || row < 0 || row >= map.rows)
        return '.';
    return map.tiles[map.at(column, row)];
}

bool isSolid(const World& world, TileMapId id, int column, int row) {
    const TileMapData& map = lookUp(WorldAccess::state(world), id, "isSolid");
    if (column < 0 || column >= map.columns || row < 0 || row >= map.rows)
        return false;
    return map.isSolid(column, row);
}

std::optional<TileCoord> tileAt(const World& world, TileMapId id, Vec2 point) {
    const TileMapData& map = lookUp(WorldAccess::state(world), id, "tileAt");
    requireFinite("tileAt", "point", point);
    const double tile = static_cast<double>(map.settings.tile);
    const double column =
        std::floor((static_cast<double>(point.x) - static_cast<double>(map.settings.x)) / tile);
    const double row =
        std::floor((static_cast<double>(point.y) - static_cast<double>(map.settings.y)) / tile);
    if (column < 0 || column >= map.columns || row < 0 || row >= map.rows)
        return std::nullopt;
    return TileCoord{static_cast<int>(column), static_cast<int>(row)};
}

int tileMapColumns(const World& world, TileMapId id) {
    return lookUp(WorldAccess::state(world), id, "tileMapColumns").columns;
}

int tileMapRows(const World& world, TileMapId id) {
    return lookUp(WorldAccess::state(world), id, "tileMapRows").rows;
}

TileMapDef tileMapDef(const World& world, TileMapId id) {
    const TileMapData& map = lookUp(WorldAccess::state(world), id, "tileMapDef");
    TileMapDef def = map.settings;
    def.rows.reserve(static_cast<std::size_t>(map.rows));
    for (int row = 0; row < map.rows; ++row) {
        def.rows.emplace_back(map.tiles.begin() + static_cast<std::ptrdiff_t>(map.at(0, row)),
                              map.tiles.begin() +
                                  static_cast<std::ptrdiff_t>(map.at(map.columns - 1, row) + 1));
    }
    return def;
}

std::span<const BodyId> tileMapBodies(const World& world, TileMapId id) {
    const WorldState& state = WorldAccess::state(world);
    const TileMapData& map = lookUp(state, id, "tileMapBodies");
    std::lock_guard<std::mutex> lock(state.tileMaps.listLock);
    return map.bodies.live();
}

TileMapId tileMapOf(const World& world, BodyId body) {
    const WorldState& state = WorldAccess::state(world);
    lookUp(state, body, "tileMapOf");
    const auto owner = state.tileMaps.owners.find(body.index);
    if (owner == state.tileMaps.owners.end() || owner->second.body != body)
        return {};
    return owner->second.map;
}

} // namespace jostle
