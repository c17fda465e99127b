// Creating and destroying many bodies, timed.
#include "lifecycle.hpp"

#include "jostle/world.hpp"

#include <chrono>
#include <vector>

namespace jostle::bench {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Creates `count` unit boxes on a grid, none touching another, and returns their
/// handles in creation order; prints how long it took.
std::vector<BodyId> createAll(std::FILE* out, World& world, int count) {
    std::vector<BodyId> ids;
    ids.reserve(static_cast<std::size_t>(count));
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < count; ++i)
        ids.push_back(world.createBody({.x = static_cast<float>(3 * (i % 1000)),
                                        .y = static_cast<float>(3 * (i / 1000)),
                                        .hw = 1.0f,
                                        .hh = 1.0f}));
    std::fprintf(out, "  create %-26s %10.3f s\n", "", secondsSince(start));
    return ids;
}

template <class It>
void destroyAll(std::FILE* out, World& world, It first, It last, const char* order) {
    const Clock::time_point start = Clock::now();
    for (It it = first; it != last; ++it)
        world.destroyBody(*it);
    std::fprintf(out, "  destroy all in %-18s %10.3f s (%zu left)\n", order, secondsSince(start),
                 world.bodyCount());
}

} // namespace

void runLifecycle(std::FILE* out, int count) {
    std::fprintf(out, "jostle: %d bodies created, then all destroyed; wall clock\n", count);
    World world;
    std::vector<BodyId> ids = createAll(out, world, count);
    destroyAll(out, world, ids.begin(), ids.end(), "creation order");
    ids = createAll(out, world, count);
    destroyAll(out, world, ids.rbegin(), ids.rend(), "reverse order");
}

} // namespace jostle::bench
