// jostle/tasks.hpp: stepping a world on several threads.
//
// A world steps on the calling thread alone unless its WorldDef asks for more workers.
// With `workers` > 1 and nothing else, jostle starts its own threads (workers - 1 of them,
// the calling thread being the first worker) and stops them with the world:
//
//     jostle::WorldDef def;
//     def.tasks.workers = 4;
//     jostle::World world(def);
//
// A game with a job system of its own hands it to jostle instead, as Box2D v3's
// enqueueTask / finishTask do: jostle calls enqueueTask with work to be split into ranges,
// and finishTask to wait for it.
//
// Whatever the workers and however the work is split, a step gives the same results bit
// for bit: jostle cuts its work into blocks of a fixed number of items, each block writes
// its own results, and they are put together in block order on the calling thread.
// Callbacks (the pre-solve) and events stay on the thread that calls step().
//
// On jostle's own threads, a step shares its work only where that is measured faster:
// a world times its steps both ways and keeps the faster, trying the other two steps in
// 64 (a pile that is one chain of contacts, or another program on the other core, can
// make sharing slower than one thread). A game's job system is always handed the work.
#pragma once

#include "jostle/visibility.h"
#include <cstdint>

namespace jostle {
JOSTLE_EXPORT_BEGIN

/// Work jostle hands to a task system: run it for every item of [begin, end), on worker
/// `worker` (in [0, workers), no two ranges running at once on the same one).
using TaskFn = void (*)(std::uint32_t begin, std::uint32_t end, std::uint32_t worker,
                        void* taskContext);

/// Hands `task` over [0, itemCount) to the game's job system: it must call
/// task(begin, end, worker, taskContext) over ranges that cover every item once, each
/// range at least `minRange` items but the last. It may run them at once (then return
/// nullptr) or queue them and return a handle that finishTask waits on.
using EnqueueTaskFn = void* (*)(TaskFn task, std::uint32_t itemCount, std::uint32_t minRange,
                                void* taskContext, void* userContext);

/// Waits until every range of the task enqueueTask returned `userTask` for has run.
using FinishTaskFn = void (*)(void* userTask, void* userContext);

// A job system that breaks this contract cannot corrupt the world: jostle checks every
// range it runs (within [0, itemCount), on a worker in [0, workers)) and takes each item
// once, so an item run twice, a range out of bounds or a range never run changes nothing
// it should not; what was left undone is run on the calling thread after finishTask. The
// step then ends as it would have, and World::step throws jostle::Error saying how the
// contract was broken ("step: the game's task system broke its contract (jostle/
// tasks.hpp): it ran item 3 twice; ..."). What jostle cannot catch: a range still
// running, or starting, after finishTask has returned.

/// How a world shares its step among threads (WorldDef::tasks).
struct TaskSystem {
    /// How many threads may work on a step at once, the calling thread included, in
    /// [1, 64]. 1 (the default): the calling thread alone, no threads started. If the
    /// system will not start jostle's own threads, the World constructor stops those it
    /// started and throws jostle::Error ("World: WorldDef.tasks.workers = 64: the system
    /// would start only 12 threads beside the calling one (...)").
    int workers = 1;
    /// The game's job system, both or neither. Neither, with workers > 1: jostle's own
    /// threads.
    EnqueueTaskFn enqueueTask = nullptr;
    FinishTaskFn finishTask = nullptr;
    void* userContext = nullptr; ///< passed to enqueueTask and finishTask as given
};

JOSTLE_EXPORT_END
} // namespace jostle
