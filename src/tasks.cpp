// The task runner, and jostle's own threads for a world that asks for workers and gives
// no job system.
#include "tasks.hpp"

#include "jostle/error.hpp"

#include <atomic>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace jostle {

namespace {

/// Turns a waiting thread spins before it sleeps: a step hands out work many times, a
/// few microseconds apart, and waking a sleeping thread costs more than that.
constexpr int kSpinTurns = 4000;

void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/// Waits until `value` is no longer `old`: spinning a while, then sleeping.
template <class T> T waitWhileEqual(const std::atomic<T>& value, T old) {
    for (int turn = 0; turn < kSpinTurns; ++turn) {
        const T now = value.load(std::memory_order_acquire);
        if (now != old)
            return now;
        pause();
    }
    value.wait(old, std::memory_order_acquire);
    return value.load(std::memory_order_acquire);
}

} // namespace

/// Threads that take the items of one task at a time, one item each turn, beside the
/// calling thread (worker 0). Between tasks they spin a little, then sleep.
class ThreadPool {
public:
    /// Starts `threads` threads, or, if the system will not start them all, stops those
    /// it started and throws jostle::Error.
    explicit ThreadPool(std::uint32_t threads) {
        threads_.reserve(threads);
        try {
            for (std::uint32_t k = 0; k < threads; ++k)
                threads_.emplace_back([this, k] { serve(k + 1); });
        } catch (const std::system_error& error) {
            const std::size_t started = threads_.size();
            stop();
            throw Error("World: WorldDef.tasks.workers = " + std::to_string(threads + 1) +
                        ": the system would start only " + std::to_string(started) +
                        " threads beside the calling one (" + error.what() + ")");
        }
    }

    ~ThreadPool() { stop(); }

    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    /// Tells the threads to stop and joins them.
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
            generation_.fetch_add(1, std::memory_order_release);
        }
        generation_.notify_all();
        for (std::thread& thread : threads_)
            thread.join();
        threads_.clear();
    }

    /// Runs task over [0, items), one item a turn, and returns when all have run.
    void run(TaskFn task, std::uint32_t items, void* context) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            // A thread that came late to the last task may still be looking at it; it
            // needs no lock to leave.
            for (std::uint32_t inside = inside_.load(std::memory_order_acquire); inside != 0;
                 inside = inside_.load(std::memory_order_acquire))
                waitWhileEqual(inside_, inside);
            task_ = task;
            context_ = context;
            items_ = items;
            next_.store(0, std::memory_order_relaxed);
            finished_.store(0, std::memory_order_relaxed);
            generation_.fetch_add(1, std::memory_order_release);
        }
        generation_.notify_all();
        finish(take(task, items, context, 0));
        for (std::uint32_t done = finished_.load(std::memory_order_acquire); done != items;
             done = finished_.load(std::memory_order_acquire))
            waitWhileEqual(finished_, done);
    }

private:
    /// Runs items of a task until none is left; how many it ran.
    std::uint32_t take(TaskFn task, std::uint32_t items, void* context, std::uint32_t worker) {
        std::uint32_t ran = 0;
        for (std::uint32_t item = next_.fetch_add(1, std::memory_order_relaxed); item < items;
             item = next_.fetch_add(1, std::memory_order_relaxed)) {
            task(item, item + 1, worker, context);
            ++ran;
        }
        return ran;
    }

    void finish(std::uint32_t ran) {
        if (ran == 0)
            return;
        finished_.fetch_add(ran, std::memory_order_acq_rel);
        finished_.notify_all();
    }

    void serve(std::uint32_t worker) {
        std::uint64_t seen = 0;
        for (;;) {
            waitWhileEqual(generation_, seen);
            TaskFn task;
            void* context;
            std::uint32_t items;
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (stopping_)
                    return;
                seen = generation_.load(std::memory_order_relaxed);
                task = task_;
                context = context_;
                items = items_;
                inside_.fetch_add(1, std::memory_order_relaxed);
            }
            finish(take(task, items, context, worker));
            inside_.fetch_sub(1, std::memory_order_release);
            inside_.notify_all();
        }
    }

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    bool stopping_ = false;
    std::atomic<std::uint64_t> generation_{0}; ///< one more for each task, and to stop
    // The current task: set under the lock, with generation_, when no thread is inside
    // the last one; each thread copies it under the lock.
    TaskFn task_ = nullptr;
    void* context_ = nullptr;
    std::uint32_t items_ = 0;
    std::atomic<std::uint32_t> next_{0};     ///< the next item to take
    std::atomic<std::uint32_t> finished_{0}; ///< items run
    std::atomic<std::uint32_t> inside_{0};   ///< threads between copying the task and leaving it
};

TaskRunner::TaskRunner(const TaskSystem& system)
    : system_(system), workers_(std::uint32_t(system.workers < 1 ? 1 : system.workers)),
      sharing_(workers_ > 1) {
    if (workers_ > 1 && system_.enqueueTask == nullptr)
        pool_ = std::make_unique<ThreadPool>(workers_ - 1);
}

TaskRunner::~TaskRunner() = default;

void TaskRunner::dispatch(TaskFn task, std::uint32_t blocks, void* context) {
    if (pool_) {
        pool_->run(task, blocks, context);
        return;
    }
    dispatchGuarded(task, blocks, context);
}

namespace {

/// A task as handed to a game's job system, which is trusted with nothing: each range it
/// runs is checked against the contract (within the task, on a worker in range) and each
/// block is claimed before it runs, so a range run twice, out of bounds or never cannot
/// touch the step's memory wrongly. finishOnCallingThread runs what was left undone.
class GuardedTask {
public:
    GuardedTask(TaskFn task, std::uint32_t blocks, void* context, std::uint32_t workers,
                std::atomic<std::uint8_t>* claimed)
        : task_(task), blocks_(blocks), context_(context), workers_(workers), claimed_(claimed) {
        for (std::uint32_t b = 0; b < blocks; ++b)
            claimed_[b].store(0, std::memory_order_relaxed);
    }

    static void run(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* self) {
        static_cast<GuardedTask*>(self)->runRange(begin, end, worker);
    }

    /// After finishTask: runs the blocks no range ran, then waits for those still running.
    void finishOnCallingThread() {
        for (std::uint32_t b = 0; b < blocks_; ++b)
            if (claimed_[b].exchange(1, std::memory_order_acq_rel) == 0) {
                note("never ran item " + std::to_string(b));
                task_(b, b + 1, 0, context_);
                finished_.fetch_add(1, std::memory_order_release);
            }
        while (finished_.load(std::memory_order_acquire) != blocks_)
            std::this_thread::yield();
    }

    /// The first way the job system broke the contract, or "".
    std::string problem() {
        std::lock_guard<std::mutex> lock(mutex_);
        return problem_;
    }

private:
    void runRange(std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
        if (!(begin < end && end <= blocks_)) {
            note("ran the range [" + std::to_string(begin) + ", " + std::to_string(end) +
                 ") of a task of " + std::to_string(blocks_) + " items");
            return;
        }
        if (worker >= workers_)
            note("ran a range on worker " + std::to_string(worker) + " of " +
                 std::to_string(workers_));
        for (std::uint32_t b = begin; b < end; ++b) {
            if (claimed_[b].exchange(1, std::memory_order_acq_rel) != 0) {
                note("ran item " + std::to_string(b) + " twice");
                continue;
            }
            task_(b, b + 1, worker, context_);
            finished_.fetch_add(1, std::memory_order_release);
        }
    }

    void note(const std::string& what) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (problem_.empty())
            problem_ = what;
    }

    TaskFn task_;
    std::uint32_t blocks_;
    void* context_;
    std::uint32_t workers_;
    std::atomic<std::uint8_t>* claimed_;
    std::atomic<std::uint32_t> finished_{0};
    std::mutex mutex_;
    std::string problem_;
};

} // namespace

void TaskRunner::dispatchGuarded(TaskFn task, std::uint32_t blocks, void* context) {
    if (claimedCapacity_ < blocks) {
        claimed_ = std::make_unique<std::atomic<std::uint8_t>[]>(blocks);
        claimedCapacity_ = blocks;
    }
    GuardedTask guarded(task, blocks, context, workers_, claimed_.get());
    if (void* handle =
            system_.enqueueTask(&GuardedTask::run, blocks, 1, &guarded, system_.userContext))
        system_.finishTask(handle, system_.userContext);
    guarded.finishOnCallingThread();
    if (brokenContract_.empty())
        brokenContract_ = guarded.problem();
}

std::optional<std::string> TaskRunner::takeBrokenContract() {
    if (brokenContract_.empty())
        return std::nullopt;
    std::string problem = std::move(brokenContract_);
    brokenContract_.clear();
    return "the game's task system broke its contract (jostle/tasks.hpp): it " + problem +
           "; jostle did each item once, on the calling thread where it had to";
}

} // namespace jostle
