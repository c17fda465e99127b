#include "box_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace jostle {

namespace {

// Cell coordinates are clamped here: far beyond any float world, and still far from
// overflowing when a window adds or subtracts one.
constexpr double kCellLimit = 4.0e18;

float sizeOf(const Bounds& box) {
    return std::max(box.max.x - box.min.x, box.max.y - box.min.y);
}

/// The smallest power of two >= x (x > 0 and finite).
float powerOfTwoAtLeast(float x) {
    int exponent = 0;
    const float mantissa = std::frexp(x, &exponent); // x = mantissa * 2^exponent, [0.5, 1)
    return std::ldexp(1.0f, mantissa == 0.5f ? exponent - 1 : exponent);
}

std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    h ^= h >> 33;
    return h;
}

} // namespace

int BoxGrid::levelOf(const Bounds& box) const {
    const float size = sizeOf(box);
    int level = 0;
    while (level < kLevels - 1 && cellSizes_[level] < size)
        ++level;
    return level;
}

BoxGrid::Cell BoxGrid::cellOf(Vec2 point, int level) const {
    auto coordinate = [&](float value) {
        const double cell = std::floor(double(value) / double(cellSizes_[level]));
        return std::int64_t(std::clamp(cell, -kCellLimit, kCellLimit));
    };
    return {coordinate(point.x), coordinate(point.y)};
}

std::uint64_t BoxGrid::keyOf(int level, Cell cell) {
    // Distinct cells may share a key only through the hash of the table slot, never here:
    // level and both coordinates are folded with a strong mixer, and the table compares
    // whole keys. (Two cells with the same 64-bit key would merely share a list, which
    // the overlap test sorts out: a cost, never a wrong answer.)
    return mix(std::uint64_t(cell.x) * 0x9E3779B97F4A7C15ULL ^ mix(std::uint64_t(cell.y)) ^
               std::uint64_t(level) << 58);
}

std::uint32_t BoxGrid::head(std::uint64_t key) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t slot = key & mask;; slot = (slot + 1) & mask) {
        if (table_[slot].head == kNone)
            return kNone;
        if (table_[slot].key == key)
            return table_[slot].head;
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
        byLevel_.clear();
        return;
    }

    // Level 0 fits the smallest box; each level doubles. If 64 levels cannot span the
    // sizes, the small boxes share a coarser level: slower, still correct.
    float smallest = INFINITY, largest = 0.0f;
    for (const Bounds& box : boxes_) {
        smallest = std::min(smallest, sizeOf(box));
        largest = std::max(largest, sizeOf(box));
    }
    const float tiny = std::numeric_limits<float>::min();
    float base = powerOfTwoAtLeast(std::max(smallest, tiny));
    base = std::max(base, std::ldexp(powerOfTwoAtLeast(std::max(largest, tiny)), -(kLevels - 2)));
    for (int level = 0; level < kLevels; ++level)
        cellSizes_[level] = std::ldexp(base, level);
    cellSizes_[kLevels - 1] = INFINITY; // whatever is left: one cell

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
    const std::size_t mask = table_.size() - 1;
    for (std::uint32_t i = std::uint32_t(n); i-- > 0;) {
        const std::uint64_t key = keyOf(levels_[i], cellOf(boxes_[i].min, levels_[i]));
        std::size_t slot = key & mask;
        while (table_[slot].head != kNone && table_[slot].key != key)
            slot = (slot + 1) & mask;
        next_[i] = table_[slot].head;
        table_[slot] = {key, i};
    }
}

} // namespace jostle
