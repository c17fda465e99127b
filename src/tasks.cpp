// The task runner, and jostle's own threads for a world that asks for workers and gives
// no job system.
#include "tasks.hpp"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace jostle {

/// Threads that take the items of one task at a time, one item each turn, beside the
/// calling thread (worker 0). They sleep between tasks.
class ThreadPool {
public:
    explicit ThreadPool(std::uint32_t threads) {
        threads_.reserve(threads);
        for (std::uint32_t k = 0; k < threads; ++k)
            threads_.emplace_back([this, k] { serve(k + 1); });
    }

    ~ThreadPool() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (std::thread& thread : threads_)
            thread.join();
    }

    /// Runs task over [0, items), one item a turn, and returns when all have run.
    void run(TaskFn task, std::uint32_t items, void* context) {
        {
            std::unique_lock<std::mutex> lock(mutex_);
            // A thread that saw the last task only now may still be looking at its items.
            done_.wait(lock, [&] { return inside_ == 0; });
            task_ = task;
            context_ = context;
            items_ = items;
            next_.store(0, std::memory_order_relaxed);
            finished_ = 0;
            ++generation_;
        }
        wake_.notify_all();
        const std::uint32_t mine = take(task, items, context, 0);
        std::unique_lock<std::mutex> lock(mutex_);
        finished_ += mine;
        done_.wait(lock, [&] { return finished_ == items_ && inside_ == 0; });
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

    void serve(std::uint32_t worker) {
        std::uint64_t seen = 0;
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_)
                return;
            seen = generation_;
            const TaskFn task = task_;
            void* const context = context_;
            const std::uint32_t items = items_;
            ++inside_;
            lock.unlock();
            const std::uint32_t ran = take(task, items, context, worker);
            lock.lock();
            finished_ += ran;
            --inside_;
            if (inside_ == 0)
                done_.notify_all();
        }
    }

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    bool stopping_ = false;
    std::uint64_t generation_ = 0;
    // The current task: set under the lock, with generation_, when no thread is inside
    // the last one; each thread copies it under the lock.
    TaskFn task_ = nullptr;
    void* context_ = nullptr;
    std::uint32_t items_ = 0;
    std::atomic<std::uint32_t> next_{0};
    std::uint32_t finished_ = 0; ///< items run, counted under the lock
    std::uint32_t inside_ = 0;   ///< threads between seeing the task and finishing their part
};

TaskRunner::TaskRunner(const TaskSystem& system)
    : system_(system), workers_(std::uint32_t(system.workers < 1 ? 1 : system.workers)) {
    if (workers_ > 1 && system_.enqueueTask == nullptr)
        pool_ = std::make_unique<ThreadPool>(workers_ - 1);
}

TaskRunner::~TaskRunner() = default;

void TaskRunner::dispatch(TaskFn task, std::uint32_t blocks, void* context) {
    if (pool_) {
        pool_->run(task, blocks, context);
        return;
    }
    if (void* handle = system_.enqueueTask(task, blocks, 1, context, system_.userContext))
        system_.finishTask(handle, system_.userContext);
}

} // namespace jostle
