// BoxGrid: building the grid and finding in it (box_grid.hpp explains the grid).
#include "box_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

namespace jostle {

namespace {

// A level is dense (an array of cells) when it has at most this many cells per box.
constexpr std::int64_t kDenseCellsPerBox = 16;

float sizeOf(const Box& box) {
    return std::max(box.max.x - box.min.x, box.max.y - box.min.y);
}

/// Boxes per block of build's passes over them.
constexpr std::uint32_t kBoxesPerBlock = 2048;

/// Calls run(Block) over the boxes [0, n): in blocks on `tasks`, or as one block.
template <class Run> void forBlocks(TaskRunner* tasks, std::uint32_t n, Run&& run) {
    if (tasks != nullptr)
        tasks->forEachBlock(n, kBoxesPerBlock, run);
    else if (n > 0)
        run(Block{0, 0, n});
}

} // namespace

int BoxGrid::levelOf(const Box& box) const {
    // A little room above the size: a box must never be larger than its cells.
    const double size = double(sizeOf(box)) * (1.0 + 1.0 / (1 << 20));
    int level = 0;
    while (level < kLevels - 1 && levels_[level].size < size)
        ++level;
    return level;
}

std::size_t BoxGrid::hashOf(int level, Cell cell) const {
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

void BoxGrid::run(int levelIndex, std::int64_t x, std::int64_t y, std::uint32_t& first,
                  std::uint32_t& last) const {
    const Level& level = levels_[levelIndex];
    first = last = 0;
    if (level.dense) {
        const std::int64_t cx = x - level.low.x, cy = y - level.low.y;
        if (cx < 0 || cy < 0 || cx >= level.width || cy >= level.height)
            return;
        const std::size_t cell = level.cellStart + std::size_t(cy * level.width + cx);
        first = cells_.begin(cell);
        last = cells_.end(cell);
        return;
    }
    const Cell cell{std::int32_t(x), std::int32_t(y)};
    const std::size_t mask = table_.size() - 1;
    for (std::size_t slot = hashOf(levelIndex, cell) & mask;; slot = (slot + 1) & mask) {
        const HashSlot& entry = table_[slot];
        if (entry.level < 0)
            return;
        if (entry.level == levelIndex && entry.cell.x == cell.x && entry.cell.y == cell.y) {
            first = entry.first;
            last = entry.last;
            return;
        }
    }
}

int BoxGrid::mergedLevels(double base, TaskRunner* tasks) {
    // How many boxes each of the first levels would hold; the last count, all the rest.
    static_assert(kMaxMerged == 2);
    forBlocks(tasks, std::uint32_t(boxes_.size()), [&](Block block) {
        std::uint32_t(&counts)[kMaxMerged + 2] = blockSums_[block.index].firstLevels;
        std::fill(std::begin(counts), std::end(counts), 0u);
        for (std::uint32_t i = block.begin; i < block.end; ++i) {
            const double size = double(sizeOf(boxes_[i]));
            ++counts[int(base < size) + int(2.0 * base < size) + int(4.0 * base < size)];
        }
    });
    std::size_t counts[kMaxMerged + 2] = {};
    for (const BlockSums& sums : blockSums_)
        for (int k = 0; k < kMaxMerged + 2; ++k)
            counts[k] += sums.firstLevels[k];
    // Merge the first levels into one when together they hold most boxes: a world of
    // boxes of nearly one size (grown by their motion, some cross a doubling) then has
    // one level, and no box looks into another level for its neighbours. Two doublings
    // merged give the boxes of the first two levels cells at least twice their size, so
    // only when those boxes are few: a crowd of them would meet many more boxes a cell.
    const auto n = double(boxes_.size());
    std::size_t held = 0;
    for (int merged = 0; merged <= kMaxMerged; ++merged) {
        held += counts[merged];
        if (double(held) < kMergedShare * n)
            continue;
        if (merged == 2 && double(counts[0] + counts[1]) > kFewSmallShare * n)
            return 0;
        return merged;
    }
    return 0; // sizes spread out: the levels as they are
}

void BoxGrid::build(const std::vector<Box>& boxes, TaskRunner* tasks) {
    const auto n = std::uint32_t(boxes.size());
    boxes_.resize(n);
    usedLevels_ = 0;
    for (Level& level : levels_)
        level = Level{};
    sorted_.resize(n);
    cells_.reset(0);
    if (n == 0)
        return;
    blockSums_.resize(tasks ? tasks->blocksOf(n, kBoxesPerBlock) : 1);

    // Level 0 fits the smallest box, a quarter to spare (boxes a little larger than the
    // smallest, grown by their motion say, still share its level); each level doubles.
    // If 63 levels cannot span the sizes, the small boxes share a coarser level: slower,
    // still correct. The last level is one infinite cell, for whatever is larger still.
    forBlocks(tasks, n, [&](Block block) {
        float smallest = INFINITY, largest = 0.0f;
        for (std::uint32_t i = block.begin; i < block.end; ++i) {
            boxes_[i] = boxes[i];
            smallest = std::min(smallest, sizeOf(boxes[i]));
            largest = std::max(largest, sizeOf(boxes[i]));
        }
        blockSums_[block.index].smallest = smallest;
        blockSums_[block.index].largest = largest;
    });
    float smallest = INFINITY, largest = 0.0f;
    for (const BlockSums& sums : blockSums_) {
        smallest = std::min(smallest, sums.smallest);
        largest = std::max(largest, sums.largest);
    }
    const double tiny = double(std::numeric_limits<float>::min());
    double base = std::max(double(smallest), tiny) * 1.25;
    base = std::max(base, std::ldexp(std::max(double(largest), tiny), -(kLevels - 2)));
    base = std::ldexp(base, mergedLevels(base, tasks));
    for (int k = 0; k < kLevels; ++k) {
        levels_[k].size = std::ldexp(base, k);
        levels_[k].inverse = 1.0 / levels_[k].size;
    }
    levels_[kLevels - 1].size = std::numeric_limits<double>::infinity();
    levels_[kLevels - 1].inverse = 0.0;

    // Each box's level and cell, and the cells each level's boxes span.
    keyOfBox_.resize(n);
    cellOfBox_.resize(n);
    forBlocks(tasks, n, [&](Block block) {
        BlockSums& sums = blockSums_[block.index];
        std::fill(std::begin(sums.counts), std::end(sums.counts), 0u);
        for (std::uint32_t i = block.begin; i < block.end; ++i) {
            const int level = levelOf(boxes_[i]);
            const Cell c = cellOf(boxes_[i].min, levels_[level]);
            keyOfBox_[i] = std::uint32_t(level); // its key, once the levels are laid out
            cellOfBox_[i] = c;
            if (sums.counts[level]++ == 0)
                sums.low[level] = sums.high[level] = c;
            sums.low[level] = {std::min(sums.low[level].x, c.x), std::min(sums.low[level].y, c.y)};
            sums.high[level] = {std::max(sums.high[level].x, c.x),
                                std::max(sums.high[level].y, c.y)};
        }
    });
    std::uint32_t counts[kLevels] = {};
    Cell low[kLevels], high[kLevels];
    for (const BlockSums& sums : blockSums_) {
        for (int level = 0; level < kLevels; ++level) {
            if (sums.counts[level] == 0)
                continue;
            if (counts[level] == 0) {
                low[level] = sums.low[level];
                high[level] = sums.high[level];
                usedLevels_ |= std::uint64_t{1} << level;
            }
            counts[level] += sums.counts[level];
            low[level] = {std::min(low[level].x, sums.low[level].x),
                          std::min(low[level].y, sums.low[level].y)};
            high[level] = {std::max(high[level].x, sums.high[level].x),
                           std::max(high[level].y, sums.high[level].y)};
        }
    }

    // The keys of the sort, level after level: a key per cell of a level whose boxes are
    // close together (a dense array of cells), one key for all of a level too spread out
    // for that (its cells go in a hash table below).
    std::uint32_t keys = 0;
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1) {
        const int k = __builtin_ctzll(used);
        Level& level = levels_[k];
        const std::int64_t width = std::int64_t(high[k].x) - low[k].x + 1;
        const std::int64_t height = std::int64_t(high[k].y) - low[k].y + 1;
        level.cellStart = keys;
        if (double(width) * double(height) <= double(kDenseCellsPerBox * counts[k] + 16)) {
            level.dense = true;
            level.low = low[k];
            level.width = width;
            level.height = height;
            keys += std::uint32_t(width * height);
        } else {
            keys += 1;
        }
    }
    auto keyOf = [&](std::uint32_t i) {
        const Level& level = levels_[keyOfBox_[i]];
        if (!level.dense)
            return level.cellStart;
        const Cell c = cellOfBox_[i];
        return level.cellStart +
               std::uint32_t((std::int64_t(c.y) - level.low.y) * level.width + (c.x - level.low.x));
    };
    // One counting sort by key: by level, then (dense levels) by cell, each cell's boxes
    // in insertion order.
    forBlocks(tasks, n, [&](Block block) {
        for (std::uint32_t i = block.begin; i < block.end; ++i)
            keyOfBox_[i] = keyOf(i);
    });
    cells_.reset(keys);
    for (std::uint32_t i = 0; i < n; ++i)
        cells_.count(keyOfBox_[i]);
    cells_.endCounting();
    for (std::uint32_t i = 0; i < n; ++i)
        sorted_[cells_.place(keyOfBox_[i])] = i;
    cells_.endPlacing();

    // A hashed level's boxes by cell, then insertion order.
    std::size_t hashedRuns = 0;
    for (std::uint64_t used = usedLevels_; used != 0; used &= used - 1) {
        const int k = __builtin_ctzll(used);
        Level& level = levels_[k];
        level.begin = cells_.begin(level.cellStart);
        level.end = level.begin + counts[k];
        if (level.dense)
            continue;
        // Offsets as the iterator's signed type: on wasm32 that is 32 bits wide, and a
        // uint32_t does not convert to it silently.
        std::sort(sorted_.begin() + static_cast<std::ptrdiff_t>(level.begin),
                  sorted_.begin() + static_cast<std::ptrdiff_t>(level.end),
                  [&](std::uint32_t p, std::uint32_t q) {
                      const Cell a = cellOfBox_[p], b = cellOfBox_[q];
                      return a.y != b.y ? a.y < b.y : a.x != b.x ? a.x < b.x : p < q;
                  });
        hashedRuns += level.end - level.begin;
    }

    sortedBoxes_.resize(n);
    sortedCells_.resize(n);
    forBlocks(tasks, n, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            sortedBoxes_[k] = boxes_[sorted_[k]];
            sortedCells_[k] = cellOfBox_[sorted_[k]];
        }
    });

    // The hash table of the sparse levels' cells: one slot per run of equal cells.
    table_.assign(std::bit_ceil(std::max<std::size_t>(2, 2 * hashedRuns)), HashSlot{});
    tableShift_ = 64 - std::countr_zero(table_.size());
    const std::size_t mask = table_.size() - 1;
    for (int k = 0; k < kLevels; ++k) {
        const Level& level = levels_[k];
        if (level.dense || level.begin == level.end)
            continue;
        for (std::uint32_t m = level.begin; m < level.end;) {
            const Cell c = sortedCells_[m];
            std::uint32_t last = m + 1;
            while (last < level.end && sortedCells_[last].x == c.x && sortedCells_[last].y == c.y)
                ++last;
            std::size_t slot = hashOf(k, c) & mask;
            while (table_[slot].level >= 0)
                slot = (slot + 1) & mask;
            table_[slot] = {c, k, m, last};
            m = last;
        }
    }
}

} // namespace jostle
