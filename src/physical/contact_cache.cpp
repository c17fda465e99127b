// The contact cache, and storing the step's impulses in it.
#include "contact_cache.hpp"

#include "step_context.hpp"

namespace jostle {

void ContactCache::clear() {
    runs_.reset(0);
    entries_.clear();
}

const CachedContact* ContactCache::find(std::uint32_t a, std::uint32_t b) const {
    if (a >= runs_.keyCount())
        return nullptr;
    for (std::uint32_t k = runs_.begin(a); k < runs_.end(a); ++k)
        if (entries_[k].b == b)
            return &entries_[k].contact;
    return nullptr;
}

void storeImpulses(StepContext& step) {
    WorldState& w = step.world;
    ContactCache& cache = w.contactCache;
    cache.beginRebuild(w.slots.size());
    for (const Contact& c : step.contacts)
        cache.count(step.bodies[c.ia].slot);
    cache.endCounting();
    for (const Contact& c : step.contacts) {
        const std::uint32_t slotA = step.bodies[c.ia].slot, slotB = step.bodies[c.ib].slot;
        Body& a = w.slots[slotA];
        Body& b = w.slots[slotB];
        const float total = c.totalImpulse();
        // What held a touching pair together starts the next step; what closed a gap was a
        // blow, not a push that goes on.
        const bool closing = c.targetSpeed < 0.0f;
        cache.add(slotA, slotB,
                  {a.generation, b.generation, c.normal(), closing ? 0.0f : c.normalImpulse,
                   closing ? 0.0f : c.tangentImpulse});
        // How far the contact's impulse pushed each body out this step (position
        // correction was counted when it was written back); the held body felt none of the
        // shock pass's.
        const float dt = step.dt;
        a.separation +=
            c.normal() * ((c.supporter == 1 ? c.normalImpulse : total) * c.invMassA * dt);
        b.separation -=
            c.normal() * ((c.supporter == 2 ? c.normalImpulse : total) * c.invMassB * dt);
    }
    cache.endRebuild();
}

} // namespace jostle
