// Queries: world:queryPoint, queryBox, queryRect, rayCast, rayCastAll, boxCast,
// roundedBoxCast, circleCast, moveAndSlide, roundedMoveAndSlide. Each takes an optional filter
// table last: {mask = , category = , includeSensors = , ignore = body}. And world:move, bump.lua's
// move, whose filter is a function called from inside the core's sweep, the way the pre-solve
// callback is (events.cpp): through a protected runner, its error thrown through the core as
// CallbackFailed and raised once out of it.
#include "binding.hpp"

#include <cstring>
#include <initializer_list>

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

/// The arguments of a sweep: boxCast and moveAndSlide's x, y, hw, hh, dx, dy [, filter];
/// the rounded ones' x, y, hw, hh, r, dx, dy [, filter]; circleCast's x, y, r, dx, dy
/// [, filter].
struct Sweep {
    Vec2 centre;
    Vec2 half;
    float radius = 0.0f;
    Vec2 translation;
    QueryFilter filter;
};

enum class SweptShape { Box, Rounded, Circle };

Sweep readSweep(lua_State* L, const WorldData& world, const char* where, SweptShape shape) {
    Sweep sweep;
    sweep.centre = checkVec2(L, 2, where, "x", "y");
    int next = 4;
    if (shape != SweptShape::Circle) {
        sweep.half = checkVec2(L, next, where, "hw", "hh");
        requireHalf(L, where, sweep.half, true);
        next += 2;
    }
    if (shape != SweptShape::Box) {
        sweep.radius = checkNumber(L, next++, where, "r");
        if (shape == SweptShape::Circle) {
            if (!(sweep.radius > 0.0f))
                raise(L, where, "r: must be > 0");
            sweep.half = {sweep.radius, sweep.radius};
        }
    }
    sweep.translation = checkVec2(L, next, where, "dx", "dy");
    sweep.filter = readFilter(L, next + 2, world, where);
    return sweep;
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
    pushArray(
        L, handle, [](const WorldData& w) -> const auto& { return w.rayHits; },
        [&](const RayHit& hit) {
            pushBodyRecord(L, env, &handle, "body", hit.body,
                           {{"x", hit.point.x},
                            {"y", hit.point.y},
                            {"nx", hit.normal.x},
                            {"ny", hit.normal.y},
                            {"fraction", hit.fraction}});
        });
    return 1;
}

/// body, x, y, nx, ny, fraction or nil; x, y is where the box's centre stops.
int castSwept(lua_State* L, const char* where, SweptShape shape) {
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Sweep sweep = readSweep(L, *handle.data, where, shape);
    return pushFirstHit(
        L, handle, where,
        [&] {
            return boxCast(handle.data->world, sweep.centre, sweep.half, sweep.radius,
                           sweep.translation, sweep.filter);
        },
        [](const BoxCastHit& hit) { return hit.centre; });
}

int worldBoxCast(lua_State* L) {
    return castSwept(L, "World:boxCast", SweptShape::Box);
}
int worldRoundedBoxCast(lua_State* L) {
    return castSwept(L, "World:roundedBoxCast", SweptShape::Rounded);
}
int worldCircleCast(lua_State* L) {
    return castSwept(L, "World:circleCast", SweptShape::Circle);
}

/// Pushes x, y (`end`) and the array of what a move met (pushArray's), for moveAndSlide
/// and move: `push(env, element)` pushes each, `env` the world's user value table.
template <class Elements, class Push>
int pushMoved(lua_State* L, WorldHandle& handle, Vec2 end, Elements elements, Push push) {
    lua_pushnumber(L, static_cast<lua_Number>(end.x));
    lua_pushnumber(L, static_cast<lua_Number>(end.y));
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    pushArray(L, handle, elements, [&](const auto& element) { push(env, element); });
    lua_remove(L, env);
    return 3;
}

/// x, y, hits: where the box ends up, and an array of {body = , nx = , ny = }.
int moveAndSlideSwept(lua_State* L, const char* where, SweptShape shape) {
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    const Sweep sweep = readSweep(L, *handle.data, where, shape);
    WorldData& world = *handle.data;
    guard(L, where, [&] {
        // Into the kept result, so that its hits' memory serves call after call.
        MoveResult result = moveAndSlide(world.world, sweep.centre, sweep.half, sweep.radius,
                                         sweep.translation, sweep.filter);
        world.moved.centre = result.centre;
        world.moved.hits.swap(result.hits);
    });

    return pushMoved(
        L, handle, world.moved.centre,
        [](const WorldData& w) -> const auto& { return w.moved.hits; },
        [&](int env, const MoveHit& hit) {
            pushBodyRecord(L, env, &handle, "body", hit.body,
                           {{"nx", hit.normal.x}, {"ny", hit.normal.y}});
        });
}

int worldMoveAndSlide(lua_State* L) {
    return moveAndSlideSwept(L, "World:moveAndSlide", SweptShape::Box);
}
int worldRoundedMoveAndSlide(lua_State* L) {
    return moveAndSlideSwept(L, "World:roundedMoveAndSlide", SweptShape::Rounded);
}

// --- world:move ---------------------------------------------------------------------------

/// The filter's answers, in the order of Response (Ignore is nil or false).
constexpr const char* kResponseNames[] = {"slide", "touch", "cross", "bounce", nullptr};
static_assert(static_cast<int>(Response::Slide) == 0 && static_cast<int>(Response::Touch) == 1 &&
              static_cast<int>(Response::Cross) == 2 && static_cast<int>(Response::Bounce) == 3 &&
              static_cast<int>(Response::Ignore) == 4);

constexpr const char* kFilterRule =
    "expected \"slide\", \"touch\", \"cross\", \"bounce\", or nil or false to ignore";

/// Called (protected) by the filter's trampoline with the other body's BodyId, the World
/// userdata and the filter: returns the Response of filter(other), as a number.
int runMoveFilter(lua_State* L) {
    const BodyId other = *static_cast<const BodyId*>(lua_touserdata(L, 1));
    auto* world = static_cast<WorldHandle*>(lua_touserdata(L, 2));
    lua_pushvalue(L, 3);
    pushUserValue(L, 2);
    pushBody(L, -1, world, other);
    lua_remove(L, -2);
    lua_call(L, 1, 1);
    // nil or false: Ignore, as bump.lua's filters say it.
    if (lua_isnil(L, -1) || (lua_type(L, -1) == LUA_TBOOLEAN && !lua_toboolean(L, -1))) {
        pushWhole(L, static_cast<int>(Response::Ignore));
        return 1;
    }
    if (lua_type(L, -1) == LUA_TSTRING) {
        const char* given = lua_tostring(L, -1);
        for (int i = 0; kResponseNames[i]; ++i)
            if (std::strcmp(given, kResponseNames[i]) == 0) {
                pushWhole(L, i);
                return 1;
            }
        raise(L, "World:move", "filter returned \"%s\": %s", given, kFilterRule);
    }
    raise(L, "World:move", "filter returned %s: %s",
          lua_type(L, -1) == LUA_TBOOLEAN ? "true" : typeName(L, -1), kFilterRule);
}

/// The C++ filter: runs the Lua one through runMoveFilter, protected, with what it needs
/// at these stack slots.
struct FilterSlots {
    lua_State* L;
    int runner; ///< runMoveFilter
    int world;  ///< the World userdata
    int filter; ///< the Lua function
};

Response filterTrampoline(const FilterSlots& slots, BodyId other) {
    lua_State* L = slots.L;
    callBack(L, slots.runner, &other, slots.world, slots.filter);
    const auto response = static_cast<Response>(lua_tointeger(L, -1));
    lua_pop(L, 1);
    return response;
}

/// Sets t[name] = {fields...} for the table t on top.
void setRecord(lua_State* L, const char* name, std::initializer_list<NamedNumber> fields) {
    lua_createtable(L, 0, static_cast<int>(fields.size()));
    setNumbers(L, fields);
    lua_setfield(L, -2, name);
}

/// One of move's collisions as bump.lua names its fields: {item = , other = , type = ,
/// normal = {x, y}, touch = {x, y} (the centre there), ti = , otherRect = {x, y, w, h}}.
void pushCollision(lua_State* L, int env, WorldHandle* handle, int item, const MoveCollision& c) {
    lua_createtable(L, 0, 7);
    lua_pushvalue(L, item);
    lua_setfield(L, -2, "item");
    pushBody(L, env, handle, c.other);
    lua_setfield(L, -2, "other");
    lua_pushstring(L, kResponseNames[static_cast<int>(c.response)]);
    lua_setfield(L, -2, "type");
    setRecord(L, "normal", {{"x", c.normal.x}, {"y", c.normal.y}});
    setRecord(L, "touch", {{"x", c.touch.x}, {"y", c.touch.y}});
    setNumbers(L, {{"ti", c.time}});
    const Vec2 corner = c.otherCentre - c.otherHalf;
    const Vec2 size = c.otherHalf * 2.0f;
    setRecord(L, "otherRect", {{"x", corner.x}, {"y", corner.y}, {"w", size.x}, {"h", size.y}});
}

/// world:move(body, dx, dy [, filter]) -> x, y, cols, len: moves the body by (dx, dy)
/// the way bump.lua's world:move does; filter(other) answers "slide", "touch", "cross",
/// "bounce", or nil or false to go through unreported.
int worldMove(lua_State* L) {
    const char* where = "World:move";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    WorldData& world = *handle.data;
    requireChangeable(L, world, where);
    const BodyId id = checkBodyArgument(L, 2, world, where, "body");
    const Vec2 delta = checkVec2(L, 3, where, "dx", "dy");
    const bool filtered = !lua_isnoneornil(L, 5);
    if (filtered && lua_type(L, 5) != LUA_TFUNCTION)
        raise(L, where, "filter: expected a function or nil, got %s", typeName(L, 5));
    lua_settop(L, 5);
    luaL_checkstack(L, 8, "jostle: World:move");
    lua_pushcfunction(L, runMoveFilter);
    const FilterSlots slots{L, lua_gettop(L), 1, 5};

    // The filter may read the world but not change it: the core sweeps through it.
    world.moving = true;
    guardCallbacks(
        L, where,
        [&] {
            MoveFilter filter;
            if (filtered)
                filter = [&slots](BodyId other) { return filterTrampoline(slots, other); };
            // Into the kept outcome, so that its memory serves call after call.
            MoveOutcome outcome = move(world.world, id, delta, filter);
            world.outcome.centre = outcome.centre;
            world.outcome.collisions.swap(outcome.collisions);
        },
        [&] { world.moving = false; });

    pushMoved(
        L, handle, world.outcome.centre,
        [](const WorldData& w) -> const auto& { return w.outcome.collisions; },
        [&](int env, const MoveCollision& c) { pushCollision(L, env, &handle, 2, c); });
    pushWhole(L, static_cast<std::int64_t>(rawLength(L, -1)));
    return 4;
}

constexpr luaL_Reg kQueryMethods[] = {
    {"queryPoint", worldQueryPoint},
    {"queryBox", worldQueryBox},
    {"queryRect", worldQueryRect},
    {"rayCast", worldRayCast},
    {"rayCastAll", worldRayCastAll},
    {"boxCast", worldBoxCast},
    {"roundedBoxCast", worldRoundedBoxCast},
    {"circleCast", worldCircleCast},
    {"moveAndSlide", worldMoveAndSlide},
    {"roundedMoveAndSlide", worldRoundedMoveAndSlide},
    {"move", worldMove},
    {nullptr, nullptr},
};

} // namespace

void registerQueryMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kQueryMethods, 0);
    lua_pop(L, 1);
}

} // namespace jostle::lua
