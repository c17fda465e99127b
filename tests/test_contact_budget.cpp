// The contact budget (PhysicalOptions::maxContactsPerBody, docs/physical-model.md): boxes
// piled at one spot keep a bounded number of contacts, a crowd never crowds out the floor,
// and a sane scene leaves nothing out. (A step's memory for such a pile:
// test_allocations.cpp.)
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

std::size_t contactCount(const World& world) {
    std::size_t count = 0;
    for (BodyId id : world.bodies())
        count += world.contacts(id).size();
    return count / 2; // each contact is listed by both of its bodies
}

// 1,000 boxes at one spot make half a million overlapping pairs; a step kept a contact for each
// (10,000 such boxes took 8 GB). Each dynamic body now has a budget of contacts.
TEST(ContactBudget, BoxesPiledAtOneSpotKeepABoundedNumberOfContacts) {
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    constexpr int kBoxes = 1000;
    for (int i = 0; i < kBoxes; ++i)
        world.createBody({.x = 0, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    world.step(kDt);
    const int budget = PhysicalOptions{}.maxContactsPerBody;
    // Each box: at most `budget` moving neighbours (each pair counted by both) and as many
    // resting ones (here only the ground).
    EXPECT_LE(contactCount(world), std::size_t(kBoxes) * std::size_t(budget) / 2 + kBoxes);
    EXPECT_GT(world.pairsLeftOut(), 400'000u);
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    for (BodyId id : world.bodies())
        EXPECT_TRUE(std::isfinite(world.position(id).y));
}

// The crowd's pairs are counted apart from the ground's: however crowded a box is, it
// keeps its floor and never falls through it.
TEST(ContactBudget, ACrowdNeverCrowdsOutTheFloor) {
    World world(WorldDef{.gravity = {0, 10}, .physical = {.maxContactsPerBody = 4}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 100, .hh = 1});
    for (int i = 0; i < 50; ++i)
        world.createBody({.x = float(i % 5) * 0.1f, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (BodyId id : world.bodies()) {
            if (world.type(id) == BodyType::Dynamic) {
                ASSERT_LT(world.position(id).y, 0.0f) << "step " << i;
            }
        }
    }
}

TEST(ContactBudget, ASaneSceneLeavesNothingOut) {
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 100, .hh = 1});
    for (int row = 0; row < 20; ++row)
        for (int i = 0; i < 20 - row; ++i)
            world.createBody({.x = float(i) - 0.5f * float(19 - row),
                              .y = -0.5f - float(row),
                              .hw = 0.5f,
                              .hh = 0.5f});
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.pairsLeftOut(), 0u);
    }
}

TEST(ContactBudget, MustBeAtLeastOne) {
    EXPECT_TRUE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 0}}).has_value());
    EXPECT_TRUE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 65537}}).has_value());
    EXPECT_FALSE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 1}}).has_value());
}

} // namespace
} // namespace jostle
