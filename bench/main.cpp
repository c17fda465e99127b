// jostle-bench: the shared scenes in jostle, Box2D 2.4.1 and Chipmunk 7, side by side.
//
//     jostle-bench                      every scene at full size (a few minutes)
//     jostle-bench --quick              small sizes, a smoke run
//     jostle-bench --scene rain_100k    one case; --scene rain: all of a family
//     jostle-bench --series gas --csv series.csv   one family at several sizes
//     jostle-bench --markdown           the table for docs/benchmarks.md
//     jostle-bench --workers 1,2,4      jostle on 1, 2 and 4 threads (default 1,2)
//     jostle-bench --stages             and where jostle's steps spent their time
//     jostle-bench --snapshots          and what a snapshot of each jostle world costs
//     jostle-bench --lifecycle 1000000  creating and destroying a million bodies, timed
//     jostle-bench --ramp-maps 300,1000 maps of 300 x 300 and 1000 x 1000 ramp tiles
//                                       created, changed in the middle, destroyed, timed
//
// Progress goes to standard error, the table to standard output. Exit status: 0 when
// all ran; 2 for bad options; 1 when something failed (the CSV file cannot be written).
#include "catalog.hpp"
#include "engine.hpp"
#include "lifecycle.hpp"
#include "ramp_maps.hpp"
#include "report.hpp"
#include "runner.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace jostle::bench;

constexpr int kBadInput = 2;
constexpr int kFailure = 1;

struct Options {
    std::vector<std::string> scenes;
    std::vector<std::string> series;
    std::vector<std::string> engines;
    bool quick = false;
    std::optional<int> steps;
    std::optional<int> warmup;
    double maxSeconds = 20.0;
    std::string csv;
    bool markdown = false;
    bool stages = false;
    bool snapshots = false;
    bool list = false;
    int lifecycle = 0;
    std::vector<int> rampMaps;
    std::vector<int> workers{1, 2};
};

const std::vector<EngineKind>& allEngines() {
    static const std::vector<EngineKind> kinds = [] {
        std::vector<EngineKind> all{EngineKind::Jostle, EngineKind::Box2D, EngineKind::Chipmunk,
                                    EngineKind::JostleSleeping};
        if (box2d3Built())
            all.insert(all.begin() + 1, EngineKind::Box2D3);
        return all;
    }();
    return kinds;
}

EngineKind engineFromName(const std::string& text) {
    for (const EngineKind kind : allEngines())
        if (name(kind) == text)
            return kind;
    if (text == name(EngineKind::Box2D3))
        throw std::invalid_argument("--engine: box2d3 is not in this build (configure with "
                                    "-DJOSTLE_BENCH_BOX2D3=<an installed Box2D v3>)");
    throw std::invalid_argument("--engine: unknown engine \"" + text +
                                "\" (jostle, jostle+sleep, box2d, chipmunk, box2d3)");
}

std::vector<Case> chooseCases(const Options& options) {
    std::vector<Case> cases;
    for (const std::string& family : options.series)
        for (Case& c : seriesCases(family, options.quick))
            cases.push_back(std::move(c));
    for (const std::string& scene : options.scenes)
        for (Case& c : selectCases(scene, options.quick))
            cases.push_back(std::move(c));
    if (options.series.empty() && options.scenes.empty())
        cases = defaultCases(options.quick);
    for (Case& c : cases) {
        if (options.steps)
            c.steps = *options.steps;
        if (options.warmup)
            c.warmup = *options.warmup;
    }
    return cases;
}

std::vector<EngineKind> chooseEngines(const Options& options) {
    if (options.engines.empty()) {
        // A series is for the plot of time against size: sleeping off only.
        if (!options.series.empty()) {
            std::vector<EngineKind> kinds = allEngines();
            std::erase(kinds, EngineKind::JostleSleeping);
            return kinds;
        }
        return allEngines();
    }
    std::vector<EngineKind> kinds;
    for (const std::string& text : options.engines)
        kinds.push_back(engineFromName(text));
    return kinds;
}

void printIntroduction(std::FILE* out, double maxSeconds) {
    std::fprintf(out,
                 "ms/step: median of the measured steps, after the warm-up "
                 "steps (steps = warm-up + measured;\n"
                 "measuring stops early after %.0f s). jostle/peer: jostle's ms/step over the "
                 "peer's (jostle on as many threads), below 1 means jostle is faster.\n"
                 "xN: on N threads; speed-up: the engine's time on one thread over this "
                 "one. Box2D 2.4.1 and Chipmunk step on one thread.\n"
                 "Sleeping is off in all three engines; jostle+sleep is jostle with sleeping "
                 "on. Each engine as below: jostle with its\n"
                 "defaults, Box2D with its recommended iterations, Chipmunk with as many.\n"
                 "bytes/body: heap growth from before building the world to after the "
                 "warm-up, over all bodies, static ones included.\n"
                 "top drift: how far a pyramid's top box moved; max overlap: deepest overlap "
                 "of two bodies at the end; escaped: dynamic\n"
                 "bodies outside the scene's starting bounds at the end.\n",
                 maxSeconds);
    std::fprintf(out, "  %s\n", describeJostle().c_str());
    std::fprintf(out, "  %.*s\n", static_cast<int>(describeBox2D().size()), describeBox2D().data());
    std::fprintf(out, "  %.*s\n", static_cast<int>(describeChipmunk().size()),
                 describeChipmunk().data());
    if (box2d3Built())
        std::fprintf(out, "  %.*s\n", static_cast<int>(describeBox2D3().size()),
                     describeBox2D3().data());
    std::fprintf(out, "\n");
}

/// Timed runs of each snapshot measure (--snapshots): the median is printed.
constexpr int kSnapshotRuns = 21;

int runAll(const Options& options) {
    const std::vector<Case> cases = chooseCases(options);
    const std::vector<EngineKind> engines = chooseEngines(options);
    if (options.list) {
        for (const Case& c : cases)
            std::printf("%s  (warm-up %d, measured %d)\n", c.name.c_str(), c.warmup, c.steps);
        return 0;
    }

    std::vector<RunResult> results;
    for (const Case& c : cases) {
        const jostle::Scene scene = c.make();
        for (const EngineKind engine : engines) {
            for (const int workers : takesWorkers(engine) ? options.workers : std::vector{1}) {
                RunResult named{.engine = engine, .workers = workers};
                std::fprintf(stderr, "%-18s %-16s ", c.name.c_str(), label(named).c_str());
                std::fflush(stderr);
                const RunLimits limits{c.warmup, c.steps, options.maxSeconds,
                                       options.snapshots ? kSnapshotRuns : 0};
                results.push_back(run(c, scene, engine, workers, limits));
                std::fprintf(stderr, "%10.3f ms/step over %d steps\n", results.back().msPerStep,
                             results.back().measuredSteps);
            }
        }
    }

    if (options.markdown) {
        printTable(stdout, results, true);
    } else {
        std::fputc('\n', stdout);
        printIntroduction(stdout, options.maxSeconds);
        printTable(stdout, results, false);
    }
    // A further table: a blank line, its title (not in markdown), the table.
    auto section = [&](const std::string& title, auto print) {
        std::fputc('\n', stdout);
        if (!options.markdown)
            std::fputs(title.c_str(), stdout);
        print(stdout, results, options.markdown);
    };
    if (options.stages)
        section("Mean milliseconds per step in each stage of jostle's step "
                "(World::profile):\n\n",
                printStages);
    if (options.snapshots)
        section("Snapshots of each world after its measured steps (docs/snapshots.md), "
                "medians of " +
                    std::to_string(kSnapshotRuns) + " runs:\n\n",
                printSnapshots);
    if (!options.csv.empty() && !writeCsv(options.csv, results)) {
        std::fprintf(stderr, "jostle-bench: error: %s: cannot write\n", options.csv.c_str());
        return kFailure;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"jostle-bench: the shared scenes in jostle, Box2D 2.4.1 and Chipmunk 7, "
                 "timed in the same run (docs/benchmarks.md)"};
    Options options;
    app.add_option("--scene", options.scenes,
                   "Scenes to run (repeatable or a comma list): a family (pyramid, "
                   "many_pyramids, rain, gas, tilemap), a case (rain_100k) or a family at any "
                   "size (rain_30k). Default: every case")
        ->delimiter(',');
    app.add_option("--series", options.series,
                   "Run a family at several sizes, for the plot (scripts/plot-bench.sh)")
        ->delimiter(',');
    app.add_option("--engine", options.engines,
                   "Engines (repeatable or a comma list): jostle, jostle+sleep, box2d, chipmunk. "
                   "Default: all")
        ->delimiter(',');
    app.add_option("--workers", options.workers,
                   "Worker counts jostle steps on, each a row (repeatable or a comma list; the "
                   "peers step on one). Default: 1,2")
        ->delimiter(',')
        ->check(CLI::Range(1, 64));
    app.add_flag("--quick", options.quick, "Small sizes and few steps: a smoke run");
    app.add_option("--steps", options.steps, "Steps measured, for every scene")
        ->check(CLI::Range(1, 1'000'000));
    app.add_option("--warmup", options.warmup, "Steps before measuring, for every scene")
        ->check(CLI::Range(0, 1'000'000));
    app.add_option("--max-seconds", options.maxSeconds,
                   "Stop measuring an engine after this much measured time (default 20)")
        ->check(CLI::PositiveNumber);
    app.add_option("--csv", options.csv, "Also write the results to this CSV file");
    app.add_flag("--markdown", options.markdown,
                 "Print only the table, as markdown (for docs/benchmarks.md)");
    app.add_flag("--snapshots", options.snapshots,
                 "Also time a snapshot of each jostle world after its measured steps: its "
                 "bytes, save, restore and state hash (docs/snapshots.md)");
    app.add_flag("--stages", options.stages,
                 "Also print where jostle's steps spent their time, stage by stage "
                 "(World::profile)");
    app.add_flag("--list", options.list, "List the cases that would run, and stop");
    app.add_option("--lifecycle", options.lifecycle,
                   "Instead of the scenes: create this many bodies in jostle and destroy them "
                   "all, in creation order then in reverse order, and print the times")
        ->check(CLI::Range(1, 100'000'000));
    app.add_option("--ramp-maps", options.rampMaps,
                   "Instead of the scenes: for each size N (a comma list), create a map of "
                   "N x N ramp tiles in jostle, set its middle tile, destroy it, and print the "
                   "median times of three runs")
        ->delimiter(',')
        ->check(CLI::Range(1, 10'000));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int status = app.exit(error);
        return status == 0 ? 0 : kBadInput;
    }

    try {
        if (options.lifecycle > 0) {
            runLifecycle(stdout, options.lifecycle);
            return 0;
        }
        if (!options.rampMaps.empty()) {
            runRampMaps(stdout, options.rampMaps, 3);
            return 0;
        }
        return runAll(options);
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "jostle-bench: error: %s\n", error.what());
        return kBadInput;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "jostle-bench: error: %s\n", error.what());
        return kFailure;
    }
}
