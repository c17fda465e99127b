// Seams: where two static boxes meet flush, as the boxes of a tile map or a floor built
// of separate boxes do. A seam has no face to hit.
#pragma once

#include <cstdint>

namespace jostle {

struct Body;
struct WorldState;

/// Whether the face of static body `wall` that faces `other` along `axis` (0: x, 1: y) is,
/// at the corner nearest `other`, covered by another static body flush against it: a seam
/// between two boxes of a floor or a wall, which nothing can hit.
bool isSeam(const WorldState& world, const Body& wall, const Body& other, int axis);

/// The faces of `wall`'s box (shapes.hpp's FaceBit) that may push `other`: all of them,
/// but a segment's (only its sloped face pushes) and, for a static wall, those covered
/// where `other` meets them by another static body flush against them: a box's face or a
/// ramp's leg. A ramp's tips count as the faces they end on, so that the floor beside a
/// ramp's foot covers it and a body sliding onto the ramp meets only its slope.
std::uint8_t pushingFaces(const WorldState& world, const Body& wall, const Body& other);

} // namespace jostle
