#include "box_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace jostle {

namespace {

// Cell coordinates are clamped here, so that a window can add and subtract one without
// overflow. Clamping keeps the order of cells, so a box beyond the limit is still found,
// in a crowded edge cell: slower, never wrong. It takes a world 2^30 cells wide to reach.
constexpr double kCellLimit = 1073741824.0;

float sizeOf(const Bounds& box) {
    return std::max(box.max.x - box.min.x, box.max.y - box.min.y);
}

} // namespace

int BoxGrid::levelOf(const Bounds& box) const {
    // A little room above the size: a box must never be larger than its cells.
    const double size = double(sizeOf(box)) * (1.0 + 1.0 / (1 << 20));
    int level = 0;
    while (level < kLevels - 1 && cellSizes_[level] < size)
        ++level;
    return level;
}

BoxGrid::Cell BoxGrid::cellOf(Vec2 point, int level) const {
    auto coordinate = [&](float value) {
        const double cell = std::floor(double(value) * inverseSizes_[level]);
        return std::int32_t(std::clamp(cell, -kCellLimit, kCellLimit));
    };
    return {coordinate(point.x), coordinate(point.y)};
}

std::size_t BoxGrid::slotOf(int level, Cell cell) const {
    // Pack the cell into 64 bits, then mix them well (a murmur-style finalizer): nearby
    // cells must land in unrelated slots, or linear probing runs long.
    std::uint64_t h = (std::uint64_t(std::uint32_t(cell.x)) << 32 | std::uint32_t(cell.y)) ^
                      std::uint64_t(level) * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    h ^= h >> 33;
    return std::size_t(h >> tableShift_);
}

std::uint32_t BoxGrid::head(int level, Cell cell) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t slot = slotOf(level, cell);; slot = (slot + 1) & mask) {
        const Slot& entry = table_[slot];
        if (entry.level < 0)
            return kNone;
        if (entry.level == level && entry.cell.x == cell.x && entry.cell.y == cell.y)
            return entry.head;
    }
}

void BoxGrid::build(const std::vector<Bounds>& boxes) {
    boxes_ = boxes;
    const std::size_t n = boxes_.size();
    levels_.assign(n, 0);
    next_.assign(n, kNone);
    usedLevels_ = 0;
    std::fill(std::begin(levelStart_), std::end(levelStart_), 0u);
    if (n == 0) {
        table_.assign(1, Slot{});
        tableShift_ = 63;
        byLevel_.clear();
        return;
    }

    // Level 0 fits the smallest box; each level doubles. If 63 levels cannot span the
    // sizes, the small boxes share a coarser level: slower, still correct. The last
    // level is one infinite cell, for whatever is larger still.
    float smallest = INFINITY, largest = 0.0f;
    for (const Bounds& box : boxes_) {
        smallest = std::min(smallest, sizeOf(box));
        largest = std::max(largest, sizeOf(box));
    }
    const double tiny = double(std::numeric_limits<float>::min());
    // A quarter above the smallest: boxes a little larger than the smallest (grown by
    // their motion, say) still share its level.
    double base = std::max(double(smallest), tiny) * 1.25;
    base = std::max(base, std::ldexp(std::max(double(largest), tiny), -(kLevels - 2)));
    for (int level = 0; level < kLevels; ++level) {
        cellSizes_[level] = std::ldexp(base, level);
        inverseSizes_[level] = 1.0 / cellSizes_[level];
    }
    cellSizes_[kLevels - 1] = INFINITY;
    inverseSizes_[kLevels - 1] = 0.0;

    // Group by level (a counting sort keeps insertion order within a level).
    std::uint32_t counts[kLevels] = {};
    for (std::size_t i = 0; i < n; ++i) {
        levels_[i] = std::uint8_t(levelOf(boxes_[i]));
        ++counts[levels_[i]];
        usedLevels_ |= std::uint64_t{1} << levels_[i];
    }
    for (int level = 0; level < kLevels; ++level)
        levelStart_[level + 1] = levelStart_[level] + counts[level];
    byLevel_.resize(n);
    std::uint32_t fill[kLevels];
    std::copy(levelStart_, levelStart_ + kLevels, fill);
    for (std::uint32_t i = 0; i < n; ++i)
        byLevel_[fill[levels_[i]]++] = i;

    // File each box under its min corner's cell. Inserting in reverse order and linking
    // at the head leaves each cell's list in insertion order.
    table_.assign(std::bit_ceil(2 * n), Slot{});
    tableShift_ = 64 - std::countr_zero(table_.size());
    const std::size_t mask = table_.size() - 1;
    for (std::uint32_t i = std::uint32_t(n); i-- > 0;) {
        const int level = levels_[i];
        const Cell cell = cellOf(boxes_[i].min, level);
        std::size_t slot = slotOf(level, cell) & mask;
        while (table_[slot].level >= 0 &&
               !(table_[slot].level == level && table_[slot].cell.x == cell.x &&
                 table_[slot].cell.y == cell.y))
            slot = (slot + 1) & mask;
        next_[i] = table_[slot].head;
        table_[slot] = {cell, level, i};
    }

}

} // namespace jostle
