// The module's surface for a game written in JavaScript (docs/web.md, wrapped by
// jostle.js as jostle.World): worlds made from scene files, bodies from the scene
// format's body objects, steps, and reads into the module's memory. A world is a number,
// a body is a number within its world; an error returns -1 and leaves its message for
// jostle_game_error, which jostle.js throws. jostle.js checks the kind of every argument
// before it calls here (an integer, a finite number, an object); what is checked here is
// what only the module knows: whether a body is alive, and the rules of jostle itself.
#include "jostle/scene.hpp"
#include "jostle/world.hpp"

#include <emscripten/emscripten.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace jostle::web {

namespace {

struct GameWorld {
    std::unique_ptr<World> world;
    std::vector<BodyId> bodies; ///< by the number the game was given
};

struct Games {
    std::vector<std::unique_ptr<GameWorld>> worlds; ///< by number; null once destroyed
    std::vector<float> out;
    std::string error;
};

Games& games() {
    static Games instance;
    return instance;
}

GameWorld& worldAt(int number) {
    auto& worlds = games().worlds;
    if (number < 0 || static_cast<std::size_t>(number) >= worlds.size() ||
        worlds[static_cast<std::size_t>(number)] == nullptr)
        throw Error("no such world: " + std::to_string(number));
    return *worlds[static_cast<std::size_t>(number)];
}

BodyId bodyAt(const GameWorld& game, int number) {
    if (number < 0 || static_cast<std::size_t>(number) >= game.bodies.size() ||
        !game.world->isValid(game.bodies[static_cast<std::size_t>(number)]))
        throw Error("no such body: " + std::to_string(number));
    return game.bodies[static_cast<std::size_t>(number)];
}

/// The loader's message about the one body jostle_game_body_create wraps as `bodies[0]`
/// of a scene, as about the definition the game passed: "bodies[0].hw: must be > 0"
/// becomes "hw: must be > 0", "bodies[0]: unknown field "foo"" becomes "unknown field
/// "foo"" (and addBodies' "addBodies: bodies[0].radius: ..." becomes "radius: ...").
std::string aboutTheDefinition(std::string_view message) {
    if (message.starts_with("addBodies: "))
        message.remove_prefix(std::string_view("addBodies: ").size());
    if (message.starts_with("bodies[0]")) {
        message.remove_prefix(std::string_view("bodies[0]").size());
        if (message.starts_with("."))
            message.remove_prefix(1);
        else if (message.starts_with(": "))
            message.remove_prefix(2);
    }
    return std::string(message);
}

/// Runs `call`, turning an exception into `failed` and its message into the error.
template <class Call, class Result> Result guarded(Call&& call, Result failed) {
    try {
        games().error.clear();
        return call();
    } catch (const std::exception& error) {
        games().error = error.what();
        return failed;
    }
}

} // namespace

} // namespace jostle::web

using namespace jostle;
using namespace jostle::web;

extern "C" {

/// The message of the last call that failed ("" after one that succeeded).
EMSCRIPTEN_KEEPALIVE const char* jostle_game_error() {
    return games().error.c_str();
}

/// A world from a scene file's text (docs/scene-format.md), its bodies numbered from 0 in
/// the file's order. Returns the world's number, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_world_create(const char* sceneJson) {
    return guarded(
        [&] {
            const Scene scene = parseScene(sceneJson);
            auto game = std::make_unique<GameWorld>();
            game->world = std::make_unique<World>(scene.world);
            addTileMaps(*game->world, scene);
            game->bodies = addBodies(*game->world, scene);
            games().worlds.push_back(std::move(game));
            return static_cast<int>(games().worlds.size() - 1);
        },
        -1);
}

/// Frees a world. Returns 0, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_world_destroy(int world) {
    return guarded(
        [&] {
            worldAt(world);
            games().worlds[static_cast<std::size_t>(world)].reset();
            return 0;
        },
        -1);
}

/// A body from a scene file's body object (`{"type": "dynamic", "x": 0, ...}`), checked
/// as the loader checks it; a problem is named by the field alone ("hw: must be > 0").
/// Returns the body's number, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_body_create(int world, const char* bodyJson) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            try {
                const Scene scene = parseScene(std::string(R"({"bodies": [)") + bodyJson + "]}");
                if (scene.bodies.size() != 1)
                    throw Error("expected one body definition, got " +
                                std::to_string(scene.bodies.size()));
                game.bodies.push_back(addBodies(*game.world, scene).front());
                return static_cast<int>(game.bodies.size() - 1);
            } catch (const std::exception& error) {
                throw Error(aboutTheDefinition(error.what()));
            }
        },
        -1);
}

/// Destroys a body. Returns 0, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_body_destroy(int world, int body) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->destroyBody(bodyAt(game, body));
            return 0;
        },
        -1);
}

EMSCRIPTEN_KEEPALIVE int jostle_game_step(int world, float dt) {
    return guarded(
        [&] {
            worldAt(world).world->step(dt);
            return 0;
        },
        -1);
}

/// The float buffer the last read wrote.
EMSCRIPTEN_KEEPALIVE const float* jostle_game_data() {
    return games().out.data();
}

/// Every body the game made that still exists, 5 floats each: its number, centre x, y,
/// half extents hw, hh. Returns the count, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_read_boxes(int world) {
    return guarded(
        [&] {
            const GameWorld& game = worldAt(world);
            std::vector<float>& out = games().out;
            out.clear();
            for (std::size_t i = 0; i < game.bodies.size(); ++i) {
                if (!game.world->isValid(game.bodies[i]))
                    continue;
                const Vec2 at = game.world->position(game.bodies[i]);
                const Vec2 half = game.world->halfExtents(game.bodies[i]);
                out.insert(out.end(), {static_cast<float>(i), at.x, at.y, half.x, half.y});
            }
            return static_cast<int>(out.size() / 5);
        },
        -1);
}

/// One body: centre x, y, velocity x, y, and what it touched in the last step (1 floor,
/// 2 ceiling, 4 left wall, 8 right wall). Returns 5, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_read_body(int world, int body) {
    return guarded(
        [&] {
            const GameWorld& game = worldAt(world);
            const BodyId id = bodyAt(game, body);
            const Vec2 at = game.world->position(id);
            const Vec2 velocity = game.world->velocity(id);
            const Touching t = game.world->touching(id);
            const int touching = (t.floor ? 1 : 0) | (t.ceiling ? 2 : 0) | (t.wallLeft ? 4 : 0) |
                                 (t.wallRight ? 8 : 0);
            games().out = {at.x, at.y, velocity.x, velocity.y, static_cast<float>(touching)};
            return 5;
        },
        -1);
}

EMSCRIPTEN_KEEPALIVE int jostle_game_set_velocity(int world, int body, float vx, float vy) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->setVelocity(bodyAt(game, body), {vx, vy});
            return 0;
        },
        -1);
}

EMSCRIPTEN_KEEPALIVE int jostle_game_set_position(int world, int body, float x, float y) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->setPosition(bodyAt(game, body), {x, y});
            return 0;
        },
        -1);
}

EMSCRIPTEN_KEEPALIVE int jostle_game_apply_impulse(int world, int body, float ix, float iy) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->applyImpulse(bodyAt(game, body), {ix, iy});
            return 0;
        },
        -1);
}

/// A character's walk speed along what it stands on (docs/characters.md).
EMSCRIPTEN_KEEPALIVE int jostle_game_set_walk_speed(int world, int body, float speed) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->setWalkSpeed(bodyAt(game, body), speed);
            return 0;
        },
        -1);
}

/// Lets the body fall through one-way platforms for `seconds`.
EMSCRIPTEN_KEEPALIVE int jostle_game_drop_through(int world, int body, float seconds) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->dropThrough(bodyAt(game, body), seconds);
            return 0;
        },
        -1);
}

} // extern "C"
