// Seams: where two static boxes meet flush, as the boxes of a tile map or a floor built
// of separate boxes do. A seam has no face to hit.
#pragma once

namespace jostle {

struct Body;
struct WorldState;

/// Whether the face of static body `wall` that faces `other` along `axis` (0: x, 1: y) is,
/// at the corner nearest `other`, covered by another static body flush against it: a seam
/// between two boxes of a floor or a wall, which nothing can hit.
bool isSeam(const WorldState& world, const Body& wall, const Body& other, int axis);

} // namespace jostle
