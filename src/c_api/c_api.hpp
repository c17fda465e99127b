// The C API's internals, shared by src/c_api/*.cpp: the structs behind the opaque C
// handles and the rules of using them. Errors are in misuse.hpp, conversions between C and
// C++ types in conversions.hpp.
#pragma once

#include "conversions.hpp"
#include "jostle/fixed_step.hpp"
#include "jostle/jostle.h"
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

/// A C world: the C++ world and what the C layer keeps beside it.
struct jostle_world {
    explicit jostle_world(const jostle::WorldDef& def) : world(def) {}

    jostle::World world;
    jostle_pre_solve_fn preSolve = nullptr;
    void* preSolveContext = nullptr;
    /// True while jostle_world_step runs, so callbacks can be refused what would pull the
    /// world out from under the step.
    bool stepping = false;
    // The last step's events in C layout. Converted once, after each step, so that the
    // getters only read (and may run on several threads at once, as C++ getters may).
    std::vector<jostle_contact_event> contactBegins;
    std::vector<jostle_contact_event> contactEnds;
    std::vector<jostle_sensor_event> sensorBegins;
    std::vector<jostle_sensor_event> sensorEnds;
    std::vector<jostle_crush_event> crushBegins;
    std::vector<jostle_crush_event> crushEnds;
    /// True while jostle_body_move runs: its filter may read the world, not change it.
    bool moving = false;
    /// The collisions of the last jostle_body_move, which its result points into.
    std::vector<jostle_move_collision> moveCollisions;
};

struct jostle_fixed_step {
    jostle::FixedStep clock;
};

namespace jostle::c_api {

// --- Handles ----------------------------------------------------------------------------

/// The world of a function that may change it: never from a move's filter, whose sweep
/// would go on through a world changed under it.
inline jostle_world& worldOf(jostle_world* world) {
    jostle_world& w = required(world, "world");
    if (w.moving)
        misuse("called from a filter during jostle_body_move (the world may not change during "
               "a move)");
    return w;
}
inline const jostle_world& worldOf(const jostle_world* world) {
    return required(world, "world");
}

/// Sets a flag of the C world (stepping, moving) while it lives, and clears it
/// however the scope ends.
class FlagScope {
public:
    explicit FlagScope(bool& flag) : flag_(flag) { flag_ = true; }
    ~FlagScope() { flag_ = false; }
    FlagScope(const FlagScope&) = delete;
    FlagScope& operator=(const FlagScope&) = delete;

private:
    bool& flag_;
};

/// Refuses what a callback may not do during jostle_world_step: step, or change or read
/// the world as a whole (it is half stepped).
inline void requireOutsideStep(const jostle_world& w) {
    if (w.stepping)
        misuse("called from a callback during jostle_world_step");
}

/// For the functions that change the world as a whole, which a callback may not call.
inline jostle_world& outsideStep(jostle_world* world) {
    jostle_world& w = worldOf(world);
    requireOutsideStep(w);
    return w;
}
/// For the functions that read the world as a whole (snapshots, the state hash), which a
/// callback may not call either.
inline const jostle_world& outsideStep(const jostle_world* world) {
    const jostle_world& w = worldOf(world);
    requireOutsideStep(w);
    return w;
}

// --- Worlds (world.cpp) and events (events.cpp) ------------------------------------------

/// Steps the world (the checks and bookkeeping of jostle_world_step); throws on misuse.
void stepWorld(jostle_world& world, float dt);

/// Copies the C++ world's event arrays into the C world's, after a step or whatever else
/// changed them.
void publishEvents(jostle_world& world);

} // namespace jostle::c_api
