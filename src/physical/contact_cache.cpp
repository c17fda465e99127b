// The contact cache, and storing the step's impulses in it.
#include "contact_cache.hpp"

#include "../room.hpp"
#include "step_context.hpp"

#include <algorithm>

namespace jostle {

void ContactCache::clear() {
    runs_.reset(0);
    entries_.clear();
    longRuns_.clear();
}

const CachedContact* ContactCache::find(std::uint32_t a, std::uint32_t b) const {
    if (a >= runs_.keyCount())
        return nullptr;
    const std::uint32_t begin = runs_.begin(a), end = runs_.end(a);
    if (end - begin > kLongRun) {
        const Entry* first = entries_.data() + begin;
        const Entry* last = entries_.data() + end;
        const Entry* found = std::lower_bound(
            first, last, b, [](const Entry& entry, std::uint32_t key) { return entry.b < key; });
        return found != last && found->b == b ? &found->contact : nullptr;
    }
    for (std::uint32_t k = begin; k < end; ++k)
        if (entries_[k].b == b)
            return &entries_[k].contact;
    return nullptr;
}

void ContactCache::endRebuild(TaskRunner& tasks) {
    tasks.forEachBlock(std::uint32_t(longRuns_.size()), 1, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const std::uint32_t a = longRuns_[k];
            // By the other slot, a pair's contacts in the step's order: the first is found.
            std::sort(entries_.data() + runs_.begin(a), entries_.data() + runs_.end(a),
                      [](const Entry& x, const Entry& y) {
                          return x.b != y.b ? x.b < y.b : x.rank < y.rank;
                      });
        }
    });
}

void storeImpulses(StepContext& step) {
    WorldState& w = step.world;
    ContactCache& cache = w.contactCache;
    const auto count = std::uint32_t(step.contacts.size());
    std::vector<std::uint32_t>& ranks = step.scratch.store.ranks;
    resizeAnewToFit(ranks, count);
    cache.beginRebuild(w.slots.size());
    for (std::uint32_t k = 0; k < count; ++k)
        ranks[k] = cache.count(step.bodies[step.contacts[k].ia].slot);
    cache.endCounting();
    // The cache takes contacts in any order; each body's separation adds up its contacts'
    // pushes in contact order, which the solver's layers keep.
    forEachContact(step, [&](const Contact& c) {
        const auto k = std::uint32_t(&c - step.contacts.data());
        const std::uint32_t slotA = step.bodies[c.ia].slot, slotB = step.bodies[c.ib].slot;
        Body& a = w.slots[slotA];
        Body& b = w.slots[slotB];
        // What held a touching pair together starts the next step; what closed a gap was a
        // blow, not a push that goes on.
        const bool closing = c.targetSpeed < 0.0f;
        cache.add(slotA, ranks[k], slotB, k,
                  {a.generation, b.generation, c.normal(), closing ? 0.0f : c.normalImpulse,
                   closing ? 0.0f : c.tangentImpulse});
        // How far the contact's impulse pushed each body out this step (position
        // correction was counted when it was written back); the held body felt none of the
        // shock pass's. An infinitely heavy body is pushed nowhere (its separation stays 0),
        // and may be in several contacts of a layer at once.
        const float total = c.totalImpulse();
        if (step.invMassA(c) > 0.0f)
            a.separation += c.normal() * ((c.supporter == 1 ? c.normalImpulse : total) *
                                          step.invMassA(c) * step.dt);
        if (step.invMassB(c) > 0.0f)
            b.separation -= c.normal() * ((c.supporter == 2 ? c.normalImpulse : total) *
                                          step.invMassB(c) * step.dt);
    });
    cache.endRebuild(*w.tasks);
}

} // namespace jostle
