// The step context's shared measures.
#include "step_context.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

StepContext::StepContext(WorldState& w, float stepDt)
    : world(w), scratch(w.physical), options(w.def.physical), dt(stepDt), bodies(w.physical.bodies),
      contacts(w.physical.contacts),
      noisePerSlop_(options.slop > 0.0f ? kMinimumSkin / options.slop : 0.0f) {}

std::uint32_t StepContext::solverBodyOf(std::uint32_t slot) {
    std::uint32_t& index = scratch.solverIndex[slot];
    if (index == kNoSolverBody) {
        const Body& body = world.slots[slot];
        index = std::uint32_t(bodies.size());
        bodies.push_back({{body.velocity.x, body.velocity.y},
                          {body.position.x, body.position.y},
                          body.invMass,
                          slot});
    }
    return index;
}

float StepContext::skinOf(float halfA, float halfB) const {
    return contactSkin(options.slop, halfA, halfB);
}

float StepContext::overlapOf(const Contact& c) const {
    return c.extent - c.sign * (bodies[c.ia].position[c.axis] - bodies[c.ib].position[c.axis]);
}

float StepContext::noiseOf(const Contact& c) const {
    const float pa = bodies[c.ia].position[c.axis], pb = bodies[c.ib].position[c.axis];
    const float largest = std::max({std::abs(pa), std::abs(pb), c.extent});
    return c.slop * noisePerSlop_ + 4.0f * ulpOf(largest);
}

bool StepContext::beyondSlop(const Contact& c) const {
    const float overlap = overlapOf(c);
    // Centres that have passed each other: position correction leaves them alone.
    return overlap <= c.extent && overlap - c.slop > noiseOf(c);
}

} // namespace jostle
