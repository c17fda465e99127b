// The live bodies of a world in creation order: World::bodies(), and the order every
// solver, event list and query result follows. Appending and removing a body cost O(1)
// (amortised) whatever the number of bodies. (creation_order.cpp: closing the gaps.)
#pragma once

#include "jostle/body.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

namespace jostle {

/// The live bodies in creation order. Removing one leaves a gap (the null handle) where
/// it was, found through its slot's position, not by a search. Gaps at the end are
/// dropped at once; the others are closed, keeping the order, when they are half the
/// list, and whenever the list is read (live()), which is the only way to read it.
class CreationOrder {
public:
    /// Room for bodies in slots below `slots` without growing again.
    void reserve(std::size_t slots) {
        entries_.reserve(slots);
        positions_.reserve(slots);
    }

    /// Appends the body `id`, created last.
    void append(BodyId id) {
        ++changes_;
        if (entries_.size() >= UINT32_MAX) // positions fit 32 bits: fewer bodies than slots
            close();
        if (id.index >= positions_.size())
            positions_.resize(std::size_t{id.index} + 1);
        positions_[id.index] = static_cast<std::uint32_t>(entries_.size());
        entries_.push_back(id);
    }

    /// Removes the body of slot `slot`, which is in the list.
    void remove(std::uint32_t slot) {
        ++changes_;
        entries_[positions_[slot]] = BodyId{};
        std::size_t gaps = gaps_.load(std::memory_order_relaxed) + 1;
        while (!entries_.empty() && entries_.back().isNull()) {
            entries_.pop_back();
            --gaps;
        }
        gaps_.store(gaps, std::memory_order_relaxed);
        if (2 * gaps > entries_.size())
            close();
    }

    /// How many bodies have been appended and removed: a list made from live() is up to
    /// date while this has not changed.
    std::uint64_t changes() const { return changes_; }

    /// How many bodies are alive.
    std::size_t size() const { return entries_.size() - gaps_.load(std::memory_order_relaxed); }

    /// The live bodies, in creation order, with no gap: closes the gaps first. A const
    /// function of World may run on several threads at once, and this is one: the first
    /// closes the gaps under a lock, and the others find none. The span is good until
    /// the next append or remove: a loop over it must not destroy bodies nor call the
    /// game's code, which may (the solvers' and queries' loops do neither).
    std::span<const BodyId> live() const {
        if (gaps_.load(std::memory_order_acquire) != 0)
            closeUnderLock();
        return entries_;
    }

private:
    /// Moves every live body down over the gaps, in order, and notes where each went.
    void close() const;
    /// close(), under mutex_, unless another thread did it meanwhile. Out of line: the
    /// loops that call live() stay small.
    void closeUnderLock() const;

    // Mutable: live() closes the gaps. Changed only by World's non-const functions, which
    // no other call runs beside, and by the first live() after them, under mutex_.
    mutable std::vector<BodyId> entries_;
    /// By slot: the index of its body in entries_, while it lives.
    mutable std::vector<std::uint32_t> positions_;
    mutable std::atomic<std::size_t> gaps_{0};
    std::uint64_t changes_ = 0;
    mutable std::mutex mutex_;
};

} // namespace jostle
