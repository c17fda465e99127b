// Characters that feel right (docs/characters.md): no ghost walls at ledge corners, no
// hanging on walls, walking on what they stand on at a commanded speed.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

// --- Corners ------------------------------------------------------------------------------
//
// A ledge whose top is at y = 0 and whose left face is at x = 0 (y grows downward), built
// three ways; a box (12 × 16) to its left and above its top, rising and moving right: its
// path across the step clears the corner, so nothing may touch it.

enum class Ledge { OneBox, TileMap, SeparateBoxes };

void buildLedge(World& world, Ledge ledge) {
    switch (ledge) {
    case Ledge::OneBox:
        world.createBody({.type = BodyType::Static, .x = 24, .y = 8, .hw = 24, .hh = 8});
        break;
    case Ledge::TileMap:
        createTileMap(world, {.x = 0, .y = 0, .tile = 16, .rows = {"###", "###"}});
        break;
    case Ledge::SeparateBoxes:
        for (int i = 0; i < 3; ++i)
            world.createBody(
                {.type = BodyType::Static, .x = 8.0f + 16.0f * float(i), .y = 8, .hw = 8, .hh = 8});
        break;
    }
}

const char* nameOf(Ledge ledge) {
    return ledge == Ledge::OneBox ? "one box" : ledge == Ledge::TileMap ? "tile map" : "boxes";
}

TEST(Corners, ABoxRisingPastALedgeCornerKeepsItsVelocity) {
    // The case of the issue: 1.25 from the face, 0.33 above the top, at (150, -310).
    for (Ledge ledge : {Ledge::OneBox, Ledge::TileMap, Ledge::SeparateBoxes})
        for (float gapX : {0.2f, 1.25f, 3.0f, 6.0f})
            for (float gapY : {0.2f, 0.33f, 1.0f, 4.0f})
                for (float vx : {60.0f, 150.0f, 400.0f})
                    for (float vy : {-50.0f, -310.0f, -700.0f})
                        for (float g : {0.0f, 800.0f}) {
                            World world(WorldDef{.gravity = {0, g}});
                            buildLedge(world, ledge);
                            const BodyId box = world.createBody({.x = -gapX - 6,
                                                                 .y = -gapY - 8,
                                                                 .hw = 6,
                                                                 .hh = 8,
                                                                 .vx = vx,
                                                                 .vy = vy});
                            world.step(kDt);
                            // Gravity acts for the step: vy + g dt; nothing else.
                            const Vec2 v = world.velocity(box);
                            const Touching t = world.touching(box);
                            EXPECT_EQ(v.x, vx) << nameOf(ledge) << " gap " << gapX << ", " << gapY
                                               << " at " << vx << ", " << vy << " g " << g;
                            EXPECT_FLOAT_EQ(v.y, vy + g * kDt);
                            EXPECT_FALSE(t.wallRight || t.wallLeft || t.floor || t.ceiling);
                        }
}

TEST(Corners, ABoxRisingAlongALedgeOfSeparateBoxesIsNeverStopped) {
    // Without gravity the box rises for good, 0.33 above a floor of boxes and moving
    // along it past every seam: its velocity never changes.
    for (Ledge ledge : {Ledge::TileMap, Ledge::SeparateBoxes}) {
        World world(WorldDef{.gravity = {0, 0}});
        buildLedge(world, ledge);
        const BodyId box =
            world.createBody({.x = -7, .y = -8.33f, .hw = 6, .hh = 8, .vx = 200, .vy = -20});
        for (int step = 0; step < 30; ++step) {
            world.step(kDt);
            ASSERT_EQ(world.velocity(box), (Vec2{200, -20})) << nameOf(ledge) << " step " << step;
        }
    }
}

TEST(Corners, ABoxFallingOntoALedgeCornerLandsOnItsTop) {
    // 1.25 from the face and 2 above the top, moving at (600, 400): its path is over the
    // top after 1.25 / 600 = 2.1 ms, before it comes down to the top's level (2 / 400 =
    // 5 ms), so it lands on the top. By gaps alone (x is the larger) it was a wall.
    World world(WorldDef{.gravity = {0, 0}});
    buildLedge(world, Ledge::OneBox);
    const BodyId lands =
        world.createBody({.x = -1.25f - 6, .y = -2 - 8, .hw = 6, .hh = 8, .vx = 600, .vy = 400});
    world.step(kDt);
    EXPECT_TRUE(world.touching(lands).floor);
    EXPECT_FALSE(world.touching(lands).wallRight);
    // A speculative contact: it closes its gap of 2 in the step (2 / dt = 120) and no more,
    // its bottom on the top.
    EXPECT_FLOAT_EQ(world.velocity(lands).y, 120.0f);
    EXPECT_NEAR(world.position(lands).y, -8.0f, 1e-3f);
}

// --- Walls --------------------------------------------------------------------------------

constexpr float kG = 800.0f;

/// A character 12 × 16 with the default friction (0.5), standing on a floor whose top is
/// at y = 0, against a wall whose left face is at x = 100 if `wall` (else in open air),
/// walking into it at 150.
struct WallScene {
    World world;
    BodyId hero;

    WallScene(Solver solver, bool wall, bool character)
        : world(WorldDef{.gravity = {0, kG}, .solver = solver}) {
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 500, .hh = 50});
        if (wall)
            world.createBody({.type = BodyType::Static, .x = 150, .y = -200, .hw = 50, .hh = 200});
        hero = world.createBody({.x = 94, .y = -8, .hw = 6, .hh = 8, .character = character});
        if (character)
            world.setWalkSpeed(hero, 150);
        world.setSleeping(false);
    }

    /// Pushes into the wall (walking, or by setting its velocity if not a character) for
    /// `steps` steps; the highest its top rose above where it started.
    float push(int steps, bool character) {
        const float start = world.position(hero).y;
        float highest = 0;
        for (int i = 0; i < steps; ++i) {
            if (!character)
                world.setVelocity(hero, {150, world.velocity(hero).y});
            world.step(kDt);
            highest = std::max(highest, start - world.position(hero).y);
        }
        return highest;
    }
};

class Characters : public ::testing::TestWithParam<Solver> {};

TEST_P(Characters, JumpingWhilePressedIntoAWallRisesAsInOpenAir) {
    // A jump of sqrt(2 g 99): about 99 high.
    const float jump = std::sqrt(2 * kG * 99);
    WallScene open(GetParam(), false, true), walled(GetParam(), true, true);
    for (WallScene* scene : {&open, &walled}) {
        scene->push(10, true); // settle, against the wall
        scene->world.setVelocity(scene->hero, {0, -jump});
    }
    const float inOpenAir = open.push(60, true);
    const float againstTheWall = walled.push(60, true);
    EXPECT_GT(inOpenAir, 90.0f);
    EXPECT_NEAR(againstTheWall, inOpenAir, 0.01f * inOpenAir);
    EXPECT_TRUE(walled.world.touching(walled.hero).wallRight ||
                walled.world.touching(walled.hero).floor);
}

TEST_P(Characters, ABodyThatIsNotACharacterHangsOnTheWallItIsPushedInto) {
    // Why characters exist: the wall's friction, from the push the game commands every
    // step, holds an ordinary body up.
    const float jump = std::sqrt(2 * kG * 99);
    WallScene walled(GetParam(), true, false);
    walled.push(10, false);
    walled.world.setVelocity(walled.hero, {150, -jump});
    EXPECT_LT(walled.push(60, false), 50.0f);
}

TEST_P(Characters, FallingWhilePressedIntoAWallFallsAsInOpenAir) {
    WallScene open(GetParam(), false, true), walled(GetParam(), true, true);
    for (WallScene* scene : {&open, &walled}) {
        scene->push(5, true);
        scene->world.setPosition(scene->hero, {94, -300}); // high up, against the wall
        scene->world.setVelocity(scene->hero, {0, 0});
        for (int i = 0; i < 20; ++i)
            scene->world.step(kDt);
    }
    EXPECT_FLOAT_EQ(walled.world.position(walled.hero).y, open.world.position(open.hero).y);
    EXPECT_FLOAT_EQ(walled.world.velocity(walled.hero).y, open.world.velocity(open.hero).y);
}

TEST_P(Characters, WallFrictionIsTheGamesToAskFor) {
    // wallFriction 0.5: each step the walk into the wall (150) meets a push back of 150,
    // and friction up to 0.5 × 150 = 75 holds it against the g dt = 13.3 gravity adds: it
    // hangs, as an ordinary body does. In open air it falls g dt² (1 + ... + 20) = 46.7 in
    // 20 steps.
    WallScene walled(GetParam(), true, true);
    walled.world.setWallFriction(walled.hero, 0.5f);
    walled.push(5, true);
    walled.world.setPosition(walled.hero, {94, -300});
    walled.world.setVelocity(walled.hero, {0, 0});
    for (int i = 0; i < 20; ++i)
        walled.world.step(kDt);
    EXPECT_LT(walled.world.position(walled.hero).y + 300, 0.25f * 46.7f);
}

TEST_P(Characters, ClimbingOverTheTopOfAWallItIsPressedIntoDoesNotCatchOnIt) {
    // Jumping at 500 against a wall whose top is 40 above the floor, walking into it: as
    // soon as a step begins with the character's bottom above the wall's top (by more
    // than the contact skin, 0.16), it walks on at 150 in that very step.
    World world(WorldDef{.gravity = {0, kG}, .solver = GetParam(), .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 500, .hh = 50});
    world.createBody({.type = BodyType::Static, .x = 120, .y = -20, .hw = 20, .hh = 20});
    const BodyId hero = world.createBody({.x = 94, .y = -8, .hw = 6, .hh = 8, .character = true});
    world.setWalkSpeed(hero, 150);
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    world.setVelocity(hero, {150, -500});
    bool climbed = false;
    for (int i = 0; i < 20; ++i) {
        const float bottom = world.position(hero).y + 8;
        world.step(kDt);
        if (bottom < -40 - 0.16f) {
            EXPECT_EQ(world.velocity(hero).x, 150.0f) << "step " << i;
            climbed = true;
        }
    }
    EXPECT_TRUE(climbed);
}

// --- Walking --------------------------------------------------------------------------------

TEST_P(Characters, WalksAtTheCommandedSpeedOnTheGround) {
    // An ordinary body set to 150 each frame reads back 150 - mu g dt = 142.5 (friction
    // ate a step's worth); a character walks at 150 exactly. Crates keep Coulomb friction.
    World world(WorldDef{.gravity = {0, kG}, .solver = GetParam(), .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 5000, .hh = 50});
    const BodyId hero = world.createBody({.x = 0, .y = -8, .hw = 6, .hh = 8, .character = true});
    const BodyId crate = world.createBody({.x = 100, .y = -8, .hw = 8, .hh = 8});
    for (int i = 0; i < 10; ++i)
        world.step(kDt); // settle
    world.setWalkSpeed(hero, 150);
    world.setVelocity(crate, {150, 0});
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        EXPECT_EQ(world.velocity(hero).x, 150.0f) << "step " << i;
    }
    if (GetParam() == Solver::Physical) {
        // Coulomb: 30 steps of mu g dt = 6.667 each (the first step's push only half: it
        // starts at rest on the floor). 150 - 30 × 6.667 is < 0: it stopped, after
        // 150 / (mu g) = 0.375 s, 150² / (2 mu g) = 28.1 along.
        EXPECT_EQ(world.velocity(crate).x, 0.0f);
        EXPECT_NEAR(world.position(crate).x, 100.0f + 28.1f, 1.5f);
    }
}

/// A lift 80 × 12 with its top at y = 0 and a character standing on it, in the middle.
struct LiftScene {
    World world;
    BodyId lift, hero;

    explicit LiftScene(Solver solver) : world(WorldDef{.gravity = {0, kG}, .solver = solver}) {
        world.setSleeping(false);
        lift = world.createBody({.type = BodyType::Kinematic, .x = 0, .y = 6, .hw = 40, .hh = 6});
        hero = world.createBody({.x = 0, .y = -8, .hw = 6, .hh = 8, .character = true});
        for (int i = 0; i < 10; ++i)
            world.step(kDt);
    }
    Vec2 offset() const { return world.position(hero) - world.position(lift); }
};

/// Rides a lift through `legs` of 0.5 s each; the game sets the lift's velocity at the
/// start of each leg, before or after it commands the walk (0: standing). The character's
/// place on the lift never moves, and it never leaves the lift's top.
void rideLegs(Solver solver, std::span<const Vec2> legs) {
    for (bool liftFirst : {true, false}) {
        LiftScene scene(solver);
        const Vec2 start = scene.offset();
        for (Vec2 leg : legs) {
            for (int i = 0; i < 30; ++i) {
                if (liftFirst && i == 0)
                    scene.world.setVelocity(scene.lift, leg);
                scene.world.setWalkSpeed(scene.hero, 0);
                if (!liftFirst && i == 0)
                    scene.world.setVelocity(scene.lift, leg);
                scene.world.step(kDt);
                const Vec2 offset = scene.offset();
                ASSERT_NEAR(offset.x, start.x, 1e-3f) << "leg " << leg.x << ", " << leg.y;
                ASSERT_NEAR(offset.y, start.y, 0.2f) << "leg " << leg.x << ", " << leg.y;
                ASSERT_TRUE(scene.world.touching(scene.hero).floor);
            }
        }
    }
}

TEST_P(Characters, RidesALiftThatMovesSideways) {
    const Vec2 legs[] = {{60, 0}, {0, 0}, {-60, 0}, {-120, 0}, {0, 0}, {45, 0}};
    rideLegs(GetParam(), legs);
}

TEST(PhysicalCharacters, RidesALiftExactlyWhateverItDoes) {
    // Up, down and diagonally too: the physical model hands a rider what its platform's
    // velocity changed by (the classic model lets momentum carry it off a lift that stops
    // on the way up, as the tutorial does).
    const Vec2 legs[] = {{60, 0}, {0, 0},   {-60, 0}, {0, -60},  {0, 0},
                         {0, 60}, {0, 120}, {0, 0},   {90, -45}, {-30, 60}};
    rideLegs(Solver::Physical, legs);
}

TEST_P(Characters, WalksOverAMovingLiftAtItsOwnSpeed) {
    // Walking at 50 on a lift moving at -60: it moves at 50 relative to the lift, -10 in
    // the world: in 0.5 s, 25 along the lift.
    LiftScene scene(GetParam());
    const Vec2 start = scene.offset();
    scene.world.setVelocity(scene.lift, {-60, 0});
    scene.world.setWalkSpeed(scene.hero, 50);
    for (int i = 0; i < 30; ++i)
        scene.world.step(kDt);
    EXPECT_NEAR(scene.offset().x - start.x, 25.0f, 1e-3f);
    EXPECT_FLOAT_EQ(scene.world.velocity(scene.hero).x, -10.0f);
}

TEST_P(Characters, KnowsWhatItStandsOn) {
    LiftScene scene(GetParam());
    scene.world.setVelocity(scene.lift, {30, -20});
    scene.world.step(kDt);
    const std::optional<Ground> ground = scene.world.ground(scene.hero);
    ASSERT_TRUE(ground);
    EXPECT_EQ(ground->body, scene.lift);
    EXPECT_EQ(ground->normal, (Vec2{0, -1}));
    EXPECT_EQ(ground->velocity, (Vec2{30, -20}));
    // Jumping: in the air, nothing.
    scene.world.setVelocity(scene.hero, {0, -400});
    scene.world.step(kDt);
    scene.world.step(kDt);
    EXPECT_FALSE(scene.world.ground(scene.hero));
    EXPECT_FALSE(scene.world.ground(scene.lift));
}

INSTANTIATE_TEST_SUITE_P(Models, Characters, ::testing::Values(Solver::Classic, Solver::Physical),
                         [](const ::testing::TestParamInfo<Solver>& model) {
                             return model.param == Solver::Classic ? "Classic" : "Physical";
                         });

// --- On a slope: stopping and turning round (issue 29) -------------------------------------
//
// A ramp rising to the right, its foot at x = 0 on a long floor whose top is y = 0. A
// character walks up it, then the key is released or turned: it must stop where it is, or
// walk down at once, never hop off the slope.

struct RampScene {
    World world;
    BodyId hero;
    /// The ramp's rise over its run: 1 (45°) or 0.5 (2:1).
    RampScene(float rise, float snapDown)
        : world(WorldDef{.gravity = {0, 800}, .sleeping = false}) {
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
        world.createBody({.type = BodyType::Static,
                          .x = 200,
                          .y = -200 * rise,
                          .hw = 200,
                          .hh = 200 * rise,
                          .slope = {-1, -1}});
        hero = world.createBody(
            {.x = -30, .y = -8, .hw = 6, .hh = 8, .character = true, .snapDown = snapDown});
        for (int i = 0; i < 10; ++i)
            world.step(kDt);
    }
};

class OnASlope : public ::testing::TestWithParam<std::tuple<float, float>> {};

TEST_P(OnASlope, ReleasingTheKeyStopsItWhereItIsInTheSameStep) {
    const auto [rise, snapDown] = GetParam();
    RampScene scene(rise, snapDown);
    World& world = scene.world;
    world.setWalkSpeed(scene.hero, 120);
    for (int i = 0; i < 90; ++i) // 1.5 s: 180 across, well up the ramp
        world.step(kDt);
    ASSERT_GT(world.position(scene.hero).x, 60.0f);
    ASSERT_TRUE(world.ground(scene.hero)) << "walking up the ramp, on it";
    world.setWalkSpeed(scene.hero, 0);
    world.step(kDt);
    const Vec2 stopped = world.position(scene.hero);
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        ASSERT_TRUE(world.ground(scene.hero)) << "step " << i << " after releasing the key";
        EXPECT_NEAR(world.position(scene.hero).x, stopped.x, 0.05f) << "step " << i;
        EXPECT_NEAR(world.position(scene.hero).y, stopped.y, 0.05f) << "step " << i;
    }
}

TEST_P(OnASlope, TurningRoundWalksDownTheSlopeAtOnce) {
    const auto [rise, snapDown] = GetParam();
    RampScene scene(rise, snapDown);
    World& world = scene.world;
    world.setWalkSpeed(scene.hero, 120);
    for (int i = 0; i < 90; ++i)
        world.step(kDt);
    world.setWalkSpeed(scene.hero, -120);
    Vec2 last = world.position(scene.hero);
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        const Vec2 now = world.position(scene.hero);
        ASSERT_TRUE(world.ground(scene.hero)) << "step " << i << " after turning round";
        // Down the slope: 120 × dt back across, rise × that down.
        EXPECT_NEAR(now.x - last.x, -120.0f * kDt, 0.05f) << "step " << i;
        EXPECT_NEAR(now.y - last.y, 120.0f * kDt * rise, 0.05f) << "step " << i;
        last = now;
    }
}

INSTANTIATE_TEST_SUITE_P(Ramps, OnASlope,
                         ::testing::Combine(::testing::Values(1.0f, 0.5f),
                                            ::testing::Values(0.0f, 4.0f, 20.0f)));

// --- Over crests (issue 29) -----------------------------------------------------------------
//
// A character made with the defaults, as the README's first example makes one, walks over
// 45° crests on the ground: up a ramp onto a flat top and off its far edge down a ramp. It
// used to fly off each crest (61 of 190 steps of a level in the air); now a character
// follows a floor it walks onto within its floorAngle.
TEST(OverCrests, ACharacterWithTheDefaultsStaysOnTheGroundAtItsWalkSpeed) {
    for (float speed : {60.0f, 120.0f, 240.0f}) {
        World world(WorldDef{.gravity = {0, 800}});
        createTileMap(world, {.tile = 16,
                              .rows = {"..................", "......../##\\......",
                                       "......./####\\.....", "##################"}});
        const BodyId hero =
            world.createBody({.x = 24, .y = 40, .hw = 6, .hh = 8, .character = true});
        for (int i = 0; i < 30; ++i)
            world.step(kDt);
        ASSERT_TRUE(world.ground(hero));
        world.setWalkSpeed(hero, speed);
        int inTheAir = 0;
        for (int i = 0; world.position(hero).x < 250.0f && i < 1000; ++i) {
            world.step(kDt);
            if (!world.ground(hero))
                ++inTheAir;
            EXPECT_NEAR(world.velocity(hero).x, speed, 0.01f) << "step " << i;
        }
        EXPECT_GE(world.position(hero).x, 250.0f);
        EXPECT_EQ(inTheAir, 0) << "at " << speed;
    }
}

// --- Pushing (issue 29) ---------------------------------------------------------------------
//
// A character pushes as hard as its feet grip the floor: friction μ (the pair's, with the
// floor) times its weight m g. A crate of mass M on the same floor with friction μc moves
// only when μ m g exceeds μc M g, and then the two accelerate together at
// (μ m − μc M) g / (m + M). In the air it pushes with its momentum only. (It used to push
// whatever it met at its walk speed, whatever its friction: a crate 20 times its mass at 16.)

struct PushScene {
    World world{WorldDef{.gravity = {0, 800}, .sleeping = false}};
    BodyId hero, crate;
    /// The character (12 × 16, mass 192) stands against the crate's left face.
    PushScene(float heroFriction, float crateMass, float crateFriction) {
        world.createBody(
            {.type = BodyType::Static, .x = 0, .y = 50, .hw = 5000, .hh = 50, .friction = 1});
        hero = world.createBody(
            {.x = -6, .y = -8, .hw = 6, .hh = 8, .friction = heroFriction, .character = true});
        crate = world.createBody(
            {.x = 8, .y = -8, .hw = 8, .hh = 8, .friction = crateFriction, .mass = crateMass});
        for (int i = 0; i < 10; ++i)
            world.step(kDt);
    }
};

TEST(Pushing, ACrateHeavierThanTheGripStaysPut) {
    // Grip 0.5 × 192 g = 96 g against the crate's 0.5 × 960 g = 480 g.
    PushScene scene(0.5f, 960, 0.5f);
    const float start = scene.world.position(scene.crate).x;
    scene.world.setWalkSpeed(scene.hero, 150);
    for (int i = 0; i < 120; ++i)
        scene.world.step(kDt);
    EXPECT_NEAR(scene.world.position(scene.crate).x, start, 0.05f);
    EXPECT_NEAR(scene.world.velocity(scene.crate).x, 0.0f, 0.5f);
}

TEST(Pushing, AFrictionlessCharacterCannotPush) {
    PushScene scene(0.0f, 192, 0.1f);
    const float start = scene.world.position(scene.crate).x;
    scene.world.setWalkSpeed(scene.hero, 150);
    for (int i = 0; i < 120; ++i)
        scene.world.step(kDt);
    EXPECT_NEAR(scene.world.position(scene.crate).x, start, 0.05f);
}

TEST(Pushing, AGripAboveTheCratesFrictionAcceleratesBothAtWhatTheNetForceGives) {
    // Grip 1 × 192 g against 0.1 × 384 g: (192 − 38.4) g / (192 + 384) = 0.2667 g = 213.3.
    PushScene scene(1.0f, 384, 0.1f);
    scene.world.setWalkSpeed(scene.hero, 150);
    const float a = (192.0f - 38.4f) * 800.0f / (192.0f + 384.0f);
    for (int i = 1; i <= 30; ++i) {
        scene.world.step(kDt);
        // Below the walk speed all the while: 213.3 × 0.5 s = 107.
        EXPECT_NEAR(scene.world.velocity(scene.crate).x, a * kDt * float(i),
                    0.05f * a * kDt * float(i) + 1.0f)
            << "step " << i;
    }
}

TEST(Pushing, InTheAirACharacterPushesWithItsMomentumOnly) {
    // Gravity off for both: the character flies at 150 into a crate of its own mass. They
    // go on together at 75 (momentum m 150 shared by 2 m), and no faster.
    World world(WorldDef{.sleeping = false});
    const BodyId hero = world.createBody({.x = -40, .y = 0, .hw = 6, .hh = 8, .character = true});
    const BodyId crate = world.createBody({.x = 0, .y = 0, .hw = 8, .hh = 8, .mass = 192});
    world.setWalkSpeed(hero, 150);
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        EXPECT_LE(world.velocity(crate).x, 75.0f + 0.5f) << "step " << i;
    }
    EXPECT_NEAR(world.velocity(crate).x, 75.0f, 0.5f);
}

// --- Corner correction (issue 29) -------------------------------------------------------------
//
// A platform whose underside is y = 0 and whose left face is x = 0 (y grows downward). A
// body 12 × 16 below it jumps straight up at 400 (to 100 above where it starts), its right
// edge overlapping the platform's left corner by `clip`.

struct CornerScene {
    World world{WorldDef{.gravity = {0, 800}, .sleeping = false}};
    BodyId body;
    CornerScene(float clip, float cornerCorrection) {
        world.createBody({.type = BodyType::Static, .x = 50, .y = -10, .hw = 50, .hh = 10});
        body = world.createBody({.x = clip - 6,
                                 .y = 28,
                                 .hw = 6,
                                 .hh = 8,
                                 .vy = -400,
                                 .gravityScale = 1,
                                 .cornerCorrection = cornerCorrection});
    }
    /// The highest its top gets, and its vertical speed when the step it got there ends.
    float highestTop() {
        float top = 1e9f;
        for (int i = 0; i < 60; ++i) {
            world.step(kDt);
            top = std::min(top, world.position(body).y - 8);
        }
        return top;
    }
};

TEST(CornerCorrection, AJumpClippingAPlatformsCornerByNoMoreThanItGoesRoundIt) {
    for (float clip : {0.1f, 0.5f}) {
        CornerScene scene(clip, 0.5f);
        // Its top starts at 20 and rises 100 (less a step's worth of the discrete climb):
        // far above the platform's top (-20), had it gone round.
        EXPECT_LT(scene.highestTop(), -75.0f) << "clip " << clip;
        // Moved aside by the clip and the contact skin (twice the slop of its half width 6,
        // 0.12): clear of the platform, and no further.
        EXPECT_NEAR(scene.world.position(scene.body).x + 6.0f, -0.12f, 1e-4f) << "clip " << clip;
    }
}

TEST(CornerCorrection, JustOverTheDistanceOrWithoutItTheJumpIsLost) {
    // (A clip within the contact skin, 0.12, is mere touching: that passes without it.)
    for (auto [clip, correction] : {std::pair{0.51f, 0.5f}, std::pair{0.5f, 0.0f}}) {
        CornerScene scene(clip, correction);
        // Stopped by the underside: its top never above y = 0 (within the skin).
        EXPECT_GT(scene.highestTop(), -0.01f) << "clip " << clip << ", correction " << correction;
    }
}

TEST(CornerCorrection, ADashClippingALedgesTopGoesOverIt) {
    // A ledge with its top at y = 0 and its left face at x = 100; a body dashing right at
    // 400 with gravity off for it, its bottom 0.4 below the ledge's top.
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 150, .y = 50, .hw = 50, .hh = 50});
    const BodyId dasher = world.createBody({.x = 50,
                                            .y = -7.6f,
                                            .hw = 6,
                                            .hh = 8,
                                            .vx = 400,
                                            .gravityScale = 0,
                                            .cornerCorrection = 0.5f});
    for (int i = 0; i < 20; ++i)
        world.step(kDt);
    EXPECT_GT(world.position(dasher).x, 150.0f);
    EXPECT_EQ(world.velocity(dasher).x, 400.0f);
}

TEST(CornerCorrection, FallingOntoALedgesCornerStillLandsOnIt) {
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 50, .y = 10, .hw = 50, .hh = 10});
    // Its right edge 0.3 over the ledge's left corner (x = 0), falling onto it.
    const BodyId body =
        world.createBody({.x = -5.7f, .y = -40, .hw = 6, .hh = 8, .cornerCorrection = 0.5f});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    EXPECT_NEAR(world.position(body).y, -8.0f, 0.1f);
    EXPECT_NEAR(world.position(body).x, -5.7f, 1e-3f);
}

// --- Stepping up (issue 29) ------------------------------------------------------------------
//
// A floor with its top at y = 0; stairs of boxes rising to the right from x = 100, each
// step 20 wide and `rise` high. A character 12 × 16 with stepUp 8 walks at 120.

World stairs(float rise, int steps) {
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    for (int k = 1; k <= steps; ++k)
        world.createBody({.type = BodyType::Static,
                          .x = 100 + 20.0f * float(k - 1) + 10,
                          .y = -rise * float(k) * 0.5f,
                          .hw = 10,
                          .hh = rise * float(k) * 0.5f});
    return world;
}

TEST(StepUp, ACharacterWalksUpAndDownStepsNoTallerThanItsStepUpAtItsWalkSpeed) {
    World world = stairs(6, 4);
    const BodyId hero =
        world.createBody({.x = 50, .y = -8, .hw = 6, .hh = 8, .character = true, .stepUp = 8});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    world.setWalkSpeed(hero, 120);
    // Up the four steps to the top (24 above the floor), then on along it.
    for (int i = 0; world.position(hero).x < 175.0f; ++i) {
        ASSERT_LT(i, 120) << "stuck at x " << world.position(hero).x;
        world.step(kDt);
        ASSERT_NEAR(world.velocity(hero).x, 120.0f, 1e-3f) << "step " << i;
    }
    EXPECT_NEAR(world.position(hero).y, -24.0f - 8.0f, 0.1f);
    // And back down them, at the same speed.
    world.setWalkSpeed(hero, -120);
    for (int i = 0; world.position(hero).x > 60.0f; ++i) {
        ASSERT_LT(i, 120) << "stuck at x " << world.position(hero).x;
        world.step(kDt);
        ASSERT_NEAR(world.velocity(hero).x, -120.0f, 1e-3f) << "step " << i;
        ASSERT_TRUE(world.ground(hero)) << "step " << i;
    }
    EXPECT_NEAR(world.position(hero).y, -8.0f, 0.1f);
}

TEST(StepUp, ATallerStepStopsItAsAWallDoes) {
    World world = stairs(10, 1);
    const BodyId hero =
        world.createBody({.x = 50, .y = -8, .hw = 6, .hh = 8, .character = true, .stepUp = 8});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    world.setWalkSpeed(hero, 120);
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    EXPECT_NEAR(world.position(hero).x, 100.0f - 6.0f, 0.1f);
    EXPECT_NEAR(world.position(hero).y, -8.0f, 0.1f);
}

} // namespace
} // namespace jostle
