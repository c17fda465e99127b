// Parallel work within a step: blocks of a fixed number of items handed to the world's
// task system (jostle/tasks.hpp), or run in a loop on the calling thread when it has one
// worker. Results never depend on the split: a block's items are always the same ones,
// and what a block writes is its own.
#pragma once

#include "jostle/tasks.hpp"

#include <cstdint>
#include <memory>

namespace jostle {

class ThreadPool; // tasks.cpp: jostle's own threads

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

    /// Makes every loop use blocks of `items` (0: each loop's own size), so that the tests
    /// cut small worlds into many blocks: results must not change.
    void setBlockSizeForTesting(std::uint32_t items) { testBlock_ = items; }

    /// Calls run(begin, end, worker) for the items [0, count) in blocks of `block` items
    /// (the last may be shorter), on the workers, and returns when all have run.
    template <class Run> void forEachBlock(std::uint32_t count, std::uint32_t block, Run&& run);

private:
    void dispatch(TaskFn task, std::uint32_t blocks, void* context);

    TaskSystem system_;
    std::uint32_t workers_;
    std::uint32_t testBlock_ = 0;
    std::unique_ptr<ThreadPool> pool_;
};

template <class Run>
void TaskRunner::forEachBlock(std::uint32_t count, std::uint32_t block, Run&& run) {
    if (count == 0)
        return;
    if (testBlock_ != 0)
        block = testBlock_;
    if (workers_ == 1 || count <= block) {
        for (std::uint32_t begin = 0; begin < count; begin += block)
            run(begin, count - begin < block ? count : begin + block, 0u);
        return;
    }
    struct Context {
        Run* run;
        std::uint32_t count, block;
    } context{&run, count, block};
    const TaskFn task = [](std::uint32_t first, std::uint32_t last, std::uint32_t worker,
                           void* data) {
        const Context& c = *static_cast<Context*>(data);
        for (std::uint32_t b = first; b < last; ++b) {
            const std::uint32_t begin = b * c.block;
            (*c.run)(begin, c.count - begin < c.block ? c.count : begin + c.block, worker);
        }
    };
    dispatch(task, (count + block - 1) / block, &context);
}

} // namespace jostle
