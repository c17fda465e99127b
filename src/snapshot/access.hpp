// The parts of a snapshot that lie inside classes (the contact cache, the last step's
// records, a tile map's list of bodies): Access, their friend, saves and restores them as
// they lie (archive.hpp's two directions, as in world_archive.cpp).
#pragma once

#include "../events.hpp"
#include "../physical/contact_cache.hpp"
#include "../tilemap.hpp"
#include "../world_state.hpp"
#include "values.hpp"

#include <cmath>

namespace jostle::snapshot {

struct Access {
    /// The cache's runs (the entries of each first slot), then its entries as they lie. A
    /// short run lies in rank order, so only a long run's entries say their rank.
    template <class Ar> static void contactCache(Ar& ar, ContactCache& cache, std::uint32_t slots) {
        std::uint32_t keys = static_cast<std::uint32_t>(cache.runs_.keyCount());
        ar.var(keys);
        ar.check(keys <= slots, "the contact cache's slots");
        std::uint32_t count = static_cast<std::uint32_t>(cache.entries_.size());
        ar.count(count, 8);
        std::uint32_t runs = 0;
        if constexpr (!Ar::kReading)
            for (std::uint32_t key = 0; key < keys; ++key)
                runs += cache.runs_.end(key) > cache.runs_.begin(key) ? 1 : 0;
        ar.count(runs, 2);
        if constexpr (Ar::kReading) {
            cache.beginRebuild(keys);
            cache.entries_.resize(count);
        }
        // Each run: the gap from the last run's slot (or from 0), and its length.
        std::uint32_t key = 0, counted = 0;
        for (std::uint32_t r = 0; r < runs; ++r) {
            std::uint32_t gap = 0, length = 0;
            if constexpr (!Ar::kReading) {
                const std::uint32_t from = r == 0 ? 0 : key + 1;
                for (key = from; cache.runs_.end(key) == cache.runs_.begin(key); ++key) {
                }
                gap = key - from;
                length = cache.runs_.end(key) - cache.runs_.begin(key);
            }
            ar.var(gap);
            ar.var(length);
            if constexpr (Ar::kReading) {
                const std::uint64_t at = (r == 0 ? 0 : std::uint64_t{key} + 1) + gap;
                ar.check(at < keys && length > 0 && length <= count - counted,
                         "the contact cache's runs");
                key = static_cast<std::uint32_t>(at);
                counted += length;
                for (std::uint32_t k = 0; k < length; ++k)
                    cache.runs_.count(key);
            }
        }
        if constexpr (Ar::kReading) {
            ar.check(counted == count, "the contact cache's runs");
            cache.runs_.endCounting();
        }
        for (std::uint32_t run = 0, k = 0; run < keys && k < count; ++run) {
            const std::uint32_t begin = cache.runs_.begin(run), end = cache.runs_.end(run);
            const bool ranked = end - begin > ContactCache::kLongRun;
            for (k = begin; k < end; ++k) {
                ContactCache::Entry& entry = cache.entries_[k];
                // At most 5 × 4 + 9 + 8 bytes.
                ar.template record<40>([&](auto& out) JOSTLE_RECORD_INLINE {
                    out.var(entry.b);
                    if (ranked)
                        out.var(entry.rank);
                    else
                        entry.rank = k - begin;
                    out.var(entry.contact.generationA);
                    out.var(entry.contact.generationB);
                    normal(out, entry.contact.normal);
                    out.f32(entry.contact.normalImpulse);
                    out.f32(entry.contact.tangentImpulse);
                });
                // A normal impulse only pushes: a step never keeps a negative one.
                ar.check(std::isfinite(entry.contact.normalImpulse) &&
                             entry.contact.normalImpulse >= 0.0f &&
                             std::isfinite(entry.contact.tangentImpulse),
                         "a cached contact's impulses");
                // A long run lies by the other slot, then rank.
                if constexpr (Ar::kReading)
                    ar.check(!ranked || (entry.rank < end - begin &&
                                         (k == begin || cache.entries_[k - 1].b < entry.b ||
                                          (cache.entries_[k - 1].b == entry.b &&
                                           cache.entries_[k - 1].rank < entry.rank))),
                             "the contact cache's order");
            }
        }
    }

    template <class Ar>
    static void records(Ar& ar, std::vector<TouchRecord>& list, std::uint32_t slots) {
        std::uint32_t count = static_cast<std::uint32_t>(list.size());
        ar.count(count, 8);
        if constexpr (Ar::kReading)
            list.resize(count);
        for (std::uint32_t k = 0; k < count; ++k) {
            TouchRecord& r = list[k];
            // At most 4 × 5 + 9 + 8 bytes.
            ar.template record<48>([&](auto& out) JOSTLE_RECORD_INLINE {
                ref(out, r.a, slots);
                ref(out, r.b, slots);
                normal(out, r.normal);
                out.f32(r.approachSpeed);
                out.f32(r.impulse);
            });
            ar.check(std::isfinite(r.approachSpeed) && std::isfinite(r.impulse) &&
                         (k == 0 || list[k - 1].key() <= r.key()),
                     "the last step's touching pairs");
        }
    }

    template <class Ar> static void events(Ar& ar, WorldState& w) {
        const std::uint32_t slots = static_cast<std::uint32_t>(w.slots.size());
        records(ar, w.events.contactsBefore_, slots);
        records(ar, w.events.sensorsBefore_, slots);
        sequence(ar, w.events.crushing, 6, [&](CrushEvent& crush) {
            for (BodyId* id : {&crush.body, &crush.by, &crush.against})
                handle(ar, *id, w.serial, slots);
        });
        sequence(ar, w.forces, 10, [&](std::pair<BodyId, Vec2>& applied) {
            handle(ar, applied.first, w.serial, slots);
            ar.vec(applied.second);
            ar.check(isFinite(applied.second), "a force");
        });
    }

    template <class Ar>
    static void listedBodies(Ar& ar, ListedBodies& list, std::uint32_t serial,
                             std::uint32_t slots) {
        const std::size_t live = list.live().size(); // closes the gaps
        std::uint32_t count = static_cast<std::uint32_t>(live);
        ar.count(count, 3);
        std::uint32_t tickets = static_cast<std::uint32_t>(list.positions_.size());
        ar.var(tickets);
        if constexpr (Ar::kReading) {
            // Each ticket is a body's or free, and each free one takes a byte of its list.
            ar.check(count <= tickets && tickets - count <= ar.left(), "a tile map's bodies");
            list.entries_.resize(count);
            list.tickets_.resize(count);
            list.positions_.assign(tickets, UINT32_MAX);
        }
        for (std::uint32_t k = 0; k < count; ++k) {
            handle(ar, list.entries_[k], serial, slots);
            ar.var(list.tickets_[k]);
            if constexpr (Ar::kReading) {
                const std::uint32_t ticket = list.tickets_[k];
                ar.check(!list.entries_[k].isNull() && ticket < tickets &&
                             list.positions_[ticket] == UINT32_MAX,
                         "a tile map's bodies");
                list.positions_[ticket] = k;
            }
        }
        MetOnce<Ar> free(tickets);
        slotList(ar, list.freeTickets_, tickets, [&](std::uint32_t ticket) {
            ar.check(list.positions_[ticket] == UINT32_MAX && free.first(ticket),
                     "a tile map's free tickets");
        });
        ar.check(tickets == count + list.freeTickets_.size(), "a tile map's free tickets");
    }
};

} // namespace jostle::snapshot
