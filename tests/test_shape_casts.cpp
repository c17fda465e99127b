// Sweeps and queries against shapes (ramps, segments, rounded bodies): they meet the true
// shape, not its box. Every expected value is worked out by hand in the comments.
#include "jostle/query.hpp"
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

/// After a step in which `body`, struck along +x, hit a rounded corner of an outline at
/// `corner` (in the world) whose radius is `radius`: what is left of its velocity has the
/// slope `slope` (vy / vx), and where the step's move started from, the hit, lies between
/// `stopped` (the radius less the skin) and `radius` from the corner (position correction
/// pushes it out along the normal, less than the skin), along `normal`.
void expectRoundedHit(const World& world, BodyId body, Vec2 corner, float stopped, float radius,
                      Vec2 normal, float slope) {
    const Vec2 v = world.velocity(body);
    EXPECT_GT(v.x, 2000.0f); // struck hard
    EXPECT_NEAR(v.y / v.x, slope, 5e-4f);
    const Vec2 fromCorner = world.position(body) - v * kDt - corner;
    const float distance = length(fromCorner);
    EXPECT_GE(distance, stopped - 1e-3f);
    EXPECT_LE(distance, radius);
    EXPECT_NEAR(fromCorner.x / distance, normal.x, 1e-3f);
    EXPECT_NEAR(fromCorner.y / distance, normal.y, 1e-3f);
}

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
    expectRoundedHit(world, box, {198, -2}, 19.96f, 20.0f, {-0.59786f, -0.80160f}, -0.74583f);
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
    expectRoundedHit(world, circle, {190, -10}, 4.9f, 5.0f, {-0.79067f, -0.61224f}, -1.29143f);
}

// --- Queries -------------------------------------------------------------------------------
//
// The shapes of these tests, all at the origin in a world without gravity:
// - the circle of radius 10 (the box ±10 rounded by 10);
// - the ramp ±10 facing up and left ({-1, -1}): the triangle behind the line x + y = 0
//   from (-10, 10) to (10, -10), normal (-1, -1)/√2;
// - the segment: that line alone, blocking from the up-left side.

constexpr float kHalfRoot2 = 0.70710678f;

World emptyWorld() {
    return World(WorldDef{.gravity = {0, 0}, .sleeping = false});
}

BodyId circleBody(World& world, float x = 0, float y = 0) {
    return world.createBody(
        {.type = BodyType::Static, .x = x, .y = y, .hw = 10, .hh = 10, .radius = 10});
}

BodyId rampBody(World& world, float hw = 10, float hh = 10, bool segment = false) {
    return world.createBody({.type = BodyType::Static,
                             .x = 0,
                             .y = 0,
                             .hw = hw,
                             .hh = hh,
                             .slope = {-1, -1},
                             .segment = segment});
}

void expectNormal(Vec2 normal, Vec2 expected) {
    EXPECT_NEAR(normal.x, expected.x, 1e-5f);
    EXPECT_NEAR(normal.y, expected.y, 1e-5f);
}

TEST(ShapeQueries, ARayHitsACircleAtTheCircleNotAtItsBoxCorner) {
    World world = emptyWorld();
    BodyId circle = circleBody(world);
    // Along the diagonal from (-20, -20) to (20, 20): the circle at (-10, -10)/√2 =
    // (-7.0711, -7.0711), a fraction (20 - 7.0711)/40 = 0.32322 along, where the normal
    // points back along the ray. The box's corner (-10, -10) would be at 0.25.
    std::optional<RayHit> hit = rayCast(world, {-20, -20}, {20, 20});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, circle);
    EXPECT_NEAR(hit->fraction, 0.32322f, 1e-5f);
    EXPECT_NEAR(hit->point.x, -7.0711f, 1e-4f);
    EXPECT_NEAR(hit->point.y, -7.0711f, 1e-4f);
    expectNormal(hit->normal, {-kHalfRoot2, -kHalfRoot2});
    // The line x + y = -19 crosses the box's corner and passes 19/√2 = 13.4 from the centre.
    EXPECT_FALSE(rayCast(world, {-11, -8}, {-8, -11}));
    // Its flat part is its box's face: hit there exactly, along the axis.
    hit = rayCast(world, {-30, 0}, {30, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->point.x, -10.0f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    EXPECT_NEAR(hit->fraction, 20.0f / 60.0f, 1e-6f);
}

TEST(ShapeQueries, ARayHitsARampOnItsSlopeWithTheSlopesNormal) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    // Along y = 0 from x = -20: the slope at x = 0, halfway; the box's face at -10 would
    // be a quarter of the way.
    std::optional<RayHit> hit = rayCast(world, {-20, 0}, {20, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, ramp);
    EXPECT_NEAR(hit->fraction, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->point.x, 0.0f, 1e-5f);
    expectNormal(hit->normal, {-kHalfRoot2, -kHalfRoot2});
    // From behind, through its leg x = 10: the box face, exactly, along x.
    hit = rayCast(world, {20, 5}, {-20, 5});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->point, (Vec2{10, 5}));
    EXPECT_EQ(hit->normal, (Vec2{1, 0}));
    EXPECT_NEAR(hit->fraction, 0.25f, 1e-6f);
    // Through the cut-away half only: nothing there.
    EXPECT_FALSE(rayCast(world, {-20, -9}, {0, -11}));
}

TEST(ShapeQueries, ARayHitsAShallowRampOnItsSlope) {
    // The ramp ±(20, 10) facing up and left: the line x/20 + y/10 = 0, x + 2y = 0, normal
    // (-10, -20)/√500 = (-0.44721, -0.89443). Straight down at x = 5 from y = -20: the
    // slope at y = -2.5, 17.5 of 40 along.
    World world = emptyWorld();
    rampBody(world, 20, 10);
    const std::optional<RayHit> hit = rayCast(world, {5, -20}, {5, 20});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->fraction, 0.4375f, 1e-6f);
    EXPECT_NEAR(hit->point.y, -2.5f, 1e-5f);
    expectNormal(hit->normal, {-0.44721f, -0.89443f});
}

TEST(ShapeQueries, ASegmentIsHitByARayOnlyFromItsBlockingSide) {
    World world = emptyWorld();
    BodyId segment = rampBody(world, 10, 10, true);
    const std::optional<RayHit> hit = rayCast(world, {-20, 0}, {20, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, segment);
    EXPECT_NEAR(hit->fraction, 0.5f, 1e-6f);
    expectNormal(hit->normal, {-kHalfRoot2, -kHalfRoot2});
    EXPECT_FALSE(rayCast(world, {20, 0}, {-20, 0}));  // from behind
    EXPECT_FALSE(rayCast(world, {5, 5}, {-20, -20})); // from behind, starting in its box
    EXPECT_FALSE(rayCast(world, {20, 5}, {-20, 5}));  // through its box's side, behind it
    EXPECT_TRUE(rayCastAll(world, {20, 0}, {-20, 0}).empty());
    const std::vector<RayHit> all = rayCastAll(world, {-20, 0}, {20, 0});
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].body, segment);
}

TEST(ShapeQueries, RayCastAllOrdersShapesByWhereTheyAreHit) {
    // A circle at (0, 0) and a ramp at (30, 0) facing up and left, along y = 5 from the
    // left: the circle at x = -√75 = -8.6603, the ramp's slope x + y = 30 at x = 25.
    World world = emptyWorld();
    BodyId circle = circleBody(world);
    BodyId ramp = world.createBody(
        {.type = BodyType::Static, .x = 30, .y = 0, .hw = 10, .hh = 10, .slope = {-1, -1}});
    const std::vector<RayHit> all = rayCastAll(world, {-20, 5}, {60, 5});
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].body, circle);
    EXPECT_NEAR(all[0].point.x, -8.6603f, 1e-4f);
    EXPECT_EQ(all[1].body, ramp);
    EXPECT_NEAR(all[1].point.x, 25.0f, 1e-4f);
}

TEST(ShapeQueries, APointInTheCutAwayHalfOfARampIsNotInIt) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    EXPECT_TRUE(queryPoint(world, {-5, -5}).empty()); // x + y = -10: in front of the slope
    EXPECT_EQ(queryPoint(world, {5, 5}), std::vector<BodyId>{ramp});
    EXPECT_EQ(queryPoint(world, {0, 0}), std::vector<BodyId>{ramp});    // on the slope
    EXPECT_EQ(queryPoint(world, {10, -10}), std::vector<BodyId>{ramp}); // its tip
}

TEST(ShapeQueries, APointInACirclesBoxCornerIsNotInTheCircle) {
    World world = emptyWorld();
    BodyId circle = circleBody(world);
    EXPECT_TRUE(queryPoint(world, {9, 9}).empty());                      // 12.7 from the centre
    EXPECT_EQ(queryPoint(world, {7, 7}), std::vector<BodyId>{circle});   // 9.9
    EXPECT_EQ(queryPoint(world, {0, -10}), std::vector<BodyId>{circle}); // on it
}

TEST(ShapeQueries, APointIsOnASegmentOnlyOnItsLine) {
    World world = emptyWorld();
    BodyId segment = rampBody(world, 10, 10, true);
    EXPECT_EQ(queryPoint(world, {0, 0}), std::vector<BodyId>{segment});
    EXPECT_EQ(queryPoint(world, {-10, 10}), std::vector<BodyId>{segment}); // an end
    EXPECT_TRUE(queryPoint(world, {5, 5}).empty());
    EXPECT_TRUE(queryPoint(world, {-5, -5}).empty());
}

TEST(ShapeQueries, ABoxOverlapsAShapeWhereTheyShareArea) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    // Boxes of half extent 2 along the diagonal: the one at (-2, -2) has its corner (0, 0)
    // on the slope (touching); the one at (-1, -1) reaches (1, 1), behind it.
    EXPECT_TRUE(queryBox(world, {-7, -7}, {2, 2}).empty());
    EXPECT_TRUE(queryBox(world, {-2, -2}, {2, 2}).empty());
    EXPECT_EQ(queryBox(world, {-1, -1}, {2, 2}), std::vector<BodyId>{ramp});
    EXPECT_EQ(queryRect(world, {-3, -3}, {1, 1}), std::vector<BodyId>{ramp});
    // A box of size 0 overlaps what holds its centre inside.
    EXPECT_TRUE(queryBox(world, {-5, -5}, {0, 0}).empty());
    EXPECT_EQ(queryBox(world, {5, 5}, {0, 0}), std::vector<BodyId>{ramp});

    World circles = emptyWorld();
    BodyId circle = circleBody(circles);
    // The box ±0.5 at (9, 9): its nearest point (8.5, 8.5) is 12.02 from the centre; at
    // (7, 7), (6.5, 6.5) is 9.19.
    EXPECT_TRUE(queryBox(circles, {9, 9}, {0.5f, 0.5f}).empty());
    EXPECT_EQ(queryBox(circles, {7, 7}, {0.5f, 0.5f}), std::vector<BodyId>{circle});
}

TEST(ShapeQueries, ABoxOverlapsASegmentItCrosses) {
    World world = emptyWorld();
    BodyId segment = rampBody(world, 10, 10, true);
    EXPECT_EQ(queryBox(world, {-1, -1}, {2, 2}), std::vector<BodyId>{segment});
    EXPECT_TRUE(queryBox(world, {5, 5}, {2, 2}).empty());   // wholly behind it: (3, 3) on
    EXPECT_TRUE(queryBox(world, {-5, -5}, {2, 2}).empty()); // wholly in front: (-3, -3) on
    EXPECT_TRUE(queryBox(world, {2, 2}, {2, 2}).empty());   // its corner (0, 0) on the line
}

// A box of half extent 2 touches the ramp's slope (x + y = 0) when its lower right corner
// is on it: its centre on x + y = -4.

TEST(ShapeQueries, ABoxCastStopsOnARampsSlope) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    // From (-20, 0) to the right: the centre reaches x + y = -4 at x = -4, 16 of 40.
    const std::optional<BoxCastHit> hit = boxCast(world, {-20, 0}, {2, 2}, {40, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, ramp);
    EXPECT_NEAR(hit->fraction, 0.4f, 1e-6f);
    EXPECT_NEAR(hit->centre.x, -4.0f, 1e-5f);
    EXPECT_NEAR(hit->centre.y, 0.0f, 1e-5f);
    expectNormal(hit->normal, {-kHalfRoot2, -kHalfRoot2});
    // Through the cut-away half of the ramp's box, along the slope: the centre stays on
    // x + y = -14, the box's nearest corner on x + y = -10.
    EXPECT_FALSE(boxCast(world, {-20, 6}, {2, 2}, {26, -26}));
    // A segment stops it only from its side.
    World segments = emptyWorld();
    rampBody(segments, 10, 10, true);
    EXPECT_TRUE(boxCast(segments, {-20, 0}, {2, 2}, {40, 0}));
    EXPECT_FALSE(boxCast(segments, {20, 0}, {2, 2}, {-40, 0}));
}

TEST(ShapeQueries, ABoxCastMeetsACircleAroundItsCorner) {
    // A box of half extent 2 moving right along y = -18 past the circle of radius 20 at
    // the origin: its centre touches the circle's outline (±2 rounded by 20) where it is 20
    // from (-2, -2): (x + 2)² + 16² = 20², x = -14, normal (-12, -16)/20.
    World world = emptyWorld();
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 20, .hh = 20, .radius = 20});
    const std::optional<BoxCastHit> hit = boxCast(world, {-40, -18}, {2, 2}, {80, 0});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->fraction, 26.0f / 80.0f, 1e-5f);
    EXPECT_NEAR(hit->centre.x, -14.0f, 1e-4f);
    EXPECT_NEAR(hit->centre.y, -18.0f, 1e-4f);
    expectNormal(hit->normal, {-0.6f, -0.8f});
}

TEST(ShapeQueries, MoveAndSlideSlidesAlongARampsSlope) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    // Down from (0, -20) by 30: on the slope at (0, -4) after 16, the 14 left become
    // (0, 14) - n (n · (0, 14)) = (-7, 7) along the slope: it ends at (-7, 3).
    MoveResult moved = moveAndSlide(world, {0, -20}, {2, 2}, {0, 30});
    EXPECT_NEAR(moved.centre.x, -7.0f, 1e-4f);
    EXPECT_NEAR(moved.centre.y, 3.0f, 1e-4f);
    ASSERT_EQ(moved.hits.size(), 1u);
    EXPECT_EQ(moved.hits[0].body, ramp);
    expectNormal(moved.hits[0].normal, {-kHalfRoot2, -kHalfRoot2});
    // Right from (-20, 0) by 40: on the slope at (-4, 0) after 16, the 24 left become
    // (12, -12), up the slope to (8, -12), where its corner reaches the ramp's top tip.
    moved = moveAndSlide(world, {-20, 0}, {2, 2}, {40, 0});
    EXPECT_NEAR(moved.centre.x, 8.0f, 1e-4f);
    EXPECT_NEAR(moved.centre.y, -12.0f, 1e-4f);
    ASSERT_EQ(moved.hits.size(), 1u);
}

TEST(ShapeQueries, MoveAndSlideStopsInTheCreaseOfARampAndAWall) {
    // A wall whose right face is x = -6, beside the slope. A box moving down along x = -4,
    // its left face on the wall's, meets the slope x + y = -4 at y = 0 after 20 of 30. The
    // 10 left would slide along the slope, (-5, 5), into the wall; along the wall, (0, 10),
    // into the slope: it stays at (-4, 0), against both.
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    BodyId wall =
        world.createBody({.type = BodyType::Static, .x = -50, .y = 0, .hw = 44, .hh = 40});
    const MoveResult moved = moveAndSlide(world, {-4, -20}, {2, 2}, {0, 30});
    EXPECT_NEAR(moved.centre.x, -4.0f, 1e-4f);
    EXPECT_NEAR(moved.centre.y, 0.0f, 1e-4f);
    ASSERT_EQ(moved.hits.size(), 2u);
    EXPECT_EQ(moved.hits[0].body, ramp);
    EXPECT_EQ(moved.hits[1].body, wall);
    EXPECT_EQ(moved.hits[1].normal, (Vec2{1, 0}));
}

TEST(ShapeQueries, MoveSlidesAndBouncesOffASlope) {
    World world = emptyWorld();
    BodyId ramp = rampBody(world);
    BodyId box =
        world.createBody({.type = BodyType::Kinematic, .x = 0, .y = -20, .hw = 2, .hh = 2});
    MoveOutcome out = move(world, box, {0, 30});
    EXPECT_NEAR(out.centre.x, -7.0f, 1e-4f);
    EXPECT_NEAR(out.centre.y, 3.0f, 1e-4f);
    EXPECT_EQ(world.position(box), out.centre);
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, ramp);
    EXPECT_NEAR(out.collisions[0].time, 16.0f / 30.0f, 1e-6f);
    // Bouncing: right from (-20, 0) by 40, the slope at (-4, 0); the 24 left reflect off it
    // to (24, 0) - 2 n (n · (24, 0)) = (0, -24): it ends at (-4, -24).
    world.setPosition(box, {-20, 0});
    out = move(world, box, {40, 0}, [](BodyId) { return Response::Bounce; });
    EXPECT_NEAR(out.centre.x, -4.0f, 1e-4f);
    EXPECT_NEAR(out.centre.y, -24.0f, 1e-4f);
}

TEST(ShapeQueries, MoveTakesARoundedBodysOwnShape) {
    // A kinematic circle of radius 5 moved right along y = -13 past the static box ±10:
    // it touches the box's corner (-10, -10) where its centre is 5 from it: (x + 10)² + 3²
    // = 5², x = -14, normal (-4, -3)/5. The 14 left slide to (14, 0) - n (n · (14, 0)) =
    // (5.04, -6.72), round the corner and away: it ends at (-8.96, -19.72). As a box it
    // would have stopped at x = -15 against the box's side.
    World world = emptyWorld();
    BodyId wall = world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 10, .hh = 10});
    BodyId circle = world.createBody(
        {.type = BodyType::Kinematic, .x = -40, .y = -13, .hw = 5, .hh = 5, .radius = 5});
    const MoveOutcome out = move(world, circle, {40, 0});
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, wall);
    expectNormal(out.collisions[0].normal, {-0.8f, -0.6f});
    EXPECT_NEAR(out.collisions[0].touch.x, -14.0f, 1e-4f);
    EXPECT_NEAR(out.centre.x, -8.96f, 1e-3f);
    EXPECT_NEAR(out.centre.y, -19.72f, 1e-3f);
}

// --- Agreement with the point and box queries --------------------------------------------
//
// Rays and casts cross outlines (shape_casts.cpp's crossOutline); the point and box queries
// measure distances to them. On random whole-number worlds of one shape at the origin, the
// two agree: a ray meets nothing before its hit, and meets the shape there; a cast box does
// not go into the shape deeper than the skin before it stops, and touches it where it stops.

/// A small generator of its own: the same numbers everywhere.
struct Numbers {
    std::uint32_t state;
    int between(int low, int high) {
        state = state * 1664525u + 1013904223u;
        return low + int((state >> 8) % std::uint32_t(high - low + 1));
    }
};

BodyDef randomShape(Numbers& numbers) {
    BodyDef def{.type = BodyType::Static};
    def.hw = float(numbers.between(2, 12));
    def.hh = float(numbers.between(2, 12));
    switch (numbers.between(0, 3)) {
    case 0: // a circle, a capsule or a rounded box
        def.radius = std::min(def.hw, def.hh) * float(numbers.between(1, 4)) / 4.0f;
        break;
    case 1:
        def.hh = def.hw;
        def.radius = def.hw;
        break;
    default: // a ramp, or a segment, facing any corner
        def.slope = {numbers.between(0, 1) ? 1.0f : -1.0f, numbers.between(0, 1) ? 1.0f : -1.0f};
        def.segment = numbers.between(0, 2) == 0;
        break;
    }
    return def;
}

Vec2 randomPoint(Numbers& numbers) {
    return {float(numbers.between(-30, 30)), float(numbers.between(-30, 30))};
}

// --- Rounded casts: circles and capsules moved through the world ------------------------

/// The box (0, 0) ± 1, static.
World worldWithUnitBox() {
    World world;
    world.createBody({.type = BodyType::Static, .hw = 1, .hh = 1});
    return world;
}

TEST(RoundedCasts, ACircleCastLandsOnAFloorAtItsRadius) {
    // A floor whose top is y = 0; a circle of radius 2 from y = -10 moving 20 down touches
    // it with its centre at y = -2: 8 of the 20, fraction 0.4.
    World world;
    world.createBody({.type = BodyType::Static, .y = 5, .hw = 50, .hh = 5});
    const std::optional<BoxCastHit> hit = circleCast(world, {0, -10}, 2, {0, 20});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->fraction, 0.4f, 1e-5f);
    EXPECT_NEAR(hit->centre.y, -2.0f, 1e-5f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
}

TEST(RoundedCasts, ACircleMeetsABoxsCornerAlongTheLineToIt) {
    // Along the diagonal from (5, 5) to (1, 1), the circle of radius 1 touches the corner
    // (1, 1) with its centre 1 from it: (1 + 1/√2) each way, after 5 - 1.7071 = 3.2929 of
    // the 4 per axis.
    World world = worldWithUnitBox();
    const std::optional<BoxCastHit> hit = circleCast(world, {5, 5}, 1, {-4, -4});
    ASSERT_TRUE(hit);
    const float at = 1.0f + 1.0f / kRoot2;
    EXPECT_NEAR(hit->fraction, (5.0f - at) / 4.0f, 1e-4f);
    EXPECT_NEAR(hit->centre.x, at, 1e-4f);
    EXPECT_NEAR(hit->normal.x, 1.0f / kRoot2, 1e-4f);
    EXPECT_NEAR(hit->normal.y, 1.0f / kRoot2, 1e-4f);
}

TEST(RoundedCasts, ACircleGrazingABoxsCornerMeetsItOnItsCurve) {
    // Moving along y = -1.8, 0.8 above the corner (-1, -1)'s height: a sharp box of half
    // extent 1 meets the box's side at x = -2; the circle of radius 1 meets the corner when
    // its centre is 1 from it, 0.6 before it along x (0.6² + 0.8² = 1), at x = -1.6, and
    // the normal is (-0.6, -0.8).
    World world = worldWithUnitBox();
    const std::optional<BoxCastHit> box = boxCast(world, {-5, -1.8f}, {1, 1}, {10, 0});
    ASSERT_TRUE(box);
    EXPECT_NEAR(box->centre.x, -2.0f, 1e-5f);
    const std::optional<BoxCastHit> circle = boxCast(world, {-5, -1.8f}, {1, 1}, 1, {10, 0});
    ASSERT_TRUE(circle);
    EXPECT_NEAR(circle->centre.x, -1.6f, 1e-3f);
    EXPECT_NEAR(circle->fraction, 0.34f, 1e-4f);
    EXPECT_NEAR(circle->normal.x, -0.6f, 1e-3f);
    EXPECT_NEAR(circle->normal.y, -0.8f, 1e-3f);
    // Moving along y = -2.05, its bottom 0.05 above the box's top (beyond the skin, 0.02):
    // it passes.
    EXPECT_FALSE(circleCast(world, {-5, -2.05f}, 1, {10, 0}));
}

TEST(RoundedCasts, ACapsuleMovedAndSlidOntoAFloorGoesOnAlongIt) {
    // An upright capsule (half 1 × 3, radius 1) from y = -10 moving (10, 20): its bottom
    // (centre + 3) meets the floor's top y = 0 after 7 of the 20 down, fraction 0.35, 3.5
    // across; what is left, (6.5, 13), loses its part into the floor: it ends at (10, -3).
    World world;
    const BodyId floor = world.createBody({.type = BodyType::Static, .y = 5, .hw = 50, .hh = 5});
    const MoveResult moved = moveAndSlide(world, {0, -10}, {1, 3}, 1, {10, 20});
    EXPECT_NEAR(moved.centre.x, 10.0f, 1e-4f);
    EXPECT_NEAR(moved.centre.y, -3.0f, 1e-4f);
    ASSERT_EQ(moved.hits.size(), 1u);
    EXPECT_EQ(moved.hits[0].body, floor);
}

TEST(RoundedCasts, ARadiusOutOfRangeIsRefused) {
    World world = worldWithUnitBox();
    EXPECT_THROW(boxCast(world, {5, 5}, {1, 2}, 1.5f, {1, 0}), Error);
    EXPECT_THROW(boxCast(world, {5, 5}, {1, 2}, -1.0f, {1, 0}), Error);
    EXPECT_THROW(boxCast(world, {5, 5}, {1, 2}, std::nanf(""), {1, 0}), Error);
    EXPECT_THROW(circleCast(world, {5, 5}, 0.0f, {1, 0}), Error);
    EXPECT_THROW(moveAndSlide(world, {5, 5}, {1, 2}, 2.0f, {1, 0}), Error);
}

TEST(ShapeQueries, RaysAgreeWithPointQueries) {
    Numbers numbers{7};
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        World world = emptyWorld();
        const BodyDef def = randomShape(numbers);
        world.createBody(def);
        const Vec2 from = randomPoint(numbers), to = randomPoint(numbers);
        if (from == to)
            continue;
        SCOPED_TRACE(::testing::Message() << "trial " << trial);
        const Vec2 delta = to - from;
        const std::optional<RayHit> hit = rayCast(world, from, to);
        const float length = jostle::length(delta);
        const float end = hit ? hit->fraction : 1.0f;
        // Nothing after the start (which may be on its edge, heading away) and before the
        // hit, a hair (0.001 units) short of it.
        for (int i = 1; i < 20; ++i) {
            const float f = end * float(i) / 20.0f;
            if (f > end - 1e-3f / length)
                break;
            if (def.segment)
                break; // a line: crossed only at the hit from the front, anywhere from behind
            ASSERT_TRUE(queryPoint(world, from + delta * f).empty()) << "at " << f;
        }
        if (!hit)
            continue;
        ++hits;
        EXPECT_LE(dot(hit->normal, delta) / length, 1e-5f); // 0: grazing, within rounding
        if (hit->fraction == 0.0f)
            continue;
        // On the boundary: a hair outside along the normal is outside, and the shape
        // shares area with a hair's box around it.
        EXPECT_TRUE(queryPoint(world, hit->point + hit->normal * 1e-3f).empty());
        EXPECT_FALSE(queryBox(world, hit->point, {1e-3f, 1e-3f}).empty());
    }
    EXPECT_GT(hits, 500);
}

TEST(ShapeQueries, BoxCastsAgreeWithBoxQueries) {
    Numbers numbers{11};
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        World world = emptyWorld();
        const BodyDef def = randomShape(numbers);
        world.createBody(def);
        const Vec2 from = randomPoint(numbers), translation = randomPoint(numbers) * 2.0f;
        const Vec2 half{float(numbers.between(1, 6)), float(numbers.between(1, 6))};
        if (!queryBox(world, from, half).empty())
            continue; // it starts overlapping: free to leave
        SCOPED_TRACE(::testing::Message() << "trial " << trial);
        const std::optional<BoxCastHit> hit = boxCast(world, from, half, translation);
        // Deeper than the skin (2% of the smaller reach along the normal) is deeper than
        // 2.1% of the box's larger half extent inside it.
        const float skin = 0.021f * std::max(half.x, half.y);
        const Vec2 shrunk = half - Vec2{skin, skin};
        const float end = hit ? hit->fraction : 1.0f;
        for (int i = 0; i <= 20; ++i) {
            const float f = end * float(i) / 20.0f;
            if (def.segment && (!hit || i == 20))
                continue; // passing from behind; at the hit it may lie on the line
            ASSERT_TRUE(queryBox(world, from + translation * f, shrunk).empty()) << "at " << f;
        }
        if (!hit)
            continue;
        ++hits;
        EXPECT_LT(dot(hit->normal, translation), 0.0f);
        ASSERT_TRUE(queryBox(world, hit->centre, shrunk).empty());
        // Where it stops it touches the shape: a hair bigger, they share area.
        EXPECT_FALSE(queryBox(world, hit->centre, half + Vec2{1e-3f, 1e-3f}).empty());
    }
    EXPECT_GT(hits, 300);
}

} // namespace
} // namespace jostle
