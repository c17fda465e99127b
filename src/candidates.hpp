// The candidates of one query: the bodies of the world's resting grid near where it
// looks, and every body outside that grid.
//
// Static and sleeping bodies come from the resting grid, which is exact whenever it is
// not marked dirty: they do not move, and whatever changes one of them marks it. Awake
// bodies move every step without telling anyone, so every query tests each of them; a
// world's awake bodies are usually few next to its level.
#pragma once

#include "geometry.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace jostle {

/// The bodies one query looks at.
class Candidates {
public:
    explicit Candidates(const WorldState& world);

    /// Calls visit(slot) for each body of the resting grid that touches `region`.
    template <class Visit> void inGrid(const Box& region, Visit&& visit) const;

    /// Calls visit(slot) for each body not in the resting grid: the awake ones, or every
    /// body when the grid is out of date (during a step, after something changed).
    template <class Visit> void outsideGrid(Visit&& visit) const;

    /// Walks the path of a box of half extents `half` (zero: a ray) from `from` along
    /// `delta` through the resting grid, piece by piece: visit(slot) for each body near
    /// each piece (a body near two pieces is visited twice), then stop(end of the piece,
    /// as a fraction of the path); a true stop ends the walk.
    template <class Visit, class Stop>
    void walkPath(Vec2 from, Vec2 delta, Vec2 half, Visit&& visit, Stop&& stop) const;

    /// When the body in `slot` was created (WorldState::created): results are sorted by it.
    std::uint64_t created(std::uint32_t slot) const { return w_.created[slot]; }

private:
    void listAwake();

    /// A long ray or cast is looked up in the grid in at most this many pieces.
    static constexpr int kMaxPieces = 64;

    const WorldState& w_;
    QueryIndex& index_;
    bool gridUsable_ = false;
    std::vector<std::uint32_t> awake_; ///< slots, in creation order
};

// --- Template definitions ----------------------------------------------------------------

template <class Visit> void Candidates::inGrid(const Box& region, Visit&& visit) const {
    if (gridUsable_)
        w_.restingGrid.query(region, [&](std::uint32_t i) { visit(w_.restingSlots[i]); });
}

template <class Visit> void Candidates::outsideGrid(Visit&& visit) const {
    if (!gridUsable_) {
        for (BodyId id : w_.order.live())
            visit(id.index);
        return;
    }
    for (std::uint32_t slot : awake_)
        visit(slot);
}

template <class Visit, class Stop>
void Candidates::walkPath(Vec2 from, Vec2 delta, Vec2 half, Visit&& visit, Stop&& stop) const {
    const float longest = std::max(std::abs(delta.x), std::abs(delta.y));
    const float wanted = std::ceil(longest / index_.pieceLength);
    const int pieces = wanted >= float(kMaxPieces) ? kMaxPieces : std::max(1, int(wanted));
    // Each piece's box is grown by far more than the rounding of its ends and of the
    // hit tests, so that a body touching the path is near one of the pieces it touches.
    const Vec2 to = from + delta;
    const float magnitude = std::max({std::abs(from.x), std::abs(from.y), std::abs(to.x),
                                      std::abs(to.y), half.x, half.y, longest});
    const float slack = std::ldexp(magnitude, -18);
    const Vec2 grow{half.x + slack, half.y + slack};
    Vec2 a = from;
    for (int piece = 1; piece <= pieces; ++piece) {
        const float end = piece == pieces ? 1.0f : float(piece) / float(pieces);
        const Vec2 b = piece == pieces ? to : from + delta * end;
        const Box region{Vec2{std::min(a.x, b.x), std::min(a.y, b.y)} - grow,
                         Vec2{std::max(a.x, b.x), std::max(a.y, b.y)} + grow};
        inGrid(region, visit);
        if (stop(end))
            return;
        a = b;
    }
}

} // namespace jostle
