// What every stage of the physical step works on (step.cpp lists the stages): the world,
// the step's scratch buffers, dt and the options; and the few measures of a contact that
// several stages share.
#pragma once

#include "../room.hpp"
#include "../world_state.hpp"
#include "scratch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace jostle {

struct StepContext {
    StepContext(WorldState& w, float stepDt)
        : world(w), scratch(*w.physical), options(w.def.physical), dt(stepDt),
          bodies(w.physical->bodies), contacts(w.physical->contacts),
          noisePerSlop_(options.slop > 0.0f ? kMinimumSkin / options.slop : 0.0f) {}

    WorldState& world;
    PhysicalScratch& scratch;
    const PhysicalOptions options; ///< a copy: a callback may change the world's
    const float dt;
    /// Solver bodies and contacts of the step (scratch.bodies, scratch.contacts).
    std::vector<SolverBody>& bodies;
    std::vector<Contact>& contacts;

    static constexpr std::uint32_t kNoSolverBody = UINT32_MAX;
    /// The solver body of a body, made on first use. A body a callback created during the
    /// step may be met too (a sweep meets a static body made in its way).
    std::uint32_t solverBodyOf(std::uint32_t slot) {
        if (slot >= scratch.solverIndex.size())
            scratch.solverIndex.resize(world.slots.size(), kNoSolverBody);
        std::uint32_t& index = scratch.solverIndex[slot];
        if (index == kNoSolverBody) {
            const Body& body = world.slots[slot];
            index = std::uint32_t(bodies.size());
            makeRoom(bodies, bodies.size() + 1);
            bodies.push_back({{body.velocity.x, body.velocity.y},
                              {body.position.x, body.position.y},
                              body.invMass,
                              slot});
        }
        return index;
    }

    /// The overlap of contact `c` left alone (WorldOptions::slop of the smaller body).
    float slopOf(const Contact& c) const { return options.slop * c.size; }

    /// The contact skin of two half extents along one axis (geometry.hpp's contactSkin).
    float skinOf(float halfA, float halfB) const { return contactSkin(options.slop, halfA, halfB); }

    /// How deep the pair of contact `c` overlaps along its normal where the solver bodies
    /// are now (negative: the gap between them).
    float overlapOf(const Contact& c) const {
        if (c.axis == kAlongSlope)
            return c.extent - dot(positionOf(c.ia) - positionOf(c.ib), c.n);
        return c.extent -
               c.sign() * (bodies[c.ia].position[c.axis] - bodies[c.ib].position[c.axis]);
    }

    /// The inverse masses of the two bodies of `c`, and its effective mass.
    float invMassA(const Contact& c) const { return bodies[c.ia].invMass; }
    float invMassB(const Contact& c) const { return bodies[c.ib].invMass; }
    float effectiveMassOf(const Contact& c) const { return 1.0f / (invMassA(c) + invMassB(c)); }

    /// Who gives way when the pair of `c` is moved apart (position correction, a bounce
    /// taken back by settleBounces): the body that holds the other stays put, and the other takes
    /// the whole move; where neither holds, the two share it by inverse mass. a's share,
    /// then b's.
    float shareOfA(const Contact& c) const {
        return c.supporter == 1   ? 0.0f
               : c.supporter == 2 ? (invMassA(c) > 0.0f ? 1.0f : 0.0f)
                                  : invMassA(c) * effectiveMassOf(c);
    }
    float shareOfB(const Contact& c) const {
        return c.supporter == 2   ? 0.0f
               : c.supporter == 1 ? (invMassB(c) > 0.0f ? 1.0f : 0.0f)
                                  : invMassB(c) * effectiveMassOf(c);
    }

    /// An approach slower than this does not bounce: gravity alone hands a resting body
    /// about g dt each step.
    float restitutionThreshold() const {
        if (options.restitutionThreshold > 0.0f)
            return options.restitutionThreshold;
        return 2.0f * length(world.def.gravity) * dt;
    }

    /// Across gravity, to the right of "down": where a character's positive walk goes.
    Vec2 right() const {
        const Vec2 down = world.events.down;
        return {down.y, -down.x};
    }

    Vec2 positionOf(std::uint32_t solverBody) const {
        return {bodies[solverBody].position[0], bodies[solverBody].position[1]};
    }
    Vec2 velocityOf(std::uint32_t solverBody) const {
        return {bodies[solverBody].velocity[0], bodies[solverBody].velocity[1]};
    }

    /// Float noise in the overlap of `c` where the solver bodies are now: kMinimumSkin of
    /// the smaller half extent along the normal, and four float steps at the pair's
    /// coordinates. Overlap within the slop and this is within the slop.
    float noiseOf(const Contact& c) const {
        if (c.axis == kAlongSlope) {
            const Vec2 pa = positionOf(c.ia), pb = positionOf(c.ib);
            const float largest = std::max({std::abs(pa.x), std::abs(pa.y), std::abs(pb.x),
                                            std::abs(pb.y), std::abs(c.extent)});
            return slopOf(c) * noisePerSlop_ + 4.0f * ulpOf(largest);
        }
        const float pa = bodies[c.ia].position[c.axis], pb = bodies[c.ib].position[c.axis];
        const float largest = std::max({std::abs(pa), std::abs(pb), c.extent});
        return slopOf(c) * noisePerSlop_ + 4.0f * ulpOf(largest);
    }

    /// Whether the pair overlaps deeper than the slop, beyond float noise, where the
    /// solver bodies are now. Centres that have passed each other are left alone, as
    /// position correction leaves them.
    bool beyondSlop(const Contact& c) const {
        const float overlap = overlapOf(c);
        return (c.axis == kAlongSlope || overlap <= c.extent) && overlap - slopOf(c) > noiseOf(c);
    }

private:
    /// kMinimumSkin of the smaller half extent, as a multiple of a contact's slop.
    float noisePerSlop_;
};

/// Applies `impulse` to both bodies of `c` along `direction`: + to a, - to b, each by its
/// inverse mass. An infinitely heavy body is left alone: several contacts may touch it at
/// once on several threads (solver_layers.hpp).
inline void applyImpulse(StepContext& step, const Contact& c, Vec2 direction, float impulse) {
    SolverBody& a = step.bodies[c.ia];
    if (a.invMass > 0.0f) {
        a.velocity[0] += direction.x * impulse * a.invMass;
        a.velocity[1] += direction.y * impulse * a.invMass;
    }
    SolverBody& b = step.bodies[c.ib];
    if (b.invMass > 0.0f) {
        b.velocity[0] -= direction.x * impulse * b.invMass;
        b.velocity[1] -= direction.y * impulse * b.invMass;
    }
}

/// Calls solve(contact) for every contact of the step: in contact order, or, where
/// layerContacts made layers, layer by layer on the world's workers. The same bits either
/// way, if solve writes only the contact and its bodies of finite mass.
template <class Solve> void forEachContact(StepContext& step, Solve&& solve) {
    const SolverLayers& layers = step.scratch.layers;
    if (!layers.active) {
        for (Contact& c : step.contacts)
            solve(c);
        return;
    }
    for (std::size_t layer = 0; layer + 1 < layers.starts.size(); ++layer) {
        const std::uint32_t first = layers.starts[layer];
        step.world.tasks->forEachBlock(layers.starts[layer + 1] - first, kContactsPerBlock,
                                       [&](Block block) {
                                           for (std::uint32_t k = block.begin; k < block.end; ++k)
                                               solve(step.contacts[layers.order[first + k]]);
                                       });
    }
}

} // namespace jostle
