// LDtk projects read into levels (src/level/ldtk.cpp, docs/levels.md). maps/level.ldtk
// (make_ldtk.py) has two levels. Level_0, 8 x 4 cells of 16 px, its field gravityY 800:
// an IntGrid layer "Collisions" whose values are 1 "solid", 2 "oneWay", 3 "rampRight" and
// 4 "water", laid out as
//
//     0 0 0 0 0 0 0 0
//     0 0 2 2 0 0 0 4      one-way cells at columns 2 and 3, water at 7
//     0 0 0 0 0 3 1 0      a ramp at 5, a solid cell at 6
//     1 1 1 1 1 1 1 1      the floor
//
// and an Entities layer: a Player at px (8, 48) with pivot (0.5, 1), 12 x 16, no fields;
// a Crate at (40, 16) with pivot (0.5, 1), 16 x 16, fields type "dynamic" and friction
// 0.25; a Coin at (116, 44) with pivot (0.5, 0.5), 8 x 8, fields type "static", sensor
// true and value 5. Level_1 is saved apart, in level_1.ldtkl: a solid floor of 8 x 4.
#include "jostle/level.hpp"
#include "same_scene.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace jostle;

namespace {

const std::string kProject = std::string(JOSTLE_LEVEL_MAPS_DIR) + "/level.ldtk";

std::string errorOf(const std::function<void()>& load) {
    try {
        load();
    } catch (const SceneError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(Ldtk, AnIntGridValueWithNoKindIsRefusedByName) {
    // "water" is no kind of jostle's: the game says what it is, or the project is refused.
    EXPECT_EQ(
        errorOf([] { loadLdtk(kProject, "Level_0"); }),
        kProject +
            ": level \"Level_0\": layer \"Collisions\": IntGrid value 4 (\"water\"): expected an "
            "identifier \"solid\", \"oneWay\", \"none\", \"rampRight\", \"rampLeft\", "
            "\"ceilingRight\" or "
            "\"ceilingLeft\", or the value in the kinds table");
}

TEST(Ldtk, TheLevelIsReadAsDrawnWithTheGamesKinds) {
    const Level level = loadLdtk(kProject, "Level_0", {{4, "none"}});
    EXPECT_EQ(level.scene.world.gravity.y, 800.0f);
    ASSERT_EQ(level.scene.tileMaps.size(), 2u);
    EXPECT_EQ(level.scene.tileMaps[0].rows,
              (std::vector<std::string>{"........", "........", "...../#.", "########"}));
    EXPECT_EQ(level.scene.tileMaps[0].tile, 16.0f);
    EXPECT_EQ(level.scene.tileMaps[1].rows,
              (std::vector<std::string>{"........", "..##....", "........", "........"}));
    EXPECT_EQ(level.scene.tileMaps[1].oneWay, (Vec2{0, -1}));

    // The player: a named object only, its box's centre 16 / 2 above its feet at (8, 48).
    const LevelObject* player = level.find("Player");
    ASSERT_NE(player, nullptr);
    EXPECT_EQ(player->x, 8.0f);
    EXPECT_EQ(player->y, 40.0f);
    EXPECT_EQ(player->hw, 6.0f);
    EXPECT_EQ(player->body, -1);
    EXPECT_EQ(player->layer, "Entities");
    EXPECT_EQ(player->type, "Player"); // its identifier is its kind, as Tiled's class is
    EXPECT_EQ(player->id, 0);
    // The crate and the coin: bodies, as their fields say.
    ASSERT_EQ(level.scene.bodies.size(), 2u);
    const BodyDef& crate =
        level.scene.bodies[static_cast<std::size_t>(level.find("Crate")->body)].def;
    EXPECT_EQ(crate.type, BodyType::Dynamic);
    EXPECT_EQ(crate.x, 40.0f);
    EXPECT_EQ(crate.y, 8.0f);
    EXPECT_EQ(crate.friction, 0.25f);
    const LevelObject* coin = level.find("Coin");
    const BodyDef& coinBody = level.scene.bodies[static_cast<std::size_t>(coin->body)].def;
    EXPECT_TRUE(coinBody.sensor);
    EXPECT_EQ(coinBody.x, 116.0f);
    EXPECT_EQ(coinBody.y, 44.0f);
    EXPECT_EQ(std::get<double>(coin->properties.at("value")), 5.0);
    // Read by kind, a missing or mistaken one named with its object.
    EXPECT_EQ(coin->number("value"), 5.0);
    EXPECT_EQ(coin->number("speed", 2.0), 2.0);
    EXPECT_TRUE(coin->flag("sensor", false));
    EXPECT_EQ(errorOf([&] { (void)coin->flag("value"); }),
              "object \"Coin\": property \"value\": expected a flag, got a number");
    EXPECT_EQ(errorOf([&] { (void)coin->text("speed"); }),
              "object \"Coin\": no property \"speed\"");
}

TEST(Ldtk, ALevelSavedApartIsReadFromItsFile) {
    const Level level = loadLdtk(kProject, "Level_1");
    ASSERT_EQ(level.scene.tileMaps.size(), 1u);
    EXPECT_EQ(level.scene.tileMaps[0].rows, std::vector<std::string>(4, "########"));
}

TEST(Ldtk, ALevelNotThereIsRefusedWithTheNamesThereAre) {
    EXPECT_EQ(errorOf([] { loadLdtk(kProject, "Level_9"); }),
              kProject + ": no level \"Level_9\" (the project has \"Level_0\", \"Level_1\")");
    EXPECT_EQ(errorOf([] { parseLdtk("[1, 2]", "bad.ldtk", "Level_0", {}); }),
              "bad.ldtk: not an LDtk project (no \"levels\")");
    EXPECT_EQ(
        errorOf([] {
            loadLdtk(kProject, "Level_0", {{4, "lava"}});
        }),
        kProject +
            ": level \"Level_0\": layer \"Collisions\": IntGrid value 4: the kinds table: expected "
            "\"solid\", \"oneWay\", \"none\" or a ramp's character");
}

TEST(Ldtk, TheExampleLevelIsTheSameLevelAsTiledsExample) {
    // examples/levels/level.ldtk (make_level.py) is level.tmx drawn in LDtk: its IntGrid
    // values name their kinds, its entities' fields their bodies' settings.
    const std::string examples = JOSTLE_LEVEL_EXAMPLES_DIR;
    const Level ldtk = loadLdtk(examples + "/level.ldtk", "Level_0");
    const Level tiled = loadTiled(examples + "/level.tmx");
    expectSameScene(ldtk.scene, tiled.scene);
    ASSERT_EQ(ldtk.objects.size(), tiled.objects.size());
    for (std::size_t i = 0; i < ldtk.objects.size(); ++i) {
        EXPECT_EQ(ldtk.objects[i].name, tiled.objects[i].name);
        EXPECT_EQ(ldtk.objects[i].body, tiled.objects[i].body);
    }
}

} // namespace
