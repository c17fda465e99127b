// Destroying a million bodies, in creation order and in reverse, under ctest's TIMEOUT
// (tests/CMakeLists.txt): destroyBody costs O(1) amortised, so this takes about a second;
// when it searched the creation order, the reverse order alone took minutes (issue 19).
// Speed itself is measured by jostle-bench --lifecycle (docs/benchmarks.md).
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace jostle {
namespace {

constexpr int kBodies = 1'000'000;

std::vector<BodyId> createMany(World& world) {
    std::vector<BodyId> ids;
    ids.reserve(kBodies);
    for (int i = 0; i < kBodies; ++i)
        ids.push_back(world.createBody({.x = static_cast<float>(3 * (i % 1000)),
                                        .y = static_cast<float>(3 * (i / 1000)),
                                        .hw = 1,
                                        .hh = 1}));
    return ids;
}

TEST(DestroyMillion, InReverseOrderThenInCreationOrder) {
    World world;
    std::vector<BodyId> ids = createMany(world);
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

    ids = createMany(world);
    for (BodyId id : ids)
        world.destroyBody(id);
    EXPECT_EQ(world.bodyCount(), 0u);
    EXPECT_TRUE(world.bodies().empty());
}

} // namespace
} // namespace jostle
