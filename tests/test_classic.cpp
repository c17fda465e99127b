// The classic model's response, options and behaviour, with values worked out by hand
// from the tutorial's formulas. dt = 1/8 and small integers keep the arithmetic exact
// where a test compares exactly.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jostle {
namespace {

constexpr float kDt = 0.125f;

World classicWorld(Vec2 gravity = {0, 0}, ClassicOptions options = {}) {
    return World(WorldDef{.gravity = gravity, .solver = Solver::Classic, .classic = options});
}

// A floor whose top edge is y = 10 (y grows downward).
BodyId addFloor(World& world, float friction = 0.5f, float bounce = 0.0f) {
    return world.createBody({.type = BodyType::Static,
                             .x = 0,
                             .y = 20,
                             .hw = 1000,
                             .hh = 10,
                             .bounce = bounce,
                             .friction = friction});
}

TEST(ClassicResponse, BounceAndFrictionFromTheTutorialsFormulas) {
    World world = classicWorld();
    addFloor(world, 0.5f, 0.0f);
    BodyId box = world.createBody(
        {.x = 0, .y = 4, .hw = 5, .hh = 5, .vx = 8, .vy = 16, .bounce = 0.5f, .friction = 0.25f});
    world.step(kDt);
    // Moved by v*dt to (1, 6): bottom at 11, one unit into the floor. testRectRect:
    // d = (1, -14), s = (1005 - 1, 15 - 14) = (1004, 1) -> (0, -1): up by one.
    EXPECT_EQ(world.position(box), (Vec2{1, 5}));
    EXPECT_EQ(world.separation(box), (Vec2{0, -1}));
    // n = (0, -1), v = (8, 16), ps = -16, p = (0, 16), t = (8, 0);
    // r = 1 + max(0.5, 0) = 1.5, f = min(0.25, 0.5) = 0.25:
    // v' = v - p*r - t*f = (8 - 2, 16 - 24) = (6, -8).
    // (The tutorial's printed `+ tx*f` would give vx = 10: friction would speed it up.)
    EXPECT_EQ(world.velocity(box), (Vec2{6, -8}));
}

TEST(ClassicResponse, PairsMovingApartAreLeftAlone) {
    World world = classicWorld();
    addFloor(world);
    // Overlaps the floor by half a unit after its move, but moves up: ps = +4 > 0.
    BodyId box = world.createBody({.x = 0, .y = 6, .hw = 5, .hh = 5, .vx = 0, .vy = -4});
    world.step(kDt);
    EXPECT_EQ(world.position(box), (Vec2{0, 5.5f}));
    EXPECT_EQ(world.velocity(box), (Vec2{0, -4}));
    EXPECT_EQ(world.separation(box), (Vec2{0, 0}));
}

TEST(ClassicResponse, OnlyTheMovingBodyChangesWithoutMass) {
    World world = classicWorld();
    // a (created first, so resolved first) moves right into b, which has not moved yet.
    BodyId a = world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .vx = 8, .mass = 1});
    BodyId b = world.createBody({.x = 2.5f, .y = 0, .hw = 1, .hh = 1, .vx = -8, .mass = 3});
    world.step(kDt);
    // a moves to x = 1: d = -1.5, s = (0.5, 2) -> (-0.5, 0): a back to 0.5.
    EXPECT_EQ(world.position(a), (Vec2{0.5f, 0}));
    // n = (-1, 0), relative v = 16, ps = -16, r = 1: a's vx = 8 - 16 = -8. b keeps -8 and
    // then moves on its own: x = 2.5 - 1 = 1.5.
    EXPECT_EQ(world.velocity(a).x, -8.0f);
    EXPECT_EQ(world.velocity(b).x, -8.0f);
    EXPECT_EQ(world.position(b).x, 1.5f);
}

// The 1-D collision formulas: v1' and v2' for masses m1, m2 and restitution e.
struct Outcome1D {
    float v1, v2;
};
Outcome1D collide1D(float m1, float v1, float m2, float v2, float e) {
    const float p = m1 * v1 + m2 * v2;
    return {(p + m2 * e * (v2 - v1)) / (m1 + m2), (p + m1 * e * (v1 - v2)) / (m1 + m2)};
}

class ClassicMassOption : public ::testing::TestWithParam<std::tuple<float, float>> {};

TEST_P(ClassicMassOption, ImpulseSharedByInverseMassConservesMomentum) {
    const auto [massB, bounce] = GetParam();
    World world = classicWorld({0, 0}, {.mass = true});
    BodyId a = world.createBody(
        {.x = 0, .y = 0, .hw = 1, .hh = 1, .vx = 8, .bounce = bounce, .friction = 0, .mass = 1});
    BodyId b = world.createBody({.x = 2.5f,
                                 .y = 0,
                                 .hw = 1,
                                 .hh = 1,
                                 .vx = -8,
                                 .bounce = bounce,
                                 .friction = 0,
                                 .mass = massB});
    world.step(kDt);
    const Outcome1D expected = collide1D(1, 8, massB, -8, bounce);
    // A handful of float operations on values of size 16: a few ulps of 16.
    const float tolerance = 16 * 8 * std::numeric_limits<float>::epsilon();
    EXPECT_NEAR(world.velocity(a).x, expected.v1, tolerance);
    EXPECT_NEAR(world.velocity(b).x, expected.v2, tolerance);
    EXPECT_NEAR(1 * world.velocity(a).x + massB * world.velocity(b).x, 8 - 8 * massB,
                tolerance * (1 + massB));
}

INSTANTIATE_TEST_SUITE_P(MassRatiosAndBounce, ClassicMassOption,
                         ::testing::Combine(::testing::Values(1.0f, 3.0f, 0.25f, 100.0f),
                                            ::testing::Values(0.0f, 1.0f)));

TEST(ClassicMassOption, StaticBodiesAreInfinitelyHeavy) {
    World world = classicWorld({0, 0}, {.mass = true});
    BodyId floor = addFloor(world, 0, 0);
    BodyId box = world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vy = 16, .mass = 1e6f});
    world.step(kDt);
    EXPECT_EQ(world.velocity(box), (Vec2{0, 0})); // all of it, as without the option
    EXPECT_EQ(world.position(floor), (Vec2{0, 20}));
}

TEST(ClassicMassOption, KinematicBodiesAreInfinitelyHeavyToo) {
    World world = classicWorld({0, 0}, {.mass = true});
    BodyId lift = world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = 20, .hw = 50, .hh = 10, .vy = -8});
    BodyId box = world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .friction = 0});
    world.step(kDt);
    // The lift rises 1 to y = 19 (top 9): the box (bottom 9, not moving) just touches it
    // and touching is no collision. Next step the lift's top is at 8: one unit of overlap.
    world.step(kDt);
    EXPECT_EQ(world.position(box).y, 3.0f);
    EXPECT_EQ(world.velocity(box).y, -8.0f); // takes the lift's velocity
    EXPECT_EQ(world.velocity(lift).y, -8.0f);
}

TEST(ClassicCoulombOption, TangentialChangeIsCappedByTheNormalChange) {
    World world = classicWorld({0, 0}, {.coulomb = true});
    addFloor(world, 0.5f);
    BodyId box =
        world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vx = 80, .vy = 16, .friction = 0.5f});
    world.step(kDt);
    // ps = -16, r = 1: the normal change is 16, so friction may take at most
    // 0.5 * 16 = 8 of the tangent 80 (not half of it, as without the option).
    EXPECT_EQ(world.velocity(box), (Vec2{72, 0}));
}

TEST(ClassicCoulombOption, SmallTangentsStillLoseTheFraction) {
    World world = classicWorld({0, 0}, {.coulomb = true});
    addFloor(world, 0.5f);
    BodyId box =
        world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vx = 8, .vy = 16, .friction = 0.5f});
    world.step(kDt);
    // 0.5 * 8 = 4 is under the cap of 8: vx = 8 - 4.
    EXPECT_EQ(world.velocity(box), (Vec2{4, 0}));
}

/// Distance a box slides on a floor before it stops (speed below 1e-3).
float slideDistance(ClassicOptions options, float v0, float mu, float g, float dt) {
    World world = classicWorld({0, g}, options);
    // Floor top at y = 10; the box rests on it, touching.
    addFloor(world, mu);
    BodyId box = world.createBody({.x = 0, .y = 5, .hw = 5, .hh = 5, .vx = v0, .friction = mu});
    for (int i = 0; i < 10000 && std::abs(world.velocity(box).x) > 1e-3f; ++i)
        world.step(dt);
    return world.position(box).x;
}

TEST(ClassicCoulombOption, SlidingBoxStopsAfterVSquaredOverTwoMuG) {
    // Resting on the floor, each step gravity adds g*dt and the floor takes it back, so
    // the normal change is g*dt and friction removes mu*g*dt: deceleration mu*g. The box
    // moves by v*dt before friction acts in a step, so with K = v0/(mu g dt) steps
    // (an integer here: 45) the distance is sum_k (v0 - k mu g dt) dt
    // = v0^2 / (2 mu g) + v0 dt / 2 = 112.5 + 2.5.
    const float v0 = 300, mu = 0.5f, g = 800, dt = 1.0f / 60.0f;
    const float expected = v0 * v0 / (2 * mu * g) + v0 * dt / 2;
    // Float rounding of 45 steps, and the last crawl: once |v| < g*dt friction takes the
    // fraction mu per step, which adds at most g*dt*dt/mu.
    EXPECT_NEAR(slideDistance({.coulomb = true}, v0, mu, g, dt), expected,
                g * dt * dt / mu + 0.05f);
}

TEST(ClassicCoulombOption, WithoutItFrictionIsSticky) {
    // The tutorial's friction: half the speed is lost at every step's contact, so the
    // distance is v0 dt (1 + 1/2 + 1/4 + ...) = 2 v0 dt = 10, whatever gravity is.
    const float v0 = 300, dt = 1.0f / 60.0f;
    EXPECT_NEAR(slideDistance({}, v0, 0.5f, 800, dt), 2 * v0 * dt, 1e-3f);
}

TEST(ClassicScenario, BoxComesToRestOnAFloor) {
    World world = classicWorld({0, 800});
    addFloor(world);
    BodyId box = world.createBody({.x = 0, .y = -100, .hw = 5, .hh = 5});
    for (int i = 0; i < 5 * 60; ++i)
        world.step(1.0f / 60.0f);
    // Resting: bottom on the floor's top (y = 10); the floor takes back exactly what
    // gravity added (v - p*r with p = v), so the speed is 0.
    EXPECT_NEAR(world.position(box).y, 5.0f, 1e-4f);
    EXPECT_EQ(world.velocity(box), (Vec2{0, 0}));
    EXPECT_LT(world.separation(box).y, 0.0f); // pushed up by the floor: "grounded"
}

TEST(ClassicScenario, MaxVelocityHoldsWhileFalling) {
    World world(WorldDef{.gravity = {0, 800}, .maxVelocity = 300, .solver = Solver::Classic});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 5, .hh = 5, .vx = 200});
    float largest = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(1.0f / 60.0f);
        largest = std::max(largest, length(world.velocity(box)));
    }
    // clampVec scales the vector to length 300: one rounding of the scale and of each
    // component.
    EXPECT_LE(largest, 300 * (1 + 4 * std::numeric_limits<float>::epsilon()));
    EXPECT_NEAR(largest, 300, 1e-3f);
    // Falling for long, the velocity turns towards gravity but never exceeds the clamp.
    EXPECT_GT(world.velocity(box).y, world.velocity(box).x);
}

TEST(ClassicScenario, DampingDividesVelocity) {
    World world = classicWorld();
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .vx = 96, .damping = 4});
    world.step(kDt);
    // v /= 1 + 4 * 0.125 -> 64, then x += 64 * 0.125.
    EXPECT_EQ(world.velocity(box).x, 64.0f);
    EXPECT_EQ(world.position(box).x, 8.0f);
}

TEST(ClassicScenario, GravityScale) {
    World world = classicWorld({0, 8});
    BodyId floating = world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .gravityScale = 0});
    BodyId rising = world.createBody({.x = 10, .y = 0, .hw = 1, .hh = 1, .gravityScale = -1});
    world.step(kDt);
    EXPECT_EQ(world.velocity(floating), (Vec2{0, 0}));
    EXPECT_EQ(world.velocity(rising), (Vec2{0, -1}));
}

TEST(ClassicScenario, KinematicBodiesMoveByTheirVelocityOnly) {
    World world = classicWorld({0, 800});
    BodyId lift = world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = 0, .hw = 10, .hh = 2, .vx = 8, .vy = -16});
    world.createBody({.type = BodyType::Static, .x = 0, .y = -10, .hw = 100, .hh = 5});
    world.step(kDt);
    // No gravity and no collision for it: it goes through the static body.
    EXPECT_EQ(world.position(lift), (Vec2{1, -2}));
    world.step(kDt);
    EXPECT_EQ(world.position(lift), (Vec2{2, -4}));
    EXPECT_EQ(world.velocity(lift), (Vec2{8, -16}));
}

TEST(ClassicScenario, TheSeparationOfAStepAddsUp) {
    World world = classicWorld({0, 0});
    addFloor(world);
    // A wall on the right whose left edge is at x = 10.
    world.createBody({.type = BodyType::Static, .x = 20, .y = 0, .hw = 10, .hh = 100});
    BodyId box = world.createBody({.x = 4, .y = 4, .hw = 5, .hh = 5, .vx = 16, .vy = 16});
    world.step(kDt);
    // Moved to (6, 6): 1 into the floor (pushed up by 1) and 1 into the wall (pushed left).
    EXPECT_EQ(world.separation(box), (Vec2{-1, -1}));
    EXPECT_EQ(world.position(box), (Vec2{5, 5}));
    // The next step starts from zero.
    world.setVelocity(box, {0, -16});
    world.step(kDt);
    EXPECT_EQ(world.separation(box), (Vec2{0, 0}));
}

TEST(ClassicPreSolve, VetoLetsThePairPass) {
    World world = classicWorld();
    addFloor(world);
    BodyId box = world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vy = 16});
    int calls = 0;
    world.setPreSolve([&](Collision& c) {
        ++calls;
        EXPECT_EQ(c.a, box);
        EXPECT_EQ(c.normal, (Vec2{0, -1}));
        EXPECT_EQ(c.depth, 1.0f);
        return false;
    });
    world.step(kDt);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(world.position(box), (Vec2{0, 6}));
    EXPECT_EQ(world.velocity(box), (Vec2{0, 16}));
}

TEST(ClassicPreSolve, ChangesBounceAndFrictionForThisStep) {
    World world = classicWorld();
    addFloor(world, 0.5f, 0.0f);
    BodyId box = world.createBody({.x = 0, .y = 4, .hw = 5, .hh = 5, .vx = 8, .vy = 16});
    world.setPreSolve([](Collision& c) {
        EXPECT_EQ(c.bounce, 0.0f);
        EXPECT_EQ(c.friction, 0.5f);
        c.bounce = 1;
        c.friction = 0;
        return true;
    });
    world.step(kDt);
    EXPECT_EQ(world.velocity(box), (Vec2{8, -16})); // a perfect, frictionless bounce
}

} // namespace
} // namespace jostle
