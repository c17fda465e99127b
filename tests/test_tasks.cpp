// The task interface (jostle/tasks.hpp): how a world checks its TaskSystem, hands work to
// a game's job system and to its own threads. That the results never change is
// test_determinism.cpp's (the Threads tests).
#include "jostle/world.hpp"
#include "sharing_choice.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
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

std::vector<Vec2> positionsOf(const World& world) {
    std::vector<Vec2> out(world.bodyCount());
    world.readPositions(out);
    return out;
}

// --- Whether jostle's own threads pay (issue 32) ---------------------------------------------

/// The ways SharingChoice picks for `steps` steps that take `shared` and `alone` ms, and
/// `cold` ms more when the step before went the other way (its data in the other way's
/// caches).
std::vector<bool> waysChosen(SharingChoice& choice, int steps, float shared, float alone,
                             float cold = 0.0f) {
    std::vector<bool> ways;
    for (int k = 0; k < steps; ++k) {
        const bool share = choice.shareNext();
        const bool switched = !ways.empty() && ways.back() != share;
        ways.push_back(share);
        choice.record(share, (share ? shared : alone) + (switched ? cold : 0.0f));
    }
    return ways;
}

/// How many of `ways`, from `from` on, did not go the way `faster`.
int otherWay(const std::vector<bool>& ways, bool faster, std::size_t from = 0) {
    return int(std::count(ways.begin() + std::ptrdiff_t(from), ways.end(), !faster));
}

/// The most steps of `steps` that retries send the other way: two in each kRetryEvery.
int retriesIn(std::size_t steps) {
    return int(SharingChoice::kRetrySteps *
               ((steps + SharingChoice::kRetryEvery - 1) / SharingChoice::kRetryEvery));
}

TEST(SharingChoice, TheFirstStepsTakeTurnsTwoByTwoSharedFirst) {
    SharingChoice choice;
    const std::vector<bool> ways = waysChosen(choice, SharingChoice::kFirstTurns, 1, 1);
    const std::vector<bool> expected{true, true, false, false, true, true, false, false};
    EXPECT_EQ(ways, expected);
}

/// Steps that take `shared` and `alone` ms go the way `faster`, but for the retries.
void expectKeptButRetried(float shared, float alone, bool faster) {
    SharingChoice choice;
    const std::vector<bool> ways =
        waysChosen(choice, 20 * SharingChoice::kRetryEvery, shared, alone);
    const std::size_t after = SharingChoice::kFirstTurns;
    EXPECT_GE(otherWay(ways, faster, after), retriesIn(ways.size() - after) - 2);
    EXPECT_LE(otherWay(ways, faster, after), retriesIn(ways.size() - after));
}

TEST(SharingChoice, SharesWhenSharingIsFasterButForTheRetries) {
    expectKeptButRetried(1.0f, 1.6f, true);
}

TEST(SharingChoice, StepsAloneWhenThatIsFasterButForTheRetries) {
    expectKeptButRetried(1.2f, 1.0f, false);
}

// The other core gets busy (another program): sharing, which waits for it at every stage,
// becomes slower than stepping alone, and the choice follows within a few retries; and
// back when the core is free again.
TEST(SharingChoice, FollowsTheFasterWayWhenTheTimesChange) {
    SharingChoice choice;
    waysChosen(choice, 100, 1.0f, 1.6f);
    const std::size_t steps = 8 * SharingChoice::kRetryEvery, half = steps / 2;
    const std::vector<bool> busy = waysChosen(choice, int(steps), 2.5f, 1.6f);
    EXPECT_LE(otherWay(busy, false, half), retriesIn(half));
    const std::vector<bool> free = waysChosen(choice, int(steps), 1.0f, 1.6f);
    EXPECT_LE(otherWay(free, true, half), retriesIn(half));
}

// A world's first step grows its buffers and is slow whichever way it goes: it is not
// held against sharing.
TEST(SharingChoice, TheFirstStepIsNotCounted) {
    SharingChoice choice;
    choice.record(choice.shareNext(), 500.0f);
    const std::vector<bool> ways = waysChosen(choice, 4 * SharingChoice::kRetryEvery, 1.0f, 1.6f);
    const std::size_t after = SharingChoice::kFirstTurns;
    EXPECT_LE(otherWay(ways, true, after), retriesIn(ways.size() - after));
}

// A step after one of the other way finds its data in the other way's caches and is slow
// (many_pyramids_200 on two workers: 7.6 ms alone after shared steps, 6.0-6.5 in a world
// on one worker, 6.2-6.7 shared): counted, it made every retry of the faster way look
// slower. Alone is faster here, warm, and is kept.
TEST(SharingChoice, AStepAfterTheOtherWayIsNotCounted) {
    SharingChoice choice;
    const std::vector<bool> ways =
        waysChosen(choice, 20 * SharingChoice::kRetryEvery, 1.0f, 0.95f, 0.6f);
    const std::size_t after = SharingChoice::kFirstTurns;
    EXPECT_LE(otherWay(ways, false, after), retriesIn(ways.size() - after));
}

// A world on its own two threads, its steps taking turns (the first ones do) and then
// going the way measured faster, moves its bodies exactly as a world on one.
TEST(SharingChoice, EitherWayEachStepGivesTheSameBits) {
    World one = crowdOf(6000, {.workers = 1});
    World two = crowdOf(6000, {.workers = 2});
    for (int step = 0; step < 2 * int(SharingChoice::kFirstTurns); ++step) {
        one.step(1.0f / 60.0f);
        two.step(1.0f / 60.0f);
    }
    const std::vector<Vec2> a = positionsOf(one), b = positionsOf(two);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)), 0);
}

// --- Job systems that break the contract (issue 28) ----------------------------------------

/// A job system that breaks the contract of jostle/tasks.hpp in one way, on the calling
/// thread or on two threads at once.
struct BrokenJobs {
    enum class Breach { None, RunsEachRangeTwice, OnePastTheEnd, SkipsARange, RunsHalf };
    Breach breach = Breach::None;
    bool twoThreads = false;
    static void* enqueue(TaskFn task, std::uint32_t items, std::uint32_t, void* taskContext,
                         void* user) {
        const BrokenJobs& jobs = *static_cast<BrokenJobs*>(user);
        auto ranges = [&](std::uint32_t first, std::uint32_t step, std::uint32_t worker) {
            for (std::uint32_t begin = first; begin < items; begin += step) {
                switch (jobs.breach) {
                case Breach::None:
                    task(begin, begin + 1, worker, taskContext);
                    break;
                case Breach::RunsEachRangeTwice:
                    task(begin, begin + 1, worker, taskContext);
                    task(begin, begin + 1, worker, taskContext);
                    break;
                case Breach::OnePastTheEnd:
                    task(begin, std::min(items, begin + 1) + (begin + 1 == items), worker,
                         taskContext);
                    break;
                case Breach::SkipsARange:
                    if (begin != items / 2)
                        task(begin, begin + 1, worker, taskContext);
                    break;
                case Breach::RunsHalf:
                    if (begin < items / 2)
                        task(begin, begin + 1, worker, taskContext);
                    break;
                }
            }
        };
        if (jobs.twoThreads) {
            std::thread other([&] { ranges(1, 2, 1); });
            ranges(0, 2, 0);
            other.join();
        } else {
            ranges(0, 1, 0);
        }
        return nullptr; // all ran before returning
    }
    static void finish(void*, void*) {}
};

// A job system that runs a range twice, runs one out of bounds, or never runs some: the
// step is done all the same, each block once (the same bits as a good job system gives),
// and step() then throws jostle::Error saying how the contract was broken. Before, these
// wrote out of bounds (UBSan in box_grid.cpp, ASan in broadphase.cpp) or left bodies
// silently unmoved.
TEST(TaskSystem, AJobSystemThatBreaksTheContractCannotCorruptTheStep) {
    using Breach = BrokenJobs::Breach;
    const std::pair<Breach, const char*> breaches[] = {
        {Breach::RunsEachRangeTwice, "twice"},
        {Breach::OnePastTheEnd, "ran the range"},
        {Breach::SkipsARange, "never ran item"},
        {Breach::RunsHalf, "never ran item"},
    };
    BrokenJobs good;
    World reference = crowdOf(6000, {.workers = 4,
                                     .enqueueTask = &BrokenJobs::enqueue,
                                     .finishTask = &BrokenJobs::finish,
                                     .userContext = &good});
    for (int i = 0; i < 3; ++i)
        reference.step(1.0f / 60.0f);
    for (bool twoThreads : {false, true})
        for (const auto& [breach, says] : breaches) {
            BrokenJobs jobs{breach, twoThreads};
            World world = crowdOf(6000, {.workers = 4,
                                         .enqueueTask = &BrokenJobs::enqueue,
                                         .finishTask = &BrokenJobs::finish,
                                         .userContext = &jobs});
            for (int i = 0; i < 3; ++i) {
                try {
                    world.step(1.0f / 60.0f);
                    ADD_FAILURE() << "step " << i << " did not throw, breach " << int(breach);
                } catch (const Error& e) {
                    const std::string message = e.what();
                    EXPECT_NE(message.find("step: the game's task system broke its contract"),
                              std::string::npos)
                        << message;
                    EXPECT_NE(message.find(says), std::string::npos) << message;
                }
            }
            EXPECT_EQ(positionsOf(world), positionsOf(reference))
                << "breach " << int(breach) << (twoThreads ? " on two threads" : "");
        }
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define JOSTLE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define JOSTLE_SANITIZED 1
#endif
#endif

// When the system will not start a world's threads, the world is refused with
// jostle::Error, the threads it did start stopped; the process used to terminate (the
// pool's constructor threw with threads still running). The threads are kept from
// starting by a limit on the process's address space, which a sanitizer's shadow memory
// would not fit in: skipped in those builds.
TEST(TaskSystem, ThreadsThatCannotStartAreAnErrorNotATermination) {
#ifdef JOSTLE_SANITIZED
    GTEST_SKIP() << "an address-space limit and a sanitizer's shadow memory do not mix";
#else
    rlimit was{};
    ASSERT_EQ(getrlimit(RLIMIT_AS, &was), 0);
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    statm >> pages;
    ASSERT_GT(pages, 0u);
    // Room for the process as it is and 48 MB more: a thread's stack alone takes 8 MB.
    const rlimit tight{pages * std::size_t(sysconf(_SC_PAGESIZE)) + (48u << 20), was.rlim_max};
    ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
    std::string message;
    try {
        World world(WorldDef{.tasks = {.workers = 64}});
    } catch (const Error& e) {
        message = e.what();
    }
    setrlimit(RLIMIT_AS, &was);
    EXPECT_NE(message.find("World: WorldDef.tasks.workers = 64: the system would start only"),
              std::string::npos)
        << message;
    // And the process goes on: a world with threads steps as before.
    World world = crowdOf(3000, {.workers = 2});
    world.step(1.0f / 60.0f);
    EXPECT_GT(world.velocity(world.bodies().back()).y, 0.0f);
#endif
}

} // namespace
