// Scene files: JSON text in, a checked jostle::Scene out (docs/scene-format.md).
//
// Every problem becomes a SceneError that names the place ("bodies[3].hw") and the
// rule. The fields of bodies and tile maps are read by their descriptions
// (body_properties.hpp), and the value rules of bodies and worlds are not repeated here:
// checkBodyDef and checkWorldDef are the one source of truth, and this file only adds the
// place. What is checked here is what only a file can get wrong: syntax, types, unknown,
// missing and duplicate fields, numbers a float cannot hold, ids.
#include "jostle/scene.hpp"

#include "body_properties.hpp"
#include "json.hpp"
#include "tile_chars.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace jostle {

namespace {

using namespace json;

BodyType readBodyType(const Json& value, const std::string& place) {
    if (auto type = bodyTypeFromString(readString(value, place)))
        return *type;
    fail(place, R"(expected one of "static", "kinematic", "dynamic")");
}

// --- Definitions: fields by their descriptions (body_properties.hpp) ------------------

// A value of each type a property has; a pointer (userData) has no form in a file.
void readValue(const Json& value, const std::string& place, BodyType& out) {
    out = readBodyType(value, place);
}
void readValue(const Json& value, const std::string& place, float& out) {
    out = readFloat(value, place);
}
void readValue(const Json& value, const std::string& place, Vec2& out) {
    out = readVec2(value, place);
}
void readValue(const Json& value, const std::string& place, bool& out) {
    out = readBool(value, place);
}
void readValue(const Json& value, const std::string& place, std::uint32_t& out) {
    out = readBits(value, place);
}

/// Reads the field `name` of `def`; false if `def` has no field of that name that a file
/// can give.
template <class Def, class F, std::size_t N>
bool readField(Def& def, const F (&fields)[N], const std::string& name, const Json& value,
               const std::string& place) {
    const F* field = properties::find(fields, name);
    auto read = [&](auto member) {
        if constexpr (requires { readValue(value, place, def.*member); }) {
            readValue(value, place, def.*member);
            return true;
        } else {
            return false;
        }
    };
    return field && std::visit(read, field->member);
}

/// Fails unless the object `value` has every field its definition requires, in table order.
template <class F, std::size_t N>
void requireFields(const Json& value, const std::string& place, const F (&fields)[N]) {
    for (const F& field : fields)
        if (field.property->required && !value.contains(field.property->name))
            fail(place, std::string("missing field \"") + field.property->name + "\"");
}

// --- Bodies --------------------------------------------------------------------------

SceneBody readBody(const Json& value, const std::string& place, std::size_t index) {
    const Json::object_t& fields = readObject(value, place);
    SceneBody body;
    body.id = std::to_string(index);

    for (const auto& [name, fieldValue] : fields) {
        const std::string at = field(place, name);
        if (name == "id") {
            body.id = readString(fieldValue, at);
            if (body.id.empty())
                fail(at, "must not be empty");
        } else if (!readField(body.def, properties::kBodyFields, name, fieldValue, at)) {
            fail(place, "unknown field " + quoteName(name));
        }
    }
    requireFields(value, place, properties::kBodyFields); // hw, hh: a box has no default size

    // In a file, 0 is not a way to ask for the density mass (BodyDef's convention):
    // leaving "mass" out is. And a body cannot have both an explicit mass and a density.
    if (value.contains("mass") && value.contains("density"))
        fail(place, R"(give "mass" or "density", not both)");
    if (value.contains("mass") && !(body.def.mass > 0.0f))
        fail(field(place, "mass"), "must be > 0");

    if (auto problem = checkBodyDef(body.def))
        fail(field(place, problem->field), problem->problem);
    return body;
}

std::vector<SceneBody> readBodies(const Json& value, const std::string& place) {
    const Json::array_t& array = readArray(value, place);
    std::vector<SceneBody> bodies;
    bodies.reserve(array.size());
    // Ids name bodies in traces, so two bodies must never share one.
    std::unordered_map<std::string, std::size_t> owners;
    for (std::size_t i = 0; i < array.size(); ++i) {
        const std::string at = element(place, i);
        SceneBody body = readBody(array[i], at, i);
        if (auto [owner, inserted] = owners.try_emplace(body.id, i); !inserted) {
            const bool explicitId = array[i].contains("id");
            fail(explicitId ? field(at, "id") : at,
                 (explicitId ? "" : "its default id ") + quoteName(body.id) +
                     " is already the id of " + element(place, owner->second));
        }
        bodies.push_back(std::move(body));
    }
    return bodies;
}

/// Why a world in the classic model refuses a shape: it has sharp boxes only (createBody,
/// createTileMap, setTile and setSolver refuse the others there).
constexpr const char* kSharpBoxesOnly =
    R"(the classic model has sharp boxes only (solver "classic"))";

/// The first body of `bodies` that a world in the model `solver` refuses, by its place
/// ("bodies[2].radius"). Each body has passed checkBodyDef, so a segment has a slope.
std::optional<FieldError> modelProblem(Solver solver, const std::vector<SceneBody>& bodies) {
    if (solver != Solver::Classic)
        return std::nullopt;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const BodyDef& def = bodies[i].def;
        const char* shape = def.slope != Vec2{} ? "slope" : def.radius > 0.0f ? "radius" : nullptr;
        if (shape)
            return FieldError{field(element("bodies", i), shape), kSharpBoxesOnly};
    }
    return std::nullopt;
}

/// The first ramp tile of `maps` that a world in the model `solver` refuses, by its place:
/// map i is at placeOf(i) ("tilemaps[1]"), its tile at "tilemaps[1].rows[2][5]".
std::optional<FieldError> modelProblem(Solver solver, const std::vector<TileMapDef>& maps,
                                       const std::function<std::string(std::size_t)>& placeOf) {
    if (solver != Solver::Classic)
        return std::nullopt;
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const std::vector<std::string>& rows = maps[i].rows;
        for (std::size_t row = 0; row < rows.size(); ++row)
            for (std::size_t column = 0; column < rows[row].size(); ++column)
                if (rampTile(rows[row][column]))
                    return FieldError{element(element(field(placeOf(i), "rows"), row), column),
                                      kSharpBoxesOnly};
    }
    return std::nullopt;
}

// --- Tile maps -----------------------------------------------------------------------

TileMapDef readTileMap(const Json& value, const std::string& place) {
    TileMapDef def;
    for (const auto& [name, fieldValue] : readObject(value, place)) {
        const std::string at = field(place, name);
        if (name == "rows") {
            const Json::array_t& rows = readArray(fieldValue, at);
            def.rows.reserve(rows.size());
            for (std::size_t i = 0; i < rows.size(); ++i)
                def.rows.push_back(readString(rows[i], element(at, i)));
        } else if (!readField(def, properties::kTileMapFields, name, fieldValue, at)) {
            fail(place, "unknown field " + quoteName(name));
        }
    }
    // A map has no sensible default tile size, nor default tiles.
    requireFields(value, place, properties::kTileMapFields);
    if (!value.contains("rows"))
        fail(place, R"(missing field "rows")");
    if (auto problem = checkTileMapDef(def))
        fail(field(place, problem->field), problem->problem);
    return def;
}

// --- The scene -----------------------------------------------------------------------

FrictionMix readFrictionMix(const Json& value, const std::string& place) {
    if (auto mix = frictionMixFromString(readString(value, place)))
        return *mix;
    fail(place, R"(expected "min" or "geometricMean")");
}

PhysicalOptions readPhysical(const Json& value, const std::string& place) {
    PhysicalOptions options;
    for (const auto& [name, fieldValue] : readObject(value, place)) {
        const std::string at = field(place, name);
        if (name == "velocityIterations")
            options.velocityIterations = readInt(fieldValue, at);
        else if (name == "positionIterations")
            options.positionIterations = readInt(fieldValue, at);
        else if (name == "slop")
            options.slop = readFloat(fieldValue, at);
        else if (name == "correction")
            options.correction = readFloat(fieldValue, at);
        else if (name == "restitutionThreshold")
            options.restitutionThreshold = readFloat(fieldValue, at);
        else if (name == "maxContactsPerBody")
            options.maxContactsPerBody = readInt(fieldValue, at);
        else if (name == "frictionMix")
            options.frictionMix = readFrictionMix(fieldValue, at);
        else
            fail(place, "unknown field " + quoteName(name));
    }
    return options;
}

ClassicOptions readClassic(const Json& value, const std::string& place) {
    ClassicOptions options;
    for (const auto& [name, fieldValue] : readObject(value, place)) {
        if (name == "mass")
            options.mass = readBool(fieldValue, field(place, name));
        else if (name == "coulomb")
            options.coulomb = readBool(fieldValue, field(place, name));
        else if (name == "ccd")
            options.ccd = readBool(fieldValue, field(place, name));
        else
            fail(place, "unknown field " + quoteName(name));
    }
    return options;
}

Scene readScene(const Json& root) {
    if (!root.is_object())
        fail("", "expected an object at the top level" + got(root));

    Scene scene; // WorldDef's defaults are the scene's defaults
    for (const auto& [name, value] : root.get_ref<const Json::object_t&>()) {
        if (name == "gravity") {
            scene.world.gravity = readVec2(value, name);
        } else if (name == "maxVelocity") {
            scene.world.maxVelocity = readFloat(value, name);
        } else if (name == "dt") {
            scene.dt = readFloat(value, name);
            if (!(scene.dt > 0.0f))
                fail(name, "must be > 0");
            if (scene.dt < kMinMagnitude || scene.dt > kMaxMagnitude)
                fail(name, "must be in [1e-9, 1e9]"); // what World::step accepts
        } else if (name == "solver") {
            auto solver = solverFromString(readString(value, name));
            if (!solver)
                fail(name, R"(expected "classic" or "physical")");
            scene.world.solver = *solver;
        } else if (name == "classic") {
            scene.world.classic = readClassic(value, name);
        } else if (name == "physical") {
            scene.world.physical = readPhysical(value, name);
        } else if (name == "sleeping") {
            scene.world.sleeping = readBool(value, name);
        } else if (name == "bodies") {
            scene.bodies = readBodies(value, name);
        } else if (name == "tilemap" || name == "tilemaps") {
            // One map or several: two ways to say it, never both in one file.
            if (root.contains("tilemap") && root.contains("tilemaps"))
                fail("", R"(give "tilemap" or "tilemaps", not both)");
            if (name == "tilemap") {
                scene.tileMaps.push_back(readTileMap(value, name));
            } else {
                const Json::array_t& maps = readArray(value, name);
                for (std::size_t i = 0; i < maps.size(); ++i)
                    scene.tileMaps.push_back(readTileMap(maps[i], element(name, i)));
            }
        } else {
            fail("", "unknown field " + quoteName(name));
        }
    }
    if (!root.contains("bodies"))
        fail("", R"(missing field "bodies")");
    if (auto problem = checkWorldDef(scene.world))
        fail(problem->field, problem->problem);
    // Only now is the model known ("solver" may come last); its problems are looked for
    // in file order, bodies and tile maps alike.
    for (const auto& entry : root.get_ref<const Json::object_t&>()) {
        const std::string& name = entry.first;
        std::optional<FieldError> problem;
        if (name == "bodies")
            problem = modelProblem(scene.world.solver, scene.bodies);
        else if (name == "tilemap" || name == "tilemaps")
            problem = modelProblem(scene.world.solver, scene.tileMaps, [&](std::size_t i) {
                return name == "tilemap" ? name : element(name, i);
            });
        if (problem)
            fail(problem->field, problem->problem);
    }
    return scene;
}

/// The whole file, or a SceneError saying why not (in the words of the system).
std::string readFile(const std::string& path) {
    const auto cannotRead = [&](int error) {
        fail(path, "cannot read: " + std::error_code(error, std::generic_category()).message());
    };
    struct Closer {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    errno = 0;
    std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        cannotRead(errno);
    std::string text;
    char buffer[1 << 16];
    while (std::size_t count = std::fread(buffer, 1, sizeof buffer, file.get()))
        text.append(buffer, count);
    // Opening a directory succeeds; reading it is where EISDIR shows.
    if (std::ferror(file.get()))
        cannotRead(errno);
    return text;
}

} // namespace

Scene parseScene(std::string_view json) {
    try {
        return readScene(json::parse(json));
    } catch (const SceneError&) {
        throw;
    } catch (const nlohmann::json::exception& error) {
        // Every path above checks types first, so this is a bug; still, the promise is
        // that bad input gives a SceneError, never something else.
        throw SceneError(std::string("invalid scene: ") + error.what());
    }
}

Scene loadScene(const std::string& path) {
    const std::string text = readFile(path);
    try {
        return parseScene(text);
    } catch (const SceneError& error) {
        throw SceneError(path + ": " + error.what());
    }
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
