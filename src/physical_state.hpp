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
    std::uint32_t ia, ib; ///< solver bodies; a is the body created first
    /// The normal points from b towards a along one axis (0: x, 1: y), with this sign;
    /// the tangent is the other axis, with its own sign (the normal turned a quarter,
    /// (-ny, nx)).
    std::uint8_t axis;
    /// Which body holds the other, staying put in shock propagation and position
    /// correction (orderBySupport says when): 0 none, 1 a, 2 b.
    std::uint8_t supporter = 0;
    float sign, tangentSign;
    float extent; ///< sum of the half extents along the normal
    float slop;   ///< overlap left alone
    float friction;
    float invMassA, invMassB;
    float effectiveMass; ///< 1 / (invMassA + invMassB)
    /// The relative normal velocity must end >= this: 0 to stop, -gap/dt to let a
    /// speculative contact close its gap, -bounce × approach speed to bounce.
    float targetSpeed;
    float normalImpulse = 0.0f; ///< of the sequential impulses: both bodies felt it
    float shockImpulse = 0.0f;  ///< added by shock propagation: the held body felt none
    float tangentImpulse = 0.0f;
    float bounceSpeed = 0.0f;   ///< to remember: bounce at this speed next step
    float approachSpeed = 0.0f; ///< how fast the pair closed when the step began (>= 0)

    Vec2 normal() const { return axis == 0 ? Vec2{sign, 0.0f} : Vec2{0.0f, sign}; }
    /// The normal impulse of the step, what the held body's partner felt.
    float totalImpulse() const { return normalImpulse + shockImpulse; }
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
///
/// Rebuilt in place from this step's contacts, with no second copy: a counting pass
/// (count(a) for each), then a filling pass (add(a, b, contact) for each, same order).
class ContactCache {
public:
    /// Empties the cache.
    void clear();
    const CachedContact* find(std::uint32_t a, std::uint32_t b) const;

    /// Starts a rebuild for a world of `slotCount` slots; the old contents are gone.
    void beginRebuild(std::size_t slotCount);
    /// Counting pass: one more contact whose first body is `a`.
    void count(std::uint32_t a) { ++offsets_[a + 1]; }
    /// Ends the counting pass.
    void endCounting();
    /// Filling pass: the contacts counted, in the same order.
    void add(std::uint32_t a, std::uint32_t b, const CachedContact& contact);
    /// Ends the rebuild.
    void endRebuild();

private:
    struct Entry {
        std::uint32_t b = 0;
        CachedContact contact;
    };
    std::vector<std::uint32_t> offsets_; ///< by slot a: its first entry; size slotCount + 1
    std::vector<Entry> entries_;
};

/// Buffers of the physical step, reused from step to step.
struct PhysicalScratch {
    std::vector<Contact> contacts;
    std::vector<std::uint32_t> destination; ///< where the support sort moves each contact
    std::vector<SolverBody> bodies;
    std::vector<std::uint32_t> solverIndex; ///< by slot
    std::vector<std::uint32_t> levels;      ///< support level by solver body
    std::vector<std::uint8_t> backing; ///< by solver body: sides touching a static or kinematic one
    std::vector<std::uint8_t> sweepFlags; ///< by slot: moves where its contacts did not look
    std::vector<Contact> sweptContacts;   ///< found by the sweeps, not among the step's
    std::vector<std::uint64_t> vetoed;    ///< pairs the pre-solve vetoed this step (sorted keys)
    std::vector<std::uint32_t> offsets, neighbours, fill, queue, counts;
    std::vector<std::uint32_t> parent; ///< union-find of islands, by slot
    std::vector<float> islandTime;
    std::vector<std::uint32_t> islandOf;
};

} // namespace jostle
