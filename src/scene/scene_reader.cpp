// Scene files: the reader of the parser's events (scene_reader.hpp).
//
// Every problem becomes a SceneError that names the place ("bodies[3].hw") and the
// rule. The fields of bodies and tile maps are read by their descriptions
// (definition_fields.hpp), and the value rules of bodies and worlds are not repeated here:
// checkBodyDef and checkWorldDef are the one source of truth, and this file only adds the
// place. What is checked here is what only a file can get wrong: syntax, types, unknown,
// missing and duplicate fields, numbers a float cannot hold, ids.
#include "scene_reader.hpp"

#include "definition_fields.hpp"
#include "id_table.hpp"
#include "model_rules.hpp"
#include "tile_chars.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace jostle::scene_file {

namespace {

// --- Reading the parser's events ------------------------------------------------------

/// The format needs four levels (scene, tilemaps, tile map, rows); anything much deeper is
/// not a scene, and refusing it early bounds what hostile input costs.
constexpr std::size_t kMaxDepth = 32;

/// The fields of the top level, and of "classic" and "physical", by index.
constexpr std::string_view kSceneFields[] = {"gravity", "maxVelocity", "dt",       "solver",
                                             "classic", "physical",    "sleeping", "bodies",
                                             "tilemap", "tilemaps"};
enum SceneField : std::size_t {
    kGravity,
    kMaxVelocity,
    kDt,
    kSolver,
    kClassic,
    kPhysical,
    kSleeping,
    kBodies,
    kTileMap,
    kTileMaps
};
constexpr std::string_view kClassicFields[] = {"mass", "coulomb", "ccd"};
constexpr std::string_view kPhysicalFields[] = {
    "velocityIterations", "positionIterations", "slop", "correction", "restitutionThreshold",
    "frictionMix",        "maxContactsPerBody"};
/// A body's "id" and a tile map's "rows", after the fields of their definitions.
constexpr std::size_t kIdField = std::size(properties::kBodyFields);
constexpr std::size_t kRowsField = std::size(properties::kTileMapFields);
static_assert(kIdField < 64 && kRowsField < 64, "Frame::given has a bit for each field");

/// What belongs at a place of the file, and so what the reader does with the value there.
enum class Kind : std::uint8_t {
    Scene,    ///< the top-level object
    Classic,  ///< "classic"
    Physical, ///< "physical"
    Body,     ///< an element of "bodies"
    TileMap,  ///< "tilemap", an element of "tilemaps"
    Bodies,   ///< "bodies"
    TileMaps, ///< "tilemaps"
    Rows,     ///< a tile map's "rows"
    Vec2,     ///< an array of 2 numbers (gravity, oneWay, slope)
    Scalar,   ///< a number, string, boolean (never a container)
    Skip,     ///< a container where none or another belongs: read to its end, kept empty
};

/// What the value of each field of kSceneFields is.
constexpr Kind kSceneFieldKinds[] = {Kind::Vec2,    Kind::Scalar,   Kind::Scalar, Kind::Scalar,
                                     Kind::Classic, Kind::Physical, Kind::Scalar, Kind::Bodies,
                                     Kind::TileMap, Kind::TileMaps};
static_assert(std::size(kSceneFieldKinds) == std::size(kSceneFields));

bool isObjectKind(Kind kind) {
    return kind == Kind::Scene || kind == Kind::Classic || kind == Kind::Physical ||
           kind == Kind::Body || kind == Kind::TileMap;
}

bool isArrayKind(Kind kind) {
    return kind == Kind::Bodies || kind == Kind::TileMaps || kind == Kind::Rows ||
           kind == Kind::Vec2;
}

/// A name as part of a place: as it is if it is a plain word, else quoted as JSON.
std::string placeName(const std::string& name) {
    const bool plain = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_';
    });
    return plain ? name : quoteName(name);
}

/// An object or array being read: where it is, what it is, and what has been read of it.
struct Frame {
    Kind kind = Kind::Skip;
    bool object = false; ///< an object, else an array
    std::string place;
    // An object's:
    std::size_t field = kNone; ///< the index of the field whose value comes next
    std::string key;           ///< its name
    std::uint64_t given = 0;   ///< bit i: field i was given
    // An array's:
    std::size_t count = 0; ///< the elements read so far
    // A Vec2's first two elements.
    Json elements[2];
    // A body's and a tile map's definition, as read so far.
    SceneBody body;
    TileMapDef map;

    bool has(std::size_t index) const { return index != kNone && (given >> index & 1u) != 0; }
};

/// Reads a scene from the parser's events as they come, keeping only what the scene keeps:
/// each body and tile map is checked when its object ends, a field that does not belong is
/// refused at its name, and a value of the wrong type is read to its end (for its syntax)
/// but not kept. So memory is that of the scene, and the first problem reported is the
/// first in the file: a value's own problems when the value ends, an object's (missing
/// fields, rules between fields, checkBodyDef) when the object ends, the whole file's
/// (missing "bodies", checkWorldDef, the model's shapes) at the end of the text.
class SceneReader final : public nlohmann::json_sax<Json> {
public:
    explicit SceneReader(const Input& input) : input_(input) {}

    /// The scene, after json::parse has read the whole text without a problem.
    Scene finish();

    bool null() override { return value(Json()); }
    bool boolean(bool v) override { return value(Json(v)); }
    bool number_integer(number_integer_t v) override { return value(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return value(Json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return value(Json(v)); }
    bool string(string_t& v) override { return value(ignored() ? Json() : Json(std::move(v))); }
    bool binary(binary_t&) override { return value(Json()); } // JSON text has none
    bool start_object(std::size_t) override { return open(true); }
    bool key(string_t& name) override;
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&,
                     const nlohmann::detail::exception& error) override {
        failSyntax(input_, error, childPlace());
    }

private:
    /// The place of the value that comes next.
    std::string childPlace() const;
    /// What belongs at the place of the value that comes next.
    Kind expected() const;

    bool open(bool object);
    bool close();
    /// True if the value that comes next is not kept: it is within a Skip, or an element
    /// of a Vec2 after its second (only counted).
    bool ignored() const;
    /// A whole value for the place that comes next: a scalar, the two numbers of a Vec2, or
    /// a Skip's empty container.
    bool value(const Json& v);
    void take(const Json& v);
    void takeSceneField(const Frame& frame, const Json& v);
    void takePhysicalField(const Frame& frame, const Json& v);
    void endBody(Frame& frame);
    void endTileMap(Frame& frame);

    const Input& input_;
    std::vector<Frame> frames_;
    Scene scene_;
    std::uint64_t sceneFields_ = 0;  ///< the top level's Frame::given, once it has ended
    std::vector<std::size_t> order_; ///< "bodies", "tilemap", "tilemaps" in file order
    /// The whole numbers of the world's options as written, by place, for checkWorldDef's
    /// messages.
    std::vector<std::pair<std::string, std::string>> written_;
    /// Ids name bodies in traces, so two bodies must never share one.
    IdTable ids_{scene_.bodies};
};

std::string SceneReader::childPlace() const {
    if (frames_.empty())
        return "";
    const Frame& frame = frames_.back();
    if (!frame.object)
        return element(frame.place, frame.count);
    return field(frame.place, frame.kind == Kind::Skip ? placeName(frame.key) : frame.key);
}

Kind SceneReader::expected() const {
    if (frames_.empty())
        return Kind::Scene;
    const Frame& frame = frames_.back();
    switch (frame.kind) {
    case Kind::Scene:
        return kSceneFieldKinds[frame.field];
    case Kind::Body:
        return frame.field != kIdField && isVec2(properties::kBodyFields[frame.field])
                   ? Kind::Vec2
                   : Kind::Scalar;
    case Kind::TileMap:
        return frame.field == kRowsField                         ? Kind::Rows
               : isVec2(properties::kTileMapFields[frame.field]) ? Kind::Vec2
                                                                 : Kind::Scalar;
    case Kind::Bodies:
        return Kind::Body;
    case Kind::TileMaps:
        return Kind::TileMap;
    case Kind::Skip:
        return Kind::Skip;
    default: // Classic, Physical, Rows, Vec2
        return Kind::Scalar;
    }
}

bool SceneReader::open(bool object) {
    std::string place = childPlace();
    if (frames_.size() >= kMaxDepth)
        fail(place, "nested deeper than " + std::to_string(kMaxDepth) + " levels");
    const Kind kind = expected();
    const std::size_t index = frames_.empty() ? 0 : frames_.back().count;
    Frame& frame = frames_.emplace_back();
    frame.kind = (object ? isObjectKind(kind) : isArrayKind(kind)) ? kind : Kind::Skip;
    frame.object = object;
    frame.place = std::move(place);
    if (frame.kind == Kind::Body)
        frame.body.id = std::to_string(index);
    return true;
}

bool SceneReader::key(string_t& name) {
    Frame& frame = frames_.back();
    std::size_t index = kNone;
    switch (frame.kind) {
    case Kind::Scene:
        index = indexOf(kSceneFields, name);
        break;
    case Kind::Classic:
        index = indexOf(kClassicFields, name);
        break;
    case Kind::Physical:
        index = indexOf(kPhysicalFields, name);
        break;
    case Kind::Body:
        index = name == "id" ? kIdField : fileFieldIndex(properties::kBodyFields, name);
        break;
    case Kind::TileMap:
        index = name == "rows" ? kRowsField : fileFieldIndex(properties::kTileMapFields, name);
        break;
    default: // Skip: any name, read for its place
        frame.key = std::move(name);
        return true;
    }
    // Refused at its name, before its value is read: nothing of it is kept.
    if (index == kNone)
        fail(frame.place, "unknown field " + quoteName(name));
    if (frame.has(index))
        fail(frame.place, "duplicate field " + quoteName(name));
    // One map or several: two ways to say it, never both in one file.
    if (frame.kind == Kind::Scene && (index == kTileMap || index == kTileMaps) &&
        frame.has(index == kTileMap ? kTileMaps : kTileMap))
        fail("", R"(give "tilemap" or "tilemaps", not both)");
    if (frame.kind == Kind::Scene && (index == kBodies || index == kTileMap || index == kTileMaps))
        order_.push_back(index);
    frame.given |= std::uint64_t{1} << index;
    frame.field = index;
    frame.key = std::move(name);
    return true;
}

bool SceneReader::ignored() const {
    if (frames_.empty())
        return false;
    const Frame& frame = frames_.back();
    return frame.kind == Kind::Skip || (frame.kind == Kind::Vec2 && frame.count >= 2);
}

bool SceneReader::value(const Json& v) {
    if (!ignored())
        take(v);
    if (!frames_.empty() && !frames_.back().object)
        ++frames_.back().count;
    return true;
}

bool SceneReader::close() {
    Frame& frame = frames_.back();
    switch (frame.kind) {
    case Kind::Scene:
        sceneFields_ = frame.given;
        frames_.pop_back();
        return true;
    case Kind::Body:
        endBody(frame);
        break;
    case Kind::TileMap:
        endTileMap(frame);
        break;
    case Kind::Vec2: {
        if (frame.count != 2)
            failVec2Size(frame.place, frame.count);
        Json pair = Json::array();
        pair.push_back(std::move(frame.elements[0]));
        pair.push_back(std::move(frame.elements[1]));
        frames_.pop_back();
        return value(pair);
    }
    case Kind::Skip: {
        const bool object = frame.object;
        frames_.pop_back();
        if (ignored())
            return value(Json());
        // What a container stands for where it does not belong: its type, for the message.
        return value(object ? Json::object() : Json::array());
    }
    default: // Classic, Physical, Bodies, TileMaps, Rows: each value was taken as it came
        break;
    }
    frames_.pop_back();
    if (!frames_.empty() && !frames_.back().object)
        ++frames_.back().count;
    return true;
}

void SceneReader::take(const Json& v) {
    if (frames_.empty())
        fail("", "expected an object at the top level" + got(v));
    Frame& frame = frames_.back();
    switch (frame.kind) {
    case Kind::Scene:
        takeSceneField(frame, v);
        break;
    case Kind::Classic: {
        ClassicOptions& options = scene_.world.classic;
        bool* const flags[] = {&options.mass, &options.coulomb, &options.ccd};
        *flags[frame.field] = readBool(v, field(frame.place, frame.key));
        break;
    }
    case Kind::Physical:
        takePhysicalField(frame, v);
        break;
    case Kind::Body: {
        const std::string at = field(frame.place, frame.key);
        if (frame.field == kIdField) {
            frame.body.id = readString(v, at);
            if (frame.body.id.empty())
                fail(at, "must not be empty");
            // Ids are printed in traces and summaries, where "a\u0000b" would read "a".
            if (hasControlCharacter(frame.body.id))
                fail(at, "must not contain control characters, got " + quoteName(frame.body.id));
        } else {
            readField(frame.body.def, properties::kBodyFields[frame.field], v, at);
        }
        break;
    }
    case Kind::TileMap: {
        const std::string at = field(frame.place, frame.key);
        if (frame.field == kRowsField)
            failType(v, at, "an array");
        readField(frame.map, properties::kTileMapFields[frame.field], v, at);
        break;
    }
    case Kind::Bodies:
    case Kind::TileMaps:
        failType(v, element(frame.place, frame.count), "an object");
    case Kind::Rows:
        // The map is the frame below.
        frames_[frames_.size() - 2].map.rows.push_back(
            readString(v, element(frame.place, frame.count)));
        break;
    case Kind::Vec2:
        if (frame.count < 2)
            frame.elements[frame.count] = v;
        break;
    default: // Skip
        break;
    }
}

FrictionMix readFrictionMix(const Json& value, const std::string& place) {
    if (auto mix = frictionMixFromString(readString(value, place)))
        return *mix;
    fail(place, R"(expected "min" or "geometricMean")");
}

void SceneReader::takeSceneField(const Frame& frame, const Json& v) {
    const std::string& name = frame.key;
    switch (frame.field) {
    case kGravity:
        scene_.world.gravity = readVec2(v, name);
        break;
    case kMaxVelocity:
        scene_.world.maxVelocity = readFloat(v, name);
        break;
    case kDt:
        scene_.dt = readFloat(v, name);
        if (!(scene_.dt > 0.0f))
            fail(name, "must be > 0");
        if (scene_.dt < kMinMagnitude || scene_.dt > kMaxMagnitude)
            fail(name, "must be in [1e-9, 1e9]"); // what World::step accepts
        break;
    case kSolver: {
        auto solver = solverFromString(readString(v, name));
        if (!solver)
            fail(name, R"(expected "classic" or "physical")");
        scene_.world.solver = *solver;
        break;
    }
    case kSleeping:
        scene_.world.sleeping = readBool(v, name);
        break;
    case kBodies:
    case kTileMaps:
        failType(v, name, "an array");
    default: // classic, physical, tilemap
        failType(v, name, "an object");
    }
}

void SceneReader::takePhysicalField(const Frame& frame, const Json& v) {
    const std::string at = field(frame.place, frame.key);
    PhysicalOptions& options = scene_.world.physical;
    switch (frame.field) {
    case 0:
        options.velocityIterations = readInt(v, at);
        written_.emplace_back(at, numberText(v));
        break;
    case 1:
        options.positionIterations = readInt(v, at);
        written_.emplace_back(at, numberText(v));
        break;
    case 2:
        options.slop = readFloat(v, at);
        break;
    case 3:
        options.correction = readFloat(v, at);
        break;
    case 4:
        options.restitutionThreshold = readFloat(v, at);
        break;
    case 5:
        options.frictionMix = readFrictionMix(v, at);
        break;
    default:
        options.maxContactsPerBody = readInt(v, at);
        written_.emplace_back(at, numberText(v));
        break;
    }
}

/// Fails unless the object of `frame` has every field its definition requires, in table
/// order.
template <class F, std::size_t N> void requireFields(const Frame& frame, const F (&fields)[N]) {
    for (std::size_t i = 0; i < N; ++i)
        if (fields[i].property->required && !frame.has(i))
            fail(frame.place, std::string("missing field \"") + fields[i].property->name + "\"");
}

void SceneReader::endBody(Frame& frame) {
    using properties::kBodyFields;
    requireFields(frame, kBodyFields); // hw, hh: a box has no default size

    // In a file, 0 is not a way to ask for the density mass (BodyDef's convention):
    // leaving "mass" out is. And a body cannot have both an explicit mass and a density.
    static const std::size_t kMass = fileFieldIndex(kBodyFields, "mass");
    static const std::size_t kDensity = fileFieldIndex(kBodyFields, "density");
    const bool mass = frame.has(kMass);
    if (mass && frame.has(kDensity))
        fail(frame.place, R"(give "mass" or "density", not both)");
    if (mass && !(frame.body.def.mass > 0.0f))
        fail(field(frame.place, "mass"), "must be > 0");

    if (auto problem = checkBodyDef(frame.body.def))
        fail(field(frame.place, problem->field), problem->problem);

    scene_.bodies.push_back(std::move(frame.body));
    if (const std::size_t owner = ids_.insert(scene_.bodies.size() - 1); owner != kNone) {
        const bool explicitId = frame.has(kIdField);
        fail(explicitId ? field(frame.place, "id") : frame.place,
             (explicitId ? "" : "its default id ") + quoteName(scene_.bodies.back().id) +
                 " is already the id of " + element("bodies", owner));
    }
}

void SceneReader::endTileMap(Frame& frame) {
    // A map has no sensible default tile size, nor default tiles.
    requireFields(frame, properties::kTileMapFields);
    if (!frame.has(kRowsField))
        fail(frame.place, R"(missing field "rows")");
    if (auto problem = checkTileMapDef(frame.map))
        fail(field(frame.place, problem->field), problem->problem);
    scene_.tileMaps.push_back(std::move(frame.map));
}

Scene SceneReader::finish() {
    if ((sceneFields_ >> kBodies & 1u) == 0)
        fail("", R"(missing field "bodies")");
    if (auto problem = checkWorldDef(scene_.world)) {
        std::string rule = problem->problem;
        for (const auto& [place, text] : written_)
            if (place == problem->field)
                rule += ", got " + text;
        fail(problem->field, rule);
    }
    // Only now is the model known ("solver" may come last); its problems are looked for
    // in file order, bodies and tile maps alike.
    for (const std::size_t name : order_) {
        std::optional<FieldError> problem;
        if (name == kBodies)
            problem = modelProblem(scene_.world.solver, scene_.bodies);
        else
            problem = modelProblem(scene_.world.solver, scene_.tileMaps, [&](std::size_t i) {
                const std::string place(kSceneFields[name]);
                return name == kTileMap ? place : element(place, i);
            });
        if (problem)
            fail(problem->field, problem->problem);
    }
    return std::move(scene_);
}

} // namespace

Scene readScene(json::Input& input) {
    try {
        SceneReader reader(input);
        json::parse(input, reader);
        return reader.finish();
    } catch (const nlohmann::json::exception& error) {
        // Every path above checks types first, so this is a bug; still, the promise is
        // that bad input gives a SceneError, never something else.
        throw SceneError(std::string("invalid scene: ") + error.what());
    }
}

} // namespace jostle::scene_file
