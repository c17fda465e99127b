// Levels drawn in an editor, read into a Scene (docs/levels.md): Tiled's maps (.tmj/.json
// and .tmx, with external tilesets) and LDtk's projects (.ldtk). Part of the scene library
// (jostle::level), never the core.
//
//     jostle::Level level = jostle::loadTiled("level.tmj");
//     jostle::World world(level.scene.world);
//     jostle::addTileMaps(world, level.scene);    // the level first, then its bodies
//     std::vector<jostle::BodyId> bodies = jostle::addBodies(world, level.scene);
//     const jostle::LevelObject* spawn = level.find("spawn");
//     jostle::BodyId lift = bodies[level.find("lift")->body];
//
// Tile layers become tile maps, each tile solid, one-way, a ramp or nothing by its
// `collision` property (or the shape drawn in Tiled's collision editor, or the layer's
// `collision`); objects become bodies, their settings custom properties named as in scene
// files; every object comes back by name with its properties. A problem throws SceneError
// naming the file, layer, tile or object: `level.tmj: layer "ground": tile 37 (column 5,
// row 2): collision shape is not a rectangle or a ramp`.
#pragma once

#include "jostle/scene.hpp"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace jostle {

/// A custom property's value as the editor wrote it: a boolean, a number, or text (a
/// string, a colour, a file, an object's id as its number).
using PropertyValue = std::variant<bool, double, std::string>;

/// An object of a level, as the game looks it up by name: a spawn point, a door, an enemy.
struct LevelObject {
    std::string name;  ///< its name in the editor ("" if none); an LDtk entity's identifier
    std::string type;  ///< Tiled's class (its "type" before Tiled 1.9); an LDtk entity's identifier
    std::string layer; ///< the layer it is on
    int id = 0;        ///< Tiled's object id; 0 for an LDtk entity (its iid is no number)
    float x = 0.0f;    ///< its centre; a point's position
    float y = 0.0f;
    float hw = 0.0f; ///< half its width and height (0 for a point)
    float hh = 0.0f;
    std::map<std::string, PropertyValue> properties; ///< its custom properties, by name
    /// The index in Level::scene.bodies of the body made from it (addBodies returns the
    /// handles in that order), or -1: a point, or an object with `body` false.
    int body = -1;
    /// How many bodies were made from it, from `body` on: 1, or a polygon's or polyline's
    /// sides (one one-sided segment each), or 0.
    int bodyCount = 0;

    /// The custom property of that name as a number, a flag or text. Throws SceneError
    /// naming the object and the property when it has none, or one of another kind:
    /// `object "lift": property "top": expected a number, got text`.
    double number(const std::string& property) const;
    bool flag(const std::string& property) const;
    const std::string& text(const std::string& property) const;
    /// The same, `otherwise` when it has no property of that name.
    double number(const std::string& property, double otherwise) const;
    bool flag(const std::string& property, bool otherwise) const;
    std::string text(const std::string& property, const std::string& otherwise) const;
};

/// A level read from an editor's file: the scene to build, and the objects by name.
struct Level {
    Scene scene;
    std::vector<LevelObject> objects; ///< every object of every object layer, in file order

    /// The first object named `name`, or nullptr.
    const LevelObject* find(std::string_view name) const;
    /// Every object named `name`, in file order.
    std::vector<const LevelObject*> all(std::string_view name) const;
};

/// Gives the text of a file a map names (an external tileset), by the path the map wrote;
/// throws SceneError if there is none.
using FileReader = std::function<std::string(const std::string& path)>;

/// Reads a Tiled map, JSON (.tmj, .json) or XML (.tmx), with the external tilesets it
/// names (.tsj, .json, .tsx) read beside it. Throws SceneError.
Level loadTiled(const std::string& path);

/// Reads a Tiled map from its text; `name` is what errors call it ("level.tmj"), and its
/// external tilesets come from `readFile`. The format is the text's: XML if it starts
/// with '<', else JSON. Throws SceneError.
Level parseTiled(std::string_view text, const std::string& name, const FileReader& readFile);

/// What an LDtk IntGrid value is, by value: "solid", "oneWay", "none" or a ramp's
/// character ("/", "\\", "7", "F", "r", "R", "L", "l", "c", "C", "D", "d").
using IntGridKinds = std::map<int, std::string>;

/// Reads the level named `level` (its identifier) of an LDtk project (.ldtk), from its
/// separate level file (.ldtkl, beside the project) if the project saves levels apart.
/// Each IntGrid value is a tile by `kinds`, or else by its identifier in the project:
/// "solid", "oneWay", "none", or the 45° ramps "rampRight" ("/"), "rampLeft" ("\\"),
/// "ceilingRight" ("7"), "ceilingLeft" ("F"); a value neither names is refused. An entity
/// is a named object, and a body when its fields give its `type` or say `body` true.
/// Throws SceneError.
Level loadLdtk(const std::string& path, const std::string& level, const IntGridKinds& kinds = {});

/// loadLdtk from the project's text; `name` is what errors call it, and a separate level
/// file comes from `readFile`.
Level parseLdtk(std::string_view text, const std::string& name, const std::string& level,
                const FileReader& readFile, const IntGridKinds& kinds = {});

} // namespace jostle
