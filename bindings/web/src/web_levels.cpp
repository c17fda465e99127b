// Levels for JavaScript (docs/javascript.md, docs/levels.md): a Tiled map's or an LDtk
// project's JSON text read by the level library into jostle.h's definitions, kept as a
// scene file's are (web_scene.hpp) for the package to create, and its objects as JSON. In
// the game module only: the page loads no levels.
#include "c_api/misuse.hpp"
#include "jostle/level.hpp"
#include "scene/json.hpp"
#include "web_scene.hpp"

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include <string>

using namespace jostle;
using namespace jostle::c_api;

namespace {

/// The scene loader's JSON type, which the level readers use too: nlohmann-json's code is
/// in the module once for each type used.
using json::Json;

/// Keeps a level: its scene, and its objects as JSON.
const jostle_world_def* keepLevel(const Level& level) {
    const jostle_world_def* world = web::keep(level.scene);
    Json objects = Json::array();
    for (const LevelObject& o : level.objects) {
        Json properties = Json::object();
        for (const auto& property : o.properties)
            std::visit([&](const auto& v) { properties[property.first] = v; }, property.second);
        objects.push_back({{"name", o.name},
                           {"type", o.type},
                           {"layer", o.layer},
                           {"id", o.id},
                           {"x", o.x},
                           {"y", o.y},
                           {"hw", o.hw},
                           {"hh", o.hh},
                           {"properties", properties},
                           {"body", o.body},
                           {"bodyCount", o.bodyCount}});
    }
    web::levelObjects() = objects.dump(-1, ' ', false, Json::error_handler_t::replace);
    return world;
}

/// The files a level names, from a JSON object of their texts by path.
FileReader filesIn(const char* files) {
    required(files, "files");
    const Json texts = Json::parse(files);
    return [texts](const std::string& path) -> std::string {
        if (!texts.contains(path) || !texts[path].is_string())
            throw SceneError(path + ": not given (pass its text in files)");
        return texts[path].get<std::string>();
    };
}

} // namespace

extern "C" {

/// Reads a Tiled map's JSON text (.tmj; docs/levels.md) as jostle_web_read_scene reads a
/// scene, `name` naming it in errors, `files` a JSON object of the texts of the files it
/// names (external tilesets) by their paths; its objects then in jostle_web_level_objects.
/// NULL on a problem, the reader's message recorded.
EMSCRIPTEN_KEEPALIVE const jostle_world_def*
jostle_web_read_tiled(const char* text, const char* name, const char* files) {
    return guard<const jostle_world_def*>(__func__, nullptr, [&] {
        required(text, "text");
        required(name, "name");
        return keepLevel(parseTiled(text, name, filesIn(files)));
    });
}

/// Reads level `level` of an LDtk project's text, as jostle_web_read_tiled; `kinds` a JSON
/// object of IntGrid values' kinds ({"4": "none"}).
EMSCRIPTEN_KEEPALIVE const jostle_world_def*
jostle_web_read_ldtk(const char* text, const char* name, const char* level, const char* files,
                     const char* kinds) {
    return guard<const jostle_world_def*>(__func__, nullptr, [&] {
        required(text, "text");
        required(name, "name");
        required(level, "level");
        required(kinds, "kinds");
        IntGridKinds table;
        const Json given = Json::parse(kinds);
        for (const auto& [value, kind] : given.items())
            table[std::stoi(value)] = kind.get<std::string>();
        return keepLevel(parseLdtk(text, name, level, filesIn(files), table));
    });
}

/// The objects of the level last read, as a JSON array: {name, type, layer, id, x, y, hw,
/// hh, properties, body, bodyCount}, body the index of its first body in the scene or -1.
EMSCRIPTEN_KEEPALIVE const char* jostle_web_level_objects() {
    return web::levelObjects().c_str();
}

} // extern "C"
