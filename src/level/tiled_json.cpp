// Tiled's JSON format (.tmj, .tsj) read into tiled::Map: doc.mapeditor.org's "JSON Map
// Format". Fields jostle does not use are skipped; those it uses are checked by type.
#include "level_rules.hpp"
#include "tile_data.hpp"
#include "tiled_map.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace jostle::tiled {

namespace {

using level::Json;

/// Reads the values of one file, each problem a SceneError naming the file and the place.
struct Reader {
    const std::string& file;

    [[noreturn]] void bad(const std::string& place, const std::string& what) const {
        fail(file, place + ": " + what);
    }

    const Json* member(const Json& object, const char* key) const {
        const auto found = object.find(key);
        return found == object.end() || found->is_null() ? nullptr : &*found;
    }
    double number(const Json& object, const char* key, const std::string& place,
                  double fallback) const {
        const Json* value = member(object, key);
        if (value == nullptr)
            return fallback;
        if (!value->is_number())
            bad(place, std::string(key) + ": expected a number");
        return value->get<double>();
    }
    int integer(const Json& object, const char* key, const std::string& place, int fallback) const {
        const double value = number(object, key, place, fallback);
        const std::optional<int> whole = wholeNumber(value);
        if (!whole)
            bad(place, std::string(key) + ": expected a whole number");
        return *whole;
    }
    std::uint32_t tileId(const Json& object, const std::string& place) const {
        const std::optional<std::uint32_t> id = tileIdOf(number(object, "gid", place, 0));
        if (!id)
            bad(place, "gid: expected a tile id, a whole number in [0, 2^32)");
        return *id;
    }
    std::string text(const Json& object, const char* key, const std::string& place) const {
        const Json* value = member(object, key);
        if (value == nullptr)
            return {};
        if (!value->is_string())
            bad(place, std::string(key) + ": expected a string");
        return value->get<std::string>();
    }
    const Json& array(const Json& object, const char* key, const std::string& place) const {
        static const Json kEmpty = Json::array();
        const Json* value = member(object, key);
        if (value == nullptr)
            return kEmpty;
        if (!value->is_array())
            bad(place, std::string(key) + ": expected an array");
        return *value;
    }

    Properties properties(const Json& object, const std::string& place) const {
        Properties out;
        for (const Json& property : array(object, "properties", place)) {
            const std::string name = text(property, "name", place);
            const Json* value = member(property, "value");
            if (value == nullptr || value->is_object())
                continue; // a class property: jostle reads none
            if (value->is_boolean())
                out[name] = value->get<bool>();
            else if (value->is_number())
                out[name] = value->get<double>();
            else if (value->is_string())
                out[name] = value->get<std::string>();
        }
        return out;
    }

    Object object(const Json& json, const std::string& place) const {
        Object o;
        o.id = integer(json, "id", place, 0);
        o.name = text(json, "name", place);
        o.type = text(json, "class", place);
        if (o.type.empty())
            o.type = text(json, "type", place);
        o.x = number(json, "x", place, 0);
        o.y = number(json, "y", place, 0);
        o.width = number(json, "width", place, 0);
        o.height = number(json, "height", place, 0);
        o.rotation = number(json, "rotation", place, 0);
        o.gid = tileId(json, place);
        o.properties = properties(json, place);
        const auto flag = [&](const char* key) {
            const Json* value = member(json, key);
            return value != nullptr && value->is_boolean() && value->get<bool>();
        };
        if (flag("ellipse"))
            o.shape = Shape::Ellipse;
        else if (flag("point"))
            o.shape = Shape::Point;
        else if (member(json, "text") != nullptr)
            o.shape = Shape::Text;
        const bool polygon = member(json, "polygon") != nullptr;
        if (polygon || member(json, "polyline") != nullptr) {
            o.shape = polygon ? Shape::Polygon : Shape::Polyline;
            for (const Json& point : array(json, polygon ? "polygon" : "polyline", place))
                o.points.push_back({number(point, "x", place, 0), number(point, "y", place, 0)});
        }
        return o;
    }

    /// A tile layer's data, finite or in chunks, gathered into the layer's bounds.
    void tileData(const Json& json, Layer& layer, const std::string& place) const {
        const std::string encoding = text(json, "encoding", place);
        const std::string compression = text(json, "compression", place);
        const auto decode = [&](const Json& data, std::size_t count) -> std::vector<std::uint32_t> {
            try {
                if (data.is_string()) {
                    if (encoding != "base64")
                        bad(place, "data: a string, but the encoding is not base64");
                    return decodeBase64Gids(data.get<std::string>(), compression, count);
                }
                if (!data.is_array() || data.size() != count)
                    bad(place, "data: expected " + std::to_string(count) + " tile ids");
                std::vector<std::uint32_t> gids;
                gids.reserve(count);
                for (const Json& gid : data) {
                    if (!gid.is_number_unsigned() || gid.get<std::uint64_t>() > 0xFFFFFFFFu)
                        bad(place, "data: expected tile ids, whole numbers in [0, 2^32)");
                    gids.push_back(static_cast<std::uint32_t>(gid.get<std::uint64_t>()));
                }
                return gids;
            } catch (const std::runtime_error& error) {
                if (dynamic_cast<const SceneError*>(&error) != nullptr)
                    throw;
                bad(place, error.what());
            }
        };
        try {
            const Json& chunks = array(json, "chunks", place);
            if (chunks.empty()) {
                layer.width = integer(json, "width", place, 0);
                layer.height = integer(json, "height", place, 0);
                layer.left = integer(json, "startx", place, 0);
                layer.top = integer(json, "starty", place, 0);
                const std::size_t count = cellCount(layer.width, layer.height);
                const Json* data = member(json, "data");
                layer.gids =
                    data == nullptr ? std::vector<std::uint32_t>(count) : decode(*data, count);
                return;
            }
            std::vector<Chunk> parts;
            for (const Json& chunk : chunks) {
                Chunk part{integer(chunk, "x", place, 0),
                           integer(chunk, "y", place, 0),
                           integer(chunk, "width", place, 0),
                           integer(chunk, "height", place, 0),
                           {}};
                const std::size_t count = cellCount(part.width, part.height);
                const Json* data = member(chunk, "data");
                part.gids =
                    data == nullptr ? std::vector<std::uint32_t>(count) : decode(*data, count);
                parts.push_back(std::move(part));
            }
            gatherChunks(parts, layer);
        } catch (const SceneError&) {
            throw;
        } catch (const std::runtime_error& error) {
            bad(place, error.what());
        }
    }

    Layer layer(const Json& json, const std::string& parent) const {
        Layer layer;
        layer.name = text(json, "name", parent);
        const std::string place = parent + "layer \"" + layer.name + "\"";
        layer.properties = properties(json, place);
        layer.offsetX = number(json, "offsetx", place, 0);
        layer.offsetY = number(json, "offsety", place, 0);
        const std::string type = text(json, "type", place);
        if (type == "tilelayer") {
            layer.kind = LayerKind::Tiles;
            tileData(json, layer, place);
        } else if (type == "objectgroup") {
            layer.kind = LayerKind::Objects;
            for (const Json& object : array(json, "objects", place))
                layer.objects.push_back(this->object(object, place));
        } else if (type == "group") {
            layer.kind = LayerKind::Group;
            for (const Json& child : array(json, "layers", place))
                layer.layers.push_back(this->layer(child, place + ": "));
        }
        return layer;
    }

    Tileset tileset(const Json& json, std::uint32_t firstGid, const std::string& place) const {
        Tileset set;
        set.firstGid = firstGid;
        set.name = text(json, "name", place);
        set.tileWidth = integer(json, "tilewidth", place, 0);
        set.tileHeight = integer(json, "tileheight", place, 0);
        set.tileCount = integer(json, "tilecount", place, 0);
        for (const Json& tile : array(json, "tiles", place)) {
            const int id = integer(tile, "id", place, -1);
            if (id < 0)
                bad(place, "tiles: a tile without an id");
            Tile& t = set.tiles[id];
            t.properties = properties(tile, place + ": tile " + std::to_string(id));
            if (const Json* group = member(tile, "objectgroup"))
                for (const Json& shape : array(*group, "objects", place))
                    t.shapes.push_back(object(shape, place + ": tile " + std::to_string(id)));
        }
        return set;
    }
};

Json parse(std::string_view text, const std::string& file) {
    Json json = Json::parse(text, nullptr, false);
    if (json.is_discarded() || !json.is_object())
        fail(file, "not a Tiled JSON file (not a JSON object)");
    return json;
}

} // namespace

Map readJson(std::string_view text, const std::string& name, const FileReader& readFile) {
    const Json json = parse(text, name);
    const Reader read{name};
    Map map;
    map.orientation = read.text(json, "orientation", "map");
    map.tileWidth = read.integer(json, "tilewidth", "map", 0);
    map.tileHeight = read.integer(json, "tileheight", "map", 0);
    map.properties = read.properties(json, "map");
    for (const Json& set : read.array(json, "tilesets", "map")) {
        const auto firstGid =
            static_cast<std::uint32_t>(read.integer(set, "firstgid", "tilesets", 1));
        const std::string source = read.text(set, "source", "tilesets");
        map.tilesets.push_back(
            source.empty()
                ? read.tileset(set, firstGid, "tileset \"" + read.text(set, "name", "") + "\"")
                : readExternalTileset(source, firstGid, name, readFile));
    }
    for (const Json& layer : read.array(json, "layers", "map"))
        map.layers.push_back(read.layer(layer, ""));
    return map;
}

Tileset readTilesetJson(std::string_view text, const std::string& name, std::uint32_t firstGid) {
    const Json json = parse(text, name);
    return Reader{name}.tileset(json, firstGid,
                                "tileset \"" + Reader{name}.text(json, "name", "tileset") + "\"");
}

Tileset readExternalTileset(const std::string& source, std::uint32_t firstGid,
                            const std::string& mapName, const FileReader& readFile) {
    const std::string place = "tileset \"" + source + "\"";
    const std::string text = level::readNamedFile(readFile, source, mapName, place);
    const std::size_t start = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    try {
        const bool xml = start != std::string::npos && text[start] == '<';
#ifdef JOSTLE_LEVEL_JSON_ONLY
        if (xml)
            throw SceneError(
                source +
                ": XML tilesets (.tsx) are not read in this build: export it as JSON (.tsj)");
        return readTilesetJson(text, source, firstGid);
#else
        return xml ? readTilesetTmx(text, source, firstGid)
                   : readTilesetJson(text, source, firstGid);
#endif
    } catch (const SceneError& error) {
        std::string message = error.what();
        if (message.starts_with(source + ": "))
            message.erase(0, source.size() + 2);
        fail(mapName, place + ": " + message);
    }
}

} // namespace jostle::tiled
