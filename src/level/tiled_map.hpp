// A Tiled map as both of Tiled's formats describe it (doc.mapeditor.org's JSON and TMX
// references), read by tiled_json.cpp and tiled_tmx.cpp and turned into a Level by
// tiled_level.cpp. Only what jostle uses is kept. Lengths are Tiled's pixels.
#pragma once

#include "jostle/level.hpp"
#include "level_rules.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace jostle::tiled {

using Properties = std::map<std::string, PropertyValue>;

/// A global tile id's flip flags, in its top bits, and the id without them.
inline constexpr std::uint32_t kFlipHorizontal = 0x80000000u;
inline constexpr std::uint32_t kFlipVertical = 0x40000000u;
inline constexpr std::uint32_t kFlipDiagonal = 0x20000000u;
inline constexpr std::uint32_t kRotatedHex = 0x10000000u;
inline constexpr std::uint32_t kGidBits = 0x0FFFFFFFu;

struct Point {
    double x = 0.0;
    double y = 0.0;
};

enum class Shape { Rectangle, Ellipse, Point, Polygon, Polyline, Text };

struct Object {
    int id = 0;
    std::string name;
    std::string type; ///< the class ("type" before Tiled 1.9)
    Shape shape = Shape::Rectangle;
    double x = 0.0, y = 0.0; ///< top left; a tile object's bottom left
    double width = 0.0, height = 0.0;
    double rotation = 0.0;
    std::uint32_t gid = 0;     ///< a tile object's tile, with its flip flags; 0 if none
    std::vector<Point> points; ///< a polygon's or polyline's, relative to (x, y)
    Properties properties;
};

/// A tile of a tileset that has something said of it: properties, collision shapes.
struct Tile {
    Properties properties;
    std::vector<Object> shapes; ///< drawn in Tiled's collision editor, in the tile's pixels
};

struct Tileset {
    std::uint32_t firstGid = 1;
    std::string name;
    int tileWidth = 0, tileHeight = 0;
    int tileCount = 0;         ///< 0: not said (an image collection)
    std::map<int, Tile> tiles; ///< by local id
};

enum class LayerKind { Tiles, Objects, Group, Other };

struct Layer {
    LayerKind kind = LayerKind::Other;
    std::string name;
    Properties properties;
    double offsetX = 0.0, offsetY = 0.0; ///< in pixels
    /// A tile layer's cells: `width` x `height` global ids, row by row, the first at tile
    /// (left, top) of the map (chunks of an infinite map gathered into their bounds).
    int left = 0, top = 0, width = 0, height = 0;
    std::vector<std::uint32_t> gids;
    std::vector<Object> objects; ///< an object layer's
    std::vector<Layer> layers;   ///< a group's
};

struct Map {
    std::string orientation = "orthogonal";
    int tileWidth = 0, tileHeight = 0;
    Properties properties;
    std::vector<Tileset> tilesets;
    std::vector<Layer> layers;
};

/// A part of an infinite map's tile layer: `width` x `height` global ids at tile (x, y).
struct Chunk {
    int x = 0, y = 0, width = 0, height = 0;
    std::vector<std::uint32_t> gids;
};

/// `value` as an int, if it is a whole number an int holds.
std::optional<int> wholeNumber(double value);
/// `value` as a global tile id with its flags, if it is a whole number in [0, 2^32).
std::optional<std::uint32_t> tileIdOf(double value);

/// The tiles of a `width` x `height` layer or chunk: throws std::runtime_error for a
/// negative size or more than 2^26 tiles.
std::size_t cellCount(int width, int height);

/// Fills the layer's cells from its chunks, within their bounds (tile_data.cpp); throws
/// std::runtime_error past 2^26 tiles.
void gatherChunks(const std::vector<Chunk>& chunks, Layer& layer);

/// Reads the JSON format (tiled_json.cpp); `name` is for errors.
Map readJson(std::string_view text, const std::string& name, const FileReader& readFile);
/// Reads the XML format (tiled_tmx.cpp).
Map readTmx(std::string_view text, const std::string& name, const FileReader& readFile);
/// A tileset in either format (an external .tsj or .tsx), its first gid given.
Tileset readTilesetJson(std::string_view text, const std::string& name, std::uint32_t firstGid);
Tileset readTilesetTmx(std::string_view text, const std::string& name, std::uint32_t firstGid);
/// The tileset `source` names, read by readFile, in the format its text is.
Tileset readExternalTileset(const std::string& source, std::uint32_t firstGid,
                            const std::string& mapName, const FileReader& readFile);

using level::fail;

} // namespace jostle::tiled
