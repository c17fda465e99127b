// World: construction, the world's settings, the step entry point and the events a step
// leaves. Its bodies are in world_bodies.cpp.
#include "world_access.hpp"

#include "classic/step.hpp"
#include "integrate.hpp"
#include "physical/sleep.hpp"
#include "physical/step.hpp"
#include "stopwatch.hpp"
#include "tasks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <utility>

namespace jostle {

namespace {

/// Ends a step however it ends (a callback may throw): the world is steppable again
/// and the slots destroyed meanwhile become reusable.
struct StepScope {
    WorldState& world;
    explicit StepScope(WorldState& w) : world(w) { world.stepping = true; }
    ~StepScope() {
        world.stepping = false;
        world.freeSlots.insert(world.freeSlots.end(), world.pendingFree.begin(),
                               world.pendingFree.end());
        world.pendingFree.clear();
    }
    StepScope(const StepScope&) = delete;
    StepScope& operator=(const StepScope&) = delete;
};

void wakeAll(WorldState& world) {
    for (BodyId id : world.order.live())
        wakeIsland(world, id.index);
}

} // namespace

WorldSerials& worldSerials() {
    static WorldSerials serials;
    return serials;
}

// --- Construction ----------------------------------------------------------------------

World::World(const WorldDef& def) : state_(std::make_unique<WorldState>()) {
    if (auto problem = checkWorldDef(def))
        fail("World", "WorldDef." + problem->field + ": " + problem->problem);
    state_->def = def;
    const std::optional<std::uint32_t> serial = worldSerials().take();
    if (!serial)
        fail("World", "this process has made 4294967295 worlds, as many as handles can tell "
                      "apart (BodyId::world)");
    state_->serial = *serial;
    state_->tasks = std::make_unique<TaskRunner>(def.tasks);
}

namespace {

// A world destroyed or overwritten from inside its own step would pull its state from
// under the solver; a destructor cannot throw, so this stops the program with a message.
void refuseWhileStepping(const std::unique_ptr<WorldState>& state, const char* what) {
    if (state && (state->stepping || state->moveUnderWay)) {
        std::fprintf(stderr, "jostle: %s from a callback during %s: stopping\n", what,
                     state->moveUnderWay ? "move()" : "step()");
        std::abort();
    }
}

// The world's settings change only between steps: the step reads them throughout.
void requireNotStepping(const WorldState& w, const char* function) {
    requireChangeable(w, function);
    if (w.stepping)
        fail(function, "called from a callback during step(): change the world's settings "
                       "after step() returns");
}

} // namespace

World::~World() {
    refuseWhileStepping(state_, "World destroyed");
}
World::World(World&&) noexcept = default;
World& World::operator=(World&& other) noexcept {
    refuseWhileStepping(state_, "World overwritten");
    state_ = std::move(other.state_);
    return *this;
}

// --- Events ----------------------------------------------------------------------------

std::span<const ContactEvent> World::contactBegins() const {
    return state_->events.begins;
}

std::span<const ContactEvent> World::contactEnds() const {
    return state_->events.ends;
}

std::span<const SensorEvent> World::sensorBegins() const {
    return state_->events.sensorBegins;
}

std::span<const SensorEvent> World::sensorEnds() const {
    return state_->events.sensorEnds;
}

std::span<const CrushEvent> World::crushBegins() const {
    return state_->events.crushBegins;
}

std::span<const CrushEvent> World::crushEnds() const {
    return state_->events.crushEnds;
}

std::uint64_t World::pairsLeftOut() const {
    return state_->pairsLeftOut;
}

void World::contacts(BodyId id, std::vector<ContactInfo>& out) const {
    lookUp(*state_, id, "contacts");
    out.clear();
    state_->forEachContactOf(id, [&](BodyId other, Vec2 normal, const TouchRecord& r) {
        out.push_back({other, normal, pointOf(*state_, r), r.impulse});
    });
}

std::vector<ContactInfo> World::contacts(BodyId id) const {
    std::vector<ContactInfo> out;
    contacts(id, out);
    return out;
}

bool World::isTouching(BodyId a, BodyId b) const {
    lookUp(*state_, a, "isTouching");
    lookUp(*state_, b, "isTouching");
    bool touching = false;
    state_->forEachContactOf(
        a, [&](BodyId other, Vec2, const TouchRecord&) { touching = touching || other == b; });
    return touching;
}

Touching World::touching(BodyId id) const {
    lookUp(*state_, id, "touching");
    const std::vector<std::uint8_t>& flags = state_->events.touching;
    const std::uint8_t bits = id.index < flags.size() ? flags[id.index] : 0;
    return {(bits & kFloor) != 0, (bits & kCeiling) != 0, (bits & kWallLeft) != 0,
            (bits & kWallRight) != 0};
}

// --- World settings and stepping -------------------------------------------------------

const StepProfile& World::profile() const {
    return state_->profile;
}

void World::step(float dt) {
    WorldState& w = *state_;
    Stopwatch stopwatch;
    requireChangeable(w, "step");
    if (w.stepping)
        fail("step", "called from a callback during step()");
    if (!std::isfinite(dt) || dt <= 0.0f)
        fail("step", "dt must be a finite number > 0");
    if (dt < kMinMagnitude || dt > kMaxMagnitude)
        fail("step", "dt must be in [1e-9, 1e9] (math.hpp)");

    StepScope scope(w);
    w.tasks->beginStep();
    w.profile = {};
    w.pairsLeftOut = 0; // the physical model's broadphase counts them
    // A sleeping body keeps the separation of its last awake step: what held it up
    // still does ("grounded" stays true while it sleeps on the ground).
    for (BodyId id : w.movers())
        if (!w.slots[id.index].asleep)
            w.slots[id.index].separation = {};
    try {
        if (w.def.solver == Solver::Classic)
            stepClassic(w, dt);
        else
            stepPhysical(w, dt);
    } catch (...) {
        // An exception the step did not expect (out of memory) ends it where it got to:
        // bodies already moved still stop at the edge of the world.
        keepInsideTheWorld(w);
        w.preSolveThrew = nullptr;
        throw;
    }
    keepInsideTheWorld(w);
    w.profile.step = stopwatch.lap();
    w.tasks->endStep(w.profile.step);
    if (std::optional<std::string> broken = w.tasks->takeBrokenContract())
        fail("step", *broken);
    if (w.preSolveThrew) // the step is whole: what the callback threw comes out now
        std::rethrow_exception(std::exchange(w.preSolveThrew, nullptr));
}

Vec2 World::gravity() const {
    return state_->def.gravity;
}

void World::setGravity(Vec2 gravity) {
    requireNotStepping(*state_, "setGravity");
    requireFinite("setGravity", "gravity", gravity);
    state_->def.gravity = gravity;
    wakeAll(*state_);
}

float World::maxVelocity() const {
    return state_->def.maxVelocity;
}

void World::setMaxVelocity(float maxVelocity) {
    requireNotStepping(*state_, "setMaxVelocity");
    if (std::isnan(maxVelocity) || maxVelocity <= 0.0f)
        fail("setMaxVelocity", "maxVelocity must be > 0 (infinity for no clamp)");
    state_->def.maxVelocity = maxVelocity;
}

Solver World::solver() const {
    return state_->def.solver;
}

void World::setSolver(Solver solver) {
    requireNotStepping(*state_, "setSolver");
    if (solver != Solver::Classic && solver != Solver::Physical)
        fail("setSolver", "solver must be classic or physical");
    if (solver == Solver::Classic && state_->shapedBodies > 0)
        fail("setSolver", "the classic model has sharp boxes only, and this world has "
                          "rounded bodies, ramps or segments");
    if (solver == Solver::Classic && state_->tileMaps.hasRampTiles())
        fail("setSolver", "the classic model has sharp boxes only, and a tile map of this world "
                          "has ramp tiles");
    state_->def.solver = solver;
    state_->contactCache.clear();
    state_->events.clear();
    wakeAll(*state_); // the classic model has no sleep
}

bool World::sleeping() const {
    return state_->def.sleeping;
}

int World::workers() const {
    return state_->def.tasks.workers;
}

void World::setSleeping(bool enabled) {
    requireNotStepping(*state_, "setSleeping");
    state_->def.sleeping = enabled;
    if (!enabled)
        wakeAll(*state_);
}

ClassicOptions World::classicOptions() const {
    return state_->def.classic;
}

void World::setClassicOptions(ClassicOptions options) {
    requireNotStepping(*state_, "setClassicOptions");
    state_->def.classic = options;
}

PhysicalOptions World::physicalOptions() const {
    return state_->def.physical;
}

void World::setPhysicalOptions(PhysicalOptions options) {
    requireNotStepping(*state_, "setPhysicalOptions");
    WorldDef def = state_->def;
    def.physical = options;
    if (auto problem = checkWorldDef(def))
        fail("setPhysicalOptions", problem->field + ": " + problem->problem);
    state_->def.physical = options;
}

void World::setPreSolve(PreSolveFn callback) {
    requireNotStepping(*state_, "setPreSolve");
    state_->preSolve = std::move(callback);
}

} // namespace jostle
