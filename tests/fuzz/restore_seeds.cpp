// The seeds of fuzz_restore (tests/fuzz/README.md): snapshots of a small world with a tile
// map, of the determinism tests' busy worlds (classic and physical after 100 steps, the
// slopes world after 200) and of a pile asleep, written into a directory. A new snapshot
// format makes the old seeds bytes every restore refuses at the header: run this, then a
// campaign (scripts/fuzz.sh restore) to grow the corpus again.
//   jostle-restore-seeds DIRECTORY
#include "../busy_worlds.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace jostle;

void write(const std::string& path, const World& world) {
    const std::vector<std::byte> bytes = world.snapshot();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    std::printf("%s: %zu bytes\n", path.c_str(), bytes.size());
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: jostle-restore-seeds DIRECTORY\n");
        return 2;
    }
    const std::string dir = argv[1];

    World small(WorldDef{.gravity = {0, 10}});
    createTileMap(small, {.tile = 1, .rows = {"#./.#", "#####"}});
    small.createBody({.x = 1.5f, .y = -2, .hw = 0.4f, .hh = 0.4f});
    for (int step = 0; step < 30; ++step)
        small.step(1.0f / 60.0f);
    write(dir + "/seed-small", small);

    for (Solver solver : {Solver::Classic, Solver::Physical}) {
        testing::BusyWorld busy(solver);
        for (int step = 0; step < 100; ++step)
            busy.step();
        write(dir + (solver == Solver::Classic ? "/seed-busy-classic" : "/seed-busy-physical"),
              busy.world);
    }

    testing::SlopesWorld slopes;
    for (int step = 0; step < 200; ++step)
        slopes.step();
    write(dir + "/seed-slopes", slopes.world);

    World pile(WorldDef{.gravity = {0, 600}});
    pile.createBody({.type = BodyType::Static, .y = 10, .hw = 200, .hh = 10});
    for (int i = 0; i < 24; ++i)
        pile.createBody({.x = -60.0f + 10.0f * float(i % 8),
                         .y = -5.0f - 10.0f * float(i / 8),
                         .hw = 5,
                         .hh = 5,
                         .friction = 0.6f});
    for (int step = 0; step < 600; ++step)
        pile.step(1.0f / 60.0f);
    write(dir + "/seed-pile-asleep", pile);
    return 0;
}
