// What the files of the Lua module share: the userdata layouts, the registry names and
// the functions one file offers the others.
//
// Objects and their lifetimes:
// - A World userdata holds a pointer to a WorldData (the jostle::World and the module's
//   state for it) on the C++ heap, freed by world:destroy() or the garbage collector.
// - Body and TileMap userdata hold the World userdata's address and a handle. Each one's
//   user value is the world's user value table (below), which holds the World userdata:
//   so a world lives as long as any of its bodies or maps is reachable, and a body never
//   points to freed memory. After world:destroy() the pointer in the World userdata is
//   null, and every method of its bodies raises "the body's world was destroyed".
// - The same body is always the same userdata while Lua holds it (a weak-valued cache
//   per world, by storage slot), so == works and bodies can be table keys.
#pragma once

#include "args.hpp"
#include "lua_compat.hpp"

#include <jostle/query.hpp>
#include <jostle/tilemap.hpp>
#include <jostle/world.hpp>

#include <new>
#include <vector>

namespace jostle::lua {

// Metatables in the registry, by the names luaL_newmetatable gives them.
inline constexpr const char* kWorldType = "jostle.World";
inline constexpr const char* kBodyType = "jostle.Body";
inline constexpr const char* kTileMapType = "jostle.TileMap";
inline constexpr const char* kFixedStepType = "jostle.FixedStep";

/// The slots of a world's user value table, shared by the world, its bodies and its maps.
/// Integer keys: reading them allocates nothing.
enum Slot : int {
    kSlotWorld = 1,       ///< the World userdata
    kSlotBodies = 2,      ///< storage slot -> Body userdata (weak values)
    kSlotMaps = 3,        ///< tile map slot -> TileMap userdata (weak values)
    kSlotUserData = 4,    ///< body storage slot -> the value of body:setUserData
    kSlotUserDataGen = 5, ///< body storage slot -> the generation that value belongs to
    kSlotPreSolve = 6,    ///< the pre-solve function, or nil
    kSlotCount = 6,
};

/// The module's state for one world, on the C++ heap.
struct WorldData {
    explicit WorldData(const WorldDef& def) : world(def) {}

    World world;

    // While world:step() runs: the state it was called in, and the stack slots holding
    // what the pre-solve callback needs (events.cpp).
    bool stepping = false;
    lua_State* stepState = nullptr;
    int worldIndex = 0;    ///< the World userdata
    int runnerIndex = 0;   ///< the C function that calls the Lua callback, protected
    int callbackIndex = 0; ///< the Lua callback, as it was when the step began
    bool preSolveInstalled = false;

    // Results of queries, kept here and reused so that no C++ container lives in a
    // frame that may raise a Lua error (args.hpp).
    std::vector<BodyId> ids;
    std::vector<RayHit> rayHits;
    MoveResult moved;
};

struct WorldHandle {
    WorldData* data; ///< null once destroyed
};

struct BodyHandle {
    WorldHandle* world;
    BodyId id;
};

struct TileMapHandle {
    WorldHandle* world;
    TileMapId id;
};

/// Thrown through the core's step by the pre-solve trampoline when the Lua callback
/// raised an error; the error value waits on top of the Lua stack (events.cpp).
struct CallbackFailed {};

// --- world.cpp -------------------------------------------------------------------------

/// The live world whose userdata is at `index` (self of a World method), or a Lua error.
WorldData& checkWorld(lua_State* L, int index, const char* where);
WorldHandle& checkWorldHandle(lua_State* L, int index, const char* where);
/// world:step(dt) for the World userdata at `index`; raises what the step or a callback
/// raised.
void stepWorld(lua_State* L, int index, float dt, const char* where);
int newWorld(lua_State* L);
void openWorld(lua_State* L);

// --- body.cpp --------------------------------------------------------------------------

/// Pushes the Body userdata of `id` (nil for the null handle). `env` is the stack index
/// of the world's user value table; `world` the World userdata's contents.
void pushBody(lua_State* L, int env, WorldHandle* world, BodyId id);
/// The body at `index`, live and of `world`, as an argument called `name`.
BodyId checkBodyArgument(lua_State* L, int index, const WorldData& world, const char* where,
                         const char* name);
void registerBodyMethods(lua_State* L, int worldMethods);
void openBody(lua_State* L);

// --- events.cpp ------------------------------------------------------------------------

/// Before a step: installs or removes the C++ pre-solve callback to match the Lua one,
/// and pushes what it needs onto the stack (see WorldData). Pops nothing.
void preparePreSolve(lua_State* L, int worldIndex, WorldData& world);
void registerEventMethods(lua_State* L, int worldMethods);

// --- queries.cpp -----------------------------------------------------------------------

void registerQueryMethods(lua_State* L, int worldMethods);

// --- tilemap.cpp -----------------------------------------------------------------------

void registerTileMapMethods(lua_State* L, int worldMethods);
void openTileMap(lua_State* L);
/// Pushes the TileMap userdata of `id` (nil for the null handle); `env` as for pushBody.
void pushTileMap(lua_State* L, int env, WorldHandle* world, TileMapId id);

// --- fixed_step.cpp --------------------------------------------------------------------

int newFixedStep(lua_State* L);
void openFixedStep(lua_State* L);

// --- Shared helpers ----------------------------------------------------------------------

/// Pushes the userdata of `Handle` type (BodyHandle, TileMapHandle) for `id`, from the
/// weak cache at `cacheSlot` of the user value table at `env`, or a new one (stored in
/// the cache). Nil for the null handle. A cached userdata of a stale handle whose slot
/// was reused is replaced: the new body gets its own userdata.
template <class Handle, class Id>
void pushHandle(lua_State* L, int env, int cacheSlot, const char* type, WorldHandle* world, Id id) {
    if (id.isNull()) {
        lua_pushnil(L);
        return;
    }
    env = absIndex(L, env);
    lua_rawgeti(L, env, cacheSlot);
    rawGetInteger(L, -1, id.index);
    if (const auto* cached = static_cast<const Handle*>(lua_touserdata(L, -1));
        cached && cached->id == id) {
        lua_remove(L, -2); // the cache
        return;
    }
    lua_pop(L, 1);
    new (newUserdata(L, sizeof(Handle))) Handle{world, id};
    luaL_getmetatable(L, type);
    lua_setmetatable(L, -2);
    lua_pushvalue(L, env);
    setUserValue(L, -2);
    lua_pushvalue(L, -1);
    rawSetInteger(L, -3, id.index);
    lua_remove(L, -2); // the cache
}

} // namespace jostle::lua
