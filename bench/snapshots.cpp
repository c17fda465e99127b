// jostle-bench-snapshots: what snapshots cost (docs/snapshots.md, issue 31's targets): the
// bytes of a world of boxes piled awake on a floor, and the time to save, restore and hash
// it, and a rollback frame (restore, then 8 times a snapshot and a step). Medians of --runs
// runs. Rapier's figures are its own tracker's, quoted: they are not measured here.
//   jostle-bench-snapshots [--runs N] [--bodies N,N...]
#include "jostle/world.hpp"
#include "timing.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace jostle;
using bench::medianMicroseconds;

/// `bodies` boxes in a pile on a floor, awake (sleeping off), settled for a second.
World pile(int bodies) {
    World world(WorldDef{.gravity = {0, 600}, .sleeping = false});
    const int columns = bodies <= 1000 ? 40 : 100;
    world.createBody({.type = BodyType::Static, .y = 10, .hw = 2000, .hh = 10});
    for (int i = 0; i < bodies; ++i)
        world.createBody({.x = -500.0f + 10.0f * float(i % columns),
                          .y = -5.0f - 10.0f * float(i / columns),
                          .hw = 5,
                          .hh = 5,
                          .friction = 0.6f});
    for (int step = 0; step < 60; ++step)
        world.step(1.0f / 60.0f);
    return world;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 50;
    std::vector<int> sizes{1000, 10000};
    CLI::App app{"jostle-bench-snapshots: the size and speed of snapshots",
                 "jostle-bench-snapshots"};
    app.add_option("--runs", runs, "Timed runs of each measure (the median is printed)")
        ->check(CLI::Range(1, 100000));
    app.add_option("--bodies", sizes, "Piles of these many bodies")->delimiter(',');
    CLI11_PARSE(app, argc, argv);

    std::printf("| bodies | contacts | bytes | bytes a body | save µs | restore µs | stateHash µs "
                "| step µs | rollback frame µs (restore + 8 × (snapshot + step)) |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int bodies : sizes) {
        World world = pile(bodies);
        std::size_t contacts = 0;
        for (BodyId id : world.bodies())
            contacts += world.contacts(id).size();
        std::vector<std::byte> saved(world.snapshotSize());
        world.snapshot(saved);
        std::vector<std::vector<std::byte>> frames(8, saved);
        const double save = medianMicroseconds(runs, [&] { world.snapshot(saved); });
        const double restore = medianMicroseconds(runs, [&] { world.restore(saved); });
        const double hash = medianMicroseconds(runs, [&] {
            volatile std::uint64_t h = world.stateHash();
            (void)h;
        });
        const double stepAndRestore = medianMicroseconds(runs, [&] {
            world.step(1.0f / 60.0f);
            world.restore(saved);
        });
        const double frame = medianMicroseconds(runs, [&] {
            world.restore(saved);
            for (std::vector<std::byte>& bytes : frames) {
                bytes.resize(world.snapshotSize());
                world.snapshot(bytes);
                world.step(1.0f / 60.0f);
            }
        });
        std::printf("| %d | %zu | %zu | %.0f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", bodies,
                    contacts / 2, saved.size(), double(saved.size()) / bodies, save, restore, hash,
                    stepAndRestore - restore, frame);
    }
    std::printf("\nRapier (its own tracker, not measured here): ~1,000-1,200 bytes a body; "
                "800 bodies 989 KB, 0.40 ms.\n");
    return 0;
}
