// The contact cache finds last step's contact of a pair, whether the pair's first body has
// a few contacts (searched in turn) or thousands (a floor under a crowd: its run sorted
// and searched by halves), and always the first of a pair's contacts in the step's order.
#include "physical/contact_cache.hpp"
#include "tasks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace jostle {
namespace {

struct Added {
    std::uint32_t a, b;
    float impulse; ///< tells the entries apart
};

void rebuild(ContactCache& cache, const std::vector<Added>& contacts, TaskRunner& tasks,
             std::uint32_t slotCount) {
    cache.beginRebuild(slotCount);
    std::vector<std::uint32_t> ranks;
    for (const Added& c : contacts)
        ranks.push_back(cache.count(c.a));
    cache.endCounting();
    // Filled back to front: the filling pass may go in any order.
    for (std::size_t k = contacts.size(); k-- > 0;)
        cache.add(contacts[k].a, ranks[k], contacts[k].b, std::uint32_t(k),
                  {1, 1, {0.0f, -1.0f}, contacts[k].impulse, 0.0f});
    cache.endRebuild(tasks);
}

/// A floor (slot 0) under 3,000 bodies, listed in a shuffled order, some pairs twice; and
/// a few bodies with short runs.
std::vector<Added> crowdOnAFloor() {
    std::vector<Added> contacts;
    for (std::uint32_t b = 1; b <= 3000; ++b)
        contacts.push_back({0, b, float(b)});
    std::mt19937 rng(7);
    std::shuffle(contacts.begin(), contacts.end(), rng);
    contacts.push_back({0, 42, -1.0f}); // a second contact of (0, 42), after the first
    for (std::uint32_t a = 1; a <= 20; ++a)
        contacts.push_back({a, a + 1, 10000.0f + float(a)});
    contacts.push_back({5, 6, -2.0f}); // a second contact of a short run's pair
    return contacts;
}

void expectEveryPairFound(const ContactCache& cache) {
    for (std::uint32_t b = 1; b <= 3000; ++b) {
        const CachedContact* found = cache.find(0, b);
        ASSERT_NE(found, nullptr) << "floor and body " << b;
        EXPECT_EQ(found->normalImpulse, float(b)) << "the first contact of (0, " << b << ")";
    }
    for (std::uint32_t a = 1; a <= 20; ++a) {
        const CachedContact* found = cache.find(a, a + 1);
        ASSERT_NE(found, nullptr) << a;
        EXPECT_EQ(found->normalImpulse, 10000.0f + float(a));
    }
    EXPECT_EQ(cache.find(0, 3001), nullptr);
    EXPECT_EQ(cache.find(0, 0), nullptr);
    EXPECT_EQ(cache.find(3, 5), nullptr);
    EXPECT_EQ(cache.find(2999, 1), nullptr);   // a slot with no contacts
    EXPECT_EQ(cache.find(100000, 1), nullptr); // beyond the slots
}

TEST(ContactCache, FindsEveryPairOfALongRunAndTheFirstOfDuplicates) {
    ContactCache cache;
    TaskRunner tasks(TaskSystem{});
    rebuild(cache, crowdOnAFloor(), tasks, 3001);
    expectEveryPairFound(cache);
}

TEST(ContactCache, TheSameOnSeveralWorkersInSmallBlocks) {
    ContactCache cache;
    TaskSystem system;
    system.workers = 3;
    TaskRunner tasks(system);
    tasks.setBlockSizeForTesting(1);
    // Rebuilt twice: the second rebuild starts from the first's long runs.
    rebuild(cache, crowdOnAFloor(), tasks, 3001);
    rebuild(cache, crowdOnAFloor(), tasks, 3001);
    expectEveryPairFound(cache);
}

TEST(ContactCache, ClearForgetsEverything) {
    ContactCache cache;
    TaskRunner tasks(TaskSystem{});
    rebuild(cache, crowdOnAFloor(), tasks, 3001);
    cache.clear();
    EXPECT_EQ(cache.find(0, 1), nullptr);
    EXPECT_EQ(cache.find(1, 2), nullptr);
}

} // namespace
} // namespace jostle
