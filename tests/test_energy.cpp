// Energy in collisions of many bodies (docs/physical-model.md, "Simultaneous
// collisions"): no collision creates kinetic energy, a bouncing gas keeps it, and a blow
// passes down a row of touching boxes. Expected values come from momentum and energy:
// equal masses in an elastic collision swap velocities, in an inelastic one share them.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

/// ½ m |v|², in doubles.
double energyOf(float mass, Vec2 v) {
    const double x = static_cast<double>(v.x), y = static_cast<double>(v.y);
    return 0.5 * static_cast<double>(mass) * (x * x + y * y);
}

double kineticEnergy(const World& world, const std::vector<BodyId>& bodies) {
    double energy = 0.0;
    for (BodyId id : bodies)
        energy += energyOf(world.mass(id), world.velocity(id));
    return energy;
}

Vec2 momentum(const World& world, const std::vector<BodyId>& bodies) {
    Vec2 p{};
    for (BodyId id : bodies)
        p += world.velocity(id) * world.mass(id);
    return p;
}

/// A box of 20 × 20 that bounces fully and does not rub.
BodyDef ball(float x, float y, float vx, float vy = 0.0f, float bounce = 1.0f) {
    return {
        .x = x, .y = y, .hw = 10, .hh = 10, .vx = vx, .vy = vy, .bounce = bounce, .friction = 0};
}

TEST(Energy, ThreeBoxesMeetingAtOnceSwapTheirVelocities) {
    // A (300) catches B (200) while C (-250) comes at B, all elastic, equal masses, no
    // gravity: each collision swaps two velocities, so when they part, left to right, they
    // move at -250, 200 and 300, with the energy and momentum they began with.
    World world(WorldDef{.gravity = {0, 0}});
    const std::vector<BodyId> boxes{world.createBody(ball(0, 0, 300)),
                                    world.createBody(ball(25, 0, 200)),
                                    world.createBody(ball(50, 0, -250))};
    const double energy = kineticEnergy(world, boxes);
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    EXPECT_NEAR(world.velocity(boxes[0]).x, -250.0f, 1e-2f);
    EXPECT_NEAR(world.velocity(boxes[1]).x, 200.0f, 1e-2f);
    EXPECT_NEAR(world.velocity(boxes[2]).x, 300.0f, 1e-2f);
    EXPECT_NEAR(kineticEnergy(world, boxes) / energy, 1.0, 1e-5);
    EXPECT_NEAR(momentum(world, boxes).x, 250.0f * world.mass(boxes[0]), 1e-2f);
}

/// Newton's cradle: a striker at 200 into four touching boxes on a frictionless floor,
/// `back` behind where it touches the row at the start of a step. The velocities after a
/// second.
std::vector<float> cradle(float bounce, float back) {
    World world(WorldDef{.gravity = {0, 800}});
    world.createBody({.type = BodyType::Static, .y = 20, .hw = 1000, .hh = 10, .friction = 0});
    std::vector<BodyId> row{world.createBody(ball(-60 - back, 0, 200, 0, bounce))};
    for (int k = 0; k < 4; ++k)
        row.push_back(world.createBody(ball(20.0f * float(k), 0, 0, 0, bounce)));
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    std::vector<float> speeds;
    for (BodyId id : row)
        speeds.push_back(world.velocity(id).x);
    return speeds;
}

TEST(Energy, NewtonsCradlePassesTheBlowToTheLastBox) {
    // Elastic, equal masses: each box hands its velocity on and stops; the last leaves at
    // 200 with all the energy, wherever in a step the striker arrives.
    for (float back : {0.0f, 1.0f / 3.0f, 2.0f / 3.0f}) {
        const std::vector<float> v = cradle(1.0f, back);
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(v[k], 0.0f, 0.5f) << "box " << k << ", " << back << " back";
        EXPECT_GE(v[4] * v[4] / (200.0f * 200.0f), 0.9f) << back << " back";
        EXPECT_NEAR(v[4], 200.0f, 0.02f * 200.0f) << back << " back";
    }
}

TEST(Energy, AnInelasticCradleMovesOnTogetherAtTheCommonSpeed) {
    // Without a bounce the five share the striker's momentum: 200 / 5 = 40 each.
    for (float back : {0.0f, 1.0f / 3.0f, 2.0f / 3.0f})
        for (float v : cradle(0.0f, back))
            EXPECT_NEAR(v, 40.0f, 0.4f) << back << " back";
}

/// 500 boxes of 20 in a closed box 800 wide, every one bouncing fully off every other and
/// off the walls, nothing rubbing, no gravity.
TEST(Energy, AClosedBouncingGasKeepsItsEnergy) {
    World world(WorldDef{.gravity = {0, 0}});
    const float half = 400;
    for (Vec2 wall : {Vec2{0, -1}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{1, 0}})
        world.createBody({.type = BodyType::Static,
                          .x = wall.x * (half + 10),
                          .y = wall.y * (half + 10),
                          .hw = wall.x != 0 ? 10 : half + 20,
                          .hh = wall.y != 0 ? 10 : half + 20,
                          .bounce = 1,
                          .friction = 0});
    std::vector<BodyId> gas;
    std::uint32_t seed = 12345;
    auto random = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24) - 0.5f; // in [-0.5, 0.5)
    };
    for (int i = 0; i < 500; ++i) {
        const float x = -half + 20 + (2 * half - 40) * (float(i % 23) + 0.5f) / 23;
        const float y = -half + 20 + (2 * half - 40) * (float(i / 23) + 0.5f) / 23;
        gas.push_back(world.createBody(ball(x, y, 400 * random(), 400 * random())));
    }
    const double energy = kineticEnergy(world, gas);
    for (int i = 0; i < 20 * 60; ++i)
        world.step(kDt);
    EXPECT_GE(kineticEnergy(world, gas) / energy, 0.95);
    EXPECT_LE(kineticEnergy(world, gas) / energy, 1.0 + 1e-4);
}

/// A group of 2 to 8 boxes of random sizes, masses, bounces and frictions, placed close
/// together (apart, touching in rows, overlapping a little) and thrown at each other.
std::vector<BodyId> randomGroup(World& world, std::uint32_t& seed) {
    auto random = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24); // in [0, 1)
    };
    const int count = 2 + int(random() * 7.0f);
    std::vector<BodyId> group;
    for (int i = 0; i < count; ++i) {
        const float hw = 4 + 8 * random(), hh = 4 + 8 * random();
        const float arrangement = random();
        // A row touching along x, a column along y, or anywhere near.
        const float x = arrangement < 0.3f ? 20.0f * float(i) : 40 * random();
        const float y =
            arrangement >= 0.3f && arrangement < 0.6f ? 20.0f * float(i) : 40 * random();
        group.push_back(world.createBody({.x = x,
                                          .y = y,
                                          .hw = hw,
                                          .hh = hh,
                                          .vx = 600 * (random() - 0.5f),
                                          .vy = 600 * (random() - 0.5f),
                                          .bounce = random() < 0.3f ? 1.0f : random(),
                                          .friction = random() < 0.3f ? 0.0f : random(),
                                          .density = 0.5f + 4 * random()}));
    }
    return group;
}

TEST(Energy, NoStepCreatesKineticEnergyInAnyGroup) {
    // Thousands of groups, each stepped a few times: no step ends with more kinetic energy
    // than it began with (within float rounding), and momentum is the same throughout.
    std::uint32_t seed = 2026;
    for (int trial = 0; trial < 3000; ++trial) {
        World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
        const std::vector<BodyId> group = randomGroup(world, seed);
        const Vec2 p0 = momentum(world, group);
        float scale = 0.0f;
        for (BodyId id : group)
            scale += world.mass(id) * length(world.velocity(id));
        for (int step = 0; step < 4; ++step) {
            const double before = kineticEnergy(world, group);
            world.step(kDt);
            const double after = kineticEnergy(world, group);
            ASSERT_LE(after, before * (1.0 + 1e-5) + 1e-3) << "trial " << trial << " step " << step;
            const Vec2 p = momentum(world, group);
            ASSERT_NEAR(p.x, p0.x, 1e-4f * scale) << "trial " << trial << " step " << step;
            ASSERT_NEAR(p.y, p0.y, 1e-4f * scale) << "trial " << trial << " step " << step;
        }
    }
}

TEST(Energy, WithGravityAndAFloorNoStepCreatesMoreThanGravityGives) {
    // Over a floor, gravity adds its work: a step ends with at most the kinetic energy
    // each body would have with gravity's g dt added to its velocity.
    std::uint32_t seed = 77;
    const Vec2 g{0, 800};
    for (int trial = 0; trial < 1000; ++trial) {
        World world(WorldDef{.gravity = g, .sleeping = false});
        world.createBody({.type = BodyType::Static, .x = 20, .y = 60, .hw = 200, .hh = 10});
        const std::vector<BodyId> group = randomGroup(world, seed);
        for (int step = 0; step < 4; ++step) {
            double allowed = 0.0;
            for (BodyId id : group)
                allowed += energyOf(world.mass(id), world.velocity(id) + g * kDt);
            world.step(kDt);
            ASSERT_LE(kineticEnergy(world, group), allowed * (1.0 + 1e-5) + 1e-3)
                << "trial " << trial << " step " << step;
        }
    }
}

} // namespace
} // namespace jostle
