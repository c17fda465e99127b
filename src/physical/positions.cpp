// Positions: the move by velocity, then position correction over the step's contacts.
#include "positions.hpp"

#include "sleep.hpp"
#include "step_context.hpp"

#include <algorithm>
#include <atomic>

namespace jostle {

namespace {

/// One pass of position correction; false if it moved no body.
bool correctionPass(StepContext& step) {
    std::atomic<bool> moved{false};
    forEachContact(step, [&](Contact& c) {
        SolverBody& a = step.bodies[c.ia];
        SolverBody& b = step.bodies[c.ib];
        const float overlap = step.overlapOf(c);
        // Centres that have passed each other along the normal (a kinematic body that
        // went on through what it pushed): pushing "out" would push through.
        const bool sloped = c.axis == kAlongSlope;
        if (!sloped && overlap > c.extent)
            return;
        const float slop = step.slopOf(c);
        const float excess = overlap - slop;
        if (!(excess > 0.0f))
            return;
        // An excess within float noise goes at once: a fraction of it would round to
        // nothing, and a pair pushed from both sides would stay beyond the slop for good.
        const float correction = excess <= step.noiseOf(c)
                                     ? excess
                                     : std::min(step.options.correction * excess,
                                                0.25f * ((sloped ? c.size : c.extent) - slop));
        // The body that holds the other stays put (support.hpp).
        const float moveA = correction * step.shareOfA(c);
        const float moveB = correction * step.shareOfB(c);
        // An infinitely heavy body never moves (and may be in several contacts at once on
        // several threads: solver_layers.hpp).
        if (sloped) {
            if (step.invMassA(c) > 0.0f) {
                a.position[0] += c.n.x * moveA;
                a.position[1] += c.n.y * moveA;
            }
            if (step.invMassB(c) > 0.0f) {
                b.position[0] -= c.n.x * moveB;
                b.position[1] -= c.n.y * moveB;
            }
        } else {
            if (step.invMassA(c) > 0.0f)
                a.position[c.axis] += c.sign() * moveA;
            if (step.invMassB(c) > 0.0f)
                b.position[c.axis] -= c.sign() * moveB;
        }
        moved.store(true, std::memory_order_relaxed);
    });
    return moved.load(std::memory_order_relaxed);
}

} // namespace

void integratePositions(StepContext& step) {
    // The bodies that were moving when the step began (a callback may have created others
    // since: they join next step).
    WorldState& w = step.world;
    const auto count = std::uint32_t(w.movingSlots.size());
    w.tasks->forEachBlock(count, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const std::uint32_t slot = w.movingSlots[k];
            if (w.isLive(slot))
                w.slots[slot].position += w.slots[slot].velocity * step.dt;
        }
    });
}

void correctPositions(StepContext& step) {
    WorldState& w = step.world;
    const auto count = std::uint32_t(step.bodies.size());
    w.tasks->forEachBlock(count, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            SolverBody& body = step.bodies[k];
            body.position[0] = w.slots[body.slot].position.x;
            body.position[1] = w.slots[body.slot].position.y;
        }
    });
    // A pass that moved nothing leaves the next one nothing to do.
    for (int i = 0; i < step.options.positionIterations && correctionPass(step); ++i) {
    }
    w.tasks->forEachBlock(count, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const SolverBody& body = step.bodies[k];
            if (body.invMass <= 0.0f)
                continue;
            // What position correction moved the body is part of its separation.
            Body& written = w.slots[body.slot];
            const Vec2 corrected{body.position[0], body.position[1]};
            const Vec2 moved = corrected - written.position;
            written.separation += moved;
            written.position = corrected;
            // Still being pushed out of an overlap: not at rest, whatever its speed.
            if (length(moved) > restingSpeed(written) * step.dt)
                written.sleepTime = 0.0f;
        }
    });
}

} // namespace jostle
