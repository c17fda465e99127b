// Destroying bodies costs O(1) amortised, in any order: when destroyBody searched the
// creation order, destroying a million bodies in reverse took minutes (issue 19). Ten times
// the bodies take about ten times as long (growth.hpp: measured in one process, so a busy
// machine cannot fail it). Speed itself: jostle-bench --lifecycle (docs/benchmarks.md).
#include "growth.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace jostle {
namespace {

std::vector<BodyId> createMany(World& world, int bodies) {
    std::vector<BodyId> ids;
    ids.reserve(static_cast<std::size_t>(bodies));
    for (int i = 0; i < bodies; ++i)
        ids.push_back(world.createBody({.x = static_cast<float>(3 * (i % 1000)),
                                        .y = static_cast<float>(3 * (i / 1000)),
                                        .hw = 1,
                                        .hh = 1}));
    return ids;
}

/// Creates `bodies` bodies, then destroys them in reverse order, then in creation order.
void createAndDestroy(int bodies) {
    World world;
    std::vector<BodyId> ids = createMany(world, bodies);
    for (std::size_t i = ids.size(); i-- > 0;)
        world.destroyBody(ids[i]);
    ids = createMany(world, bodies);
    for (BodyId id : ids)
        world.destroyBody(id);
}

TEST(DestroyMany, TenTimesTheBodiesTakeTenTimesAsLong) {
    // 300,000 in reverse took minutes when each destroy searched the creation order.
    const double growth =
        test_support::growthOf([] { createAndDestroy(30'000); }, [] { createAndDestroy(300'000); });
    EXPECT_LT(growth, test_support::kTenTimesTheWorkAtMost) << "ten times the bodies";
}

TEST(DestroyMany, InReverseOrderThenInCreationOrderTheRestKeepTheirOrder) {
    World world;
    std::vector<BodyId> ids = createMany(world, 100'000);
    // Every tenth body is kept, to check the order of the rest at the end.
    std::vector<BodyId> kept;
    for (std::size_t i = ids.size(); i-- > 0;)
        if (i % 10 != 0)
            world.destroyBody(ids[i]);
    for (std::size_t i = 0; i < ids.size(); i += 10)
        kept.push_back(ids[i]);
    ASSERT_EQ(world.bodyCount(), kept.size());
    ASSERT_TRUE(std::equal(kept.begin(), kept.end(), world.bodies().begin(), world.bodies().end()));
    for (BodyId id : kept)
        world.destroyBody(id);
    EXPECT_EQ(world.bodyCount(), 0u);
    EXPECT_TRUE(world.bodies().empty());
}

} // namespace
} // namespace jostle
