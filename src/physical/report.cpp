// Events of the physical step: contacts that touch, sensor overlaps, crushes.
#include "report.hpp"

#include "../events.hpp"
#include "../record_touch.hpp"
#include "../room.hpp"
#include "step_context.hpp"

#include <algorithm>

namespace jostle {

namespace {

/// A body overlapped by a kinematic one deeper than this fraction of its half extent is
/// being crushed (if held on the other side): the solver could not push it out.
constexpr float kCrushDepth = 0.1f;

/// Contacts per block: each block lists the pairs of its contacts that touch, and its
/// crush candidates, in contact order.
constexpr std::uint32_t kContactsPerReportBlock = 1024;

/// A dynamic body that a kinematic body moving into it overlaps deeper than kCrushDepth
/// of its size becomes a candidate.
void findCrush(const WorldState& w, const Contact& c, std::uint32_t slotA, std::uint32_t slotB,
               float overlap, std::vector<CrushCandidate>& candidates) {
    const Body& a = w.slots[slotA];
    const Body& b = w.slots[slotB];
    const bool kinematicA = a.type == BodyType::Kinematic,
               kinematicB = b.type == BodyType::Kinematic;
    if (kinematicA == kinematicB || (kinematicA ? !b.isDynamic() : !a.isDynamic()))
        return;
    const std::uint32_t body = kinematicA ? slotB : slotA;
    const std::uint32_t by = kinematicA ? slotA : slotB;
    const Vec2 into = kinematicA ? -c.normal() : c.normal();
    const Vec2 bodyHalf = w.slots[body].half;
    const float half = c.axis == kAlongSlope ? std::min(bodyHalf.x, bodyHalf.y) : bodyHalf[c.axis];
    if (dot(w.slots[by].velocity, into) > 0.0f && overlap > kCrushDepth * half)
        candidates.push_back({body, by, into});
}

/// Whether the crush under way `e` goes on: both bodies are still there and overlap.
bool goesOn(const WorldState& w, const CrushEvent& e) {
    return w.isCurrent(e.body) && w.isCurrent(e.by) &&
           overlaps(w.slots[e.body.index].box(), w.slots[e.by.index].box());
}

/// Each candidate with a contact on its far side, against something heavy (static,
/// kinematic, or a body that holds it), is crushed. A crush begins once; those under way
/// end when the two no longer overlap.
void reportCrushes(StepContext& step) {
    WorldState& w = step.world;
    StepEvents& events = w.events;
    std::erase_if(events.crushing, [&](const CrushEvent& e) {
        if (goesOn(w, e))
            return false;
        events.crushEnds.push_back(e);
        return true;
    });
    const auto underWay = [&](BodyId body, BodyId by) {
        return std::any_of(events.crushing.begin(), events.crushing.end(),
                           [&](const CrushEvent& e) { return e.body == body && e.by == by; });
    };
    step.scratch.report.crushCandidates.forEachInOrder([&](const CrushCandidate& candidate) {
        for (const Contact& c : step.contacts) {
            const std::uint32_t slotA = step.bodies[c.ia].slot, slotB = step.bodies[c.ib].slot;
            if (slotA != candidate.body && slotB != candidate.body)
                continue;
            const std::uint32_t other = slotA == candidate.body ? slotB : slotA;
            // The other body pushes back against the kinematic one's push.
            const Vec2 push = slotA == candidate.body ? c.normal() : -c.normal();
            if (other == candidate.by || dot(push, candidate.into) >= 0.0f)
                continue;
            const bool otherHolds = c.supporter == (other == slotA ? 1 : 2);
            const bool heavy = !w.slots[other].isDynamic() || otherHolds;
            if (heavy && c.totalImpulse() > 0.0f) {
                const CrushEvent crush{w.idOf(candidate.body), w.idOf(candidate.by), w.idOf(other)};
                if (!underWay(crush.body, crush.by)) {
                    events.crushBegins.push_back(crush);
                    events.crushing.push_back(crush);
                }
                break;
            }
        }
    });
}

/// Whether contact `c` touches where the step leaves its bodies, which overlap by
/// `overlap` along its normal (StepContext::overlapOf: the solver bodies hold where the step
/// leaves every body of a contact).
bool touchesAtTheEnd(const StepContext& step, const Contact& c, float overlap) {
    const float gap = -overlap;
    const float skin =
        std::max(2.0f * step.slopOf(c), kMinimumSkin * (c.axis == kAlongSlope ? c.size : c.extent));
    // A pair that collided touched this step, if only for a moment: a bounce from the
    // middle of the step ends it apart.
    return gap <= skin || c.collisionImpulse > 0.0f;
}

FoundTouch touchOf(const StepContext& step, const Contact& c) {
    return findTouch(step.world, step.bodies[c.ia].slot, step.bodies[c.ib].slot, c.normal(),
                     c.approachSpeed, c.totalImpulse());
}

/// A contact's entry in ReportScratch::touches: it touches, and the flags of its record's
/// two bodies (TouchingBit: four bits each).
constexpr std::uint16_t kTouches = 0x100;

/// Lists the touching contacts, in contact order, and finds the crush candidates. On one
/// thread, each is listed as it is found. Shared among the workers, each contact that
/// touches writes its record at its own index and its bodies' flags beside it, and one
/// pass then closes the gaps and sets the flags in contact order: the same list and the
/// same flags, in the list's own room.
void listTouches(StepContext& step) {
    WorldState& w = step.world;
    ReportScratch& scratch = step.scratch.report;
    std::vector<TouchRecord>& records = w.events.contactsNow;
    const auto count = std::uint32_t(step.contacts.size());
    scratch.crushCandidates.reset(w.tasks->blocksOf(count, kContactsPerReportBlock));
    const bool inOrder = !w.tasks->sharing();
    const std::size_t listed = records.size();
    // At most a record a contact.
    makeRoom(records, listed + count);
    if (!inOrder) {
        resizeAnewToFit(scratch.touches, count);
        records.resize(listed + count);
    }
    w.tasks->forEachBlock(count, kContactsPerReportBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const Contact& c = step.contacts[k];
            const float overlap = step.overlapOf(c);
            const bool touches = touchesAtTheEnd(step, c, overlap);
            if (inOrder) {
                if (touches)
                    listTouch(w, touchOf(step, c));
            } else if (touches) {
                const FoundTouch touch = touchOf(step, c);
                records[listed + k] = touch.record;
                scratch.touches[k] = std::uint16_t(kTouches | touch.flagA | touch.flagB << 4);
            } else {
                scratch.touches[k] = 0;
            }
            // Only a dynamic body against an infinitely heavy one can be crushed.
            if ((step.invMassA(c) == 0.0f) != (step.invMassB(c) == 0.0f))
                findCrush(w, c, step.bodies[c.ia].slot, step.bodies[c.ib].slot, overlap,
                          scratch.crushCandidates[block.index]);
        }
    });
    if (inOrder)
        return;
    std::size_t at = listed;
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::uint16_t touch = scratch.touches[k];
        if (touch == 0)
            continue;
        const TouchRecord record = records[listed + k];
        flagTouch(w.events, record, TouchingBit(touch & 0xF), TouchingBit(touch >> 4 & 0xF));
        records[at++] = record;
    }
    records.resize(at);
}

} // namespace

void reportEvents(StepContext& step) {
    WorldState& w = step.world;
    listTouches(step);
    for (const BodyPair& pair : step.scratch.sensorPairs) {
        if (!w.isLive(pair.a) || !w.isLive(pair.b))
            continue;
        // Overlapping, not merely touching.
        if (overlaps(w.slots[pair.a].box(), w.slots[pair.b].box()))
            recordSensor(w, pair.a, pair.b);
    }
    reportCrushes(step);
}

} // namespace jostle
