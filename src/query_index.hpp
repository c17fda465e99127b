// What queries keep of a world between calls (candidates.hpp brings it up to date).
#pragma once

#include "jostle/body.hpp"

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace jostle {

/// One lives in every WorldState. Candidates bring it up to date when a query finds that
/// bodies were created or destroyed, or that a static body stopped being one.
struct QueryIndex {
    /// Held while the index, or the world's resting grid, is brought up to date, and while
    /// a query lists the awake bodies: queries take a const World and may run on several
    /// threads at once.
    std::mutex mutex;
    bool built = false;
    /// WorldState::order when it was built, in short: its size and its last body. Bodies
    /// are only ever appended to the order or removed from it, and a new body's handle is
    /// new (its slot's generation is), so if the size and the last body are the same,
    /// so is the order.
    std::size_t bodyCount = 0;
    BodyId lastBody{};
    /// Slots of the dynamic and kinematic bodies when it was built, in creation order: the
    /// only bodies that may be outside the resting grid (when awake). A static body made
    /// dynamic since is missing; Candidates notice and rebuild.
    std::vector<std::uint32_t> mobile;
    /// The length of the pieces a long ray or cast is cut into, each looked up in the
    /// grid on its own: a few typical bodies long, so that a diagonal ray across a big
    /// level looks at the cells along it, not at all the cells of its bounding box.
    float pieceLength = 1.0f;
    /// Scratch of the rebuild: a sample of body sizes, to find the typical one.
    std::vector<float> sizes;
};

} // namespace jostle
