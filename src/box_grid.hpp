// BoxGrid: a hierarchical grid of boxes, the broadphase of both models.
//
// Each box lives in one cell of one level: the level whose cells are at least as large as
// the box (level 0 fits the smallest box, and each level doubles), the cell that holds
// its min corner. So a box
// spans at most two cells of its level along each axis, and a box of any size is found
// by looking at a window of at most 3 × 3 cells per level. Small and huge boxes in one
// grid cost no more than their own levels, and the cost of a step grows about linearly
// with the number of boxes. Cells live in a hash table: the world may be as large and as
// far from the origin as floats go.
//
// Everything is visited in a fixed order (insertion order, then cell order), never in
// pointer or hash order, so the same input gives the same pairs in the same order.
#pragma once

#include "jostle/math.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

/// An axis-aligned box given by its corners, min <= max.
struct Bounds {
    Vec2 min;
    Vec2 max;
};

/// True when the two boxes overlap or touch.
inline bool touches(const Bounds& a, const Bounds& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

class BoxGrid {
public:
    /// Replaces the grid's contents with these boxes; the i-th is named i in results.
    void build(const std::vector<Bounds>& boxes);

    std::size_t size() const { return boxes_.size(); }
    const Bounds& bounds(std::uint32_t i) const { return boxes_[i]; }

    /// Calls visit(i) for every box i that overlaps or touches `query`, each once.
    template <class Visit> void query(const Bounds& query, Visit&& visit) const;

    /// Calls visit(i, j) for every pair of boxes that overlap or touch, each pair once.
    /// The calls come in a fixed order: by i, the boxes in insertion order; j may be
    /// smaller or larger than i.
    template <class Visit> void forEachPair(Visit&& visit) const;

private:
    static constexpr std::uint32_t kNone = UINT32_MAX;
    static constexpr int kLevels = 64;

    struct Cell {
        std::int32_t x, y;
    };

    /// A cell of the hash table: which cell it is (compared whole, so that two cells
    /// never share a list, which would visit their boxes twice) and its first box.
    struct Slot {
        Cell cell{0, 0};
        std::int32_t level = -1; ///< -1: empty
        std::uint32_t head = kNone;
    };

    int levelOf(const Bounds& box) const;
    Cell cellOf(Vec2 point, int level) const;
    std::size_t slotOf(int level, Cell cell) const;
    std::uint32_t head(int level, Cell cell) const;

    /// Visits every box of `level` in the window of cells that may hold a box touching
    /// `query`, or, when that window has more cells than the level has boxes, every box
    /// of the level. visit(i) is called for each box that does touch `query`.
    template <class Visit> void visitLevel(int level, const Bounds& query, Visit&& visit) const;

    std::vector<Bounds> boxes_;
    std::vector<std::uint8_t> levels_;   ///< level of each box
    std::vector<std::uint32_t> next_;    ///< next box in the same cell
    std::vector<std::uint32_t> byLevel_; ///< box indices grouped by level, in order
    std::uint32_t levelStart_[kLevels + 1] = {};
    std::uint64_t usedLevels_ = 0; ///< bit k: level k has boxes
    /// Cell sizes and their inverses, in double: cells are found by multiplying float
    /// coordinates, and double's 29 extra bits keep that exact enough that a box is
    /// never filed a cell away from where a query looks for it.
    double cellSizes_[kLevels] = {};
    double inverseSizes_[kLevels] = {};
    int tableShift_ = 64;
    std::vector<Slot> table_; ///< open addressing, linear probing; size a power of two
};

// --- Template definitions ----------------------------------------------------------------

template <class Visit>
void BoxGrid::visitLevel(int level, const Bounds& query, Visit&& visit) const {
    const Cell low = cellOf(query.min, level);
    const Cell high = cellOf(query.max, level);
    // A box is filed under its min corner and is at most one cell large, so one touching
    // the query has its min corner at most one cell before the query's.
    const std::int64_t fromX = std::int64_t(low.x) - 1, fromY = std::int64_t(low.y) - 1;
    const double cells =
        (double(high.x) - double(fromX) + 1) * (double(high.y) - double(fromY) + 1);
    const std::uint32_t count = levelStart_[level + 1] - levelStart_[level];
    if (cells > double(count)) {
        for (std::uint32_t k = levelStart_[level]; k < levelStart_[level + 1]; ++k)
            if (touches(boxes_[byLevel_[k]], query))
                visit(byLevel_[k]);
        return;
    }
    for (std::int64_t y = fromY; y <= std::int64_t(high.y); ++y)
        for (std::int64_t x = fromX; x <= std::int64_t(high.x); ++x)
            for (std::uint32_t i = head(level, {std::int32_t(x), std::int32_t(y)}); i != kNone;
                 i = next_[i])
                if (touches(boxes_[i], query))
                    visit(i);
}

template <class Visit> void BoxGrid::query(const Bounds& query, Visit&& visit) const {
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1)
        visitLevel(__builtin_ctzll(used), query, visit);
}

template <class Visit> void BoxGrid::forEachPair(Visit&& visit) const {
    for (std::uint32_t i = 0; i < boxes_.size(); ++i) {
        const int level = levels_[i];
        // Same level: both boxes see each other; the one inserted first reports.
        visitLevel(level, boxes_[i], [&](std::uint32_t j) {
            if (j > i)
                visit(i, j);
        });
        // Coarser levels: only the finer box looks, so each pair is found once.
        const std::uint64_t coarser =
            level + 1 < kLevels ? usedLevels_ >> (level + 1) << (level + 1) : 0;
        for (std::uint64_t used = coarser; used != 0; used &= used - 1)
            visitLevel(__builtin_ctzll(used), boxes_[i], [&](std::uint32_t j) { visit(i, j); });
    }
}

} // namespace jostle
