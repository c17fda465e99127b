// Events: what touches at the end of this step against what touched at the end of the last,
// made into begin and end events and touching flags (events.hpp).
#include "events.hpp"

#include "counting_sort.hpp"
#include "ground.hpp"
#include "record_touch.hpp"
#include "room.hpp"
#include "world_state.hpp"

#include <algorithm>

namespace jostle {

namespace {

/// A contact the step did not look at: neither body is an awake dynamic body.
bool contactNotEvaluated(const WorldState& world, const TouchRecord& record) {
    auto resting = [&](SlotRef ref) {
        const Body& body = world.slots[ref.index];
        return !body.isDynamic() || body.asleep;
    };
    return world.isCurrent(record.a) && world.isCurrent(record.b) && resting(record.a) &&
           resting(record.b);
}

/// A sensor overlap the step did not look at: one of the two sleeps. Sensors see every
/// body that moves, kinematic ones included, at every step.
bool sensorNotEvaluated(const WorldState& world, const TouchRecord& record) {
    return world.isCurrent(record.a) && world.isCurrent(record.b) &&
           (world.slots[record.a.index].asleep || world.slots[record.b.index].asleep);
}

/// Records fewer than the slots over this many are merge-sorted: a counting sort's passes
/// over every slot would cost more (a level of a thousand static boxes and one player).
constexpr std::size_t kSlotsPerRecordForCounting = 16;

/// Sorts `records` by pair (a's slot, then b's), stably: in two counting sorts, by b then
/// by a, or, where the records are few against the slots, in a merge sort by the pair.
/// A slot holds one body at a time, so within one list the pair of slots names the pair.
void sortByPair(std::vector<TouchRecord>& records, std::vector<TouchRecord>& scratch,
                Buckets& buckets, std::size_t slotCount) {
    // Nothing to sort (no sensors, most steps): leave the buffers, sized by the last
    // sort, as they are.
    if (records.size() < 2)
        return;
    if (records.size() * kSlotsPerRecordForCounting < slotCount) {
        mergeSortByKey(
            records, [](const TouchRecord& r) { return r.key(); }, scratch);
        return;
    }
    sortByKey(
        records, [](const TouchRecord& r) { return r.b.index; }, slotCount, buckets, scratch);
    sortByKey(
        records, [](const TouchRecord& r) { return r.a.index; }, slotCount, buckets, scratch);
}

/// Walks this step's pairs (`now`, sorted) beside the last step's (`before`, sorted):
/// pairs only in `now` begin; pairs only in `before` end, unless the step did not look
/// at them (then they carry over); a slot pair holding other bodies than before ends
/// and begins. `before` becomes the new list, merged in `now`'s room: `carried` notes
/// where each pair carried over goes (before its place in `before`, the count of `now`'s
/// pairs ahead of it).
template <class NotEvaluated, class OnBegin, class OnEnd>
void compare(const WorldState& world, std::vector<TouchRecord>& now,
             std::vector<TouchRecord>& before, std::vector<CarriedPair>& carried,
             NotEvaluated&& notEvaluated, OnBegin&& begin, OnEnd&& end) {
    carried.clear();
    std::size_t i = 0, j = 0;
    while (i < now.size() || j < before.size()) {
        if (j == before.size() || (i < now.size() && now[i].key() < before[j].key())) {
            begin(now[i++]);
        } else if (i == now.size() || before[j].key() < now[i].key()) {
            if (notEvaluated(world, before[j]))
                carried.push_back({std::uint32_t(j), std::uint32_t(i)});
            else
                end(before[j]);
            ++j;
        } else {
            if (now[i].a != before[j].a || now[i].b != before[j].b) {
                end(before[j]);
                begin(now[i]);
            }
            ++i;
            ++j;
        }
    }
    // The pairs carried over go in among now's, from the back: each of now's moves up by
    // the count carried over ahead of it, to a place not yet read.
    std::size_t moved = now.size();
    makeRoom(now, now.size() + carried.size());
    now.resize(now.size() + carried.size());
    for (std::size_t m = carried.size(); m-- > 0;) {
        const CarriedPair pair = carried[m];
        for (std::size_t q = moved; q-- > pair.nowAhead;)
            now[q + m + 1] = now[q];
        moved = pair.nowAhead;
        now[pair.nowAhead + m] = before[pair.before];
    }
    before.swap(now);
    now.clear();
}

} // namespace

void recordContact(WorldState& world, std::uint32_t body, std::uint32_t other, Vec2 normal,
                   float approachSpeed, float impulse) {
    listTouch(world, findTouch(world, body, other, normal, approachSpeed, impulse));
}

Vec2 pointOf(const WorldState& world, const TouchRecord& record) {
    const Body& a = world.slots[record.a.index];
    const Body& b = world.slots[record.b.index];
    if (a.isBox() && b.isBox())
        return touchPoint(a.box(), b.box(), record.normal);
    return b.position + touchPointOf(a.position - b.position, a.half, world.shapes[record.a.index],
                                     b.half, world.shapes[record.b.index], record.normal);
}

void recordSensor(WorldState& world, std::uint32_t sensor, std::uint32_t visitor) {
    world.events.sensorsNow.push_back({world.refOf(sensor), world.refOf(visitor), {}, 0.0f});
}

void StepEvents::clearStepLists() {
    clearAfterBurst(begins);
    clearAfterBurst(ends);
    clearAfterBurst(sensorBegins);
    clearAfterBurst(sensorEnds);
    clearAfterBurst(crushBegins);
    clearAfterBurst(crushEnds);
    contactsNow.clear();
    sensorsNow.clear();
    contactsNowSorted = false;
}

void StepEvents::beginStep(const WorldState& world) {
    clearStepLists();
    touching.resize(world.slots.size(), 0);

    down = downOf(world.def.gravity);
    // Awake dynamic bodies are evaluated afresh; the others keep their flags.
    for (BodyId id : world.movers()) {
        const Body& body = world.slots[id.index];
        if (body.isDynamic() && !body.asleep)
            touching[id.index] = 0;
    }
}

void StepEvents::publish(const WorldState& world, bool anyAwake) {
    // Nothing awake and nothing gone: every pair of the last step carries over as it was.
    if (!anyAwake && !destroyedSincePublish && contactsNow.empty() && sensorsNow.empty())
        return;
    if (destroyedSincePublish) {
        // A pair recorded before a callback destroyed one of its bodies, later in the
        // step (the classic model records pairs as it resolves them): the body is gone,
        // and a pair that touched before this step ends (below), one that had just met is
        // dropped.
        auto gone = [&](const TouchRecord& r) {
            return !world.isCurrent(r.a) || !world.isCurrent(r.b);
        };
        std::erase_if(contactsNow, gone);
        std::erase_if(sensorsNow, gone);
    }
    destroyedSincePublish = false;
    if (!contactsNowSorted)
        sortByPair(contactsNow, contactScratch_, buckets_, world.slots.size());
    compare(
        world, contactsNow, contactsBefore_, carried_, contactNotEvaluated,
        [&](const TouchRecord& r) {
            begins.push_back(
                {world.idFor(r.a), world.idFor(r.b), r.normal, r.approachSpeed, pointOf(world, r)});
        },
        [&](const TouchRecord& r) {
            ends.push_back({world.idFor(r.a), world.idFor(r.b), r.normal, 0.0f, Vec2{}});
        });
    {
        std::lock_guard<std::mutex> lock(indexMutex_);
        indexed_ = false; // contactsBefore_ changed
    }
    sortByPair(sensorsNow, sensorScratch_, buckets_, world.slots.size());
    compare(
        world, sensorsNow, sensorsBefore_, carried_, sensorNotEvaluated,
        [&](const TouchRecord& r) {
            sensorBegins.push_back({world.idFor(r.a), world.idFor(r.b)});
        },
        [&](const TouchRecord& r) {
            sensorEnds.push_back({world.idFor(r.a), world.idFor(r.b)});
        });
}

void StepEvents::indexTouches() const {
    std::uint32_t slotCount = 0;
    for (const TouchRecord& r : contactsBefore_)
        slotCount = std::max({slotCount, r.a.index + 1, r.b.index + 1});
    touchesBySlot_.reset(slotCount);
    for (const TouchRecord& r : contactsBefore_) {
        touchesBySlot_.count(r.a.index);
        touchesBySlot_.count(r.b.index);
    }
    touchIndex_.resize(touchesBySlot_.endCounting());
    for (std::uint32_t k = 0; k < contactsBefore_.size(); ++k) {
        touchIndex_[touchesBySlot_.place(contactsBefore_[k].a.index)] = k;
        touchIndex_[touchesBySlot_.place(contactsBefore_[k].b.index)] = k;
    }
    touchesBySlot_.endPlacing();
    indexed_ = true;
}

void StepEvents::clear() {
    clearStepLists();
    crushing.clear();
    touching.clear();
    contactsBefore_.clear();
    sensorsBefore_.clear();
    destroyedSincePublish = false;
    std::lock_guard<std::mutex> lock(indexMutex_);
    indexed_ = false;
}

} // namespace jostle
