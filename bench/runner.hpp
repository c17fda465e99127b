// bench/runner.hpp: runs one scene in one engine and takes its figures.
#pragma once

#include "catalog.hpp"
#include "engine.hpp"
#include "shared/quality.hpp"

#include <optional>
#include <string>

namespace jostle::bench {

struct RunLimits {
    int warmup = 0; ///< steps before measuring, the same for every engine
    int steps = 0;  ///< steps measured, unless the time limit stops it earlier
    /// Measuring stops once the measured steps took this long (at least kMinSteps are
    /// measured): a slow engine at 100,000 bodies gets fewer measured steps, in the same
    /// run. Warm-up steps are never cut, so every engine is measured in the same state.
    double maxSeconds = 0.0;
    /// After measuring, time snapshots of the world this many times (0: not at all).
    int snapshotRuns = 0;
    static constexpr int kMinSteps = 10;
};

struct RunResult {
    std::string caseName;
    std::string family;
    int size = 0;
    EngineKind engine = EngineKind::Jostle;
    int workers = 1; ///< threads the engine stepped on
    int bodies = 0;
    int warmupSteps = 0;
    int measuredSteps = 0;
    double msPerStep = 0.0; ///< median of the measured steps
    double bytesPerBody = 0.0;
    /// The most heap the engine held after any step, warm-up included, in bytes: what a
    /// step's buffers take where the scene is at its busiest (a pile's first step).
    double peakBytes = 0.0;
    shared::Quality quality;
    /// The mean time of each stage over the measured steps, for an engine that profiles
    /// its steps (jostle).
    std::optional<StepProfile> stages;
    /// What a snapshot of the world after the measured steps costs (jostle's, if asked).
    std::optional<SnapshotFigures> snapshots;
};

/// The stages of jostle's step profile, by name (jostle::kStepProfileFields).
using StageField = StepProfileField;
inline constexpr const auto& kStages = kStepProfileFields;

/// Builds the case's scene in `engine` on `workers` threads, steps it `warmup` times, reads
/// the heap, measures up to `steps` steps, and reads the final positions for the quality
/// figures.
RunResult run(const Case& c, const Scene& scene, EngineKind engine, int workers,
              const RunLimits& limits);

/// The engine's name, and its workers beyond one: "jostle", "jostle x2".
std::string label(const RunResult& result);

} // namespace jostle::bench
