// What every editor's level shares (docs/levels.md): a tile's kind by name, custom
// properties as scene file fields, and the scene loader reading a level's world, tile map
// settings and bodies with its own rules and messages, each message about the place in
// the editor's file. Used by tiled_level.cpp and ldtk.cpp.
#pragma once

#include "jostle/level.hpp"
#include "scene/json.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jostle::level {

/// The JSON the level readers read and write: the scene loader's own type, since each type
/// instantiates nlohmann-json's parser again (some 40 KB of the web module).
using Json = json::Json;

using Properties = std::map<std::string, PropertyValue>;

/// Throws SceneError("<file>: <what>").
[[noreturn]] void fail(const std::string& file, const std::string& what);

/// The text of `path`, a file a level names (a tileset, a level saved apart), read by
/// `readFile`; a problem reading or with it is about the level's file:
/// "level.tmj: tileset "tiles.tsj": cannot read the file".
std::string readNamedFile(const FileReader& readFile, const std::string& path,
                          const std::string& file, const std::string& place);

/// `"text"`, as messages quote names.
std::string quoted(const std::string& text);

/// How a tile collides: a tile map character ('#', '.', a ramp's) and whether it is one-way.
struct TileKind {
    char tile = '.';
    bool oneWay = false;
};

/// The ramps' tile map characters (tilemap.hpp).
inline constexpr std::string_view kRamps = "/\\7FrRLlcCDd";

/// The kind a `collision` property names: "solid", "oneWay", "none" or a ramp's
/// character; nullopt for a name that is none.
std::optional<TileKind> kindNamed(const std::string& name);

/// The words of a message about a kind that is none.
inline constexpr const char* kKindsExpected =
    "expected \"solid\", \"oneWay\", \"none\" or a ramp's character";

/// A tile layer's tiles as two tile maps: its solid tiles and ramps, and its one-way tiles
/// (blocking from above, in a y-down world), each kept only if it holds a tile.
class LayerTiles {
public:
    LayerTiles(std::size_t columns, std::size_t rows)
        : solid_(rows, std::string(columns, '.')), oneWay_(solid_) {}
    void set(std::size_t column, std::size_t row, TileKind kind);
    /// Adds the maps that hold a tile to `level`, each with `settings` (position, tile
    /// size, friction...).
    void addTo(Level& level, TileMapDef settings);

private:
    std::vector<std::string> solid_, oneWay_;
    bool anySolid_ = false, anyOneWay_ = false;
};

/// True for the name of a body field of scene files (src/body_properties.hpp).
bool isBodyField(const std::string& name);

/// A property's value as a scene file's field; a vector field (oneWay, slope,
/// surfaceVelocity) also from text such as "0, -1" (editors have no vector property).
Json fieldValue(const std::string& name, const PropertyValue& value);

/// The custom properties that are body fields of scene files, as a scene file's body
/// object holds them (fieldValue).
Json bodyFields(const Properties& properties);

/// The body object of an object's box: its custom properties that are body fields, with
/// its centre and half size over any the properties gave.
Json boxBody(const LevelObject& object);

/// True for a length a float holds with room: |v| <= 1e30 (NaN is not).
bool withinFloats(double v);

/// The world's settings from a level's custom properties, as a scene file names them:
/// gravityX and gravityY (editors have no vector), solver, sleeping, maxVelocity.
WorldDef worldFrom(const Properties& properties, const std::string& file);

/// A tile map's settings from a layer's custom properties: friction, bounce, category,
/// mask, sensor; the other fields left at their defaults.
TileMapDef tileMapSettings(const Properties& properties, const std::string& file,
                           const std::string& place);

/// The bodies of a level, gathered as scene file objects and read by the scene loader at
/// once (a message about one names the place of what it was made from).
class LevelBodies {
public:
    /// Adds a body's object; returns its index in the level's bodies.
    int add(Json def, std::string id, std::string place);
    int size() const { return static_cast<int>(bodies_.size()); }
    /// Reads them all into level.scene.bodies, in the model of level.scene.world.
    void readInto(Level& level, const std::string& file) const;

private:
    struct Body {
        Json def;
        std::string id;
        std::string place;
    };
    std::vector<Body> bodies_;
};

} // namespace jostle::level
