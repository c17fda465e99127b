// Events of the physical step: contacts that touch, sensor overlaps, crushes.
#include "report.hpp"

#include "../events.hpp"
#include "../record_touch.hpp"
#include "../room.hpp"
#include "contact_cache.hpp"
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
void findCrush(const WorldState& w, const Contact& c, std::uint32_t k, std::uint32_t slotA,
               std::uint32_t slotB, float overlap, std::vector<CrushCandidate>& candidates) {
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
        candidates.push_back({body, by, into, k});
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
    for (const CrushCandidate& candidate : step.scratch.report.candidatesInOrder) {
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
    }
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

/// Sorts the records of one run of the contact cache (one first body) by the other body,
/// stably: a run is short (ContactCache's long runs lie sorted).
void sortRunByB(TouchRecord* first, TouchRecord* last) {
    for (TouchRecord* i = first + 1; i < last; ++i) {
        const TouchRecord record = *i;
        TouchRecord* j = i;
        for (; j > first && (j - 1)->b.index > record.b.index; --j)
            *j = *(j - 1);
        *j = record;
    }
}

/// Lists the touching contacts sorted by pair, as publish() compares them, and finds the
/// crush candidates. The contacts are taken in the contact cache's order, which storeImpulses
/// has just made: by first body, so that sorting each body's few records by the other
/// gives the whole list sorted. On one thread, each is listed as it is found. Shared
/// among the workers, each contact that touches writes its record at its cache place and
/// its bodies' flags beside it, and one pass then closes the gaps and sets the flags in
/// that order: the same list and the same flags.
void listTouches(StepContext& step) {
    WorldState& w = step.world;
    ReportScratch& scratch = step.scratch.report;
    std::vector<TouchRecord>& records = w.events.contactsNow;
    const ContactCache& cache = w.contactCache;
    const std::uint32_t count = cache.size();
    std::vector<CrushCandidate>& candidates = scratch.candidatesInOrder;
    candidates.clear();
    // At most a record a contact.
    makeRoom(records, count);
    // Only a dynamic body against an infinitely heavy one can be crushed.
    const auto lookForCrush = [&](const Contact& c, std::uint32_t k, float overlap,
                                  std::vector<CrushCandidate>& found) {
        if ((step.invMassA(c) == 0.0f) != (step.invMassB(c) == 0.0f))
            findCrush(w, c, k, step.bodies[c.ia].slot, step.bodies[c.ib].slot, overlap, found);
    };
    if (!w.tasks->sharing()) {
        cache.forEachRun([&](std::uint32_t begin, std::uint32_t end, bool sortedByB) {
            const std::size_t first = records.size();
            for (std::uint32_t place = begin; place < end; ++place) {
                const std::uint32_t k = cache.stepContactAt(place);
                const Contact& c = step.contacts[k];
                const float overlap = step.overlapOf(c);
                if (touchesAtTheEnd(step, c, overlap))
                    listTouch(w, touchOf(step, c));
                lookForCrush(c, k, overlap, candidates);
            }
            if (!sortedByB)
                sortRunByB(records.data() + first, records.data() + records.size());
        });
    } else {
        scratch.crushCandidates.reset(w.tasks->blocksOf(count, kContactsPerReportBlock));
        resizeAnewToFit(scratch.touches, count);
        records.resize(count);
        w.tasks->forEachBlock(count, kContactsPerReportBlock, [&](Block block) {
            for (std::uint32_t place = block.begin; place < block.end; ++place) {
                const std::uint32_t k = cache.stepContactAt(place);
                const Contact& c = step.contacts[k];
                const float overlap = step.overlapOf(c);
                scratch.touches[place] = 0;
                if (touchesAtTheEnd(step, c, overlap)) {
                    const FoundTouch touch = touchOf(step, c);
                    records[place] = touch.record;
                    scratch.touches[place] =
                        std::uint16_t(kTouches | touch.flagA | touch.flagB << 4);
                }
                lookForCrush(c, k, overlap, scratch.crushCandidates[block.index]);
            }
        });
        std::size_t at = 0;
        cache.forEachRun([&](std::uint32_t begin, std::uint32_t end, bool sortedByB) {
            const std::size_t first = at;
            for (std::uint32_t place = begin; place < end; ++place) {
                const std::uint16_t touch = scratch.touches[place];
                if (touch == 0)
                    continue;
                const TouchRecord record = records[place];
                flagTouch(w.events, record, TouchingBit(touch & 0xF),
                          TouchingBit(touch >> 4 & 0xF));
                records[at++] = record;
            }
            if (!sortedByB)
                sortRunByB(records.data() + first, records.data() + at);
        });
        records.resize(at);
        scratch.crushCandidates.forEachInOrder(
            [&](const CrushCandidate& candidate) { candidates.push_back(candidate); });
    }
    w.events.contactsNowSorted = true;
    // Crushes are reported in contact order.
    std::sort(
        candidates.begin(), candidates.end(),
        [](const CrushCandidate& x, const CrushCandidate& y) { return x.contact < y.contact; });
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
