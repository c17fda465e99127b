// jostle.newFixedStep: a fixed time step from variable frame times (fixed_step.hpp).
//
//     local clock = jostle.newFixedStep(1/60)
//     function love.update(frameSeconds) clock:update(world, frameSeconds) end
#include "binding.hpp"

#include <jostle/fixed_step.hpp>

#include <new>

namespace jostle::lua {

namespace {

FixedStep& checkClock(lua_State* L, const char* where) {
    auto* clock = static_cast<FixedStep*>(luaL_testudata(L, 1, kFixedStepType));
    if (!clock)
        raise(L, where,
              "expected a FixedStep as self (call it with a colon: clock:method()), got %s",
              typeName(L, 1));
    return *clock;
}

/// The number of steps to take now for a frame of frameSeconds.
int clockAdvance(lua_State* L) {
    const char* where = "FixedStep:advance";
    FixedStep& clock = checkClock(L, where);
    const float seconds = checkNumber(L, 2, where, "frameSeconds");
    if (!(seconds >= 0.0f))
        raise(L, where, "frameSeconds: must be >= 0");
    int steps = 0;
    guard(L, where, [&] { steps = clock.advance(seconds); });
    pushWhole(L, steps);
    return 1;
}

/// advance(frameSeconds), then world:step(dt) that many times, calling afterStep() (if
/// given) after each: where a game reads the step's events. Returns the number of steps.
/// An error in a step (a pre-solve callback's) or in afterStep is raised at once; the steps
/// left are not taken and their time is lost, as in C++.
int clockUpdate(lua_State* L) {
    const char* where = "FixedStep:update";
    FixedStep& clock = checkClock(L, where);
    checkWorld(L, 2, where);
    const float seconds = checkNumber(L, 3, where, "frameSeconds");
    if (!(seconds >= 0.0f))
        raise(L, where, "frameSeconds: must be >= 0");
    const bool afterStep = !lua_isnoneornil(L, 4);
    if (afterStep && !lua_isfunction(L, 4))
        raise(L, where, "afterStep: expected a function, got %s", typeName(L, 4));
    int steps = 0;
    guard(L, where, [&] { steps = clock.advance(seconds); });
    clock.takeSteps(checkWorld(L, 2, where).world, steps, [&] {
        stepWorld(L, 2, clock.dt(), where);
        if (afterStep) {
            lua_pushvalue(L, 4);
            lua_call(L, 0, 0);
        }
    });
    pushWhole(L, steps);
    return 1;
}

/// x, y: where to draw the body now, between where it was before the last step update
/// took and where it is, by alpha.
int clockGetDrawPosition(lua_State* L) {
    const char* where = "FixedStep:getDrawPosition";
    const FixedStep& clock = checkClock(L, where);
    const WorldData& world = checkWorld(L, 2, where);
    const BodyId body = checkBodyArgument(L, 3, world, where, "body");
    Vec2 at;
    guard(L, where, [&] { at = clock.drawPosition(world.world, body); });
    lua_pushnumber(L, static_cast<lua_Number>(at.x));
    lua_pushnumber(L, static_cast<lua_Number>(at.y));
    return 2;
}

/// {x1, y1, x2, y2, ...}: getDrawPosition of every body, in the order of
/// world:getBodies(), into the table given or a new one.
int clockGetDrawPositions(lua_State* L) {
    const char* where = "FixedStep:getDrawPositions";
    const FixedStep& clock = checkClock(L, where);
    return pushBulkRead(
        L, checkWorldHandle(L, 2, where), 3, where,
        [&](const World& w, std::span<Vec2> out) { clock.readDrawPositions(w, out); });
}

/// Keeps where every body is now, for getDrawPosition: update calls it before the last
/// step it takes; a game stepping the world by hand calls it before the last step of a
/// frame.
int clockRememberPositions(lua_State* L) {
    const char* where = "FixedStep:rememberPositions";
    FixedStep& clock = checkClock(L, where);
    const WorldData& world = checkWorld(L, 2, where);
    guard(L, where, [&] { clock.rememberPositions(world.world); });
    return 0;
}

int clockGetAlpha(lua_State* L) {
    lua_pushnumber(L, static_cast<lua_Number>(checkClock(L, "FixedStep:getAlpha").alpha()));
    return 1;
}

int clockGetDroppedSeconds(lua_State* L) {
    lua_pushnumber(
        L, static_cast<lua_Number>(checkClock(L, "FixedStep:getDroppedSeconds").droppedSeconds()));
    return 1;
}

int clockGetDt(lua_State* L) {
    lua_pushnumber(L, static_cast<lua_Number>(checkClock(L, "FixedStep:getDt").dt()));
    return 1;
}

int clockGetMaxStepsPerFrame(lua_State* L) {
    pushWhole(L, checkClock(L, "FixedStep:getMaxStepsPerFrame").maxStepsPerFrame());
    return 1;
}

int clockReset(lua_State* L) {
    checkClock(L, "FixedStep:reset").reset();
    return 0;
}

int clockGetPendingNanoseconds(lua_State* L) {
    pushWhole(L, checkClock(L, "FixedStep:getPendingNanoseconds").pendingNanoseconds());
    return 1;
}

int clockSetPendingNanoseconds(lua_State* L) {
    const char* where = "FixedStep:setPendingNanoseconds";
    FixedStep& clock = checkClock(L, where);
    // The clock says its own range; whole numbers beyond a double's exact ones are refused.
    const std::int64_t nanoseconds =
        checkWhole(L, 2, where, "nanoseconds", -(std::int64_t{1} << 53), std::int64_t{1} << 53);
    guard(L, where, [&] { clock.setPendingNanoseconds(nanoseconds); });
    return 0;
}

/// FixedStep lives in the userdata itself; its buffers go with it.
int clockGc(lua_State* L) {
    static_cast<FixedStep*>(lua_touserdata(L, 1))->~FixedStep();
    return 0;
}

int clockToString(lua_State* L) {
    const auto* clock = static_cast<const FixedStep*>(lua_touserdata(L, 1));
    lua_pushfstring(L, "jostle.FixedStep (dt %f s)", static_cast<lua_Number>(clock->dt()));
    return 1;
}

constexpr luaL_Reg kClockMethods[] = {
    {"advance", clockAdvance},
    {"update", clockUpdate},
    {"getAlpha", clockGetAlpha},
    {"getDroppedSeconds", clockGetDroppedSeconds},
    {"getDt", clockGetDt},
    {"getMaxStepsPerFrame", clockGetMaxStepsPerFrame},
    {"reset", clockReset},
    {"getPendingNanoseconds", clockGetPendingNanoseconds},
    {"setPendingNanoseconds", clockSetPendingNanoseconds},
    {"getDrawPosition", clockGetDrawPosition},
    {"getDrawPositions", clockGetDrawPositions},
    {"rememberPositions", clockRememberPositions},
    {nullptr, nullptr},
};

} // namespace

/// jostle.newFixedStep([dt [, maxStepsPerFrame]]): dt defaults to 1/60 s, the cap to 8.
int newFixedStep(lua_State* L) {
    const char* where = "jostle.newFixedStep";
    const float dt = optNumber(L, 1, where, "dt", 1.0f / 60.0f);
    if (!(dt >= FixedStep::kMinDt && dt <= FixedStep::kMaxDt))
        raise(L, where, "dt: must be a number of seconds from 1e-6 to 3600");
    int maxSteps = 8;
    if (!lua_isnoneornil(L, 2))
        maxSteps = static_cast<int>(
            checkWhole(L, 2, where, "maxStepsPerFrame", 1, FixedStep::kMaxStepsLimit));
    void* memory = newUserdata(L, sizeof(FixedStep));
    guard(L, where, [&] { new (memory) FixedStep(dt, maxSteps); });
    luaL_getmetatable(L, kFixedStepType);
    lua_setmetatable(L, -2);
    return 1;
}

void openFixedStep(lua_State* L) {
    luaL_newmetatable(L, kFixedStepType);
    lua_createtable(L, 0, 8);
    luaL_setfuncs(L, kClockMethods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, clockToString);
    lua_setfield(L, -2, "__tostring");
    lua_pushcfunction(L, clockGc);
    lua_setfield(L, -2, "__gc");
    lua_pushliteral(L, "jostle.FixedStep");
    lua_setfield(L, -2, "__name");
    lua_pop(L, 1);
}

} // namespace jostle::lua
