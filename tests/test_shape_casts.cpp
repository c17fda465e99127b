// Sweeps and queries against shapes (ramps, segments, rounded bodies): they meet the true
// shape, not its box. Every expected value is worked out by hand in the comments.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
const float kRoot2 = std::sqrt(2.0f);

// --- Continuous collision ----------------------------------------------------------------
//
// The segment of these tests: the box (1000, 0) ± 50 cut along the diagonal whose face looks
// up and left ({-1, -1} in a y-down world): the line x + y = 1000 from (950, 50) to
// (1050, -50), with the unit normal (-1, -1)/√2. A circle of radius 4 touches it from the
// front when its centre is 4 from the line: x + y = 1000 - 4√2 = 994.343. The contact
// skin of the pair is twice the slop (1%) of the smaller reach along the normal (the
// circle's, 4): 0.08; so the centre never gets nearer the line than 3.92: x + y <=
// 1000 - 3.92√2 = 994.456.

BodyDef segmentAt(float x, float y) {
    return {.type = BodyType::Static,
            .x = x,
            .y = y,
            .hw = 50,
            .hh = 50,
            .slope = {-1, -1},
            .segment = true};
}

BodyDef circleAt(float x, float y, float vx) {
    return {.x = x, .y = y, .hw = 4, .hh = 4, .vx = vx, .radius = 4};
}

TEST(ShapeSweeps, AFastCircleDoesNotPassAOneSidedSegment) {
    // 30,000 units/s is 500 units a step: the line falls between two positions.
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody(segmentAt(1000, 0));
    BodyId circle = world.createBody(circleAt(0, 0, 30000));
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        const Vec2 p = world.position(circle);
        ASSERT_LE(p.x + p.y, 1000.0f - 3.92f * kRoot2 + 1e-3f) << "step " << i;
    }
    // It met the line and slides along it, up and to the right: what went into it is gone.
    const Vec2 v = world.velocity(circle);
    EXPECT_GT(v.x, 0.0f);
    EXPECT_NEAR(v.x + v.y, 0.0f, 1e-2f);
}

TEST(ShapeSweeps, AFastCirclePassesAOneSidedSegmentFromBehind) {
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody(segmentAt(1000, 0));
    BodyId circle = world.createBody(circleAt(2000, 0, -30000));
    for (int i = 0; i < 4; ++i)
        world.step(kDt);
    // Four steps of 500 units, from 2000, through the line at x = 1000, untouched.
    EXPECT_NEAR(world.position(circle).x, 0.0f, 0.01f);
    EXPECT_EQ(world.position(circle).y, 0.0f);
    EXPECT_EQ(world.velocity(circle).x, -30000.0f);
}

/// A body at rest struck at 30,000 units/s by a kinematic paddle along `direction`: only
/// the sweep, after the solver, sees where it then goes. The paddle stops after the strike.
BodyId struck(World& world, BodyDef def, Vec2 direction) {
    world.createBody({.type = BodyType::Kinematic,
                      .x = def.x - direction.x * (def.hw + 46),
                      .y = def.y - direction.y * (def.hh + 46),
                      .hw = direction.x != 0 ? 10.0f : 50.0f,
                      .hh = direction.x != 0 ? 50.0f : 10.0f,
                      .vx = direction.x * 30000,
                      .vy = direction.y * 30000});
    return world.createBody(def);
}

void stopPaddle(World& world) {
    for (BodyId id : world.bodies())
        if (world.type(id) == BodyType::Kinematic)
            world.setVelocity(id, {0, 0});
}

TEST(ShapeSweeps, ACircleStruckTowardsASegmentStopsAtIt) {
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody(segmentAt(200, 0)); // the line x + y = 200
    BodyId circle = struck(world, circleAt(0, 0, 0), {1, 0});
    world.step(kDt);
    stopPaddle(world);
    const Vec2 v = world.velocity(circle);
    EXPECT_GT(v.x, 10000.0f); // struck hard
    // Stopped at the line by the sweep, it slides along it: x + y stays 200 - 4√2, within
    // the skin.
    EXPECT_NEAR(v.x + v.y, 0.0f, 1e-2f);
    for (int i = 0; i < 10; ++i) {
        const Vec2 p = world.position(circle);
        ASSERT_LE(p.x + p.y, 200.0f - 3.92f * kRoot2 + 1e-3f) << "step " << i;
        ASSERT_GE(p.x + p.y, 200.0f - 4.0f * kRoot2 - 1e-3f) << "step " << i;
        world.step(kDt);
    }
}

TEST(ShapeSweeps, ACircleStruckTowardsASegmentFromBehindPassesIt) {
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody(segmentAt(200, 0)); // its box: 150 to 250
    BodyId circle = struck(world, circleAt(400, 0, 0), {-1, 0});
    world.step(kDt);
    EXPECT_LT(world.position(circle).x, 150.0f - 4.0f); // beyond the segment's whole box
    EXPECT_LT(world.velocity(circle).x, -10000.0f);
    EXPECT_EQ(world.velocity(circle).y, 0.0f);
}

// The ramp: the box (1000, 0) ± 50 cut as the segment above, solid behind its slope, above
// a floor whose top is y = 100, with a wall whose right face is x = 500. A box of half
// extent 2 touches the slope when its lower right corner is on the line x + y = 1000: its
// centre on x + y = 996. Skin: 2% of the smaller reach along the normal, the box's
// (|nx| 2 + |ny| 2 = 2√2) against the ramp's 50: 0.0566, so x + y <= 996 + 0.0566 √2 =
// 996.08. Off the slope's foot (950, 50) the box falls to the floor, on the slope's side:
// x <= 948, y = 98.

World rampWorld() {
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    world.createBody(
        {.type = BodyType::Static, .x = 1000, .y = 0, .hw = 50, .hh = 50, .slope = {-1, -1}});
    world.createBody({.type = BodyType::Static, .x = 1000, .y = 110, .hw = 1000, .hh = 10});
    world.createBody({.type = BodyType::Static, .x = 495, .y = 0, .hw = 5, .hh = 200});
    return world;
}

void expectOnTheSlopeSide(World& world, BodyId box, int steps) {
    for (int i = 0; i < steps; ++i) {
        world.step(kDt);
        // In front of the slope, or below the ramp's box (its top at 52 - 2 = 50 or lower).
        const Vec2 p = world.position(box);
        ASSERT_TRUE(p.x + p.y <= 996.08f + 1e-3f || p.y >= 52.0f) << "step " << i;
    }
    // On the floor, left of the slope's foot, within the floor's skin (1% of 2, twice).
    EXPECT_LE(world.position(box).x, 948.0f + 1e-3f);
    EXPECT_NEAR(world.position(box).y, 98.0f, 0.05f);
}

TEST(ShapeSweeps, ABoxStruckOntoARampSlidesDownItsSlope) {
    World world = rampWorld();
    BodyId box = struck(world, {.x = 1000, .y = -300, .hw = 2, .hh = 2}, {0, 1});
    world.step(kDt);
    stopPaddle(world);
    // It hit the slope above x = 1000 (at y = -4) and lost what went into it: (0, V)
    // became (0, V) - n (n · (0, V)) = (-V/2, V/2), down the slope, which it left at its
    // foot; 50 lower it met the floor, which took the rest of its fall: (-V/2, 0), all in
    // the step.
    const Vec2 p = world.position(box), v = world.velocity(box);
    EXPECT_LT(v.x, -5000.0f);
    EXPECT_EQ(v.y, 0.0f);
    EXPECT_LT(p.x, 950.0f - 2.0f);
    EXPECT_NEAR(p.y, 98.0f, 0.05f);
    expectOnTheSlopeSide(world, box, 120);
    EXPECT_NEAR(world.position(box).x, 502.0f, 0.05f); // it went on to the wall at 500
}

TEST(ShapeSweeps, ABoxFallingFastOntoARampDoesNotPassIt) {
    // 30,000 units/s down, from phases that put the slope at different points of a step.
    for (float start : {-2000.0f, -2123.0f, -2250.0f, -2377.0f, -2498.0f}) {
        World world = rampWorld();
        BodyId box = world.createBody({.x = 1000, .y = start, .hw = 2, .hh = 2, .vy = 30000});
        SCOPED_TRACE(start);
        expectOnTheSlopeSide(world, box, 200);
    }
}

// The sweep stops a body where it would go deeper than the skin, as between boxes: around
// a rounded corner, where its centre is the outline's radius less the skin from the
// corner. The skin there is that of the faces beside the corner (twice the slop of the
// smaller half extent across them, 2% of it).

TEST(ShapeSweeps, ABoxStruckPastACirclesBoxCornerMeetsTheCircle) {
    // A static circle of radius 20 at (200, 0); a box of half extent 2 struck along
    // y = -18. Its centre meets the circle's outline (the circle's centre grown by the
    // box: the square ±2 rounded by 20) near the square's corner (-2, -2). Skin: 2% of 2,
    // 0.04, so the sweep stops it 19.96 from the corner: (x + 2)² + 16² = 19.96², x + 2 =
    // -11.9332, x = 186.0668. The normal there is (-11.9332, -16) / 19.96 = (-0.59786,
    // -0.80160). Its box alone would have stopped the box at x = 178, with the normal -x.
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody(
        {.type = BodyType::Static, .x = 200, .y = 0, .hw = 20, .hh = 20, .radius = 20});
    BodyId box = struck(world, {.x = 0, .y = -18, .hw = 2, .hh = 2}, {1, 0});
    world.step(kDt);
    // What goes into the circle is gone: (V, 0) - n (V nx) = V (1 - nx², -nx ny), whose
    // slope is -nx ny / (1 - nx²) = -0.47924 / 0.64256 = -0.74583. The step's move then
    // takes it from the hit by that velocity.
    const Vec2 v = world.velocity(box);
    EXPECT_GT(v.x, 5000.0f);
    EXPECT_NEAR(v.y / v.x, -0.74583f, 5e-4f);
    // Position correction then pushed it out along the normal, by less than the skin.
    const Vec2 fromCorner = world.position(box) - v * kDt - Vec2{198, -2};
    EXPECT_GE(length(fromCorner), 19.96f - 1e-3f);
    EXPECT_LE(length(fromCorner), 20.0f);
    EXPECT_NEAR(fromCorner.x / length(fromCorner), -0.59786f, 1e-3f);
    EXPECT_NEAR(fromCorner.y / length(fromCorner), -0.80160f, 1e-3f);
}

TEST(ShapeSweeps, ACircleStruckPastABoxsCornerRollsOverIt) {
    // A circle of radius 5 struck along y = -13 at a static box (200, 0) ± 10: its centre
    // meets the box grown by 5 near the corner (190, -10). Skin: 2% of 5, 0.1, so it stops
    // 4.9 from the corner: (x - 190)² + 3² = 4.9², x = 190 - 3.87427 = 186.12573; the
    // normal (-3.87427, -3) / 4.9 = (-0.79067, -0.61224).
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 200, .y = 0, .hw = 10, .hh = 10});
    BodyId circle = struck(world, {.x = 0, .y = -13, .hw = 5, .hh = 5, .radius = 5}, {1, 0});
    world.step(kDt);
    // Slope of what is left: -nx ny / (1 - nx²) = -0.48408 / 0.37484 = -1.29143.
    const Vec2 v = world.velocity(circle);
    EXPECT_GT(v.x, 2000.0f);
    EXPECT_NEAR(v.y / v.x, -1.29143f, 5e-4f);
    const Vec2 fromCorner = world.position(circle) - v * kDt - Vec2{190, -10};
    EXPECT_GE(length(fromCorner), 4.9f - 1e-3f);
    EXPECT_LE(length(fromCorner), 5.0f);
    EXPECT_NEAR(fromCorner.x / length(fromCorner), -0.79067f, 1e-3f);
    EXPECT_NEAR(fromCorner.y / length(fromCorner), -0.61224f, 1e-3f);
}

} // namespace
} // namespace jostle
