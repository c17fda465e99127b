// jostle/body.hpp: bodies, as the user describes them.
//
// A body is an axis-aligned box: a centre (x, y) and half extents (hw, hh). It never
// rotates. Within its box it may be rounded (a radius: rounded boxes, capsules, circles),
// or cut along a diagonal (a ramp, or a ramp's sloped face alone: a one-sided segment);
// docs/slopes-and-shapes.md. You describe one with a BodyDef, hand it to World::createBody, and get
// a BodyId back: a small handle that the world checks on every use.
#pragma once

#include "jostle/math.hpp"
#include "jostle/visibility.h"

#include <cstdint>
#include <optional>
#include <string>

namespace jostle {
JOSTLE_EXPORT_BEGIN

/// How a body moves.
enum class BodyType : std::uint8_t {
    /// Never moves: floors, walls, platforms. Infinitely heavy.
    Static,
    /// Moves by its own velocity only: ignores gravity and collisions, pushes what is in
    /// its way, infinitely heavy. Lifts and moving platforms. The user may move it.
    Kinematic,
    /// Moved by gravity, its velocity and collisions. Crates, players, bullets.
    Dynamic,
};

/// The names used in scene files and traces: "static", "kinematic", "dynamic".
const char* toString(BodyType type);
std::optional<BodyType> bodyTypeFromString(const std::string& name);

/// A handle to a body of one world. A default-constructed BodyId is the null handle.
///
/// It names the world that made it, a storage slot of that world, and a generation that
/// counts how often the slot was reused. So a handle is never mistaken for another body:
/// World::isValid returns false, and every other World function throws jostle::Error,
/// for a handle of a destroyed body ("stale BodyId") and for a handle of another world
/// ("BodyId of another world"), however many worlds and bodies the process made.
/// Handles are compared, never ordered: their values say nothing about creation order.
struct BodyId {
    std::uint32_t index = 0;
    std::uint32_t generation = 0; ///< 0 only in the null handle
    /// The serial number of the world that made it, unique in the process; 0 only in the
    /// null handle (World::World).
    std::uint32_t world = 0;

    constexpr bool isNull() const { return generation == 0; }
    friend constexpr bool operator==(BodyId a, BodyId b) = default;
};

/// Everything that describes a body. Start from the defaults and set what you need:
///
///     jostle::BodyDef def;
///     def.type = jostle::BodyType::Dynamic;
///     def.x = 0; def.y = 0; def.hw = 10; def.hh = 10;
///     def.bounce = 0.3f;
///     jostle::BodyId crate = world.createBody(def);
///
/// The member names are the field names of scene files (docs/scene-format.md).
struct BodyDef {
    BodyType type = BodyType::Dynamic;
    float x = 0.0f;  ///< centre
    float y = 0.0f;  ///< centre
    float hw = 0.0f; ///< half width, must be > 0
    float hh = 0.0f; ///< half height, must be > 0
    float vx = 0.0f; ///< velocity, in units per second
    float vy = 0.0f;
    /// Restitution in [0, 1]: 0 does not bounce, 1 bounces back at full speed.
    /// A pair bounces with the larger of its two values.
    float bounce = 0.0f;
    /// Friction in [0, 1]. A pair rubs with the smaller of its two values.
    float friction = 0.5f;
    /// Mass, > 0 to set it explicitly; 0 (the default) means density × area.
    /// Static and kinematic bodies are infinitely heavy whatever this says.
    float mass = 0.0f;
    /// Mass per unit of area, > 0; used when mass is 0. Area is 4 × hw × hh.
    float density = 1.0f;
    /// Multiplies the world's gravity for this body (0: floats, -1: falls up).
    float gravityScale = 1.0f;
    /// Linear damping, >= 0: every step, velocity /= 1 + damping × dt.
    float damping = 0.0f;
    /// A fast dynamic body that must not pass through other dynamic bodies either.
    /// Every dynamic body is kept from passing through static and kinematic ones; a bullet
    /// is also swept against dynamic bodies, which costs more.
    bool bullet = false;
    /// A one-way platform: the outward normal of its one blocking face, {0, -1} for a
    /// jump-through platform in a y-down world (its top blocks). Others pass through it
    /// from every other side, and land on the blocking face only if they were wholly on
    /// its side when the step began. {0, 0} (the default): solid on every side. Must be
    /// {0, 0} or one of {±1, 0}, {0, ±1}. docs/one-way-platforms.md.
    Vec2 oneWay{};
    /// Collision filtering: the category bits this body belongs to, and the categories
    /// it collides with. Two bodies collide when each one's category shares a bit with
    /// the other's mask. Queries filter with the same bits. docs/filtering.md.
    std::uint32_t category = 1;
    std::uint32_t mask = 0xFFFFFFFF;
    /// A sensor detects overlaps and reports them (World::sensorBegins, sensorEnds),
    /// but never pushes nor is pushed. docs/events.md.
    bool sensor = false;
    /// A character, for a player or an enemy (docs/characters.md). A dynamic body that
    /// walks at the speed the game commands (World::setWalkSpeed) along what it stands
    /// on, relative to it, so that friction neither eats that speed nor leaves it
    /// behind a moving lift; and that rubs only on floors: against walls and ceilings its
    /// friction is wallFriction, so pushing into a wall while jumping does not hold it up.
    /// Ignored for static and kinematic bodies.
    bool character = false;
    /// A character's friction against walls and ceilings, in [0, 1]. 0 (the default):
    /// it slides along a wall it is pressed into as in open air.
    float wallFriction = 0.0f;
    /// The steepest surface, in degrees from level, that is a floor to this body: what
    /// World::touching calls floor and World::ground returns, where a character walks and
    /// rubs with its friction. Steeper, it is a wall (or a ceiling, past 120 degrees). In
    /// [0, 90); 60 by default. A character on a slope steeper than this slides down it.
    float floorAngle = 60.0f;
    /// Sticks to the ground, for characters walking down slopes and over crests: a body
    /// that stood on a floor at the end of the last step, and does not move away from it,
    /// is moved down (along gravity) onto the floor below at the end of the step, by at
    /// most this distance, instead of flying off; its velocity then runs along that floor
    /// (a character keeps its speed across gravity, any other body its speed). Jumping
    /// (moving away from the floor) and falling further than this are left alone.
    /// >= 0; 0 (the default): off, except that a character always snaps by at least the
    /// drop a step at its walk speed meets on the steepest floor it stands on,
    /// |walkSpeed| dt tan(floorAngle), at most its half extent along gravity: it walks over
    /// crests and down ramps it can stand on without leaving the ground. The physical
    /// model only: the classic one ignores it.
    float snapDown = 0.0f;
    /// Slips round corners it clips by at most this much (>= 0; 0, the default: off): a
    /// body rising into the underside of a platform, or moving sideways into a ledge, whose
    /// edge overlaps the obstacle's corner by no more than this is moved aside (across its
    /// motion) to clear the corner, keeping its velocity, instead of being stopped: a jump
    /// that clips a platform's corner by half a pixel is not lost. Not when falling onto
    /// something (landing on a ledge's corner stays a landing), and not into anything else.
    /// Sharp boxes against static and kinematic boxes; the physical model only.
    /// docs/characters.md.
    float cornerCorrection = 0.0f;
    /// A character walks up a step no taller than this (>= 0; 0, the default: off) at its
    /// walk speed, without jumping and without catching on the step's edge, and down one
    /// as high; a taller step stops it as a wall does. Sharp boxes against static and
    /// kinematic boxes; the physical model only. docs/characters.md.
    float stepUp = 0.0f;
    /// Rounds the box's corners with this radius, in [0, min(hw, hh)]: hw = hh = radius is
    /// a circle, hw = radius < hh an upright capsule. 0 (the default): a sharp box. Mass
    /// still comes from the box's area, 4 × hw × hh. The physical model only.
    float radius = 0.0f;
    /// A ramp: the box cut along a diagonal, keeping the right triangle whose sloped face
    /// looks towards this corner (each component -1 or +1). {-1, -1} in a y-down world is
    /// a floor rising to the right (the slope faces up and left), {1, 1} a ceiling
    /// falling to the right. {0, 0} (the default): not cut. Ramps are static or
    /// kinematic, and not rounded. The physical model only.
    Vec2 slope{};
    /// With a slope: only the sloped face, a one-sided line from corner to corner that
    /// blocks what comes from the side it looks towards and lets through what comes from
    /// behind, as a one-way platform does (dropThrough works on it too).
    bool segment = false;
    /// A conveyor belt: the velocity its surface moves at, as far as friction is concerned,
    /// while the body itself stays where it is (or moves by its own velocity). What rests
    /// on it is carried by friction, along each face by the part of this along the face: a
    /// crate comes up to the belt's speed at the rate friction gives (μ g), a character
    /// walks relative to the belt. {0, 0} (the default): none. Static and kinematic
    /// bodies only. docs/moving-platforms.md.
    Vec2 surfaceVelocity{};
    /// Yours: jostle stores it and gives it back, nothing more.
    void* userData = nullptr;
};

/// What is wrong with a definition: the member's name and the rule it breaks,
/// e.g. {"hw", "must be > 0"}.
struct FieldError {
    std::string field;
    std::string problem;
};

/// The first problem with `def`, or nothing if World::createBody will accept it.
/// The rules: every number finite; hw, hh, density > 0; mass, damping, radius >= 0;
/// surfaceVelocity {0, 0} unless the body is static or kinematic;
/// bounce, friction and wallFriction in [0, 1]; floorAngle in [0, 90); snapDown >= 0; oneWay {0, 0}
/// or a unit vector along x or y; radius at most hw and hh; slope {0, 0} or each component -1 or
/// +1, and then the body static or kinematic, with no radius and no oneWay; segment only with a
/// slope; a rounded body not one-way.
std::optional<FieldError> checkBodyDef(const BodyDef& def);

/// True if `normal` is acceptable as BodyDef::oneWay.
bool isValidOneWay(Vec2 normal);

/// True if `corner` is acceptable as BodyDef::slope.
bool isValidSlope(Vec2 corner);

JOSTLE_EXPORT_END
} // namespace jostle
