// Counting sort: items placed by a small whole-number key, stably, in two passes (count
// every item's key, then give each item its place, in the same order). Linear in the
// items and the keys, and the same input always gives the same order. The broadphase's
// grid, the support order, the contact cache and the events all sort this way. And a
// merge sort, as stable, for a few items among many keys.
#pragma once

#include "room.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace jostle {

/// The runs of a counting sort, one per key: count, then place, then read the runs.
class Buckets {
public:
    /// Starts over with keys 0 .. keyCount - 1, all empty.
    void reset(std::size_t keyCount) { starts_.assign(keyCount + 1, 0); }
    /// Counting pass: one more item of `key`. Returns its rank, how many items of `key`
    /// were counted before it: after endCounting() its place is begin(key) + rank, which
    /// a placing pass on several threads can find without placing in order.
    std::uint32_t count(std::size_t key) { return starts_[key + 1]++; }
    /// Ends the counting pass: every run starts where the one before ends. Returns how
    /// many items were counted.
    std::uint32_t endCounting() {
        for (std::size_t k = 0; k + 1 < starts_.size(); ++k)
            starts_[k + 1] += starts_[k];
        return starts_.back();
    }
    /// Placing pass, over the items in the order they were counted: the place of the
    /// next item of `key`.
    std::uint32_t place(std::size_t key) { return starts_[key]++; }
    /// Ends the placing pass: each key's run is [begin(key), end(key)) again.
    void endPlacing() {
        // Each start now holds the end of its run, which is the start of the next one.
        for (std::size_t k = starts_.size() - 1; k > 0; --k)
            starts_[k] = starts_[k - 1];
        starts_[0] = 0;
    }

    std::size_t keyCount() const { return starts_.empty() ? 0 : starts_.size() - 1; }
    std::uint32_t begin(std::size_t key) const { return starts_[key]; }
    std::uint32_t end(std::size_t key) const { return starts_[key + 1]; }

private:
    std::vector<std::uint32_t> starts_;
};

/// Sorts `items` stably by keyOf(item), a whole number below `keyCount`, through
/// `scratch` (which ends up holding the old order).
template <class T, class KeyOf>
void sortByKey(std::vector<T>& items, KeyOf&& keyOf, std::size_t keyCount, Buckets& buckets,
               std::vector<T>& scratch) {
    buckets.reset(keyCount);
    for (const T& item : items)
        buckets.count(keyOf(item));
    buckets.endCounting();
    resizeAnew(scratch, items.size());
    for (const T& item : items)
        scratch[buckets.place(keyOf(item))] = item;
    items.swap(scratch);
}

/// Sorts `items` stably by keyOf(item), any ordered key, through `scratch`: a bottom-up
/// merge sort, n log n in the items whatever the keys, where a counting sort would walk
/// every key. Equal keys keep their order, so it gives what sortByKey gives.
template <class T, class KeyOf>
void mergeSortByKey(std::vector<T>& items, KeyOf&& keyOf, std::vector<T>& scratch) {
    const std::size_t n = items.size();
    scratch.resize(n);
    T* from = items.data();
    T* to = scratch.data();
    for (std::size_t width = 1; width < n; width *= 2) {
        for (std::size_t lo = 0; lo < n; lo += 2 * width) {
            const std::size_t mid = std::min(lo + width, n), hi = std::min(lo + 2 * width, n);
            std::size_t i = lo, j = mid, k = lo;
            // From the right run only when strictly smaller: equal keys keep their order.
            while (i < mid && j < hi)
                to[k++] = keyOf(from[j]) < keyOf(from[i]) ? from[j++] : from[i++];
            while (i < mid)
                to[k++] = from[i++];
            while (j < hi)
                to[k++] = from[j++];
        }
        std::swap(from, to);
    }
    if (from != items.data())
        items.swap(scratch);
}

} // namespace jostle
