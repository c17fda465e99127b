// An LDtk project's level read into a Level (docs/levels.md): IntGrid layers into tile maps
// by a value -> kind table or the values' identifiers, entities into named objects and
// bodies. The JSON is ldtk.io's "JSON structure" (1.x); what jostle does not use is skipped.
#include "level_rules.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <stdexcept>

namespace jostle {

namespace {

using namespace level;

/// The kinds an IntGrid value's identifier names: those of a `collision` property, and the
/// 45° ramps by words (an identifier cannot be "/").
std::optional<TileKind> kindOfIdentifier(const std::string& identifier) {
    static const std::map<std::string, char> kRampWords = {
        {"rampRight", '/'}, {"rampLeft", '\\'}, {"ceilingRight", '7'}, {"ceilingLeft", 'F'}};
    if (const auto ramp = kRampWords.find(identifier); ramp != kRampWords.end())
        return TileKind{ramp->second, false};
    if (identifier.size() == 1)
        return std::nullopt; // a ramp's character is not an identifier
    return kindNamed(identifier);
}

class LdtkReader {
public:
    LdtkReader(const std::string& file, const IntGridKinds& kinds) : file_(file), kinds_(kinds) {}

    [[noreturn]] void bad(const std::string& place, const std::string& what) const {
        fail(file_, place + ": " + what);
    }

    const Json& member(const Json& object, const char* key, const std::string& place) const {
        if (!object.is_object() || !object.contains(key))
            bad(place, std::string("missing \"") + key + "\"");
        return object.at(key);
    }
    double number(const Json& object, const char* key, const std::string& place) const {
        const Json& value = member(object, key, place);
        if (!value.is_number() || !withinFloats(value.get<double>()))
            bad(place, std::string(key) + ": expected a number within +-1e30");
        return value.get<double>();
    }
    int integer(const Json& object, const char* key, const std::string& place) const {
        const double value = number(object, key, place);
        if (value != std::trunc(value) || std::abs(value) > 1e9)
            bad(place, std::string(key) + ": expected a whole number");
        return static_cast<int>(value);
    }
    std::string text(const Json& object, const char* key, const std::string& place) const {
        const Json& value = member(object, key, place);
        if (!value.is_string())
            bad(place, std::string(key) + ": expected a string");
        return value.get<std::string>();
    }
    const Json& array(const Json& object, const char* key, const std::string& place) const {
        const Json& value = member(object, key, place);
        if (!value.is_array())
            bad(place, std::string(key) + ": expected an array");
        return value;
    }

    /// Field instances as properties: numbers, booleans, text (strings, enums, colours,
    /// file paths); other fields (points, arrays, entity references) are left out.
    Properties fields(const Json& owner, const std::string& place) const {
        Properties out;
        if (!owner.contains("fieldInstances"))
            return out;
        for (const Json& field : array(owner, "fieldInstances", place)) {
            const std::string name = text(field, "__identifier", place);
            const Json& value = member(field, "__value", place + ": field " + level::quoted(name));
            if (value.is_boolean())
                out[name] = value.get<bool>();
            else if (value.is_number())
                out[name] = value.get<double>();
            else if (value.is_string())
                out[name] = value.get<std::string>();
        }
        return out;
    }

    /// The kind of IntGrid value `value` of a layer: the game's table, else the value's
    /// identifier in the layer's definition.
    TileKind kindOf(int value, const Json* definition, const std::string& place) {
        if (const auto given = kinds_.find(value); given != kinds_.end()) {
            const std::optional<TileKind> kind = kindNamed(given->second);
            if (!kind)
                bad(place, "IntGrid value " + std::to_string(value) +
                               ": the kinds table: " + kKindsExpected);
            return *kind;
        }
        std::string identifier;
        if (definition != nullptr && definition->contains("intGridValues"))
            for (const Json& v : array(*definition, "intGridValues", place))
                if (v.is_object() && v.value("value", -1) == value && v.contains("identifier") &&
                    v["identifier"].is_string())
                    identifier = v["identifier"].get<std::string>();
        const std::optional<TileKind> kind = kindOfIdentifier(identifier);
        if (!kind)
            bad(place,
                "IntGrid value " + std::to_string(value) +
                    (identifier.empty() ? " (no identifier)"
                                        : " (" + level::quoted(identifier) + ")") +
                    ": expected an identifier \"solid\", \"oneWay\", \"none\", \"rampRight\", "
                    "\"rampLeft\", \"ceilingRight\" or \"ceilingLeft\", or the value in the kinds "
                    "table");
        return *kind;
    }

    void intGrid(const Json& layer, const Json* definition, const std::string& place,
                 Level& level) {
        const int columns = integer(layer, "__cWid", place), rows = integer(layer, "__cHei", place);
        const int grid = integer(layer, "__gridSize", place);
        if (columns < 0 || rows < 0 || double(columns) * rows > double(1 << 26) || grid <= 0)
            bad(place, "__cWid, __cHei and __gridSize: expected a grid of at most 2^26 cells of a "
                       "size > 0");
        const Json& cells = array(layer, "intGridCsv", place);
        if (cells.size() != static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows))
            bad(place, "intGridCsv: " + std::to_string(cells.size()) + " cells, expected " +
                           std::to_string(columns) + " x " + std::to_string(rows));
        const auto width = static_cast<std::size_t>(columns);
        LayerTiles tiles(width, static_cast<std::size_t>(rows));
        std::map<int, TileKind> known;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (!cells[i].is_number_integer())
                bad(place, "intGridCsv: expected whole numbers");
            const int value = cells[i].get<int>();
            if (value == 0)
                continue;
            auto found = known.find(value);
            if (found == known.end())
                found = known.emplace(value, kindOf(value, definition, place)).first;
            tiles.set(i % width, i / width, found->second);
        }
        TileMapDef def = tileMapSettings(fields(layer, place), file_, place);
        def.x = static_cast<float>(number(layer, "__pxTotalOffsetX", place));
        def.y = static_cast<float>(number(layer, "__pxTotalOffsetY", place));
        def.tile = static_cast<float>(grid);
        tiles.addTo(level, def);
    }

    /// An entity: a named object, and a body when its fields say `body` true or give its
    /// `type`, its settings the fields named as scene files name body fields.
    void entity(const Json& entity, const std::string& layerName, const Json& layer,
                const std::string& layerPlace, Level& level) {
        LevelObject out;
        out.name = text(entity, "__identifier", layerPlace);
        out.type = out.name; // an entity's identifier is its kind, as Tiled's class is
        out.layer = layerName;
        const std::string place = layerPlace + ": entity " + level::quoted(out.name);
        out.properties = fields(entity, place);
        const Json& px = array(entity, "px", place);
        const Json pivot = entity.contains("__pivot") ? entity["__pivot"] : Json::array({0.0, 0.0});
        if (px.size() != 2 || !px[0].is_number() || !px[1].is_number() || !pivot.is_array() ||
            pivot.size() != 2 || !pivot[0].is_number() || !pivot[1].is_number())
            bad(place, "px and __pivot: expected [x, y] numbers");
        const double w = number(entity, "width", place), h = number(entity, "height", place);
        const double left = number(layer, "__pxTotalOffsetX", layerPlace) + px[0].get<double>() -
                            pivot[0].get<double>() * w;
        const double top = number(layer, "__pxTotalOffsetY", layerPlace) + px[1].get<double>() -
                           pivot[1].get<double>() * h;
        if (!withinFloats(left) || !withinFloats(top) || !withinFloats(w) || !withinFloats(h))
            bad(place, "px, width and height: expected numbers within +-1e30");
        out.x = static_cast<float>(left + w / 2);
        out.y = static_cast<float>(top + h / 2);
        out.hw = static_cast<float>(w / 2);
        out.hh = static_cast<float>(h / 2);
        const auto body = out.properties.find("body");
        const bool wantsBody =
            out.properties.contains("type") ||
            (body != out.properties.end() && body->second == PropertyValue(true));
        if (wantsBody) {
            out.body = bodies_.add(boxBody(out), out.name, place);
            out.bodyCount = 1;
        }
        level.objects.push_back(std::move(out));
    }

    Level read(const Json& project, const std::string& wanted, const FileReader& readFile) {
        if (!project.is_object() || !project.contains("levels"))
            fail(file_, "not an LDtk project (no \"levels\")");
        // The layers' definitions, for their IntGrid values' identifiers.
        std::map<int, const Json*> definitions;
        if (project.contains("defs") && project["defs"].is_object() &&
            project["defs"].contains("layers"))
            for (const Json& definition : array(project["defs"], "layers", "defs"))
                if (definition.is_object() && definition.contains("uid") &&
                    definition["uid"].is_number_integer())
                    definitions[definition["uid"].get<int>()] = &definition;
        std::string names;
        for (const Json& candidate : array(project, "levels", "project")) {
            const std::string name = text(candidate, "identifier", "levels");
            names += (names.empty() ? "" : ", ") + level::quoted(name);
            if (name != wanted)
                continue;
            const std::string place = "level " + level::quoted(name);
            // A project that saves its levels apart names each level's file.
            Json separate;
            const Json* level = &candidate;
            if (!candidate.contains("layerInstances") || candidate["layerInstances"].is_null()) {
                const std::string path = text(candidate, "externalRelPath", place);
                // As a string_view, as every text is parsed: one parser in the code.
                const std::string levelText =
                    readNamedFile(readFile, path, file_, place + ": " + level::quoted(path));
                separate = Json::parse(std::string_view(levelText), nullptr, false);
                if (separate.is_discarded() || !separate.is_object())
                    bad(place,
                        level::quoted(path) + ": not an LDtk level file (not a JSON object)");
                level = &separate;
            }
            Level out;
            out.scene.world = worldFrom(fields(*level, place), file_);
            // LDtk lists layers top first; they are read bottom first, as drawn.
            const Json& layers = array(*level, "layerInstances", place);
            for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
                const std::string layerName = text(*layer, "__identifier", place);
                const std::string layerPlace = place + ": layer " + level::quoted(layerName);
                const std::string type = text(*layer, "__type", layerPlace);
                const auto definition =
                    layer->contains("layerDefUid") && (*layer)["layerDefUid"].is_number_integer()
                        ? definitions.find((*layer)["layerDefUid"].get<int>())
                        : definitions.end();
                if (type == "IntGrid")
                    intGrid(*layer, definition == definitions.end() ? nullptr : definition->second,
                            layerPlace, out);
                else if (type == "Entities")
                    for (const Json& e : array(*layer, "entityInstances", layerPlace))
                        entity(e, layerName, *layer, layerPlace, out);
            }
            bodies_.readInto(out, file_);
            return out;
        }
        fail(file_, "no level " + level::quoted(wanted) + " (the project has " +
                        (names.empty() ? "none" : names) + ")");
    }

private:
    const std::string& file_;
    const IntGridKinds& kinds_;
    LevelBodies bodies_;
};

} // namespace

Level parseLdtk(std::string_view text, const std::string& name, const std::string& level,
                const FileReader& readFile, const IntGridKinds& kinds) {
    const Json project = Json::parse(text, nullptr, false);
    if (project.is_discarded())
        fail(name, "not an LDtk project (not JSON)");
    try {
        return LdtkReader(name, kinds).read(project, level, readFile);
    } catch (const Json::exception& error) {
        fail(name, std::string("not an LDtk project: ") + error.what());
    }
}

} // namespace jostle
