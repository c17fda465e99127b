// Where a box moving through the world first stops: the core of boxCast, moveAndSlide and
// move (jostle/query.hpp states their rules). Between boxes, geometry.hpp's castBox; where
// the mover is rounded or the body is not a sharp box, shape_casts.hpp's castShape.
#pragma once

#include "candidates.hpp"
#include "geometry.hpp"
#include "one_way.hpp"
#include "shape_casts.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace jostle {

/// A body a moving box runs into.
struct Met {
    std::uint32_t slot;
    std::uint64_t created; ///< when its body was created: results follow it
    /// Its axis kAlongSlope for a normal along neither axis (a slope, a rounded corner). Of
    /// a body that is not a sharp box, or met by a rounded box, also where the two touch:
    /// dot(centre - body's centre, touching) == extent; between sharp boxes those are left
    /// {0, 0} and 0.
    ShapeHit contact;
};

/// What stops a moving box first: the time, and every body met then, in creation order.
struct FirstStop {
    float time = 2.0f; ///< > 1: nothing in the way
    std::vector<Met> met;
    Vec2 centre; ///< where the box stops
};

/// Where a box of half extents `half` rounded by `radius` (0: a sharp box) moving from
/// `centre` by `motion` runs into the body in `slot`, which is not a sharp box or is met by
/// a rounded one (shape_casts.hpp's castShape): the hit and its extent.
inline std::optional<Met> castAgainstShape(const WorldState& w, std::uint32_t slot, Vec2 centre,
                                           Vec2 half, float radius, Vec2 motion) {
    const Body& body = w.slots[slot];
    // A one-way box stops only with its blocking face.
    const std::uint8_t stopping = blockingFaces(body);
    const CastOutline cast = castOutlineOf(half, radius, body.half, w.shapes[slot], stopping,
                                           std::max(2.0f * w.def.physical.slop, kMinimumSkin));
    const std::optional<ShapeHit> hit = castShape(cast, centre - body.position, motion);
    if (!hit)
        return std::nullopt;
    return Met{slot, 0, *hit};
}

/// Where a box of half extents `half` rounded by `radius` (0: sharp) moving from `centre`
/// by `motion` runs into the body in `slot`, by the rules of boxCast: castBox between sharp
/// boxes, castAgainstShape otherwise. `created` is left 0.
inline std::optional<Met> castAgainst(const WorldState& w, std::uint32_t slot, Vec2 centre,
                                      Vec2 half, float radius, Vec2 motion) {
    const Body& body = w.slots[slot];
    if (radius != 0.0f || !body.isBox())
        return castAgainstShape(w, slot, centre, half, radius, motion);
    const float slop = w.def.physical.slop;
    const Vec2 skin{contactSkin(slop, half.x, body.half.x), contactSkin(slop, half.y, body.half.y)};
    const std::optional<Hit> hit = castBox(centre - body.position, half + body.half, motion, skin);
    if (!hit)
        return std::nullopt;
    return Met{slot, 0, ShapeHit{*hit, {}, 0.0f}};
}

/// Where a box of `half` rounded by `radius`, at `centre` where its cast along `motion`
/// met `m`, exactly touches it, whatever the rounding: along the axis they came into contact
/// on, or, along a normal on neither axis, moved along it to touching.
inline Vec2 touchingAt(const WorldState& w, Vec2 centre, Vec2 half, float radius, Vec2 motion,
                       const Met& m) {
    const Axis axis = m.contact.axis;
    if (axis == kFromInside)
        return centre;
    const Body& body = w.slots[m.slot];
    const Vec2 n = m.contact.touching;
    if (axis == kAlongSlope)
        centre += n * (m.contact.extent - dot(centre - body.position, n));
    else if (radius == 0.0f && body.isBox())
        centre[axis] =
            body.position[axis] - std::copysign(half[axis] + body.half[axis], motion[axis]);
    else
        centre[axis] = body.position[axis] + n[axis] * m.contact.extent;
    return centre;
}

/// The bodies `stop` met, in creation order, each once (a body near two pieces of the path
/// was met twice), and where the box stops against them. Not a template, so that every
/// query that casts shares one sort.
inline void settleStop(const WorldState& w, Vec2 centre, Vec2 half, float radius, Vec2 motion,
                       FirstStop& stop) {
    std::sort(stop.met.begin(), stop.met.end(),
              [](const Met& p, const Met& q) { return p.created < q.created; });
    stop.met.erase(std::unique(stop.met.begin(), stop.met.end(),
                               [](const Met& p, const Met& q) { return p.slot == q.slot; }),
                   stop.met.end());
    stop.centre = centre + motion * stop.time;
    for (const Met& m : stop.met)
        stop.centre = touchingAt(w, stop.centre, half, radius, motion, m);
}

/// Sweeps the box of `centre` and `half`, rounded by `radius` (0: sharp), along `motion`
/// through the bodies that accept(slot) lets stop it, by the rules of boxCast.
template <class Accept>
void firstStop(const WorldState& w, const Candidates& candidates, Vec2 centre, Vec2 half,
               float radius, Vec2 motion, Accept&& accept, FirstStop& stop) {
    stop.time = 2.0f;
    stop.met.clear();
    auto consider = [&](std::uint32_t slot) {
        if (!accept(slot))
            return;
        std::optional<Met> met = castAgainst(w, slot, centre, half, radius, motion);
        if (!met || met->contact.time > stop.time)
            return;
        // castBox finds only what the box runs into from outside.
        if (!stops(w.slots[slot], met->contact.normal, true, 0.0f))
            return;
        if (met->contact.time < stop.time) {
            stop.time = met->contact.time;
            stop.met.clear();
        }
        met->created = candidates.created(slot);
        stop.met.push_back(*met);
    };
    candidates.outsideGrid(consider);
    candidates.walkPath(centre, motion, half, consider, [&](float end) { return stop.time < end; });
    if (!stop.met.empty())
        settleStop(w, centre, half, radius, motion, stop);
}

/// What is left of `motion` when it may not go into any of `normals`, those of the bodies
/// a box stopped against where it is (unit, from each body towards the box). Along
/// axis-aligned faces alone, the axis of each is dropped (bump.lua's slide). With a slope
/// or a rounded corner among them, the nearest motion that goes into none: the motion
/// itself, or its slide along one of them, or none at all (into a crease).
inline Vec2 slideAlong(Vec2 motion, const std::vector<Vec2>& normals) {
    const bool alongAxes = std::all_of(normals.begin(), normals.end(),
                                       [](Vec2 n) { return n.x == 0.0f || n.y == 0.0f; });
    if (alongAxes) {
        for (Vec2 n : normals)
            (n.x != 0.0f ? motion.x : motion.y) = 0.0f;
        return motion;
    }
    // Rounding leaves a slide a hair into the face it slides along.
    const float tolerance = 1e-5f * length(motion);
    auto goesIntoNone = [&](Vec2 m) {
        return std::all_of(normals.begin(), normals.end(),
                           [&](Vec2 n) { return dot(m, n) >= -tolerance; });
    };
    if (goesIntoNone(motion))
        return motion;
    Vec2 best{};
    float bestLost = std::numeric_limits<float>::infinity();
    for (Vec2 n : normals) {
        const float into = dot(motion, n);
        if (!(into < 0.0f) || -into >= bestLost)
            continue;
        const Vec2 slid = motion - n * into;
        if (goesIntoNone(slid)) {
            best = slid;
            bestLost = -into;
        }
    }
    return best;
}

} // namespace jostle
