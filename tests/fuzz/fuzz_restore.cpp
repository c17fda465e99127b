// libFuzzer: any bytes as a snapshot for World::restore (docs/snapshots.md).
//
// The header's length and checksum are made to match the bytes first, so that what the
// fuzzer changes reaches the payload's reader (a changed byte is otherwise refused by the
// checksum alone, which the tests cover). The contract: the bytes are refused with a
// jostle::Error naming what is wrong, and the world is left exactly as it was; or they are
// taken, and the world then steps keeping every invariant of invariants.hpp, and snapshots
// to bytes that restore to the same state. Anything else is a finding: the fuzzer aborts.
#include "invariants.hpp"

#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "snapshot/xxhash64.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace {

using namespace jostle;

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_restore finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

/// A world with a little of everything, which a restore replaces.
World target() {
    World world(WorldDef{.gravity = {0, 10}});
    createTileMap(world, {.tile = 1, .rows = {"#./.#", "#####"}});
    world.createBody({.x = 1.5f, .y = -2, .hw = 0.4f, .hh = 0.4f});
    return world;
}

void putLE(std::uint8_t* at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> bytes(data, data + size);
    if (bytes.size() >= 32) {
        putLE(bytes.data() + 16, bytes.size() - 32);
        putLE(bytes.data() + 24, snapshot::xxHash64(bytes.data() + 32, bytes.size() - 32));
    }
    const std::span<const std::byte> snapshot(reinterpret_cast<const std::byte*>(bytes.data()),
                                              bytes.size());
    World world = target();
    const std::uint64_t before = world.stateHash();
    try {
        world.restore(snapshot);
    } catch (const Error& error) {
        if (std::strncmp(error.what(), "restore: ", 9) != 0)
            finding(std::string("a refusal that does not name restore: ") + error.what());
        if (world.stateHash() != before)
            finding(std::string("refused, yet the world changed: ") + error.what());
        return 0;
    }
    // Taken: what it wrote back restores to the same state, and the world steps soundly.
    const std::vector<std::byte> again = world.snapshot();
    World copy;
    copy.restore(again);
    if (copy.stateHash() != world.stateHash() || copy.snapshot() != again)
        finding("a restored world's snapshot does not restore to the same state");
    for (int step = 0; step < 10; ++step) {
        try {
            world.step(1.0f / 60.0f);
        } catch (const Error& error) {
            finding(std::string("a restored world refused to step: ") + error.what());
        }
        if (auto problem = check::finiteState(world))
            finding("after a restore, step " + std::to_string(step) + ": " + *problem);
    }
    return 0;
}
