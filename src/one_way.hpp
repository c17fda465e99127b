// The one-way rule (docs/one-way-platforms.md, tests/test_one_way.cpp): which surfaces stop
// a body that meets them. Contacts, sweeps, snapping to the ground and queries all ask here.
//
// - A one-way platform (BodyDef::oneWay) stops only what meets its blocking face, having
//   been wholly outside it when the motion began, and not while the body drops through.
// - A segment (a ramp's sloped face alone, BodyDef::segment) stops only what meets it from
//   the side it looks towards (its outline has no other face), having been outside it, and
//   not while the body drops through.
// - Every other body stops everything.
#pragma once

#include "shapes.hpp"
#include "world_state.hpp"

#include <cstdint>

namespace jostle {

/// The faces of `surface` that stop what meets it (shapes.hpp's FaceBit): a one-way
/// platform's blocking face, or all four.
inline std::uint8_t blockingFaces(const Body& surface) {
    return surface.isOneWay()
               ? faceBit(surface.oneWay.x != 0.0f ? 0 : 1, surface.oneWay.x + surface.oneWay.y)
               : std::uint8_t{kAllFaces};
}

/// Whether `surface` stops a body that meets it along `normal` (from the surface towards the
/// body), the body having been wholly outside it when the motion began (`fromOutside`) and
/// dropping through one-way surfaces for `dropTime` more seconds (its dropThroughTime).
inline bool stops(const Body& surface, Vec2 normal, bool fromOutside, float dropTime) {
    if (surface.isOneWay())
        return normal == surface.oneWay && fromOutside && dropTime <= 0.0f;
    if (surface.shape == ShapeKind::Segment)
        return fromOutside && dropTime <= 0.0f;
    return true;
}

} // namespace jostle
