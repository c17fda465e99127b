// jostle/query.hpp: asking the world what is where.
//
//     // What is under the mouse?
//     std::vector<jostle::BodyId> picked = jostle::queryPoint(world, mouse);
//
//     // Can the guard see the player? Only the level blocks the view.
//     jostle::QueryFilter sight{.mask = kLevel, .ignore = guard};
//     bool seen = !jostle::rayCast(world, eye, world.position(player), sight);
//
//     // Move a character by hand, sliding along floors and walls, as bump.lua does.
//     jostle::MoveResult moved = jostle::moveAndSlide(world, centre, half, velocity * dt,
//                                                     {.ignore = player});
//
// Queries look at every body where it is now: after step(), after setPosition, while
// asleep. They change nothing in the world, and they filter bodies as collisions do
// (QueryFilter). They see each body's true shape (BodyDef::radius, slope, segment): a ray
// meets a circle at the circle, a ramp on its slope; the box a cast or a move carries is a
// sharp box unless given a radius (the rounded boxCast and moveAndSlide, circleCast).
// docs/queries.md is the guide; this header is the reference.
//
// Results come in a fixed order, the same run after run: bodies in creation order, hits
// by distance along the query and, at equal distance, in creation order.
//
// Misuse throws jostle::Error (error.hpp): a NaN or infinite number anywhere, sizes that
// break the rule given with each function, a stale QueryFilter::ignore.
//
// Cost: static and sleeping bodies are found through the grid the broadphase keeps of
// them, so in a big level a query looks only at the bodies near it (a long ray, piece by
// piece along its path). Awake bodies (dynamic and kinematic ones not asleep) are each
// tested by every query: a world's awake bodies are usually few next to its level. The
// first query after bodies were created or destroyed spends time proportional to the
// number of bodies re-indexing them; the first after a static body changed, or bodies
// fell asleep or woke, rebuilds the grid (which the next step would otherwise do).
//
// Threads: queries may run on several threads at once on the same world, as long as
// nothing changes the world meanwhile (they share the index update through a lock). A
// query may be made from a callback during step(): it sees the bodies where the step has
// got them to. If a static body changed or bodies woke during that step, the grid cannot
// be rebuilt under the step's feet, and the query tests every body.
#pragma once

#include "jostle/body.hpp"
#include "jostle/math.hpp"
#include "jostle/visibility.h"
#include "jostle/world.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace jostle {
JOSTLE_EXPORT_BEGIN

/// Which bodies a query reports. The defaults report every body except sensors.
///
/// A body is reported when, as in a collision between the body and the query,
///
///     (body.category & filter.mask) != 0 && (filter.category & body.mask) != 0
///
/// and it is not a sensor (unless includeSensors) and not `ignore`. A body whose mask is
/// 0 collides with nothing, and no query sees it either.
struct QueryFilter {
    /// The categories to report.
    std::uint32_t mask = 0xFFFFFFFF;
    /// The category the query belongs to, as the bodies' masks see it: a query with
    /// `category = kPlayer` sees what a player would collide with.
    std::uint32_t category = 0xFFFFFFFF;
    /// Report sensors too. Off by default: a sensor is an area, not a thing, so it does
    /// not block a line of sight nor stop a cast. Turn it on to ask "which trigger zones
    /// is this point in?". moveAndSlide never stops at a sensor, whatever this says.
    bool includeSensors = false;
    /// A body never reported: the character doing the query. The null handle (the
    /// default) ignores nothing. A stale handle throws jostle::Error: the caller holds a
    /// dead character's handle, which is a bug worth hearing about.
    BodyId ignore{};
};

// --- What is here? ---------------------------------------------------------------------

/// The bodies that contain `point`, in creation order. A point on an edge is on the body
/// (a click on the seam between two tiles picks both). A body is its shape: a point in a
/// circle's box but outside the circle, or in the half of a ramp's box cut away, is not in
/// it; a segment, a line, holds the points on it (within float rounding).
std::vector<BodyId> queryPoint(const World& world, Vec2 point, const QueryFilter& filter = {});

/// The bodies that overlap the box of centre `centre` and half extents `half` (each >= 0),
/// in creation order. Overlap means sharing some area: a body merely touching the box
/// edge to edge is not reported, so a box resting on a floor does not overlap the floor,
/// and "is there room to stand up here?" is answered with the standing box. A body is its
/// shape (a ramp's slope, a circle's curve); a segment overlaps the boxes it crosses.
std::vector<BodyId> queryBox(const World& world, Vec2 centre, Vec2 half,
                             const QueryFilter& filter = {});

/// queryBox by corners: the box from `min` to `max` (min <= max on both axes).
std::vector<BodyId> queryRect(const World& world, Vec2 min, Vec2 max,
                              const QueryFilter& filter = {});

/// The same three, filling `out` (cleared first) so that its memory serves frame after
/// frame.
void queryPoint(const World& world, Vec2 point, const QueryFilter& filter,
                std::vector<BodyId>& out);
void queryBox(const World& world, Vec2 centre, Vec2 half, const QueryFilter& filter,
              std::vector<BodyId>& out);
void queryRect(const World& world, Vec2 min, Vec2 max, const QueryFilter& filter,
               std::vector<BodyId>& out);

// --- Rays --------------------------------------------------------------------------------

/// Where a ray meets a body.
struct RayHit {
    BodyId body;
    /// from + (to - from) × fraction, placed exactly on the face it meets.
    Vec2 point;
    /// The outward normal of the surface the ray meets, unit, against the ray: along x or y
    /// for a box's face, a ramp's slope's normal, or a rounded body's normal there.
    Vec2 normal;
    /// How far along from → to, in [0, 1].
    float fraction = 0.0f;
};

/// The first body on the segment from `from` to `to`, if any.
///
/// The rules, each a regression test:
/// - Touching counts: a ray that grazes a corner hits it there, and a ray that runs
///   exactly along a face hits the box where it reaches the face. So a ray cast straight
///   down the seam between two floor tiles hits the floor, never slips through.
/// - A ray that starts inside a box, or on its edge heading in or along it, hits it at
///   fraction 0, at `from`. The normal is the face it heads into if it starts on one,
///   else the one facing its main direction (the axis along which it moves more; y if
///   equal). A ground probe that starts a little inside the floor reports the floor.
/// - A ray that starts on a box's edge and heads away from it does not hit it.
/// - A one-way platform (BodyDef::oneWay) is hit only through its blocking face, from
///   outside; a ray starting inside it passes. So is a segment (BodyDef::segment): only
///   from the side it faces, never from behind.
/// - A point on an axis-aligned face (a box's, a ramp's legs, a rounded box's flat sides)
///   lies exactly on it; on a slope or a curve, it is from + (to - from) × fraction.
/// - A zero-length ray (from == to) hits nothing: use queryPoint.
/// - Equal fractions: the body created first wins.
std::optional<RayHit> rayCast(const World& world, Vec2 from, Vec2 to,
                              const QueryFilter& filter = {});

/// Every body on the segment, by fraction (equal fractions in creation order), each once,
/// by the rules of rayCast.
std::vector<RayHit> rayCastAll(const World& world, Vec2 from, Vec2 to,
                               const QueryFilter& filter = {});
void rayCastAll(const World& world, Vec2 from, Vec2 to, const QueryFilter& filter,
                std::vector<RayHit>& out);

// --- Moving boxes ------------------------------------------------------------------------

/// Where a box swept along a translation first touches a body.
struct BoxCastHit {
    BodyId body;
    /// Where the box's centre stops: touching the body. Along the normal's axis it is
    /// placed exactly so (centre = the body's face + the half extent); against a slope or
    /// a curve, moved along the normal to touching, within float rounding.
    Vec2 centre;
    /// Unit, pointing from the body towards the box: along x or y for a box's face, the
    /// slope's normal for a ramp's slope, the normal there for a rounded body's curve.
    Vec2 normal;
    /// The time of impact: the fraction of the translation travelled, in [0, 1].
    float fraction = 0.0f;
};

/// Sweeps the box of centre `centre` and half extents `half` (each > 0) along
/// `translation`, and returns the first body it runs into, if any.
///
/// The rules are those of a solid body moving through the world (the continuous-collision
/// sweep's, docs/continuous-collision.md):
/// - Touching is not running into. A body that the box touches at the start, or overlaps
///   by no more than the contact skin (twice the world's slop times the smaller half
///   extent, as the physical model counts a resting contact), stops the box only if the
///   box moves into it; moving along it (a box on a floor moving sideways, a box sliding
///   along a wall made of separate boxes, across their seams) is free.
/// - The box stops touching the body, not inside it: a motion that would end inside a
///   body, or within the skin of it, stops at its face.
/// - A body that the box already overlaps by more than the skin on both axes does not
///   stop it: the box is inside and free to leave (queryBox tells that it is there).
/// - A one-way platform stops the box only on its blocking face, and only if the box
///   starts wholly on that side of it (within the skin), as in the physical model. So does
///   a segment, on the side it faces.
/// - The moving box is a sharp box (the overload with a radius rounds it); the bodies are
///   their shapes: a box meets a ramp on its slope, a circle where the curve is (the skin
///   there is twice the slop of the smaller reach of the two along the normal).
/// - A zero translation hits nothing. Equal fractions: the body created first wins.
std::optional<BoxCastHit> boxCast(const World& world, Vec2 centre, Vec2 half, Vec2 translation,
                                  const QueryFilter& filter = {});
/// boxCast of the box rounded by `radius`, in [0, min(half.x, half.y)], as BodyDef::radius
/// rounds a body: half.x == half.y == radius is a circle, half.x == radius < half.y an
/// upright capsule. It meets the bodies with its curve (its normal there the curve's);
/// the rest is boxCast's rules. jostle::Error for a radius out of range or NaN.
std::optional<BoxCastHit> boxCast(const World& world, Vec2 centre, Vec2 half, float radius,
                                  Vec2 translation, const QueryFilter& filter = {});
/// boxCast of a circle (radius > 0).
std::optional<BoxCastHit> circleCast(const World& world, Vec2 centre, float radius,
                                     Vec2 translation, const QueryFilter& filter = {});

/// A body met by moveAndSlide.
struct MoveHit {
    BodyId body;
    Vec2 normal; ///< unit, pointing from the body towards the box (as BoxCastHit's)
};

/// Where moveAndSlide left the box, and what it met on the way.
struct MoveResult {
    Vec2 centre;
    /// In the order met; bodies met at the same moment in creation order.
    std::vector<MoveHit> hits;
};

/// Moves a box by `translation` the way bump.lua moves its items: the box goes until it
/// runs into a body (the rules of boxCast), then slides along it for the rest of the
/// translation (the part into the body is dropped), and so on. Every body met at the
/// moment of a stop is reported; one met on its side along x and one on its top along y
/// together stop the box. Axis-aligned faces take away one axis each, so among boxes the
/// box stops at most twice. A slope or a curve takes away the part of the motion along its
/// normal: the box slides along a ramp's slope. Where what is left would go into another
/// body the box touches there (a slope meeting a wall), it slides along whichever keeps
/// the most of the motion and goes into neither, or stops in the crease; after 32 stops it
/// stays where the last one left it.
///
/// This is the tool to move a character by hand. Nothing in the world moves: use the
/// result (setPosition of the character's own body, which `filter.ignore` should name,
/// or your own variable). A hit with normal.y < 0 in a y-down world is the floor: the
/// character is grounded. Sensors never stop the box; one-way platforms stop it only on
/// their blocking face.
MoveResult moveAndSlide(const World& world, Vec2 centre, Vec2 half, Vec2 translation,
                        const QueryFilter& filter = {});
/// moveAndSlide of the box rounded by `radius` (boxCast's rounded box): a circle or a
/// capsule rolls over a crest and round a corner where a box would stop.
MoveResult moveAndSlide(const World& world, Vec2 centre, Vec2 half, float radius, Vec2 translation,
                        const QueryFilter& filter = {});

// --- Moving a body by hand, bump.lua's way -----------------------------------------------

/// How a body moved by move() answers a body in its way (bump.lua's responses).
enum class Response : std::uint8_t {
    Slide,  ///< stops going into it and goes on along its face, for the rest of the move
    Touch,  ///< stops where it touches it: the move ends there
    Cross,  ///< goes through it, and reports it (a coin, a trigger)
    Bounce, ///< turns back off its face for the rest of the move, as a ball off a wall
    Ignore, ///< goes through it, unreported
};

/// Chooses the response to each body in the way. Called at most once per body and move,
/// while move() walks the world: it may read the world, not change it. Every call that
/// would change it (createBody, destroyBody, a setter, step, move, a tile map's change)
/// throws jostle::Error from the filter, "...: called from move()'s filter", and changes
/// nothing; destroying the world from it stops the program with a message.
using MoveFilter = std::function<Response(BodyId other)>;

/// A body move() met.
struct MoveCollision {
    BodyId other;
    Response response;
    /// Unit, pointing from `other` towards the moved body (as BoxCastHit's).
    Vec2 normal;
    /// The moved body's centre when it touched `other` (placed exactly against its face).
    Vec2 touch;
    /// When, as a fraction of the whole move, in [0, 1]: the move takes unit time, and
    /// keeps going at the same pace after a slide or a bounce.
    float time = 0.0f;
    /// The other body's box.
    Vec2 otherCentre;
    Vec2 otherHalf;
};

/// Where move() left the body, and what it met.
struct MoveOutcome {
    Vec2 centre;
    /// In the order met; bodies met at the same moment in creation order.
    std::vector<MoveCollision> collisions;
};

/// Moves body `id` by `delta`, the way bump.lua's world:move does, in one call: its box
/// goes from where the body is towards where it would be, and each body it runs into
/// (the rules of boxCast: touching is not running into, a body it is already inside does
/// not stop it, a one-way platform only from its blocking side; and, as in bump.lua, a
/// body reached just as the move ends is not met: the next move into it meets it) answers
/// by `filter`:
/// Slide (the default for solid bodies), Touch, Cross (the default for sensors), Bounce
/// or Ignore. Bodies its category and mask leave out, and the body itself, are never
/// met. The body is put where the move ends (World::setPosition: it wakes what it
/// leaves and what it reaches); its velocity is left alone. After 32 stops the body stays
/// where the last one left it. A rounded body (BodyDef::radius) moves as its shape: a
/// circle rolls round a corner that its box would have caught on; a ramp or a segment
/// moves as its box. Against a slope or a curve, Slide goes on along it (as moveAndSlide)
/// and Bounce is reflected off it; where a bounce or a slide would carry it past the edge
/// of the range of math.hpp, it stops at the edge (that last stretch is not checked against
/// bodies). Throws jostle::Error for a stale `id` or a delta that is not finite, or that
/// carries the body out of the range of math.hpp.
MoveOutcome move(World& world, BodyId id, Vec2 delta, const MoveFilter& filter = {});

JOSTLE_EXPORT_END
} // namespace jostle
