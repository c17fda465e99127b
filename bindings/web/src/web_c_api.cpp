// The few C functions the JavaScript API (page/jostle.js, docs/web.md) needs beside
// jostle.h, whose every function the module exports for jostle.js to call: what jostle.h
// cannot say, a scene file's JSON read into its definitions (the core library, and so
// jostle.h, reads no JSON) and its last error in JavaScript's notation; and the heap in
// use, for the tests.
//
// They keep jostle.h's error contract by its own machinery (src/c_api/misuse.hpp): a
// function that fails returns NULL and records "function: message" for
// jostle_last_error(), calling the error handler if one is set. A reader creates nothing:
// jostle.js gives the definitions it reads to jostle_world_create, jostle_tile_map_create
// and jostle_body_create, which check them as they check a C program's and hand out the
// handles.
#include "c_api/conversions.hpp"
#include "c_api/misuse.hpp"
#include "jostle/jostle.h"
#include "jostle/scene.hpp"
#include "notation.hpp"
#include "web_scene.hpp"

#include <emscripten/emscripten.h>
#include <malloc.h>

#include <cinttypes>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

using namespace jostle;
using namespace jostle::c_api;

namespace {

/// A scene read by jostle_web_read_scene, in jostle.h's definitions, kept until the next
/// read or jostle_web_forget_scene.
struct ReadScene {
    jostle_world_def world{};
    std::vector<jostle_tile_map_def> tileMaps;
    std::vector<std::string> cells; ///< each tile map's rows laid end to end
    std::vector<jostle_body_def> bodies;
};

ReadScene& readScene() {
    static ReadScene scene;
    return scene;
}

/// A scene's tile map in C: its rows laid end to end are the cells (jostle.h's
/// jostle_tile_map_def::cells), kept in `cells`, which must outlive the definition.
jostle_tile_map_def tileMapInC(const TileMapDef& map, std::string& cells) {
    jostle_tile_map_def c = jostle_default_tile_map_def();
    copyToC(map, c, properties::kTileMapFields);
    cells.clear();
    for (const std::string& row : map.rows)
        cells += row;
    c.columns = map.rows.empty() ? 0 : static_cast<int>(map.rows.front().size());
    c.rows = static_cast<int>(map.rows.size());
    c.cells = reinterpret_cast<const unsigned char*>(cells.c_str());
    return c;
}

} // namespace

namespace jostle::web {

std::string& levelObjects() {
    static std::string objects = "[]";
    return objects;
}

const jostle_world_def* keep(const Scene& scene) {
    ReadScene read;
    read.world = toC(scene.world);
    read.cells.resize(scene.tileMaps.size());
    for (std::size_t i = 0; i < scene.tileMaps.size(); ++i)
        read.tileMaps.push_back(tileMapInC(scene.tileMaps[i], read.cells[i]));
    for (const SceneBody& body : scene.bodies)
        read.bodies.push_back(toC(body.def));
    readScene() = std::move(read);
    levelObjects() = "[]";
    return &readScene().world;
}

} // namespace jostle::web

namespace {

/// The loader's message about the one body jostle_web_read_body reads as `bodies[0]` of a
/// scene, as about the definition the game passed: "bodies[0].hw: must be > 0" becomes
/// "hw: must be > 0", "bodies[0]: unknown field "foo"" becomes "unknown field "foo"".
std::string aboutTheDefinition(std::string_view message) {
    if (message.starts_with("bodies[0]")) {
        message.remove_prefix(std::string_view("bodies[0]").size());
        if (message.starts_with("."))
            message.remove_prefix(1);
        else if (message.starts_with(": "))
            message.remove_prefix(2);
    }
    return std::string(message);
}

} // namespace

extern "C" {

/// Reads a scene file's text (docs/scene-format.md) with the scene loader into jostle.h's
/// definitions, kept by the module until the next read or jostle_web_forget_scene: returns
/// the world's (then jostle_web_scene_tile_map and jostle_web_scene_body give the rest),
/// or NULL, the loader's message recorded ("jostle_web_read_scene: bodies[3].hw: must be
/// > 0").
EMSCRIPTEN_KEEPALIVE const jostle_world_def* jostle_web_read_scene(const char* json) {
    return guard<const jostle_world_def*>(__func__, nullptr, [&] {
        required(json, "json");
        return web::keep(parseScene(json));
    });
}

/// Tile map `i` (from 0, in the file's order) of the scene last read, or NULL past the
/// last (not misuse). Its cells live as long as the scene.
EMSCRIPTEN_KEEPALIVE const jostle_tile_map_def* jostle_web_scene_tile_map(int i) {
    const auto& maps = readScene().tileMaps;
    return i >= 0 && static_cast<std::size_t>(i) < maps.size() ? &maps[static_cast<std::size_t>(i)]
                                                               : nullptr;
}

/// Body `i` (from 0, in the file's order) of the scene last read, or NULL past the last
/// (not misuse).
EMSCRIPTEN_KEEPALIVE const jostle_body_def* jostle_web_scene_body(int i) {
    const auto& bodies = readScene().bodies;
    return i >= 0 && static_cast<std::size_t>(i) < bodies.size()
               ? &bodies[static_cast<std::size_t>(i)]
               : nullptr;
}

/// Frees the scene last read.
EMSCRIPTEN_KEEPALIVE void jostle_web_forget_scene() {
    readScene() = ReadScene{};
}

/// Reads a scene file's body object (`{"type": "static", "x": 0, ...}`) with the scene
/// loader, as a body of `world` (whose model may refuse a shape), into a definition for
/// jostle_body_create, kept by the module until the next call; or NULL, the loader's
/// message about the field recorded ("jostle_web_read_body: hw: must be > 0").
EMSCRIPTEN_KEEPALIVE const jostle_body_def* jostle_web_read_body(const jostle_world* world,
                                                                 const char* json) {
    static jostle_body_def def;
    return guard<const jostle_body_def*>(__func__, nullptr, [&] {
        required(world, "world");
        required(json, "json");
        const Solver solver = toCpp(jostle_world_get_solver(world));
        Scene scene;
        try {
            scene = parseScene(std::string(R"({"solver": ")") + toString(solver) +
                               R"(", "bodies": [)" + json + "]}");
        } catch (const SceneError& error) {
            throw SceneError(aboutTheDefinition(error.what()));
        }
        if (scene.bodies.size() != 1)
            misuse("expected one body definition, got " + std::to_string(scene.bodies.size()));
        def = toC(scene.bodies.front().def);
        return &def;
    });
}

/// A body's definition (jostle_body_get_def) as a scene file's body object (bodyToJson),
/// kept by the module until the next call; or NULL, jostle_body_get_def's message recorded.
EMSCRIPTEN_KEEPALIVE const char* jostle_web_body_def(const jostle_world* world, jostle_body_id id) {
    static std::string text;
    const jostle_body_def c = jostle_body_get_def(world, id);
    if (c.internal_cookie != kCookie) // misuse, reported by jostle_body_get_def
        return nullptr;
    return guard<const char*>(__func__, nullptr, [&] {
        text = bodyToJson(fromC<BodyDef>(c, properties::kBodyFields));
        return text.c_str();
    });
}

/// jostle_last_error() in JavaScript's notation (src/notation.hpp): vectors as arrays,
/// [0, -1]; a definition's field as the object holds it, character: true. The same words.
EMSCRIPTEN_KEEPALIVE const char* jostle_web_last_error() {
    static char message[512];
    copyInNotation(jostle_last_error(), Notation::JavaScript, message, sizeof message);
    return message;
}

/// jostle_world_state_hash as 16 hexadecimal digits, as Lua has it: a JavaScript number
/// cannot hold 64 bits, and this module is built without BigInt results. "" on misuse.
EMSCRIPTEN_KEEPALIVE const char* jostle_web_state_hash(const jostle_world* world) {
    static char text[17];
    const std::uint64_t hash = jostle_world_state_hash(world);
    if (hash == 0 && jostle_last_error()[0] != '\0')
        return "";
    std::snprintf(text, sizeof text, "%016" PRIx64, hash);
    return text;
}

/// The bytes the module's heap has handed out and not taken back (mallinfo): for the
/// tests, which check that a world's memory does not grow with its history.
EMSCRIPTEN_KEEPALIVE std::size_t jostle_web_heap_in_use() {
    return static_cast<std::size_t>(mallinfo().uordblks);
}

} // extern "C"
