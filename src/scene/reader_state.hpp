// Scene files: the reader's state, shared by its two halves. scene_reader.cpp follows the
// parser's events (objects and arrays opened and closed, names, values); scene_fields.cpp
// says what each field means and checks each body, tile map and world as it ends.
// Internal to the scene library: readScene (scene_reader.hpp) is its only way in.
#pragma once

#include "definition_fields.hpp"
#include "id_table.hpp"
#include "jostle/scene.hpp"
#include "json.hpp"
#include "world_options.hpp"

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace jostle::scene_file {

/// The fields of the top level by index: WorldDef's own (properties::kWorldFields) first,
/// then the scene's own from kWorldRows on. "classic" and "physical" are read by their
/// tables (world_options.hpp).
inline constexpr std::size_t kWorldRows = std::size(properties::kWorldFields);
inline constexpr std::string_view kSceneOwnFields[] = {"dt",     "classic", "physical",
                                                       "bodies", "tilemap", "tilemaps"};
enum SceneField : std::size_t {
    kDt = kWorldRows,
    kClassic,
    kPhysical,
    kBodies,
    kTileMap,
    kTileMaps,
    kSceneFieldCount
};
static_assert(kSceneFieldCount - kWorldRows == std::size(kSceneOwnFields));
/// A body's "id" and a tile map's "rows", after the fields of their definitions.
inline constexpr std::size_t kIdField = std::size(properties::kBodyFields);
inline constexpr std::size_t kRowsField = std::size(properties::kTileMapFields);
static_assert(kIdField < 64 && kRowsField < 64 && kSceneFieldCount <= 64 &&
                  std::size(properties::kPhysicalFields) <= 64,
              "Frame::given has a bit for each field");

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

/// What the value of each field of kSceneOwnFields is.
inline constexpr Kind kSceneOwnKinds[] = {Kind::Scalar, Kind::Classic, Kind::Physical,
                                          Kind::Bodies, Kind::TileMap, Kind::TileMaps};
static_assert(std::size(kSceneOwnKinds) == std::size(kSceneOwnFields));

/// What the value of a field of a definition's table is.
template <class F> Kind kindOf(const F& field) {
    return isVec2(field) ? Kind::Vec2 : Kind::Scalar;
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
    /// Reads a world option of `def` by its row, keeping a whole number as written.
    template <class Def, class F>
    void takeOption(Def& def, const F& field, const Json& v, const std::string& at);
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

template <class Def, class F>
void SceneReader::takeOption(Def& def, const F& field, const Json& v, const std::string& at) {
    readField(def, field, v, at);
    if (isWhole(field))
        written_.emplace_back(at, numberText(v)); // for checkWorldDef's messages: ", got 0"
}

} // namespace jostle::scene_file
