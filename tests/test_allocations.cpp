// What the library allocates, counted through operator new (its own program: every byte and
// every call the process makes is counted). A pile of boxes at one spot keeps a step's
// memory linear in bodies × maxContactsPerBody (issue 28: 10,000 boxes took 459 MB in their
// first step, the pair search keeping every overlapping pair before the budget applied). A
// snapshot into a buffer big enough, and a state hash, allocate nothing (issue 31).
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace {

std::atomic<std::size_t> allocated{0};
std::atomic<std::size_t> calls{0};
std::atomic<std::size_t> peak{0};

void* track(std::size_t size) {
    // A header before each block remembers its size for delete.
    void* block = std::malloc(size + sizeof(std::max_align_t));
    if (block == nullptr)
        throw std::bad_alloc();
    *static_cast<std::size_t*>(block) = size;
    calls.fetch_add(1);
    const std::size_t now = allocated.fetch_add(size) + size;
    std::size_t seen = peak.load();
    while (now > seen && !peak.compare_exchange_weak(seen, now)) {
    }
    return static_cast<char*>(block) + sizeof(std::max_align_t);
}

void untrack(void* pointer) {
    if (pointer == nullptr)
        return;
    void* block = static_cast<char*>(pointer) - sizeof(std::max_align_t);
    allocated.fetch_sub(*static_cast<std::size_t*>(block));
    std::free(block);
}

} // namespace

void* operator new(std::size_t size) {
    return track(size);
}
void* operator new[](std::size_t size) {
    return track(size);
}
void operator delete(void* pointer) noexcept {
    untrack(pointer);
}
void operator delete[](void* pointer) noexcept {
    untrack(pointer);
}
void operator delete(void* pointer, std::size_t) noexcept {
    untrack(pointer);
}
void operator delete[](void* pointer, std::size_t) noexcept {
    untrack(pointer);
}

namespace jostle {
namespace {

/// The most bytes one step of `boxes` boxes piled at one spot on a ground holds at once,
/// beyond what the world held before it.
std::size_t peakOfAPileStep(int boxes, int workers) {
    World world(WorldDef{.gravity = {0, 10}, .tasks = {.workers = workers}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    for (int i = 0; i < boxes; ++i)
        world.createBody({.x = 0, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    const std::size_t before = allocated.load();
    peak.store(before);
    world.step(1.0f / 60.0f);
    return peak.load() - before;
}

// What a step must hold, per body and per pair its budget allows: a pair (8 bytes), a
// contact of the solver (under 128), its cached copy and its event record (under 64
// each), the lists that order them (under 32): 256 bytes a budget place is generous. The
// step that kept every overlapping pair needed 45,000 bytes a body for 10,000 boxes.
TEST(PileMemory, AStepHoldsMemoryLinearInBodiesAndTheContactBudget) {
    constexpr int kBoxes = 10'000;
    const std::size_t budget = std::size_t(PhysicalOptions{}.maxContactsPerBody);
    const std::size_t bound = std::size_t(kBoxes) * budget * 256;
    for (int workers : {1, 2}) {
        const std::size_t used = peakOfAPileStep(kBoxes, workers);
        EXPECT_LT(used, bound) << workers << " workers: " << used / 1'000'000 << " MB";
    }
}

// A row of boxes set down on a floor at once begins every contact in one step; two quiet
// steps later the list of begun contacts no longer holds room for them all (it kept 720 KB,
// 143 bytes a body, in a pyramid of 100 rows that had landed).
TEST(PileMemory, TheEventListsGiveBackTheMemoryOfABurst) {
    constexpr int kBoxes = 2'000;
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    for (int i = 0; i < kBoxes; ++i)
        world.createBody({.x = 2.0f * float(i) - 2000.0f, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    world.step(1.0f / 60.0f);
    ASSERT_EQ(world.contactBegins().size(), std::size_t(kBoxes));
    world.step(1.0f / 60.0f);
    ASSERT_TRUE(world.contactBegins().empty());
    const std::size_t heldAfterTheBurst = allocated.load();
    world.step(1.0f / 60.0f);
    ASSERT_TRUE(world.contactBegins().empty());
    EXPECT_GE(heldAfterTheBurst, allocated.load() + kBoxes * sizeof(ContactEvent));
}

// A floor crowded by 2,000 boxes, then left with 500: the lists made of each step's contacts
// (the solver's, 88 bytes a contact, and the cache's, 32) give back the room of the 1,500
// gone, where they kept the largest size they ever had (and the world held as much as
// before: 1 KB more). At least the solver's share must come back.
TEST(PileMemory, TheContactListsGiveBackTheRoomOfAPileThatWentAway) {
    constexpr int kBoxes = 2'000, kKept = 500;
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    std::vector<BodyId> boxes;
    for (int i = 0; i < kBoxes; ++i)
        boxes.push_back(
            world.createBody({.x = 2.0f * float(i) - 2000.0f, .y = -0.5f, .hw = 0.5f, .hh = 0.5f}));
    for (int step = 0; step < 3; ++step)
        world.step(1.0f / 60.0f);
    const std::size_t heldByTheCrowd = allocated.load();
    for (int i = kKept; i < kBoxes; ++i)
        world.destroyBody(boxes[std::size_t(i)]);
    for (int step = 0; step < 4; ++step)
        world.step(1.0f / 60.0f);
    EXPECT_GE(heldByTheCrowd, allocated.load() + (kBoxes - kKept) * 88);
}

/// A job system that runs each task on the calling thread: a step shares its work, and
/// keeps what sharing needs, with no second thread.
void* runAtOnce(TaskFn task, std::uint32_t items, std::uint32_t, void* taskContext, void*) {
    task(0, items, 0, taskContext);
    return nullptr;
}
void finishAtOnce(void*, void*) {}

/// The bytes a world of columns of boxes on a floor holds after some steps, and how many
/// pairs touch in it.
std::pair<std::size_t, std::size_t> heldByColumns(const TaskSystem& tasks) {
    const std::size_t before = allocated.load();
    World world(WorldDef{.gravity = {0, 10}, .tasks = tasks});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    for (int column = 0; column < 100; ++column)
        for (int row = 0; row < 40; ++row)
            world.createBody(
                {.x = 4.0f * float(column), .y = -0.5f - float(row), .hw = 0.5f, .hh = 0.5f});
    std::size_t touching = 0;
    for (int step = 0; step < 10; ++step) {
        world.step(1.0f / 60.0f);
        touching = 0;
        for (BodyId body : world.bodies())
            touching += world.contacts(body).size();
    }
    return {allocated.load() - before, touching / 2};
}

// Listing the touching pairs on several workers kept each block's pairs in a list of its
// own (36 bytes a pair) before listing them all: 120 bytes a body more than one worker
// held in a pyramid of 100 rows. Now a pair's two flags (2 bytes) are all it keeps beside.
TEST(PileMemory, StepsSharedAmongWorkersKeepNoSecondListOfTheTouchingPairs) {
    const auto [alone, touching] = heldByColumns({});
    const auto [shared, touchingShared] =
        heldByColumns({.workers = 2, .enqueueTask = &runAtOnce, .finishTask = &finishAtOnce});
    ASSERT_EQ(touching, touchingShared);
    ASSERT_GE(touching, 4'000u);
    EXPECT_LT(shared, alone + 16 * touching) << alone << " bytes alone";
}

TEST(Snapshots, ASnapshotIntoABufferBigEnoughAndAStateHashAllocateNothing) {
    World world(WorldDef{.gravity = {0, 600}});
    createTileMap(world, {.tile = 10, .rows = {"#..../##", "########"}});
    for (int i = 0; i < 40; ++i)
        world.createBody({.x = 15.0f + 2.0f * float(i % 10),
                          .y = -10.0f - 10.0f * float(i / 10),
                          .hw = 4,
                          .hh = 4,
                          .radius = i % 3 == 0 ? 2.0f : 0.0f});
    for (int step = 0; step < 60; ++step)
        world.step(1.0f / 60.0f);
    std::vector<std::byte> buffer(world.snapshotSize() + 100);
    const std::size_t before = calls.load();
    const std::size_t written = world.snapshot(buffer);
    const std::uint64_t hash = world.stateHash();
    EXPECT_EQ(calls.load(), before) << "allocations during snapshot() and stateHash()";
    EXPECT_GT(written, 0u);
    EXPECT_NE(hash, 0u);
}

} // namespace
} // namespace jostle
