// Where a box moving through the world first stops: the core of boxCast, moveAndSlide and
// move (jostle/query.hpp states their rules).
#pragma once

#include "geometry.hpp"
#include "candidates.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace jostle {

/// A body a moving box runs into.
struct Met {
    std::uint32_t slot;
    std::uint64_t created; ///< when its body was created: results follow it
    Hit contact;
};

/// What stops a moving box first: the time, and every body met then, in creation order.
struct FirstStop {
    float time = 2.0f; ///< > 1: nothing in the way
    std::vector<Met> met;
    Vec2 centre; ///< where the box stops
};

/// Sweeps the box of `centre` and `half` along `motion` through the bodies that
/// accept(slot) lets stop it, by the rules of boxCast.
template <class Accept>
void firstStop(const WorldState& w, const Candidates& candidates, Vec2 centre, Vec2 half,
               Vec2 motion, Accept&& accept, FirstStop& stop) {
    stop.time = 2.0f;
    stop.met.clear();
    const float slop = w.def.physical.slop;
    auto consider = [&](std::uint32_t slot) {
        if (!accept(slot))
            return;
        const Body& body = w.slots[slot];
        const Vec2 skin{contactSkin(slop, half.x, body.half.x),
                        contactSkin(slop, half.y, body.half.y)};
        const std::optional<Hit> contact =
            castBox(centre - body.position, half + body.half, motion, skin);
        if (!contact || contact->time > stop.time)
            return;
        // castBox finds only what the box runs into from outside.
        if (!body.blocks(contact->normal, true, 0.0f))
            return;
        if (contact->time < stop.time) {
            stop.time = contact->time;
            stop.met.clear();
        }
        stop.met.push_back({slot, candidates.created(slot), *contact});
    };
    candidates.outsideGrid(consider);
    candidates.walkPath(centre, motion, half, consider, [&](float end) { return stop.time < end; });
    if (stop.met.empty())
        return;
    // A body near two pieces of the path was met twice.
    std::sort(stop.met.begin(), stop.met.end(),
              [](const Met& p, const Met& q) { return p.created < q.created; });
    stop.met.erase(std::unique(stop.met.begin(), stop.met.end(),
                               [](const Met& p, const Met& q) { return p.slot == q.slot; }),
                   stop.met.end());
    stop.centre = centre + motion * stop.time;
    // Exactly touching along the axis they came into contact on, whatever the rounding.
    for (const Met& m : stop.met) {
        const int axis = m.contact.axis;
        if (axis < 0)
            continue;
        const Body& body = w.slots[m.slot];
        stop.centre[axis] =
            body.position[axis] - std::copysign(half[axis] + body.half[axis], motion[axis]);
    }
}

} // namespace jostle
