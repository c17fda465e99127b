// What a step reports: contact and sensor events, crushes, touching flags. The solver
// lists what touches at the end of the step; publish() compares that with what touched
// at the end of the step before, and fills the arrays World hands out.
#pragma once

#include "counting_sort.hpp"
#include "ground.hpp"
#include "handles.hpp"
#include "jostle/world.hpp"

#include <cstdint>
#include <mutex>
#include <vector>

namespace jostle {

struct WorldState;
namespace snapshot {
struct Access;
}

/// A pair touching (or, for sensors, overlapping) at the end of a step.
struct TouchRecord {
    SlotRef a, b; ///< contacts: a created first; sensors: a is the sensor
    Vec2 normal;
    float approachSpeed = 0.0f;
    float impulse = 0.0f; ///< contacts: the normal impulse between them in the step

    std::uint64_t key() const { return std::uint64_t(a.index) << 32 | b.index; }
};
static_assert(sizeof(TouchRecord) == 32, "a record of the bodies' slots, not their handles");

/// A pair of the last step's that carries over to this step's list: its place in the last
/// step's, and how many of this step's pairs go ahead of it.
struct CarriedPair {
    std::uint32_t before, nowAhead;
};

struct StepEvents {
    std::vector<ContactEvent> begins, ends;
    std::vector<SensorEvent> sensorBegins, sensorEnds;
    std::vector<CrushEvent> crushBegins, crushEnds;
    /// Crushes under way (physical model): the body and what crushes it pass through each
    /// other, without a contact, until they no longer overlap (physical/report.cpp).
    std::vector<CrushEvent> crushing;
    /// TouchingBit flags by slot, from the last step that evaluated the body.
    std::vector<std::uint8_t> touching;
    /// Unit "down" for the touching flags this step, set by beginStep().
    Vec2 down{0.0f, 1.0f};

    /// Filled by the solver during a step: what touches (overlaps) at its end.
    std::vector<TouchRecord> contactsNow, sensorsNow;
    /// Set by a step that lists contactsNow sorted by pair already, as publish() needs it.
    bool contactsNowSorted = false;

    /// Empties the outputs and the lists of the step about to run.
    void beginStep(const WorldState& world);
    /// Turns this step's lists into begin and end events against the last step's, and
    /// keeps them for the next step. Pairs that were not looked at this step (neither
    /// body an awake dynamic one: a sleeping pile on its floor) carry over unchanged.
    /// `anyAwake`: whether the step had any awake dynamic or kinematic body (if not, and
    /// nothing was destroyed, there is nothing to compare).
    void publish(const WorldState& world, bool anyAwake);

    /// Set by destroyBody: the next publish must look for the pairs it ended.
    bool destroyedSincePublish = false;
    /// Forgets everything (the model changed).
    void clear();

    /// The pairs that touched at the end of the last step, sorted by pair.
    const std::vector<TouchRecord>& touchingBefore() const { return contactsBefore_; }
    /// Calls visit(record) for each pair of touchingBefore() that `slot` is part of, in
    /// their order. The index behind it is built on first use after a step, under a lock:
    /// World's const functions may run on several threads at once.
    template <class Visit> void forEachTouchOf(std::uint32_t slot, Visit&& visit) const {
        std::lock_guard<std::mutex> lock(indexMutex_);
        if (!indexed_)
            indexTouches();
        if (slot >= touchesBySlot_.keyCount())
            return;
        for (std::uint32_t k = touchesBySlot_.begin(slot); k < touchesBySlot_.end(slot); ++k)
            visit(contactsBefore_[touchIndex_[k]]);
    }

    /// The room the lists of touching contacts hold, in records (this step's, the last
    /// step's, the sort's): for the tests of what a step keeps.
    std::size_t contactRecordRoom() const {
        return contactsNow.capacity() + contactsBefore_.capacity() + contactScratch_.capacity();
    }

private:
    /// Empties the outputs and this step's lists (beginStep and clear).
    void clearStepLists();
    friend struct snapshot::Access; // saves and restores the last step's records
    std::vector<TouchRecord> contactsBefore_, sensorsBefore_;
    /// The sorts' buffers, one for each list (the physical model lists its contacts
    /// sorted, and leaves contactScratch_ empty).
    std::vector<TouchRecord> contactScratch_, sensorScratch_;
    /// The comparisons' notes of the pairs carried over (events.cpp's compare).
    std::vector<CarriedPair> carried_;
    Buckets buckets_;
    /// contactsBefore_ by slot: each slot's run of indices into it (forEachTouchOf).
    mutable std::mutex indexMutex_;
    mutable bool indexed_ = false;
    mutable Buckets touchesBySlot_;
    mutable std::vector<std::uint32_t> touchIndex_;
    void indexTouches() const;
};

/// Records that two bodies touch at the end of this step: `normal` points from `other`
/// towards `body`, `approachSpeed` is how fast they closed, `impulse` how hard they
/// pushed each other (0 where the model does not say). Sets both bodies' touching flags.
void recordContact(WorldState& world, std::uint32_t body, std::uint32_t other, Vec2 normal,
                   float approachSpeed, float impulse);

/// recordContact in two halves (record_touch.hpp), for contacts looked at on several
/// threads: what the pair is, then listing it (on one thread, in order).
struct FoundTouch {
    TouchRecord record;
    TouchingBit flagA, flagB; ///< what each body of the record gets
};

/// Where the two bodies of `record` touch, as they are now (ContactEvent::point).
Vec2 pointOf(const WorldState& world, const TouchRecord& record);

/// Records that `visitor` overlaps `sensor` at the end of this step.
void recordSensor(WorldState& world, std::uint32_t sensor, std::uint32_t visitor);

} // namespace jostle
