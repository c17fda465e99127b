// The broadphase never misses a pair and never reports one twice: property tests against
// brute force on random worlds of boxes from 1 to 10,000 units, near and far from the
// origin.
#include "box_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace jostle {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

std::vector<Box> randomBoxes(unsigned seed, int count, float spread, Vec2 origin) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Box> boxes;
    for (int i = 0; i < count; ++i) {
        // Sizes spread evenly over four orders of magnitude: 1 to 10,000 units.
        const float hw = 0.5f * std::pow(10.0f, 4.0f * unit(rng));
        const float hh = i % 3 == 0 ? hw : 0.5f * std::pow(10.0f, 4.0f * unit(rng));
        const Vec2 c{origin.x + spread * (unit(rng) - 0.5f),
                     origin.y + spread * (unit(rng) - 0.5f)};
        boxes.push_back({{c.x - hw, c.y - hh}, {c.x + hw, c.y + hh}});
    }
    // Some boxes exactly touching others, edge to edge and corner to corner.
    for (int i = 0; i + 1 < count; i += 9) {
        Box& b = boxes[std::size_t(i) + 1];
        const Box& a = boxes[std::size_t(i)];
        const float w = b.max.x - b.min.x;
        b.min.x = a.max.x;
        b.max.x = a.max.x + w;
    }
    return boxes;
}

std::set<Pair> bruteForcePairs(const std::vector<Box>& boxes) {
    std::set<Pair> pairs;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
            if (touches(boxes[i], boxes[j]))
                pairs.insert({i, j});
    return pairs;
}

/// The grid's pairs, each as (smaller, larger).
std::set<Pair> pairsOf(const BoxGrid& grid) {
    std::set<Pair> found;
    grid.forEachPair([&](std::uint32_t i, std::uint32_t j) {
        found.insert({std::min(i, j), std::max(i, j)});
    });
    return found;
}

class BoxGridProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(BoxGridProperty, PairsEqualBruteForce) {
    const unsigned seed = GetParam();
    const Vec2 origin = seed % 2 ? Vec2{1e6f, -3e6f} : Vec2{0, 0};
    const std::vector<Box> boxes = randomBoxes(seed, 600, 60000.0f, origin);
    BoxGrid grid;
    grid.build(boxes);
    std::set<Pair> found;
    std::size_t calls = 0;
    grid.forEachPair([&](std::uint32_t i, std::uint32_t j) {
        ++calls;
        found.insert({std::min(i, j), std::max(i, j)});
    });
    const std::set<Pair> expected = bruteForcePairs(boxes);
    EXPECT_EQ(found, expected);
    EXPECT_EQ(calls, expected.size()); // each pair once
    EXPECT_GT(expected.size(), 100u);  // the worlds are crowded enough to mean something
}

TEST_P(BoxGridProperty, QueriesEqualBruteForce) {
    const unsigned seed = GetParam();
    const std::vector<Box> boxes = randomBoxes(seed, 400, 30000.0f, {0, 0});
    BoxGrid grid;
    grid.build(boxes);
    const std::vector<Box> queries = randomBoxes(seed + 1000, 50, 30000.0f, {0, 0});
    for (const Box& q : queries) {
        std::vector<std::uint32_t> found;
        grid.query(q, [&](std::uint32_t i) { found.push_back(i); });
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            if (touches(boxes[i], q))
                expected.push_back(i);
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, expected);
    }
}

INSTANTIATE_TEST_SUITE_P(RandomWorlds, BoxGridProperty, ::testing::Range(1u, 13u));

TEST(BoxGrid, SameInputSameOrder) {
    const std::vector<Box> boxes = randomBoxes(7, 500, 20000.0f, {0, 0});
    auto run = [&] {
        BoxGrid grid;
        grid.build(boxes);
        std::vector<Pair> calls;
        grid.forEachPair([&](std::uint32_t i, std::uint32_t j) { calls.push_back({i, j}); });
        return calls;
    };
    EXPECT_EQ(run(), run());
}

// Threads search the grid in pieces (forEachPairOf): however the items are cut, the
// pieces in order give forEachPair's pairs in forEachPair's order.
TEST(BoxGrid, PiecesInOrderGiveEveryPairInTheSameOrder) {
    const std::vector<Box> boxes = randomBoxes(11, 800, 20000.0f, {0, 0});
    BoxGrid grid;
    grid.build(boxes);
    std::vector<Pair> whole;
    grid.forEachPair([&](std::uint32_t i, std::uint32_t j) { whole.push_back({i, j}); });
    ASSERT_GT(whole.size(), 100u);
    for (std::uint32_t piece : {1u, 7u, 64u, 1000u, 5000u}) {
        std::vector<Pair> pieces;
        for (std::uint32_t begin = 0; begin < grid.pairItems(); begin += piece)
            grid.forEachPairOf(begin, std::min(grid.pairItems(), begin + piece),
                               [&](std::uint32_t i, std::uint32_t j) {
                                   pieces.push_back({i, j});
                               });
        EXPECT_EQ(pieces, whole) << "pieces of " << piece << " items";
    }
}

TEST(BoxGrid, HugeAndTinyAndFarAway) {
    const std::vector<Box> boxes = {
        {{-1e7f, -10}, {1e7f, 10}},           // a floor 20 million units long
        {{5e6f, 10}, {5e6f + 1, 11}},         // a small box resting on it, far out
        {{1e30f, 1e30f}, {1.1e30f, 1.1e30f}}, // out at the edge of floats
        {{1.05e30f, 1.05e30f}, {1.2e30f, 1.2e30f}},
        {{-3, -3}, {-2.999f, -2.999f}}, // a speck inside the floor
    };
    BoxGrid grid;
    grid.build(boxes);
    EXPECT_EQ(pairsOf(grid), bruteForcePairs(boxes));
    EXPECT_EQ(pairsOf(grid), (std::set<Pair>{{0, 1}, {0, 4}, {2, 3}}));
}

/// A pile of boxes whose sides run from `smallest` to 4 times that (as rain's do), side by
/// side in overlapping rows; with `smallEvery`, every smallEvery-th box instead `smallest`
/// wide and high.
std::vector<Box> pileOfSizes(float smallest, int count, int smallEvery) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> side(smallest, 4.0f * smallest);
    std::vector<Box> boxes;
    float x = 0.0f, y = 0.0f;
    for (int i = 0; i < count; ++i) {
        const bool small = smallEvery > 0 && i % smallEvery == 0;
        const float w = small ? smallest : side(rng), h = small ? smallest : side(rng);
        boxes.push_back({{x, y}, {x + w, y + h}});
        x += w;
        if (x > 40.0f * smallest) {
            x = 0.0f;
            y += 2.5f * smallest;
        }
    }
    return boxes;
}

/// The widths of the grid's cells, each to a part in a thousand.
std::set<long> cellWidths(const BoxGrid& grid) {
    std::set<long> widths;
    grid.forEachCell([&](const Box& cell) {
        widths.insert(std::lround(double(cell.max.x - cell.min.x) * 1000.0));
    });
    return widths;
}

// Rain's boxes span two doublings of size, three in four of them in the larger half: they
// share one level, of cells 4 times level 0's (which are 1.25 times the smallest box), so
// that no box looks into a coarser level for its neighbours.
TEST(BoxGrid, BoxesOfUpToFourTimesTheSmallestShareOneLevel) {
    const std::vector<Box> boxes = pileOfSizes(1.0f, 3000, 0);
    BoxGrid grid;
    grid.build(boxes);
    EXPECT_EQ(pairsOf(grid), bruteForcePairs(boxes));
    float smallest = INFINITY;
    for (const Box& b : boxes)
        smallest = std::min(smallest, std::max(b.max.x - b.min.x, b.max.y - b.min.y));
    EXPECT_EQ(cellWidths(grid), (std::set<long>{std::lround(5.0 * double(smallest) * 1000.0)}));
}

// Where the smallest boxes are many (half of them here), they keep cells of their own
// size: cells four times as large would hold many of them each.
TEST(BoxGrid, ACrowdOfSmallBoxesKeepsItsOwnLevel) {
    const std::vector<Box> boxes = pileOfSizes(1.0f, 3000, 2);
    BoxGrid grid;
    grid.build(boxes);
    EXPECT_EQ(pairsOf(grid), bruteForcePairs(boxes));
    const std::set<long> widths = cellWidths(grid);
    EXPECT_TRUE(widths.contains(1250)) << "the small boxes' own cells, 1.25 times their size";
    EXPECT_GT(widths.size(), 1u);
}

TEST(BoxGrid, Empty) {
    BoxGrid grid;
    grid.build({});
    int calls = 0;
    grid.forEachPair([&](std::uint32_t, std::uint32_t) { ++calls; });
    grid.query({{0, 0}, {1, 1}}, [&](std::uint32_t) { ++calls; });
    EXPECT_EQ(calls, 0);
}

} // namespace
} // namespace jostle
