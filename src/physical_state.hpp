// The physical model's working data: solver bodies, contacts, the contact cache, and
// the buffers a step reuses (kept in the world so that a step allocates nothing once
// the world has reached its size).
#pragma once

#include "jostle/math.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

/// What the solver passes need of a body, packed together so that the passes over
/// thousands of contacts read few cache lines.
struct SolverBody {
    float velocity[2]; ///< x, y: indexed by a contact's axis
    float position[2];
    float invMass;
    std::uint32_t slot;
};

struct Contact {
    std::uint32_t a, b;   ///< slots
    std::uint32_t ia, ib; ///< solver bodies
    Vec2 normal;          ///< unit, along x or y, pointing from b towards a
    /// The normal as the passes use it: the axis (0: x, 1: y) and its sign; the tangent
    /// is the other axis, with its own sign (the normal turned a quarter, (-ny, nx)).
    int axis;
    float sign, tangentSign;
    float extent; ///< sum of the half extents along the normal
    float slop;   ///< overlap left alone
    float friction;
    float invMassA, invMassB;
    float effectiveMass; ///< 1 / (invMassA + invMassB)
    /// The relative normal velocity must end >= this: 0 to stop, -gap/dt to let a
    /// speculative contact close its gap, -bounce × approach speed to bounce.
    float targetSpeed;
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    float bounceSpeed = 0.0f; ///< to remember: bounce at this speed next step
    /// Which body is held fixed across support levels: 0 none, 1 a, 2 b.
    int supporter = 0;
    std::uint32_t level = 0;  ///< the lower support level of the two
    float correctionA = 0.0f; ///< distance moved out by position correction, for separation()
    float correctionB = 0.0f;
};

/// What the physical model remembers of a contact from one step to the next, to start
/// its solver from last step's impulses (warm starting).
struct CachedContact {
    std::uint32_t generationA = 0;
    std::uint32_t generationB = 0;
    Vec2 normal;
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    /// A pair that met this step within a speculative gap bounces on the next step, from
    /// the surface, at this relative speed (0: no bounce).
    float bounceSpeed = 0.0f;
};

/// Last step's contacts, looked up by the pair's slots. Stored grouped by the first
/// slot (a counting sort, rebuilt every step), so a lookup scans the few contacts of one
/// body, and lookups in creation order walk the table front to back. Never iterated for
/// results, so nothing of its layout can leak into them.
class ContactCache {
public:
    /// Empties the cache.
    void clear();
    /// Stages one contact of this step; commit() makes the staged contacts the cache.
    void stage(std::uint32_t a, std::uint32_t b, const CachedContact& contact);
    /// Replaces the cache with the staged contacts, for a world of `slotCount` slots.
    void commit(std::size_t slotCount);
    const CachedContact* find(std::uint32_t a, std::uint32_t b) const;

private:
    struct Entry {
        std::uint32_t a = 0, b = 0;
        CachedContact contact;
    };
    std::vector<std::uint32_t> offsets_; ///< by slot a: its first entry; size slotCount + 1
    std::vector<Entry> entries_;
    std::vector<Entry> staged_;
};

/// Buffers of the physical step, reused from step to step.
struct PhysicalScratch {
    std::vector<Contact> contacts, sorted;
    std::vector<SolverBody> bodies;
    std::vector<std::uint32_t> solverIndex; ///< by slot
    std::vector<std::uint32_t> levels;      ///< support level by solver body
    std::vector<std::uint32_t> offsets, neighbours, fill, queue, counts;
    std::vector<std::uint32_t> parent; ///< union-find of islands, by slot
    std::vector<float> islandTime;
    std::vector<std::uint32_t> islandOf;
};

} // namespace jostle
