// Queries: world:queryPoint, queryBox, queryRect, rayCast, rayCastAll, boxCast,
// moveAndSlide. Each takes an optional filter table last:
// {mask = , category = , includeSensors = , ignore = body}.
#include "binding.hpp"

namespace jostle::lua {

namespace {

/// The QueryFilter of the table at `index` (none or nil: the defaults).
QueryFilter readFilter(lua_State* L, int index, const WorldData& world, const char* where) {
    QueryFilter filter;
    if (lua_isnoneornil(L, index))
        return filter;
    if (lua_type(L, index) != LUA_TTABLE)
        raise(L, where, "filter: expected a table, got %s", typeName(L, index));
    const Fields fields(L, index, where, "filter.");
    static constexpr const char* kNames[] = {"mask", "category", "includeSensors", "ignore",
                                             nullptr};
    fields.allowOnly(kNames);
    fields.bits("mask", filter.mask);
    fields.bits("category", filter.category);
    fields.boolean("includeSensors", filter.includeSensors);
    fields.push("ignore");
    if (!lua_isnil(L, -1))
        filter.ignore = checkBodyArgument(L, -1, world, where, "filter.ignore");
    lua_pop(L, 1);
    return filter;
}

/// Pushes world.ids as an array of bodies.
int pushIds(lua_State* L, WorldHandle& handle) {
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(handle.data->ids.size()), 0);
    // Index by index, checking the size each time: creating userdata may run a
    // finalizer, and a finalizer is Lua code that might query this very world.
    for (std::size_t i = 0; handle.data && i < handle.data->ids.size(); ++i) {
        pushBody(L, env, &handle, handle.data->ids[i]);
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    return 1;
}

void requireHalf(lua_State* L, const char* where, Vec2 half, bool positive) {
    if (positive ? !(half.x > 0.0f) : !(half.x >= 0.0f))
        raise(L, where, positive ? "hw: must be > 0" : "hw: must be >= 0");
    if (positive ? !(half.y > 0.0f) : !(half.y >= 0.0f))
        raise(L, where, positive ? "hh: must be > 0" : "hh: must be >= 0");
}

int worldQueryPoint(lua_State* L) {
    const char* where = "World:queryPoint";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Vec2 point = checkVec2(L, 2, where, "x", "y");
    const QueryFilter filter = readFilter(L, 4, *handle.data, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] { queryPoint(world.world, point, filter, world.ids); });
    return pushIds(L, handle);
}

int worldQueryBox(lua_State* L) {
    const char* where = "World:queryBox";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Vec2 centre = checkVec2(L, 2, where, "x", "y");
    const Vec2 half = checkVec2(L, 4, where, "hw", "hh");
    requireHalf(L, where, half, false);
    const QueryFilter filter = readFilter(L, 6, *handle.data, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] { queryBox(world.world, centre, half, filter, world.ids); });
    return pushIds(L, handle);
}

int worldQueryRect(lua_State* L) {
    const char* where = "World:queryRect";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Vec2 min = checkVec2(L, 2, where, "x1", "y1");
    const Vec2 max = checkVec2(L, 4, where, "x2", "y2");
    if (!(min.x <= max.x && min.y <= max.y))
        raise(L, where, "x1, y1 must be <= x2, y2 (the top-left corner first)");
    const QueryFilter filter = readFilter(L, 6, *handle.data, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] { queryRect(world.world, min, max, filter, world.ids); });
    return pushIds(L, handle);
}

/// The arguments of rayCast and rayCastAll: x1, y1, x2, y2 [, filter].
struct Segment {
    Vec2 from;
    Vec2 to;
    QueryFilter filter;
};

Segment readSegment(lua_State* L, const WorldData& world, const char* where) {
    const Vec2 from = checkVec2(L, 2, where, "x1", "y1");
    const Vec2 to = checkVec2(L, 4, where, "x2", "y2");
    return {from, to, readFilter(L, 6, world, where)};
}

/// The arguments of boxCast and moveAndSlide: x, y, hw, hh, dx, dy [, filter].
struct Sweep {
    Vec2 centre;
    Vec2 half;
    Vec2 translation;
    QueryFilter filter;
};

Sweep readSweep(lua_State* L, const WorldData& world, const char* where) {
    const Vec2 centre = checkVec2(L, 2, where, "x", "y");
    const Vec2 half = checkVec2(L, 4, where, "hw", "hh");
    requireHalf(L, where, half, true);
    const Vec2 translation = checkVec2(L, 6, where, "dx", "dy");
    return {centre, half, translation, readFilter(L, 8, world, where)};
}

/// Returns body, x, y, nx, ny, fraction for the hit that `cast` finds (an optional of
/// RayHit or BoxCastHit; `place` picks its point), or nil.
template <class Cast, class Place>
int pushFirstHit(lua_State* L, WorldHandle& handle, const char* where, Cast cast, Place place) {
    using Hit = typename decltype(cast())::value_type;
    bool found = false;
    Hit hit;
    guard(L, where, [&] {
        if (const auto result = cast()) {
            found = true;
            hit = *result;
        }
    });
    if (!found) {
        lua_pushnil(L);
        return 1;
    }
    pushUserValue(L, 1);
    pushBody(L, -1, &handle, hit.body);
    lua_remove(L, -2);
    const Vec2 point = place(hit);
    const float numbers[] = {point.x, point.y, hit.normal.x, hit.normal.y, hit.fraction};
    for (float number : numbers)
        lua_pushnumber(L, static_cast<lua_Number>(number));
    return 6;
}

/// body, x, y, nx, ny, fraction of the first body on the segment, or nil.
int worldRayCast(lua_State* L) {
    const char* where = "World:rayCast";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Segment ray = readSegment(L, *handle.data, where);
    return pushFirstHit(
        L, handle, where, [&] { return rayCast(handle.data->world, ray.from, ray.to, ray.filter); },
        [](const RayHit& hit) { return hit.point; });
}

/// An array of {body = , x = , y = , nx = , ny = , fraction = }, nearest first.
int worldRayCastAll(lua_State* L) {
    const char* where = "World:rayCastAll";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Segment ray = readSegment(L, *handle.data, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] { rayCastAll(world.world, ray.from, ray.to, ray.filter, world.rayHits); });

    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(world.rayHits.size()), 0);
    for (std::size_t i = 0; handle.data && i < handle.data->rayHits.size(); ++i) {
        const RayHit hit = handle.data->rayHits[i];
        lua_createtable(L, 0, 6);
        pushBody(L, env, &handle, hit.body);
        lua_setfield(L, -2, "body");
        const struct {
            const char* name;
            float value;
        } numbers[] = {{"x", hit.point.x},
                       {"y", hit.point.y},
                       {"nx", hit.normal.x},
                       {"ny", hit.normal.y},
                       {"fraction", hit.fraction}};
        for (const auto& number : numbers) {
            lua_pushnumber(L, static_cast<lua_Number>(number.value));
            lua_setfield(L, -2, number.name);
        }
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    return 1;
}

/// body, x, y, nx, ny, fraction or nil; x, y is where the box's centre stops.
int worldBoxCast(lua_State* L) {
    const char* where = "World:boxCast";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Sweep sweep = readSweep(L, *handle.data, where);
    return pushFirstHit(
        L, handle, where,
        [&] {
            return boxCast(handle.data->world, sweep.centre, sweep.half, sweep.translation,
                           sweep.filter);
        },
        [](const BoxCastHit& hit) { return hit.centre; });
}

/// x, y, hits: where the box ends up, and an array of {body = , nx = , ny = }.
int worldMoveAndSlide(lua_State* L) {
    const char* where = "World:moveAndSlide";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Sweep sweep = readSweep(L, *handle.data, where);
    WorldData& world = *handle.data;
    guard(L, where, [&] {
        // Into the kept result, so that its hits' memory serves call after call.
        MoveResult result =
            moveAndSlide(world.world, sweep.centre, sweep.half, sweep.translation, sweep.filter);
        world.moved.centre = result.centre;
        world.moved.hits.swap(result.hits);
    });

    const Vec2 end = world.moved.centre;
    lua_pushnumber(L, static_cast<lua_Number>(end.x));
    lua_pushnumber(L, static_cast<lua_Number>(end.y));
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(world.moved.hits.size()), 0);
    for (std::size_t i = 0; handle.data && i < handle.data->moved.hits.size(); ++i) {
        const MoveHit hit = handle.data->moved.hits[i];
        lua_createtable(L, 0, 3);
        pushBody(L, env, &handle, hit.body);
        lua_setfield(L, -2, "body");
        lua_pushnumber(L, static_cast<lua_Number>(hit.normal.x));
        lua_setfield(L, -2, "nx");
        lua_pushnumber(L, static_cast<lua_Number>(hit.normal.y));
        lua_setfield(L, -2, "ny");
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    lua_remove(L, env);
    return 3;
}

constexpr luaL_Reg kQueryMethods[] = {
    {"queryPoint", worldQueryPoint},     {"queryBox", worldQueryBox},
    {"queryRect", worldQueryRect},       {"rayCast", worldRayCast},
    {"rayCastAll", worldRayCastAll},     {"boxCast", worldBoxCast},
    {"moveAndSlide", worldMoveAndSlide}, {nullptr, nullptr},
};

} // namespace

void registerQueryMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kQueryMethods, 0);
    lua_pop(L, 1);
}

} // namespace jostle::lua
