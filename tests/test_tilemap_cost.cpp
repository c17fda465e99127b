// What tile maps cost (docs/tilemaps.md, "What a change costs"): creating a map does work
// in proportion to its tiles, and setTile makes and unmakes the same few bodies, and does
// the same work, whatever the map's size, for ramps as for solid tiles. Work is counted,
// not timed (TileMapData::work, a white-box counter), so these hold on a loaded machine.
// And ramps changed one by one give the bodies of a map made from scratch.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include "tilemap.hpp"
#include "world_access.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace jostle {
namespace {

TileMapDef mapOf(std::vector<std::string> rows) {
    TileMapDef def;
    def.tile = 16;
    def.rows = std::move(rows);
    return def;
}

/// A map of `columns` × `rows` tiles, `pattern` repeated across and down.
TileMapDef tiled(int columns, int rows, const std::vector<std::string>& pattern) {
    std::vector<std::string> tiles(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const std::string& line = pattern[static_cast<std::size_t>(r) % pattern.size()];
        for (int c = 0; c < columns; ++c)
            tiles[static_cast<std::size_t>(r)] += line[static_cast<std::size_t>(c) % line.size()];
    }
    return mapOf(std::move(tiles));
}

/// The map code's work so far: its counter, and the entries its body list moved.
std::uint64_t workOf(const World& world, TileMapId map) {
    const TileMapData& data = WorldAccess::state(world).tileMaps.maps[map.index];
    return data.work + data.bodies.moved();
}

std::uint64_t keyOf(BodyId body) {
    return std::uint64_t{body.index} << 32 | body.generation;
}

std::vector<std::uint64_t> bodiesOf(const World& world, TileMapId map) {
    std::vector<std::uint64_t> keys;
    for (BodyId body : tileMapBodies(world, map))
        keys.push_back(keyOf(body));
    std::sort(keys.begin(), keys.end());
    return keys;
}

/// What one setTile did: the map's bodies it destroyed and created, and its work.
struct Cost {
    std::size_t destroyed = 0;
    std::size_t created = 0;
    std::uint64_t work = 0;
    friend bool operator==(const Cost&, const Cost&) = default;
};

std::ostream& operator<<(std::ostream& out, const Cost& cost) {
    return out << "{destroyed " << cost.destroyed << ", created " << cost.created << ", work "
               << cost.work << "}";
}

Cost costOfSetTile(World& world, TileMapId map, int column, int row, char tile) {
    const std::vector<std::uint64_t> before = bodiesOf(world, map); // closes the list's gaps
    const std::uint64_t workBefore = workOf(world, map);
    setTile(world, map, column, row, tile);
    const std::uint64_t work = workOf(world, map) - workBefore;
    const std::vector<std::uint64_t> after = bodiesOf(world, map);
    std::vector<std::uint64_t> gone, come;
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(),
                        std::back_inserter(gone));
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                        std::back_inserter(come));
    return {gone.size(), come.size(), work};
}

/// One change to a map, at (middle column + dc, middle row).
struct Edit {
    int dc;
    char tile;
};

/// The costs of `edits` made in turn in the middle of a map `def`.
std::vector<Cost> costsOfEdits(const TileMapDef& def, const std::vector<Edit>& edits) {
    World world;
    const TileMapId map = createTileMap(world, def);
    const int column = tileMapColumns(world, map) / 2;
    const int row = tileMapRows(world, map) / 2;
    std::vector<Cost> costs;
    for (const Edit& edit : edits)
        costs.push_back(costOfSetTile(world, map, column + edit.dc, row, edit.tile));
    return costs;
}

// The sizes a change is made in: small, square, wide and tall (at most 100,000 tiles, so
// that the suite stays light on memory). Their middle tiles are alike in both patterns.
struct Size {
    int columns;
    int rows;
};
constexpr Size kSizes[] = {{30, 30}, {300, 300}, {1000, 100}, {100, 1000}};

TEST(TileMapCost, ChangingARampInTheMiddleTouchesTheSameFewBodiesWhateverTheMapsSize) {
    // A map of '/' tiles, one body each. Before, setTile rebuilt every ramp of the row
    // (300 bodies destroyed and created in a 300 × 300 map) and each body destroyed was
    // searched for in the map's list of bodies.
    const std::vector<Edit> edits{
        {0, '\\'}, // a ramp for a ramp: one body goes, one comes
        {0, 'r'},  // a lone low half of a 2:1 ramp
        {1, 'R'},  // its high half beside it: 'r' and a '/' go, one triangle comes
        {1, '/'},  // and back: the triangle goes, 'r' and '/' come
        {0, '#'},  // a solid tile: the ramp goes, a box comes
        {0, '.'},  // the box goes
        {0, 'R'},  // a lone high half: its triangle and the box under it
        {0, '/'},  // back as it was
    };
    const std::vector<Cost> expected{{1, 1}, {1, 1}, {2, 1}, {1, 2},
                                     {1, 1}, {1, 0}, {0, 2}, {2, 1}};
    std::vector<Cost> first;
    for (const Size size : kSizes) {
        const std::vector<Cost> costs = costsOfEdits(tiled(size.columns, size.rows, {"/"}), edits);
        for (std::size_t i = 0; i < edits.size(); ++i) {
            EXPECT_EQ(costs[i].destroyed, expected[i].destroyed)
                << "edit " << i << " in a map of " << size.columns << " x " << size.rows;
            EXPECT_EQ(costs[i].created, expected[i].created)
                << "edit " << i << " in a map of " << size.columns << " x " << size.rows;
        }
        if (first.empty())
            first = costs;
        EXPECT_EQ(costs, first) << "in a map of " << size.columns << " x " << size.rows
                                << ", beside one of " << kSizes[0].columns << " x "
                                << kSizes[0].rows;
    }
}

TEST(TileMapCost, ChangingASolidTileInTheMiddleTouchesTheSameFewBodiesWhateverTheMapsSize) {
    // A checkerboard of '#' tiles, one box each: filling the hole beside the middle tile
    // joins the three tiles' run; digging it again cuts it.
    const std::vector<Edit> edits{{1, '#'}, {1, '.'}, {0, '.'}, {0, '#'}, {0, '/'}, {0, '#'}};
    const std::vector<Cost> expected{{2, 1}, {1, 2}, {1, 0}, {0, 1}, {1, 1}, {1, 1}};
    std::vector<Cost> first;
    for (const Size size : kSizes) {
        const std::vector<Cost> costs =
            costsOfEdits(tiled(size.columns, size.rows, {"#.", ".#"}), edits);
        for (std::size_t i = 0; i < edits.size(); ++i) {
            EXPECT_EQ(costs[i].destroyed, expected[i].destroyed)
                << "edit " << i << " in a map of " << size.columns << " x " << size.rows;
            EXPECT_EQ(costs[i].created, expected[i].created)
                << "edit " << i << " in a map of " << size.columns << " x " << size.rows;
        }
        if (first.empty())
            first = costs;
        EXPECT_EQ(costs, first) << "in a map of " << size.columns << " x " << size.rows;
    }
}

TEST(TileMapCost, CreatingAMapTwiceAsLargeDoesTwiceTheWork) {
    // Ramps of every kind, solid and empty tiles. Before, each row's ramps were made after
    // a pass over every ramp piece made so far: four times the work for twice the rows.
    const std::vector<std::string> pattern{"/\\rR#Ll..cCDd7F", "#RR.R#/##\\rr..L",
                                           "###############", ".#.#.#.#.#.#.#."};
    const auto work = [&](int columns, int rows) {
        World world;
        const TileMapId map = createTileMap(world, tiled(columns, rows, pattern));
        return static_cast<double>(workOf(world, map));
    };
    const double small = work(150, 150);
    EXPECT_GT(small, 0.0);
    EXPECT_NEAR(work(150, 300) / small, 2.0, 0.1) << "twice the rows";
    EXPECT_NEAR(work(300, 150) / small, 2.0, 0.1) << "twice the columns";
    EXPECT_NEAR(work(300, 300) / small, 4.0, 0.2) << "four times the tiles";
}

TEST(TileMapCost, DestroyingAChangedMapDestroysItsBodiesAndNoOthers) {
    // The map's list has a gap where setTile destroyed a body.
    World world;
    const BodyId before = world.createBody({.x = -100, .hw = 1, .hh = 1});
    const TileMapId map = createTileMap(world, tiled(200, 200, {"/r", "R#"}));
    setTile(world, map, 10, 10, '.');
    const BodyId after = world.createBody({.x = -200, .hw = 1, .hh = 1});
    destroyTileMap(world, map);
    EXPECT_EQ(world.bodyCount(), 2u);
    EXPECT_TRUE(world.isValid(before));
    EXPECT_TRUE(world.isValid(after));
}

// tileMapBodies is a const function, which several threads may call at once; the first
// to read the list after a change closes its gaps (under a lock; ThreadSanitizer runs the
// Threads suite).
TEST(Threads, TileMapBodiesReadOnSeveralThreadsAfterAChangeAgree) {
    World world;
    const TileMapId map = createTileMap(world, tiled(40, 40, {"/"}));
    for (int column = 0; column < 40; column += 2)
        setTile(world, map, column, 20, '.');
    std::vector<std::vector<BodyId>> seen(4);
    std::vector<std::thread> threads;
    for (std::vector<BodyId>& mine : seen)
        threads.emplace_back([&world, map, &mine] {
            const std::span<const BodyId> bodies = tileMapBodies(world, map);
            mine.assign(bodies.begin(), bodies.end());
        });
    for (std::thread& thread : threads)
        thread.join();
    EXPECT_EQ(seen[0].size(), 40u * 40u - 20u);
    for (const std::vector<BodyId>& mine : seen)
        EXPECT_EQ(mine, seen[0]);
}

// --- Ramps changed one by one -------------------------------------------------------------

/// A body as the world sees it, with its slope, to compare maps by their bodies.
using Piece = std::tuple<float, float, float, float, float, float>;

std::vector<Piece> piecesOf(const World& world, TileMapId map) {
    std::vector<Piece> pieces;
    for (BodyId body : tileMapBodies(world, map)) {
        const Vec2 p = world.position(body);
        const Vec2 h = world.halfExtents(body);
        const Vec2 s = world.bodyDef(body).slope;
        pieces.emplace_back(p.x, p.y, h.x, h.y, s.x, s.y);
    }
    std::sort(pieces.begin(), pieces.end());
    return pieces;
}

// After any sequence of changes to tiles of every kind, the map's bodies are those of a map
// made from scratch with the same tiles, and each change made or unmade only a few bodies
// (the boxes of SetTile.AnyChangesGiveTheBoxesOfAMapMadeFromScratch, and the ramp pieces
// through the tile and its two neighbours).
TEST(TileMapCost, AnyChangesToRampsGiveTheBodiesOfAMapMadeFromScratch) {
    const std::string kinds = "#.../\\7FrRLlcCDd";
    std::mt19937 random(11);
    for (int trial = 0; trial < 30; ++trial) {
        const int columns = 1 + int(random() % 10);
        const int rows = 1 + int(random() % 6);
        std::vector<std::string> tileRows(std::size_t(rows),
                                          std::string(std::size_t(columns), '.'));
        for (std::string& row : tileRows)
            for (char& tile : row)
                tile = kinds[random() % kinds.size()];
        World world;
        const TileMapId map = createTileMap(world, mapOf(tileRows));
        for (int change = 0; change < 80; ++change) {
            const int column = int(random() % unsigned(columns));
            const int row = int(random() % unsigned(rows));
            // Half the changes put the partner of a 2:1 half beside it, to pair them.
            char tile = kinds[random() % kinds.size()];
            if (random() % 2 == 0 && column > 0) {
                const char left = tileOf(world, map, column - 1, row);
                const std::string halves = "rRLlcCDd";
                if (const std::size_t at = halves.find(left);
                    at != std::string::npos && at % 2 == 0)
                    tile = halves[at + 1];
            }
            const Cost cost = costOfSetTile(world, map, column, row, tile);
            ASSERT_EQ(tileOf(world, map, column, row), tile);

            World fresh;
            const TileMapId scratch = createTileMap(fresh, tileMapDef(world, map));
            ASSERT_EQ(piecesOf(world, map), piecesOf(fresh, scratch))
                << "trial " << trial << ", change " << change << ": (" << column << ", " << row
                << ") to '" << tile << "'";
            ASSERT_EQ(world.bodyCount(), fresh.bodyCount());
            ASSERT_LE(cost.destroyed, 9u);
            ASSERT_LE(cost.created, 9u);
        }
    }
}

} // namespace
} // namespace jostle
