// Moving a body by hand, bump.lua's way (jostle/query.hpp's move): one sweep after
// another from where the body is, each stop answered as the filter says.
#include "jostle/query.hpp"

#include "first_stop.hpp"
#include "world_access.hpp"

#include <unordered_map>

namespace jostle {

namespace {

/// After this many stops in one move, the body stays where the last one left it.
constexpr int kMaxStops = 32;

/// The responses of one move, asked of the filter once per body. Only looked up, never
/// iterated: its hash order cannot leak into the results.
class Responses {
public:
    Responses(const WorldState& w, const MoveFilter& filter) : w_(w), filter_(filter) {}

    Response of(std::uint32_t slot) {
        const auto [at, fresh] = chosen_.try_emplace(slot, Response::Slide);
        if (fresh) {
            const Body& other = w_.slots[slot];
            at->second = filter_ ? filter_(w_.idOf(slot))
                                 : (other.sensor ? Response::Cross : Response::Slide);
        }
        return at->second;
    }

private:
    const WorldState& w_;
    const MoveFilter& filter_;
    std::unordered_map<std::uint32_t, Response> chosen_;
};

/// Marks the world as walked by a move while it lives, however the walk ends (a filter may
/// throw): the filter may read the world, not change it (requireChangeable).
class MoveUnderWay {
public:
    explicit MoveUnderWay(WorldState& w) : w_(w) { w_.moveUnderWay = true; }
    ~MoveUnderWay() { w_.moveUnderWay = false; }
    MoveUnderWay(const MoveUnderWay&) = delete;
    MoveUnderWay& operator=(const MoveUnderWay&) = delete;

private:
    WorldState& w_;
};

/// Where body `id` goes moving by `delta`, and what it meets on the way; nothing moves.
MoveOutcome walk(WorldState& w, BodyId id, Vec2 delta, const MoveFilter& filter) {
    const MoveUnderWay underWay(w);
    const Body& self = w.slots[id.index];
    const Vec2 half = self.half;
    // A rounded body moves as its shape; a ramp or a segment as its box.
    const float radius = self.shape == ShapeKind::Round ? w.shapes[id.index].radius : 0.0f;
    MoveOutcome out{self.position, {}};
    Responses responses(w, filter);
    std::vector<std::uint32_t> crossed;
    auto meets = [&](std::uint32_t slot) {
        return slot != id.index && canCollide(w.slots[id.index], w.slots[slot]) &&
               std::find(crossed.begin(), crossed.end(), slot) == crossed.end() &&
               responses.of(slot) != Response::Ignore;
    };
    const Candidates candidates(w);
    Vec2 left = delta;    // what is left of the move, from out.centre
    float elapsed = 0.0f; // the part of the move's time already used
    FirstStop stop;
    // The normals of the bodies it slid against where it is now; those of one stop.
    std::vector<Vec2> against, slides, bounces;
    for (int stops = 0; stops < kMaxStops && (left.x != 0.0f || left.y != 0.0f); ++stops) {
        firstStop(w, candidates, out.centre, half, radius, left, meets, stop);
        // A move that ends touching a body has not run into it (bump.lua's rule): the next
        // move that goes on into it meets it, once.
        if (stop.met.empty() || stop.time >= 1.0f) {
            out.centre += left;
            break;
        }
        const float at = elapsed + (1.0f - elapsed) * stop.time;
        bool stopped = false, touched = false;
        bool slide[2] = {false, false}, bounce[2] = {false, false};
        slides.clear();
        bounces.clear();
        for (const Met& m : stop.met) {
            const Body& other = w.slots[m.slot];
            const Response response = responses.of(m.slot);
            out.collisions.push_back({w.idOf(m.slot), response, m.contact.normal, stop.centre, at,
                                      other.position, other.half});
            const int axis = m.contact.normal.x != 0.0f ? 0 : 1;
            switch (response) {
            case Response::Cross:
                crossed.push_back(m.slot);
                break;
            case Response::Touch:
                touched = stopped = true;
                break;
            case Response::Slide:
                slide[axis] = stopped = true;
                slides.push_back(m.contact.normal);
                break;
            case Response::Bounce:
                bounce[axis] = stopped = true;
                bounces.push_back(m.contact.normal);
                break;
            case Response::Ignore:
                break;
            }
        }
        if (!stopped)
            continue; // only crossed: on from where it is, without them
        // It goes to where it touched; what is left of the move turns there.
        out.centre = stop.centre;
        elapsed = at;
        left = left * (1.0f - stop.time);
        if (touched)
            break;
        if (stop.time > 0.0f)
            against.clear(); // it moved: what it slid against before is behind it
        against.insert(against.end(), slides.begin(), slides.end());
        const auto alongAxis = [](Vec2 n) { return n.x == 0.0f || n.y == 0.0f; };
        if (std::all_of(against.begin(), against.end(), alongAxis) &&
            std::all_of(bounces.begin(), bounces.end(), alongAxis)) {
            for (int axis = 0; axis < 2; ++axis) {
                if (slide[axis])
                    left[axis] = 0.0f;
                else if (bounce[axis])
                    left[axis] = -left[axis];
            }
            continue;
        }
        // A slope or a rounded corner: off each face it bounces from (each face once: after
        // the first, it no longer goes into it), then along those it slides against.
        for (Vec2 n : bounces)
            if (const float into = dot(left, n); into < 0.0f)
                left -= n * (2.0f * into);
        left = slideAlong(left, against);
    }
    return out;
}

} // namespace

MoveOutcome move(World& world, BodyId id, Vec2 delta, const MoveFilter& filter) {
    WorldState& w = WorldAccess::state(world);
    const Body& self = lookUpToChange(w, id, "move");
    requireFinite("move", "delta", delta);
    if (!inRange(self.position + delta))
        fail("move", "position + delta must be of magnitude <= 1e9 (math.hpp)");
    MoveOutcome out = walk(w, id, delta, filter);
    // A bounce may turn it back past the edge of the range jostle works in: it stops there.
    for (float* at : {&out.centre.x, &out.centre.y})
        *at = std::clamp(*at, -kMaxMagnitude, kMaxMagnitude);
    world.setPosition(id, out.centre);
    return out;
}

} // namespace jostle
