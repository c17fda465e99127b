// The way in to a World's state for the parts of the library that live outside world.cpp
// (queries, tile maps): World keeps its state private, and befriends this alone.
#pragma once

#include "jostle/world.hpp"
#include "range_check.hpp"
#include "world_state.hpp"

#include <cmath>
#include <string>

namespace jostle {

struct WorldAccess {
    static WorldState& state(World& world) { return *world.state_; }
    static const WorldState& state(const World& world) { return *world.state_; }
};

// --- Argument checks shared by every API function: misuse throws jostle::Error --------

/// Throws jostle::Error("function: message").
[[noreturn]] inline void fail(const char* function, const std::string& message) {
    throw Error(std::string(function) + ": " + message);
}

/// A number given to the API: finite, of magnitude <= kMaxMagnitude (math.hpp).
inline void requireFinite(const char* function, const char* what, float value) {
    if (const char* problem = rangeProblem(value))
        fail(function, std::string(what) + " " + problem);
}

inline void requireFinite(const char* function, const char* what, Vec2 value) {
    if (const char* problem = rangeProblem(value))
        fail(function, std::string(what) + " " + problem);
}

/// A size, density, mass or dt: in [kMinMagnitude, kMaxMagnitude] (math.hpp).
inline void requireSize(const char* function, const char* what, float value) {
    requireFinite(function, what, value);
    if (value <= 0.0f)
        fail(function, std::string(what) + " must be > 0");
    if (value < kMinMagnitude)
        fail(function, std::string(what) + " must be >= 1e-9");
}

/// The live body `id` names, or jostle::Error (null, stale or foreign handle).
inline Body& lookUp(WorldState& world, BodyId id, const char* function) {
    if (std::optional<std::string> problem =
            handleProblem(world.slots, world.serial, id, "BodyId", "body"))
        fail(function, *problem);
    return world.slots[id.index];
}

inline const Body& lookUp(const WorldState& world, BodyId id, const char* function) {
    return lookUp(const_cast<WorldState&>(world), id, function);
}

/// Every function that changes the world checks this first: never from move()'s filter,
/// whose sweep goes on through the world as it was.
inline void requireChangeable(const WorldState& world, const char* function) {
    if (world.moveUnderWay)
        fail(function, "called from move()'s filter (the world cannot change until the move "
                       "is done)");
    if (world.drawing)
        fail(function, "called from a DebugDraw function (the world cannot change until "
                       "debugDraw is done)");
}

/// The live body `id` names, for a function that changes it.
inline Body& lookUpToChange(WorldState& world, BodyId id, const char* function) {
    requireChangeable(world, function);
    return lookUp(world, id, function);
}

} // namespace jostle
