// What every stage of the physical step works on (step.cpp lists the stages): the world,
// the step's scratch buffers, dt and the options; and the few measures of a contact that
// several stages share.
#pragma once

#include "../world_state.hpp"

#include <cstdint>

namespace jostle {

struct StepContext {
    StepContext(WorldState& w, float stepDt);

    WorldState& world;
    PhysicalScratch& scratch;
    const PhysicalOptions options; ///< a copy: a callback may change the world's
    const float dt;
    /// Solver bodies and contacts of the step (scratch.bodies, scratch.contacts).
    std::vector<SolverBody>& bodies;
    std::vector<Contact>& contacts;

    static constexpr std::uint32_t kNoSolverBody = UINT32_MAX;
    /// The solver body of a body, made on first use.
    std::uint32_t solverBodyOf(std::uint32_t slot);

    /// The contact skin of two half extents along one axis (geometry.hpp's contactSkin).
    float skinOf(float halfA, float halfB) const;
    /// How deep the pair of contact `c` overlaps along its normal where the solver bodies
    /// are now (negative: the gap between them).
    float overlapOf(const Contact& c) const;
    /// Float noise in the overlap of `c` where the solver bodies are now: kMinimumSkin of
    /// the smaller half extent along the normal, and four float steps at the pair's
    /// coordinates. Overlap within the slop and this is within the slop.
    float noiseOf(const Contact& c) const;
    /// Whether the pair overlaps deeper than the slop, beyond float noise, where the
    /// solver bodies are now.
    bool beyondSlop(const Contact& c) const;

private:
    /// kMinimumSkin of the smaller half extent, as a multiple of a contact's slop.
    float noisePerSlop_;
};

} // namespace jostle
