// The C API's worlds: creation, stepping, settings, the body list and the pre-solve
// callback.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

/// Calls the C callback with a C copy of the pair, and takes back what it may change.
bool callPreSolve(jostle_world& w, Collision& collision) {
    jostle_collision c = toC(collision);
    const bool keep = w.preSolve(&c, w.preSolveContext);
    collision.bounce = c.bounce;
    collision.friction = c.friction;
    return keep;
}

} // namespace

namespace jostle::c_api {

void stepWorld(jostle_world& w, float dt) {
    requireOutsideStep(w);
    {
        const FlagScope scope(w.stepping);
        w.world.step(dt);
    }
    publishEvents(w);
}

} // namespace jostle::c_api

extern "C" {

jostle_world_def jostle_default_world_def(void) {
    return toC(WorldDef{});
}

jostle_world* jostle_world_create(const jostle_world_def* def) {
    return guard<jostle_world*>(__func__, nullptr,
                                [&] { return new jostle_world(toCpp(required(def, "def"))); });
}

bool jostle_world_destroy(jostle_world* world) {
    return guard(__func__, false, [&] {
        if (world == nullptr)
            return true;
        delete &outsideStep(world);
        return true;
    });
}

bool jostle_world_step(jostle_world* world, float dt) {
    return guard(__func__, false, [&] {
        stepWorld(worldOf(world), dt);
        return true;
    });
}

jostle_vec2 jostle_world_get_gravity(const jostle_world* world) {
    return guard(__func__, jostle_vec2{}, [&] { return toC(worldOf(world).world.gravity()); });
}

bool jostle_world_set_gravity(jostle_world* world, jostle_vec2 gravity) {
    return guard(__func__, false, [&] {
        outsideStep(world).world.setGravity(toCpp(gravity));
        return true;
    });
}

float jostle_world_get_max_velocity(const jostle_world* world) {
    return guard(__func__, 0.0f, [&] { return worldOf(world).world.maxVelocity(); });
}

bool jostle_world_set_max_velocity(jostle_world* world, float max_velocity) {
    return guard(__func__, false, [&] {
        outsideStep(world).world.setMaxVelocity(max_velocity);
        return true;
    });
}

jostle_solver jostle_world_get_solver(const jostle_world* world) {
    return guard(__func__, JOSTLE_SOLVER_CLASSIC,
                 [&] { return toC(worldOf(world).world.solver()); });
}

bool jostle_world_set_solver(jostle_world* world, jostle_solver solver) {
    return guard(__func__, false, [&] {
        jostle_world& w = outsideStep(world);
        w.world.setSolver(toCpp(solver));
        publishEvents(w); // the new model starts with none
        return true;
    });
}

bool jostle_world_get_sleeping(const jostle_world* world) {
    return guard(__func__, false, [&] { return worldOf(world).world.sleeping(); });
}

int jostle_world_get_workers(const jostle_world* world) {
    return guard(__func__, 0, [&] { return worldOf(world).world.workers(); });
}

bool jostle_world_set_sleeping(jostle_world* world, bool enabled) {
    return guard(__func__, false, [&] {
        outsideStep(world).world.setSleeping(enabled);
        return true;
    });
}

jostle_classic_options jostle_world_get_classic_options(const jostle_world* world) {
    return guard(__func__, jostle_classic_options{},
                 [&] { return toC(worldOf(world).world.classicOptions()); });
}

bool jostle_world_set_classic_options(jostle_world* world, jostle_classic_options options) {
    return guard(__func__, false, [&] {
        outsideStep(world).world.setClassicOptions(toCpp(options));
        return true;
    });
}

jostle_physical_options jostle_world_get_physical_options(const jostle_world* world) {
    return guard(__func__, jostle_physical_options{},
                 [&] { return toC(worldOf(world).world.physicalOptions()); });
}

bool jostle_world_set_physical_options(jostle_world* world, jostle_physical_options options) {
    return guard(__func__, false, [&] {
        outsideStep(world).world.setPhysicalOptions(toCpp(options));
        return true;
    });
}

int jostle_world_body_count(const jostle_world* world) {
    return guard(__func__, 0, [&] { return countOf(worldOf(world).world.bodyCount()); });
}

int jostle_world_bodies(const jostle_world* world, jostle_body_id* out, int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        checkBuffer(out, capacity);
        return copyOut(w.bodies(), out, capacity);
    });
}

int jostle_world_read_positions(const jostle_world* world, jostle_vec2* out, int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        return readEach(w, out, capacity, [&](std::span<Vec2> read) { w.readPositions(read); });
    });
}

int jostle_world_read_velocities(const jostle_world* world, jostle_vec2* out, int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        return readEach(w, out, capacity, [&](std::span<Vec2> read) { w.readVelocities(read); });
    });
}

int jostle_world_read_half_extents(const jostle_world* world, jostle_vec2* out, int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        return readEach(w, out, capacity, [&](std::span<Vec2> read) { w.readHalfExtents(read); });
    });
}

bool jostle_world_set_pre_solve(jostle_world* world, jostle_pre_solve_fn callback, void* context) {
    return guard(__func__, false, [&] {
        // Refused during a step: the C++ callback running now would be replaced under
        // its own feet.
        jostle_world& w = outsideStep(world);
        PreSolveFn adapter;
        if (callback != nullptr)
            adapter = [&w](Collision& collision) { return callPreSolve(w, collision); };
        w.world.setPreSolve(std::move(adapter));
        w.preSolve = callback;
        w.preSolveContext = context;
        return true;
    });
}

} // extern "C"
