// Building contacts: each pair the broadphase found made into a contact along the normal
// contact_normal.hpp chooses (one-way platforms, the pre-solve callback, warm starting, the target
// speed), in blocks on the workers or pair by pair around the pre-solve.
#include "contacts.hpp"

#include "../characters.hpp"
#include "../one_way.hpp"
#include "../room.hpp"
#include "../shapes.hpp"
#include "contact_normal.hpp"
#include "contact_of.hpp"
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

/// The two slots as one number, the same in either order.
std::uint64_t pairKey(std::uint32_t slotA, std::uint32_t slotB) {
    return std::uint64_t{std::min(slotA, slotB)} << 32 | std::max(slotA, slotB);
}

/// contactOf for a pair chooseShapedNormal found: along an axis if its normal is one.
Contact shapedContactOf(const StepContext& step, const Body& a, const Body& b,
                        const ShapedFacing& facing) {
    Contact c;
    const Vec2 n = facing.normal;
    if (n.x == 0.0f || n.y == 0.0f) {
        const bool alongX = n.x != 0.0f;
        c.axis = alongX ? kAlongX : kAlongY;
        c.n = axisNormal(c.axis, alongX ? n.x : n.y);
    } else {
        c.axis = kAlongSlope;
        c.n = n;
    }
    c.extent = facing.extent;
    c.size = facing.size;
    const Vec2 down = step.world.events.down;
    c.friction = frictionOfPair(step, a, b, n);
    if (keepsATangentSpeed(a, b, step.world.conveyors > 0)) {
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
        if (!stops(a, -outcome.normal, outcome.gap >= -skin, b.dropThroughTime) ||
            !stops(b, outcome.normal, outcome.gap >= -skin, a.dropThroughTime))
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

/// Fills in the warm start and the target of a contact examinePair made.
void finishContact(const StepContext& step, Contact& c, const BodyPair& pair,
                   const PairOutcome& outcome) {
    warmStart(step, c, pair.a, pair.b, outcome.normal);
    setTarget(c, outcome.bounce, outcome.gap, step.dt);
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
    resizeAnewToFit(made, pairs.size());
    // Last step's contacts are overwritten, not made anew first: only the rest are.
    resizeAnewToFit(step.contacts, pairs.size());
    w.tasks->forEachBlock(std::uint32_t(pairs.size()), kPairsPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            // The reads of a pair are scattered over memory: ask for them a few pairs ahead.
            if (k + kLookAhead < block.end) {
                const BodyPair& ahead = pairs[k + kLookAhead];
                __builtin_prefetch(&w.slots[ahead.a]);
                __builtin_prefetch(&w.slots[ahead.b]);
                w.contactCache.prefetch(ahead.a);
            }
            // Written whole where the pair makes a contact, and read nowhere else.
            Contact& c = step.contacts[k];
            const PairOutcome outcome = examinePair(step, pairs[k], c);
            made[k] = outcome.kind;
            if (outcome.kind != PairOutcome::kContact)
                continue;
            // No callback runs here: the bodies' masses are those the step met them with.
            if (w.slots[pairs[k].a].invMass + w.slots[pairs[k].b].invMass <= 0.0f)
                made[k] = PairOutcome::kNothing;
            else
                finishContact(step, c, pairs[k], outcome);
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
        // The callback sees the pair's friction as the world mixes it, also where a
        // character stands firm on a slope: that footing stays unless it lowers it.
        const float mixed = c.walksAlongSlope ? frictionOfPair(step, w.slots[pair.a],
                                                               w.slots[pair.b], outcome.normal)
                                              : c.friction;
        Collision info{w.idOf(pair.a), w.idOf(pair.b), outcome.normal,
                       -outcome.gap,   outcome.bounce, mixed};
        const bool keep = w.askPreSolve(info);
        if (!keep)
            vetoed.push_back(pairKey(pair.a, pair.b));
        if (!keep || !w.isLive(pair.a) || !w.isLive(pair.b))
            continue;
        if (!std::isnan(info.bounce))
            outcome.bounce = std::clamp(info.bounce, 0.0f, 1.0f);
        if (!std::isnan(info.friction) && !(c.walksAlongSlope && info.friction >= mixed))
            c.friction = std::clamp(info.friction, 0.0f, 1.0f);
        // The callback may have created bodies: finishContact reads them afresh.
        c.ia = step.solverBodyOf(pair.a);
        c.ib = step.solverBodyOf(pair.b);
        // The solver reads the masses its bodies had when the step met them: a body a
        // callback made heavier or lighter since keeps them to the end of the step.
        if (step.invMassA(c) + step.invMassB(c) > 0.0f) {
            finishContact(step, c, pair, outcome);
            step.contacts.push_back(c);
        }
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

namespace {

/// A body being crushed and what crushes it pass through each other until they part
/// (docs/events.md): their pair makes no contact, and no sweep of either meets the other.
void leaveOutCrushes(StepContext& step) {
    WorldState& w = step.world;
    std::vector<std::uint64_t>& vetoed = step.scratch.contactsBuild.vetoed;
    for (const CrushEvent& e : w.events.crushing)
        if (w.isCurrent(e.body) && w.isCurrent(e.by))
            vetoed.push_back(pairKey(e.body.index, e.by.index));
    if (vetoed.empty())
        return;
    std::sort(vetoed.begin(), vetoed.end());
    std::erase_if(w.pairs, [&](const BodyPair& pair) {
        return std::binary_search(vetoed.begin(), vetoed.end(), pairKey(pair.a, pair.b));
    });
}

} // namespace

void buildContacts(StepContext& step) {
    WorldState& w = step.world;
    w.physical->solverIndex.assign(w.slots.size(), StepContext::kNoSolverBody);
    step.bodies.clear();
    step.scratch.contactsBuild.vetoed.clear();
    step.scratch.sensorPairs.clear();
    leaveOutCrushes(step);
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
    return shapedContactOf(step, a, b, ShapedFacing{{normal, 0.0f, 0.0f}, extent, size});
}

} // namespace jostle
