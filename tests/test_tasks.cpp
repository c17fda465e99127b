// The task interface (jostle/tasks.hpp): how a world checks its TaskSystem, hands work to
// a game's job system and to its own threads. That the results never change is
// test_determinism.cpp's (the Threads tests).
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace {

using namespace jostle;

TEST(TaskSystem, OneWorkerAndNoJobSystemByDefault) {
    const TaskSystem tasks = WorldDef{}.tasks;
    EXPECT_EQ(tasks.workers, 1);
    EXPECT_EQ(tasks.enqueueTask, nullptr);
    EXPECT_EQ(tasks.finishTask, nullptr);
    EXPECT_EQ(World(WorldDef{}).workers(), 1);
}

/// A job system that runs each task's ranges on the calling thread, in ranges of
/// `minRange`, and records what it was asked.
struct RecordingJobs {
    int tasks = 0;
    std::uint32_t largestWorker = 0;
    bool rangesTooShort = false;
    static void* enqueue(TaskFn task, std::uint32_t items, std::uint32_t minRange,
                         void* taskContext, void* user) {
        RecordingJobs& jobs = *static_cast<RecordingJobs*>(user);
        ++jobs.tasks;
        jobs.rangesTooShort |= minRange == 0;
        for (std::uint32_t begin = 0; begin < items; begin += minRange) {
            const std::uint32_t end = std::min(items, begin + minRange);
            const std::uint32_t worker = (begin / minRange) % 3;
            jobs.largestWorker = std::max(jobs.largestWorker, worker);
            task(begin, end, worker, taskContext);
        }
        return &jobs; // a handle: finishTask is called with it
    }
    static void finish(void* userTask, void* user) {
        EXPECT_EQ(userTask, user) << "finishTask gets what enqueueTask returned";
    }
};

World crowdOf(int boxes, const TaskSystem& tasks) {
    World world(WorldDef{.gravity = {0, 10}, .tasks = tasks});
    world.createBody({.type = BodyType::Static, .y = 1, .hw = 1000, .hh = 1});
    for (int i = 0; i < boxes; ++i)
        world.createBody(
            {.x = float(i % 500) * 2.0f, .y = -float(i / 500) * 2.0f, .hw = 0.5f, .hh = 0.5f});
    return world;
}

TEST(TaskSystem, AGamesJobSystemIsHandedTheStepsWork) {
    RecordingJobs jobs;
    World world = crowdOf(10000, {.workers = 3,
                                  .enqueueTask = &RecordingJobs::enqueue,
                                  .finishTask = &RecordingJobs::finish,
                                  .userContext = &jobs});
    world.step(1.0f / 60.0f);
    EXPECT_GT(jobs.tasks, 0);
    EXPECT_FALSE(jobs.rangesTooShort);
    EXPECT_LT(jobs.largestWorker, 3u);
}

TEST(TaskSystem, ASmallWorldStepsOnTheCallingThreadAlone) {
    RecordingJobs jobs;
    World world = crowdOf(10, {.workers = 4,
                               .enqueueTask = &RecordingJobs::enqueue,
                               .finishTask = &RecordingJobs::finish,
                               .userContext = &jobs});
    world.step(1.0f / 60.0f);
    EXPECT_EQ(jobs.tasks, 0) << "work smaller than a block is not worth a thread";
}

TEST(TaskSystem, OutOfRangeOrHalfAJobSystemIsRefusedByName) {
    for (int workers : {0, -1, 65}) {
        const auto problem = checkWorldDef(WorldDef{.tasks = {.workers = workers}});
        ASSERT_TRUE(problem.has_value()) << workers;
        EXPECT_EQ(problem->field, "tasks.workers");
        EXPECT_THROW(World(WorldDef{.tasks = {.workers = workers}}), Error);
    }
    EXPECT_FALSE(checkWorldDef(WorldDef{.tasks = {.workers = 64}}).has_value());
    const auto half =
        checkWorldDef(WorldDef{.tasks = {.workers = 2, .enqueueTask = &RecordingJobs::enqueue}});
    ASSERT_TRUE(half.has_value());
    EXPECT_EQ(half->field, "tasks");
}

TEST(TaskSystem, WorldsWithThreadsComeAndGo) {
    // Each world starts and stops its own threads; none may hang or leak.
    for (int round = 0; round < 50; ++round) {
        World world = crowdOf(3000, {.workers = 1 + round % 4});
        world.step(1.0f / 60.0f);
        EXPECT_GT(world.velocity(world.bodies().back()).y, 0.0f) << "the step ran";
    }
}

} // namespace
