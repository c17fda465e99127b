// Building contacts: which pairs touch and along which axis, one-way platforms, the
// pre-solve callback, warm starting and the target speed of each contact.
#include "contacts.hpp"

#include "../characters.hpp"
#include "../shapes.hpp"
#include "seams.hpp"
#include "step_context.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace jostle {

namespace {

/// The friction of a character's foot on a sloped floor: enough for any walk.
constexpr float kFirmFooting = 1e3f;

/// Two normals this close (the cosine of their angle) are one contact's, from step to step.
constexpr float kSameNormal = 0.995f;

float combineFriction(FrictionMix mix, float a, float b) {
    return mix == FrictionMix::GeometricMean ? std::sqrt(a * b) : std::min(a, b);
}

/// The friction of a pair touching along `normal` (from b towards a): each body's against
/// the surface it meets (a character's wallFriction off its floor), combined.
float frictionOfPair(const StepContext& step, const Body& a, const Body& b, Vec2 normal) {
    const Vec2 down = step.world.events.down;
    return combineFriction(step.options.frictionMix, frictionAgainst(a, normal, down),
                           frictionAgainst(b, -normal, down));
}

/// The two slots as one number, the same in either order.
std::uint64_t pairKey(std::uint32_t slotA, std::uint32_t slotB) {
    return std::uint64_t{std::min(slotA, slotB)} << 32 | std::max(slotA, slotB);
}

/// The axis a pair touches along, as a unit normal from b towards a, with the gap
/// between them along it (negative: overlap) and the skin within which they touch.
struct Facing {
    Vec2 normal;
    float gap;
    float skin;
};

/// Apart along `normal` by `gap`, and neither body moving fast enough towards the other
/// to close it within the step. Each body's own speed counts, not only the pair's: two
/// boxes falling together do not approach, but when the lower one lands the upper one
/// must be stopped in the same step.
bool staysApart(const Body& a, const Body& b, Vec2 normal, float gap, float dt) {
    const float towardB = std::max(0.0f, -dot(a.velocity, normal));
    const float towardA = std::max(0.0f, dot(b.velocity, normal));
    return gap > 0.0f && gap > (towardA + towardB) * dt;
}

/// Where a contact's normal is chosen, or nothing if the pair cannot meet in this step:
/// apart along an axis by more than the skin, or along the chosen one at all, and not
/// closing that gap (staysApart). The axis is geometry.hpp's contactAxis, with two
/// exceptions at corners:
/// - A dynamic body apart on both axes from a static or kinematic one meets it where its
///   path across the step first touches it, and not at all if the path clears it: a box
///   rising past a ledge does not hit the ledge's side.
/// - If the corner is a seam between two static bodies, the face the contact would push
///   on is inside the level, and the other axis is the one. In a world with ramps, any
///   face the level covers where the body is (seams.hpp's pushingFaces) is inside it, and
///   the other face is the one if the body is at it and it is bare; else no contact. A
///   pair overlapping deeper than the skin goes the shallower way out, covered or not.
std::optional<Facing> chooseNormal(const StepContext& step, const Body& a, const Body& b) {
    const Vec2 d = a.position - b.position;
    const float gapX = std::abs(d.x) - (a.half.x + b.half.x);
    const float gapY = std::abs(d.y) - (a.half.y + b.half.y);
    const float skinX = step.skinOf(a.half.x, b.half.x);
    const float skinY = step.skinOf(a.half.y, b.half.y);
    // Apart along an axis by more than the skin, and not closing that gap in the step:
    // they never overlap along it, so they cannot touch (a box rising past a ledge it is
    // flush with does not meet the ledge's side).
    const Vec2 normalX{d.x < 0.0f ? -1.0f : 1.0f, 0.0f}, normalY{0.0f, d.y < 0.0f ? -1.0f : 1.0f};
    if ((gapX > skinX && staysApart(a, b, normalX, gapX, step.dt)) ||
        (gapY > skinY && staysApart(a, b, normalY, gapY, step.dt)))
        return std::nullopt;
    bool alongX = contactAxis(gapX, gapY, skinX, skinY) == Axis::X;
    if (gapX > skinX && gapY > skinY && (a.invMass == 0.0f || b.invMass == 0.0f)) {
        const std::optional<Hit> path =
            sweepBox(d, a.half + b.half, (a.velocity - b.velocity) * step.dt, Vec2{});
        if (!path)
            return std::nullopt;
        alongX = path->axis == 0;
    }
    const bool oneStatic =
        a.type != b.type && (a.type == BodyType::Static || b.type == BodyType::Static);
    const bool deep = gapX < -skinX && gapY < -skinY; // overlapping beyond the skin
    if (oneStatic && !deep && step.world.shapedBodies > 0) {
        // Among ramps, a box's face may be covered anywhere along it (a ramp sitting on a
        // floor): the faces that push are those the level leaves bare where the body is,
        // and a box with none is inside the level, which the bodies around it stand for.
        const bool aStatic = a.type == BodyType::Static;
        const Body& wall = aStatic ? a : b;
        const Body& other = aStatic ? b : a;
        const std::uint8_t pushing = pushingFaces(step.world, wall, other);
        auto pushes = [&](bool x) {
            const float side = (x ? d.x : d.y) * (aStatic ? -1.0f : 1.0f);
            return (pushing & faceBit(x ? 0 : 1, side < 0.0f ? -1.0f : 1.0f)) != 0;
        };
        if (!pushes(alongX)) {
            // The other face, if the body is at it (not across it) and it is bare.
            alongX = !alongX;
            if ((alongX ? gapX < -skinX : gapY < -skinY) || !pushes(alongX))
                return std::nullopt;
        }
    } else if (gapX >= -skinX && gapY >= -skinY && oneStatic) {
        const bool aStatic = a.type == BodyType::Static;
        if (isSeam(step.world, aStatic ? a : b, aStatic ? b : a, alongX ? 0 : 1))
            alongX = !alongX;
    }
    const Facing facing = alongX ? Facing{normalX, gapX, skinX} : Facing{normalY, gapY, skinY};
    if (staysApart(a, b, facing.normal, facing.gap, step.dt))
        return std::nullopt;
    return facing;
}

/// A pair where one body is not a sharp box (shapes.hpp), as chooseNormal for boxes.
struct ShapedFacing {
    Vec2 normal; ///< from b towards a
    float gap;
    float skin;
    float extent;
    float size; ///< the smaller reach along the normal
};

/// Where a pair with a rounded body, a ramp or a segment touches, or nothing if it cannot
/// meet in this step. One body is the obstacle, whose outline the other's centre stays out
/// of: a ramp or segment if there is one, else a static or kinematic body, else b. Only
/// the faces of a static obstacle the level leaves bare push (seams.hpp's pushingFaces); a
/// segment pushes with its slope alone, and only what was on its side when the step began.
std::optional<ShapedFacing> chooseShapedNormal(const StepContext& step, std::uint32_t slotA,
                                               std::uint32_t slotB) {
    const WorldState& w = step.world;
    const Body& a = w.slots[slotA];
    const Body& b = w.slots[slotB];
    auto isCut = [](const Body& body) {
        return body.shape == ShapeKind::Ramp || body.shape == ShapeKind::Segment;
    };
    if (isCut(a) && isCut(b))
        return std::nullopt; // ramps are infinitely heavy: two never push each other
    const bool aIsObstacle = isCut(a) || (!isCut(b) && a.invMass == 0.0f);
    const std::uint32_t moverSlot = aIsObstacle ? slotB : slotA;
    const std::uint32_t obstacleSlot = aIsObstacle ? slotA : slotB;
    const Body& mover = w.slots[moverSlot];
    const Body& obstacle = w.slots[obstacleSlot];
    const Shape& moverShape = w.shapes[moverSlot];
    const Shape& obstacleShape = w.shapes[obstacleSlot];
    const float r = moverShape.radius;
    const Outline outline = outlineOf(mover.half - Vec2{r, r}, r, obstacle.half, obstacleShape);
    const std::uint8_t pushing = pushingFaces(w, obstacle, mover);
    float apart = 0.0f;
    const Vec2 offset = mover.position - obstacle.position;
    std::optional<Touch> touch = touchOf(outline, offset, pushing, true, apart);
    if (!touch)
        return std::nullopt;
    touch =
        atImpact(*touch, offset, (mover.velocity - obstacle.velocity) * step.dt, outline.radius);
    if (!touch)
        return std::nullopt;
    const float size = std::min(reachOf(mover.half, moverShape, touch->normal),
                                reachOf(obstacle.half, obstacleShape, touch->normal));
    const float skin = std::max(2.0f * step.options.slop, kMinimumSkin) * size;
    const float reachable = (length(mover.velocity) + length(obstacle.velocity)) * step.dt;
    if ((apart > skin && apart > reachable) ||
        staysApart(mover, obstacle, touch->normal, touch->gap, step.dt))
        return std::nullopt;
    if (obstacle.shape == ShapeKind::Segment &&
        (touch->gap < -skin || mover.dropThroughTime > 0.0f))
        return std::nullopt;
    return ShapedFacing{aIsObstacle ? -touch->normal : touch->normal, touch->gap, skin,
                        touch->extent, size};
}

/// contactOf for a pair chooseShapedNormal found: along an axis if its normal is one.
Contact shapedContactOf(const StepContext& step, const Body& a, const Body& b,
                        const ShapedFacing& facing) {
    Contact c;
    const Vec2 n = facing.normal;
    if (n.x == 0.0f || n.y == 0.0f) {
        const bool alongX = n.x != 0.0f;
        c.axis = alongX ? 0 : 1;
        c.sign = alongX ? n.x : n.y;
        c.tangentSign = alongX ? n.x : -n.y;
    } else {
        c.axis = Contact::kSloped;
        c.sign = c.tangentSign = 1.0f;
    }
    c.sloped = n;
    c.extent = facing.extent;
    c.size = facing.size;
    c.slop = step.options.slop * facing.size;
    const Vec2 down = step.world.events.down;
    c.friction = frictionOfPair(step, a, b, n);
    if (a.character || b.character) {
        const float walk = walkAlongSlope(a, b, n, down);
        if (std::isnan(walk)) {
            c.tangentTarget = dot(walkOver(a, b, n, down), c.tangent());
        } else {
            // A character walks up and down a slope as on flat ground: at its walk speed
            // across gravity, and standing where it stops, whatever its friction.
            c.tangentTarget = walk;
            c.walksAlongSlope = true;
            c.friction = kFirmFooting;
        }
    }
    return c;
}

/// Starts `c` from last step's impulses if the cache holds the same contact: the same
/// bodies, touching along the same normal. Returns what it found.
const CachedContact* warmStart(const StepContext& step, Contact& c, std::uint32_t slotA,
                               std::uint32_t slotB, Vec2 normal) {
    const CachedContact* found = step.world.contactCache.find(slotA, slotB);
    // The same normal, or nearly: a rounded body rolling over a corner turns it a little
    // every step.
    if (!found || found->generationA != step.world.slots[slotA].generation ||
        found->generationB != step.world.slots[slotB].generation ||
        !(found->normal == normal || dot(found->normal, normal) > kSameNormal))
        return nullptr;
    c.normalImpulse = found->normalImpulse;
    c.tangentImpulse = found->tangentImpulse;
    return found;
}

/// The target speed: a speculative contact may close its gap, and no more; a touching
/// one stops the pair. Bounces are the impacts stage's (impacts.hpp).
void setTarget(Contact& c, float bounce, float gap, float dt) {
    c.targetSpeed = gap > 0.0f ? -gap / dt : 0.0f;
    c.bounce = bounce;
}

/// contactAlong, with internal linkage so that buildContacts, its hot caller, inlines it.
Contact contactOf(const StepContext& step, const Body& a, const Body& b, Vec2 normal) {
    Contact c;
    const bool alongX = normal.x != 0.0f;
    c.axis = alongX ? 0 : 1;
    c.sign = alongX ? normal.x : normal.y;
    c.tangentSign = alongX ? normal.x : -normal.y;
    c.extent = alongX ? a.half.x + b.half.x : a.half.y + b.half.y;
    c.slop =
        step.options.slop * (alongX ? std::min(a.half.x, b.half.x) : std::min(a.half.y, b.half.y));
    if (a.character || b.character) {
        // Characters rub only on floors, and walk over them (characters.hpp).
        const Vec2 down = step.world.events.down;
        c.friction = frictionOfPair(step, a, b, normal);
        Vec2 tangent;
        tangent[1 - c.axis] = c.tangentSign;
        c.tangentTarget = dot(walkOver(a, b, normal, down), tangent);
    } else {
        c.friction = combineFriction(step.options.frictionMix, a.friction, b.friction);
    }
    return c;
}

} // namespace

Contact contactAlong(const StepContext& step, const Body& a, const Body& b, Vec2 normal) {
    return contactOf(step, a, b, normal);
}

namespace {

/// What a pair makes before the pre-solve has its say.
struct PairOutcome {
    enum Kind : std::uint8_t { kNothing, kSensor, kContact } kind = kNothing;
    Vec2 normal; ///< of a contact, from b towards a
    float gap = 0.0f;
    float bounce = 0.0f;
};

/// The contact of `pair`, all but its solver bodies, warm start and target (finishContact),
/// reading the world and writing nothing: pairs may be examined on any thread.
PairOutcome examinePair(const StepContext& step, const BodyPair& pair, Contact& c) {
    const WorldState& w = step.world;
    if (!w.isLive(pair.a) || !w.isLive(pair.b))
        return {}; // destroyed by a callback earlier in the step
    const Body& a = w.slots[pair.a];
    const Body& b = w.slots[pair.b];
    if (!canCollide(a, b))
        return {};
    if (a.sensor || b.sensor) {
        // Overlap is judged where the step leaves them (report.cpp).
        return {a.sensor != b.sensor ? PairOutcome::kSensor : PairOutcome::kNothing};
    }
    PairOutcome outcome{PairOutcome::kContact};
    if (a.isBox() && b.isBox()) {
        const std::optional<Facing> facing = chooseNormal(step, a, b);
        if (!facing)
            return {};
        outcome.normal = facing->normal;
        outcome.gap = facing->gap;
        const float skin = facing->skin;
        // The normal points from b towards a; a pair touching within the skin was on
        // the platform's side when the step began.
        if ((a.isOneWay() && !a.blocks(-outcome.normal, outcome.gap >= -skin, b.dropThroughTime)) ||
            (b.isOneWay() && !b.blocks(outcome.normal, outcome.gap >= -skin, a.dropThroughTime)))
            return {};
        c = contactOf(step, a, b, outcome.normal);
    } else {
        const std::optional<ShapedFacing> facing = chooseShapedNormal(step, pair.a, pair.b);
        if (!facing)
            return {};
        outcome.normal = facing->normal;
        outcome.gap = facing->gap;
        c = shapedContactOf(step, a, b, *facing);
    }
    const float approach = dot(a.velocity - b.velocity, outcome.normal);
    c.approachSpeed = std::max(0.0f, -approach);
    outcome.bounce = std::max(a.bounce, b.bounce);
    return outcome;
}

/// Fills in the masses, the warm start and the target of a contact examinePair made;
/// false if both bodies are infinitely heavy (a callback made them so).
bool finishContact(const StepContext& step, Contact& c, const BodyPair& pair,
                   const PairOutcome& outcome) {
    c.invMassA = step.world.slots[pair.a].invMass;
    c.invMassB = step.world.slots[pair.b].invMass;
    const float invMassSum = c.invMassA + c.invMassB;
    if (invMassSum <= 0.0f)
        return false;
    c.effectiveMass = 1.0f / invMassSum;
    warmStart(step, c, pair.a, pair.b, outcome.normal);
    setTarget(c, outcome.bounce, outcome.gap, step.dt);
    return true;
}

/// Keeps a pair of a sensor and a body that may overlap it, the sensor first.
void addSensorPair(StepContext& step, const BodyPair& pair) {
    const bool aIsSensor = step.world.slots[pair.a].sensor;
    step.scratch.sensorPairs.push_back(aIsSensor ? pair : BodyPair{pair.b, pair.a});
}

/// Pairs per block of the parallel build.
constexpr std::uint32_t kPairsPerBlock = 1024;
/// How many pairs ahead the build asks the memory for a pair's bodies and cached contact.
constexpr std::uint32_t kLookAhead = 8;

/// Without a pre-solve callback: the pairs examined in blocks, each contact written at its
/// pair's index, then packed in pair order with solver bodies given in that order.
void buildInParallel(StepContext& step) {
    WorldState& w = step.world;
    const std::vector<BodyPair>& pairs = w.pairs;
    std::vector<std::uint8_t>& made = step.scratch.contactsBuild.made;
    made.resize(pairs.size());
    // Last step's contacts are overwritten, not made anew first: only the rest are.
    step.contacts.resize(pairs.size());
    w.tasks->forEachBlock(std::uint32_t(pairs.size()), kPairsPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            // The reads of a pair are scattered over memory: ask for them a few pairs ahead.
            if (k + kLookAhead < block.end) {
                const BodyPair& ahead = pairs[k + kLookAhead];
                __builtin_prefetch(&w.slots[ahead.a]);
                __builtin_prefetch(&w.slots[ahead.b]);
                w.contactCache.prefetch(ahead.a);
            }
            Contact& c = step.contacts[k];
            c = Contact{};
            const PairOutcome outcome = examinePair(step, pairs[k], c);
            made[k] = outcome.kind;
            if (outcome.kind == PairOutcome::kContact && !finishContact(step, c, pairs[k], outcome))
                made[k] = PairOutcome::kNothing;
        }
    });
    std::size_t kept = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const BodyPair& pair = pairs[k];
        if (made[k] == PairOutcome::kSensor) {
            addSensorPair(step, pair);
        } else if (made[k] == PairOutcome::kContact) {
            Contact& c = step.contacts[kept++];
            if (&c != &step.contacts[k])
                c = step.contacts[k];
            c.ia = step.solverBodyOf(pair.a);
            c.ib = step.solverBodyOf(pair.b);
        }
    }
    step.contacts.resize(kept);
}

/// With a pre-solve callback: pair by pair on the calling thread, the callback between
/// examining a pair and finishing its contact. It may veto the contact, change its bounce
/// and friction, and create and destroy bodies.
void buildWithCallback(StepContext& step) {
    WorldState& w = step.world;
    std::vector<std::uint64_t>& vetoed = step.scratch.contactsBuild.vetoed;
    for (const BodyPair& pair : w.pairs) {
        Contact c;
        PairOutcome outcome = examinePair(step, pair, c);
        if (outcome.kind == PairOutcome::kSensor)
            addSensorPair(step, pair);
        if (outcome.kind != PairOutcome::kContact)
            continue;
        Collision info{w.idOf(pair.a), w.idOf(pair.b), outcome.normal,
                       -outcome.gap,   outcome.bounce, c.friction};
        const bool keep = w.preSolve(info);
        if (!keep)
            vetoed.push_back(pairKey(pair.a, pair.b));
        if (!keep || !w.isLive(pair.a) || !w.isLive(pair.b))
            continue;
        if (!std::isnan(info.bounce))
            outcome.bounce = std::clamp(info.bounce, 0.0f, 1.0f);
        if (!std::isnan(info.friction))
            c.friction = std::clamp(info.friction, 0.0f, 1.0f);
        // The callback may have created bodies: finishContact reads them afresh.
        c.ia = step.solverBodyOf(pair.a);
        c.ib = step.solverBodyOf(pair.b);
        if (finishContact(step, c, pair, outcome))
            step.contacts.push_back(c);
    }
    std::sort(vetoed.begin(), vetoed.end());
    // A callback may have destroyed a body after its contact was made: the body is left
    // out of the rest of the step (no impulses, no events, no cached contact whose
    // generations would be those of the slot's next body).
    std::erase_if(step.contacts, [&](const Contact& c) {
        return !w.isLive(step.bodies[c.ia].slot) || !w.isLive(step.bodies[c.ib].slot);
    });
}

} // namespace

void buildContacts(StepContext& step) {
    WorldState& w = step.world;
    w.physical.solverIndex.assign(w.slots.size(), StepContext::kNoSolverBody);
    step.bodies.clear();
    step.scratch.contactsBuild.vetoed.clear();
    step.scratch.sensorPairs.clear();
    if (w.preSolve) {
        step.contacts.clear();
        buildWithCallback(step);
    } else {
        buildInParallel(step);
    }
}

bool isVetoed(const StepContext& step, std::uint32_t slotA, std::uint32_t slotB) {
    const std::vector<std::uint64_t>& vetoed = step.scratch.contactsBuild.vetoed;
    return std::binary_search(vetoed.begin(), vetoed.end(), pairKey(slotA, slotB));
}

Contact contactAlongShape(const StepContext& step, const Body& a, const Body& b, Vec2 normal,
                          float extent, float size) {
    return shapedContactOf(step, a, b, ShapedFacing{normal, 0.0f, 0.0f, extent, size});
}

} // namespace jostle
