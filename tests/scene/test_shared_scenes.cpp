// The shared scenes (shared/scenes.hpp), the ones the benchmark times, run in the
// physical model and judged by the benchmark's own quality figures (shared/quality.hpp):
// what the benchmark reports beside its times is held to bounds here, at smaller sizes.
//
// The bounds come from the physical model's settings: resting contact may overlap by up to
// twice the slop, 0.01 × the smaller half extent of the pair (docs/physical-model.md).
#include "shared/quality.hpp"
#include "shared/scenes.hpp"

#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace jostle {
namespace {

constexpr float kSlopFraction = 0.01f; // PhysicalOptions::slop's default

struct Outcome {
    std::vector<Vec2> positions;
    shared::Quality quality;
};

Outcome simulate(Scene scene, int steps, bool sleeping) {
    scene.world.sleeping = sleeping;
    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    for (int i = 0; i < steps; ++i)
        world.step(scene.dt);
    Outcome run;
    for (BodyId id : ids)
        run.positions.push_back(world.position(id));
    run.quality = shared::measureQuality(scene, run.positions);
    return run;
}

class SharedScenes : public ::testing::TestWithParam<bool> {};

TEST_P(SharedScenes, APyramidStandsForTenSeconds) {
    const int rows = 20;
    const Outcome run = simulate(shared::pyramid(rows), 600, GetParam());
    // Unit boxes (half extent 0.5): each of the rows may sit up to twice the slop deep in
    // the one below.
    const float restingOverlap = 2.0f * kSlopFraction * 0.5f;
    ASSERT_TRUE(run.quality.topDrift);
    EXPECT_LE(*run.quality.topDrift, float(rows) * restingOverlap);
    EXPECT_LE(run.quality.maxPenetration, restingOverlap + 1e-5f);
    EXPECT_EQ(run.quality.escaped, 0);
}

TEST_P(SharedScenes, ManyPyramidsStand) {
    const Outcome run = simulate(shared::manyPyramids(10, 10), 600, GetParam());
    const float restingOverlap = 2.0f * kSlopFraction * 0.5f;
    ASSERT_TRUE(run.quality.topDrift);
    EXPECT_LE(*run.quality.topDrift, 10.0f * restingOverlap);
    EXPECT_LE(run.quality.maxPenetration, restingOverlap + 1e-5f);
    EXPECT_EQ(run.quality.escaped, 0);
}

TEST_P(SharedScenes, RainSettlesIntoAPileWithoutDeepOverlaps) {
    // Landed by 2 s (shared/scenes.hpp); 4 s to settle.
    const Outcome run = simulate(shared::rain(2000), 240, GetParam());
    // The largest half extent is 2.
    EXPECT_LE(run.quality.maxPenetration, 2.0f * kSlopFraction * 2.0f + 1e-5f);
    EXPECT_EQ(run.quality.escaped, 0);
}

TEST_P(SharedScenes, GasStaysInItsBox) {
    const Outcome run = simulate(shared::gas(2000), 600, GetParam());
    EXPECT_EQ(run.quality.escaped, 0);
}

TEST_P(SharedScenes, TilemapActorsStayInTheLevel) {
    const Outcome run = simulate(shared::tilemap(1000), 600, GetParam());
    EXPECT_EQ(run.quality.escaped, 0);
}

TEST_P(SharedScenes, ACrowdStandsStillOnOneLongFloorAndOnAPiecedOne) {
    // Unit boxes set down exactly on the floor: nothing pushes them anywhere, and each may
    // sink into the floor by up to twice the slop.
    const float restingOverlap = 2.0f * kSlopFraction * 0.5f;
    for (int pieces : {1, 40}) {
        const Scene scene = shared::crowdOnFloor(2000, pieces);
        const Outcome run = simulate(scene, 300, GetParam());
        EXPECT_LE(run.quality.maxPenetration, restingOverlap + 1e-5f) << pieces;
        EXPECT_EQ(run.quality.escaped, 0) << pieces;
        for (std::size_t k = std::size_t(pieces); k < scene.bodies.size(); ++k) {
            const BodyDef& start = scene.bodies[k].def;
            ASSERT_EQ(run.positions[k].x, start.x) << pieces << " pieces, box " << k;
            ASSERT_NEAR(run.positions[k].y, start.y, restingOverlap + 1e-5f)
                << pieces << " pieces, box " << k;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SleepingOffAndOn, SharedScenes, ::testing::Bool());

// Elastic boxes in a closed box: collisions may lose energy (several at once are solved
// approximately), but nothing may create it, position correction included.
TEST(SharedScenesEnergy, GasNeverGainsEnergy) {
    Scene scene = shared::gas(2000);
    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    auto energy = [&] {
        double sum = 0.0;
        for (BodyId id : ids) {
            if (world.type(id) != BodyType::Dynamic)
                continue; // the walls: infinitely heavy, at rest
            const Vec2 v = world.velocity(id);
            sum += double(world.mass(id)) * (double(v.x) * double(v.x) + double(v.y) * double(v.y));
        }
        return sum / 2.0;
    };
    const double start = energy();
    for (int i = 0; i < 600; ++i) {
        world.step(scene.dt);
        // Float rounding of a sum of 2,000 terms: far below one part in 10^4.
        ASSERT_LE(energy(), start * (1.0 + 1e-4)) << "step " << i;
    }
}

TEST(SharedScenesDeterminism, RainTwiceIsTheSameBitForBit) {
    const Outcome first = simulate(shared::rain(1000), 120, true);
    const Outcome second = simulate(shared::rain(1000), 120, true);
    ASSERT_EQ(first.positions.size(), second.positions.size());
    EXPECT_EQ(std::memcmp(first.positions.data(), second.positions.data(),
                          first.positions.size() * sizeof(Vec2)),
              0);
}

} // namespace
} // namespace jostle
