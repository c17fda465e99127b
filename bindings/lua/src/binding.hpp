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
//   per world, by storage slot, and one of destroyed bodies pushed out of it by newer
//   ones: pushHandle), so == works and bodies can be table keys.
#pragma once

#include "args.hpp"
#include "lua_compat.hpp"

#include <jostle/query.hpp>
#include <jostle/tilemap.hpp>
#include <jostle/world.hpp>

#include <initializer_list>
#include <new>
#include <span>
#include <vector>

namespace jostle::lua {

/// A field of a table of numbers, for setNumbers.
struct NamedNumber {
    const char* name;
    float value;
};

/// Sets each field to its number in the table on top of the stack.
inline void setNumbers(lua_State* L, std::initializer_list<NamedNumber> fields) {
    for (const NamedNumber& field : fields) {
        lua_pushnumber(L, static_cast<lua_Number>(field.value));
        lua_setfield(L, -2, field.name);
    }
}

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
    kSlotRetired = 7,     ///< "b12:3", "m0:1" -> a destroyed body's or map's userdata (weak values)
    kSlotCount = 7,
};

/// The module's state for one world, on the C++ heap.
struct WorldData {
    explicit WorldData(const WorldDef& def) : world(def) {}

    World world;

    // While world:step() runs: the state it was called in, and the stack slots holding
    // what the pre-solve callback needs (events.cpp).
    bool stepping = false;
    /// While world:move() runs, and so while its filter does: the world must not change
    /// under the core's sweep (requireChangeable).
    bool moving = false;
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
    MoveOutcome outcome;
    std::vector<ContactInfo> contacts;
    /// The last world:snapshot()'s bytes, on their way into a Lua string.
    std::vector<std::byte> snapshot;
    /// Positions or velocities on their way into a Lua table (pushVec2Array).
    std::vector<Vec2> vectors;
    /// What world:getPositionsBuffer and getVelocitiesBuffer hand to LuaJIT's FFI: kept
    /// until the next call of the same method, or until the world goes.
    std::vector<Vec2> positionsBuffer;
    std::vector<Vec2> velocitiesBuffer;
    /// What world:debugDraw draws, before the Lua functions draw it; `drawing` while they
    /// do, when the world may change but not go, nor draw again into the list.
    DebugDrawList drawList;
    bool drawing = false;
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

/// Thrown through the core's step by the pre-solve trampoline (and through move by the
/// filter's) when the Lua callback raised an error; the error value waits on top of the
/// Lua stack (events.cpp).
struct CallbackFailed {};

/// What a trampoline does: calls the C function at `runner` with `data` (a light
/// userdata), the World userdata at `world` and the Lua callback at `callback`, protected,
/// leaving its one result on top. If it raised, throws CallbackFailed with the error value
/// on top instead. Pushes nothing that allocates before the call, so raises nothing itself.
void callBack(lua_State* L, int runner, void* data, int world, int callback);

/// guard() for C++ work that calls Lua back through a trampoline that throws
/// CallbackFailed. `after` runs once the work is done, however it ended (it clears the
/// flags set for the work, and must not raise); then the callback's error is raised as
/// it was (a string keeps its position, a table stays the same table), or the C++ one as
/// guard raises it.
template <class Work, class After>
void guardCallbacks(lua_State* L, const char* where, Work&& work, After&& after) {
    char message[kMessageSize];
    bool callbackFailed = false;
    const bool ran = attempt(message, [&] {
        try {
            work();
        } catch (const CallbackFailed&) {
            callbackFailed = true;
            throw;
        }
    });
    after();
    if (callbackFailed)
        lua_error(L); // the callback's own error value, left on top by the trampoline
    if (!ran)
        raise(L, where, "%s", message);
}

/// Raises "<where>: called from World:move's filter ..." while a move of `world` runs: its
/// filter may read the world but not change it. Every method that changes a world, its
/// bodies or its maps calls it.
void requireChangeable(lua_State* L, const WorldData& world, const char* where);

// --- world.cpp -------------------------------------------------------------------------

/// The live world whose userdata is at `index` (self of a World method), or a Lua error.
WorldData& checkWorld(lua_State* L, int index, const char* where);
WorldHandle& checkWorldHandle(lua_State* L, int index, const char* where);
/// checkWorld, for a method that changes the world: requireChangeable too.
WorldData& checkWorldToChange(lua_State* L, int index, const char* where);
/// Pushes world.vectors as a flat array {x1, y1, x2, y2, ...}: into the table at
/// `tableIndex` if it is one (its entries beyond the new ones cleared), else a new one.
/// `handle` is the World userdata's contents (read afresh at each entry).
void pushVec2Array(lua_State* L, WorldHandle& handle, int tableIndex);
/// The table argument at `index` that a bulk read fills: its absolute index, or 0 for
/// none or nil; a Lua error for anything else.
int optTableToFill(lua_State* L, int index, const char* where);

/// A bulk read of one vector per body, in the order of World::bodies(): `read(world,
/// out)` fills `out` (as long as the body count) under guard, then the result is pushed
/// as pushVec2Array pushes it, into the table argument at `tableArg` if one is given.
template <class Read>
int pushBulkRead(lua_State* L, WorldHandle& handle, int tableArg, const char* where, Read read) {
    const int table = optTableToFill(L, tableArg, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] {
        world.vectors.resize(world.world.bodyCount());
        read(world.world, std::span<Vec2>(world.vectors));
    });
    pushVec2Array(L, handle, table);
    return 1;
}
/// world:step(dt) for the World userdata at `index`; raises what the step or a callback
/// raised.
void stepWorld(lua_State* L, int index, float dt, const char* where);
int newWorld(lua_State* L);
/// Pushes a new World userdata made from `def` (checked already) and returns its contents.
WorldHandle& pushNewWorld(lua_State* L, const WorldDef& def, const char* where);

// --- level.cpp (where the level library is built: JOSTLE_LUA_LEVELS) -------------------

/// jostle.loadTiled(path) and jostle.loadLdtk(path, level [, kinds]).
int loadTiled(lua_State* L);
int loadLdtk(lua_State* L);
void openWorld(lua_State* L);

// --- body.cpp --------------------------------------------------------------------------

/// Pushes the Body userdata of `id` (nil for the null handle). `env` is the stack index
/// of the world's user value table; `world` the World userdata's contents.
void pushBody(lua_State* L, int env, WorldHandle* world, BodyId id);
/// The body at `index`, live and of `world`, as an argument called `name`.
BodyId checkBodyArgument(lua_State* L, int index, const WorldData& world, const char* where,
                         const char* name);
/// Pushes a table {[bodyField] = body, numbers...}: a ray's hit, a contact.
void pushBodyRecord(lua_State* L, int env, WorldHandle* world, const char* bodyField, BodyId id,
                    std::initializer_list<NamedNumber> numbers);
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

// --- debug_draw.cpp --------------------------------------------------------------------

void registerDebugDrawMethods(lua_State* L, int worldMethods);
/// jostle.rgba(colour) -> r, g, b, a from 0 to 1.
int rgba(lua_State* L);

// --- snapshot.cpp ----------------------------------------------------------------------

void registerSnapshotMethods(lua_State* L, int worldMethods);

// --- fixed_step.cpp --------------------------------------------------------------------

int newFixedStep(lua_State* L);
void openFixedStep(lua_State* L);

// --- Shared helpers ----------------------------------------------------------------------

/// Pushes an array of one value per element of `elements(data)`, a vector of the world's
/// data: `push(element)` pushes each. The vector is read afresh at each entry, and not at
/// all once the world is gone: creating tables and userdata may run a finalizer, Lua code
/// that might use this very world.
template <class Elements, class Push>
void pushArray(lua_State* L, WorldHandle& handle, Elements elements, Push push) {
    lua_createtable(L, static_cast<int>(elements(*handle.data).size()), 0);
    for (std::size_t i = 0; handle.data && i < elements(*handle.data).size(); ++i) {
        push(elements(*handle.data)[i]);
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
}

/// Pushes the key under which the userdata of (slot, generation) is kept once retired
/// (see pushHandle): a string, "b12:3" for a body; `tag` tells bodies and maps apart.
void pushRetiredKey(lua_State* L, char tag, std::uint32_t slot, std::uint32_t generation);

/// Pushes the userdata of `Handle` type (BodyHandle, TileMapHandle) for `id`, or nil for
/// the null handle. The same handle always gives the same userdata while Lua holds it:
/// - The cache at `cacheSlot` of the user value table at `env` holds, by storage slot,
///   the userdata of the live body in that slot (weak values: Lua may collect it).
/// - A userdata pushed out of it by a newer body in its slot is kept among the retired,
///   by slot and generation, so that a contact-end event naming a destroyed body gives
///   back the very userdata the game holds for it.
/// `live` says whether `id` names a live body (or map); `tag` is 'b' or 'm'.
template <class Handle, class Id>
void pushHandle(lua_State* L, int env, int cacheSlot, char tag, const char* type,
                WorldHandle* world, Id id, bool live) {
    if (id.isNull()) {
        lua_pushnil(L);
        return;
    }
    env = absIndex(L, env);
    lua_rawgeti(L, env, cacheSlot);
    const int cache = lua_gettop(L);
    rawGetInteger(L, cache, id.index);
    const auto* cached = static_cast<const Handle*>(lua_touserdata(L, -1));
    if (cached && cached->id == id) {
        lua_remove(L, cache);
        return;
    }
    // Not the slot's current userdata. A destroyed body's may be among the retired; a
    // live body's never is (only a newer body of its slot could have pushed it out), so
    // the common case makes no key.
    lua_rawgeti(L, env, kSlotRetired);
    const int retired = lua_gettop(L);
    if (!live) {
        pushRetiredKey(L, tag, id.index, id.generation);
        lua_rawget(L, retired);
        if (!lua_isnil(L, -1)) {
            lua_replace(L, cache);
            lua_settop(L, cache);
            return;
        }
        lua_pop(L, 1);
    }

    new (newUserdata(L, sizeof(Handle))) Handle{world, id};
    const int created = lua_gettop(L);
    luaL_getmetatable(L, type);
    lua_setmetatable(L, created);
    lua_pushvalue(L, env);
    setUserValue(L, created);
    if (live || !cached) {
        if (cached) { // an older body of this slot makes way
            pushRetiredKey(L, tag, cached->id.index, cached->id.generation);
            lua_pushvalue(L, cache + 1);
            lua_rawset(L, retired);
        }
        lua_pushvalue(L, created);
        rawSetInteger(L, cache, id.index);
    } else { // a destroyed body named by an event, while a newer one holds the slot
        pushRetiredKey(L, tag, id.index, id.generation);
        lua_pushvalue(L, created);
        lua_rawset(L, retired);
    }
    lua_replace(L, cache);
    lua_settop(L, cache);
}

} // namespace jostle::lua
