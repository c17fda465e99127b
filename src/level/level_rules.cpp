// The rules every editor's level shares (level_rules.hpp).
#include "level_rules.hpp"

#include "body_properties.hpp"
#include "jostle/tilemap.hpp"

#include <cmath>
#include <cstdio>

namespace jostle::level {

namespace {

/// A scene file's text of `scene`, for the scene loader to read with its rules. Text that
/// is not UTF-8 (a property of an XML map may hold any bytes) is written with U+FFFD in
/// place of each bad byte, for the loader to refuse or keep as it would.
std::string sceneText(const Json& scene) {
    return scene.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Json toJson(const PropertyValue& value) {
    return std::visit([](const auto& v) { return Json(v); }, value);
}

} // namespace

void fail(const std::string& file, const std::string& what) {
    throw SceneError(file + ": " + what);
}

std::string readNamedFile(const FileReader& readFile, const std::string& path,
                          const std::string& file, const std::string& place) {
    if (!readFile)
        fail(file, place + ": its file is needed");
    try {
        return readFile(path);
    } catch (const SceneError& error) {
        std::string message = error.what();
        if (message.starts_with(path + ": "))
            message.erase(0, path.size() + 2);
        fail(file, place + ": " + message);
    }
}

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}

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

bool isBodyField(const std::string& name) {
    for (const auto& field : properties::kBodyFields)
        if (name == field.property->name)
            return true;
    return false;
}

Json fieldValue(const std::string& name, const PropertyValue& value) {
    const auto* text = std::get_if<std::string>(&value);
    if (text != nullptr && (name == "oneWay" || name == "slope" || name == "surfaceVelocity")) {
        double x = 0, y = 0;
        char end = 0;
        const std::string bracketed =
            text->find('[') == std::string::npos ? "[" + *text + "]" : *text;
        if (std::sscanf(bracketed.c_str(), " [ %lf , %lf ] %c", &x, &y, &end) == 2)
            return Json::array({x, y});
    }
    return toJson(value);
}

Json bodyFields(const Properties& properties) {
    Json def = Json::object();
    for (const auto& [name, value] : properties)
        if (isBodyField(name))
            def[name] = fieldValue(name, value);
    return def;
}

Json boxBody(const LevelObject& object) {
    Json def = bodyFields(object.properties);
    def["x"] = object.x;
    def["y"] = object.y;
    def["hw"] = object.hw;
    def["hh"] = object.hh;
    return def;
}

bool withinFloats(double v) {
    return std::abs(v) <= 1e30;
}

WorldDef worldFrom(const Properties& p, const std::string& file) {
    Json scene = {{"bodies", Json::array()}};
    if (p.contains("gravityX") || p.contains("gravityY")) {
        const auto number = [&](const char* key) {
            const auto found = p.find(key);
            return found == p.end() ? Json(0) : toJson(found->second);
        };
        scene["gravity"] = Json::array({number("gravityX"), number("gravityY")});
    }
    for (const char* key : {"solver", "sleeping", "maxVelocity"})
        if (const auto found = p.find(key); found != p.end())
            scene[key] = toJson(found->second);
    try {
        return parseScene(sceneText(scene)).world;
    } catch (const SceneError& error) {
        fail(file, std::string("map properties: ") + error.what());
    }
}

TileMapDef tileMapSettings(const Properties& properties, const std::string& file,
                           const std::string& place) {
    Json map = {{"tile", 1}, {"rows", {"#"}}};
    for (const char* key : {"friction", "bounce", "category", "mask", "sensor"})
        if (const auto found = properties.find(key); found != properties.end())
            map[key] = toJson(found->second);
    try {
        return parseScene(sceneText({{"tilemap", map}, {"bodies", Json::array()}}))
            .tileMaps.front();
    } catch (const SceneError& error) {
        std::string message = error.what();
        if (message.starts_with("tilemap."))
            message.erase(0, 8);
        fail(file, place + ": " + message);
    }
}

void LayerTiles::set(std::size_t column, std::size_t row, TileKind kind) {
    (kind.oneWay ? oneWay_ : solid_)[row][column] = kind.tile;
    (kind.oneWay ? anyOneWay_ : anySolid_) |= kind.tile != '.';
}

void LayerTiles::addTo(Level& level, TileMapDef settings) {
    if (anySolid_) {
        settings.rows = std::move(solid_);
        level.scene.tileMaps.push_back(settings);
    }
    if (anyOneWay_) {
        settings.rows = std::move(oneWay_);
        settings.oneWay = {0.0f, -1.0f};
        level.scene.tileMaps.push_back(settings);
    }
}

int LevelBodies::add(Json def, std::string id, std::string place) {
    bodies_.push_back({std::move(def), std::move(id), std::move(place)});
    return size() - 1;
}

void LevelBodies::readInto(Level& level, const std::string& file) const {
    Json defs = Json::array();
    for (const Body& body : bodies_)
        defs.push_back(body.def);
    Scene scene;
    try {
        scene = parseScene(
            sceneText({{"solver", toString(level.scene.world.solver)}, {"bodies", defs}}));
    } catch (const SceneError& error) {
        std::string message = error.what();
        std::size_t index = 0;
        const std::size_t end = message.find(']');
        if (message.starts_with("bodies[") && end != std::string::npos &&
            std::sscanf(message.c_str(), "bodies[%zu]", &index) == 1 && index < bodies_.size()) {
            message.erase(0, end + 1);
            if (message.starts_with("."))
                message.erase(0, 1);
            else if (message.starts_with(": "))
                message.erase(0, 2);
            fail(file, bodies_[index].place + ": " + message);
        }
        fail(file, message);
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        level.scene.bodies.push_back({bodies_[i].id, scene.bodies[i].def});
}

} // namespace jostle::level
