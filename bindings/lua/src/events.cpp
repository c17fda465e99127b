// What a step reports (contact, sensor and crush events) and the pre-solve callback.
//
// The callback is a Lua function called from inside the core's step. The way there and
// back, safe in both interpreters:
// - Before the step, world:step pushes a C function (runPreSolve) and the Lua callback
//   onto the stack, so that the trampoline called by the core pushes nothing that could
//   allocate, and so cannot raise an error outside protection.
// - The trampoline calls runPreSolve with lua_pcall: every Lua error, the callback's own
//   or one while building its argument, stops there, never unwinding through the core.
// - If it failed, the trampoline leaves the error value on the stack and throws
//   CallbackFailed to the core (which finishes its step as if the callback had answered
//   true, then throws it again); world:step catches it and, once out of every C++ scope,
//   raises the error value as is.
#include "binding.hpp"

#include <cmath>
#include <utility>

namespace jostle::lua {

namespace {

void setNumber(lua_State* L, const char* name, float value) {
    lua_pushnumber(L, static_cast<lua_Number>(value));
    lua_setfield(L, -2, name);
}

/// Reads c.bounce or c.friction back from the callback's table, which must still hold a
/// number in [0, 1]. A protected function: raising here is caught by the trampoline's
/// lua_pcall.
float readBack(lua_State* L, int table, const char* name) {
    lua_getfield(L, table, name);
    if (lua_type(L, -1) != LUA_TNUMBER)
        raise(L, "World:step", "pre-solve: c.%s: expected a number, got %s", name, typeName(L, -1));
    const double value = static_cast<double>(lua_tonumber(L, -1));
    if (!(value >= 0.0 && value <= 1.0))
        raise(L, "World:step", "pre-solve: c.%s: must be in [0, 1]", name);
    lua_pop(L, 1);
    return static_cast<float>(value);
}

/// Called (protected) by the trampoline with the Collision, the World userdata and the
/// Lua callback. Builds c = {a, b, nx, ny, depth, bounce, friction}, calls the callback
/// and writes back what it changed. Returns false if the callback returned false.
int runPreSolve(lua_State* L) {
    auto* collision = static_cast<Collision*>(lua_touserdata(L, 1));
    auto* world = static_cast<WorldHandle*>(lua_touserdata(L, 2));
    pushUserValue(L, 2);
    const int env = lua_gettop(L);

    lua_createtable(L, 0, 7);
    const int table = lua_gettop(L);
    pushBody(L, env, world, collision->a);
    lua_setfield(L, table, "a");
    pushBody(L, env, world, collision->b);
    lua_setfield(L, table, "b");
    setNumber(L, "nx", collision->normal.x);
    setNumber(L, "ny", collision->normal.y);
    setNumber(L, "depth", collision->depth);
    setNumber(L, "bounce", collision->bounce);
    setNumber(L, "friction", collision->friction);

    lua_pushvalue(L, 3); // the callback
    lua_pushvalue(L, table);
    lua_call(L, 1, 1);
    // Only false ignores the pair: a callback that returns nothing keeps it.
    const bool keep = !(lua_type(L, -1) == LUA_TBOOLEAN && !lua_toboolean(L, -1));
    // A field the callback set that is none of c's (c.frcition = 0) must not pass silently.
    static const char* const kFields[] = {"a",     "b",      "nx",       "ny",
                                          "depth", "bounce", "friction", nullptr};
    Fields(L, table, "World:step", "pre-solve: c.").allowOnly(kFields);
    const float bounce = readBack(L, table, "bounce");
    const float friction = readBack(L, table, "friction");
    collision->bounce = bounce;
    collision->friction = friction;
    lua_pushboolean(L, keep);
    return 1;
}

/// The C++ pre-solve callback: runs the Lua one through runPreSolve, protected.
bool trampoline(WorldData& world, Collision& collision) {
    lua_State* L = world.stepState;
    callBack(L, world.runnerIndex, &collision, world.worldIndex, world.callbackIndex);
    const bool keep = lua_toboolean(L, -1) != 0;
    lua_pop(L, 1);
    return keep;
}

// --- Events ----------------------------------------------------------------------------

/// Pushes an array of one table per event. `count` reads the number of events and
/// `fill` pushes the fields of event i into the table on top; both read the world afresh
/// each time, since creating tables may run a finalizer (Lua code) that steps the world.
template <class Count, class Fill>
int pushEvents(lua_State* L, const char* where, Count count, Fill fill) {
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(count(handle.data->world)), 0);
    for (std::size_t i = 0; handle.data && i < count(handle.data->world); ++i) {
        lua_createtable(L, 0, 7);
        fill(env, &handle, i);
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    return 1;
}

/// {a = body, b = body, nx = , ny = , approachSpeed = }, and x, y where they touch for a
/// begin (`withPoint`).
template <class Get>
int pushContactEvents(lua_State* L, const char* where, bool withPoint, Get get) {
    return pushEvents(
        L, where, [&](const World& w) { return get(w).size(); },
        [&](int env, WorldHandle* handle, std::size_t i) {
            const ContactEvent e = get(handle->data->world)[i];
            pushBody(L, env, handle, e.a);
            lua_setfield(L, -2, "a");
            pushBody(L, env, handle, e.b);
            lua_setfield(L, -2, "b");
            setNumber(L, "nx", e.normal.x);
            setNumber(L, "ny", e.normal.y);
            setNumber(L, "approachSpeed", e.approachSpeed);
            if (withPoint) {
                setNumber(L, "x", e.point.x);
                setNumber(L, "y", e.point.y);
            }
        });
}

/// {sensor = body, visitor = body}
template <class Get> int pushSensorEvents(lua_State* L, const char* where, Get get) {
    return pushEvents(
        L, where, [&](const World& w) { return get(w).size(); },
        [&](int env, WorldHandle* handle, std::size_t i) {
            const SensorEvent e = get(handle->data->world)[i];
            pushBody(L, env, handle, e.sensor);
            lua_setfield(L, -2, "sensor");
            pushBody(L, env, handle, e.visitor);
            lua_setfield(L, -2, "visitor");
        });
}

int worldGetContactBegins(lua_State* L) {
    return pushContactEvents(L, "World:getContactBegins", true,
                             [](const World& w) { return w.contactBegins(); });
}

int worldGetContactEnds(lua_State* L) {
    return pushContactEvents(L, "World:getContactEnds", false,
                             [](const World& w) { return w.contactEnds(); });
}

int worldGetSensorBegins(lua_State* L) {
    return pushSensorEvents(L, "World:getSensorBegins",
                            [](const World& w) { return w.sensorBegins(); });
}

int worldGetSensorEnds(lua_State* L) {
    return pushSensorEvents(L, "World:getSensorEnds",
                            [](const World& w) { return w.sensorEnds(); });
}

/// {body = , by = , against = }, of World::crushBegins or crushEnds.
template <class Get> int pushCrushEvents(lua_State* L, const char* where, Get get) {
    return pushEvents(
        L, where, [&](const World& w) { return get(w).size(); },
        [&](int env, WorldHandle* handle, std::size_t i) {
            const CrushEvent e = get(handle->data->world)[i];
            pushBody(L, env, handle, e.body);
            lua_setfield(L, -2, "body");
            pushBody(L, env, handle, e.by);
            lua_setfield(L, -2, "by");
            pushBody(L, env, handle, e.against);
            lua_setfield(L, -2, "against");
        });
}

int worldGetCrushBegins(lua_State* L) {
    return pushCrushEvents(L, "World:getCrushBegins",
                           [](const World& w) { return w.crushBegins(); });
}

int worldGetCrushEnds(lua_State* L) {
    return pushCrushEvents(L, "World:getCrushEnds", [](const World& w) { return w.crushEnds(); });
}

/// Pairs the last step left out for want of maxContactsPerBody (0 in a sane scene).
int worldGetPairsLeftOut(lua_State* L) {
    const WorldData& world = checkWorld(L, 1, "World:getPairsLeftOut");
    pushWhole(L, static_cast<std::int64_t>(world.world.pairsLeftOut()));
    return 1;
}

/// world:getProfile(): where the last step's time went, in milliseconds, by stage.
int worldGetProfile(lua_State* L) {
    const StepProfile& p = checkWorld(L, 1, "World:getProfile").world.profile();
    lua_createtable(L, 0, static_cast<int>(std::size(kStepProfileFields)));
    for (const StepProfileField& stage : kStepProfileFields) {
        lua_pushnumber(L, p.*stage.ms);
        lua_setfield(L, -2, stage.name);
    }
    return 1;
}

// --- The pre-solve callback --------------------------------------------------------------

/// world:setPreSolve(function(c) ... end) or nil to remove it. Changed from inside the
/// callback, the change applies from the next step.
int worldSetPreSolve(lua_State* L) {
    const char* where = "World:setPreSolve";
    checkWorld(L, 1, where);
    if (!lua_isnoneornil(L, 2) && lua_type(L, 2) != LUA_TFUNCTION)
        raise(L, where, "callback: expected a function or nil, got %s", typeName(L, 2));
    lua_settop(L, 2);
    pushUserValue(L, 1);
    lua_pushvalue(L, 2);
    lua_rawseti(L, -2, kSlotPreSolve);
    return 0;
}

int worldGetPreSolve(lua_State* L) {
    checkWorld(L, 1, "World:getPreSolve");
    pushUserValue(L, 1);
    lua_rawgeti(L, -1, kSlotPreSolve);
    return 1;
}

constexpr luaL_Reg kEventMethods[] = {
    {"getContactBegins", worldGetContactBegins},
    {"getContactEnds", worldGetContactEnds},
    {"getSensorBegins", worldGetSensorBegins},
    {"getSensorEnds", worldGetSensorEnds},
    {"getCrushBegins", worldGetCrushBegins},
    {"getCrushEnds", worldGetCrushEnds},
    {"getPairsLeftOut", worldGetPairsLeftOut},
    {"getProfile", worldGetProfile},
    {"setPreSolve", worldSetPreSolve},
    {"getPreSolve", worldGetPreSolve},
    {nullptr, nullptr},
};

} // namespace

void callBack(lua_State* L, int runner, void* data, int world, int callback) {
    lua_pushvalue(L, runner);
    lua_pushlightuserdata(L, data);
    lua_pushvalue(L, world);
    lua_pushvalue(L, callback);
    if (lua_pcall(L, 3, 1, 0) != 0)
        throw CallbackFailed{}; // the error value stays on top, for the caller to raise
}

void preparePreSolve(lua_State* L, int worldIndex, WorldData& world) {
    worldIndex = absIndex(L, worldIndex);
    luaL_checkstack(L, 8, "jostle: World:step");
    pushUserValue(L, worldIndex);
    lua_rawgeti(L, -1, kSlotPreSolve);
    lua_remove(L, -2);
    const bool wanted = lua_type(L, -1) == LUA_TFUNCTION;
    if (wanted) {
        world.callbackIndex = lua_gettop(L);
        lua_pushcfunction(L, runPreSolve);
        world.runnerIndex = lua_gettop(L);
        world.worldIndex = worldIndex;
    }
    if (wanted != world.preSolveInstalled) {
        // Not stepping, so replacing the core's callback cannot pull it from under itself.
        WorldData* data = &world;
        guard(L, "World:step", [&] {
            if (wanted)
                data->world.setPreSolve([data](Collision& c) { return trampoline(*data, c); });
            else
                data->world.setPreSolve({});
        });
        world.preSolveInstalled = wanted;
    }
}

void registerEventMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kEventMethods, 0);
    lua_pop(L, 1);
}

} // namespace jostle::lua
