// Handles of other worlds and of destroyed bodies, the end of the ranges of world serial
// numbers and of generations, and the creation order of bodies() through creates and
// destroys. (Basic handle checks: test_world.cpp.)
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include "handles.hpp"
#include "world_access.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace jostle {
namespace {

BodyDef boxAt(float x, float y) {
    return {.x = x, .y = y, .hw = 1, .hh = 1};
}

std::string messageOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const Error& e) {
        return e.what();
    }
    return "no exception";
}

// --- Another world's handles ----------------------------------------------------------------

TEST(Handles, TwoWorldsFirstBodiesDifferOnlyByTheirWorldAndAreToldApart) {
    World first;
    World second;
    const BodyId a = first.createBody(boxAt(0, 0));
    const BodyId b = second.createBody(boxAt(5, 0));
    ASSERT_EQ(a.index, b.index);
    ASSERT_EQ(a.generation, b.generation);
    EXPECT_NE(a.world, b.world);
    EXPECT_NE(a, b);
    EXPECT_FALSE(first.isValid(b));
    EXPECT_FALSE(second.isValid(a));
    EXPECT_EQ(messageOf([&] {
                  first.setPosition(b, {1, 1});
              }),
              "setPosition: BodyId of another world");
    EXPECT_EQ(messageOf([&] { second.destroyBody(a); }), "destroyBody: BodyId of another world");
    EXPECT_EQ(messageOf([&] {
                  (void)queryPoint(first, {0, 0}, {.ignore = b});
              }),
              "queryPoint: QueryFilter.ignore: BodyId of another world");
    EXPECT_EQ(first.position(a), (Vec2{0, 0}));
    EXPECT_EQ(second.position(b), (Vec2{5, 0}));
    EXPECT_EQ(second.bodyCount(), 1u);
}

TEST(Handles, AHandleNoWorldMadeIsOfAnotherWorld) {
    World world;
    const BodyId a = world.createBody(boxAt(0, 0));
    EXPECT_EQ(messageOf([&] {
                  (void)world.position(BodyId{a.index, a.generation, 0});
              }),
              "position: BodyId of another world");
    EXPECT_EQ(messageOf([&] { (void)world.position(BodyId{}); }), "position: null BodyId");
    world.destroyBody(a);
    EXPECT_EQ(messageOf([&] { (void)world.position(a); }),
              "position: stale BodyId (the body was destroyed)");
}

TEST(Handles, TileMapsOfTwoWorldsInTheSameSlotAreToldApart) {
    World first;
    World second;
    const TileMapDef def{.tile = 4, .rows = {"##"}};
    const TileMapId a = createTileMap(first, def);
    const TileMapId b = createTileMap(second, def);
    ASSERT_EQ(a.index, b.index);
    ASSERT_EQ(a.generation, b.generation);
    EXPECT_NE(a, b);
    EXPECT_FALSE(first.isValid(b));
    EXPECT_EQ(messageOf([&] { setTile(first, b, 0, 0, false); }),
              "setTile: TileMapId of another world");
    EXPECT_TRUE(isSolid(first, a, 0, 0));
    destroyTileMap(first, a);
    EXPECT_EQ(messageOf([&] { setTile(first, a, 0, 0, false); }),
              "setTile: stale TileMapId (the map was destroyed)");
}

// Issue 19: each world used to start its generations at its own value, so a world made
// 28,657 worlds after another started 52,777 above it, and after as many reuses of slot 0
// in the older world the two worlds' handles there were equal: setPosition with the
// newer world's handle moved the older world's own body.
TEST(ForeignHandles, ARecipeThatOnceMadeTwoWorldsHandlesEqualIsRefused) {
    World world;
    BodyId mine = world.createBody(boxAt(0, 0));
    for (int i = 1; i < 28657; ++i)
        World intervening;
    World other;
    const BodyId theirs = other.createBody(boxAt(5, 0));
    for (int i = 0; i < 52777; ++i) {
        world.destroyBody(mine);
        mine = world.createBody(boxAt(0, 0));
    }
    ASSERT_EQ(mine.index, theirs.index);
    EXPECT_FALSE(world.isValid(theirs));
    EXPECT_THROW(world.setPosition(theirs, {100, 100}), Error);
    EXPECT_EQ(world.position(mine), (Vec2{0, 0}));
    EXPECT_EQ(other.position(theirs), (Vec2{5, 0}));
}

// --- The end of the ranges ----------------------------------------------------------------

TEST(Handles, WorldSerialsAreGivenOnceEachUpToTheLast) {
    WorldSerials serials;
    EXPECT_EQ(serials.take(), 1u);
    EXPECT_EQ(serials.take(), 2u);
    serials.exchangeLast(UINT32_MAX - 1);
    EXPECT_EQ(serials.take(), UINT32_MAX);
    EXPECT_EQ(serials.take(), std::nullopt);
    EXPECT_EQ(serials.take(), std::nullopt); // and it stays so: no wrap-around to 0 or 1
}

TEST(Handles, WorldSerialsFromSeveralThreadsAreAllDifferent) {
    WorldSerials serials;
    constexpr int kThreads = 4;
    constexpr int kEach = 2000;
    std::vector<std::vector<std::uint32_t>> taken(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&serials, &mine = taken[static_cast<std::size_t>(t)]] {
            for (int i = 0; i < kEach; ++i)
                mine.push_back(serials.take().value_or(0));
        });
    for (std::thread& thread : threads)
        thread.join();
    std::set<std::uint32_t> all;
    for (const std::vector<std::uint32_t>& mine : taken)
        all.insert(mine.begin(), mine.end());
    EXPECT_EQ(all.size(), std::size_t{kThreads * kEach});
    EXPECT_EQ(*all.begin(), 1u);
    EXPECT_EQ(*all.rbegin(), std::uint32_t{kThreads * kEach});
}

/// Makes the process's world serials look nearly used up, for the life of the object.
class LastSerialsScope {
public:
    explicit LastSerialsScope(std::uint32_t last) : saved_(worldSerials().exchangeLast(last)) {}
    ~LastSerialsScope() { worldSerials().exchangeLast(saved_); }
    LastSerialsScope(const LastSerialsScope&) = delete;
    LastSerialsScope& operator=(const LastSerialsScope&) = delete;

private:
    std::uint32_t saved_;
};

TEST(Handles, AWorldBeyondTheLastSerialIsRefused) {
    LastSerialsScope scope(UINT32_MAX - 1);
    World last;
    const BodyId a = last.createBody(boxAt(0, 0));
    EXPECT_EQ(a.world, UINT32_MAX);
    EXPECT_TRUE(last.isValid(a));
    EXPECT_EQ(messageOf([] { World refused; }),
              "World: this process has made 4294967295 worlds, as many as handles can tell "
              "apart (BodyId::world)");
    EXPECT_EQ(last.position(a), (Vec2{0, 0})); // the last world works
}

// Until slots retired at the last generation, a slot's generation went from UINT32_MAX
// back to 1, and the handle of the slot's first body named its 4,294,967,296th.
TEST(Handles, ASlotAtTheLastGenerationIsRetiredNotReused) {
    World world;
    const BodyId first = world.createBody(boxAt(0, 0));
    world.destroyBody(first);
    // As if the slot had been reused 4,294,967,293 more times since.
    WorldAccess::state(world).slots[first.index].generation = UINT32_MAX;
    const BodyId last = world.createBody(boxAt(1, 0));
    ASSERT_EQ(last.index, first.index);
    EXPECT_EQ(last.generation, UINT32_MAX);
    world.destroyBody(last);
    const BodyId next = world.createBody(boxAt(2, 0));
    EXPECT_NE(next.index, first.index); // a new slot: the old one is retired
    EXPECT_EQ(next.generation, 1u);
    EXPECT_FALSE(world.isValid(first));
    EXPECT_FALSE(world.isValid(last));
    EXPECT_THROW(world.setPosition(first, {9, 9}), Error);
    EXPECT_EQ(world.position(next), (Vec2{2, 0}));
    // Still retired after a step (which frees the slots destroyed during it).
    world.step(1.0f / 60.0f);
    EXPECT_NE(world.createBody(boxAt(3, 0)).index, first.index);
}

TEST(Handles, ATileMapSlotAtTheLastGenerationIsRetiredNotReused) {
    World world;
    const TileMapDef def{.tile = 4, .rows = {"#"}};
    const TileMapId first = createTileMap(world, def);
    destroyTileMap(world, first);
    WorldAccess::state(world).tileMaps.maps[first.index].generation = UINT32_MAX;
    const TileMapId last = createTileMap(world, def);
    ASSERT_EQ(last.index, first.index);
    destroyTileMap(world, last);
    const TileMapId next = createTileMap(world, def);
    EXPECT_NE(next.index, first.index);
    EXPECT_FALSE(world.isValid(first));
    EXPECT_FALSE(world.isValid(last));
    EXPECT_TRUE(world.isValid(next));
}

// --- Creation order -------------------------------------------------------------------------

// A generator of our own, so that the sequence does not depend on the standard library.
class Lcg {
public:
    std::uint32_t next() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<std::uint32_t>(state_ >> 33);
    }

private:
    std::uint64_t state_ = 2024;
};

/// The world's bodies() against `expected`, and the same order from every other way of
/// listing the bodies: readPositions, and a query over all of them.
void expectOrder(const World& world, const std::vector<BodyId>& expected,
                 const std::vector<Vec2>& positions) {
    const std::span<const BodyId> listed = world.bodies();
    ASSERT_EQ(std::vector<BodyId>(listed.begin(), listed.end()), expected);
    ASSERT_EQ(world.bodyCount(), expected.size());
    std::vector<Vec2> read(expected.size() + 1);
    ASSERT_EQ(world.readPositions(read), expected.size());
    read.pop_back();
    ASSERT_EQ(read, positions);
    ASSERT_EQ(queryRect(world, {-1e6f, -1e6f}, {1e6f, 1e6f}), expected);
}

TEST(CreationOrder, StaysCreationOrderThroughInterleavedCreatesAndDestroys) {
    World world(WorldDef{.gravity = {0, 0}});
    Lcg random;
    std::vector<BodyId> expected;
    std::vector<Vec2> positions;
    float next = 0;
    for (int round = 0; round < 3000; ++round) {
        const std::uint32_t what = random.next() % 8;
        if (what < 5 || expected.empty()) { // create, a few at a time
            for (std::uint32_t n = random.next() % 8; n-- > 0;) {
                const Vec2 at{3 * next++, 0};
                expected.push_back(world.createBody(boxAt(at.x, at.y)));
                positions.push_back(at);
            }
        } else if (what < 7) { // destroy anywhere: first, last, or in between
            const std::size_t victim = random.next() % expected.size();
            world.destroyBody(expected[victim]);
            expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(victim));
            positions.erase(positions.begin() + static_cast<std::ptrdiff_t>(victim));
        } else { // destroy a run, which leaves many gaps at once
            const std::size_t begin = random.next() % expected.size();
            const std::size_t end = std::min(expected.size(), begin + random.next() % 20);
            for (std::size_t i = begin; i < end; ++i)
                world.destroyBody(expected[i]);
            expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(begin),
                           expected.begin() + static_cast<std::ptrdiff_t>(end));
            positions.erase(positions.begin() + static_cast<std::ptrdiff_t>(begin),
                            positions.begin() + static_cast<std::ptrdiff_t>(end));
        }
        ASSERT_EQ(world.bodyCount(), expected.size());
        if (round % 7 == 0) {
            expectOrder(world, expected, positions);
            if (HasFatalFailure())
                return;
        }
        if (round % 50 == 0)
            world.step(1.0f / 60.0f); // no gravity, no velocity: nothing moves
    }
    EXPECT_GT(expected.size(), 1000u); // the list grew, with gaps anywhere in it
    expectOrder(world, expected, positions);
}

TEST(CreationOrder, DestroyingInCreationOrderAndInReverseKeepsTheRestInOrder) {
    for (const bool reverse : {false, true}) {
        World world;
        std::vector<BodyId> ids;
        std::vector<Vec2> positions;
        for (int i = 0; i < 1000; ++i) {
            ids.push_back(world.createBody(boxAt(3.0f * float(i), 0)));
            positions.push_back({3.0f * float(i), 0});
        }
        while (!ids.empty()) {
            world.destroyBody(reverse ? ids.back() : ids.front());
            if (reverse) {
                ids.pop_back();
                positions.pop_back();
            } else {
                ids.erase(ids.begin());
                positions.erase(positions.begin());
            }
            if (ids.size() % 97 == 0) {
                expectOrder(world, ids, positions);
                if (HasFatalFailure())
                    return;
            }
        }
        EXPECT_TRUE(world.bodies().empty());
        // The slots are reused, and the order starts over.
        const BodyId again = world.createBody(boxAt(0, 0));
        EXPECT_EQ(std::vector<BodyId>(world.bodies().begin(), world.bodies().end()),
                  std::vector<BodyId>{again});
    }
}

TEST(CreationOrder, BodiesDestroyedInACallbackLeaveTheOrderAtOnce) {
    World world(WorldDef{.gravity = {0, 100}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 1});
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i)
        boxes.push_back(world.createBody(boxAt(-50.0f + 5.0f * float(i), 8.5f)));
    std::vector<BodyId> expected = {world.bodies().begin(), world.bodies().end()};
    bool destroyed = false;
    std::vector<BodyId> seenInCallback;
    world.setPreSolve([&](Collision&) {
        if (!destroyed) {
            destroyed = true;
            for (std::size_t i = 0; i < boxes.size(); i += 2)
                world.destroyBody(boxes[i]);
            seenInCallback.assign(world.bodies().begin(), world.bodies().end());
        }
        return true;
    });
    world.step(1.0f / 60.0f);
    ASSERT_TRUE(destroyed);
    for (std::size_t i = 0; i < boxes.size(); i += 2)
        std::erase(expected, boxes[i]);
    EXPECT_EQ(seenInCallback, expected);
    EXPECT_EQ(std::vector<BodyId>(world.bodies().begin(), world.bodies().end()), expected);
    for (std::size_t i = 1; i < boxes.size(); i += 2)
        EXPECT_TRUE(world.isValid(boxes[i]));
    world.step(1.0f / 60.0f); // the freed slots are reusable after the step
    const BodyId late = world.createBody(boxAt(0, -20));
    expected.push_back(late);
    EXPECT_EQ(std::vector<BodyId>(world.bodies().begin(), world.bodies().end()), expected);
}

// The body tables grow by half, not double (room.hpp's slotRoomAfter): 10,003 bodies,
// just past a power of two, held room for 16,384 (128 bytes a Body), a third of it empty.
TEST(SlotTables, GrowByHalfSoThatAWorldHoldsAtMostAThirdMoreSlotsThanItsBodies) {
    World world;
    for (int i = 0; i < 10'003; ++i)
        world.createBody({.x = 2.0f * float(i), .hw = 0.5f, .hh = 0.5f});
    const WorldState& w = WorldAccess::state(world);
    const std::size_t most = w.slots.size() + w.slots.size() / 3 + 16;
    EXPECT_LE(w.slots.capacity(), most);
    EXPECT_LE(w.created.capacity(), most);
    EXPECT_LE(w.shapes.capacity(), most);
    EXPECT_LE(w.asGiven.capacity(), most);
    EXPECT_LE(w.events.touching.capacity(), most);
}

} // namespace
} // namespace jostle
