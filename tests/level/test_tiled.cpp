// Tiled's maps read into levels (src/level/, docs/levels.md). The map of maps/ is drawn to
// be read by hand: 8 x 4 tiles of 16 px; its tileset says tile 0 is solid, 1 one-way, 2 a
// '/' ramp by property, 3 a rectangle covering the tile and 4 a bottom-right triangle in
// the collision editor, 5 nothing (decoration); its ground layer (global ids, 0 empty,
// tile n is n + 1):
//
//     0 0 0 0 0 0 0 0
//     0 0 2 2 0 0 0 6      one-way tiles at columns 2 and 3, a decoration at 7
//     0 0 0 0 0 3 4 5      a '/' by property at 5, a rectangle shape at 6, a triangle at 7
//     1 1 1 1 1 1 1 1      the floor
//
// and its objects: a dynamic crate (friction 0.25) at (32, 0) 16 x 16, a point "spawn" at
// (8, 40), a kinematic "lift" of class "platform" at (96, 32) 32 x 8, an ellipse "ball"
// 16 x 16 at the origin with bounce 0.5, a "zone" with body false and properties coins 3,
// label "bonus", and a static sensor "coin" of class "pickup" at (112, 40) 8 x 8. Its map
// property gravityY is 800. The same map is there as .tmx (CSV), as .tmj with plain,
// base64, zlib and gzip data, and with its tileset in tiles.tsj (make_maps.py writes them).
#include "jostle/level.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "same_scene.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace jostle;

namespace {

const std::string kMaps = JOSTLE_LEVEL_MAPS_DIR;

std::string errorOf(const std::string& text, const std::string& name = "level.tmj") {
    try {
        parseTiled(text, name, {});
    } catch (const SceneError& error) {
        return error.what();
    }
    return "(no error)";
}

/// The level.tmj text with `from` replaced by `to` once.
std::string levelWith(const std::string& from, const std::string& to);

void expectTheMapOfMaps(const Level& level) {
    const Scene& scene = level.scene;
    EXPECT_EQ(scene.world.gravity.x, 0.0f);
    EXPECT_EQ(scene.world.gravity.y, 800.0f);
    // The solid tiles and ramps in one map, the one-way tiles in another.
    ASSERT_EQ(scene.tileMaps.size(), 2u);
    const TileMapDef& solid = scene.tileMaps[0];
    EXPECT_EQ(solid.tile, 16.0f);
    EXPECT_EQ(solid.x, 0.0f);
    EXPECT_EQ(solid.y, 0.0f);
    EXPECT_EQ(solid.rows,
              (std::vector<std::string>{"........", "........", "...../#/", "########"}));
    EXPECT_EQ(solid.oneWay, (Vec2{0, 0}));
    const TileMapDef& oneWay = scene.tileMaps[1];
    EXPECT_EQ(oneWay.rows,
              (std::vector<std::string>{"........", "..##....", "........", "........"}));
    EXPECT_EQ(oneWay.oneWay, (Vec2{0, -1}));

    // Bodies: the crate, the lift, the ball and the coin, in file order; not the point, not
    // the zone.
    ASSERT_EQ(scene.bodies.size(), 4u);
    const BodyDef& crate = scene.bodies[0].def;
    EXPECT_EQ(scene.bodies[0].id, "crate");
    EXPECT_EQ(crate.type, BodyType::Dynamic);
    EXPECT_EQ(crate.x, 40.0f); // 32 + 16 / 2
    EXPECT_EQ(crate.y, 8.0f);
    EXPECT_EQ(crate.hw, 8.0f);
    EXPECT_EQ(crate.hh, 8.0f);
    EXPECT_EQ(crate.friction, 0.25f);
    const BodyDef& lift = scene.bodies[1].def;
    EXPECT_EQ(lift.type, BodyType::Kinematic);
    EXPECT_EQ(lift.x, 112.0f);
    EXPECT_EQ(lift.y, 36.0f);
    EXPECT_EQ(lift.hw, 16.0f);
    EXPECT_EQ(lift.hh, 4.0f);
    const BodyDef& ball = scene.bodies[2].def;
    EXPECT_EQ(ball.radius, 8.0f); // a circle: an ellipse as wide as high
    EXPECT_EQ(ball.bounce, 0.5f);
    const BodyDef& coin = scene.bodies[3].def;
    EXPECT_TRUE(coin.sensor);
    EXPECT_EQ(coin.type, BodyType::Static);

    // Every object by name, with the body made from it.
    ASSERT_EQ(level.objects.size(), 6u);
    const LevelObject* spawn = level.find("spawn");
    ASSERT_NE(spawn, nullptr);
    EXPECT_EQ(spawn->x, 8.0f);
    EXPECT_EQ(spawn->y, 40.0f);
    EXPECT_EQ(spawn->body, -1);
    EXPECT_EQ(spawn->layer, "things");
    EXPECT_EQ(level.find("lift")->body, 1);
    EXPECT_EQ(level.find("lift")->type, "platform");
    EXPECT_EQ(level.find("coin")->type, "pickup");
    const LevelObject* zone = level.find("zone");
    ASSERT_NE(zone, nullptr);
    EXPECT_EQ(zone->body, -1);
    EXPECT_EQ(std::get<double>(zone->properties.at("coins")), 3.0);
    EXPECT_EQ(std::get<std::string>(zone->properties.at("label")), "bonus");
    EXPECT_EQ(level.find("nobody"), nullptr);
}

TEST(Tiled, TheJsonMapOfMapsIsReadAsDrawn) {
    expectTheMapOfMaps(loadTiled(kMaps + "/level.tmj"));
}

TEST(Tiled, TheXmlMapIsTheSameLevel) {
    expectTheMapOfMaps(loadTiled(kMaps + "/level.tmx"));
}

TEST(Tiled, EveryEncodingOfTheLayerGivesTheSameLevel) {
    for (const char* file :
         {"level_base64.tmj", "level_zlib.tmj", "level_gzip.tmj", "level_external.tmj"}) {
        SCOPED_TRACE(file);
        expectTheMapOfMaps(loadTiled(kMaps + "/" + file));
    }
}

TEST(Tiled, TheLevelBuildsAWorldWhereTheBallFallsToTheFloorAndTheCrateStaysOnThePlatform) {
    const Level level = loadTiled(kMaps + "/level.tmj");
    World world(level.scene.world);
    addTileMaps(world, level.scene);
    const std::vector<BodyId> bodies = addBodies(world, level.scene);
    const auto bodyOf = [&](const char* name) {
        return bodies[static_cast<std::size_t>(level.find(name)->body)];
    };
    for (int i = 0; i < 180; ++i)
        world.step(1.0f / 60.0f);
    // Column 0 is open down to the floor, whose top is row 3's, y = 48: the ball of
    // radius 8 rests at y = 40. The crate (x 32 to 48) stands on the one-way tiles of
    // columns 2 and 3, whose top is y = 16: it stays at y = 8.
    EXPECT_NEAR(world.position(bodyOf("ball")).y, 40.0f, 0.05f);
    EXPECT_NEAR(world.position(bodyOf("crate")).y, 8.0f, 0.05f);
}

std::string levelWith(const std::string& from, const std::string& to) {
    std::string text;
    {
        std::FILE* file = std::fopen((kMaps + "/level.tmj").c_str(), "rb");
        char buffer[4096];
        for (std::size_t n; file && (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
            text.append(buffer, n);
        if (file)
            std::fclose(file);
    }
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

TEST(Tiled, AnInfiniteMapsChunksAreGatheredWithinTheirBounds) {
    // Two chunks of 2 x 1 tiles, at tile (-2, -1) and (4, 1): their bounds are 8 x 3 tiles
    // from (-2, -1), so the map's corner is at (-32, -16) and the chunks' solid tiles sit
    // at its columns 0-1 of row 0 and 6-7 of row 2.
    const std::string tileset =
        R"("tilesets": [{"firstgid": 1, "name": "t", "tilewidth": 16, "tileheight": 16,
        "tilecount": 1, "tiles": [{"id": 0, "properties": [{"name": "collision", "type": "string",
        "value": "solid"}]}]}])";
    const Level json = parseTiled(
        R"({"orientation": "orthogonal", "tilewidth": 16, "tileheight": 16, "infinite": true, )" +
            tileset +
            R"(, "layers": [{"type": "tilelayer", "name": "g", "chunks": [
              {"x": -2, "y": -1, "width": 2, "height": 1, "data": [1, 1]},
              {"x": 4, "y": 1, "width": 2, "height": 1, "data": [1, 1]}]}]})",
        "infinite.tmj", {});
    ASSERT_EQ(json.scene.tileMaps.size(), 1u);
    EXPECT_EQ(json.scene.tileMaps[0].x, -32.0f);
    EXPECT_EQ(json.scene.tileMaps[0].y, -16.0f);
    EXPECT_EQ(json.scene.tileMaps[0].rows,
              (std::vector<std::string>{"##......", "........", "......##"}));
    const Level tmx = parseTiled(
        R"(<map orientation="orthogonal" tilewidth="16" tileheight="16" infinite="1">
             <tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="1">
               <tile id="0"><properties><property name="collision" value="solid"/></properties></tile>
             </tileset>
             <layer name="g"><data encoding="csv">
               <chunk x="-2" y="-1" width="2" height="1">1,1</chunk>
               <chunk x="4" y="1" width="2" height="1">1,1</chunk>
             </data></layer></map>)",
        "infinite.tmx", {});
    expectSameScene(tmx.scene, json.scene);
}

TEST(Tiled, ZstdCompressedDataIsRead) {
    // A floor of 4 solid tiles (global id 1): the 16 bytes of its little-endian ids as
    // `zstd -19` compresses them, in base64.
    const Level level = parseTiled(
        R"({"orientation": "orthogonal", "tilewidth": 16, "tileheight": 16,
            "tilesets": [{"firstgid": 1, "name": "t", "tilewidth": 16, "tileheight": 16, "tilecount": 1,
              "tiles": [{"id": 0, "properties": [{"name": "collision", "type": "string", "value": "solid"}]}]}],
            "layers": [{"type": "tilelayer", "name": "g", "width": 4, "height": 1, "encoding": "base64",
                        "compression": "zstd", "data": "KLUv/QRoTQAAAkEBgBCIiAEAe6Fo4A=="}]})",
        "zstd.tmj", {});
    ASSERT_EQ(level.scene.tileMaps.size(), 1u);
    EXPECT_EQ(level.scene.tileMaps[0].rows, std::vector<std::string>{"####"});
}

TEST(Tiled, FlipFlagsTurnRamps) {
    // Tile 2's '/' flipped horizontally is '\', vertically '7', both 'F'.
    const std::string ramp = "\"data\": [\n    0,\n    0,";
    for (const auto& [gid, expected] :
         {std::pair{2147483651u, '\\'}, std::pair{1073741827u, '7'}, std::pair{3221225475u, 'F'}}) {
        const Level level =
            parseTiled(levelWith(ramp, "\"data\": [\n    " + std::to_string(gid) + ",\n    0,"),
                       "level.tmj", {});
        EXPECT_EQ(level.scene.tileMaps[0].rows[0][0], expected) << gid;
    }
}

/// A map of 16 px tiles with no tile layer and one object layer of `objects` (JSON).
std::string mapOfObjects(const std::string& objects) {
    return R"({"orientation": "orthogonal", "tilewidth": 16, "tileheight": 16, "tilesets": [],
               "layers": [{"type": "objectgroup", "name": "lines", "objects": [)" +
           objects + "]}]}";
}

TEST(Tiled, APolylineIsOneSidedSegmentsBlockingOnItsLeft) {
    // Right along y = 100, then up a 45° slope: drawn left to right, it blocks from above.
    const Level level = parseTiled(mapOfObjects(R"({"id": 1, "name": "ground", "x": 0, "y": 100,
                         "polyline": [{"x": 0, "y": 0}, {"x": 32, "y": 0}, {"x": 64, "y": -32}]})"),
                                   "lines.tmj", {});
    ASSERT_EQ(level.scene.bodies.size(), 2u);
    EXPECT_EQ(level.find("ground")->body, 0);
    EXPECT_EQ(level.find("ground")->bodyCount, 2);
    const BodyDef& level0 = level.scene.bodies[0].def;
    EXPECT_EQ(level0.type, BodyType::Static);
    EXPECT_EQ(level0.x, 16.0f);
    EXPECT_EQ(level0.y, 100.0f);
    EXPECT_EQ(level0.hw, 16.0f);
    EXPECT_EQ(level0.hh, 0.5f);
    EXPECT_EQ(level0.oneWay, (Vec2{0, -1}));
    const BodyDef& slope = level.scene.bodies[1].def;
    EXPECT_EQ(slope.x, 48.0f);
    EXPECT_EQ(slope.y, 84.0f);
    EXPECT_EQ(slope.hw, 16.0f);
    EXPECT_EQ(slope.hh, 16.0f);
    EXPECT_EQ(slope.slope, (Vec2{-1, -1})); // a floor rising to the right, y down
    EXPECT_TRUE(slope.segment);
}

TEST(Tiled, APolygonBlocksOnItsOutsideWhicheverWayItIsDrawn) {
    for (const char* points :
         {R"([{"x": 0, "y": 0}, {"x": 32, "y": 0}, {"x": 32, "y": 32}, {"x": 0, "y": 32}])",
          R"([{"x": 0, "y": 0}, {"x": 0, "y": 32}, {"x": 32, "y": 32}, {"x": 32, "y": 0}])"}) {
        SCOPED_TRACE(points);
        const Level level = parseTiled(
            mapOfObjects(
                std::string(R"({"id": 1, "name": "block", "x": 100, "y": 0, "polygon": )") +
                points + "}"),
            "lines.tmj", {});
        ASSERT_EQ(level.scene.bodies.size(), 4u);
        for (const SceneBody& side : level.scene.bodies) {
            // Each side's one-way face looks away from the square's centre (116, 16).
            const Vec2 away{side.def.x - 116.0f, side.def.y - 16.0f};
            EXPECT_GT(side.def.oneWay.x * away.x + side.def.oneWay.y * away.y, 0.0f) << side.id;
        }
    }
}

TEST(Tiled, ProblemsNameTheFileTheLayerAndTheTile) {
    EXPECT_EQ(
        errorOf(levelWith("\"orientation\": \"orthogonal\"", "\"orientation\": \"isometric\"")),
        "level.tmj: \"isometric\" maps are not read: jostle reads orthogonal maps");
    // Something that is not a map at all (an empty object) says so, not "" maps.
    EXPECT_EQ(errorOf(levelWith("\"orientation\": \"orthogonal\",", "")),
              "level.tmj: the map has no orientation: not a Tiled map? (jostle reads orthogonal "
              "maps)");
    EXPECT_EQ(errorOf(levelWith("\"tileheight\": 16,\n \"type\": \"map\"",
                                "\"tileheight\": 8,\n \"type\": \"map\"")),
              "level.tmj: tiles must be square, got 16 x 8");
    EXPECT_EQ(
        errorOf(levelWith("\"value\": \"oneWay\"", "\"value\": \"wall\"")),
        "level.tmj: layer \"ground\": tile 1 (column 2, row 1): collision: expected \"solid\", "
        "\"oneWay\", \"none\" or a ramp's character");
    // Tile 4's triangle made a quadrilateral.
    EXPECT_EQ(errorOf(levelWith("{\n          \"x\": 0,\n          \"y\": 16\n         }",
                                "{\"x\": 0, \"y\": 16}, {\"x\": 0, \"y\": 8}")),
              "level.tmj: layer \"ground\": tile 4 (column 7, row 2): collision shape is not a "
              "rectangle or a ramp");
    EXPECT_EQ(errorOf(levelWith("\"value\": 0.25", "\"value\": 2")),
              "level.tmj: layer \"things\": object \"crate\" (id 1): friction: must be in [0, 1]");
    EXPECT_EQ(
        errorOf(levelWith("\"value\": \"kinematic\"", "\"value\": \"floating\"")),
        "level.tmj: layer \"things\": object \"lift\" (id 3): type: expected one of \"static\", "
        "\"kinematic\", \"dynamic\"");
    EXPECT_EQ(errorOf("{\"orientation\": \"orthogonal\", \"tilewidth\": 16, \"tileheight\": 16, "
                      "\"tilesets\": "
                      "[{\"firstgid\": 1, \"source\": \"missing.tsj\"}], \"layers\": []}"),
              "level.tmj: tileset \"missing.tsj\": its file is needed");
    EXPECT_EQ(errorOf("not json"), "level.tmj: not a Tiled JSON file (not a JSON object)");
    EXPECT_EQ(errorOf("<map orientation=\"orthogonal\"", "level.tmx").substr(0, 19),
              "level.tmx: not XML:");
}

TEST(Tiled, TheExampleLevelIsOneLevelInTiledsTwoFormats) {
    // examples/levels/level.tmj is Tiled's own export of level.tmx (make_level.py).
    const Level tmx = loadTiled(std::string(JOSTLE_LEVEL_EXAMPLES_DIR) + "/level.tmx");
    const Level tmj = loadTiled(std::string(JOSTLE_LEVEL_EXAMPLES_DIR) + "/level.tmj");
    expectSameScene(tmx.scene, tmj.scene);
    ASSERT_EQ(tmx.objects.size(), tmj.objects.size());
    // What its game looks up: a spawn point, a kinematic lift with where it stops, two
    // crates and three coins (sensors).
    const LevelObject* spawn = tmx.find("spawn");
    ASSERT_NE(spawn, nullptr);
    EXPECT_EQ(spawn->body, -1);
    const LevelObject* lift = tmx.find("lift");
    ASSERT_NE(lift, nullptr);
    EXPECT_EQ(tmx.scene.bodies[static_cast<std::size_t>(lift->body)].def.type, BodyType::Kinematic);
    EXPECT_EQ(std::get<double>(lift->properties.at("top")), 104.0);
    EXPECT_EQ(tmx.all("crate").size(), 2u);
    ASSERT_EQ(tmx.all("coin").size(), 3u);
    for (const LevelObject* coin : tmx.all("coin"))
        EXPECT_TRUE(tmx.scene.bodies[static_cast<std::size_t>(coin->body)].def.sensor);
    // Its tiles: the floor's row whole, the hill's ramps turned by a flip, the platforms
    // one-way, the grass nothing.
    ASSERT_EQ(tmx.scene.tileMaps.size(), 2u);
    EXPECT_EQ(tmx.scene.tileMaps[0].rows[14], std::string(40, '#'));
    EXPECT_EQ(tmx.scene.tileMaps[0].rows[13], "#......./####\\.........................#");
    EXPECT_EQ(tmx.scene.tileMaps[1].rows[10], "................#####...................");
}

TEST(Tiled, FuzzInvalidUtf8InAnXmlPropertyIsReadNotThrownAsAnotherError) {
    // fuzz_tiled's first finding: a property value of an XML map holding a 0xFF byte made
    // the JSON the scene loader reads throw nlohmann's type_error, not a SceneError.
    const std::string text =
        "<map orientation=\"orthogonal\" tilewidth=\"16\" tileheight=\"16\"><properties>"
        "<property name=\"solver\" value=\"cl\xFF\"/></properties></map>";
    EXPECT_EQ(errorOf(text, "bad.tmx"),
              "bad.tmx: map properties: solver: expected \"classic\" or \"physical\"");
}

TEST(Tiled, FuzzNumbersPastAnIntOrAFloatAreRefusedByName) {
    // fuzz_tiled's second finding: a layer 1.65556e+59 tiles wide was cast to an int.
    EXPECT_EQ(errorOf("<map orientation=\"orthogonal\" tilewidth=\"16\" tileheight=\"16\">"
                      "<layer name=\"g\" width=\"1.65556e+59\" height=\"1\"/></map>",
                      "bad.tmx"),
              "bad.tmx: layer \"g\": width: expected a whole number");
    EXPECT_EQ(errorOf(mapOfObjects(
                  R"({"id": 1, "name": "far", "x": 1e200, "y": 0, "width": 1, "height": 1})")),
              "level.tmj: layer \"lines\": object \"far\" (id 1): x, y, width and height: expected "
              "numbers "
              "within +-1e30");
    EXPECT_EQ(errorOf(mapOfObjects(R"({"id": 2, "name": "tile", "gid": -3, "x": 0, "y": 0})")),
              "level.tmj: layer \"lines\": gid: expected a tile id, a whole number in [0, 2^32)");
}

TEST(Tiled, AnUnreadableFileIsNamed) {
    try {
        loadTiled(kMaps + "/nothing.tmj");
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), kMaps + "/nothing.tmj: cannot read the file");
    }
}

} // namespace
