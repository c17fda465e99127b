// A Tiled map turned into a Level (docs/levels.md): tile layers into tile maps, objects
// into bodies and named objects. The rules a designer meets are here; the formats are
// tiled_json.cpp's and tiled_tmx.cpp's.
#include "tiled_level.hpp"

#include "level_rules.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string_view>

namespace jostle::tiled {

using namespace jostle::level;

namespace {

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

class Builder {
public:
    Builder(const Map& map, const std::string& file) : map_(map), file_(file) {}

    Level build() {
        if (map_.orientation.empty())
            fail(file_, "the map has no orientation: not a Tiled map? (jostle reads "
                        "orthogonal maps)");
        if (map_.orientation != "orthogonal")
            fail(file_,
                 quoted(map_.orientation) + " maps are not read: jostle reads orthogonal maps");
        if (map_.tileWidth <= 0 || map_.tileWidth != map_.tileHeight)
            fail(file_, "tiles must be square, got " + std::to_string(map_.tileWidth) + " x " +
                            std::to_string(map_.tileHeight));
        level_.scene.world = worldFrom(map_.properties, file_);
        for (const Layer& layer : map_.layers)
            this->layer(layer, 0.0, 0.0);
        bodies_.readInto(level_, file_);
        return std::move(level_);
    }

private:
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
                fail(file_, place + ": collision: " + std::string(kKindsExpected));
        }
        const std::size_t columns = static_cast<std::size_t>(layer.width);
        LayerTiles tiles(columns, static_cast<std::size_t>(layer.height));
        for (std::size_t row = 0; row < static_cast<std::size_t>(layer.height); ++row)
            for (std::size_t column = 0; column < columns; ++column) {
                const std::uint32_t gid = layer.gids[row * columns + column];
                if ((gid & kGidBits) == 0)
                    continue;
                const TileKind kind =
                    kindOf(gid, layer, layerKind, static_cast<int>(column), static_cast<int>(row));
                tiles.set(column, row, kind);
            }
        TileMapDef def = tileMapSettings(layer.properties, file_, place);
        def.x = static_cast<float>(offsetX + double(layer.left) * map_.tileWidth);
        def.y = static_cast<float>(offsetY + double(layer.top) * map_.tileWidth);
        def.tile = static_cast<float>(map_.tileWidth);
        tiles.addTo(level_, def);
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
                    fail(file_, place + ": collision: " + std::string(kKindsExpected));
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
            out.body = bodies_.size();
            addSides(o, x, y, id, place);
            out.bodyCount = bodies_.size() - out.body;
        } else if (wantsBody && (o.shape == Shape::Rectangle || o.shape == Shape::Ellipse)) {
            out.body = bodies_.add(bodyOf(o, out), id, place);
            out.bodyCount = 1;
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
            Json side = bodyFields(o.properties);
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
                side["oneWay"] = dx == 0 ? Json{sign(nx), 0} : Json{0, sign(ny)};
            }
            bodies_.add(side, id + "." + std::to_string(i), place + ": side " + std::to_string(i));
        }
    }

    /// The body of a rectangle, an ellipse (a circle or an upright or lying capsule) or a
    /// tile object: its centre and size from the object, its settings from the custom
    /// properties named as scene files name body fields, read by the scene loader.
    static Json bodyOf(const Object& o, const LevelObject& out) {
        Json def = boxBody(out);
        if (o.shape == Shape::Ellipse)
            def["radius"] = std::min(out.hw, out.hh);
        return def;
    }

    const Map& map_;
    LevelBodies bodies_;
    const std::string& file_;
    Level level_;
};

} // namespace

Level toLevel(const Map& map, const std::string& file) {
    return Builder(map, file).build();
}

} // namespace jostle::tiled
