// The pairs of a world that touch now, kept from step to step out of the world's events:
// a pair goes in on World::contactBegins and out on World::contactEnds. The world reports
// only the changes of each step (docs/events.md), and debug drawing wants every touching
// pair, resting ones too, which the public API does not list.
#pragma once

#include "jostle/world.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>

namespace jostle::demo {

/// A pair that touches, as its begin event gave it.
struct TouchingPair {
    BodyId a;    ///< the body created first
    BodyId b;    ///< the other body
    Vec2 normal; ///< unit, along x or y, pointing from b towards a
};

class ContactSet {
public:
    /// Applies the events of the step `world` just took; call after every step, since
    /// each step's events replace the last.
    void update(const World& world);

    /// Calls visit(pair) for every touching pair of `world` whose bodies both exist, in
    /// the order of the bodies' handles. A body destroyed since the last step (while
    /// paused, say) gets its end event only from the next step; until then its pairs are
    /// skipped here, so that nothing is asked of a stale handle.
    template <class Visit> void forEach(const World& world, Visit&& visit) const {
        for (const auto& entry : pairs_)
            if (world.isValid(entry.second.a) && world.isValid(entry.second.b))
                visit(entry.second);
    }

    /// The pairs forEach visits.
    std::size_t count(const World& world) const;

private:
    /// A handle as one number: its slot and its generation, so that a reused slot is
    /// another key.
    static std::uint64_t keyOf(BodyId id) {
        return std::uint64_t{id.index} << 32 | std::uint64_t{id.generation};
    }
    using Key = std::pair<std::uint64_t, std::uint64_t>;
    static Key keyOf(const ContactEvent& event) { return {keyOf(event.a), keyOf(event.b)}; }

    std::map<Key, TouchingPair> pairs_;
};

} // namespace jostle::demo
