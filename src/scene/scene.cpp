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

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace jostle {

namespace {

// ordered_json keeps fields in file order, so that "the first problem" is the first
// one a reader meets in the file, not the first in alphabetical order.
using Json = nlohmann::ordered_json;

// The format needs four levels (scene, tilemaps, tile map, rows); anything much deeper is
// not a scene, and refusing it early bounds the memory spent on hostile input.
constexpr int kMaxDepth = 32;

// Error messages quote what they cite, at most this many bytes of it.
constexpr std::size_t kMaxQuoted = 200;

[[noreturn]] void fail(const std::string& place, const std::string& rule) {
    throw SceneError(place.empty() ? rule : place + ": " + rule);
}

std::string field(const std::string& place, const std::string& name) {
    return place.empty() ? name : place + "." + name;
}

std::string element(const std::string& place, std::size_t index) {
    return place + "[" + std::to_string(index) + "]";
}

/// Cuts `text` to at most kMaxQuoted bytes, never inside a UTF-8 sequence.
std::string clip(std::string text) {
    if (text.size() <= kMaxQuoted)
        return text;
    std::size_t end = kMaxQuoted;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u)
        --end;
    text.resize(end);
    return text + "...";
}

/// A name as JSON spells it, quotes and escapes included, so that odd names stay
/// readable in a one-line message.
std::string quoteName(const std::string& name) {
    return clip(Json(name).dump(-1, ' ', false, Json::error_handler_t::replace));
}

std::string got(const Json& value) {
    return std::string(", got ") + value.type_name();
}

// --- Syntax: parsing with duplicate fields and depth refused -------------------------

/// Follows the parser through the document, knowing the place of the value being read,
/// to refuse with that place what nlohmann-json would accept: a duplicate field (it
/// would keep the last of two, and {"hw": 1, "hw": -1} should not mean whatever the
/// parser picks) and nesting beyond kMaxDepth. It also names the place of a number the
/// parser itself refuses.
class PlaceTracker {
public:
    bool operator()(int depth, Json::parse_event_t event, Json& parsed) {
        switch (event) {
        case Json::parse_event_t::object_start:
        case Json::parse_event_t::array_start:
            if (depth >= kMaxDepth)
                fail(childPlace(), "nested deeper than " + std::to_string(kMaxDepth) + " levels");
            containers_.push_back(
                {childPlace(), event == Json::parse_event_t::object_start, {}, {}, 0});
            break;
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            containers_.pop_back();
            if (!containers_.empty() && !containers_.back().isObject)
                ++containers_.back().elements;
            break;
        case Json::parse_event_t::key: {
            Container& object = containers_.back();
            object.lastKey = parsed.get<std::string>();
            if (!object.keys.insert(object.lastKey).second)
                fail(object.place, "duplicate field " + quoteName(object.lastKey));
            break;
        }
        case Json::parse_event_t::value:
            if (!containers_.empty() && !containers_.back().isObject)
                ++containers_.back().elements;
            break;
        }
        return true; // keep every value
    }

    /// The place of the value being read now.
    std::string childPlace() const {
        if (containers_.empty())
            return "";
        const Container& parent = containers_.back();
        return parent.isObject ? field(parent.place, parent.lastKey)
                               : element(parent.place, parent.elements);
    }

private:
    struct Container {
        std::string place;
        bool isObject;
        std::unordered_set<std::string> keys;
        std::string lastKey;
        std::size_t elements;
    };

    std::vector<Container> containers_;
};

/// The length of the valid UTF-8 sequence at the start of `text`, or 0 if there is none.
std::size_t utf8Length(std::string_view text) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    const std::size_t length = lead < 0x80                    ? 1
                               : lead >= 0xC2 && lead <= 0xDF ? 2
                               : lead >= 0xE0 && lead <= 0xEF ? 3
                               : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                              : 0;
    if (length == 0 || length > text.size())
        return 0;
    for (std::size_t i = 1; i < length; ++i)
        if ((byte(i) & 0xC0u) != 0x80u)
            return 0;
    return length;
}

/// `text` with every byte that is not part of valid UTF-8 spelt as <0xNN>: the parser
/// quotes what it last read, and a message must stay printable text even when the
/// file is binary garbage.
std::string printable(std::string_view text) {
    std::string result;
    while (!text.empty()) {
        std::size_t length = utf8Length(text);
        if (length == 0) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "<0x%02X>",
                          static_cast<unsigned>(static_cast<unsigned char>(text[0])));
            result += escaped;
            length = 1;
        } else {
            result.append(text.substr(0, length));
        }
        text.remove_prefix(length);
    }
    return result;
}

/// "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
/// becomes "invalid JSON at line 2, column 7: syntax error ...".
std::string describe(const nlohmann::json::parse_error& error) {
    std::string message = error.what();
    const std::string marker = "parse error ";
    if (const std::size_t at = message.find(marker); at != std::string::npos)
        message = message.substr(at + marker.size());
    else if (const std::size_t bracket = message.find("] "); bracket != std::string::npos)
        message = ": " + message.substr(bracket + 2);
    // The parser quotes the last token it read, which may be a whole megabyte string.
    return "invalid JSON " + printable(clip(message));
}

Json parseJson(std::string_view text) {
    PlaceTracker tracker;
    try {
        // No comments: a scene file is plain JSON, readable by every other tool.
        return Json::parse(text.begin(), text.end(), std::ref(tracker),
                           /*allow_exceptions=*/true, /*ignore_comments=*/false);
    } catch (const nlohmann::json::parse_error& error) {
        throw SceneError(describe(error));
    } catch (const nlohmann::json::out_of_range& error) {
        // The parser refuses numbers beyond a double (1e400) itself, while reading the
        // value whose place the tracker knows.
        if (error.id == 406)
            fail(tracker.childPlace(), "must be a finite number");
        throw;
    }
}

// --- Values --------------------------------------------------------------------------

float readFloat(const Json& value, const std::string& place) {
    // is_number() is false for booleans: true is not 1 in a scene file.
    if (!value.is_number())
        fail(place, "expected a number" + got(value));
    const double number = value.get<double>();
    // 2^128 - 2^103 is FLT_MAX plus half its ulp: doubles below it round to a finite
    // float, doubles from it up (1e39) to infinity. (The parser refuses 1e400 itself.)
    constexpr double kFloatLimit = 0x1.ffffffp127;
    if (!(std::fabs(number) < kFloatLimit))
        fail(place, "must be a finite number");
    return static_cast<float>(number);
}

Vec2 readVec2(const Json& value, const std::string& place) {
    if (!value.is_array())
        fail(place, "expected an array of 2 numbers" + got(value));
    if (value.size() != 2)
        fail(place, "expected an array of 2 numbers, got " + std::to_string(value.size()) +
                        (value.size() == 1 ? " number" : " numbers"));
    return {readFloat(value[0], element(place, 0)), readFloat(value[1], element(place, 1))};
}

/// Bit fields (category, mask): a whole number from 0 to 2^32 - 1.
std::uint32_t readBits(const Json& value, const std::string& place) {
    if (!value.is_number_integer())
        fail(place, "expected a whole number from 0 to 4294967295" + got(value));
    if (value.is_number_unsigned() ? value.get<std::uint64_t>() > 0xFFFFFFFFull
                                   : value.get<std::int64_t>() < 0)
        fail(place, "must be a whole number from 0 to 4294967295");
    return static_cast<std::uint32_t>(value.get<std::uint64_t>());
}

bool readBool(const Json& value, const std::string& place) {
    if (!value.is_boolean())
        fail(place, "expected true or false" + got(value));
    return value.get<bool>();
}

const std::string& readString(const Json& value, const std::string& place) {
    if (!value.is_string())
        fail(place, "expected a string" + got(value));
    return value.get_ref<const std::string&>();
}

const Json::object_t& readObject(const Json& value, const std::string& place) {
    if (!value.is_object())
        fail(place, "expected an object" + got(value));
    return value.get_ref<const Json::object_t&>();
}

const Json::array_t& readArray(const Json& value, const std::string& place) {
    if (!value.is_array())
        fail(place, "expected an array" + got(value));
    return value.get_ref<const Json::array_t&>();
}

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

/// An int option: a whole number. Those beyond an int are kept as INT_MIN or INT_MAX,
/// which every int option's range (checked by checkWorldDef) refuses.
int readInt(const Json& value, const std::string& place) {
    if (!value.is_number())
        fail(place, "expected a whole number" + got(value));
    const double number = value.get<double>();
    if (number != std::floor(number))
        fail(place, "expected a whole number");
    constexpr double lowest = std::numeric_limits<int>::min();
    constexpr double highest = std::numeric_limits<int>::max();
    return static_cast<int>(std::clamp(number, lowest, highest));
}

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
        return readScene(parseJson(json));
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
    std::vector<TileMapId> ids;
    ids.reserve(scene.tileMaps.size());
    for (const TileMapDef& map : scene.tileMaps)
        ids.push_back(createTileMap(world, map));
    return ids;
}

} // namespace jostle
