// Characters (docs/characters.md): bodies whose walking the game commands. Both models
// call these: walking after the velocities are integrated, and the friction and the
// tangent speed of each contact a character is part of.
#pragma once

#include "jostle/math.hpp"

namespace jostle {

struct Body;
struct WorldState;

/// Each awake character's velocity along its ground (across gravity) becomes its ground's
/// plus its walk speed; in the air, its walk speed. The ground is the one of the last
/// step, moving as it moves now. Against a slope too steep to stand on (past its floor
/// angle), not walking away from it, the velocity is left alone: it slides down.
void walkCharacters(WorldState& world);

/// The friction `body` brings to a contact whose surface pushes it along `push`: a
/// character rubs with its wallFriction against what is not its floor.
float frictionAgainst(const Body& body, Vec2 push, Vec2 down);

/// The velocity of `a` relative to `b` that a contact's friction keeps, instead of none:
/// a character on its floor walks at its walk speed over it, and a conveyor's surface
/// carries what rubs on it (BodyDef::surfaceVelocity; the part along the contact counts).
Vec2 walkOver(const Body& a, const Body& b, Vec2 normal, Vec2 down);

/// Whether friction between `a` and `b` keeps a relative velocity (walkOver) other than
/// none: a character is in the pair, or a conveyor (looked for only if `conveyors`, the
/// world has one).
bool keepsATangentSpeed(const Body& a, const Body& b, bool conveyors);

/// On a sloped floor (normal from b towards a, neither along gravity nor across it): the
/// speed of `a` relative to `b` along the contact's tangent (-ny, nx) at which a character
/// standing on it moves across gravity at its walk speed. NaN if neither is a character on
/// it as its floor.
float walkAlongSlope(const Body& a, const Body& b, Vec2 normal, Vec2 down);

} // namespace jostle
