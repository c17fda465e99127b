// Where a touching pair's contact is drawn in debug drawing, and which way its normal
// points: the point and normal of each pair, SDL-free (the demo and the web page draw it).
#pragma once

#include "contact_set.hpp"

namespace jostle::demo {

/// Where the two boxes of `pair` meet: across the normal, the middle of the stretch their
/// faces share (of the gap between them, should they no longer share one); along it,
/// halfway between the two faces that touch.
Vec2 contactPoint(const World& world, const TouchingPair& pair);

/// The point and normal (from b towards a) to draw for `pair`: contactPoint and the begin
/// event's normal for a pair that met along an axis; for one that met on a slope or a
/// rounded corner, where the boxes do not tell, the contact as World::contacts has it now
/// (a ball rolling down a ramp touches it somewhere else every step).
struct DrawnContact {
    Vec2 point;
    Vec2 normal;
};
DrawnContact drawnContact(const World& world, const TouchingPair& pair);

} // namespace jostle::demo
