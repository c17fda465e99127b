// Handles, getters and setters, argument checks, and changes made during a step.
#include "jostle/query.hpp"
#include "jostle/world.hpp"

#include <array>
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace jostle {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

World classicWorld(Vec2 gravity = {0, 0}) {
    return World(WorldDef{.gravity = gravity, .solver = Solver::Classic});
}

BodyDef boxAt(float x, float y) {
    return {.x = x, .y = y, .hw = 1, .hh = 1};
}

TEST(Handles, CreateDestroyAndStaleness) {
    World world = classicWorld();
    BodyId a = world.createBody(boxAt(0, 0));
    EXPECT_TRUE(world.isValid(a));
    EXPECT_FALSE(world.isValid(BodyId{}));
    world.destroyBody(a);
    EXPECT_FALSE(world.isValid(a));
    EXPECT_THROW(world.position(a), Error);
    EXPECT_THROW(world.destroyBody(a), Error);

    // The slot is reused; the old handle stays stale and does not reach the new body.
    BodyId b = world.createBody(boxAt(5, 5));
    EXPECT_EQ(b.index, a.index);
    EXPECT_NE(b.generation, a.generation);
    EXPECT_FALSE(world.isValid(a));
    EXPECT_THROW(world.setPosition(a, {1, 1}), Error);
    EXPECT_EQ(world.position(b), (Vec2{5, 5}));
}

TEST(Handles, NullAndForeignHandlesThrowWithTheirReason) {
    World world = classicWorld();
    try {
        world.velocity(BodyId{});
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "velocity: null BodyId");
    }
    EXPECT_THROW(world.velocity(BodyId{42, 1}), Error);
}

TEST(Handles, AHandleOfAnotherWorldIsRejected) {
    // Two worlds built alike: their first bodies sit in the same slot, yet neither world
    // takes the other's handle, even after the slot has been reused many times.
    World first = classicWorld();
    World second = classicWorld();
    BodyId a = first.createBody(boxAt(0, 0));
    BodyId b = second.createBody(boxAt(0, 0));
    EXPECT_EQ(a.index, b.index);
    EXPECT_FALSE(first.isValid(b));
    EXPECT_FALSE(second.isValid(a));
    EXPECT_THROW(second.setPosition(a, {1, 1}), Error);
    for (int i = 0; i < 1000; ++i) {
        second.destroyBody(b);
        b = second.createBody(boxAt(0, 0));
        ASSERT_FALSE(second.isValid(a));
        ASSERT_FALSE(first.isValid(b));
    }
    EXPECT_EQ(first.position(a), (Vec2{0, 0}));
}

TEST(Handles, BodiesAreListedInCreationOrder) {
    World world = classicWorld();
    BodyId a = world.createBody(boxAt(0, 0));
    BodyId b = world.createBody(boxAt(3, 0));
    BodyId c = world.createBody(boxAt(6, 0));
    world.destroyBody(b);
    BodyId d = world.createBody(boxAt(9, 0)); // reuses b's slot, but comes last
    std::vector<BodyId> listed(world.bodies().begin(), world.bodies().end());
    EXPECT_EQ(listed, (std::vector<BodyId>{a, c, d}));
    EXPECT_EQ(world.bodyCount(), 3u);
}

TEST(Bodies, EverySetterRoundTrips) {
    World world = classicWorld();
    int tag = 0;
    BodyId id = world.createBody(boxAt(0, 0));
    world.setPosition(id, {1, 2});
    world.setVelocity(id, {3, 4});
    world.setHalfExtents(id, {5, 6});
    world.setBounce(id, 0.25f);
    world.setFriction(id, 0.75f);
    world.setGravityScale(id, -2);
    world.setDamping(id, 0.5f);
    world.setUserData(id, &tag);
    world.setMass(id, 7);
    BodyDef def = world.bodyDef(id);
    EXPECT_EQ(def.type, BodyType::Dynamic);
    EXPECT_EQ((Vec2{def.x, def.y}), (Vec2{1, 2}));
    EXPECT_EQ((Vec2{def.vx, def.vy}), (Vec2{3, 4}));
    EXPECT_EQ((Vec2{def.hw, def.hh}), (Vec2{5, 6}));
    EXPECT_EQ(def.bounce, 0.25f);
    EXPECT_EQ(def.friction, 0.75f);
    EXPECT_EQ(def.gravityScale, -2.0f);
    EXPECT_EQ(def.damping, 0.5f);
    EXPECT_EQ(def.userData, &tag);
    EXPECT_EQ(world.userData(id), &tag);
    EXPECT_EQ(world.mass(id), 7.0f);
    world.setType(id, BodyType::Kinematic);
    EXPECT_EQ(world.type(id), BodyType::Kinematic);
}

// A step walks only the bodies that are not static (a level's static boxes cost it
// nothing), a list made again whenever bodies come, go or change type. Each change counts
// from the next step: a static box made dynamic falls (v = g dt after one step, the
// physical model integrating velocity first), one created after steps falls, a falling box
// made static stops where it is and, pushed by nothing any more, reports no separation.
TEST(Bodies, TypeChangesCreationsAndDestructionsCountFromTheNextStep) {
    constexpr float kG = 10.0f, kStep = 1.0f / 60.0f;
    World world(WorldDef{.gravity = {0, kG}});
    std::vector<BodyId> level;
    for (int i = 0; i < 50; ++i)
        level.push_back(world.createBody(
            {.type = BodyType::Static, .x = float(i) * 4, .y = 0, .hw = 1, .hh = 1}));
    world.createBody({.type = BodyType::Static, .x = 500, .y = 10, .hw = 10, .hh = 1}); // a floor
    const BodyId resting = world.createBody({.x = 500, .y = 8.5f, .hw = 0.5f, .hh = 0.5f});
    for (int s = 0; s < 30; ++s)
        world.step(kStep);
    ASSERT_NE(world.separation(resting), (Vec2{0, 0})) << "the floor holds it up";

    world.setType(level[7], BodyType::Dynamic);
    const BodyId dropped = world.createBody({.x = -100, .y = 0, .hw = 1, .hh = 1});
    world.destroyBody(level[8]);
    world.setType(resting, BodyType::Static);
    EXPECT_EQ(world.separation(resting), (Vec2{0, 0}));
    const Vec2 restingAt = world.position(resting);
    world.step(kStep);
    EXPECT_FLOAT_EQ(world.velocity(level[7]).y, kG * kStep);
    EXPECT_FLOAT_EQ(world.velocity(dropped).y, kG * kStep);
    EXPECT_EQ(world.position(resting), restingAt);
    EXPECT_EQ(world.separation(resting), (Vec2{0, 0}));
    EXPECT_EQ(world.velocity(level[6]), (Vec2{0, 0}));

    // And back: made dynamic again, it rests on the floor as before.
    world.setType(resting, BodyType::Dynamic);
    for (int s = 0; s < 10; ++s)
        world.step(kStep);
    EXPECT_NE(world.separation(resting), (Vec2{0, 0}));
    EXPECT_NEAR(world.position(resting).y, restingAt.y, 0.02f);
}

TEST(Bodies, MassFromDensityTimesArea) {
    World world = classicWorld();
    BodyId id = world.createBody({.hw = 2, .hh = 3, .density = 0.5f});
    EXPECT_EQ(world.mass(id), 0.5f * 4 * 2 * 3);
    world.setHalfExtents(id, {1, 1});
    EXPECT_EQ(world.mass(id), 0.5f * 4);
    world.setMass(id, 10);
    EXPECT_EQ(world.mass(id), 10.0f);
    world.setDensity(id, 2);
    EXPECT_EQ(world.mass(id), 8.0f);
    world.setType(id, BodyType::Static);
    EXPECT_EQ(world.mass(id), std::numeric_limits<float>::infinity());
    EXPECT_EQ(world.velocity(id), (Vec2{0, 0})); // static bodies never move
}

TEST(Bodies, BadArgumentsThrowAndChangeNothing) {
    World world = classicWorld();
    BodyId id = world.createBody(boxAt(1, 1));
    EXPECT_THROW(world.setPosition(id, {kNaN, 0}), Error);
    EXPECT_THROW(world.setVelocity(id, {0, std::numeric_limits<float>::infinity()}), Error);
    EXPECT_THROW(world.setHalfExtents(id, {0, 1}), Error);
    EXPECT_THROW(world.setBounce(id, 1.1f), Error);
    EXPECT_THROW(world.setBounce(id, kNaN), Error);
    EXPECT_THROW(world.setFriction(id, -0.1f), Error);
    EXPECT_THROW(world.setMass(id, 0), Error);
    EXPECT_THROW(world.setDensity(id, -1), Error);
    EXPECT_THROW(world.setDamping(id, -1), Error);
    EXPECT_THROW(world.setGravityScale(id, kNaN), Error);
    EXPECT_EQ(world.position(id), (Vec2{1, 1}));
    EXPECT_EQ(world.halfExtents(id), (Vec2{1, 1}));

    try {
        world.createBody({.hw = 1, .hh = -2});
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "createBody: BodyDef.hh: must be > 0");
    }
    EXPECT_THROW(world.createBody({.type = BodyType::Static, .hw = 1, .hh = 1, .vx = 1}), Error);
    BodyId wall = world.createBody({.type = BodyType::Static, .hw = 1, .hh = 1});
    EXPECT_THROW(world.setVelocity(wall, {1, 0}), Error);
    EXPECT_EQ(world.bodyCount(), 2u);
}

TEST(WorldSettings, RoundTripAndChecks) {
    World world = classicWorld();
    world.setGravity({0, 9.8f});
    EXPECT_EQ(world.gravity(), (Vec2{0, 9.8f}));
    world.setMaxVelocity(100);
    EXPECT_EQ(world.maxVelocity(), 100.0f);
    world.setClassicOptions({.mass = true, .coulomb = true});
    EXPECT_TRUE(world.classicOptions().mass);
    EXPECT_TRUE(world.classicOptions().coulomb);
    EXPECT_THROW(world.setGravity({kNaN, 0}), Error);
    EXPECT_THROW(world.setMaxVelocity(-1), Error);
    EXPECT_THROW(World(WorldDef{.maxVelocity = 0}), Error);
    EXPECT_THROW(world.step(0), Error);
    EXPECT_THROW(world.step(-1), Error);
    EXPECT_THROW(world.step(kNaN), Error);
}

// A dynamic box falling onto a floor, and a callback that acts during the step: in the
// classic model (the default) or the physical one.
struct Scene {
    explicit Scene(Solver solver = Solver::Classic)
        : world(WorldDef{.gravity = {0, 800}, .solver = solver}) {}
    World world;
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 20, .hw = 100, .hh = 10});
    BodyId box = world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vy = 60});
};

// The callback tests hold in either model.
class DuringStep : public ::testing::TestWithParam<Solver> {};

TEST_P(DuringStep, DestroyingTheMovingBodyFromACallbackIsSafe) {
    Scene s(GetParam());
    BodyId later = s.world.createBody({.x = 50, .y = 0, .hw = 1, .hh = 1});
    s.world.setPreSolve([&](Collision& c) {
        const BodyId moving = c.a == s.box ? c.a : c.b;
        s.world.destroyBody(moving);
        EXPECT_FALSE(s.world.isValid(moving));
        return true;
    });
    s.world.step(1.0f / 60);
    EXPECT_FALSE(s.world.isValid(s.box));
    EXPECT_EQ(s.world.bodyCount(), 2u);
    // The rest of the step went on: the later body fell.
    EXPECT_GT(s.world.position(later).y, 0.0f);
    // The slot comes back only after the step, under a new generation.
    BodyId fresh = s.world.createBody({.hw = 1, .hh = 1});
    EXPECT_FALSE(s.world.isValid(s.box));
    EXPECT_TRUE(s.world.isValid(fresh));
    s.world.step(1.0f / 60);
}

TEST_P(DuringStep, DestroyingTheOtherBodyFromACallbackIsSafe) {
    Scene s(GetParam());
    s.world.setPreSolve([&](Collision& c) {
        s.world.destroyBody(c.a == s.box ? c.b : c.a);
        return true;
    });
    s.world.step(1.0f / 60);
    EXPECT_FALSE(s.world.isValid(s.floor));
    // The floor is gone: the box was not pushed back.
    EXPECT_GT(s.world.position(s.box).y, 4.0f);
}

TEST_P(DuringStep, BodiesCreatedInACallbackJoinFromTheNextStep) {
    Scene s(GetParam());
    BodyId spawned;
    s.world.setPreSolve([&](Collision&) {
        if (spawned.isNull()) {
            // Enough bodies to move the storage in memory mid-step.
            for (int i = 0; i < 1000; ++i)
                spawned = s.world.createBody({.x = 500, .y = 0, .hw = 1, .hh = 1});
        }
        return true;
    });
    s.world.step(1.0f / 60);
    EXPECT_TRUE(s.world.isValid(spawned));
    EXPECT_EQ(s.world.position(spawned), (Vec2{500, 0})); // not moved yet
    EXPECT_EQ(s.world.velocity(spawned), (Vec2{0, 0}));
    s.world.step(1.0f / 60);
    EXPECT_GT(s.world.position(spawned).y, 0.0f);
}

TEST_P(DuringStep, SteppingFromACallbackIsRefused) {
    Scene s(GetParam());
    bool threw = false;
    s.world.setPreSolve([&](Collision&) {
        try {
            s.world.step(1.0f / 60);
        } catch (const Error&) {
            threw = true;
        }
        return true;
    });
    s.world.step(1.0f / 60);
    EXPECT_TRUE(threw);
}

// Found by the C API's tests under ASan: replacing the pre-solve callback from inside
// itself destroyed the running function, and switching the model cleared the events the
// step was filling. Every world setting now waits for the step to end.
TEST(DuringStep, ChangingTheWorldsSettingsFromACallbackIsRefused) {
    for (Solver solver : {Solver::Classic, Solver::Physical}) {
        Scene s;
        s.world.setSolver(solver);
        const Vec2 gravity = s.world.gravity();
        const float maxVelocity = s.world.maxVelocity();
        const bool sleeping = s.world.sleeping();
        int refused = 0;
        int calls = 0;
        s.world.setPreSolve([&](Collision&) {
            ++calls;
            const std::function<void()> changes[] = {
                [&] { s.world.setPreSolve({}); },
                [&] { s.world.setSolver(Solver::Classic); },
                [&] { s.world.setSolver(Solver::Physical); },
                [&] {
                    s.world.setGravity({0, -1});
                },
                [&] { s.world.setMaxVelocity(1); },
                [&] { s.world.setSleeping(false); },
                [&] { s.world.setClassicOptions({.mass = true}); },
                [&] { s.world.setPhysicalOptions({.velocityIterations = 1}); },
            };
            for (const auto& change : changes) {
                try {
                    change();
                } catch (const Error& e) {
                    EXPECT_NE(std::string(e.what()).find("during step()"), std::string::npos);
                    ++refused;
                }
            }
            return true;
        });
        s.world.step(1.0f / 60);
        ASSERT_GT(calls, 0);
        EXPECT_EQ(refused, 8 * calls);
        EXPECT_EQ(s.world.gravity(), gravity);
        EXPECT_EQ(s.world.solver(), solver);
        EXPECT_EQ(s.world.maxVelocity(), maxVelocity);
        EXPECT_EQ(s.world.sleeping(), sleeping);
        s.world.setPreSolve({}); // and after the step, all of them are fine
        s.world.setSolver(Solver::Classic);
    }
}

TEST(DuringStepDeathTest, DestroyingTheWorldFromItsOwnCallbackStopsWithAMessage) {
    EXPECT_DEATH(
        {
            auto world = std::make_unique<World>(WorldDef{.gravity = {0, 10}});
            world->createBody({.type = BodyType::Static, .y = 2, .hw = 10, .hh = 1});
            world->createBody({.hw = 1, .hh = 1});
            world->setPreSolve([&](Collision&) {
                world.reset();
                return true;
            });
            for (int i = 0; i < 60; ++i)
                world->step(1.0f / 60);
        },
        "World destroyed from a callback during step");
}

TEST_P(DuringStep, AnExceptionFromACallbackLeavesTheWorldUsable) {
    Scene s(GetParam());
    s.world.setPreSolve([&](Collision&) -> bool {
        s.world.destroyBody(s.box);
        throw std::runtime_error("game error");
    });
    EXPECT_THROW(s.world.step(1.0f / 60), std::runtime_error);
    s.world.setPreSolve({});
    s.world.step(1.0f / 60); // not "called from a callback"
    BodyId again = s.world.createBody({.hw = 1, .hh = 1});
    EXPECT_EQ(again.index, s.box.index); // the destroyed slot was released
}

// A game that caught a pre-solve's exception and went on found the box with its velocity
// stepped and its position not (a newcomer's C++ game): the step was left half done.
TEST_P(DuringStep, AStepWhoseCallbackThrowsFinishesAsIfItHadAnsweredTrueThenThrows) {
    Scene thrown(GetParam()), answered(GetParam());
    int calls = 0;
    thrown.world.setPreSolve([&](Collision& c) -> bool {
        c.bounce = 1; // changed, then thrown: not kept
        if (++calls == 1)
            throw std::runtime_error("game error");
        return false; // never asked again in the step
    });
    answered.world.setPreSolve([](Collision&) { return true; });
    EXPECT_THROW(thrown.world.step(1.0f / 60), std::runtime_error);
    answered.world.step(1.0f / 60);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(thrown.world.position(thrown.box), answered.world.position(answered.box));
    EXPECT_EQ(thrown.world.velocity(thrown.box), answered.world.velocity(answered.box));
    EXPECT_EQ(thrown.world.stateHash(), answered.world.stateHash());
    thrown.world.step(1.0f / 60); // the callback is asked again in the next step
    EXPECT_EQ(calls, 2);
}

INSTANTIATE_TEST_SUITE_P(EitherModel, DuringStep,
                         ::testing::Values(Solver::Classic, Solver::Physical));

TEST(World, ProfileSharesTheStepAmongItsStages) {
    auto stages = [](const StepProfile& p) {
        return std::array{p.pairs,  p.contacts,  p.support, p.impacts, p.velocities,
                          p.sweeps, p.positions, p.store,   p.events,  p.sleep};
    };
    for (Solver solver : {Solver::Physical, Solver::Classic}) {
        World world(WorldDef{.gravity = {0, 10}, .solver = solver});
        for (float ms : stages(world.profile()))
            EXPECT_EQ(ms, 0.0f); // no step yet
        EXPECT_EQ(world.profile().step, 0.0f);
        world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 50, .hh = 1});
        for (int i = 0; i < 200; ++i)
            world.createBody(
                {.x = float(i % 20) * 2 - 20, .y = float(i / 20) * 2 - 10, .hw = 0.9f, .hh = 0.9f});
        world.step(1.0f / 60.0f);
        const StepProfile& p = world.profile();
        EXPECT_GT(p.step, 0.0f);
        float sum = 0.0f;
        for (float ms : stages(p)) {
            EXPECT_GE(ms, 0.0f);
            sum += ms;
        }
        // The stages are laps within the step's own time; the classic model has none.
        EXPECT_LE(sum, p.step * 1.001f);
        if (solver == Solver::Physical)
            EXPECT_GT(sum, 0.0f);
        else
            EXPECT_EQ(sum, 0.0f);
    }
}

} // namespace
} // namespace jostle

namespace jostle {
namespace {

// --- The range jostle works in (math.hpp) ------------------------------------------------

TEST(Range, NumbersBeyondItAreRefusedByEverySetter) {
    World world;
    BodyId box = world.createBody({.hw = 1, .hh = 1});
    EXPECT_THROW(world.setPosition(box, {2e9f, 0}), Error);
    EXPECT_THROW(world.setVelocity(box, {0, -1e10f}), Error);
    EXPECT_THROW(world.setHalfExtents(box, {1e-10f, 1}), Error);
    EXPECT_THROW(world.setMass(box, 1e-10f), Error);
    EXPECT_THROW(world.setDensity(box, 2e9f), Error);
    EXPECT_THROW(world.setGravityScale(box, 1e30f), Error);
    EXPECT_THROW(world.setGravity({1e10f, 0}), Error);
    EXPECT_THROW(world.step(1e-10f), Error);
    EXPECT_THROW(world.step(2e9f), Error);
    EXPECT_EQ(world.position(box), (Vec2{0, 0}));
    EXPECT_EQ(world.halfExtents(box), (Vec2{1, 1}));
    // The ends themselves are fine.
    world.setPosition(box, {1e9f, -1e9f});
    world.setHalfExtents(box, {1e-9f, 1e9f});
    world.step(1e-9f);
    world.step(1e9f);
}

TEST(Range, ABodyStopsAtTheEdgeOfTheWorld) {
    for (Solver solver : {Solver::Classic, Solver::Physical}) {
        World world(WorldDef{.solver = solver});
        // 1e9 - 100 + 1e9 × 1 is far past the edge: it stops at 1e9, its speed along x gone.
        BodyId box = world.createBody({.x = 1e9f - 100, .hw = 1, .hh = 1, .vx = 1e9f, .vy = 3});
        world.step(1.0f);
        EXPECT_EQ(world.position(box).x, 1e9f);
        EXPECT_EQ(world.velocity(box).x, 0.0f);
        EXPECT_EQ(world.velocity(box).y, 3.0f); // the other axis goes on
        EXPECT_EQ(world.position(box).y, 3.0f);
    }
}

TEST(Range, TheLargestNumbersTogetherStayFinite) {
    // Gravity 1e9 × scale 1e9 × dt 1e9 adds 1e27 to a speed: it is held to 1e9 per axis,
    // and the body stops at the edge; every number stays finite step after step.
    for (Solver solver : {Solver::Classic, Solver::Physical}) {
        World world(WorldDef{.gravity = {1e9f, -1e9f}, .solver = solver});
        world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 1e9f, .hh = 1e-9f});
        BodyId heavy = world.createBody(
            {.x = 5, .y = 5, .hw = 1e9f, .hh = 1e9f, .density = 1e9f, .gravityScale = 1e9f});
        BodyId light = world.createBody({.x = -5,
                                         .y = 5,
                                         .hw = 1e-9f,
                                         .hh = 1e-9f,
                                         .vx = -1e9f,
                                         .density = 1e-9f,
                                         .gravityScale = -1e9f});
        for (int i = 0; i < 20; ++i) {
            world.step(i % 2 == 0 ? 1e9f : 1e-9f);
            for (BodyId id : {heavy, light}) {
                ASSERT_TRUE(inRange(world.position(id))) << i;
                ASSERT_TRUE(inRange(world.velocity(id))) << i;
            }
        }
    }
}

TEST(World, ReadsEveryPositionVelocityAndHalfExtentsInOneCall) {
    World world;
    const BodyId a = world.createBody({.x = 1, .y = 2, .hw = 1, .hh = 1, .vx = 3, .vy = 4});
    const BodyId b = world.createBody({.x = 5, .y = 6, .hw = 2, .hh = 3, .vx = 7, .vy = 8});
    world.createBody({.x = 9, .y = 10, .hw = 4, .hh = 5});
    world.destroyBody(a); // the order is bodies()'s: b, then the third
    std::vector<Vec2> positions(5, Vec2{-1, -1}), velocities(1);
    EXPECT_EQ(world.readPositions(positions), 2u);
    EXPECT_EQ(positions[0], (Vec2{5, 6}));
    EXPECT_EQ(positions[1], (Vec2{9, 10}));
    EXPECT_EQ(positions[2], (Vec2{-1, -1}));         // left alone
    EXPECT_EQ(world.readVelocities(velocities), 1u); // as many as fit
    EXPECT_EQ(velocities[0], world.velocity(b));
    std::vector<Vec2> halves(2);
    EXPECT_EQ(world.readHalfExtents(halves), 2u);
    EXPECT_EQ(halves[0], (Vec2{2, 3}));
    EXPECT_EQ(halves[1], (Vec2{4, 5}));
}

// --- The edge of the world (math.hpp), found by the fuzzers (tests/fuzz/corpus/) --------

// Found by fuzz_api (tests/fuzz/corpus/api/edge-of-the-world-after-a-callback-throws).
// A body that reaches the edge of the world (math.hpp: ±1e9) stops there at the end of
// the step; a step that a pre-solve callback ended with an exception skipped that, and
// left the body beyond the edge, out of the range every function promises. (The classic
// model calls the callback after a body has moved; the physical one, before.)
TEST(EdgeOfTheWorld, ABodyStopsAtTheEdgeOfTheWorldEvenWhenTheStepThrows) {
    World world(WorldDef{.solver = Solver::Classic});
    // 1e9 units a second carries the box 1.7e7 units past the edge in a step, into a
    // static body that reaches beyond it (its numbers are in the range, its far side is
    // not); the collision calls the callback, which throws.
    const BodyId box = world.createBody({.y = 1e9f - 10, .hw = 1, .hh = 1, .vy = 1e9f});
    world.createBody({.type = BodyType::Static, .y = 1e9f, .hw = 10, .hh = 1e8f});
    world.setPreSolve([](Collision&) -> bool { throw std::runtime_error("game over"); });
    EXPECT_THROW(world.step(1.0f / 60.0f), std::runtime_error);
    EXPECT_LE(world.position(box).y, kMaxMagnitude);
    EXPECT_LE(world.velocity(box).y, kMaxMagnitude);
}

// Found by fuzz_api (tests/fuzz/corpus/api/edge-of-the-world-asleep). The edge of the
// world left sleeping bodies alone, but a body can fall asleep in the very step that
// carries it past the edge: slow enough to be at rest, with a dt long enough (up to 1e9 s)
// to take it there. It stayed beyond the edge, asleep.
TEST(EdgeOfTheWorld, ABodyThatFallsAsleepPastTheEdgeStopsAtIt) {
    World world; // sleeping is on
    // 1.5 units a second is rest for a box of half extent 40 (0.05 × 40 = 2 per second).
    const BodyId box = world.createBody({.hw = 40, .hh = 40, .vx = 1.5f});
    world.step(1e9f);
    EXPECT_LE(world.position(box).x, kMaxMagnitude);
    // Where it stopped, the queries find it.
    EXPECT_EQ(queryPoint(world, world.position(box)).size(), 1u);
}

} // namespace
} // namespace jostle
