// Parallel work within a step: blocks of a fixed number of items handed to the world's
// task system (jostle/tasks.hpp), or run in a loop on the calling thread when it has one
// worker. Results never depend on the split: a block's items are always the same ones,
// and what a block writes is its own.
#pragma once

#include "jostle/tasks.hpp"
#include "sharing_choice.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace jostle {

class ThreadPool; // tasks.cpp: jostle's own threads

/// A block of a loop: its items [begin, end), the index-th block of the loop.
struct Block {
    std::uint32_t index, begin, end;
};

/// What each block of a loop gives, kept apart and read back in block order on the
/// calling thread: the same whatever ran where. Reused from step to step.
template <class T> class PerBlock {
public:
    /// Empties the lists of `blocks` blocks.
    void reset(std::uint32_t blocks) {
        if (lists_.size() < blocks)
            lists_.resize(blocks);
        for (std::uint32_t k = 0; k < blocks; ++k)
            lists_[k].items.clear();
        blocks_ = blocks;
    }
    std::vector<T>& operator[](std::uint32_t block) { return lists_[block].items; }
    /// Calls f(item) for every item, block after block.
    template <class F> void forEachInOrder(F&& f) const {
        for (std::uint32_t k = 0; k < blocks_; ++k)
            for (const T& item : lists_[k].items)
                f(item);
    }

private:
    /// A cache line each: two threads filling neighbouring lists never share one.
    struct alignas(64) List {
        std::vector<T> items;
    };
    std::vector<List> lists_;
    std::uint32_t blocks_ = 0;
};

/// Items per block of the loops over bodies: enough that a block costs far more than
/// handing it to a thread.
inline constexpr std::uint32_t kBodiesPerBlock = 2048;

class TaskRunner {
public:
    /// Starts workers - 1 threads if `system` gives no enqueueTask and asks for more than
    /// one worker. `system` must be valid (checkWorldDef).
    explicit TaskRunner(const TaskSystem& system);
    ~TaskRunner();
    TaskRunner(const TaskRunner&) = delete;
    TaskRunner& operator=(const TaskRunner&) = delete;

    std::uint32_t workers() const { return workers_; }

    /// Whether this step hands its blocks to the workers. With jostle's own threads, the
    /// way measured faster (SharingChoice); always with a game's job system, or blocks cut
    /// for testing; never with one worker.
    bool sharing() const { return sharing_; }
    /// Around each step: chooses whether it shares, then records how long it took.
    void beginStep() {
        sharing_ = workers_ > 1 && (!pool_ || testBlock_ != 0 || choice_.shareNext());
    }
    void endStep(float ms) {
        if (workers_ > 1)
            choice_.record(sharing_, ms);
    }

    /// Makes every loop use blocks of `items` (0: each loop's own size), so that the tests
    /// cut small worlds into many blocks: results must not change.
    void setBlockSizeForTesting(std::uint32_t items) { testBlock_ = items; }

    /// The items of a block forEachBlock makes when asked for blocks of `block` items.
    std::uint32_t blockSize(std::uint32_t block) const {
        return testBlock_ != 0 ? testBlock_ : block;
    }
    /// How many blocks forEachBlock cuts `count` items into, `block` a block.
    std::uint32_t blocksOf(std::uint32_t count, std::uint32_t block) const {
        return (count + blockSize(block) - 1) / blockSize(block);
    }

    /// Calls run(Block) for the items [0, count) in blocks of `block` items (the last
    /// may be shorter), on the workers, and returns when all have run.
    template <class Run> void forEachBlock(std::uint32_t count, std::uint32_t block, Run&& run);

    /// How the game's job system broke the contract of jostle/tasks.hpp since this was last
    /// asked (the first way it did), or nothing. The work was done all the same: each block
    /// once, what the job system left undone on the calling thread.
    std::optional<std::string> takeBrokenContract();

private:
    void dispatch(TaskFn task, std::uint32_t blocks, void* context);
    void dispatchGuarded(TaskFn task, std::uint32_t blocks, void* context);

    TaskSystem system_;
    std::uint32_t workers_;
    std::uint32_t testBlock_ = 0;
    bool sharing_;
    SharingChoice choice_;
    std::unique_ptr<ThreadPool> pool_;
    /// For a game's job system: which blocks of the task under way have been taken.
    std::unique_ptr<std::atomic<std::uint8_t>[]> claimed_;
    std::uint32_t claimedCapacity_ = 0;
    std::string brokenContract_;
};

template <class Run>
void TaskRunner::forEachBlock(std::uint32_t count, std::uint32_t block, Run&& run) {
    if (count == 0)
        return;
    if (testBlock_ != 0)
        block = testBlock_;
    const std::uint32_t blocks = (count + block - 1) / block;
    auto runBlock = [&](std::uint32_t b) {
        const std::uint32_t begin = b * block;
        run(Block{b, begin, count - begin < block ? count : begin + block});
    };
    if (!sharing_ || blocks == 1) {
        for (std::uint32_t b = 0; b < blocks; ++b)
            runBlock(b);
        return;
    }
    const TaskFn task = [](std::uint32_t first, std::uint32_t last, std::uint32_t, void* data) {
        auto& each = *static_cast<decltype(runBlock)*>(data);
        for (std::uint32_t b = first; b < last; ++b)
            each(b);
    };
    dispatch(task, blocks, &runBlock);
}

} // namespace jostle
