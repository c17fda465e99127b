// The contact cache: what the physical model remembers of a contact from one step to the
// next (its impulses, to warm start the solver; a pending bounce), and the stage that
// stores it, with each body's separation.
#pragma once

#include "../counting_sort.hpp"
#include "../room.hpp"
#include "../tasks.hpp"
#include "jostle/math.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;
namespace snapshot {
struct Access;
}

/// A contact as the next step finds it.
struct CachedContact {
    std::uint32_t generationA = 0;
    std::uint32_t generationB = 0;
    Vec2 normal;
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
};

/// Last step's contacts, looked up by the pair's slots. Stored grouped by the first
/// slot (a counting sort, rebuilt every step), so a lookup scans the few contacts of one
/// body, and lookups in creation order walk the table front to back. A body with many
/// contacts (a floor under a crowd) has its run sorted by the other slot and searched by
/// halves. Nothing of its layout leaks into results: a lookup finds the first of the
/// step's contacts of the pair, however the runs lie, and the events walk it only to list
/// the touching contacts by first body, then sort each body's by the other.
///
/// Rebuilt in place from this step's contacts, with no second copy: a counting pass
/// (count(a) for each, in order, giving each its rank), a filling pass (add for each, in
/// any order, on any thread), then endRebuild.
class ContactCache {
public:
    /// Empties the cache.
    void clear();
    const CachedContact* find(std::uint32_t a, std::uint32_t b) const;
    /// Asks the memory for what find(a, ...) will read first: for loops that know their
    /// lookups a little ahead.
    void prefetch(std::uint32_t a) const {
        if (a < runs_.keyCount())
            __builtin_prefetch(&entries_.data()[runs_.begin(a)]);
    }

    /// Visits every entry, visit(a, b, contact): for the fuzzers' checks of a restored
    /// cache, never for a step's results.
    template <class Visit> void forEachEntry(Visit&& visit) const {
        for (std::uint32_t a = 0; a < runs_.keyCount(); ++a)
            for (std::uint32_t k = runs_.begin(a); k < runs_.end(a); ++k)
                visit(a, entries_[k].b, entries_[k].contact);
    }

    /// Starts a rebuild for a world of `slotCount` slots; the old contents are gone.
    void beginRebuild(std::size_t slotCount) {
        runs_.reset(slotCount);
        longRuns_.clear();
    }
    /// Counting pass: one more contact whose first body is `a`. Returns its rank among
    /// them, for add().
    std::uint32_t count(std::uint32_t a) {
        const std::uint32_t rank = runs_.count(a);
        if (rank == kLongRun)
            longRuns_.push_back(a);
        return rank;
    }
    /// Ends the counting pass.
    void endCounting() { resizeAnewToFit(entries_, runs_.endCounting()); }
    /// Filling pass: the contact of rank `rank` among those of `a`. Contacts of different
    /// ranks may be added at once on several threads.
    /// `k` is the contact's index in the step's list (stepContactAt).
    void add(std::uint32_t a, std::uint32_t rank, std::uint32_t b, std::uint32_t k,
             const CachedContact& contact) {
        entries_[runs_.begin(a) + rank] = {b, rank, k, contact};
    }
    /// After a rebuild, the step's contacts in the cache's order: the entries' places
    /// [0, size()), each holding the index of the step's contact it came from
    /// (stepContactAt), in runs by the first slot: forEachRun(visit(begin, end, sortedByB))
    /// in slot order, a run in the step's order, or by the other slot where sortedByB.
    std::uint32_t size() const { return std::uint32_t(entries_.size()); }
    std::uint32_t stepContactAt(std::uint32_t place) const { return entries_[place].stepContact; }
    template <class Visit> void forEachRun(Visit&& visit) const {
        for (std::uint32_t a = 0; a < runs_.keyCount(); ++a) {
            const std::uint32_t begin = runs_.begin(a), end = runs_.end(a);
            if (begin != end)
                visit(begin, end, end - begin > kLongRun);
        }
    }
    /// Ends the rebuild: sorts the long runs, on `tasks`' workers.
    void endRebuild(TaskRunner& tasks);

private:
    friend struct snapshot::Access; // saves and restores the entries as they lie
    /// Runs longer than this are sorted and searched by halves.
    static constexpr std::uint32_t kLongRun = 16;
    struct Entry {
        std::uint32_t b = 0;
        std::uint32_t rank = 0;        ///< in the run as counted: the step's order of its contacts
        std::uint32_t stepContact = 0; ///< its index in the step's contacts
        CachedContact contact;
    };
    Buckets runs_; ///< by slot a: its entries
    std::vector<Entry> entries_;
    std::vector<std::uint32_t> longRuns_; ///< the slots whose runs are longer than kLongRun
};

/// Stage: store impulses. Rebuilds the world's contact cache from step.contacts, and adds
/// to each body's separation how far its contacts' impulses pushed it.
void storeImpulses(StepContext& step);

/// storeImpulses' scratch: each contact's rank in the cache (ContactCache::count).
struct StoreScratch {
    std::vector<std::uint32_t> ranks;
};

} // namespace jostle
