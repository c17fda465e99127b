// Footing (docs/slopes-and-shapes.md): what counts as floor (BodyDef::floorAngle) and
// sticking to the ground (BodyDef::snapDown). Expected values come from the geometry of
// the level and the kinematics of a body leaving it.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 10.0f; // y grows downward
constexpr float kWalk = 8.0f;

/// Flat ground (top y = 5), a 45° ramp up (x 6 to 8), a flat top (y = 3, x 8 to 12), a 45°
/// ramp down (x 12 to 13), a 2:1 ramp down (x 13 to 15), flat ground again.
World hills() {
    World world(WorldDef{.gravity = {0, kG}});
    createTileMap(world, {.tile = 1,
                          .rows = {"........................", "........................",
                                   "........................", "......./####\\...........",
                                   "....../######Ll.........", "########################",
                                   "########################"}});
    return world;
}

BodyId walker(World& world, float snapDown) {
    const BodyId player = world.createBody(
        {.x = 1.5f, .y = 4.5f, .hw = 0.375f, .hh = 0.5f, .character = true, .snapDown = snapDown});
    world.setWalkSpeed(player, kWalk);
    return player;
}

/// Walks `player` to x = 20; the number of steps it ended off the ground, and the largest
/// difference between its horizontal speed and its walk speed.
struct Walk {
    int airborne = 0;
    float worstSpeed = 0.0f;
};
Walk walkAcross(World& world, BodyId player) {
    Walk walk;
    for (int i = 0; i < 600 && world.position(player).x < 20.0f; ++i) {
        world.step(kDt);
        walk.airborne += world.touching(player).floor ? 0 : 1;
        walk.worstSpeed = std::max(walk.worstSpeed, std::abs(world.velocity(player).x - kWalk));
    }
    EXPECT_GE(world.position(player).x, 20.0f) << "stuck";
    return walk;
}

TEST(SnapDown, ACharacterWalkingOverHillsAt8UnitsPerSecondStaysOnTheGroundEveryStep) {
    // A step at 8 units/s goes 8/60 = 0.13 across, so 0.13 down a 45° ramp: within 0.25.
    World world = hills();
    const BodyId player = walker(world, 0.25f);
    const Walk walk = walkAcross(world, player);
    EXPECT_EQ(walk.airborne, 0);
    EXPECT_LE(walk.worstSpeed, 0.01f * kWalk); // and never slowed at a junction
}

TEST(SnapDown, ACharacterFollowsTheFloorsItWalksOntoWithoutIt) {
    // A character snaps by at least what a step at its walk speed drops on the steepest
    // floor it stands on: 8/60 tan 60° = 0.23, more than the 0.13 of the 45° ramp down.
    World world = hills();
    const BodyId player = walker(world, 0.0f);
    const Walk walk = walkAcross(world, player);
    EXPECT_EQ(walk.airborne, 0);
    EXPECT_LE(walk.worstSpeed, 0.01f * kWalk);
}

TEST(SnapDown, WithoutItACrateSlidingOverTheSameHillsLeavesTheGround) {
    // Sent at 12 units/s, it tops the ramp up (2 high) at sqrt(12² - 2 g 2) = 10.2 and
    // leaves its crest rising at 10.2 sin 45° = 7.2 (to 7.2²/2g = 2.6 above it); off the
    // flat top onto the ramp down it falls g t²/2 while the ramp falls 10 t.
    World world = hills();
    const BodyId crate = world.createBody(
        {.x = 1.5f, .y = 4.5f, .hw = 0.375f, .hh = 0.5f, .vx = 12.0f, .friction = 0.0f});
    int airborne = 0;
    for (int i = 0; i < 600 && world.position(crate).x < 20.0f; ++i) {
        world.step(kDt);
        airborne += world.touching(crate).floor ? 0 : 1;
    }
    EXPECT_GE(world.position(crate).x, 20.0f) << "stuck";
    EXPECT_GT(airborne, 10);
}

TEST(SnapDown, AJumpIsNotPulledBack) {
    World world = hills();
    const BodyId player = walker(world, 0.25f);
    world.setWalkSpeed(player, 0.0f);
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    ASSERT_TRUE(world.touching(player).floor);
    world.setVelocity(player, {0.0f, -5.0f});
    world.step(kDt);
    EXPECT_FALSE(world.touching(player).floor);
    // It rose by the jump's speed less gravity's: (5 - 10/60) / 60 from where it stood.
    EXPECT_NEAR(world.position(player).y, 4.5f - (5.0f - kG * kDt) * kDt, 1e-4f);
}

TEST(SnapDown, OffACliffHigherThanItsReachItFalls) {
    World world(WorldDef{.gravity = {0, kG}});
    createTileMap(world, {.tile = 1, .rows = {"######....", "######....", "##########"}});
    // Walking off the top (y = 0) at 8 units/s: the floor below (y = 2) is 2 down, beyond 0.25.
    const BodyId player = world.createBody(
        {.x = 4.5f, .y = -0.5f, .hw = 0.375f, .hh = 0.5f, .character = true, .snapDown = 0.25f});
    world.setWalkSpeed(player, kWalk);
    // Its left side passes the edge (x = 6) after (6.375 - 4.5) / 8 s, in step 15.
    for (int i = 0; i < 20; ++i)
        world.step(kDt);
    EXPECT_FALSE(world.touching(player).floor);
    EXPECT_GT(world.position(player).y, -0.5f);
    EXPECT_GT(world.velocity(player).y, 0.0f);
}

/// A box at rest on a 45° ramp rising to the right (friction 1.2 > tan 45° holds it), its
/// bottom-right corner on the slope y = -x.
BodyId boxOnRamp(World& world, float floorAngle, bool character) {
    world.createBody({.type = BodyType::Static,
                      .x = -5,
                      .y = 5,
                      .hw = 5,
                      .hh = 5,
                      .friction = 1,
                      .slope = {-1, -1}});
    return world.createBody({.x = -3.5f,
                             .y = 2.5f,
                             .hw = 0.5f,
                             .hh = 0.5f,
                             .friction = 1,
                             .character = character,
                             .floorAngle = floorAngle});
}

TEST(FloorAngle, A45DegreeSlopeIsAFloorWithin60AndAWallWithin40) {
    for (float angle : {60.0f, 40.0f}) {
        World world(WorldDef{.gravity = {0, kG}});
        const BodyId box = boxOnRamp(world, angle, false);
        for (int i = 0; i < 30; ++i)
            world.step(kDt);
        const Touching t = world.touching(box);
        EXPECT_EQ(t.floor, angle > 45.0f) << angle;
        // The slope pushes it up and to the left: seen along gravity, a wall on its right.
        EXPECT_EQ(t.wallRight, angle < 45.0f) << angle;
        EXPECT_EQ(world.ground(box).has_value(), angle > 45.0f) << angle;
    }
}

TEST(FloorAngle, ACharacterSlidesDownASlopeSteeperThanItsFloorAngle) {
    // Against a 45° slope steeper than its 30°, a character rubs with its wall friction (0):
    // it slides as on a frictionless incline, at g sin 45° t after t, standing still or
    // walking into the slope.
    for (float walk : {0.0f, 2.0f}) { // the slope is on its right
        World world(WorldDef{.gravity = {0, kG}});
        const BodyId hero = boxOnRamp(world, 30.0f, true);
        world.step(kDt); // on the slope, at rest
        world.setWalkSpeed(hero, walk);
        for (int i = 1; i < 60; ++i)
            world.step(kDt);
        const float k = std::numbers::sqrt2_v<float> / 2.0f;
        const Vec2 downhill{-k, k};
        EXPECT_NEAR(dot(world.velocity(hero), downhill), kG * k * 1.0f, 0.01f * kG * k) << walk;
        EXPECT_FALSE(world.ground(hero).has_value());
    }
}

TEST(FloorAngle, ItIsCheckedAndKept) {
    World world(WorldDef{.gravity = {0, kG}});
    const BodyId box = world.createBody({.hw = 1, .hh = 1, .floorAngle = 45, .snapDown = 2});
    EXPECT_EQ(world.floorAngle(box), 45.0f);
    EXPECT_EQ(world.snapDown(box), 2.0f);
    EXPECT_EQ(world.bodyDef(box).floorAngle, 45.0f);
    world.setFloorAngle(box, 0.0f);
    world.setSnapDown(box, 0.0f);
    EXPECT_EQ(world.bodyDef(box).floorAngle, 0.0f);
    EXPECT_EQ(world.bodyDef(box).snapDown, 0.0f);
    EXPECT_THROW(world.setFloorAngle(box, 90.0f), Error);
    EXPECT_THROW(world.setFloorAngle(box, std::nanf("")), Error);
    EXPECT_THROW(world.setSnapDown(box, -1.0f), Error);
    EXPECT_EQ(checkBodyDef({.hw = 1, .hh = 1, .floorAngle = -1})->field, "floorAngle");
    EXPECT_EQ(checkBodyDef({.hw = 1, .hh = 1, .snapDown = -1})->field, "snapDown");
}

// fuzz_restore found a world whose gravity (1.5612e-39, 0) was too weak for its length to
// be a float: "down" came out NaN, and so did a character snapping down to its floor.
TEST(Down, FuzzNaN_GravityTooWeakForItsLengthStillPointsWhereItPulls) {
    World world(WorldDef{.gravity = {1.5612e-39f, 0}}); // down is +x: the block is a floor
    world.createBody({.type = BodyType::Static, .x = 2, .hw = 1, .hh = 5});
    const BodyId player = world.createBody(
        {.hw = 0.5f, .hh = 0.5f, .vx = 5, .character = true, .snapDown = 1, .radius = 0.25f});
    bool floor = false, wall = false;
    for (int step = 0; step < 30; ++step) {
        world.step(kDt);
        ASSERT_TRUE(std::isfinite(world.position(player).x)) << "step " << step;
        ASSERT_TRUE(std::isfinite(world.position(player).y)) << "step " << step;
        floor = floor || world.touching(player).floor;
        wall = wall || world.touching(player).wallRight || world.touching(player).wallLeft;
    }
    EXPECT_TRUE(floor); // it ran into the block along +x, where gravity pulls: a floor
    EXPECT_FALSE(wall);
}

} // namespace
} // namespace jostle
