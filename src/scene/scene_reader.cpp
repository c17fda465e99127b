// Scene files: the reader of the parser's events (scene_reader.hpp), the half of it that
// follows objects and arrays as they open and close (reader_state.hpp; what each field
// means is scene_fields.cpp's).
//
// Every problem becomes a SceneError that names the place ("bodies[3].hw") and the
// rule. The fields of bodies and tile maps are read by their descriptions
// (definition_fields.hpp). What is checked here is what only a file can get wrong:
// syntax, types, unknown (with the known field it was probably meant to be: suggest.hpp),
// missing and duplicate fields, numbers a float cannot hold, ids.
#include "scene_reader.hpp"

#include "reader_state.hpp"
#include "suggest.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>

namespace jostle::scene_file {

namespace {

/// The format needs four levels (scene, tilemaps, tile map, rows); anything much deeper is
/// not a scene, and refusing it early bounds what hostile input costs.
constexpr std::size_t kMaxDepth = 32;

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

/// The field of an object of `kind` that `name` was probably meant to be (suggest.hpp),
/// or empty.
std::string_view nearestField(Kind kind, std::string_view name) {
    NearestName nearest(name);
    auto considerAll = [&](const auto& names) {
        for (std::string_view known : names)
            nearest.consider(known);
    };
    auto considerFile = [&](const auto& fields) {
        for (const auto& field : fields)
            if (inFile(field))
                nearest.consider(field.property->name);
    };
    switch (kind) {
    case Kind::Scene:
        considerFile(properties::kWorldFields);
        considerAll(kSceneOwnFields);
        break;
    case Kind::Classic:
        considerFile(properties::kClassicFields);
        break;
    case Kind::Physical:
        considerFile(properties::kPhysicalFields);
        break;
    case Kind::Body:
        considerFile(properties::kBodyFields);
        nearest.consider("id");
        break;
    case Kind::TileMap:
        considerFile(properties::kTileMapFields);
        nearest.consider("rows");
        break;
    default:
        break;
    }
    return nearest.name();
}

} // namespace

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
        return frame.field < kWorldRows ? kindOf(properties::kWorldFields[frame.field])
                                        : kSceneOwnKinds[frame.field - kWorldRows];
    case Kind::Classic:
        return kindOf(properties::kClassicFields[frame.field]);
    case Kind::Physical:
        return kindOf(properties::kPhysicalFields[frame.field]);
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
    default: // Rows, Vec2
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
        index = fileFieldIndex(properties::kWorldFields, name);
        if (const std::size_t own = indexOf(kSceneOwnFields, name); own != kNone)
            index = kWorldRows + own;
        break;
    case Kind::Classic:
        index = fileFieldIndex(properties::kClassicFields, name);
        break;
    case Kind::Physical:
        index = fileFieldIndex(properties::kPhysicalFields, name);
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
        fail(frame.place,
             "unknown field " + quoteName(name) + didYouMean(nearestField(frame.kind, name)));
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
    case Kind::Classic:
        takeOption(scene_.world.classic, properties::kClassicFields[frame.field], v,
                   field(frame.place, frame.key));
        break;
    case Kind::Physical:
        takeOption(scene_.world.physical, properties::kPhysicalFields[frame.field], v,
                   field(frame.place, frame.key));
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
