// A world's payload, described once for both directions (archive.hpp): each archive
// function below writes with a Writer and reads, checking, with a Reader. The sections
// come in this order, each opened by its letter: W the settings, S the slots, B the
// bodies, I the sleeping islands, C the contact cache, E the last step's records, M the
// tile maps. docs/snapshots.md lists the fields.
#include "world_archive.hpp"

#include "../body_properties.hpp"
#include "../physical/contact_cache.hpp"
#include "../tile_chars.hpp"
#include "../world_options.hpp"
#include "../world_state.hpp"
#include "access.hpp"
#include "body_codec.hpp"
#include "maps_archive.hpp"
#include "values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

namespace jostle::snapshot {

namespace {

template <class Ar> void section(Ar& ar, char letter) {
    std::uint8_t tag = static_cast<std::uint8_t>(letter);
    ar.u8(tag);
    ar.checkOr(tag == static_cast<std::uint8_t>(letter),
               [&] { return std::string("section ") + letter + " is not where it belongs"; });
}

// --- W: the world's settings, from the tables of world_options.hpp ------------------------

template <class Ar, class Def, class F, std::size_t N>
void settings(Ar& ar, Def& def, const F (&fields)[N]) {
    for (const F& field : fields)
        std::visit([&](auto member) { value(ar, def.*member); }, field.member);
}

template <class Ar> void worldSettings(Ar& ar, WorldState& w) {
    settings(ar, w.def, properties::kWorldFields);
    settings(ar, w.def.classic, properties::kClassicFields);
    settings(ar, w.def.physical, properties::kPhysicalFields);
    if constexpr (Ar::kReading) {
        const std::optional<FieldError> problem = checkWorldDef(w.def);
        ar.checkOr(!problem, [&] { return "world." + problem->field + ": " + problem->problem; });
    }
    ar.vec(w.events.down);
    ar.check(isFinite(w.events.down) && std::abs(dot(w.events.down, w.events.down) - 1.0f) <= 1e-5f,
             "the world's down");
    ar.flag(w.events.destroyedSincePublish);
    ar.var(w.bodiesCreated);
}

// --- S: the slots: generations, which hold a body, which are free, which moved ------------

template <class Ar> void slotTable(Ar& ar, WorldState& w) {
    std::uint32_t slotCount = static_cast<std::uint32_t>(w.slots.size());
    ar.count(slotCount, 1);
    if constexpr (Ar::kReading) {
        // Copies of one made Body: a copy is a few wide moves, making each a zeroing and
        // its defaults.
        w.slots.assign(slotCount, Body{});
        w.created.resize(slotCount);
        w.shapes.resize(slotCount);
        w.asGiven.resize(slotCount);
    }
    for (Body& slot : w.slots) {
        std::uint64_t word = std::uint64_t{slot.generation} << 1 | (slot.alive ? 1 : 0);
        ar.var(word);
        if constexpr (Ar::kReading) {
            slot.generation = static_cast<std::uint32_t>(word >> 1);
            slot.alive = (word & 1) != 0;
            ar.check(slot.generation != 0 && word >> 1 <= UINT32_MAX, "a slot's generation");
        }
    }
    MetOnce<Ar> free(slotCount);
    slotList(ar, w.freeSlots, slotCount, [&](std::uint32_t slot) {
        ar.check(!w.slots[slot].alive && w.slots[slot].generation != UINT32_MAX && free.first(slot),
                 "the free slots");
    });
    slotList(ar, w.movingSlots, slotCount, [](std::uint32_t) {});
    std::uint32_t flags = static_cast<std::uint32_t>(w.events.touching.size());
    ar.count(flags, 1);
    ar.check(flags <= slotCount, "the touching flags");
    if constexpr (Ar::kReading)
        w.events.touching.resize(flags);
    for (std::uint8_t& bits : w.events.touching)
        ar.u8(bits);
}

// --- B: the live bodies, in creation order ------------------------------------------------

/// A body's flags byte: asleep, and settings that are the body before it's.
enum BodyFlags : std::uint8_t { kAsleep = 1, kSettingsAsBefore = 2 };

/// Whether a body's position and velocity pass their rows, a static body's velocity being
/// zero: what a body whose other settings are the body before it's (checked already) needs
/// for checkBodyDef to pass. A quick test: where it fails, checkBodyDef gives the verdict.
bool motionPasses(const Body& body) {
    using namespace properties;
    constexpr std::size_t x = find(kBodyFields, kX) - kBodyFields;
    constexpr std::size_t y = find(kBodyFields, kY) - kBodyFields;
    constexpr std::size_t vx = find(kBodyFields, kVx) - kBodyFields;
    constexpr std::size_t vy = find(kBodyFields, kVy) - kBodyFields;
    BodyDef def;
    def.x = body.position.x;
    def.y = body.position.y;
    def.vx = body.velocity.x;
    def.vy = body.velocity.y;
    return passes<kBodyFields, x>(def) && passes<kBodyFields, y>(def) &&
           passes<kBodyFields, vx>(def) && passes<kBodyFields, vy>(def) &&
           (body.type != BodyType::Static || body.velocity == Vec2{});
}

/// A body read back: its settings checked as createBody checks them (those the body before
/// it had, its motion only), the rest in range.
void checkBody(Reader& ar, const WorldState& w, std::uint32_t slot, std::size_t index,
               bool settingsAsBefore) {
    const properties::ConstPlaces places{w.slots[slot], w.asGiven[slot], w.shapes[slot]};
    if (!settingsAsBefore || !motionPasses(places.body)) {
        const std::optional<FieldError> problem = checkBodyDef(properties::definitionOf(places));
        ar.checkOr(!problem, [&] {
            return "bodies[" + std::to_string(index) + "]." + problem->field + ": " +
                   problem->problem;
        });
    }
    const Body& body = places.body;
    bool finite = true;
    for (float Body::*number : kRunTimeNumbers)
        finite = finite && std::isfinite(body.*number);
    for (Vec2 Body::*vector : kRunTimeVectors)
        finite = finite && isFinite(body.*vector);
    ar.checkOr(finite && body.sleepTime >= 0.0f && body.dropThroughTime >= 0.0f &&
                   std::abs(body.floorCos) <= 1.0f,
               [&] { return "bodies[" + std::to_string(index) + "]: its state is out of range"; });
    ar.checkOr(!(w.def.solver == Solver::Classic && places.shape.kind() != ShapeKind::Box), [&] {
        return "bodies[" + std::to_string(index) + "]: not a box in the classic model";
    });
}

/// A reader's body in `slot` before its fields are read: the defaults, or the settings of
/// the body in `before` with the state's defaults.
void startBody(WorldState& w, std::uint32_t slot, std::uint32_t before, bool settingsAsBefore) {
    const DefaultPlaces& defaults = defaultPlaces();
    const std::uint32_t generation = w.slots[slot].generation;
    Body& body = w.slots[slot];
    if (settingsAsBefore) {
        body = w.slots[before];
        w.asGiven[slot] = w.asGiven[before];
        w.shapes[slot] = w.shapes[before];
        // The state group's defaults (body_codec.hpp): velocity and the run-time state.
        body.velocity = defaults.body.velocity;
        for (float Body::*number : kRunTimeNumbers)
            body.*number = defaults.body.*number;
        for (Vec2 Body::*vector : kRunTimeVectors)
            body.*vector = defaults.body.*vector;
        body.island = 0;
    } else {
        body = defaults.body;
        w.asGiven[slot] = defaults.kept;
        w.shapes[slot] = defaults.shape;
    }
    body.generation = generation;
    body.alive = true;
}

template <class Ar> void bodies(Ar& ar, WorldState& w) {
    std::span<const BodyId> live = w.order.live();
    std::uint32_t count = static_cast<std::uint32_t>(live.size());
    ar.count(count, 12); // at least a slot, a gap, the flags, a position and the state's bits
    std::uint64_t lastCreated = 0;
    std::uint32_t lastSlot = 0;
    MetOnce<Ar> read(w.slots.size());
    for (std::uint32_t k = 0; k < count; ++k) {
        std::uint32_t slot = 0;
        if constexpr (!Ar::kReading)
            slot = live[k].index;
        ar.var(slot);
        ar.check(slot < w.slots.size() && w.slots[slot].alive, "a body's slot");
        if constexpr (Ar::kReading)
            ar.check(read.first(slot), "a body's slot is listed twice");
        Body& body = w.slots[slot];
        const properties::Places places{body, w.asGiven[slot], w.shapes[slot]};
        const PlaceBytes bytes(places);
        std::uint8_t flags = 0;
        // Its longest: some 170 bytes.
        ar.template record<256>([&](auto& out) JOSTLE_RECORD_INLINE {
            // Its creation number, as the gap after the body before it's.
            std::uint64_t gap = k == 0 ? w.created[slot] : w.created[slot] - lastCreated - 1;
            out.var(gap);
            if constexpr (!Ar::kReading) {
                const bool asBefore =
                    k > 0 && SettingsBytes::get().same(
                                 bytes, PlaceBytes({w.slots[lastSlot], w.asGiven[lastSlot],
                                                    w.shapes[lastSlot]}));
                flags = static_cast<std::uint8_t>((body.asleep ? kAsleep : 0) |
                                                  (asBefore ? kSettingsAsBefore : 0));
            }
            out.u8(flags);
            if constexpr (Ar::kReading) {
                ar.check(flags <= (kAsleep | kSettingsAsBefore) &&
                             (k > 0 || (flags & kSettingsAsBefore) == 0) &&
                             gap < w.bodiesCreated - (k == 0 ? 0 : lastCreated + 1),
                         "a body's flags, or the bodies' creation order");
                w.created[slot] = k == 0 ? gap : lastCreated + 1 + gap;
                startBody(w, slot, lastSlot, (flags & kSettingsAsBefore) != 0);
                body.asleep = (flags & kAsleep) != 0;
            }
            if ((flags & kSettingsAsBefore) == 0)
                groupFields(out, bytes, FieldCodec::Settings);
            out.vec(body.position);
            groupFields(out, bytes, FieldCodec::State);
            if (body.asleep)
                out.var(body.island);
        });
        lastCreated = w.created[slot];
        lastSlot = slot;
        if constexpr (Ar::kReading) {
            checkBody(ar, w, slot, k, (flags & kSettingsAsBefore) != 0);
            body.shape = places.shape.kind();
            body.updateMass(places.kept.density);
            w.order.append(w.idOf(slot));
            w.count(slot, true);
        }
    }
    if constexpr (Ar::kReading) {
        std::size_t alive = 0;
        for (const Body& slot : w.slots)
            alive += slot.alive ? 1 : 0;
        ar.check(alive == w.order.size(), "a live slot has no body, or one has two");
    }
}

// --- I: sleeping islands ------------------------------------------------------------------

template <class Ar> void islands(Ar& ar, WorldState& w) {
    std::uint32_t count = static_cast<std::uint32_t>(w.islands.size());
    ar.count(count, 1);
    if constexpr (Ar::kReading)
        w.islands.resize(count);
    // Each sleeping body is listed once, in the island it names: waking an island must
    // wake every body that names it (the pair search goes round until nobody sleeps in
    // its way).
    MetOnce<Ar> listed(w.slots.size());
    for (std::uint32_t i = 0; i < count; ++i)
        slotList(ar, w.islands[i], static_cast<std::uint32_t>(w.slots.size()),
                 [&](std::uint32_t slot) {
                     const Body& body = w.slots[slot];
                     ar.check(body.alive && body.asleep && body.island == i && listed.first(slot),
                              "an island's bodies");
                 });
    MetOnce<Ar> free(count);
    slotList(ar, w.freeIslands, count, [&](std::uint32_t island) {
        ar.check(w.islands[island].empty() && free.first(island), "the free islands");
    });
    if constexpr (Ar::kReading)
        for (BodyId id : w.order.live())
            ar.check(!w.slots[id.index].asleep || listed.met(id.index), "a sleeping body's island");
}

} // namespace

namespace {

template <class Ar> void world(Ar& ar, WorldState& w) {
    section(ar, 'W');
    worldSettings(ar, w);
    section(ar, 'S');
    slotTable(ar, w);
    section(ar, 'B');
    bodies(ar, w);
    section(ar, 'I');
    islands(ar, w);
    section(ar, 'C');
    Access::contactCache(ar, w.contactCache, static_cast<std::uint32_t>(w.slots.size()));
    section(ar, 'E');
    Access::events(ar, w);
    section(ar, 'M');
    tileMaps(ar, w);
}

// A writer only reads the world: the one function serves both directions, hence non-const.
WorldState& forWriting(const WorldState& w) {
    return const_cast<WorldState&>(w);
}

} // namespace

std::size_t payloadSize(const WorldState& w) {
    ChunkSink<ByteCount> sink;
    Writer<Sink> ar(sink);
    world(ar, forWriting(w));
    return sink.taken().size;
}

std::optional<std::size_t> writePayload(const WorldState& w, std::span<std::uint8_t> out) {
    BufferSink sink(out.data(), out.data() + out.size());
    Writer<Sink> ar(sink);
    world(ar, forWriting(w));
    if (sink.overflowed())
        return std::nullopt;
    return sink.written();
}

std::uint64_t payloadHash(const WorldState& w) {
    ChunkSink<XxHash64> sink;
    Writer<Sink> ar(sink);
    world(ar, forWriting(w));
    return sink.taken().digest();
}

void readPayload(std::span<const std::uint8_t> payload, WorldState& into) {
    Reader ar(payload);
    world(ar, into);
    ar.check(ar.left() == 0, "bytes after the end of the snapshot");
}

} // namespace jostle::snapshot
