// Solver layers: the step's contacts grouped so that the solver's passes can run on
// several threads and give the bits of one thread. Contacts that share no dynamic body
// commute exactly (each writes only its own bodies' velocities and itself), so each
// contact goes one layer after the last layer an earlier contact of either of its dynamic
// bodies is in, and a layer's contacts may run in any order, on any thread.
#pragma once

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

/// Contacts per block of a layer.
inline constexpr std::uint32_t kContactsPerBlock = 256;
/// The blocks a layer must hold on average for the passes to run in layers (measured).
inline constexpr std::uint32_t kBlocksPerLayer = 8;

/// After layers too narrow to share, the steps until they are looked for again.
inline constexpr std::uint32_t kStepsBetweenNarrowLooks = 8;

struct SolverLayers {
    bool active = false;                ///< false: the passes run in contact order
    std::vector<std::uint32_t> order;   ///< contact indices, layer by layer
    std::vector<std::uint32_t> starts;  ///< layer k is order[starts[k], starts[k + 1])
    std::vector<std::uint32_t> next;    ///< scratch: by solver body, its next free layer
    std::vector<std::uint32_t> layerOf; ///< scratch: by contact
    /// Steps left before layers found too narrow are looked for again (layerContacts).
    std::uint32_t stepsToNextLook = 0;
};

/// Groups step.contacts into layers, when the world has several workers and the layers are
/// wide enough to share; else leaves the passes in contact order.
void layerContacts(StepContext& step);

// forEachContact, which runs a pass over the layers, is in step_context.hpp.

} // namespace jostle
