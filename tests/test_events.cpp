// What a step reports: contact begin and end, touching flags, crushes.
#include "counting_sort.hpp"
#include "jostle/world.hpp"
#include "world_access.hpp"
#include "world_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 800.0f;

struct Level {
    explicit Level(Solver solver = Solver::Physical, bool sleeping = false)
        : world(WorldDef{.gravity = {0, kG}, .solver = solver, .sleeping = sleeping}) {}
    World world;
    // Top face at y = 0 (y grows downward).
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    std::vector<ContactEvent> begins, ends;

    void run(int steps) {
        for (int i = 0; i < steps; ++i) {
            world.step(kDt);
            begins.insert(begins.end(), world.contactBegins().begin(), world.contactBegins().end());
            ends.insert(ends.end(), world.contactEnds().begin(), world.contactEnds().end());
        }
    }
};

class DroppedBox : public ::testing::TestWithParam<Solver> {};

TEST_P(DroppedBox, BeginsTouchingOnceWithItsImpactSpeed) {
    Level level(GetParam());
    // Its bottom 100 above the floor: it lands at sqrt(2 g h).
    BodyId box = level.world.createBody({.x = 0, .y = -105, .hw = 5, .hh = 5});
    level.run(120);
    ASSERT_EQ(level.begins.size(), 1u);
    const ContactEvent& e = level.begins[0];
    EXPECT_EQ(e.a, level.floor); // created first
    EXPECT_EQ(e.b, box);
    EXPECT_EQ(e.normal, (Vec2{0, 1})); // from the box towards the floor
    // The speed is read at the start of the step it lands in: within one step's gravity
    // (g dt = 13.3) of the true impact speed.
    EXPECT_NEAR(e.approachSpeed, std::sqrt(2 * kG * 100), kG * kDt + 0.5f);
    EXPECT_TRUE(level.ends.empty()); // resting: still touching
    EXPECT_TRUE(level.world.touching(box).floor);
}

TEST_P(DroppedBox, EndsTouchingWhenItJumps) {
    Level level(GetParam());
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(30);
    ASSERT_EQ(level.begins.size(), 1u);
    level.world.setVelocity(box, {0, -400});
    level.run(10);
    ASSERT_EQ(level.ends.size(), 1u);
    EXPECT_EQ(level.ends[0].a, level.floor);
    EXPECT_EQ(level.ends[0].b, box);
    EXPECT_FALSE(level.world.touching(box).floor);
}

INSTANTIATE_TEST_SUITE_P(Models, DroppedBox, ::testing::Values(Solver::Classic, Solver::Physical),
                         [](const ::testing::TestParamInfo<Solver>& model) {
                             return model.param == Solver::Classic ? "Classic" : "Physical";
                         });

TEST(Events, DestroyingABodyEndsItsContacts) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(10);
    level.world.destroyBody(box);
    level.run(1);
    ASSERT_EQ(level.ends.size(), 1u);
    EXPECT_EQ(level.ends[0].b, box); // the handle it had, now stale
    EXPECT_FALSE(level.world.isValid(level.ends[0].b));
}

TEST(Events, FallingAsleepEndsNothing) {
    Level level(Solver::Physical, true);
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(300);
    ASSERT_FALSE(level.world.isAwake(box));
    EXPECT_EQ(level.begins.size(), 1u);
    EXPECT_TRUE(level.ends.empty());
    EXPECT_TRUE(level.world.touching(box).floor);
}

// Columns asleep between columns kept awake, made row by row so that their pairs lie among
// each other's by slot: each step the awake columns' pairs are this step's list and the
// sleeping ones carry over into it, in order. Nothing begins or ends, and every box still
// touches what it rests on and what rests on it.
TEST(Events, PairsOfSleepingColumnsCarryOverAmongAwakeOnes) {
    Level level(Solver::Physical, true);
    constexpr int kColumns = 6, kRows = 4;
    std::vector<std::vector<BodyId>> columns(kColumns);
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column)
            columns[std::size_t(column)].push_back(level.world.createBody(
                {.x = 30.0f * float(column), .y = -5.0f - 10.0f * float(row), .hw = 5, .hh = 5}));
    level.run(300);
    for (const auto& column : columns)
        ASSERT_FALSE(level.world.isAwake(column[0]));
    level.begins.clear();
    for (int step = 0; step < 30; ++step) {
        for (int column = 1; column < kColumns; column += 2)
            level.world.wake(columns[std::size_t(column)][0]);
        level.run(1);
    }
    EXPECT_TRUE(level.begins.empty());
    EXPECT_TRUE(level.ends.empty());
    for (int column = 0; column < kColumns; ++column) {
        const auto& boxes = columns[std::size_t(column)];
        EXPECT_EQ(level.world.isAwake(boxes[0]), column % 2 == 1) << "column " << column;
        for (int row = 0; row < kRows; ++row) {
            std::vector<BodyId> expected{row == 0 ? level.floor : boxes[std::size_t(row - 1)]};
            if (row + 1 < kRows)
                expected.push_back(boxes[std::size_t(row + 1)]);
            std::vector<BodyId> found;
            for (const ContactInfo& contact : level.world.contacts(boxes[std::size_t(row)]))
                found.push_back(contact.other);
            const auto bySlot = [](BodyId x, BodyId y) { return x.index < y.index; };
            std::sort(expected.begin(), expected.end(), bySlot);
            std::sort(found.begin(), found.end(), bySlot);
            EXPECT_EQ(found, expected) << "column " << column << ", row " << row;
        }
    }
}

// The physical model lists its touching contacts sorted by pair (in the order of the contact
// cache it has just stored) and merges them with the last step's in the list's own room: two
// lists of touching pairs, each with room for an eighth more than it holds, where sorting
// and merging through a third list kept three.
TEST(Events, ThePhysicalModelKeepsTwoListsOfTouchingPairs) {
    for (int workers : {1, 2}) {
        World world(WorldDef{.gravity = {0, kG}, .tasks = {.workers = workers}});
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
        for (int column = 0; column < 40; ++column)
            for (int row = 0; row < 20; ++row)
                world.createBody({.x = 20.0f * float(column) - 400.0f,
                                  .y = -5.0f - 10.0f * float(row),
                                  .hw = 5,
                                  .hh = 5});
        std::size_t touching = 0;
        for (int step = 0; step < 30; ++step) {
            world.step(kDt);
            touching = WorldAccess::state(world).events.touchingBefore().size();
        }
        ASSERT_EQ(touching, 40u * 20u) << "each box on the one below, the bottom ones on the floor";
        EXPECT_LE(WorldAccess::state(world).events.contactRecordRoom(), 2 * touching * 9 / 8 + 2)
            << workers << " workers";
    }
}

TEST(Touching, WallsAndCeilingRelativeToGravity) {
    Level level;
    // Walls at x = ±20 (inner faces), a ceiling with its bottom face at y = -40.
    level.world.createBody({.type = BodyType::Static, .x = 30, .y = -50, .hw = 10, .hh = 50});
    level.world.createBody({.type = BodyType::Static, .x = -30, .y = -50, .hw = 10, .hh = 50});
    level.world.createBody({.type = BodyType::Static, .x = 0, .y = -50, .hw = 20, .hh = 10});
    BodyId right = level.world.createBody({.x = 10, .y = -5, .hw = 5, .hh = 5, .vx = 200});
    BodyId left = level.world.createBody({.x = -10, .y = -5, .hw = 5, .hh = 5, .vx = -200});
    BodyId up = level.world.createBody({.x = 0, .y = -20, .hw = 4, .hh = 4, .gravityScale = -1});
    level.run(30);
    const Touching r = level.world.touching(right);
    EXPECT_TRUE(r.floor && r.wallRight && !r.wallLeft && !r.ceiling);
    const Touching l = level.world.touching(left);
    EXPECT_TRUE(l.floor && l.wallLeft && !l.wallRight && !l.ceiling);
    const Touching u = level.world.touching(up);
    EXPECT_TRUE(u.ceiling && !u.floor);
}

TEST(Touching, FollowsGravityWhenItTurns) {
    // Gravity pulling right: the wall on the right is the floor now.
    World world(WorldDef{.gravity = {kG, 0}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 50, .y = 0, .hw = 40, .hh = 1000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 5, .hh = 5});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    EXPECT_TRUE(world.touching(box).floor);
}

// A block 20 high comes down at 60 units/s onto a box 10 high on the floor (top y = 0),
// and goes on down through the floor, as a kinematic body does. The crush begins once,
// when the block is a tenth of the box's half height into it; until then the box is
// pressed into the floor by no more than that, and from then on it stays on the floor
// (within the slop), the block passing through it; the crush ends once, when the block's
// top has gone below the box's bottom (the floor's top): the two no longer overlap. (It
// was reported at every step, and the box was pushed 13 units into the floor: issue 29.)
TEST(Crush, BeginsOnceTheBoxStaysOnTheFloorAndEndsWhenTheBlockHasPassed) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    BodyId block = level.world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = -40, .hw = 30, .hh = 10, .vy = 60});
    int begins = 0, ends = 0, beganAt = -1, endedAt = -1;
    for (int i = 0; i < 120; ++i) {
        level.world.step(kDt);
        for (const CrushEvent& e : level.world.crushBegins()) {
            EXPECT_EQ(e.body, box);
            EXPECT_EQ(e.by, block);
            EXPECT_EQ(e.against, level.floor);
            ++begins;
            beganAt = i;
        }
        for (const CrushEvent& e : level.world.crushEnds()) {
            EXPECT_EQ(e.body, box);
            EXPECT_EQ(e.by, block);
            ++ends;
            endedAt = i;
        }
        // Never deeper in the floor than the crush depth and the slop (0.5 + 0.05).
        ASSERT_LE(level.world.position(box).y, -5.0f + 0.55f) << "step " << i;
        // Ten steps into the crush, back on the floor within the slop.
        if (beganAt >= 0 && i >= beganAt + 10) {
            EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.05f + 1e-4f) << "step " << i;
        }
    }
    EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.05f + 1e-4f);
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
    // The block's top (its y - 10) passes the floor's top (0) at y = 10: from -40 at 1 unit a
    // step, after 50 steps.
    EXPECT_NEAR(endedAt, 50, 1);
}

TEST(Crush, ARiderOnALiftIsNotCrushed) {
    Level level;
    BodyId lift = level.world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = -10, .hw = 30, .hh = 10, .vy = -60});
    level.world.createBody({.x = 0, .y = -25, .hw = 5, .hh = 5});
    for (int i = 0; i < 60; ++i) {
        level.world.step(kDt);
        EXPECT_TRUE(level.world.crushBegins().empty()) << "step " << i;
    }
    (void)lift;
}

// The touch lists are sorted by pair each step: by two counting sorts over the slots, or,
// where the records are few against the slots (a level of many static boxes), by a merge
// sort. Both must give the order a stable sort gives, equal keys kept in their order, or
// the events would depend on the number of bodies in the world.
TEST(TouchLists, BothSortsGiveTheStableOrder) {
    std::mt19937 random(7);
    for (std::size_t n : {0u, 1u, 2u, 3u, 7u, 8u, 9u, 100u, 1000u}) {
        // (key, the item's place before sorting): keys from a small range, so many repeat.
        std::vector<std::pair<std::uint32_t, std::uint32_t>> items(n);
        for (std::uint32_t k = 0; k < n; ++k)
            items[k] = {std::uint32_t(random() % (n / 3 + 1)), k};
        auto byKey = [](const auto& a, const auto& b) { return a.first < b.first; };
        auto expected = items;
        std::stable_sort(expected.begin(), expected.end(), byKey);

        auto merged = items, scratch = items;
        mergeSortByKey(
            merged, [](const auto& item) { return item.first; }, scratch);
        EXPECT_EQ(merged, expected) << n << " items";

        auto counted = items;
        Buckets buckets;
        sortByKey(
            counted, [](const auto& item) { return item.first; }, n / 3 + 1, buckets, scratch);
        EXPECT_EQ(counted, expected) << n << " items";
    }
}

} // namespace
} // namespace jostle
