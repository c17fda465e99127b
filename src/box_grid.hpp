// BoxGrid: a hierarchical grid of boxes, the broadphase of both models.
//
// Each box lives in one cell of one level: the level whose cells are at least as large as
// the box (level 0 fits the smallest box, and each level doubles), the cell that holds
// its min corner. So a box spans at most two cells of its level along each axis, and a
// box of any size is found by looking at a window of at most 3 × 3 cells per level.
// Small and huge boxes in one grid cost no more than their own levels, and the cost of a
// step grows about linearly with the number of boxes.
//
// A level's cells are a dense array over the cells its boxes occupy, its boxes sorted by
// cell (a counting sort), so that walking the boxes in cell order reads memory in order.
// A level whose boxes are too spread out for that (a few boxes kilometres apart) keeps
// its cells in a hash table instead: the world may be as large and as far from the
// origin as floats go.
//
// Everything is visited in a fixed order (by level, then cell, then insertion order),
// never in pointer or hash order, so the same input gives the same pairs in the same
// order.
#pragma once

#include "counting_sort.hpp"
#include "geometry.hpp"
#include "tasks.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace jostle {

class BoxGrid {
public:
    /// Replaces the grid's contents with these boxes; the i-th is named i in results.
    /// With `tasks`, the passes over the boxes run in blocks on its workers: the same grid.
    void build(const std::vector<Box>& boxes, TaskRunner* tasks = nullptr);

    std::size_t size() const { return boxes_.size(); }
    const Box& bounds(std::uint32_t i) const { return boxes_[i]; }

    /// Calls visit(i) for every box i that overlaps or touches `query`, each once.
    template <class Visit> void query(const Box& query, Visit&& visit) const;

    /// Calls visit(i, j) for every pair of boxes that overlap or touch, each pair once,
    /// in a fixed order (j may be smaller or larger than i).
    template <class Visit> void forEachPair(Visit&& visit) const {
        forEachPairOf(0, pairItems(), visit);
    }

    /// forEachPair in pieces, for threads: the pairs are found item by item, 2 size()
    /// items in all, and forEachPairOf(begin, end) gives those of items [begin, end) in
    /// the order forEachPair gives them.
    std::uint32_t pairItems() const { return 2 * std::uint32_t(boxes_.size()); }
    template <class Visit>
    void forEachPairOf(std::uint32_t begin, std::uint32_t end, Visit&& visit) const;

    /// Calls visit(cell) with the bounds of every cell that holds a box (of every level
    /// but the last, infinite one), for debug drawing: in a dense level each once, in a
    /// hashed one once for each run of its boxes in the same cell.
    template <class Visit> void forEachCell(Visit&& visit) const {
        for (int index = 0; index + 1 < kLevels; ++index) {
            const Level& level = levels_[index];
            for (std::uint32_t k = level.begin; k < level.end; ++k) {
                const Cell c = sortedCells_[k];
                if (k > level.begin && sortedCells_[k - 1].x == c.x && sortedCells_[k - 1].y == c.y)
                    continue;
                const Vec2 low{float(c.x * level.size), float(c.y * level.size)};
                visit(Box{low, {float((c.x + 1) * level.size), float((c.y + 1) * level.size)}});
            }
        }
    }

private:
    static constexpr std::uint32_t kNone = UINT32_MAX;
    /// Cell coordinates are clamped here, so that a window can add and subtract one
    /// without overflow. Clamping keeps the order of cells, so a box beyond the limit is
    /// still found, in a crowded edge cell: slower, never wrong. It takes a world 2^30
    /// cells wide to reach.
    static constexpr double kCellLimit = 1073741824.0;
    static constexpr int kLevels = 64;

    struct Cell {
        std::int32_t x, y;
    };

    /// A cell of a hashed level: which cell (compared whole, so that two cells never
    /// share a run) and where its boxes are in `sorted_`.
    struct HashSlot {
        Cell cell{0, 0};
        std::int32_t level = -1; ///< -1: empty
        std::uint32_t first = 0, last = 0;
    };

    /// All zero when value-initialized (Level{}): no member initializers, so that the 64
    /// of them are zeroed at once, not each field by its own store.
    struct Level {
        std::uint32_t begin, end; ///< its boxes: sorted_[begin, end)
        double size, inverse;     ///< cell size and its inverse
        bool dense;
        Cell low;           ///< dense: the first cell of the array
        std::int64_t width; ///< dense: cells per row
        std::int64_t height;
        /// Its first key in cells_: a dense level has a key per cell, in row order; a
        /// hashed one a single key for all its boxes.
        std::uint32_t cellStart;
    };

    static constexpr int kMaxMerged = 2;
    static constexpr double kMergedShare = 0.9;
    /// Two doublings are merged only when the boxes of the first two levels are at most
    /// this share of all.
    static constexpr double kFewSmallShare = 1.0 / 3.0;

    /// What a block of boxes adds up to in build's passes over them: sizes, then how
    /// many would go in each of the first levels, then each level's boxes and the cells
    /// they span. Combined in block order (counts, minima, maxima: exact in any order).
    struct BlockSums {
        float smallest, largest;
        std::uint32_t firstLevels[kMaxMerged + 2];
        std::uint32_t counts[kLevels];
        Cell low[kLevels], high[kLevels];
    };

    int levelOf(const Box& box) const;
    /// By how many doublings to grow the first level's cells so that it holds most of
    /// the boxes (at most kMaxMerged: cells up to 5 times as wide as the smallest box).
    int mergedLevels(double base, TaskRunner* tasks);
    Cell cellOf(Vec2 point, const Level& level) const;
    std::size_t hashOf(int level, Cell cell) const;
    /// The run of sorted_ that holds cell (x, y) of `level`: [first, last).
    void run(int level, std::int64_t x, std::int64_t y, std::uint32_t& first,
             std::uint32_t& last) const;

    /// Calls visit(k) for every position k in sorted_ of the boxes in cells x0..x1 of row
    /// y of `level`. A dense level stores a row's cells one after another, so that is
    /// one run of sorted_; a hashed level looks each cell up.
    template <class Visit>
    void forEachInRow(int level, std::int64_t y, std::int64_t x0, std::int64_t x1,
                      Visit&& visit) const;

    /// Calls visit(i) for every box of `level` that touches `query`, looking at the window
    /// of cells that may hold one, or at all of the level's boxes when that is fewer.
    template <class Visit> void visitLevel(int level, const Box& query, Visit&& visit) const;

    /// Same-level pairs of the boxes at [from, to) of sorted_, all of one level: each box
    /// against the boxes of the cells of its window that come after its own cell (and
    /// after it in its own cell).
    template <class Visit>
    void pairsWithinLevel(int level, std::uint32_t from, std::uint32_t to, Visit&& visit) const;
    /// Pairs of the boxes at [from, to) of sorted_, all of one level, with the boxes of
    /// the coarser levels.
    template <class Visit>
    void pairsAcrossLevels(int level, std::uint32_t from, std::uint32_t to, Visit&& visit) const;

    std::vector<Box> boxes_;              ///< as given: bounds(i)
    std::vector<BlockSums> blockSums_;    ///< build's scratch, by block of boxes
    std::vector<std::uint32_t> keyOfBox_; ///< build's scratch: each box's level, then key
    std::vector<Cell> cellOfBox_;
    std::vector<std::uint32_t> sorted_; ///< box indices by level, then cell, then index
    /// The boxes and their cells in the order of sorted_, so that the scans of a cell's
    /// boxes read memory in order.
    std::vector<Box> sortedBoxes_;
    std::vector<Cell> sortedCells_;
    /// The run of sorted_ of each key (Level::cellStart): the boxes of a dense level's
    /// cell, or of a hashed level.
    Buckets cells_;
    std::vector<HashSlot> table_; ///< hashed levels: open addressing
    int tableShift_ = 63;
    Level levels_[kLevels]{};
    std::uint64_t usedLevels_ = 0; ///< bit k: level k has boxes
};

// --- Inline and template definitions -----------------------------------------------------

inline BoxGrid::Cell BoxGrid::cellOf(Vec2 point, const Level& level) const {
    auto coordinate = [&](float value) {
        // floor() by hand: truncate, then step down for negative fractions. (std::floor
        // is a library call on baseline x86-64, and this runs for every box and query.)
        const double cell = std::clamp(double(value) * level.inverse, -kCellLimit, kCellLimit);
        const auto truncated = std::int32_t(cell);
        return truncated - std::int32_t(double(truncated) > cell);
    };
    return {coordinate(point.x), coordinate(point.y)};
}

template <class Visit>
void BoxGrid::visitLevel(int levelIndex, const Box& query, Visit&& visit) const {
    const Level& level = levels_[levelIndex];
    // Either way the boxes are visited in sorted order. A window has at least four
    // cells: a level of no more boxes than that is scanned without finding it.
    const std::uint32_t count = level.end - level.begin;
    const Cell low = count > 4 ? cellOf(query.min, level) : Cell{0, 0};
    const Cell high = count > 4 ? cellOf(query.max, level) : Cell{0, 0};
    // A box is filed under its min corner and is at most one cell large, so one touching
    // the query has its min corner at most one cell before the query's.
    const std::int64_t fromX = std::int64_t(low.x) - 1, fromY = std::int64_t(low.y) - 1;
    const double cells =
        (double(high.x) - double(fromX) + 1) * (double(high.y) - double(fromY) + 1);
    if (count <= 4 || cells > double(count)) {
        for (std::uint32_t k = level.begin; k < level.end; ++k)
            if (touches(sortedBoxes_[k], query))
                visit(sorted_[k]);
        return;
    }
    for (std::int64_t y = fromY; y <= high.y; ++y) {
        forEachInRow(levelIndex, y, fromX, high.x, [&](std::uint32_t k) {
            if (touches(sortedBoxes_[k], query))
                visit(sorted_[k]);
        });
    }
}

template <class Visit>
void BoxGrid::forEachInRow(int levelIndex, std::int64_t y, std::int64_t x0, std::int64_t x1,
                           Visit&& visit) const {
    const Level& level = levels_[levelIndex];
    if (level.dense) {
        const std::int64_t row = y - level.low.y;
        const std::int64_t from = std::max<std::int64_t>(x0 - level.low.x, 0);
        const std::int64_t to = std::min<std::int64_t>(x1 - level.low.x, level.width - 1);
        if (row < 0 || row >= level.height || from > to)
            return;
        const std::size_t cell = level.cellStart + std::size_t(row * level.width + from);
        const std::uint32_t last = cells_.begin(cell + std::size_t(to - from) + 1);
        for (std::uint32_t k = cells_.begin(cell); k < last; ++k)
            visit(k);
        return;
    }
    for (std::int64_t x = x0; x <= x1; ++x) {
        std::uint32_t first, last;
        run(levelIndex, x, y, first, last);
        for (std::uint32_t k = first; k < last; ++k)
            visit(k);
    }
}

template <class Visit>
void BoxGrid::pairsWithinLevel(int levelIndex, std::uint32_t from, std::uint32_t to,
                               Visit&& visit) const {
    // Touching boxes have cells at most one apart on each axis (either way: the relation
    // is symmetric), so each pair is reported by the box that comes first in sorted order
    // (cells in row order): the boxes after it in its own cell, and those of the four
    // neighbour cells that come after its cell: one to the right in its row, three in the
    // next row. Every box of those neighbours comes after it in sorted order.
    const Level& level = levels_[levelIndex];
    const Box* const boxes = sortedBoxes_.data();
    const std::uint32_t* const names = sorted_.data();
    // The boxes of a short run that touch are gathered first, without a branch a box
    // (most do not touch, and which do is a coin the branch predictor cannot call), then
    // visited in order; a long run, a crowd in one cell, box by box.
    auto testRun = [&](std::uint32_t k, std::uint32_t first, std::uint32_t last) {
        const Box box = boxes[k];
        constexpr std::uint32_t kShortRun = 16;
        if (last - first > kShortRun) {
            for (std::uint32_t m = first; m < last; ++m)
                if (touches(box, boxes[m]))
                    visit(names[k], names[m]);
            return;
        }
        std::uint32_t hits[kShortRun];
        std::uint32_t found = 0;
        for (std::uint32_t m = first; m < last; ++m) {
            hits[found] = m;
            found += touches(box, boxes[m]) ? 1u : 0u;
        }
        for (std::uint32_t h = 0; h < found; ++h)
            visit(names[k], names[hits[h]]);
    };
    if (level.dense) {
        // A row's cells lie one after another in sorted_: the rest of its own cell and the
        // next one are one run, the three cells below another.
        for (std::uint32_t k = from; k < to; ++k) {
            const Cell home = sortedCells_[k];
            const std::int64_t x = std::int64_t(home.x) - level.low.x;
            const std::int64_t y = std::int64_t(home.y) - level.low.y;
            const std::size_t cell = level.cellStart + std::size_t(y * level.width + x);
            const std::int64_t right = std::min<std::int64_t>(x + 1, level.width - 1);
            testRun(k, k + 1, cells_.begin(cell + std::size_t(right - x) + 1));
            if (y + 1 < level.height) {
                const std::int64_t left = std::max<std::int64_t>(x - 1, 0);
                const std::size_t below = cell + std::size_t(level.width);
                testRun(k, cells_.begin(below - std::size_t(x - left)),
                        cells_.begin(below + std::size_t(right - x) + 1));
            }
        }
        return;
    }
    for (std::uint32_t k = from; k < to; ++k) {
        const Cell home = sortedCells_[k];
        auto test = [&](std::uint32_t m) {
            if (m > k && touches(boxes[k], boxes[m]))
                visit(names[k], names[m]);
        };
        forEachInRow(levelIndex, home.y, home.x, std::int64_t(home.x) + 1, test);
        forEachInRow(levelIndex, std::int64_t(home.y) + 1, std::int64_t(home.x) - 1,
                     std::int64_t(home.x) + 1, test);
    }
}

template <class Visit> void BoxGrid::query(const Box& query, Visit&& visit) const {
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1)
        visitLevel(__builtin_ctzll(used), query, visit);
}

template <class Visit>
void BoxGrid::pairsAcrossLevels(int level, std::uint32_t from, std::uint32_t to,
                                Visit&& visit) const {
    // The finer box looks into the coarser levels, so each pair is found once.
    const std::uint64_t coarser =
        level + 1 < kLevels ? usedLevels_ >> (level + 1) << (level + 1) : 0;
    if (coarser == 0)
        return;
    for (std::uint32_t k = from; k < to; ++k) {
        const std::uint32_t i = sorted_[k];
        for (std::uint64_t used = coarser; used != 0; used &= used - 1)
            visitLevel(__builtin_ctzll(used), sortedBoxes_[k],
                       [&](std::uint32_t j) { visit(i, j); });
    }
}

template <class Visit>
void BoxGrid::forEachPairOf(std::uint32_t begin, std::uint32_t end, Visit&& visit) const {
    // Item k < size(): the same-level pairs of sorted_[k]; item size() + k: its pairs
    // across levels. Levels lie one after another in sorted_, finest first.
    const auto n = std::uint32_t(boxes_.size());
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1) {
        const int k = __builtin_ctzll(used);
        const std::uint32_t from = std::max(begin, levels_[k].begin);
        const std::uint32_t to = std::min(end, levels_[k].end);
        if (from < to)
            pairsWithinLevel(k, from, to, visit);
    }
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1) {
        const int k = __builtin_ctzll(used);
        const std::uint32_t from = std::max(begin, n + levels_[k].begin);
        const std::uint32_t to = std::min(end, n + levels_[k].end);
        if (from < to)
            pairsAcrossLevels(k, from - n, to - n, visit);
    }
}

} // namespace jostle
