// shared/scenes.hpp: scenes defined once in code, for the benchmarks, the tests and
// the demo (library jostle::shared).
//
//     #include "shared/scenes.hpp"
//
//     jostle::Scene scene = jostle::shared::pyramid(20);
//     jostle::World world(scene.world);
//     jostle::addBodies(world, scene);
//
// Conventions shared by every scene here:
// - y grows downward; gravity, where there is any, is {0, kGravity}.
// - Lengths are in "box" units: the common box is 1 unit wide (half extent 0.5), and
//   gravity is 10 units/s², so a unit behaves like a metre. That keeps the scenes in the
//   range Box2D 2.4.1 is tuned for (its slop, skin and 2-units-per-step speed cap are
//   fixed lengths), so the benchmark can build the very same scene in it. jostle itself
//   has no preferred unit.
// - Deterministic: the same call gives the same scene, bit for bit, on every standard
//   library (random numbers come from std::mt19937, whose output the standard fixes,
//   mapped to floats by our own formula).
// - Bodies of special interest have ids that say so: the top box of a pyramid is "top"
//   (in many_pyramids "top.0", "top.1", ...). Other bodies keep their index as id.
// - Friction and bounce are the same for every pair that can touch (or one side is 0),
//   so jostle's min, Box2D's geometric mean and Chipmunk's product all give one value.
#pragma once

#include "jostle/scene.hpp"

namespace jostle::shared {

/// Gravity of every scene that falls, downward (y grows downward).
inline constexpr float kGravity = 10.0f;

/// A pyramid of unit boxes, `rows` boxes wide at the base and 1 at the top, standing on a
/// static ground. rows = 20: 210 boxes; rows = 100: 5,050 boxes. rows >= 1.
Scene pyramid(int rows);

/// `count` pyramids of `rows` rows side by side on one static ground, 2 units apart.
/// count >= 1, rows >= 1.
Scene manyPyramids(int count, int rows);

/// `count` boxes of mixed sizes (half extents 0.5 to 2, not square) dropped in loose
/// columns (a quarter unit between boxes) into an open-top container of static boxes,
/// whose floor is about 16 √count units wide. They land within 2 s (10,000) to 3 s
/// (100,000) and settle into a pile about 30 (10,000) to 90 (100,000) boxes deep.
/// count >= 1.
Scene rain(int count);

/// `count` unit boxes in a closed static box, no gravity, friction 0 and bounce 1 for
/// every body, random velocities up to 10 units/s per axis. They start on a grid with
/// three units between centres, so nothing overlaps and about a ninth of the box is
/// filled. count >= 1.
Scene gas(int count);

/// A tile level, 40 tiles high and about `actors / 4` tiles wide (at least 64), made of
/// unit static tiles: a floor, walls at both ends and five layers of platforms. `actors`
/// dynamic boxes (half extent 0.4) stand on the floor and platforms, sliding left or
/// right at 2 to 8 units/s with friction 0, so they keep moving: they run into each
/// other, drop off platform ends and pile up at the walls. 10,000 actors: about
/// 8,000 tiles. actors >= 0.
Scene tilemap(int actors);

/// `count` unit boxes all at one spot, resting on a static ground wide enough for them to
/// spread over: a stress scene (every box overlaps every other), which a game never means
/// to build but a bug or an editor can. count >= 1.
Scene pile(int count);

/// `count` unit boxes standing in a row, a quarter unit apart, on a static floor as long
/// as the row, made of `pieces` equal static boxes: one long body, or the many short ones
/// a tile map makes. A floor that touches thousands of bodies at once costs about what
/// its pieces cost. count >= 1, pieces >= 1.
Scene crowdOnFloor(int count, int pieces);

/// A level as a level editor's object layer gives it: `tiles` unit static boxes, each its
/// own body, laid edge to edge in one floor with a wall at each end, and 16 dynamic boxes
/// (half extent 0.4) sliding along it at 2 to 8 units/s, friction 0, spread over its
/// length: many static bodies, few that move. tiles >= 1.
Scene staticLevel(int tiles);

} // namespace jostle::shared
