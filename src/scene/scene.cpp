// Scene files: JSON text in, a checked jostle::Scene out (docs/scene-format.md); scenes
// added to worlds; a body written back. The reader is scene_reader.cpp.
#include "jostle/scene.hpp"

#include "definition_fields.hpp"
#include "json.hpp"
#include "model_rules.hpp"
#include "scene_reader.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace jostle {

using json::element;
using scene_file::modelProblem;
using scene_file::readScene;

Scene parseScene(std::string_view json) {
    if (json.size() > kMaxSceneBytes)
        throw SceneError(json::tooLarge());
    json::Input input(json);
    return readScene(input);
}

Scene loadScene(const std::string& path) {
    try {
        // A regular file says its size: one too large is refused before it is read. Others
        // (a pipe) are refused when they pass the limit.
        std::error_code error;
        if (std::filesystem::is_regular_file(path, error) &&
            std::filesystem::file_size(path, error) > kMaxSceneBytes && !error)
            throw SceneError(json::tooLarge());
        struct Closer {
            void operator()(std::FILE* file) const { std::fclose(file); }
        };
        errno = 0;
        std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rb"));
        if (!file)
            throw SceneError("cannot read: " +
                             std::error_code(errno, std::generic_category()).message());
        json::Input input(file.get());
        return readScene(input);
    } catch (const SceneError& error) {
        throw SceneError(path + ": " + error.what());
    } catch (const std::bad_alloc&) {
        throw SceneError(path + ": cannot load: out of memory");
    }
}

std::string bodyToJson(const BodyDef& def) {
    json::Json fields = scene_file::fileFields(def, properties::kBodyFields);
    fields.erase(def.mass > 0.0f ? properties::kDensity.name : properties::kMass.name);
    return fields.dump();
}

std::vector<BodyId> addBodies(World& world, const Scene& scene) {
    // Check every body before creating any, so that a bad one leaves the world as it was.
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (auto problem = checkBodyDef(scene.bodies[i].def))
            throw Error("addBodies: " + element("bodies", i) + "." + problem->field + ": " +
                        problem->problem);
    if (auto problem = modelProblem(world.solver(), scene.bodies))
        throw Error("addBodies: " + problem->field + ": " + problem->problem);
    std::vector<BodyId> ids;
    ids.reserve(scene.bodies.size());
    for (const SceneBody& body : scene.bodies)
        ids.push_back(world.createBody(body.def));
    return ids;
}

std::vector<TileMapId> addTileMaps(World& world, const Scene& scene) {
    // Check every map before creating any, so that a bad one leaves the world as it was.
    for (std::size_t i = 0; i < scene.tileMaps.size(); ++i)
        if (auto problem = checkTileMapDef(scene.tileMaps[i]))
            throw Error("addTileMaps: " + element("tileMaps", i) + "." + problem->field + ": " +
                        problem->problem);
    if (auto problem = modelProblem(world.solver(), scene.tileMaps,
                                    [](std::size_t i) { return element("tileMaps", i); }))
        throw Error("addTileMaps: " + problem->field + ": " + problem->problem);
    std::vector<TileMapId> ids;
    ids.reserve(scene.tileMaps.size());
    for (const TileMapDef& map : scene.tileMaps)
        ids.push_back(createTileMap(world, map));
    return ids;
}

} // namespace jostle
