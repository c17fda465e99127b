// Slopes and round shapes (docs/slopes-and-shapes.md): ramps, segments, rounded bodies.
// Expected values come from the physics of a block on an incline (a = g (sin θ - μ cos θ))
// and from the geometry of the shapes.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 10.0f; // y grows downward

/// A static ramp rising to the right at `degrees`, its slope through the origin: the line
/// y = -x tan θ. Its outward normal is (-sin θ, -cos θ); down the slope is (-cos θ, sin θ).
struct Incline {
    float theta;
    Vec2 normal;
    Vec2 downhill;
    BodyId ramp;
};

Incline makeIncline(World& world, float degrees, float friction) {
    const float theta = degrees * std::numbers::pi_v<float> / 180.0f;
    const float hw = 200.0f, hh = hw * std::tan(theta);
    Incline incline{
        theta, {-std::sin(theta), -std::cos(theta)}, {-std::cos(theta), std::sin(theta)}};
    incline.ramp = world.createBody(
        {.type = BodyType::Static, .hw = hw, .hh = hh, .friction = friction, .slope = {-1, -1}});
    return incline;
}

/// A body of half extents (hw, hh) and `radius` resting on the incline at distance `along`
/// up the slope from the origin: its centre at the distance from the line that its shape
/// reaches along -normal.
BodyId placeOnIncline(World& world, const Incline& incline, float along, float hw, float hh,
                      float radius, float friction) {
    const Vec2 onLine = incline.downhill * -along;
    const Vec2 n = incline.normal;
    const float reach = std::abs(n.x) * (hw - radius) + std::abs(n.y) * (hh - radius) + radius;
    const Vec2 centre = onLine + n * reach;
    return world.createBody(
        {.x = centre.x, .y = centre.y, .hw = hw, .hh = hh, .friction = friction, .radius = radius});
}

void run(World& world, float seconds) {
    const int steps = int(std::lround(seconds / kDt));
    for (int i = 0; i < steps; ++i)
        world.step(kDt);
}

TEST(Slopes, AFrictionlessInclineAcceleratesAtGSinTheta) {
    for (float degrees : {30.0f, 45.0f}) {
        for (float radius : {0.0f, 1.0f}) {
            World world(WorldDef{.gravity = {0, kG}});
            const Incline incline = makeIncline(world, degrees, 0.0f);
            const BodyId box = placeOnIncline(world, incline, 100.0f, 1, 1, radius, 0.0f);
            const float seconds = 2.0f;
            run(world, seconds);
            const Vec2 v = world.velocity(box);
            const float expected = kG * std::sin(incline.theta) * seconds;
            SCOPED_TRACE(testing::Message() << degrees << " degrees, radius " << radius);
            EXPECT_NEAR(dot(v, incline.downhill), expected, 1e-3f * expected);
            EXPECT_NEAR(dot(v, incline.normal), 0.0f, 1e-3f * expected);
        }
    }
}

TEST(Slopes, FrictionAboveTanThetaHoldsABodyThenItSleeps) {
    // 45° would need a friction of 1.02, beyond jostle's [0, 1]: 30° and 2:1 instead.
    for (float degrees : {30.0f, 26.565051f}) {
        World world(WorldDef{.gravity = {0, kG}});
        const float mu = std::tan(degrees * std::numbers::pi_v<float> / 180.0f) + 0.02f;
        const Incline incline = makeIncline(world, degrees, mu);
        const BodyId box = placeOnIncline(world, incline, 100.0f, 1, 1, 0.0f, mu);
        const Vec2 start = world.position(box);
        run(world, 5.0f);
        SCOPED_TRACE(degrees);
        EXPECT_LT(length(world.position(box) - start), 1e-4f * 100.0f);
        run(world, 2.0f);
        EXPECT_FALSE(world.isAwake(box));
    }
}

TEST(Slopes, FrictionBelowTanThetaSlidesAtGSinThetaLessMuCosTheta) {
    for (float degrees : {30.0f, 45.0f}) {
        World world(WorldDef{.gravity = {0, kG}});
        const float theta = degrees * std::numbers::pi_v<float> / 180.0f;
        const float mu = std::tan(theta) - 0.05f;
        const Incline incline = makeIncline(world, degrees, mu);
        const BodyId box = placeOnIncline(world, incline, 100.0f, 1, 1, 0.0f, mu);
        run(world, 1.0f);
        const float v1 = dot(world.velocity(box), incline.downhill);
        run(world, 1.0f);
        const float v2 = dot(world.velocity(box), incline.downhill);
        const float expected = kG * (std::sin(theta) - mu * std::cos(theta));
        SCOPED_TRACE(degrees);
        EXPECT_NEAR(v2 - v1, expected, 0.01f * expected);
    }
}

TEST(Slopes, ACircleAndACapsuleRestAtTheirHeightOnASlope) {
    // The centre of a circle of radius r resting on a line lies r from it; a capsule (an
    // upright core of half height c, then the radius) touches with its lower end: the
    // lower end's centre lies r from the line.
    World world(WorldDef{.gravity = {0, kG}});
    const Incline incline = makeIncline(world, 30.0f, 1.0f);
    const BodyId circle = placeOnIncline(world, incline, 100.0f, 2, 2, 2, 1.0f);
    const BodyId capsule = placeOnIncline(world, incline, 50.0f, 1, 3, 1, 1.0f);
    run(world, 3.0f);
    const float slop = world.physicalOptions().slop;
    const float circleDistance = dot(world.position(circle), incline.normal);
    EXPECT_NEAR(circleDistance, 2.0f, 2.0f * slop * 2.0f + 1e-3f);
    const Vec2 lowerEnd = world.position(capsule) + Vec2{0, 2};
    EXPECT_NEAR(dot(lowerEnd, incline.normal), 1.0f, 2.0f * slop * 1.0f + 1e-3f);
}

TEST(RoundShapes, ACircleHittingABoxCornerLeavesAlongTheDiagonal) {
    // A circle of radius 1 moving right at 10 meets the top-left corner of a box of equal
    // mass, its centre 1/√2 above the corner's level: the normal is at 45°. Elastic, equal
    // masses, no friction: the velocity along the normal is exchanged.
    World world(WorldDef{.gravity = {0, 0}});
    const float k = 1.0f / std::sqrt(2.0f);
    const BodyId box =
        world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .bounce = 1, .friction = 0, .mass = 1});
    // The circle touches the corner (-1, -1) along (-k, -k) when its centre is at
    // (-1 - k, -1 - k); start it 0.5 to the left of that.
    const BodyId ball = world.createBody({.x = -1 - k - 0.5f,
                                          .y = -1 - k,
                                          .hw = 1,
                                          .hh = 1,
                                          .vx = 10,
                                          .bounce = 1,
                                          .friction = 0,
                                          .mass = 1,
                                          .radius = 1});
    run(world, 0.5f);
    const Vec2 vb = world.velocity(ball), vx = world.velocity(box);
    // Momentum: 10 along x before.
    EXPECT_NEAR(vb.x + vx.x, 10.0f, 0.1f);
    EXPECT_NEAR(vb.y + vx.y, 0.0f, 0.1f);
    // Energy: 100 (×m/2) before.
    EXPECT_NEAR(dot(vb, vb) + dot(vx, vx), 100.0f, 1.0f);
    // Along the normal (k, k) the box takes the ball's 10k: (5, 5); the ball keeps (5, -5).
    EXPECT_NEAR(vx.x, 5.0f, 0.1f);
    EXPECT_NEAR(vx.y, 5.0f, 0.1f);
    EXPECT_NEAR(vb.x, 5.0f, 0.1f);
    EXPECT_NEAR(vb.y, -5.0f, 0.1f);
}

TEST(Slopes, AStackOfCratesOnATwoToOneRampStands) {
    World world(WorldDef{.gravity = {0, kG}});
    const float theta = std::atan(0.5f);
    const Incline incline = makeIncline(world, theta * 180.0f / std::numbers::pi_v<float>, 0.9f);
    std::vector<BodyId> crates;
    // A column of three crates, each resting on the one below (the lowest on the slope).
    const BodyId bottom = placeOnIncline(world, incline, 100.0f, 1, 1, 0.0f, 0.9f);
    crates.push_back(bottom);
    for (int i = 1; i < 3; ++i) {
        const Vec2 below = world.position(crates.back());
        crates.push_back(world.createBody(
            {.x = below.x, .y = below.y - 2.0f, .hw = 1, .hh = 1, .friction = 0.9f}));
    }
    std::vector<Vec2> start;
    for (BodyId c : crates)
        start.push_back(world.position(c));
    run(world, 10.0f);
    for (std::size_t i = 0; i < crates.size(); ++i)
        EXPECT_LT(length(world.position(crates[i]) - start[i]), 0.05f) << "crate " << i;
}

TEST(RampTiles, ABoxSlidingIntoARampsFootGoesUpItToVSquaredOverTwoG) {
    // A frictionless box meeting a 45° ramp at 100 units/s keeps the part of its velocity
    // along the slope, 100 cos 45°, and rises to (100 cos 45°)² / 2g = 25 above the floor.
    World world(WorldDef{.gravity = {0, 100}});
    createTileMap(world, {.tile = 16,
                          .rows = {".......#####", "....../#####", "...../######", "..../#######",
                                   "############"},
                          .friction = 0});
    const BodyId box =
        world.createBody({.x = 20, .y = 60, .hw = 4, .hh = 4, .vx = 100, .friction = 0});
    float highest = 60.0f;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        highest = std::min(highest, world.position(box).y);
    }
    // Semi-implicit Euler climbs v sin 45° dt / 2 short of it, and the step of the impact,
    // spent partly on the floor, takes up to a step's gravity along the slope more: v sin
    // 45° dt. With v = 70.7: 0.42 and 0.83.
    const float perStep = 100.0f * 0.5f * kDt; // v sin 45° dt = 100 cos 45° sin 45° dt
    EXPECT_LE(60.0f - highest, 25.0f);
    EXPECT_GE(60.0f - highest, 25.0f - 1.5f * perStep);
}

TEST(Slopes, ABoxFallingPastARampsTopTipFallsFreely) {
    // The ramp's top tip is at (100, 0); the box falls beside its leg, half a unit clear:
    // nothing slows it, v = v0 + g t after every step, and nothing pushes it sideways.
    World world(WorldDef{.gravity = {0, 800}});
    world.createBody(
        {.type = BodyType::Static, .x = 50, .y = 50, .hw = 50, .hh = 50, .slope = {-1, -1}});
    const BodyId box = world.createBody({.x = 104.5f, .y = -40, .hw = 4, .hh = 4, .vy = 1200});
    for (int i = 1; i <= 8; ++i) {
        world.step(kDt);
        EXPECT_NEAR(world.velocity(box).y, 1200.0f + 800.0f * kDt * float(i), 1e-2f) << i;
        EXPECT_EQ(world.velocity(box).x, 0.0f) << i;
    }
}

TEST(Slopes, AFastBoxOntoARampOnAWideFloorIsNotThrownAlongTheFloor) {
    // At 7000 units/s onto a 45° ramp (friction 0.5): the slope takes the normal half of its
    // speed, friction as much again of the other, leaving 7000 sin 45° / 2 along the slope,
    // 1750 across: it slides off the ramp's foot at that speed, not hundreds of units away.
    World world(WorldDef{.gravity = {0, 800}});
    world.createBody(
        {.type = BodyType::Static, .x = 1000, .y = 0, .hw = 50, .hh = 50, .slope = {-1, -1}});
    world.createBody({.type = BodyType::Static, .x = 1000, .y = 60, .hw = 1000, .hh = 10});
    const BodyId box = world.createBody({.x = 1019, .y = -60, .hw = 2, .hh = 2, .vy = 7000});
    for (int i = 0; i < 3; ++i)
        world.step(kDt);
    EXPECT_LT(world.position(box).x, 1019.0f);
    // Three steps at 1750 go 87.5 across; the step of the impact goes faster along the
    // slope before friction has done its part: within twice that.
    EXPECT_GT(world.position(box).x, 1019.0f - 2.0f * 3.0f * 1750.0f * kDt);
    EXPECT_NEAR(world.velocity(box).x, -1750.0f, 0.02f * 1750.0f);
}

} // namespace
} // namespace jostle

namespace jostle {
namespace {

// --- Ramp tiles --------------------------------------------------------------------------

TEST(RampTiles, SlidingDownTenChainedRampsTheSpeedNeverDipsAtASeam) {
    // Ten '/' tiles climbing to the right, solid ground under them, no friction anywhere.
    std::vector<std::string> rows;
    for (int r = 0; r < 10; ++r) {
        std::string row(12, '.');
        for (int c = 0; c < 12; ++c)
            if (c == 9 - r)
                row[std::size_t(c)] = '/';
            else if (c > 9 - r)
                row[std::size_t(c)] = '#';
        rows.push_back(row);
    }
    rows.emplace_back(12, '#');
    World world(WorldDef{.gravity = {0, 100}});
    createTileMap(world, {.tile = 16, .rows = rows, .friction = 0});
    // A box on the slope near the top: the line through the tiles' corners is
    // x + y = 160 (y down); its corner (x + 4, y + 4) on it.
    const float k = 1.0f / std::sqrt(2.0f);
    const BodyId box =
        world.createBody({.x = 140 - 4, .y = 20 - 4, .hw = 4, .hh = 4, .friction = 0});
    const Vec2 downhill{-k, k};
    float last = 0.0f;
    int steps = 0;
    for (; steps < 300 && world.position(box).x > 24; ++steps) {
        world.step(kDt);
        const float speed = dot(world.velocity(box), downhill);
        ASSERT_GE(speed, last - 1e-3f) << "step " << steps << " at x " << world.position(box).x;
        last = speed;
    }
    // It crossed most of the seams, speeding up at g sin 45° all the way.
    EXPECT_LT(world.position(box).x, 40.0f);
    EXPECT_NEAR(last, 100.0f * k * float(steps) * kDt, 0.01f * last);
}

TEST(RampTiles, ACharacterKeepsItsSpeedAcrossFlatRampFlatAndDownRamp) {
    // Flat ground, two 45° tiles up, a flat top, two 2:1 ramps down, flat again.
    World world(WorldDef{.gravity = {0, 800}});
    createTileMap(world, {.tile = 16,
                          .rows = {"........................", "........................",
                                   "........................", "......./####Ll..........",
                                   "....../#######Ll........", "########################",
                                   "########################"}});
    const BodyId player = world.createBody({.x = 24, .y = 72, .hw = 6, .hh = 8, .character = true});
    world.setWalkSpeed(player, 120);
    std::vector<float> speeds;
    for (int i = 0; i < 600 && world.position(player).x < 320; ++i) {
        world.step(kDt);
        speeds.push_back(world.velocity(player).x);
    }
    ASSERT_GE(world.position(player).x, 320.0f) << "it got stuck at x " << world.position(player).x;
    // Up, over and down at its walk speed, (320 - 24) / 120 s, within 1% at every step.
    EXPECT_LE(speeds.size(), std::size_t((320.0f - 24.0f) / 120.0f / kDt) + 1);
    for (std::size_t i = 0; i < speeds.size(); ++i)
        EXPECT_NEAR(speeds[i], 120.0f, 1.2f) << "step " << i;
}

} // namespace
} // namespace jostle

namespace jostle {
namespace {

// --- Contact points ----------------------------------------------------------------------
//
// Where a pair with a shape touches, by the geometry of the shapes: a circle at its centre
// less its radius along the normal, a box's corner on a slope, the middle of the stretch
// where a face meets a face. Along the normal the point is halfway between the two
// surfaces, so it lies within half the skin (twice the slop of the smaller size) of each.

/// The one contact `body` has, from World::contacts.
ContactInfo onlyContact(const World& world, BodyId body) {
    const std::vector<ContactInfo> contacts = world.contacts(body);
    EXPECT_EQ(contacts.size(), 1u);
    return contacts.empty() ? ContactInfo{} : contacts[0];
}

/// The begin event of the pair (a, b) in the last step, if there is one.
std::optional<ContactEvent> beginOf(const World& world, BodyId a, BodyId b) {
    for (const ContactEvent& e : world.contactBegins())
        if (e.a == a && e.b == b)
            return e;
    return std::nullopt;
}

void expectNear(Vec2 actual, Vec2 expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

TEST(ContactPoints, ACircleOnASlopeTouchesAtItsCentreLessItsRadiusAlongTheNormal) {
    // A circle of radius 2 sliding down a frictionless 30° or 45° incline: the contact's
    // normal is the slope's, and the point is r back along it from the centre, on the line
    // y = -x tan θ (dot(point, normal) = 0).
    for (float degrees : {30.0f, 45.0f}) {
        SCOPED_TRACE(degrees);
        World world(WorldDef{.gravity = {0, kG}});
        const Incline incline = makeIncline(world, degrees, 0.0f);
        const BodyId ball = placeOnIncline(world, incline, 100.0f, 2, 2, 2, 0.0f);
        run(world, 1.0f);
        const ContactInfo c = onlyContact(world, ball);
        EXPECT_EQ(c.other, incline.ramp);
        expectNear(c.normal, incline.normal, 1e-5f);
        const float halfSkin = world.physicalOptions().slop * 2.0f;
        expectNear(c.point, world.position(ball) - incline.normal * 2.0f, halfSkin);
        EXPECT_NEAR(dot(c.point, incline.normal), 0.0f, halfSkin);
    }
}

TEST(ContactPoints, ACircleLandingOnARampBeginsWhereItMeetsTheLine) {
    // Dropped from just above a 45° ramp (y = -x), a circle of radius 2 centred at x = 20
    // meets the line at the foot of the perpendicular from its centre: r k to the right of
    // it, (20 + 2k, -(20 + 2k)), with k = 1/√2. It falls 0.1 first, to 1.41 units/s: in
    // the step it lands it keeps its speed along the slope, 1.41 k, and slides down by at
    // most 1.41 k dt = 0.017 (0.012 in each of x and y) before the begin is reported.
    World world(WorldDef{.gravity = {0, kG}});
    const Incline incline = makeIncline(world, 45.0f, 0.0f);
    const float k = 1.0f / std::sqrt(2.0f);
    const float restY = -20.0f - 2.0f / k; // dot((20, y), normal) = 2
    const BodyId ball = world.createBody(
        {.x = 20, .y = restY - 0.1f, .hw = 2, .hh = 2, .friction = 0, .radius = 2});
    std::optional<ContactEvent> begin;
    for (int i = 0; i < 60 && !begin; ++i) {
        world.step(kDt);
        begin = beginOf(world, incline.ramp, ball);
    }
    ASSERT_TRUE(begin);
    expectNear(begin->normal, -incline.normal, 1e-5f); // from the ball towards the ramp
    const float halfSkin = world.physicalOptions().slop * 2.0f;
    expectNear(begin->point, {20 + 2 * k, -(20 + 2 * k)}, 0.012f + halfSkin);
}

TEST(ContactPoints, ABoxOnASlopeTouchesAtItsLowCorner) {
    // A box of half size 1 held by friction on a 30° incline rising to the right (y down):
    // of its corners, (x + 1, y + 1) reaches furthest into the slope, and it is the one
    // that touches, on the line. The box stays put, so its start is where it is.
    World world(WorldDef{.gravity = {0, kG}});
    const float mu = std::tan(30.0f * std::numbers::pi_v<float> / 180.0f) + 0.02f;
    const Incline incline = makeIncline(world, 30.0f, mu);
    const BodyId box = placeOnIncline(world, incline, 100.0f, 1, 1, 0.0f, mu);
    const Vec2 corner = world.position(box) + Vec2{1, 1};
    EXPECT_NEAR(dot(corner, incline.normal), 0.0f, 1e-3f); // placed touching
    const float halfSkin = world.physicalOptions().slop * 1.0f;
    world.step(kDt);
    const std::optional<ContactEvent> begin = beginOf(world, incline.ramp, box);
    ASSERT_TRUE(begin);
    expectNear(begin->point, corner, halfSkin + 1e-3f);
    run(world, 2.0f);
    const ContactInfo c = onlyContact(world, box);
    expectNear(c.normal, incline.normal, 1e-5f);
    expectNear(c.point, corner, halfSkin + 1e-2f); // it drifts less than 1e-2 in 2 s
}

TEST(ContactPoints, ABoxAgainstARampsLegTouchesAtTheMiddleOfTheStretchTheyShare) {
    // A 45° ramp rising to the right, of half size 50 at the origin: its leg is the face
    // x = 50, y from -50 to 50. A box of half size 10 pressed against it from the right
    // shares the stretch of its own left face that the leg spans: y 10..30 for a box at
    // y = 20, -50..-35 for one at y = -45 (the leg ends at the ramp's tip, y = -50).
    for (auto [y, middle] : {std::pair{20.0f, 20.0f}, {-45.0f, -42.5f}}) {
        SCOPED_TRACE(y);
        World world;
        const BodyId ramp =
            world.createBody({.type = BodyType::Static, .hw = 50, .hh = 50, .slope = {-1, -1}});
        const BodyId box = world.createBody({.x = 60, .y = y, .hw = 10, .hh = 10, .vx = -5});
        world.step(kDt);
        const std::optional<ContactEvent> begin = beginOf(world, ramp, box);
        ASSERT_TRUE(begin);
        expectNear(begin->normal, {-1, 0}, 0.0f);
        expectNear(begin->point, {50, middle}, 0.1f); // within half the skin in x
        EXPECT_EQ(onlyContact(world, box).point, begin->point);
    }
}

TEST(ContactPoints, ACapsuleAgainstAWallTouchesAlongItsStraightSide) {
    // A capsule of radius 5 and half height 15 (its straight side y ± 10) against a wall's
    // face x = 0 that ends at y = 50: at y = 45 the side spans 35..55 and the wall 35..50
    // of it, so the middle is 42.5. (Its box would say 30..50, and 40.)
    World world;
    const BodyId wall = world.createBody({.type = BodyType::Static, .x = -10, .hw = 10, .hh = 50});
    const BodyId capsule =
        world.createBody({.x = 5, .y = 45, .hw = 5, .hh = 15, .vx = -5, .radius = 5});
    world.step(kDt);
    const std::optional<ContactEvent> begin = beginOf(world, wall, capsule);
    ASSERT_TRUE(begin);
    expectNear(begin->normal, {-1, 0}, 0.0f);
    expectNear(begin->point, {0, 42.5f}, 0.05f);
}

TEST(ContactPoints, ACircleRollingOverABoxCornerTouchesAtTheCorner) {
    // A circle of radius 1 moving right meets the top-left corner (-1, -1) of a static box,
    // its centre 1/√2 above the corner's level: it touches at the corner itself, along the
    // diagonal.
    World world;
    const float k = 1.0f / std::sqrt(2.0f);
    const BodyId box = world.createBody({.type = BodyType::Static, .hw = 1, .hh = 1});
    const BodyId ball = world.createBody(
        {.x = -1 - k - 0.05f, .y = -1 - k, .hw = 1, .hh = 1, .vx = 10, .friction = 0, .radius = 1});
    std::optional<ContactEvent> begin;
    for (int i = 0; i < 10 && !begin; ++i) {
        world.step(kDt);
        begin = beginOf(world, box, ball);
    }
    ASSERT_TRUE(begin);
    // From the ball towards the box: (k, k), turned by at most what the ball slides round
    // the corner in the step, at v k = 7.07 for dt: atan(0.118), 6.7°, 0.083 in a component.
    expectNear(begin->normal, {k, k}, 0.09f);
    // Around the corner the ball touches the corner wherever it is; the point is halfway
    // between the two along the normal: within half the skin (the slop of radius 1).
    expectNear(begin->point, {-1, -1}, world.physicalOptions().slop + 1e-3f);
}

TEST(ContactPoints, TwoCirclesTouchOnTheLineBetweenTheirCentres) {
    // A static circle of radius 2 at the origin and one of radius 3 at (3, 4), 5 away along
    // (0.6, 0.8), coming slowly closer along that line: they touch 2 along it from the
    // origin, at (1.2, 1.6).
    World world;
    const BodyId still =
        world.createBody({.type = BodyType::Static, .hw = 2, .hh = 2, .radius = 2});
    const BodyId ball =
        world.createBody({.x = 3, .y = 4, .hw = 3, .hh = 3, .vx = -0.6f, .vy = -0.8f, .radius = 3});
    world.step(kDt);
    const std::optional<ContactEvent> begin = beginOf(world, still, ball);
    ASSERT_TRUE(begin);
    expectNear(begin->normal, {-0.6f, -0.8f}, 1e-5f);
    expectNear(begin->point, {1.2f, 1.6f}, world.physicalOptions().slop * 2.0f);
}

} // namespace
} // namespace jostle
