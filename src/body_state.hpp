// A body as the world keeps it: Body, what the steps read, and KeptAsGiven, the settings
// no step reads (world_state.hpp holds one of each a slot). body_properties.hpp says where
// each property of a body is kept.
#pragma once

#include "geometry.hpp"
#include "jostle/body.hpp"
#include "shapes.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace jostle {

/// One body as the solvers see it. What finding and building contacts reads comes first
/// and fills one cache line (the struct is aligned to it): a step visits bodies in pair
/// order, not in memory order, and each visit should cost one line, not two.
struct alignas(64) Body {
    // --- Read for every pair ---
    Vec2 position;
    Vec2 velocity;
    Vec2 half;
    /// 0 for static and kinematic bodies: infinitely heavy.
    float invMass = 0.0f;
    float bounce = 0.0f;
    float friction = 0.0f;
    std::uint32_t category = 1;
    std::uint32_t mask = 0xFFFFFFFF;
    /// One-way platform: outward normal of the blocking face, or {0, 0}.
    Vec2 oneWay;
    /// Counts the slot's reuses; a BodyId matches only the generation it was made with
    /// (handles.hpp).
    std::uint32_t generation = 1;
    BodyType type = BodyType::Dynamic;
    /// The slot holds a live body. Cleared at once by destroyBody, even mid-step.
    bool alive = false;
    bool sensor = false;
    bool asleep = false;
    /// BodyDef::character: walks at walkSpeed, rubs only on floors (docs/characters.md).
    bool character = false;
    /// A box, or a shape whose numbers are in WorldState::shapes (shapes.hpp).
    ShapeKind shape = ShapeKind::Box;
    bool bullet = false;

    // --- Read once a step, or less ---
    /// BodyDef::surfaceVelocity: a conveyor's, for friction (looked at only while the world
    /// has a conveyor: WorldState::conveyors).
    Vec2 surfaceVelocity;
    /// BodyDef::floorAngle's cosine: a surface pushing it at least this much against
    /// gravity is its floor (ground.hpp's surfaceOf).
    float floorCos = 0.5f;
    /// BodyDef::snapDown: how far it is moved down onto the ground (physical/snap.hpp).
    float snapDown = 0.0f;
    /// Whether the snap stage looks at it: a snapDown, or a character (which follows the
    /// floors it walks onto whatever its snapDown).
    bool maySnap() const { return snapDown > 0.0f || character; }
    /// Sum of the separation vectors applied to this body during the last step.
    Vec2 separation;
    /// Kinematic bodies: the velocity they moved with in the last step, to hand what
    /// changed since to their riders.
    Vec2 lastStepVelocity;
    float mass = 0.0f; ///< explicit mass, or 0 for density × area (KeptAsGiven::density)
    float gravityScale = 1.0f;
    float damping = 0.0f;
    /// Seconds this body has been slow enough to sleep.
    float sleepTime = 0.0f;
    /// While asleep: the index of its island in WorldState::islands.
    std::uint32_t island = 0;
    /// A character's friction against walls and ceilings.
    float wallFriction = 0.0f;
    /// The speed a character walks at, along its ground and relative to it.
    float walkSpeed = 0.0f;
    /// Seconds left during which this body falls through one-way platforms.
    float dropThroughTime = 0.0f;

    bool isDynamic() const { return type == BodyType::Dynamic; }
    /// A character that walks and rubs only on floors: the flag counts on dynamic bodies.
    bool isCharacter() const { return character && isDynamic(); }
    /// The mass it has as a dynamic body: explicit, or `density` × area.
    float dynamicMass(float density) const {
        return mass > 0.0f ? mass : density * 4.0f * half.x * half.y;
    }
    /// Sets invMass from the type, mass, `density` (its KeptAsGiven's) and size.
    void updateMass(float density) { invMass = isDynamic() ? 1.0f / dynamicMass(density) : 0.0f; }
    /// A sharp box: the pair rules of geometry.hpp, not those of shapes.hpp.
    bool isBox() const { return shape == ShapeKind::Box; }
    bool isOneWay() const { return oneWay.x != 0.0f || oneWay.y != 0.0f; }
    /// The velocity of its surface where it pushes along `normal`: what a body resting there
    /// moves with, a conveyor's surface velocity along the surface included.
    Vec2 surfaceMotion(Vec2 normal) const {
        if (surfaceVelocity.x == 0.0f && surfaceVelocity.y == 0.0f)
            return velocity;
        return velocity + surfaceVelocity - normal * dot(surfaceVelocity, normal);
    }
    /// Its box, by corners.
    Box box() const { return boxAround(position, half); }
};

static_assert(offsetof(Body, shape) < 64, "the hot part of Body fits one cache line");
static_assert(sizeof(Body) == 128, "a Body is two cache lines");

/// A body's settings that the steps never read, as the user gave them.
struct KeptAsGiven {
    void* userData = nullptr;
    float floorAngle = 60.0f; ///< degrees; Body::floorCos is what the steps read
    float density = 1.0f;     ///< Body::invMass is what the steps read
    /// Read by the corner stage alone (physical/corners.hpp), for the bodies that have one.
    float cornerCorrection = 0.0f;
    float stepUp = 0.0f;
    bool slipsRoundCorners() const { return cornerCorrection > 0.0f || stepUp > 0.0f; }
};

/// The cosine of an angle in degrees: the floorCos of a floorAngle (60 gives 0.5 exactly).
inline float floorCosOf(float degrees) {
    return float(std::cos(double(degrees) * (3.14159265358979323846 / 180.0)));
}

/// Works out again what the steps read of the settings kept as given: floorCos from
/// floorAngle, invMass from density (with the body's type, mass and size).
inline void deriveFrom(const KeptAsGiven& kept, Body& body) {
    body.floorCos = floorCosOf(kept.floorAngle);
    body.updateMass(kept.density);
}

/// The filter rule: each one's category shares a bit with the other's mask.
inline bool canCollide(const Body& a, const Body& b) {
    return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

} // namespace jostle
