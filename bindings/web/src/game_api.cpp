// The module's surface for a game written in JavaScript (docs/web.md, wrapped by
// jostle.js as jostle.World): worlds made from scene files, bodies from the scene
// format's body objects, steps, and reads into the module's memory. A world is a number,
// a body is a number within its world; an error returns -1 and leaves its message for
// jostle_game_error, which jostle.js throws. jostle.js checks the kind of every argument
// before it calls here (an integer, a finite number, an object); what is checked here is
// what only the module knows: whether a body is alive, and the rules of jostle itself.
//
// Body numbers are the indices of a table, reused: a number names its body until the body
// is destroyed, and createBody gives the smallest number no live body has. So the table
// is as long as the most bodies alive at once, and what a world costs does not grow with
// the bodies it made and destroyed. A destroyed body's number is refused until it is
// given again, and then names the new body (docs/web.md).
#include "jostle/scene.hpp"
#include "jostle/world.hpp"
#include "notation.hpp"

#include <emscripten/emscripten.h>
#include <malloc.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <string>
#include <string_view>
#include <vector>

namespace jostle::web {

namespace {

/// What boxes() reads of a body: its number, exact, and its centre and half extents.
struct GameBox {
    std::int32_t body;
    float x, y, hw, hh;
};
static_assert(sizeof(GameBox) == 5 * 4, "jostle.js reads five 32-bit words a body");

struct GameWorld {
    std::unique_ptr<World> world;
    std::vector<BodyId> bodies; ///< by number; the null handle where no live body has it
    /// The numbers below bodies.size() that no live body has, smallest on top.
    std::priority_queue<std::int32_t, std::vector<std::int32_t>, std::greater<>> free;
    /// A body's number by its handle's slot (BodyId::index); -1 for the world's other
    /// bodies (a tile map's boxes) and for empty slots.
    std::vector<std::int32_t> numberOfSlot;
};

struct Games {
    std::vector<std::unique_ptr<GameWorld>> worlds; ///< by number; null where none
    std::vector<float> out;                         ///< what jostle_game_read_body wrote
    std::vector<GameBox> boxes;                     ///< what jostle_game_read_boxes wrote
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

/// Gives `id`, a body just made, the smallest number no live body has. (Numbers fit an
/// int32_t: a body takes more than two bytes of the module's 4 GiB at most.)
std::int32_t giveNumber(GameWorld& game, BodyId id) {
    std::int32_t number = static_cast<std::int32_t>(game.bodies.size());
    if (game.free.empty())
        game.bodies.emplace_back();
    else {
        number = game.free.top();
        game.free.pop();
    }
    game.bodies[static_cast<std::size_t>(number)] = id;
    if (id.index >= game.numberOfSlot.size())
        game.numberOfSlot.resize(std::size_t{id.index} + 1, -1);
    game.numberOfSlot[id.index] = number;
    return number;
}

/// Takes back the number of a body just destroyed, for the next body made.
void takeBackNumber(GameWorld& game, std::int32_t number) {
    BodyId& id = game.bodies[static_cast<std::size_t>(number)];
    game.numberOfSlot[id.index] = -1;
    id = BodyId{};
    game.free.push(number);
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

/// Runs `call`, turning an exception into `failed` and its message into the error: the
/// C++ library's rules (jostle::Error) in JavaScript's notation (src/notation.hpp: [0, -1],
/// "character: true"), the scene loader's (SceneError) as they are, in JSON's already.
template <class Call, class Result> Result guarded(Call&& call, Result failed) {
    try {
        games().error.clear();
        return call();
    } catch (const Error& error) {
        games().error = inNotation(error.what(), Notation::JavaScript);
    } catch (const std::exception& error) {
        games().error = error.what();
    }
    return failed;
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
/// the file's order. Returns the world's number (the smallest no world has), or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_world_create(const char* sceneJson) {
    return guarded(
        [&] {
            const Scene scene = parseScene(sceneJson);
            auto game = std::make_unique<GameWorld>();
            game->world = std::make_unique<World>(scene.world);
            addTileMaps(*game->world, scene);
            for (const BodyId body : addBodies(*game->world, scene))
                giveNumber(*game, body);
            auto& worlds = games().worlds;
            std::size_t number = 0;
            while (number < worlds.size() && worlds[number] != nullptr)
                ++number;
            if (number == worlds.size())
                worlds.emplace_back();
            worlds[number] = std::move(game);
            return static_cast<int>(number);
        },
        -1);
}

/// Frees a world; its number may be given to a later world. Returns 0, or -1.
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
/// Returns the body's number, the smallest no live body has, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_body_create(int world, const char* bodyJson) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            try {
                const Scene scene = parseScene(std::string(R"({"bodies": [)") + bodyJson + "]}");
                if (scene.bodies.size() != 1)
                    throw Error("expected one body definition, got " +
                                std::to_string(scene.bodies.size()));
                return giveNumber(game, addBodies(*game.world, scene).front());
            } catch (const SceneError& error) {
                throw SceneError(aboutTheDefinition(error.what()));
            } catch (const std::exception& error) {
                throw Error(aboutTheDefinition(error.what()));
            }
        },
        -1);
}

/// Destroys a body; its number may be given to a later body. Returns 0, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_body_destroy(int world, int body) {
    return guarded(
        [&] {
            GameWorld& game = worldAt(world);
            game.world->destroyBody(bodyAt(game, body));
            takeBackNumber(game, body);
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

/// The float buffer jostle_game_read_body wrote.
EMSCRIPTEN_KEEPALIVE const float* jostle_game_data() {
    return games().out.data();
}

/// The boxes jostle_game_read_boxes wrote, five 32-bit words each: the body's number (an
/// int32), its centre x, y and half extents hw, hh (floats).
EMSCRIPTEN_KEEPALIVE const GameBox* jostle_game_boxes() {
    return games().boxes.data();
}

/// Every body the game made that is alive, in creation order, into jostle_game_boxes:
/// in time proportional to the world's live bodies. Returns the count, or -1.
EMSCRIPTEN_KEEPALIVE int jostle_game_read_boxes(int world) {
    return guarded(
        [&] {
            const GameWorld& game = worldAt(world);
            std::vector<GameBox>& out = games().boxes;
            out.clear();
            for (const BodyId id : game.world->bodies()) {
                const std::int32_t number =
                    id.index < game.numberOfSlot.size() ? game.numberOfSlot[id.index] : -1;
                if (number < 0)
                    continue;
                const Vec2 at = game.world->position(id);
                const Vec2 half = game.world->halfExtents(id);
                out.push_back({number, at.x, at.y, half.x, half.y});
            }
            return static_cast<int>(out.size());
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

/// The bytes the module's heap has handed out and not taken back (mallinfo): for the
/// tests, which check that a world's memory does not grow with its history.
EMSCRIPTEN_KEEPALIVE std::size_t jostle_game_heap_in_use() {
    return static_cast<std::size_t>(mallinfo().uordblks);
}

} // extern "C"
