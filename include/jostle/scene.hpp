// jostle/scene.hpp: scene files, the JSON description of a world and its bodies.
//
// Part of the jostle::scene library (it reads JSON with nlohmann-json); the core
// library does not need it. The format is a contract: docs/scene-format.md.
//
//     jostle::Scene scene = jostle::loadScene("examples/scenes/tutorial.json");
//     jostle::World world(scene.world);
//     jostle::addTileMaps(world, scene);
//     std::vector<jostle::BodyId> ids = jostle::addBodies(world, scene);
//     world.step(scene.dt);
#pragma once

#include "jostle/tilemap.hpp"
#include "jostle/visibility.h"
#include "jostle/world.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace jostle {
JOSTLE_EXPORT_BEGIN

/// A body of a scene: its definition and the name it goes by in traces.
struct SceneBody {
    std::string id; ///< "id" in the file; defaults to the body's index ("0", "1", ...)
    BodyDef def;
};

struct Scene {
    WorldDef world;
    float dt = 1.0f / 60.0f; ///< the time step the scene is meant to run at
    std::vector<SceneBody> bodies;
    /// "tilemap" (one) or "tilemaps" (several) in the file, in file order.
    std::vector<TileMapDef> tileMaps;
};

/// A scene file that cannot be used. what() names the place and the rule, e.g.
/// "bodies[3].hw: must be > 0", "tilemap.rows[2][5]: expected '#', '.' or a ramp, got 'x'" or
/// "gravity: expected an array of 2 numbers".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The longest scene file, in bytes: 1 GiB. Loading reads a file as it goes: it holds the
/// scene, and of the text only what the parser holds (a string being read, a run of
/// whitespace and brackets between two strings or numbers).
inline constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 30;

/// Reads a scene from JSON text of at most kMaxSceneBytes. Throws SceneError.
Scene parseScene(std::string_view json);

/// Reads a scene file: a regular file, or anything that can be read to its end (a pipe,
/// /dev/stdin), of at most kMaxSceneBytes. Throws SceneError whose what() starts with
/// the path (also when the file cannot be read, or is too large).
Scene loadScene(const std::string& path);

/// A body's definition as a scene file's body object, `{"type": "dynamic", "x": 0, ...}`:
/// every field a file holds (all but userData), mass or density as the body uses them (mass
/// if it is > 0, else density). Read back in a scene's "bodies", it gives `def` again.
std::string bodyToJson(const BodyDef& def);

/// Creates the scene's bodies in `world`, in file order; returns their handles. After
/// addTileMaps, as every loader of jostle does (C's jostle_level_create_world, Lua,
/// JavaScript, `jostle run`): the order makes the slots, so two programs that add a
/// scene the same way make the same world, to the state hash.
std::vector<BodyId> addBodies(World& world, const Scene& scene);

/// Creates the scene's tile maps in `world`, in file order; returns their handles.
/// Checks every map before creating any, so that a bad one (in a Scene built in code), or
/// a ramp tile in a world of the classic model ("addTileMaps: tileMaps[0].rows[2][5]: the
/// classic model has sharp boxes only (solver \"classic\")"), throws jostle::Error and
/// leaves the world as it was.
std::vector<TileMapId> addTileMaps(World& world, const Scene& scene);

JOSTLE_EXPORT_END
} // namespace jostle
