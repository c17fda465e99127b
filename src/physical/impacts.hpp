// Stage: impacts. Before the contacts hold the bodies apart, every pair that meets this
// step (touching, or closing its gap within the step) faster than gravity alone explains
// collides as two bodies do: the impulse (1 + e) m v along the normal, friction within
// Coulomb's cone of it. Pair by pair, over and over, until no pair meets: a blow passes
// down a row of touching boxes as it does in Newton's cradle, and as every one of those
// collisions keeps or loses kinetic energy, the step never creates any
// (docs/physical-model.md, "Simultaneous collisions").
#pragma once

#include "jostle/math.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

struct ImpactsScratch {
    /// What the impacts know of one solver body in this step.
    struct OfBody {
        int changedInSweep = 0; ///< the last sweep that changed it
        /// When in the step (s) a collision met after a gap or at a body's earlier change
        /// last changed it, along x and along y (both for a slope); 0 if none.
        Vec2 changedAt{};
        Vec2 rubbed{};             ///< the velocity friction has given it so far
        std::uint8_t meetings = 0; ///< how many times it met something, up to kRattleMeetings
    };
    std::vector<OfBody> ofBody;               ///< by solver body, made anew each step
    std::vector<std::uint32_t> changed, next; ///< solver bodies changed in a sweep
    std::vector<Vec2> gravityInStep;          ///< by solver body: what gravity adds to its velocity
    std::vector<std::uint64_t> queued;        ///< a bit per contact: to look at in this sweep
    /// A pair that met from a gap `meetAfter` into the step (by contact index), and the
    /// speed it parts at after every collision of the step, but for what friction changed
    /// of it after this one (`rubbed`: the pair's friction velocities when it met).
    struct Bounced {
        std::uint32_t contact;
        float meetAfter, leaving;
        Vec2 rubbed;
    };
    std::vector<Bounced> bounced;
};

/// Resolves the step's impacts on the solver bodies' velocities; each body of a pair that
/// closes a gap to bounce is moved so that it ends the step where its new velocity takes
/// it from the moment of contact.
void resolveImpacts(StepContext& step);

/// After the contacts are solved: a pair moved for a bounce that it no longer makes at
/// that speed (a heavy body landed on top and held it down) is moved back by the part of
/// the bounce that is not made, as position correction moves bodies, never into what
/// holds them.
void settleBounces(StepContext& step);

} // namespace jostle
