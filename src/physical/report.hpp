// Stage: report events (docs/events.md). Contacts that touch where the step leaves them,
// sensor overlaps, and bodies crushed by kinematic ones, handed to the world's events.
#pragma once

#include "../events.hpp"
#include "../tasks.hpp"
#include "jostle/math.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

/// A dynamic body that a kinematic body pushes deep into: crushed if something holds it
/// on the other side.
struct CrushCandidate {
    std::uint32_t body, by;
    Vec2 into;             ///< from the kinematic body into the dynamic one
    std::uint32_t contact; ///< the contact's index in the step's list
};

/// What listing the touching contacts keeps on the side (report.cpp).
struct ReportScratch {
    /// Shared among the workers: whether each contact touches at the end of the step, with
    /// its bodies' touching flags, at its place in the contact cache (report.cpp's
    /// listTouches).
    std::vector<std::uint16_t> touches;
    /// What each block of contacts found, then all of them in contact order.
    PerBlock<CrushCandidate> crushCandidates;
    std::vector<CrushCandidate> candidatesInOrder;
};

void reportEvents(StepContext& step);

} // namespace jostle
