// Stages: solve velocities, then shock propagation. Sequential impulses over all the
// step's contacts, then one last normal pass from the ground up in which the body that
// holds the other stays put.
#pragma once

namespace jostle {

struct StepContext;

/// Warm starts every contact from its impulses, then runs the velocity passes:
/// each nudges the accumulated normal impulse (never pulling: >= 0) and the friction
/// impulse (Coulomb: |friction| <= mu × normal).
void solveVelocities(StepContext& step);

/// One last normal pass, from the ground up, in which the body that holds the other is
/// held fixed: what the passes before left unresolved, the other takes.
void propagateShock(StepContext& step);

} // namespace jostle
