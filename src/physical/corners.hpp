// Stage: slipping round corners (BodyDef::cornerCorrection, stepUp). Before contacts are
// made, a body about to run into a face of a static or kinematic box that its own edge
// overlaps by very little is moved aside, so that its path clears the corner instead of
// stopping at it: a jump that clips a platform's underside, a dash that clips a ledge's top,
// a character walking into a step it can climb.
#pragma once

namespace jostle {

struct StepContext;

/// For each pair of the step (in the step's order) of a dynamic body that slips round
/// corners and a static or kinematic box: if the body is apart from the box along one axis
/// and will meet its face within the step, overlapping it along the other axis by at most
///
/// - its cornerCorrection, unless the face is a floor under it (a landing stays one),
/// - or, for a character that stood on the ground and walks into the box's side, its
///   stepUp, and the box's top is what it overlaps,
///
/// the body is moved along that other axis to clear the corner (past the contact skin; onto
/// a step's top exactly), keeping its velocity, provided nothing solid is where it would
/// go.
void slipRoundCorners(StepContext& step);

} // namespace jostle
