// jostle.newWorld and the World's own methods: settings, bodies, stepping, destroy. The
// fields of newWorld and of the options are read and given back by the tables of
// src/world_options.hpp (definitions.hpp).
#include "binding.hpp"

#include "definitions.hpp"
#include "world_options.hpp"

#include <cmath>
#include <cstdio>
#include <span>
#include <type_traits>

namespace jostle::lua {

namespace {

/// Reads the options of `table` that a Lua table gives, and only those, into `options`.
template <class Options, class F, std::size_t N>
void readGroup(const Fields& fields, Options& options, const F (&table)[N]) {
    static const auto names = Names<N>().addAll(table);
    fields.allowOnly(names.data());
    readOptions(fields, options, table);
}

void readClassic(const Fields& fields, ClassicOptions& options) {
    readGroup(fields, options, properties::kClassicFields);
}

void readPhysical(const Fields& fields, PhysicalOptions& options) {
    readGroup(fields, options, properties::kPhysicalFields);
}

/// Reads the nested table `name` of `fields`, if present, with `read`.
template <class Options, class Read>
void readNested(lua_State* L, const Fields& fields, const char* where, const char* name,
                const char* prefix, Options& options, Read read) {
    fields.push(name);
    if (!lua_isnil(L, -1)) {
        if (lua_type(L, -1) != LUA_TTABLE)
            raise(L, where, "%s: expected a table, got %s", name, typeName(L, -1));
        read(Fields(L, -1, where, prefix), options);
    }
    lua_pop(L, 1);
}

/// The WorldDef described by the table at `index` (absent: the defaults).
WorldDef readWorldDef(lua_State* L, int index, const char* where) {
    WorldDef def;
    if (lua_isnoneornil(L, index))
        return def;
    checkTable(L, index, where, "def");
    const Fields fields(L, index, where);
    // WorldDef's own fields, its options in tables of their own, and (at the top level) its
    // task system's settings, workers.
    static constexpr auto kNames =
        Names<std::size(properties::kWorldFields) + 2 + std::size(properties::kTaskFields)>()
            .addAll(properties::kWorldFields)
            .add("classic")
            .add("physical")
            .addAll(properties::kTaskFields);
    fields.allowOnly(kNames.data());
    readOptions(fields, def, properties::kWorldFields);
    readNested(L, fields, where, "classic", "classic.", def.classic, readClassic);
    readNested(L, fields, where, "physical", "physical.", def.physical, readPhysical);
    readOptions(fields, def.tasks, properties::kTaskFields);
    return def;
}

/// Raises the first problem checkWorldDef finds, named as a field of the Lua table.
void requireValidWorldDef(lua_State* L, const WorldDef& def, const char* where) {
    char message[kMessageSize];
    bool bad = false;
    const bool ran = attempt(message, [&] {
        if (auto problem = checkWorldDef(def)) {
            bad = true;
            describe(message, *problem);
        }
    });
    if (!ran || bad)
        raise(L, where, "%s", message);
}

/// The options as a table that their setter (and newWorld) accepts.
template <class Options, class F, std::size_t N>
void pushOptions(lua_State* L, const Options& options, const F (&table)[N]) {
    lua_createtable(L, 0, static_cast<int>(N));
    setFields(L, options, table);
}

// --- Methods -----------------------------------------------------------------------------

int worldStep(lua_State* L) {
    const char* where = "World:step";
    checkWorld(L, 1, where);
    const float dt = checkNumber(L, 2, where, "dt");
    if (!(dt > 0.0f))
        raise(L, where, "dt: must be > 0");
    stepWorld(L, 1, dt, where);
    return 0;
}

int worldGetBodies(lua_State* L) {
    const char* where = "World:getBodies";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] {
        const auto bodies = world.world.bodies();
        world.ids.assign(bodies.begin(), bodies.end());
    });
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(world.ids.size()), 0);
    // Index by index, checking the size each time: creating userdata may run a
    // finalizer, and a finalizer is Lua code that might query this very world.
    for (std::size_t i = 0; handle.data && i < handle.data->ids.size(); ++i) {
        pushBody(L, env, &handle, handle.data->ids[i]);
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    return 1;
}

/// world:adopt(other): this world's Body (or TileMap) of the same slot and generation as
/// `other`, a Body or TileMap of another world whose snapshot this one restored; nil if
/// none is alive here.
int worldAdopt(lua_State* L) {
    const char* where = "World:adopt";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const World& world = handle.data->world;
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    if (const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, 2, kBodyType))) {
        pushBody(L, env, &handle, world.adopt(body->id));
        return 1;
    }
    if (const auto* map = static_cast<TileMapHandle*>(luaL_testudata(L, 2, kTileMapType))) {
        pushTileMap(L, env, &handle, world.adopt(map->id));
        return 1;
    }
    raise(L, where, "other: expected a Body or a TileMap, got %s", typeName(L, 2));
}

/// {x1, y1, x2, y2, ...}: the positions (or velocities) of the bodies, in the order of
/// world:getBodies(), into the table given or a new one.
int worldGetPositions(lua_State* L) {
    const char* where = "World:getPositions";
    return pushBulkRead(L, checkWorldHandle(L, 1, where), 2, where,
                        [](const World& w, std::span<Vec2> out) { w.readPositions(out); });
}

int worldGetVelocities(lua_State* L) {
    const char* where = "World:getVelocities";
    return pushBulkRead(L, checkWorldHandle(L, 1, where), 2, where,
                        [](const World& w, std::span<Vec2> out) { w.readVelocities(out); });
}

/// {hw1, hh1, hw2, hh2, ...}: the half extents of the bodies, in the same order.
int worldGetHalfExtents(lua_State* L) {
    const char* where = "World:getHalfExtents";
    return pushBulkRead(L, checkWorldHandle(L, 1, where), 2, where,
                        [](const World& w, std::span<Vec2> out) { w.readHalfExtents(out); });
}

#ifdef LUAJIT_VERSION
// For LuaJIT's FFI: the array itself, as floats x1, y1, x2, y2, ..., and the number of
// bodies; no call per body nor per value.
static_assert(sizeof(Vec2) == 2 * sizeof(float) && std::is_standard_layout_v<Vec2>,
              "the buffers are read as float arrays");

/// Fills the kept `buffer` by `read` and returns a pointer to it and the body count.
int pushBuffer(lua_State* L, const char* where, std::vector<Vec2> WorldData::*buffer,
               std::size_t (World::*read)(std::span<Vec2>) const) {
    WorldData& world = checkWorld(L, 1, where);
    std::vector<Vec2>& out = world.*buffer;
    guard(L, where, [&] {
        out.resize(world.world.bodyCount());
        (world.world.*read)(out);
    });
    lua_pushlightuserdata(L, out.data());
    pushWhole(L, static_cast<std::int64_t>(out.size()));
    return 2;
}

int worldGetPositionsBuffer(lua_State* L) {
    return pushBuffer(L, "World:getPositionsBuffer", &WorldData::positionsBuffer,
                      &World::readPositions);
}

int worldGetVelocitiesBuffer(lua_State* L) {
    return pushBuffer(L, "World:getVelocitiesBuffer", &WorldData::velocitiesBuffer,
                      &World::readVelocities);
}
#endif

int worldGetBodyCount(lua_State* L) {
    const WorldData& world = checkWorld(L, 1, "World:getBodyCount");
    pushWhole(L, static_cast<std::int64_t>(world.world.bodyCount()));
    return 1;
}

int worldGetGravity(lua_State* L) {
    const Vec2 g = checkWorld(L, 1, "World:getGravity").world.gravity();
    lua_pushnumber(L, static_cast<lua_Number>(g.x));
    lua_pushnumber(L, static_cast<lua_Number>(g.y));
    return 2;
}

int worldSetGravity(lua_State* L) {
    const char* where = "World:setGravity";
    WorldData& world = checkWorldToChange(L, 1, where);
    const Vec2 g = checkVec2(L, 2, where, "x", "y");
    guard(L, where, [&] { world.world.setGravity(g); });
    return 0;
}

int worldGetMaxVelocity(lua_State* L) {
    lua_pushnumber(
        L, static_cast<lua_Number>(checkWorld(L, 1, "World:getMaxVelocity").world.maxVelocity()));
    return 1;
}

int worldSetMaxVelocity(lua_State* L) {
    const char* where = "World:setMaxVelocity";
    WorldData& world = checkWorldToChange(L, 1, where);
    const float maxVelocity = checkNumberOrInfinity(L, 2, where, "maxVelocity");
    if (!(maxVelocity > 0.0f))
        raise(L, where, "maxVelocity: must be > 0 (math.huge for no clamp)");
    guard(L, where, [&] { world.world.setMaxVelocity(maxVelocity); });
    return 0;
}

int worldGetSolver(lua_State* L) {
    pushField(L, checkWorld(L, 1, "World:getSolver").world.solver());
    return 1;
}

int worldSetSolver(lua_State* L) {
    const char* where = "World:setSolver";
    WorldData& world = checkWorldToChange(L, 1, where);
    const Solver solver = valueAt<Solver>(checkOption(L, 2, where, "solver", kSolverNames));
    guard(L, where, [&] { world.world.setSolver(solver); });
    return 0;
}

int worldGetWorkers(lua_State* L) {
    pushWhole(L, checkWorld(L, 1, "World:getWorkers").world.workers());
    return 1;
}

int worldGetSleeping(lua_State* L) {
    lua_pushboolean(L, checkWorld(L, 1, "World:getSleeping").world.sleeping());
    return 1;
}

int worldSetSleeping(lua_State* L) {
    const char* where = "World:setSleeping";
    WorldData& world = checkWorldToChange(L, 1, where);
    const bool enabled = checkBoolean(L, 2, where, "enabled");
    guard(L, where, [&] { world.world.setSleeping(enabled); });
    return 0;
}

int worldGetClassicOptions(lua_State* L) {
    pushOptions(L, checkWorld(L, 1, "World:getClassicOptions").world.classicOptions(),
                properties::kClassicFields);
    return 1;
}

/// Fields left out keep their current values.
int worldSetClassicOptions(lua_State* L) {
    const char* where = "World:setClassicOptions";
    WorldData& world = checkWorldToChange(L, 1, where);
    checkTable(L, 2, where, "options");
    ClassicOptions options = world.world.classicOptions();
    readClassic(Fields(L, 2, where), options);
    guard(L, where, [&] { world.world.setClassicOptions(options); });
    return 0;
}

int worldGetPhysicalOptions(lua_State* L) {
    pushOptions(L, checkWorld(L, 1, "World:getPhysicalOptions").world.physicalOptions(),
                properties::kPhysicalFields);
    return 1;
}

int worldSetPhysicalOptions(lua_State* L) {
    const char* where = "World:setPhysicalOptions";
    WorldData& world = checkWorldToChange(L, 1, where);
    checkTable(L, 2, where, "options");
    PhysicalOptions options = world.world.physicalOptions();
    readPhysical(Fields(L, 2, where), options);
    guard(L, where, [&] { world.world.setPhysicalOptions(options); });
    return 0;
}

/// Frees the world at once instead of when it is collected. Its bodies and maps stay
/// valid Lua values whose methods raise "the body's world was destroyed".
int worldDestroy(lua_State* L) {
    const char* where = "World:destroy";
    WorldHandle* handle = static_cast<WorldHandle*>(luaL_testudata(L, 1, kWorldType));
    if (!handle)
        raise(L, where, "expected a World as self (call it with a colon), got %s", typeName(L, 1));
    if (!handle->data)
        return 0; // twice is harmless, as for a file
    if (handle->data->stepping)
        raise(L, where, "called from a callback during step()");
    if (handle->data->drawing)
        raise(L, where, "called from a function of world:debugDraw");
    requireChangeable(L, *handle->data, where);
    delete handle->data;
    handle->data = nullptr;
    // Let go of the Lua values the world held for its bodies.
    pushUserValue(L, 1);
    for (int slot : {kSlotUserData, kSlotUserDataGen, kSlotPreSolve}) {
        lua_pushnil(L);
        lua_rawseti(L, -2, slot);
    }
    return 0;
}

int worldIsDestroyed(lua_State* L) {
    const auto* handle = static_cast<WorldHandle*>(luaL_testudata(L, 1, kWorldType));
    if (!handle)
        raise(L, "World:isDestroyed", "expected a World as self (call it with a colon), got %s",
              typeName(L, 1));
    lua_pushboolean(L, handle->data == nullptr);
    return 1;
}

int worldGc(lua_State* L) {
    auto* handle = static_cast<WorldHandle*>(lua_touserdata(L, 1));
    if (handle && handle->data) {
        delete handle->data;
        handle->data = nullptr;
    }
    return 0;
}

int worldToString(lua_State* L) {
    const auto* handle = static_cast<const WorldHandle*>(lua_touserdata(L, 1));
    if (!handle->data)
        lua_pushfstring(L, "jostle.World (destroyed): %p", lua_topointer(L, 1));
    else
        lua_pushfstring(L, "jostle.World (%d bodies): %p",
                        static_cast<int>(handle->data->world.bodyCount()), lua_topointer(L, 1));
    return 1;
}

constexpr luaL_Reg kWorldMethods[] = {
    {"step", worldStep},
    {"getBodies", worldGetBodies},
    {"adopt", worldAdopt},
    {"getBodyCount", worldGetBodyCount},
    {"getPositions", worldGetPositions},
    {"getVelocities", worldGetVelocities},
    {"getHalfExtents", worldGetHalfExtents},
#ifdef LUAJIT_VERSION
    {"getPositionsBuffer", worldGetPositionsBuffer},
    {"getVelocitiesBuffer", worldGetVelocitiesBuffer},
#endif
    {"getGravity", worldGetGravity},
    {"setGravity", worldSetGravity},
    {"getMaxVelocity", worldGetMaxVelocity},
    {"setMaxVelocity", worldSetMaxVelocity},
    {"getSolver", worldGetSolver},
    {"setSolver", worldSetSolver},
    {"getSleeping", worldGetSleeping},
    {"getWorkers", worldGetWorkers},
    {"setSleeping", worldSetSleeping},
    {"getClassicOptions", worldGetClassicOptions},
    {"setClassicOptions", worldSetClassicOptions},
    {"getPhysicalOptions", worldGetPhysicalOptions},
    {"setPhysicalOptions", worldSetPhysicalOptions},
    {"destroy", worldDestroy},
    {"isDestroyed", worldIsDestroyed},
    {nullptr, nullptr},
};

} // namespace

WorldHandle& checkWorldHandle(lua_State* L, int index, const char* where) {
    auto* handle = static_cast<WorldHandle*>(luaL_testudata(L, index, kWorldType));
    if (!handle && index == 1)
        raise(L, where, "expected a World as self (call it with a colon: world:method()), got %s",
              typeName(L, index));
    if (!handle)
        raise(L, where, "world: expected a World, got %s", typeName(L, index));
    if (!handle->data)
        raise(L, where, "the world was destroyed");
    return *handle;
}

void pushRetiredKey(lua_State* L, char tag, std::uint32_t slot, std::uint32_t generation) {
    char key[32];
    std::snprintf(key, sizeof key, "%c%u:%u", tag, slot, generation);
    lua_pushstring(L, key);
}

WorldData& checkWorld(lua_State* L, int index, const char* where) {
    return *checkWorldHandle(L, index, where).data;
}

void requireChangeable(lua_State* L, const WorldData& world, const char* where) {
    if (world.moving)
        raise(L, where,
              "called from World:move's filter (the world cannot change until the "
              "move is done)");
}

WorldData& checkWorldToChange(lua_State* L, int index, const char* where) {
    WorldData& world = checkWorld(L, index, where);
    requireChangeable(L, world, where);
    return world;
}

int optTableToFill(lua_State* L, int index, const char* where) {
    if (lua_isnoneornil(L, index))
        return 0;
    return checkTable(L, index, where, "t");
}

void pushVec2Array(lua_State* L, WorldHandle& handle, int tableIndex) {
    // A table reused shorter than before loses its tail, so that #t stays 2 x the count.
    const std::size_t before = tableIndex != 0 ? rawLength(L, tableIndex) : 0;
    if (tableIndex != 0)
        lua_pushvalue(L, tableIndex);
    else
        lua_createtable(L, static_cast<int>(handle.data->vectors.size() * 2), 0);
    const int table = lua_gettop(L);
    // Entry by entry, reading the world each time: growing the table may run a finalizer,
    // Lua code that might use this very world.
    int next = 1;
    for (std::size_t i = 0; handle.data && i < handle.data->vectors.size(); ++i) {
        const Vec2 v = handle.data->vectors[i];
        lua_pushnumber(L, static_cast<lua_Number>(v.x));
        lua_rawseti(L, table, next++);
        lua_pushnumber(L, static_cast<lua_Number>(v.y));
        lua_rawseti(L, table, next++);
    }
    for (std::size_t i = static_cast<std::size_t>(next); i <= before; ++i) {
        lua_pushnil(L);
        lua_rawseti(L, table, static_cast<int>(i));
    }
}

void stepWorld(lua_State* L, int index, float dt, const char* where) {
    index = absIndex(L, index);
    WorldData& world = checkWorld(L, index, where);
    if (world.stepping)
        raise(L, where, "called from a callback during step()");
    requireChangeable(L, world, where);
    const int top = lua_gettop(L);
    preparePreSolve(L, index, world);

    world.stepping = true;
    world.stepState = L;
    guardCallbacks(
        L, where, [&] { world.world.step(dt); },
        [&] {
            world.stepping = false;
            world.stepState = nullptr;
        });
    lua_settop(L, top);
}

int newWorld(lua_State* L) {
    const char* where = "jostle.newWorld";
    const WorldDef def = readWorldDef(L, 1, where);
    requireValidWorldDef(L, def, where);
    pushNewWorld(L, def, where);
    return 1;
}

WorldHandle& pushNewWorld(lua_State* L, const WorldDef& def, const char* where) {
    // The userdata first, empty: if anything below fails, the collector frees it.
    auto* handle = static_cast<WorldHandle*>(newUserdata(L, sizeof(WorldHandle)));
    handle->data = nullptr;
    luaL_getmetatable(L, kWorldType);
    lua_setmetatable(L, -2);
    const int self = lua_gettop(L);

    lua_createtable(L, kSlotCount, 0);
    lua_pushvalue(L, self);
    lua_rawseti(L, -2, kSlotWorld);
    for (int slot : {kSlotBodies, kSlotMaps, kSlotRetired}) {
        lua_newtable(L);
        luaL_getmetatable(L, "jostle.weakValues");
        lua_setmetatable(L, -2);
        lua_rawseti(L, -2, slot);
    }
    lua_newtable(L);
    lua_rawseti(L, -2, kSlotUserData);
    lua_newtable(L);
    lua_rawseti(L, -2, kSlotUserDataGen);
    setUserValue(L, self);

    WorldData* data = nullptr;
    guard(L, where, [&] { data = new WorldData(def); });
    handle->data = data;
    return *handle;
}

void openWorld(lua_State* L) {
    luaL_newmetatable(L, "jostle.weakValues");
    lua_pushliteral(L, "v");
    lua_setfield(L, -2, "__mode");
    lua_pop(L, 1);

    luaL_newmetatable(L, kWorldType);
    lua_createtable(L, 0, 64);
    luaL_setfuncs(L, kWorldMethods, 0);
    const int methods = lua_gettop(L);
    registerBodyMethods(L, methods);
    registerEventMethods(L, methods);
    registerQueryMethods(L, methods);
    registerTileMapMethods(L, methods);
    registerSnapshotMethods(L, methods);
    registerDebugDrawMethods(L, methods);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, worldGc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, worldToString);
    lua_setfield(L, -2, "__tostring");
    lua_pushliteral(L, "jostle.World");
    lua_setfield(L, -2, "__name");
    lua_pop(L, 1);
}

} // namespace jostle::lua
