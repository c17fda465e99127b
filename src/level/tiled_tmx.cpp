// Tiled's XML format (.tmx, .tsx) read into tiled::Map with pugixml: doc.mapeditor.org's
// "TMX Map Format". The same model as the JSON reader's, so that both formats give one
// level.
#include "tile_data.hpp"
#include "tiled_map.hpp"

#include <pugixml.hpp>

#include <climits>
#include <cstdlib>
#include <stdexcept>

namespace jostle::tiled {

namespace {

struct Reader {
    const std::string& file;

    [[noreturn]] void bad(const std::string& place, const std::string& what) const {
        fail(file, place + ": " + what);
    }

    double number(const pugi::xml_node& node, const char* key, const std::string& place,
                  double fallback) const {
        const pugi::xml_attribute attribute = node.attribute(key);
        if (!attribute)
            return fallback;
        char* end = nullptr;
        const double value = std::strtod(attribute.value(), &end);
        if (end == attribute.value() || *end != '\0')
            bad(place, std::string(key) + ": expected a number, got \"" + attribute.value() + "\"");
        return value;
    }
    int integer(const pugi::xml_node& node, const char* key, const std::string& place,
                int fallback) const {
        const double value = number(node, key, place, fallback);
        const std::optional<int> whole = wholeNumber(value);
        if (!whole)
            bad(place, std::string(key) + ": expected a whole number");
        return *whole;
    }

    std::uint32_t tileId(const pugi::xml_node& node, const std::string& place) const {
        const std::optional<std::uint32_t> id = tileIdOf(number(node, "gid", place, 0));
        if (!id)
            bad(place, "gid: expected a tile id, a whole number in [0, 2^32)");
        return *id;
    }

    Properties properties(const pugi::xml_node& node) const {
        Properties out;
        for (const pugi::xml_node& property : node.child("properties").children("property")) {
            const std::string type = property.attribute("type").value();
            const pugi::xml_attribute value = property.attribute("value");
            const std::string text = value ? value.value() : property.text().get();
            if (type == "bool")
                out[property.attribute("name").value()] = text == "true";
            else if (type == "int" || type == "float" || type == "object")
                out[property.attribute("name").value()] = std::strtod(text.c_str(), nullptr);
            else if (type != "class")
                out[property.attribute("name").value()] = text;
        }
        return out;
    }

    Object object(const pugi::xml_node& node, const std::string& place) const {
        Object o;
        o.id = integer(node, "id", place, 0);
        o.name = node.attribute("name").value();
        o.type = node.attribute("class") ? node.attribute("class").value()
                                         : node.attribute("type").value();
        o.x = number(node, "x", place, 0);
        o.y = number(node, "y", place, 0);
        o.width = number(node, "width", place, 0);
        o.height = number(node, "height", place, 0);
        o.rotation = number(node, "rotation", place, 0);
        o.gid = tileId(node, place);
        o.properties = properties(node);
        if (node.child("ellipse"))
            o.shape = Shape::Ellipse;
        else if (node.child("point"))
            o.shape = Shape::Point;
        else if (node.child("text"))
            o.shape = Shape::Text;
        for (const char* kind : {"polygon", "polyline"})
            if (const pugi::xml_node poly = node.child(kind)) {
                o.shape = std::string(kind) == "polygon" ? Shape::Polygon : Shape::Polyline;
                // "x1,y1 x2,y2 ..."
                const char* at = poly.attribute("points").value();
                while (*at != '\0') {
                    char* end = nullptr;
                    const double x = std::strtod(at, &end);
                    if (end == at || *end != ',')
                        bad(place, std::string(kind) + ": points: expected \"x,y x,y ...\"");
                    at = end + 1;
                    const double y = std::strtod(at, &end);
                    if (end == at)
                        bad(place, std::string(kind) + ": points: expected \"x,y x,y ...\"");
                    o.points.push_back({x, y});
                    at = end;
                    while (*at == ' ')
                        ++at;
                }
            }
        return o;
    }

    std::vector<std::uint32_t> gids(const pugi::xml_node& data, const char* text, std::size_t count,
                                    const std::string& place) const {
        const std::string encoding = data.attribute("encoding").value();
        try {
            if (encoding == "csv")
                return decodeCsvGids(text, count);
            if (encoding == "base64")
                return decodeBase64Gids(text, data.attribute("compression").value(), count);
            if (!encoding.empty())
                bad(place, "data: unknown encoding \"" + encoding + "\"");
            // The oldest form: a <tile gid="..."/> per cell.
            std::vector<std::uint32_t> out;
            for (const pugi::xml_node& tile : data.children("tile"))
                out.push_back(tileId(tile, place));
            if (out.size() != count)
                bad(place, "data: " + std::to_string(out.size()) + " tiles, expected " +
                               std::to_string(count));
            return out;
        } catch (const SceneError&) {
            throw;
        } catch (const std::runtime_error& error) {
            bad(place, error.what());
        }
    }

    void tileData(const pugi::xml_node& node, Layer& layer, const std::string& place) const {
        const pugi::xml_node data = node.child("data");
        try {
            if (!data.child("chunk")) {
                layer.width = integer(node, "width", place, 0);
                layer.height = integer(node, "height", place, 0);
                const std::size_t count = cellCount(layer.width, layer.height);
                layer.gids = data ? gids(data, data.text().get(), count, place)
                                  : std::vector<std::uint32_t>(count);
                return;
            }
            std::vector<Chunk> parts;
            for (const pugi::xml_node& chunk : data.children("chunk")) {
                Chunk part{integer(chunk, "x", place, 0),
                           integer(chunk, "y", place, 0),
                           integer(chunk, "width", place, 0),
                           integer(chunk, "height", place, 0),
                           {}};
                part.gids =
                    gids(data, chunk.text().get(), cellCount(part.width, part.height), place);
                parts.push_back(std::move(part));
            }
            gatherChunks(parts, layer);
        } catch (const SceneError&) {
            throw;
        } catch (const std::runtime_error& error) {
            bad(place, error.what());
        }
    }

    /// The layers under `parent` (the map or a group), in file order.
    void layers(const pugi::xml_node& parent, std::vector<Layer>& out,
                const std::string& prefix) const {
        for (const pugi::xml_node& node : parent.children()) {
            const std::string kind = node.name();
            if (kind != "layer" && kind != "objectgroup" && kind != "group")
                continue;
            Layer layer;
            layer.name = node.attribute("name").value();
            const std::string place = prefix + "layer \"" + layer.name + "\"";
            layer.properties = properties(node);
            layer.offsetX = number(node, "offsetx", place, 0);
            layer.offsetY = number(node, "offsety", place, 0);
            if (kind == "layer") {
                layer.kind = LayerKind::Tiles;
                tileData(node, layer, place);
            } else if (kind == "objectgroup") {
                layer.kind = LayerKind::Objects;
                for (const pugi::xml_node& object : node.children("object"))
                    layer.objects.push_back(this->object(object, place));
            } else {
                layer.kind = LayerKind::Group;
                layers(node, layer.layers, place + ": ");
            }
            out.push_back(std::move(layer));
        }
    }

    Tileset tileset(const pugi::xml_node& node, std::uint32_t firstGid) const {
        Tileset set;
        set.firstGid = firstGid;
        set.name = node.attribute("name").value();
        const std::string place = "tileset \"" + set.name + "\"";
        set.tileWidth = integer(node, "tilewidth", place, 0);
        set.tileHeight = integer(node, "tileheight", place, 0);
        set.tileCount = integer(node, "tilecount", place, 0);
        for (const pugi::xml_node& tile : node.children("tile")) {
            const int id = integer(tile, "id", place, -1);
            if (id < 0)
                bad(place, "a tile without an id");
            Tile& t = set.tiles[id];
            t.properties = properties(tile);
            for (const pugi::xml_node& shape : tile.child("objectgroup").children("object"))
                t.shapes.push_back(object(shape, place + ": tile " + std::to_string(id)));
        }
        return set;
    }
};

pugi::xml_document parse(std::string_view text, const std::string& file) {
    pugi::xml_document document;
    const pugi::xml_parse_result result = document.load_buffer(text.data(), text.size());
    if (!result)
        fail(file, std::string("not XML: ") + result.description() + " at byte " +
                       std::to_string(result.offset));
    return document;
}

} // namespace

Map readTmx(std::string_view text, const std::string& name, const FileReader& readFile) {
    const pugi::xml_document document = parse(text, name);
    const pugi::xml_node root = document.child("map");
    if (!root)
        fail(name, "not a Tiled map (no <map>)");
    const Reader read{name};
    Map map;
    map.orientation = root.attribute("orientation").value();
    map.tileWidth = read.integer(root, "tilewidth", "map", 0);
    map.tileHeight = read.integer(root, "tileheight", "map", 0);
    map.properties = read.properties(root);
    for (const pugi::xml_node& set : root.children("tileset")) {
        const auto firstGid =
            static_cast<std::uint32_t>(read.integer(set, "firstgid", "tileset", 1));
        const std::string source = set.attribute("source").value();
        map.tilesets.push_back(source.empty()
                                   ? read.tileset(set, firstGid)
                                   : readExternalTileset(source, firstGid, name, readFile));
    }
    read.layers(root, map.layers, "");
    return map;
}

Tileset readTilesetTmx(std::string_view text, const std::string& name, std::uint32_t firstGid) {
    const pugi::xml_document document = parse(text, name);
    const pugi::xml_node root = document.child("tileset");
    if (!root)
        fail(name, "not a Tiled tileset (no <tileset>)");
    return Reader{name}.tileset(root, firstGid);
}

} // namespace jostle::tiled
