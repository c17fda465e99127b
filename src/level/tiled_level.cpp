// A Tiled map turned into a Level (docs/levels.md): tile layers into tile maps, objects
// into bodies and named objects. The rules a designer meets are here; the formats are
// tiled_json.cpp's and tiled_tmx.cpp's.
#include "tiled_level.hpp"

#include "body_properties.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string_view>

namespace jostle::tiled {

namespace {

/// How a tile collides: a tile map character ('#', '.', a ramp's) and whether it is one-way.
struct TileKind {
    char tile = '.';
    bool oneWay = false;
};

constexpr std::string_view kRamps = "/\\7FrRLlcCDd";

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}

/// The kind a `collision` property names, or nullopt for a name that is none.
std::optional<TileKind> kindNamed(const std::string& name) {
    if (name == "solid")
        return TileKind{'#', false};
    if (name == "oneWay")
        return TileKind{'#', true};
    if (name == "none")
        return TileKind{'.', false};
    if (name.size() == 1 && kRamps.find(name[0]) != std::string_view::npos)
        return TileKind{name[0], false};
    return std::nullopt;
}

/// A ramp seen through Tiled's flips (diagonal first, then horizontal, then vertical, as
/// Tiled applies them); nullopt where the result is no ramp of jostle's (a 2:1 ramp on its
/// side).
std::optional<char> flipped(char tile, std::uint32_t flags) {
    const auto swap = [](char c, std::string_view from, std::string_view to) {
        const std::size_t at = from.find(c);
        return at == std::string_view::npos ? c : to[at];
    };
    if (tile == '#' || tile == '.')
        return tile;
    if (flags & kFlipDiagonal) {
        if (std::string_view("rRLlcCDd").find(tile) != std::string_view::npos)
            return std::nullopt;
        tile = swap(tile, "\\7", "7\\");
    }
    if (flags & kFlipHorizontal)
        tile = swap(tile, "/\\7FrRLlcCDd", "\\/F7lLRrdDCc");
    if (flags & kFlipVertical)
        tile = swap(tile, "/\\7FrRlLcCdD", "7F/\\cCdDrRlL");
    return tile;
}

/// The kind of a tile drawn in Tiled's collision editor: one rectangle covering it is
/// solid, one triangle that is a 45° ramp is that ramp, nothing is nothing; nullopt for
/// anything else.
std::optional<TileKind> kindDrawn(const std::vector<Object>& shapes, double w, double h) {
    if (shapes.empty())
        return TileKind{};
    if (shapes.size() != 1)
        return std::nullopt;
    const Object& s = shapes.front();
    const auto near = [](double a, double b) { return std::abs(a - b) <= 0.5; };
    if (s.shape == Shape::Rectangle && s.gid == 0 && s.rotation == 0.0)
        return near(s.x, 0) && near(s.y, 0) && near(s.width, w) && near(s.height, h)
                   ? std::optional(TileKind{'#', false})
                   : std::nullopt;
    if (s.shape != Shape::Polygon || s.points.size() != 3 || s.rotation != 0.0)
        return std::nullopt;
    // The three corners of the tile the triangle has, as bits: 1 top left, 2 top right,
    // 4 bottom right, 8 bottom left.
    int corners = 0;
    for (const Point& p : s.points) {
        const double x = s.x + p.x, y = s.y + p.y;
        const int corner = near(x, 0) && near(y, 0)   ? 1
                           : near(x, w) && near(y, 0) ? 2
                           : near(x, w) && near(y, h) ? 4
                           : near(x, 0) && near(y, h) ? 8
                                                      : 0;
        if (corner == 0 || (corners & corner))
            return std::nullopt;
        corners |= corner;
    }
    switch (corners) {
    case 2 | 4 | 8:
        return TileKind{'/', false}; // solid bottom right
    case 1 | 4 | 8:
        return TileKind{'\\', false}; // bottom left
    case 1 | 2 | 4:
        return TileKind{'7', false}; // top right
    case 1 | 2 | 8:
        return TileKind{'F', false}; // top left
    default:
        return std::nullopt;
    }
}

/// Body fields of scene files (src/body_properties.hpp): the custom properties a body
/// takes.
bool isBodyField(const std::string& name) {
    for (const auto& field : properties::kBodyFields)
        if (name == field.property->name)
            return true;
    return false;
}

nlohmann::json toJson(const PropertyValue& value) {
    return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

/// A scene file's vector from a custom property: "0, -1" or "[0, -1]" (Tiled has no
/// vector property); anything else goes to the loader as it is, to be refused by name.
nlohmann::json vectorOrAsIs(const PropertyValue& value) {
    if (const auto* text = std::get_if<std::string>(&value)) {
        double x = 0, y = 0;
        char end = 0;
        const std::string trimmed =
            text->find('[') == std::string::npos ? "[" + *text + "]" : *text;
        if (std::sscanf(trimmed.c_str(), " [ %lf , %lf ] %c", &x, &y, &end) == 2)
            return nlohmann::json::array({x, y});
    }
    return toJson(value);
}

/// True for a length a float holds with room: |v| <= 1e30 (NaN is not).
bool withinFloats(double v) {
    return std::abs(v) <= 1e30;
}

/// A scene file's text of `scene`, for the scene loader to read with its rules. Text that
/// is not UTF-8 (a property of an XML map may hold any bytes) is written with U+FFFD in
/// place of each bad byte, for the loader to refuse or keep as it would.
std::string sceneText(const nlohmann::json& scene) {
    return scene.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

class Builder {
public:
    Builder(const Map& map, const std::string& file) : map_(map), file_(file) {}

    Level build() {
        if (map_.orientation != "orthogonal")
            fail(file_,
                 quoted(map_.orientation) + " maps are not read: jostle reads orthogonal maps");
        if (map_.tileWidth <= 0 || map_.tileWidth != map_.tileHeight)
            fail(file_, "tiles must be square, got " + std::to_string(map_.tileWidth) + " x " +
                            std::to_string(map_.tileHeight));
        world();
        for (const Layer& layer : map_.layers)
            this->layer(layer, 0.0, 0.0);
        readBodies();
        return std::move(level_);
    }

private:
    /// The world's settings from the map's custom properties, as a scene file names them:
    /// gravityX and gravityY (Tiled has no vector), solver, sleeping, maxVelocity.
    void world() {
        nlohmann::json scene = {{"bodies", nlohmann::json::array()}};
        const auto& p = map_.properties;
        if (p.contains("gravityX") || p.contains("gravityY")) {
            const auto number = [&](const char* key) {
                const auto found = p.find(key);
                return found == p.end() ? nlohmann::json(0) : toJson(found->second);
            };
            scene["gravity"] = nlohmann::json::array({number("gravityX"), number("gravityY")});
        }
        for (const char* key : {"solver", "sleeping", "maxVelocity"})
            if (const auto found = p.find(key); found != p.end())
                scene[key] = toJson(found->second);
        try {
            level_.scene.world = parseScene(sceneText(scene)).world;
        } catch (const SceneError& error) {
            fail(file_, std::string("map properties: ") + error.what());
        }
    }

    void layer(const Layer& layer, double offsetX, double offsetY) {
        offsetX += layer.offsetX;
        offsetY += layer.offsetY;
        if (!withinFloats(offsetX) || !withinFloats(offsetY))
            fail(file_, "layer " + quoted(layer.name) +
                            ": offsetx and offsety: expected numbers within +-1e30");
        if (layer.kind == LayerKind::Tiles)
            tiles(layer, offsetX, offsetY);
        else if (layer.kind == LayerKind::Objects)
            for (const Object& object : layer.objects)
                this->object(object, layer, offsetX, offsetY);
        else if (layer.kind == LayerKind::Group)
            for (const Layer& child : layer.layers)
                this->layer(child, offsetX, offsetY);
    }

    const Tileset* tilesetOf(std::uint32_t gid) const {
        const Tileset* found = nullptr;
        for (const Tileset& set : map_.tilesets)
            if (set.firstGid <= gid && (found == nullptr || set.firstGid > found->firstGid))
                found = &set;
        return found;
    }

    /// A tile layer: one tile map of its solid tiles and ramps, one of its one-way tiles.
    void tiles(const Layer& layer, double offsetX, double offsetY) {
        const std::string place = "layer " + quoted(layer.name);
        std::optional<TileKind> layerKind;
        if (const auto found = layer.properties.find("collision");
            found != layer.properties.end()) {
            const auto* name = std::get_if<std::string>(&found->second);
            layerKind = name ? kindNamed(*name) : std::nullopt;
            if (!layerKind)
                fail(file_, place + ": collision: expected \"solid\", \"oneWay\", \"none\" or a "
                                    "ramp's character");
        }
        const std::size_t columns = static_cast<std::size_t>(layer.width);
        std::vector<std::string> solid(static_cast<std::size_t>(layer.height),
                                       std::string(columns, '.'));
        std::vector<std::string> oneWay = solid;
        bool anySolid = false, anyOneWay = false;
        for (std::size_t row = 0; row < solid.size(); ++row)
            for (std::size_t column = 0; column < columns; ++column) {
                const std::uint32_t gid = layer.gids[row * columns + column];
                if ((gid & kGidBits) == 0)
                    continue;
                const TileKind kind =
                    kindOf(gid, layer, layerKind, static_cast<int>(column), static_cast<int>(row));
                (kind.oneWay ? oneWay : solid)[row][column] = kind.tile;
                (kind.oneWay ? anyOneWay : anySolid) |= kind.tile != '.';
            }
        TileMapDef def = tileMapSettings(layer, place);
        def.x = static_cast<float>(offsetX + double(layer.left) * map_.tileWidth);
        def.y = static_cast<float>(offsetY + double(layer.top) * map_.tileWidth);
        def.tile = static_cast<float>(map_.tileWidth);
        if (anySolid) {
            def.rows = std::move(solid);
            level_.scene.tileMaps.push_back(def);
        }
        if (anyOneWay) {
            def.rows = std::move(oneWay);
            def.oneWay = {0.0f, -1.0f};
            level_.scene.tileMaps.push_back(def);
        }
    }

    TileKind kindOf(std::uint32_t gid, const Layer& layer, const std::optional<TileKind>& layerKind,
                    int column, int row) const {
        const Tileset* set = tilesetOf(gid & kGidBits);
        const int id = set ? static_cast<int>((gid & kGidBits) - set->firstGid) : -1;
        const std::string place = "layer " + quoted(layer.name) + ": tile " + std::to_string(id) +
                                  " (column " + std::to_string(layer.left + column) + ", row " +
                                  std::to_string(layer.top + row) + ")";
        if (set == nullptr || (set->tileCount > 0 && id >= set->tileCount))
            fail(file_, place + ": no tileset has tile id " + std::to_string(gid & kGidBits));
        if (gid & kRotatedHex)
            fail(file_, place + ": a hexagonal rotation");
        std::optional<TileKind> kind;
        const auto tile = set->tiles.find(id);
        if (tile != set->tiles.end()) {
            if (const auto found = tile->second.properties.find("collision");
                found != tile->second.properties.end()) {
                const auto* name = std::get_if<std::string>(&found->second);
                kind = name ? kindNamed(*name) : std::nullopt;
                if (!kind)
                    fail(file_, place + ": collision: expected \"solid\", \"oneWay\", \"none\" or "
                                        "a ramp's character");
            } else if (!tile->second.shapes.empty()) {
                kind = kindDrawn(tile->second.shapes, set->tileWidth, set->tileHeight);
                if (!kind)
                    fail(file_, place + ": collision shape is not a rectangle or a ramp");
            }
        }
        if (!kind)
            kind = layerKind.value_or(TileKind{});
        const std::optional<char> turned = flipped(kind->tile, gid);
        if (!turned)
            fail(file_, place + ": a 2:1 ramp turned on its side is no ramp of jostle's");
        return {*turned, kind->oneWay};
    }

    /// A tile layer's custom properties that are tile map settings: friction, bounce,
    /// category, mask, sensor.
    TileMapDef tileMapSettings(const Layer& layer, const std::string& place) const {
        nlohmann::json map = {{"tile", 1}, {"rows", {"#"}}};
        for (const char* key : {"friction", "bounce", "category", "mask", "sensor"})
            if (const auto found = layer.properties.find(key); found != layer.properties.end())
                map[key] = toJson(found->second);
        try {
            return parseScene(sceneText(nlohmann::json{{"tilemap", map},
                                                       {"bodies", nlohmann::json::array()}}))
                .tileMaps.front();
        } catch (const SceneError& error) {
            std::string message = error.what();
            if (message.starts_with("tilemap."))
                message.erase(0, 8);
            fail(file_, place + ": " + message);
        }
    }

    void object(const Object& o, const Layer& layer, double offsetX, double offsetY) {
        const std::string place = "layer " + quoted(layer.name) + ": object " +
                                  (o.name.empty() ? "" : quoted(o.name) + " ") + "(id " +
                                  std::to_string(o.id) + ")";
        if (o.rotation != 0.0)
            fail(file_, place + ": rotated objects are not read: jostle's bodies are upright");
        LevelObject out;
        out.name = o.name;
        out.type = o.type;
        out.layer = layer.name;
        out.id = o.id;
        out.properties = o.properties;
        double x = offsetX + o.x, y = offsetY + o.y, w = o.width, h = o.height;
        if (!withinFloats(x) || !withinFloats(y) || !withinFloats(w) || !withinFloats(h))
            fail(file_, place + ": x, y, width and height: expected numbers within +-1e30");
        if (o.gid != 0)
            y -= h; // a tile object stands on its (x, y)
        out.x = static_cast<float>(x + w / 2);
        out.y = static_cast<float>(y + h / 2);
        out.hw = static_cast<float>(w / 2);
        out.hh = static_cast<float>(h / 2);
        const auto body = o.properties.find("body");
        const bool wantsBody = body == o.properties.end() || body->second != PropertyValue(false);
        const std::string id = o.name.empty() ? std::to_string(o.id) : o.name;
        if (wantsBody && (o.shape == Shape::Polygon || o.shape == Shape::Polyline)) {
            out.body = static_cast<int>(bodies_.size());
            addSides(o, x, y, id, place);
            out.bodyCount = static_cast<int>(bodies_.size()) - out.body;
        } else if (wantsBody && (o.shape == Shape::Rectangle || o.shape == Shape::Ellipse)) {
            out.body = static_cast<int>(bodies_.size());
            out.bodyCount = 1;
            bodies_.push_back({bodyOf(o, out), id, place});
        }
        level_.objects.push_back(std::move(out));
    }

    /// The sides of a polygon or polyline at (x, y), each a static one-sided segment
    /// (docs/levels.md): a slanted side a ramp's sloped face alone (BodyDef::segment), a
    /// level or upright side a thin one-way box, each blocking on its outer side (a
    /// polygon's outside; a polyline's left, going from point to point: a line drawn left
    /// to right blocks from above). Their other settings are the object's custom properties.
    void addSides(const Object& o, double x, double y, const std::string& id,
                  const std::string& place) {
        std::vector<Point> points;
        for (const Point& p : o.points)
            points.push_back({x + p.x, y + p.y});
        if (o.shape == Shape::Polygon && points.size() >= 3)
            points.push_back(points.front());
        if (points.size() < 2)
            fail(file_, place + ": a polygon or polyline needs at least two points");
        // Screen y grows downward: a polygon whose shoelace sum is positive goes round
        // clockwise on screen, and its outside is on the left of each side.
        double area = 0;
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
            area += points[i].x * points[i + 1].y - points[i + 1].x * points[i].y;
        const bool outsideOnLeft = o.shape == Shape::Polyline || area > 0;
        constexpr double kThin = 0.5; // the half thickness of a level or upright side
        const auto sign = [](double v) { return v > 0 ? 1.0 : -1.0; };
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const double dx = points[i + 1].x - points[i].x, dy = points[i + 1].y - points[i].y;
            if (dx == 0 && dy == 0)
                continue;
            // The outer normal's direction: the left of (dx, dy) is (dy, -dx) on screen.
            const double nx = outsideOnLeft ? dy : -dy, ny = outsideOnLeft ? -dx : dx;
            nlohmann::json side = nlohmann::json::object();
            for (const auto& [name, value] : o.properties)
                if (isBodyField(name))
                    side[name] = toJson(value);
            if (!side.contains("type"))
                side["type"] = "static";
            side["x"] = (points[i].x + points[i + 1].x) / 2;
            side["y"] = (points[i].y + points[i + 1].y) / 2;
            side["hw"] = dx == 0 ? kThin : std::abs(dx) / 2;
            side["hh"] = dy == 0 ? kThin : std::abs(dy) / 2;
            if (dx != 0 && dy != 0) {
                side["slope"] = {sign(nx), sign(ny)};
                side["segment"] = true;
            } else {
                side["oneWay"] =
                    dx == 0 ? nlohmann::json{sign(nx), 0} : nlohmann::json{0, sign(ny)};
            }
            bodies_.push_back(
                {side, id + "." + std::to_string(i), place + ": side " + std::to_string(i)});
        }
    }

    /// Every body's object read by the scene loader at once, a message about one named
    /// by the place of its object.
    void readBodies() {
        nlohmann::json defs = nlohmann::json::array();
        for (const BodyToRead& body : bodies_)
            defs.push_back(body.def);
        Scene scene;
        try {
            scene = parseScene(
                sceneText({{"solver", toString(level_.scene.world.solver)}, {"bodies", defs}}));
        } catch (const SceneError& error) {
            std::string message = error.what();
            std::size_t index = 0;
            const std::size_t end = message.find(']');
            if (message.starts_with("bodies[") && end != std::string::npos &&
                std::sscanf(message.c_str(), "bodies[%zu]", &index) == 1 &&
                index < bodies_.size()) {
                message.erase(0, end + 1);
                if (message.starts_with("."))
                    message.erase(0, 1);
                else if (message.starts_with(": "))
                    message.erase(0, 2);
                fail(file_, bodies_[index].place + ": " + message);
            }
            fail(file_, message);
        }
        for (std::size_t i = 0; i < bodies_.size(); ++i)
            level_.scene.bodies.push_back({bodies_[i].id, scene.bodies[i].def});
    }

    /// The body of a rectangle, an ellipse (a circle or an upright or lying capsule) or a
    /// tile object: its centre and size from the object, its settings from the custom
    /// properties named as scene files name body fields, read by the scene loader.
    static nlohmann::json bodyOf(const Object& o, const LevelObject& out) {
        nlohmann::json def = nlohmann::json::object();
        for (const auto& [name, value] : o.properties)
            if (isBodyField(name) && name != "x" && name != "y" && name != "hw" && name != "hh")
                def[name] = name == "oneWay" || name == "slope" || name == "surfaceVelocity"
                                ? vectorOrAsIs(value)
                                : toJson(value);
        def["x"] = out.x;
        def["y"] = out.y;
        def["hw"] = out.hw;
        def["hh"] = out.hh;
        if (o.shape == Shape::Ellipse)
            def["radius"] = std::min(out.hw, out.hh);
        return def;
    }

    /// A body to read: its object in a scene file, its id, and the place of its object.
    struct BodyToRead {
        nlohmann::json def;
        std::string id;
        std::string place;
    };

    const Map& map_;
    std::vector<BodyToRead> bodies_;
    const std::string& file_;
    Level level_;
};

} // namespace

Level toLevel(const Map& map, const std::string& file) {
    return Builder(map, file).build();
}

} // namespace jostle::tiled
