// The human summary `jostle run` prints when it writes no trace.
#pragma once

#include "jostle/scene.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace jostle::cli {

struct RunReport {
    std::string scenePath;
    const Scene& scene;
    const World& world;
    std::span<const BodyId> bodies; ///< the scene's bodies, in scene order
    std::int64_t steps;
    std::chrono::steady_clock::duration wallTime;
};

void printSummary(std::FILE* out, const RunReport& report);

} // namespace jostle::cli
