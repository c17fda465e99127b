// The determinism tests' busy worlds (test_determinism.cpp), shared with the snapshot
// tests (test_snapshots.cpp): scripted scenes that use most of what the library does, a
// step at a time, hashed bit for bit.
#pragma once

#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "shared/fnv1a.hpp"
#include "tasks.hpp"
#include "world_access.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace jostle::testing {

// A generator of our own, so that the scene does not depend on how a standard library
// maps random bits to floats.
class Lcg {
public:
    std::uint32_t next() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<std::uint32_t>(state_ >> 33);
    }
    /// A float in [lo, hi), a multiple of 1/1024 of the range.
    float range(float lo, float hi) {
        return lo + (hi - lo) * static_cast<float>(next() % 1024) / 1024.0f;
    }

private:
    std::uint64_t state_ = 12345;
};

// FNV-1a over the bits of what the world says about itself.
class Hash : public shared::Fnv1a {
public:
    using Fnv1a::add;
    // The slot alone: a handle's world (its serial number) differs from world to world
    // and with the worlds made before, and nothing in the simulation depends on it or on
    // the generation.
    void add(BodyId id) { add(id.index); }
};

void hashStep(const World& world, Hash& hash) {
    for (BodyId id : world.bodies()) {
        hash.add(id);
        hash.add(world.position(id));
        hash.add(world.velocity(id));
        hash.add(world.separation(id));
        hash.add(static_cast<std::uint32_t>(world.isAwake(id)));
    }
    for (const ContactEvent& e : world.contactBegins()) {
        hash.add(e.a);
        hash.add(e.b);
        hash.add(e.normal);
        hash.add(e.approachSpeed);
    }
    for (const ContactEvent& e : world.contactEnds()) {
        hash.add(e.a);
        hash.add(e.b);
    }
    for (const SensorEvent& e : world.sensorBegins())
        hash.add(e.visitor);
    for (const CrushEvent& e : world.crushBegins())
        hash.add(e.body);
    for (const CrushEvent& e : world.crushEnds())
        hash.add(e.by);
}

/// Destroys a body of `rain` that `random` picks, and forgets it.
inline void destroyOne(World& world, std::vector<BodyId>& rain, Lcg& random) {
    const std::size_t victim = random.next() % rain.size();
    world.destroyBody(rain[victim]);
    rain.erase(rain.begin() + static_cast<std::ptrdiff_t>(victim));
}

/// Turns a lift round: its vertical velocity reversed.
inline void turnRound(World& world, BodyId lift) {
    world.setVelocity(lift, {0, -world.velocity(lift).y});
}

// A container with a pyramid, a tile floor with a one-way ledge, a lift, a sensor and
// boxes of every kind raining in, some destroyed as they go, tiles dug and filled,
// queries asked: most of what the library does, a step at a time.
class BusyWorld {
public:
    explicit BusyWorld(Solver solver, TaskSystem tasks = {}) : world(defOf(solver, tasks)) {
        TileMapDef floorDef;
        floorDef.x = -400.0f;
        floorDef.y = 0.0f;
        floorDef.tile = 20.0f;
        floorDef.rows = {
            "#......................................#", "#......................................#",
            "#....................................###", "########################################"};
        floor_ = createTileMap(world, floorDef);

        world.createBody(
            {.type = BodyType::Static, .x = -200, .y = -150, .hw = 60, .hh = 4, .oneWay = {0, -1}});
        lift_ = world.createBody(
            {.type = BodyType::Kinematic, .x = 200, .y = -40, .hw = 40, .hh = 6, .vy = -30});
        sensor_ = world.createBody(
            {.type = BodyType::Static, .x = 0, .y = -100, .hw = 50, .hh = 50, .sensor = true});
        for (int row = 0; row < 8; ++row)
            for (int i = 0; i <= row; ++i)
                world.createBody({.x = -40.0f + 10.0f * float(i) - 5.0f * float(row),
                                  .y = -90.0f + 10.0f * float(row),
                                  .hw = 5,
                                  .hh = 5,
                                  .friction = 0.6f});
        world.setPreSolve([this](Collision& c) {
            if (c.a == sensor_ || c.b == sensor_)
                return true;
            c.friction *= 0.9f; // something a game might do, and every pair goes through it
            return true;
        });
    }

    /// One step of the script, hashed.
    void step() {
        if (steps_ % 3 == 0) {
            BodyDef box{.x = random_.range(-360, 360),
                        .y = random_.range(-600, -400),
                        .hw = random_.range(2, 12),
                        .hh = random_.range(2, 12),
                        .vx = random_.range(-200, 200),
                        .vy = random_.range(0, 400),
                        .bounce = random_.range(0, 1),
                        .friction = random_.range(0, 1),
                        .density = random_.range(0.5f, 4.0f)};
            box.bullet = random_.next() % 16 == 0;
            if (box.bullet)
                box.vy = 1500.0f;
            rain_.push_back(world.createBody(box));
        }
        if (steps_ % 7 == 0 && rain_.size() > 150)
            destroyOne(world, rain_, random_);
        if (steps_ % 120 == 60)
            turnRound(world, lift_);
        if (steps_ % 250 == 125) {
            const int column = 1 + static_cast<int>(random_.next() % 38);
            setTile(world, floor_, column, 2, !isSolid(world, floor_, column, 2));
        }
        world.step(1.0f / 60.0f);
        hashStep(world, hash);
        contactBegins += world.contactBegins().size();
        if (steps_ % 50 == 0) {
            for (BodyId id : queryBox(world, {0, -100}, {100, 100}))
                hash.add(id);
            if (auto hit = rayCast(world, {-390, -700}, {390, 10})) {
                hash.add(hit->body);
                hash.add(hit->point);
            }
        }
        ++steps_;
    }

    World world;
    Hash hash;
    std::size_t contactBegins = 0; ///< over the whole run

    /// What the script keeps between steps besides the world: saved and put back with a
    /// snapshot by the tests that roll back.
    struct Script {
        Lcg random;
        std::vector<BodyId> rain;
        int steps = 0;
    };
    Script script() const { return {random_, rain_, steps_}; }
    void setScript(const Script& script) {
        random_ = script.random;
        rain_ = script.rain;
        steps_ = script.steps;
    }

private:
    static WorldDef defOf(Solver solver, TaskSystem tasks) {
        WorldDef def;
        def.tasks = tasks;
        def.gravity = {0.0f, 600.0f};
        def.solver = solver;
        def.classic = {.mass = true, .coulomb = true, .ccd = true};
        def.maxVelocity = 2000.0f;
        return def;
    }

    Lcg random_;
    TileMapId floor_;
    BodyId lift_, sensor_;
    std::vector<BodyId> rain_;
    int steps_ = 0;
};

struct BusyRun {
    std::uint64_t hash = 0;
    std::size_t bodies = 0;        ///< alive at the end
    std::size_t contactBegins = 0; ///< over the whole run
};

BusyRun runBusyWorld(Solver solver, int steps, TaskSystem tasks = {}, std::uint32_t blockSize = 0) {
    BusyWorld busy(solver, tasks);
    WorldAccess::state(busy.world).tasks->setBlockSizeForTesting(blockSize);
    for (int step = 0; step < steps; ++step)
        busy.step();
    return {busy.hash.value(), busy.world.bodyCount(), busy.contactBegins};
}

// Hills of 45° and 2:1 ramp tiles, a one-sided segment, a kinematic ramp going up and
// down, a character with snapDown walking to and fro, and circles, capsules and rounded
// boxes raining in: the shapes of docs/slopes-and-shapes.md, a step at a time.
class SlopesWorld {
public:
    explicit SlopesWorld(TaskSystem tasks = {})
        : world(WorldDef{.gravity = {0.0f, 600.0f}, .maxVelocity = 2000.0f, .tasks = tasks}) {
        createTileMap(world, {.x = -400,
                              .tile = 20,
                              .rows = {"#......................................#",
                                       "#......................................#",
                                       "#....../##\\.........rR##Ll.......7####F#",
                                       "#...../####\\.....rR######Ll............#",
                                       "########################################"}});
        world.createBody({.type = BodyType::Static,
                          .x = 200,
                          .y = -120,
                          .hw = 60,
                          .hh = 20,
                          .slope = {1, -1},
                          .segment = true});
        lift_ = world.createBody({.type = BodyType::Kinematic,
                                  .x = -250,
                                  .y = -60,
                                  .hw = 40,
                                  .hh = 20,
                                  .vy = -30,
                                  .slope = {-1, -1}});
        hero_ = world.createBody(
            {.x = -300, .y = 30, .hw = 6, .hh = 9, .character = true, .snapDown = 6, .radius = 3});
    }

    /// One step of the script, hashed.
    void step() {
        const int step = script_.steps++;
        Lcg& random = script_.random;
        std::vector<BodyId>& rain = script_.rain;
        if (step % 4 == 0) {
            const float hw = random.range(3, 10);
            const float hh = random.next() % 2 == 0 ? hw : random.range(3, 10);
            rain.push_back(world.createBody({.x = random.range(-360, 360),
                                             .y = random.range(-500, -300),
                                             .hw = hw,
                                             .hh = hh,
                                             .vx = random.range(-100, 100),
                                             .bounce = random.range(0, 0.5f),
                                             .friction = random.range(0, 1),
                                             .radius = random.range(0, std::min(hw, hh))}));
        }
        if (step % 5 == 0 && rain.size() > 80)
            destroyOne(world, rain, random);
        if (step % 120 == 60)
            turnRound(world, lift_);
        if (step % 240 == 0)
            world.setWalkSpeed(hero_, step % 480 == 0 ? 90.0f : -90.0f);
        world.step(1.0f / 60.0f);
        hashStep(world, hash);
    }

    struct Script {
        Lcg random;
        std::vector<BodyId> rain;
        int steps = 0;
    };
    Script script() const { return script_; }
    void setScript(const Script& script) { script_ = script; }

    World world;
    Hash hash;

private:
    Script script_;
    BodyId lift_, hero_;
};

std::uint64_t runSlopesWorld(int steps, TaskSystem tasks = {}, std::uint32_t blockSize = 0) {
    SlopesWorld slopes(tasks);
    WorldAccess::state(slopes.world).tasks->setBlockSizeForTesting(blockSize);
    for (int step = 0; step < steps; ++step)
        slopes.step();
    return slopes.hash.value();
}

} // namespace jostle::testing
