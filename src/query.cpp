// Queries: what is at a point, in a box, on a ray, in the way of a moving box. The
// geometry is in geometry.hpp, the candidates come from candidates.hpp; this file
// applies the filters and the rules of each query (jostle/query.hpp).
#include "jostle/query.hpp"

#include "candidates.hpp"
#include "first_stop.hpp"
#include "geometry.hpp"
#include "one_way.hpp"
#include "shape_casts.hpp"
#include "world_access.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace jostle {

namespace {

/// moveAndSlide gives up after this many stops (bump.lua's items stop at most twice among
/// boxes; slopes and rounded corners may take more, into a crease).
constexpr int kMaxSlides = 32;

bool passes(const WorldState& w, std::uint32_t slot, const QueryFilter& filter) {
    const Body& body = w.slots[slot];
    return (body.category & filter.mask) != 0 && (filter.category & body.mask) != 0 &&
           (filter.includeSensors || !body.sensor) && w.idOf(slot) != filter.ignore;
}

// --- Argument checks ---------------------------------------------------------------------

void checkFilter(const WorldState& w, const QueryFilter& filter, const char* function) {
    if (filter.ignore.isNull())
        return;
    if (std::optional<std::string> problem =
            handleProblem(w.slots, w.serial, filter.ignore, "BodyId", "body"))
        fail(function, "QueryFilter.ignore: " + *problem);
}

void checkBox(const char* function, Vec2 centre, Vec2 half, bool sizeZeroAllowed) {
    requireFinite(function, "centre", centre);
    requireFinite(function, "half", half);
    if (sizeZeroAllowed ? (half.x < 0.0f || half.y < 0.0f) : (half.x <= 0.0f || half.y <= 0.0f))
        fail(function, sizeZeroAllowed ? "half must be >= 0" : "half must be > 0");
    if (!isFinite(centre - half) || !isFinite(centre + half))
        fail(function, "the box's corners must be finite numbers (centre ± half overflows)");
}

void checkTranslation(const char* function, Vec2 centre, Vec2 translation) {
    requireFinite(function, "translation", translation);
    if (!isFinite(centre + translation))
        fail(function, "centre + translation must be finite numbers");
}

/// The arguments of a moving box: a box, a translation it can make, a filter.
void checkCast(const WorldState& w, const char* function, Vec2 centre, Vec2 half, float radius,
               Vec2 translation, const QueryFilter& filter) {
    checkBox(function, centre, half, false);
    requireFinite(function, "radius", radius);
    if (!(radius >= 0.0f) || radius > std::min(half.x, half.y))
        fail(function, "radius must be in [0, min(half.x, half.y)]");
    checkTranslation(function, centre, translation);
    checkFilter(w, filter, function);
}

// --- What is here? -----------------------------------------------------------------------

/// Sorts `bodies` in creation order. Not in collect, a template: one sort for every query.
void inCreationOrder(const Candidates& candidates, std::vector<BodyId>& bodies) {
    std::sort(bodies.begin(), bodies.end(), [&](BodyId p, BodyId q) {
        return candidates.created(p.index) < candidates.created(q.index);
    });
}

/// Fills `out` with the bodies that pass the filter and for which inside(slot) holds,
/// among those touching `region`, in creation order.
template <class Inside>
void collect(const WorldState& w, const Box& region, const QueryFilter& filter, Inside&& inside,
             std::vector<BodyId>& out) {
    out.clear();
    const Candidates candidates(w);
    auto consider = [&](std::uint32_t slot) {
        if (inside(slot) && passes(w, slot, filter))
            out.push_back(w.idOf(slot));
    };
    candidates.inGrid(region, consider);
    candidates.outsideGrid(consider);
    inCreationOrder(candidates, out);
}

void overlapping(const WorldState& w, Box box, const QueryFilter& filter,
                 std::vector<BodyId>& out) {
    // Sharing area: touching edge to edge is not overlapping. A shape shares area with
    // the box within its own box.
    const Vec2 centre = (box.min + box.max) * 0.5f, half = (box.max - box.min) * 0.5f;
    collect(
        w, box, filter,
        [&](std::uint32_t slot) {
            const Body& body = w.slots[slot];
            return overlaps(body.box(), box) &&
                   (body.isBox() ||
                    shapeOverlaps(body.half, w.shapes[slot], centre - body.position, half));
        },
        out);
}

// --- Rays --------------------------------------------------------------------------------

struct RayFound {
    std::uint32_t slot;
    std::uint64_t created; ///< when its body was created: results follow it
    Hit contact;
};

bool before(const RayFound& p, const RayFound& q) {
    return p.contact.time < q.contact.time ||
           (p.contact.time == q.contact.time && p.created < q.created);
}

/// The ray against the body in `slot`, by the rules of rayCast: the body passes the filter,
/// and a one-way platform is met only through its blocking face, from outside.
std::optional<RayFound> rayMeets(const WorldState& w, const Candidates& candidates,
                                 std::uint32_t slot, Vec2 from, Vec2 delta,
                                 const QueryFilter& filter) {
    if (!passes(w, slot, filter))
        return std::nullopt;
    const Body& body = w.slots[slot];
    std::optional<Hit> contact;
    if (body.isBox()) {
        contact = castRay(from, delta, body.box());
    } else if (const std::optional<ShapeHit> hit =
                   rayShape(from - body.position, delta, body.half, w.shapes[slot])) {
        contact = Hit{hit->time, hit->normal, hit->axis};
    }
    if (!contact || !stops(body, contact->normal, contact->axis != kFromInside, 0.0f))
        return std::nullopt;
    return RayFound{slot, candidates.created(slot), *contact};
}

RayHit toRayHit(const WorldState& w, const RayFound& found, Vec2 from, Vec2 delta) {
    const Hit& contact = found.contact;
    Vec2 point = from + delta * contact.time;
    if ((contact.axis == kAlongX || contact.axis == kAlongY) && contact.time > 0.0f) {
        // Exactly on the face, whatever the rounding of the fraction (a flat face of a
        // shape lies on its box's face too).
        const Box box = w.slots[found.slot].box();
        if (contact.axis == kAlongX)
            point.x = contact.normal.x < 0.0f ? box.min.x : box.max.x;
        else
            point.y = contact.normal.y < 0.0f ? box.min.y : box.max.y;
    }
    return {w.idOf(found.slot), point, contact.normal, contact.time};
}

void checkRay(const WorldState& w, const char* function, Vec2 from, Vec2 to,
              const QueryFilter& filter) {
    requireFinite(function, "from", from);
    requireFinite(function, "to", to);
    if (!isFinite(to - from))
        fail(function, "to - from must be finite numbers (the ray is too long for a float)");
    checkFilter(w, filter, function);
}

} // namespace

// --- The API -----------------------------------------------------------------------------

void queryPoint(const World& world, Vec2 point, const QueryFilter& filter,
                std::vector<BodyId>& out) {
    const WorldState& w = WorldAccess::state(world);
    requireFinite("queryPoint", "point", point);
    checkFilter(w, filter, "queryPoint");
    // On the edge is on the box; a shape holds it within its own box.
    const Box at{point, point};
    collect(
        w, at, filter,
        [&](std::uint32_t slot) {
            const Body& body = w.slots[slot];
            return touches(body.box(), at) &&
                   (body.isBox() || shapeHolds(body.half, w.shapes[slot], point - body.position));
        },
        out);
}

std::vector<BodyId> queryPoint(const World& world, Vec2 point, const QueryFilter& filter) {
    std::vector<BodyId> out;
    queryPoint(world, point, filter, out);
    return out;
}

void queryBox(const World& world, Vec2 centre, Vec2 half, const QueryFilter& filter,
              std::vector<BodyId>& out) {
    const WorldState& w = WorldAccess::state(world);
    checkBox("queryBox", centre, half, true);
    checkFilter(w, filter, "queryBox");
    overlapping(w, {centre - half, centre + half}, filter, out);
}

std::vector<BodyId> queryBox(const World& world, Vec2 centre, Vec2 half,
                             const QueryFilter& filter) {
    std::vector<BodyId> out;
    queryBox(world, centre, half, filter, out);
    return out;
}

void queryRect(const World& world, Vec2 min, Vec2 max, const QueryFilter& filter,
               std::vector<BodyId>& out) {
    const WorldState& w = WorldAccess::state(world);
    requireFinite("queryRect", "min", min);
    requireFinite("queryRect", "max", max);
    if (min.x > max.x || min.y > max.y)
        fail("queryRect", "min must be <= max on both axes");
    checkFilter(w, filter, "queryRect");
    overlapping(w, {min, max}, filter, out);
}

std::vector<BodyId> queryRect(const World& world, Vec2 min, Vec2 max, const QueryFilter& filter) {
    std::vector<BodyId> out;
    queryRect(world, min, max, filter, out);
    return out;
}

std::optional<RayHit> rayCast(const World& world, Vec2 from, Vec2 to, const QueryFilter& filter) {
    const WorldState& w = WorldAccess::state(world);
    checkRay(w, "rayCast", from, to, filter);
    const Vec2 delta = to - from;
    const Candidates candidates(w);
    std::optional<RayFound> best;
    auto consider = [&](std::uint32_t slot) {
        const std::optional<RayFound> found = rayMeets(w, candidates, slot, from, delta, filter);
        if (found && (!best || before(*found, *best)))
            best = found;
    };
    candidates.outsideGrid(consider);
    // Once a hit lies before the end of a piece, no later piece holds an earlier one (a
    // hit at the same fraction may still be there: it might be of an older body).
    candidates.walkPath(from, delta, Vec2{}, consider,
                        [&](float end) { return best && best->contact.time < end; });
    if (!best)
        return std::nullopt;
    return toRayHit(w, *best, from, delta);
}

void rayCastAll(const World& world, Vec2 from, Vec2 to, const QueryFilter& filter,
                std::vector<RayHit>& out) {
    const WorldState& w = WorldAccess::state(world);
    checkRay(w, "rayCastAll", from, to, filter);
    out.clear();
    const Vec2 delta = to - from;
    const Candidates candidates(w);
    std::vector<RayFound> found;
    auto consider = [&](std::uint32_t slot) {
        if (std::optional<RayFound> met = rayMeets(w, candidates, slot, from, delta, filter))
            found.push_back(*met);
    };
    candidates.outsideGrid(consider);
    candidates.walkPath(from, delta, Vec2{}, consider, [](float) { return false; });
    // A body near two pieces of the ray was found twice, with the same fraction: the
    // copies end up side by side.
    std::sort(found.begin(), found.end(), before);
    found.erase(std::unique(found.begin(), found.end(),
                            [](const RayFound& p, const RayFound& q) { return p.slot == q.slot; }),
                found.end());
    out.reserve(found.size());
    for (const RayFound& f : found)
        out.push_back(toRayHit(w, f, from, delta));
}

std::vector<RayHit> rayCastAll(const World& world, Vec2 from, Vec2 to, const QueryFilter& filter) {
    std::vector<RayHit> out;
    rayCastAll(world, from, to, filter, out);
    return out;
}

std::optional<BoxCastHit> boxCast(const World& world, Vec2 centre, Vec2 half, Vec2 translation,
                                  const QueryFilter& filter) {
    return boxCast(world, centre, half, 0.0f, translation, filter);
}

std::optional<BoxCastHit> boxCast(const World& world, Vec2 centre, Vec2 half, float radius,
                                  Vec2 translation, const QueryFilter& filter) {
    const WorldState& w = WorldAccess::state(world);
    checkCast(w, "boxCast", centre, half, radius, translation, filter);
    const Candidates candidates(w);
    FirstStop stop;
    firstStop(
        w, candidates, centre, half, radius, translation,
        [&](std::uint32_t slot) { return passes(w, slot, filter); }, stop);
    if (stop.met.empty())
        return std::nullopt;
    const Met& first = stop.met.front();
    return BoxCastHit{w.idOf(first.slot), stop.centre, first.contact.normal, stop.time};
}

std::optional<BoxCastHit> circleCast(const World& world, Vec2 centre, float radius,
                                     Vec2 translation, const QueryFilter& filter) {
    return boxCast(world, centre, {radius, radius}, radius, translation, filter);
}

MoveResult moveAndSlide(const World& world, Vec2 centre, Vec2 half, Vec2 translation,
                        const QueryFilter& filter) {
    return moveAndSlide(world, centre, half, 0.0f, translation, filter);
}

MoveResult moveAndSlide(const World& world, Vec2 centre, Vec2 half, float radius, Vec2 translation,
                        const QueryFilter& filter) {
    const WorldState& w = WorldAccess::state(world);
    checkCast(w, "moveAndSlide", centre, half, radius, translation, filter);
    const Candidates candidates(w);
    // Sensors never stop the box, whatever the filter says.
    auto stopsMovingBox = [&](std::uint32_t slot) {
        return passes(w, slot, filter) && !w.slots[slot].sensor;
    };
    MoveResult result{centre, {}};
    Vec2 left = translation;
    FirstStop stop;
    // The normals of the bodies the box stopped against where it is now.
    std::vector<Vec2> against;
    // Every stop drops the part of what is left that goes into the bodies met. Among
    // boxes a normal is along an axis the box is moving along: after two stops nothing
    // is left.
    for (int stops = 0; stops < kMaxSlides && (left.x != 0.0f || left.y != 0.0f); ++stops) {
        firstStop(w, candidates, result.centre, half, radius, left, stopsMovingBox, stop);
        if (stop.met.empty()) {
            result.centre += left;
            break;
        }
        if (stop.time > 0.0f)
            against.clear(); // it moved: what it stopped against before is behind it
        result.centre = stop.centre;
        left = left * (1.0f - stop.time);
        for (const Met& m : stop.met) {
            result.hits.push_back({w.idOf(m.slot), m.contact.normal});
            against.push_back(m.contact.normal);
        }
        left = slideAlong(left, against);
    }
    return result;
}

} // namespace jostle
