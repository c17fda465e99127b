// Timing, memory and quality of one engine on one scene.
#include "runner.hpp"

#include "memory.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace jostle::bench {

std::string label(const RunResult& result) {
    std::string text(name(result.engine));
    if (result.workers > 1)
        text += " x" + std::to_string(result.workers);
    return text;
}

RunResult run(const Case& c, const Scene& scene, EngineKind engine, int workers,
              const RunLimits& limits) {
    RunResult result;
    result.caseName = c.name;
    result.family = c.family;
    result.size = c.size;
    result.engine = engine;
    result.workers = workers;
    result.bodies = static_cast<int>(scene.bodies.size());
    result.warmupSteps = limits.warmup;

    // Everything the bench itself needs afterwards is allocated before the first heap
    // reading, so the difference is the engine's alone.
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(std::max(limits.steps, 0)));
    std::vector<Vec2> positions(scene.bodies.size());

    const std::size_t heapBefore = heapInUse();
    std::size_t peak = heapBefore;
    const auto notePeak = [&] { peak = std::max(peak, heapInUse()); };
    std::unique_ptr<Engine> world = makeEngine(engine, scene, workers);
    for (int i = 0; i < limits.warmup; ++i) {
        world->step(scene.dt);
        notePeak();
    }
    // After the warm-up, so the contact and pair storage of a busy world is counted.
    const std::size_t heapAfter = heapInUse();
    result.bytesPerBody = scene.bodies.empty()
                              ? 0.0
                              : (static_cast<double>(heapAfter) - static_cast<double>(heapBefore)) /
                                    static_cast<double>(scene.bodies.size());

    using Clock = std::chrono::steady_clock;
    double measured = 0.0;
    for (int i = 0; i < limits.steps; ++i) {
        const Clock::time_point start = Clock::now();
        world->step(scene.dt);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        notePeak();
        times.push_back(seconds);
        measured += seconds;
        if (const StepProfile* profile = world->profile()) {
            StepProfile& sum = result.stages ? *result.stages : result.stages.emplace();
            for (const StageField& stage : kStages)
                sum.*stage.ms += profile->*stage.ms;
        }
        if (measured > limits.maxSeconds && i + 1 >= RunLimits::kMinSteps)
            break;
    }
    result.measuredSteps = static_cast<int>(times.size());
    result.peakBytes = static_cast<double>(peak - heapBefore);
    if (result.stages && !times.empty())
        for (const StageField& stage : kStages)
            result.stages.value().*stage.ms /= static_cast<float>(times.size());
    if (!times.empty()) {
        const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
        std::nth_element(times.begin(), middle, times.end());
        result.msPerStep = *middle * 1000.0;
    }

    world->positions(positions);
    result.quality = shared::measureQuality(scene, positions);
    if (limits.snapshotRuns > 0)
        result.snapshots = world->measureSnapshots(limits.snapshotRuns);
    return result;
}

} // namespace jostle::bench
