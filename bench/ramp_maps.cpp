// Big maps of ramp tiles created, changed and destroyed, timed (ramp_maps.hpp).
#include "ramp_maps.hpp"

#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <algorithm>
#include <chrono>
#include <string>

namespace jostle::bench {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

TileMapDef rampMap(int size) {
    return TileMapDef{
        .tile = 16,
        .rows = std::vector<std::string>(static_cast<std::size_t>(size),
                                         std::string(static_cast<std::size_t>(size), '/'))};
}

/// Seconds per setTile in the middle of `map`, turning its middle tile to '\\' and back
/// to '/' until a tenth of a second has passed (at least two calls).
double secondsPerSetTile(World& world, TileMapId map, int size) {
    const int middle = size / 2;
    int calls = 0;
    const Clock::time_point start = Clock::now();
    do {
        setTile(world, map, middle, middle, calls % 2 == 0 ? '\\' : '/');
        ++calls;
    } while (calls < 2 || (calls % 2 != 0 || secondsSince(start) < 0.1));
    return secondsSince(start) / calls;
}

} // namespace

void runRampMaps(std::FILE* out, const std::vector<int>& sizes, int runs) {
    std::fprintf(out,
                 "jostle: maps of N x N '/' ramp tiles (one body each) in an empty world; median "
                 "of %d runs, wall clock\n",
                 runs);
    std::fprintf(out, "  %11s %10s %12s %18s %12s\n", "map", "bodies", "create", "setTile middle",
                 "destroy");
    for (const int size : sizes) {
        // Creating and changing first, each run in a new world (which is dropped, not
        // emptied), then destroying: the rows come as they are measured.
        std::vector<double> create, change, destroy;
        std::size_t bodies = 0;
        for (int run = 0; run < runs; ++run) {
            World world;
            const TileMapDef def = rampMap(size);
            const Clock::time_point start = Clock::now();
            const TileMapId map = createTileMap(world, def);
            create.push_back(secondsSince(start));
            bodies = world.bodyCount();
            change.push_back(secondsPerSetTile(world, map, size));
        }
        const std::string label = std::to_string(size) + " x " + std::to_string(size);
        std::fprintf(out, "  %11s %10zu %10.3f s %15.2f us", label.c_str(), bodies, median(create),
                     median(change) * 1e6);
        std::fflush(out);
        for (int run = 0; run < runs; ++run) {
            World world;
            const TileMapId map = createTileMap(world, rampMap(size));
            const Clock::time_point start = Clock::now();
            destroyTileMap(world, map);
            destroy.push_back(secondsSince(start));
        }
        std::fprintf(out, " %10.3f s\n", median(destroy));
        std::fflush(out);
    }
}

} // namespace jostle::bench
