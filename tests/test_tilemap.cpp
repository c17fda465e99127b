// Tile maps: how tiles become boxes, setTile against a map built from scratch, the
// handles and checks, and the promise that matters to a game: a box sliding along a
// floor or a wall of tiles never catches on an edge between two tiles.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace jostle {
namespace {

// A box as the world sees it, to compare maps by their bodies.
struct Rect {
    Vec2 centre;
    Vec2 half;
    friend bool operator==(const Rect&, const Rect&) = default;
    friend bool operator<(const Rect& a, const Rect& b) {
        return std::tie(a.centre.x, a.centre.y, a.half.x, a.half.y) <
               std::tie(b.centre.x, b.centre.y, b.half.x, b.half.y);
    }
};

std::vector<Rect> rectsOf(const World& world, TileMapId map) {
    std::vector<Rect> rects;
    for (BodyId body : tileMapBodies(world, map))
        rects.push_back({world.position(body), world.halfExtents(body)});
    return rects;
}

std::vector<Rect> sorted(std::vector<Rect> rects) {
    std::sort(rects.begin(), rects.end());
    return rects;
}

/// The box of tiles [column, column + columns) × [row, row + rows) of a map at (x, y).
Rect tiles(float x, float y, float tile, int column, int row, int columns, int rows) {
    return {{x + (float(column) + float(columns) / 2) * tile,
             y + (float(row) + float(rows) / 2) * tile},
            {float(columns) * tile / 2, float(rows) * tile / 2}};
}

TileMapDef mapDef(std::vector<std::string> rows, float tile = 16, float x = 0, float y = 0) {
    TileMapDef def;
    def.x = x;
    def.y = y;
    def.tile = tile;
    def.rows = std::move(rows);
    return def;
}

std::string errorOf(const TileMapDef& def) {
    auto problem = checkTileMapDef(def);
    return problem ? problem->field + ": " + problem->problem : "";
}

// --- From tiles to boxes ------------------------------------------------------------------

TEST(TileMapBoxes, RowsBecomeRunsAndRunsOfTheSameExtentStack) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"##..##", //
                                                       "##..##", //
                                                       "######", //
                                                       "#....#"},
                                                      16, 10, 20));
    // Top row first, left to right: the two stacks of rows 0-1, the full row 2, the two
    // single tiles of row 3.
    EXPECT_EQ(rectsOf(world, map), (std::vector<Rect>{
                                       tiles(10, 20, 16, 0, 0, 2, 2),
                                       tiles(10, 20, 16, 4, 0, 2, 2),
                                       tiles(10, 20, 16, 0, 2, 6, 1),
                                       tiles(10, 20, 16, 0, 3, 1, 1),
                                       tiles(10, 20, 16, 5, 3, 1, 1),
                                   }));
    EXPECT_EQ(world.bodyCount(), 5u);
    for (BodyId body : tileMapBodies(world, map))
        EXPECT_EQ(world.type(body), BodyType::Static);
}

TEST(TileMapBoxes, AFloorAWallAndABlockAreOneBoxEach) {
    World world;
    EXPECT_EQ(tileMapBodies(world, createTileMap(world, mapDef({std::string(500, '#')}))).size(),
              1u);
    EXPECT_EQ(tileMapBodies(world, createTileMap(world, mapDef(std::vector<std::string>(300, "#"))))
                  .size(),
              1u);
    EXPECT_EQ(tileMapBodies(world, createTileMap(world, mapDef(std::vector<std::string>(
                                                            40, std::string(60, '#')))))
                  .size(),
              1u);
}

TEST(TileMapBoxes, AnEmptyMapHasNoBodies) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"....", "...."}));
    EXPECT_TRUE(tileMapBodies(world, map).empty());
    EXPECT_EQ(world.bodyCount(), 0u);
    EXPECT_EQ(tileMapColumns(world, map), 4);
    EXPECT_EQ(tileMapRows(world, map), 2);
}

TEST(TileMapBoxes, EveryBodyHasTheMapsSettings) {
    World world;
    int tag = 0;
    TileMapDef def = mapDef({"#.#", "###"});
    def.friction = 0.25f;
    def.bounce = 0.75f;
    def.category = 4;
    def.mask = 6;
    def.oneWay = {0, -1};
    def.sensor = true;
    def.userData = &tag;
    const TileMapId map = createTileMap(world, def);
    ASSERT_EQ(tileMapBodies(world, map).size(), 3u);
    for (BodyId body : tileMapBodies(world, map)) {
        EXPECT_EQ(world.friction(body), 0.25f);
        EXPECT_EQ(world.bounce(body), 0.75f);
        EXPECT_EQ(world.category(body), 4u);
        EXPECT_EQ(world.mask(body), 6u);
        EXPECT_EQ(world.oneWay(body), (Vec2{0, -1}));
        EXPECT_TRUE(world.isSensor(body));
        EXPECT_EQ(world.userData(body), &tag);
    }
}

TEST(TileMapBoxes, BodiesKnowTheirMap) {
    World world;
    const TileMapId a = createTileMap(world, mapDef({"#.#"}));
    const TileMapId b = createTileMap(world, mapDef({"##"}, 16, 0, 100));
    const BodyId crate = world.createBody({.hw = 1, .hh = 1});
    for (BodyId body : tileMapBodies(world, a))
        EXPECT_EQ(tileMapOf(world, body), a);
    for (BodyId body : tileMapBodies(world, b))
        EXPECT_EQ(tileMapOf(world, body), b);
    EXPECT_TRUE(tileMapOf(world, crate).isNull());
    const BodyId gone = tileMapBodies(world, a)[0];
    destroyTileMap(world, a);
    EXPECT_THROW(tileMapOf(world, gone), Error);
}

TEST(TileMapBoxes, TheMapReadsBackAsItIs) {
    World world;
    int tag = 0;
    TileMapDef def = mapDef({"#..#", "####"}, 8, -3, 5);
    def.friction = 0.125f;
    def.userData = &tag;
    const TileMapId map = createTileMap(world, def);
    setTile(world, map, 1, 0, true);
    const TileMapDef back = tileMapDef(world, map);
    EXPECT_EQ(back.rows, (std::vector<std::string>{"##.#", "####"}));
    EXPECT_EQ(back.x, -3.0f);
    EXPECT_EQ(back.y, 5.0f);
    EXPECT_EQ(back.tile, 8.0f);
    EXPECT_EQ(back.friction, 0.125f);
    EXPECT_EQ(back.userData, &tag);
}

TEST(TileMapBoxes, IsSolidAndTileAt) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"#.", ".#"}, 10, 100, 200));
    EXPECT_TRUE(isSolid(world, map, 0, 0));
    EXPECT_FALSE(isSolid(world, map, 1, 0));
    EXPECT_TRUE(isSolid(world, map, 1, 1));
    // Outside the map is empty.
    for (auto [column, row] : {std::pair{-1, 0}, {2, 0}, {0, -1}, {0, 2}})
        EXPECT_FALSE(isSolid(world, map, column, row));

    EXPECT_EQ(tileAt(world, map, {100, 200}), (TileCoord{0, 0}));
    EXPECT_EQ(tileAt(world, map, {109.9f, 219.9f}), (TileCoord{0, 1}));
    EXPECT_EQ(tileAt(world, map, {110, 210}), (TileCoord{1, 1})); // an edge: the larger
    EXPECT_EQ(tileAt(world, map, {99.9f, 205}), std::nullopt);
    EXPECT_EQ(tileAt(world, map, {120, 205}), std::nullopt);
    EXPECT_EQ(tileAt(world, map, {105, 220}), std::nullopt);
    EXPECT_THROW(tileAt(world, map, {std::numeric_limits<float>::quiet_NaN(), 0}), Error);
}

// --- Checks and handles -------------------------------------------------------------------

TEST(TileMapChecks, EveryBadDefinitionIsNamed) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const auto with = [](auto change) {
        TileMapDef def = mapDef({"#.", ".#"});
        change(def);
        return errorOf(def);
    };
    EXPECT_EQ(errorOf(mapDef({"#.", ".#"})), "");
    EXPECT_EQ(with([&](TileMapDef& d) { d.x = nan; }), "x: must be a finite number");
    EXPECT_EQ(with([&](TileMapDef& d) { d.y = inf; }), "y: must be a finite number");
    EXPECT_EQ(with([&](TileMapDef& d) { d.tile = nan; }), "tile: must be a finite number");
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = 0; }), "tile: must be > 0");
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = -16; }), "tile: must be > 0");
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = std::numeric_limits<float>::denorm_min(); }),
              "tile: must be >= 2e-9");
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = 1e38f; }), "tile: must be of magnitude <= 1e9");
    // Two tiles of 6e8 from x = 0 end at 1.2e9, beyond the range of math.hpp.
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = 6e8f; }),
              "tile: puts the map's far corner beyond 1e9 (math.hpp)");
    EXPECT_EQ(with([](TileMapDef& d) { d.tile = 4e8f; }), "");
    EXPECT_EQ(with([](TileMapDef& d) { d.rows.clear(); }), "rows: must have at least one row");
    EXPECT_EQ(with([](TileMapDef& d) {
                  d.rows = {"", ""};
              }),
              "rows[0]: must have at least one column");
    EXPECT_EQ(with([](TileMapDef& d) {
                  d.rows = {"##", "#", "##"};
              }),
              "rows[1]: has 1 columns, rows[0] has 2");
    EXPECT_EQ(with([](TileMapDef& d) {
                  d.rows = {"##", "##", "#.", "#.#..x"};
              }),
              "rows[3][5]: expected '#', '.' or a ramp, got 'x'");
    EXPECT_EQ(with([](TileMapDef& d) {
                  d.rows = {"#", " "};
              }),
              "rows[1][0]: expected '#', '.' or a ramp, got ' '");
    EXPECT_EQ(with([](TileMapDef& d) { d.rows = {"#\t"}; }),
              "rows[0][1]: expected '#', '.' or a ramp, got byte 0x09");
    EXPECT_EQ(with([](TileMapDef& d) { d.rows = {"#\xC3\xA9"}; }), // é in UTF-8
              "rows[0][1]: expected '#', '.' or a ramp, got byte 0xC3");
    EXPECT_EQ(with([](TileMapDef& d) { d.friction = 1.5f; }), "friction: must be in [0, 1]");
    EXPECT_EQ(with([](TileMapDef& d) { d.bounce = -0.5f; }), "bounce: must be in [0, 1]");
    EXPECT_EQ(with([](TileMapDef& d) {
                  d.oneWay = {1, 1};
              }),
              "oneWay: must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}");
}

TEST(TileMapChecks, CreateTileMapRefusesWhatTheCheckRefusesAndCreatesNothing) {
    World world;
    try {
        createTileMap(world, mapDef({"#.", "#x"}));
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()),
                  "createTileMap: TileMapDef.rows[1][1]: expected '#', '.' or a ramp, got 'x'");
    }
    EXPECT_EQ(world.bodyCount(), 0u);
}

TEST(TileMapChecks, TheClassicModelRefusesRampTilesAndChangesNothing) {
    // Its bodies are sharp boxes only (createBody refuses a slope there): a map with a ramp
    // is refused before its solid tiles are made, a ramp set on a tile leaves it as it was.
    World world(WorldDef{.solver = Solver::Classic});
    try {
        createTileMap(world, mapDef({"##..", "##/."}));
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()), "createTileMap: TileMapDef.rows[1][2]: the classic "
                                             "model has sharp boxes only: no ramps");
    }
    EXPECT_EQ(world.bodyCount(), 0u);
    const TileMapId map = createTileMap(world, mapDef({"##.."}));
    try {
        setTile(world, map, 2, 0, '/');
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()),
                  "setTile: the classic model has sharp boxes only: no ramps");
    }
    EXPECT_EQ(tileOf(world, map, 2, 0), '.');
    EXPECT_EQ(world.bodyCount(), 1u);
    setTile(world, map, 2, 0, '#'); // solid tiles still change
    EXPECT_EQ(world.bodyCount(), 1u);
    EXPECT_EQ(world.halfExtents(tileMapBodies(world, map)[0]), (Vec2{24, 8}));
}

// Found by fuzz_api (tests/fuzz/corpus/api/one-way-ramp-tiles-1): a one-way map with a
// ramp was accepted by checkTileMapDef, then createTileMap made the map's boxes and threw
// at the ramp (createBody refuses oneWay for a ramp), leaving the boxes with no map; setTile
// threw from the same place with the tile already changed. A ramp blocks from every side,
// so a one-way map has boxes only, and both refuse a ramp before anything is made.
TEST(TileMapChecks, AOneWayMapRefusesRampTilesAndChangesNothing) {
    World world;
    TileMapDef def = mapDef({"##..", "##/."});
    def.oneWay = {0, -1};
    ASSERT_TRUE(checkTileMapDef(def).has_value());
    EXPECT_EQ(checkTileMapDef(def)->field, "rows[1][2]");
    try {
        createTileMap(world, def);
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()),
                  "createTileMap: TileMapDef.rows[1][2]: a one-way map has boxes only: no ramps "
                  "(a ramp blocks from every side)");
    }
    EXPECT_EQ(world.bodyCount(), 0u);
    def.rows = {"##.."};
    const TileMapId map = createTileMap(world, def);
    for (char ramp : {'/', 'l', 'D'}) {
        EXPECT_THROW(setTile(world, map, 2, 0, ramp), Error) << ramp;
        EXPECT_EQ(tileOf(world, map, 2, 0), '.');
        EXPECT_EQ(world.bodyCount(), 1u);
    }
}

// Found by fuzz_api (tests/fuzz/corpus/api/small-ramp-tiles-1): the half of a 2:1 ramp is
// a body half a tile high, so a quarter tile in half height; checkTileMapDef held only
// whole tiles to the smallest size (a half extent of 1e-9, math.hpp) and accepted a map of
// tiles 2e-9 wide with such a half, which createTileMap then failed to make after the
// map's box. A 45-degree ramp takes a whole tile and is made at that size.
TEST(TileMapChecks, TheHalvesOf2To1RampsMustBeBodiesOfTheSmallestSizeOrMore) {
    TileMapDef def{.tile = 2e-9f, .rows = {"#l"}};
    ASSERT_TRUE(checkTileMapDef(def).has_value());
    EXPECT_EQ(checkTileMapDef(def)->field, "tile");
    World world;
    EXPECT_THROW(createTileMap(world, def), Error);
    EXPECT_EQ(world.bodyCount(), 0u);
    def.rows = {"#/"}; // a whole tile: half extents of 1e-9
    EXPECT_FALSE(checkTileMapDef(def).has_value());
    const TileMapId map = createTileMap(world, def);
    EXPECT_EQ(world.bodyCount(), 2u);
    EXPECT_THROW(setTile(world, map, 1, 0, 'r'), Error);
    EXPECT_EQ(tileOf(world, map, 1, 0), '/');
    EXPECT_EQ(world.bodyCount(), 2u);
    def.tile = 4e-9f; // its halves' half height 1e-9: the smallest size
    def.rows = {"#l"};
    EXPECT_FALSE(checkTileMapDef(def).has_value());
    EXPECT_NO_THROW(createTileMap(world, def));
}

// Found by fuzz_api (tests/fuzz/corpus/api/classic-with-ramp-tiles-1): a map whose ramp
// bodies the game destroyed keeps its ramp tiles; with no shaped body left, setSolver took
// the classic model, and the next setTile in that row, even to '.', threw from rebuilding
// the row's ramps with the tile already changed. setSolver now refuses the classic model
// while a map has ramp tiles.
TEST(TileMapChecks, TheClassicModelIsRefusedWhileAMapHasRampTiles) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"#/."}));
    for (BodyId body :
         std::vector<BodyId>(tileMapBodies(world, map).begin(), tileMapBodies(world, map).end()))
        if (world.bodyDef(body).slope != Vec2{})
            world.destroyBody(body);
    EXPECT_THROW(world.setSolver(Solver::Classic), Error);
    EXPECT_EQ(world.solver(), Solver::Physical);
    setTile(world, map, 1, 0, '.'); // no ramp tile left
    world.setSolver(Solver::Classic);
    EXPECT_EQ(world.solver(), Solver::Classic);
}

TEST(TileMapChecks, HandlesAreChecked) {
    World world;
    World other;
    const TileMapId map = createTileMap(world, mapDef({"##"}));
    EXPECT_TRUE(world.isValid(map));
    EXPECT_FALSE(world.isValid(TileMapId{}));
    EXPECT_FALSE(other.isValid(map));
    EXPECT_THROW(setTile(world, TileMapId{}, 0, 0, false), Error);
    EXPECT_THROW(setTile(other, map, 0, 0, false), Error);
    // Another world's map in the same slot is still another world's.
    const TileMapId otherMap = createTileMap(other, mapDef({"##"}));
    EXPECT_EQ(otherMap.index, map.index);
    EXPECT_FALSE(world.isValid(otherMap));
    EXPECT_FALSE(other.isValid(map));
    EXPECT_THROW(setTile(other, map, 0, 0, false), Error);

    destroyTileMap(world, map);
    EXPECT_FALSE(world.isValid(map));
    EXPECT_EQ(world.bodyCount(), 0u);
    EXPECT_THROW(setTile(world, map, 0, 0, false), Error);
    EXPECT_THROW(isSolid(world, map, 0, 0), Error);
    EXPECT_THROW(tileMapBodies(world, map), Error);
    EXPECT_THROW(destroyTileMap(world, map), Error);

    // The slot is reused under a new generation: the old handle stays stale.
    const TileMapId again = createTileMap(world, mapDef({"#"}));
    EXPECT_EQ(again.index, map.index);
    EXPECT_NE(again, map);
    EXPECT_FALSE(world.isValid(map));
    EXPECT_TRUE(world.isValid(again));
}

TEST(TileMapChecks, SetTileOutsideTheMapThrowsAndChangesNothing) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"##", "##"}));
    const std::vector<BodyId> before(tileMapBodies(world, map).begin(),
                                     tileMapBodies(world, map).end());
    for (auto [column, row] : {std::pair{-1, 0}, {2, 0}, {0, -1}, {0, 2}}) {
        try {
            setTile(world, map, column, row, false);
            FAIL() << "no jostle::Error";
        } catch (const Error& error) {
            EXPECT_EQ(std::string(error.what()), "setTile: column " + std::to_string(column) +
                                                     ", row " + std::to_string(row) +
                                                     " is outside the map (2 columns, 2 rows)");
        }
    }
    EXPECT_EQ(
        std::vector<BodyId>(tileMapBodies(world, map).begin(), tileMapBodies(world, map).end()),
        before);
}

TEST(TileMapChecks, BodiesDestroyedByTheGameAreForgotten) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"###"}));
    world.destroyBody(tileMapBodies(world, map)[0]);
    setTile(world, map, 1, 0, false); // rebuilds around the body that is gone
    EXPECT_EQ(rectsOf(world, map),
              (std::vector<Rect>{tiles(0, 0, 16, 0, 0, 1, 1), tiles(0, 0, 16, 2, 0, 1, 1)}));
    destroyTileMap(world, map);
    EXPECT_EQ(world.bodyCount(), 0u);
}

// --- setTile -------------------------------------------------------------------------------

TEST(SetTile, SettingATileToWhatItIsChangesNothing) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"#.", "##"}));
    const std::vector<BodyId> before(tileMapBodies(world, map).begin(),
                                     tileMapBodies(world, map).end());
    setTile(world, map, 0, 0, true);
    setTile(world, map, 1, 0, false);
    EXPECT_EQ(
        std::vector<BodyId>(tileMapBodies(world, map).begin(), tileMapBodies(world, map).end()),
        before);
}

TEST(SetTile, CuttingAStackLeavesItsPartsAboveAndBelow) {
    World world;
    const TileMapId map = createTileMap(world, mapDef({"##", "##", "##", "##"}));
    ASSERT_EQ(tileMapBodies(world, map).size(), 1u);
    setTile(world, map, 0, 1, false);
    EXPECT_EQ(sorted(rectsOf(world, map)), sorted({
                                               tiles(0, 0, 16, 0, 0, 2, 1),
                                               tiles(0, 0, 16, 1, 1, 1, 1),
                                               tiles(0, 0, 16, 0, 2, 2, 2),
                                           }));
    // Putting it back joins the three into one again.
    setTile(world, map, 0, 1, true);
    EXPECT_EQ(rectsOf(world, map), (std::vector<Rect>{tiles(0, 0, 16, 0, 0, 2, 4)}));
}

// After any sequence of changes, the boxes are those of a map made from scratch with the
// same tiles, and each change made or unmade only the few boxes around its tile.
TEST(SetTile, AnyChangesGiveTheBoxesOfAMapMadeFromScratch) {
    std::mt19937 random(5);
    for (int trial = 0; trial < 40; ++trial) {
        const int columns = 1 + int(random() % 12);
        const int rows = 1 + int(random() % 12);
        std::vector<std::string> tileRows(std::size_t(rows),
                                          std::string(std::size_t(columns), '.'));
        for (std::string& row : tileRows)
            for (char& tile : row)
                tile = random() % 3 != 0 ? '#' : '.';
        World world;
        const TileMapId map = createTileMap(world, mapDef(tileRows, 4, -7, 3));
        for (int change = 0; change < 60; ++change) {
            const int column = int(random() % unsigned(columns));
            const int row = int(random() % unsigned(rows));
            const bool solid = random() % 2 == 0;
            const std::vector<BodyId> before(tileMapBodies(world, map).begin(),
                                             tileMapBodies(world, map).end());
            setTile(world, map, column, row, solid);
            ASSERT_EQ(isSolid(world, map, column, row), solid);

            World fresh;
            const TileMapId scratch = createTileMap(fresh, tileMapDef(world, map));
            ASSERT_EQ(sorted(rectsOf(world, map)), sorted(rectsOf(fresh, scratch)))
                << "trial " << trial << ", change " << change;
            ASSERT_EQ(world.bodyCount(), fresh.bodyCount());

            // At most two runs go and two come; each brings at most two boxes with it.
            std::size_t made = 0;
            for (BodyId body : tileMapBodies(world, map))
                made += std::find(before.begin(), before.end(), body) == before.end();
            ASSERT_LE(made, 6u);
        }
    }
}

TEST(SetTile, RemovingTheTileUnderASleepingBoxMakesItFall) {
    World world(WorldDef{.gravity = {0, 800}});
    const TileMapId map = createTileMap(world, mapDef({"##########"}));
    // On tile 4 (x from 64 to 80), narrower than the tile.
    const BodyId box = world.createBody({.x = 72, .y = -6, .hw = 6, .hh = 6});
    for (int i = 0; i < 120 && world.isAwake(box); ++i)
        world.step(1.0f / 60.0f);
    ASSERT_FALSE(world.isAwake(box)) << "the box never fell asleep";

    setTile(world, map, 4, 0, false);
    EXPECT_TRUE(world.isAwake(box));
    for (int i = 0; i < 30; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_GT(world.position(box).y, 16.0f + 6.0f) << "it fell through the hole";
}

TEST(SetTile, RemovingATileFarFromASleepingBoxLeavesItWhereItIs) {
    World world(WorldDef{.gravity = {0, 800}});
    const TileMapId map = createTileMap(world, mapDef({"##########"}));
    const BodyId box = world.createBody({.x = 24, .y = -6, .hw = 6, .hh = 6});
    for (int i = 0; i < 120 && world.isAwake(box); ++i)
        world.step(1.0f / 60.0f);
    ASSERT_FALSE(world.isAwake(box));
    const Vec2 resting = world.position(box);
    // The floor box under it is rebuilt (and so woken), but the box stays put.
    setTile(world, map, 8, 0, false);
    for (int i = 0; i < 120; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.position(box).x, resting.x, 1e-4f);
    EXPECT_NEAR(world.position(box).y, resting.y, 0.06f); // its slop: 0.01 × 6
}

TEST(SetTile, AddingATileBlocks) {
    World world(WorldDef{.gravity = {0, 800}});
    // A shaft two tiles wide between walls, with no floor; a box falls in it.
    const TileMapId map = createTileMap(world, mapDef(std::vector<std::string>(20, "#..#")));
    const BodyId box = world.createBody({.x = 32, .y = 8, .hw = 6, .hh = 6});
    world.step(1.0f / 60.0f);
    // A floor across the shaft at row 10 (its top at y = 160).
    setTile(world, map, 1, 10, true);
    setTile(world, map, 2, 10, true);
    for (int i = 0; i < 120; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.position(box).y, 160.0f - 6.0f, 0.06f);
    EXPECT_EQ(world.velocity(box).y, 0.0f);
}

TEST(SetTile, ATileMadeSolidOverABodyPushesItOut) {
    World world(WorldDef{.gravity = {0, 800}});
    const TileMapId map = createTileMap(world, mapDef({"....", "####"}));
    // On the floor (its top at y = 16), across the edge between columns 0 and 1.
    const BodyId box = world.createBody({.x = 12, .y = 10, .hw = 6, .hh = 6});
    for (int i = 0; i < 30; ++i)
        world.step(1.0f / 60.0f);
    // Column 1 above the floor becomes solid: it overlaps the box by 2 along x, 12 along
    // y, so the box is pushed out to the left, onto column 0.
    setTile(world, map, 1, 0, true);
    for (int i = 0; i < 120; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.position(box).x, 16.0f - 6.0f, 0.06f + 0.06f); // two slops
    EXPECT_NEAR(world.position(box).y, 10.0f, 0.06f);
}

// The example of docs/tilemaps.md does what the guide says.
TEST(SetTile, TheGuidesExample) {
    World world(WorldDef{.gravity = {0, 800}});
    TileMapDef def;
    def.x = 0;
    def.y = 0;
    def.tile = 16;
    def.rows = {"#..........#", //
                "#..........#", //
                "#...####...#", //
                "############"};
    const TileMapId level = createTileMap(world, def);
    const BodyId player = world.createBody({.x = 40, .y = 30, .hw = 6, .hh = 8});
    for (int i = 0; i < 60; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.position(player).y, 48.0f - 8.0f, 0.06f); // on row 3
    setTile(world, level, 2, 3, false);
    for (int i = 0; i < 30; ++i)
        world.step(1.0f / 60.0f);
    EXPECT_GT(world.position(player).y, 64.0f + 8.0f); // through the hole, below the map
}

// --- Seams: sliding along floors and walls of tiles -------------------------------------
//
// Tiles of 16; boxes smaller than, as large as and larger than a tile; speeds from 10 to
// 5000 units per second, that is from 1/6 of a unit to 83 units (five tiles) per step.
// Friction 0 everywhere, so that a box that touched the side of a tile at a seam would
// show it at once as lost speed.
//
// The same again in a world in metres far from the origin: tiles of 0.7 with their corner
// near (1234.567, 1234.567), every length and speed scaled by 0.7 / 16. There the edges of
// boxes that meet are equal only to within a float's rounding of coordinates in the
// thousands, not exactly as with tiles of 16 near 0.

/// The units of a world: its tile size, and where its floors and walls are. The numbers
/// of the tests are written for tiles of 16 and scaled by tile / 16.
struct Units {
    float tile;
    Vec2 origin;
    float scale() const { return tile / 16; }
};

constexpr Units kPixels{16, {0, 0}};
constexpr Units kMetresFarOut{0.7f, {1234.567f, 1234.567f}};

constexpr float kGravity = 800;
constexpr float kDt = 1.0f / 60.0f;
constexpr float kHalves[] = {2, 5, 8, 12, 20, 40};
constexpr float kSpeeds[] = {10, 37, 100, 333, 1000, 2500, 5000};

World slidingWorld(Units units) {
    // Sleeping off: a box at rest would pass by not moving.
    return World(WorldDef{.gravity = {0, kGravity * units.scale()}, .sleeping = false});
}

/// How far a box of half extent `half` may sink into a floor or wall whose half extent
/// along the normal is `otherHalf`, at coordinate `at`: the slop (0.01 × the smaller of
/// the two) and a few roundings of a float near `at`.
float slopAt(float half, float otherHalf, float at) {
    const float magnitude = std::abs(at);
    const float ulp = std::nextafter(magnitude, std::numeric_limits<float>::infinity()) - magnitude;
    return 0.01f * std::min(half, otherHalf) + 4 * ulp + 1e-5f;
}

/// A floor of tiles whose top is at origin.y, 750 tiles each side of origin.x (room for
/// two seconds at 5000 × scale units per second).
void tileFloor(World& world, Units units) {
    TileMapDef def = mapDef({std::string(1500, '#'), std::string(1500, '#')}, units.tile,
                            units.origin.x - 750 * units.tile, units.origin.y);
    def.friction = 0;
    createTileMap(world, def);
}

/// The same floor as 1500 separate static boxes of one tile, placed edge to edge.
void boxFloor(World& world, Units units) {
    for (int i = 0; i < 1500; ++i)
        world.createBody({.type = BodyType::Static,
                          .x = units.origin.x + units.tile * (float(i) - 750 + 0.5f),
                          .y = units.origin.y + units.tile / 2,
                          .hw = units.tile / 2,
                          .hh = units.tile / 2,
                          .friction = 0});
}

/// Slides a box of every size at every speed, both ways, along the floor `makeFloor`
/// builds (top at origin.y), from resting on it or from landing on it; checks at every
// The seam sweeps' starting phases: fewer under a sanitizer, which looks for faults, not
// for other numbers (JOSTLE_TESTS_FEWER_SAMPLES); the Release build sweeps them all.
#if JOSTLE_TESTS_FEWER_SAMPLES
constexpr float kSlidingPhases[] = {0.37f, 8.37f};
constexpr int kFallingPhaseStep = 3;
#else
constexpr float kSlidingPhases[] = {0.37f, 4.37f, 8.37f, 12.37f};
constexpr int kFallingPhaseStep = 1;
#endif

/// step that it keeps its speed exactly and never leaves the floor by more than the slop.
template <typename MakeFloor>
void expectSlidingNeverCatches(Units units, MakeFloor makeFloor, float floorHalf, bool landing) {
    const float scale = units.scale();
    for (float half16 : kHalves) {
        for (float speed16 : kSpeeds) {
            for (float direction : {1.0f, -1.0f}) {
                // Where the box starts relative to the seams: off the tile grid, at four
                // phases (two under a sanitizer: kSlidingPhases).
                for (float phase : kSlidingPhases) {
                    const float half = half16 * scale;
                    const float velocity = direction * speed16 * scale;
                    SCOPED_TRACE("half " + std::to_string(half) + ", speed " +
                                 std::to_string(velocity) + ", phase " + std::to_string(phase));
                    World world = slidingWorld(units);
                    makeFloor(world, units);
                    const float drop = landing ? 7.3f * scale : 0.0f;
                    const float restingY = units.origin.y - half;
                    const BodyId box = world.createBody({.x = units.origin.x + phase * scale + half,
                                                         .y = restingY - drop,
                                                         .hw = half,
                                                         .hh = half,
                                                         .vx = velocity,
                                                         .friction = 0});
                    for (int step = 0; step < 120; ++step) {
                        world.step(kDt);
                        ASSERT_EQ(world.velocity(box).x, velocity) << "step " << step;
                        // A dropped box lands within 8 steps (7.3 units at g = 800).
                        if (!landing || step >= 8) {
                            ASSERT_NEAR(world.position(box).y, restingY,
                                        slopAt(half, floorHalf * scale, restingY))
                                << "step " << step;
                        }
                    }
                }
            }
        }
    }
}

/// A wall of tiles whose left face is at origin.x, from 125 tiles above origin.y to 675
/// below: its rows all alike (one box), or each ending at a different column behind the
/// face (so that the face is made of one box per row).
void tileWall(World& world, Units units, bool jagged) {
    std::vector<std::string> rows;
    for (int row = 0; row < 800; ++row)
        rows.push_back(jagged ? std::string(std::size_t(1 + row % 3), '#') +
                                    std::string(std::size_t(2 - row % 3), '.')
                              : "###");
    TileMapDef def = mapDef(rows, units.tile, units.origin.x, units.origin.y - 125 * units.tile);
    def.friction = 0;
    createTileMap(world, def);
}

/// The same wall, one tile thick, as separate static boxes placed edge to edge.
void boxWall(World& world, Units units) {
    for (int i = 0; i < 800; ++i)
        world.createBody({.type = BodyType::Static,
                          .x = units.origin.x + units.tile / 2,
                          .y = units.origin.y + units.tile * (float(i) - 125 + 0.5f),
                          .hw = units.tile / 2,
                          .hh = units.tile / 2,
                          .friction = 0});
}

/// A box pressed against the wall `makeWall` builds (left face at origin.x) by a sideways
/// velocity set every step, as a player holding "right" does, falls or rises along it
/// without catching: gravity alone changes its vertical speed.
template <typename MakeWall>
void expectFallingAlongAWallNeverCatches(Units units, MakeWall makeWall) {
    const float scale = units.scale();
    const float gravity = kGravity * scale;
    for (float half16 : kHalves) {
        for (float push16 : {1.0f, 300.0f}) {
            for (float start16 : {0.0f, -1500.0f}) { // falling from rest, or jumping up
                // Where the box starts relative to the seams: ten phases across a tile
                // (every third under a sanitizer: kFallingPhaseStep).
                for (int phase = 0; phase < 10; phase += kFallingPhaseStep) {
                    const float half = half16 * scale;
                    const float push = push16 * scale;
                    const float x = units.origin.x - half;
                    const float y =
                        units.origin.y + (0.37f + 16 * float(phase) / 10) * scale + half;
                    SCOPED_TRACE("half " + std::to_string(half) + ", push " + std::to_string(push) +
                                 ", vy " + std::to_string(start16 * scale) + ", y " +
                                 std::to_string(y));
                    World world = slidingWorld(units);
                    makeWall(world, units);
                    const BodyId box = world.createBody({.x = x,
                                                         .y = y,
                                                         .hw = half,
                                                         .hh = half,
                                                         .vy = start16 * scale,
                                                         .friction = 0});
                    for (int step = 0; step < 90; ++step) {
                        const float before = world.velocity(box).y;
                        world.setVelocity(box, {push, before});
                        world.step(kDt);
                        ASSERT_NEAR(world.velocity(box).y, before + gravity * kDt, 1e-3f * scale)
                            << "step " << step;
                        ASSERT_NEAR(world.position(box).x, x, slopAt(half, 1.5f * units.tile, x))
                            << "step " << step;
                    }
                }
            }
        }
    }
}

TEST(TileSeams, SlidingAlongATileFloorKeepsItsSpeed) {
    for (Units units : {kPixels, kMetresFarOut})
        expectSlidingNeverCatches(units, tileFloor, 16, /*landing=*/false);
}

TEST(TileSeams, LandingOnATileFloorKeepsTheSpeedAlongIt) {
    for (Units units : {kPixels, kMetresFarOut})
        expectSlidingNeverCatches(units, tileFloor, 16, /*landing=*/true);
}

TEST(TileSeams, SlidingAlongSeparateBoxesPlacedEdgeToEdgeKeepsItsSpeed) {
    for (Units units : {kPixels, kMetresFarOut})
        expectSlidingNeverCatches(units, boxFloor, 8, /*landing=*/false);
}

// A box that lands while moving fast along a floor of separate boxes meets the next box
// at its corner, apart on both axes; its gap to that box's side may be larger than its
// gap to the floor. The side is a seam (another static box covers it), so the contact
// pushes on the top instead (isSeam in src/physical/seams.cpp).
TEST(TileSeams, LandingOnSeparateBoxesPlacedEdgeToEdgeKeepsTheSpeedAlongIt) {
    expectSlidingNeverCatches(kPixels, boxFloor, 8, /*landing=*/true);
}

TEST(TileSeams, FallingAlongAWallOfTilesNeverCatches) {
    for (Units units : {kPixels, kMetresFarOut})
        expectFallingAlongAWallNeverCatches(
            units, [](World& world, Units u) { tileWall(world, u, /*jagged=*/false); });
}

// The wall's face is made of one box per row here: a box touching the face, and within
// its skin of the top (or bottom) of the next box, touches that box at a corner on both
// axes, where contactAxis picks y first. That top is a seam (the row above covers it), so
// the contact pushes on the face instead.
TEST(TileSeams, FallingAlongAJaggedWallOfTilesNeverCatches) {
    expectFallingAlongAWallNeverCatches(
        kPixels, [](World& world, Units u) { tileWall(world, u, /*jagged=*/true); });
}

// The same, with a wall of separate static boxes placed edge to edge.
TEST(TileSeams, FallingAlongAWallOfSeparateBoxesNeverCatches) {
    expectFallingAlongAWallNeverCatches(kPixels, boxWall);
}

// In metres far from the origin: the edges of boxes placed edge to edge differ by a
// float's rounding of their coordinates (1.2e-4 near 1234), more than 1e-4 × a tile of
// 0.7. isSeam (src/physical/seams.cpp) allows a few float steps at the face as well.
TEST(TileSeams, LandingOnSeparateBoxesInMetresFarOutKeepsTheSpeedAlongIt) {
    expectSlidingNeverCatches(kMetresFarOut, boxFloor, 8, /*landing=*/true);
}

TEST(TileSeams, FallingAlongAJaggedWallOfTilesInMetresFarOutNeverCatches) {
    expectFallingAlongAWallNeverCatches(
        kMetresFarOut, [](World& world, Units u) { tileWall(world, u, /*jagged=*/true); });
}

TEST(TileSeams, FallingAlongAWallOfSeparateBoxesInMetresFarOutNeverCatches) {
    expectFallingAlongAWallNeverCatches(kMetresFarOut, boxWall);
}

// --- Found by the fuzzers (tests/fuzz; the input kept in tests/fuzz/corpus/) ------------

// Found by fuzz_api (tests/fuzz/corpus/api/tile-too-small-for-its-position).
// checkTileMapDef, which promises nothing for a map createTileMap accepts, passed a tile
// of 2e-9 (the smallest, math.hpp) at x = 136: createTileMap works a box's edges out in
// double, and there they round to a half extent just below 1e-9, which createBody refused
// halfway through building the map, leaving a map without a handle. Far from the origin
// (x = 9.9e8) a tile of 1e-8 rounds to no size at all.
TEST(TileMap, ATileMapThatChecksBuilds) {
    const float tiles[] = {1.99999994e-9f, 2e-9f, 1e-8f, 1e-6f};
    const float places[] = {0, 135.925842f, 1e6f, 9.9e8f, -9.9e8f};
    for (float tile : tiles) {
        for (float x : places) {
            TileMapDef def;
            def.x = x;
            def.y = 188.981445f;
            def.tile = tile;
            def.rows = {"#.#", "###", ".#.", "#.."};
            if (checkTileMapDef(def))
                continue;
            World world;
            EXPECT_NO_THROW(createTileMap(world, def)) << "tile " << tile << " at x " << x;
        }
    }
}

} // namespace
} // namespace jostle
