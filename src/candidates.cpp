// The candidates of a query, and the query index they keep up to date.
#include "candidates.hpp"

#include "broadphase.hpp"
#include "world_state.hpp"

#include <span>

namespace jostle {

namespace {

/// Pieces of a long ray or cast are this many typical bodies long.
constexpr float kPieceBodies = 4.0f;
/// The typical body size is the median of a sample of at most this many bodies.
constexpr std::size_t kSizeSample = 63;

bool orderChanged(std::span<const BodyId> order, const QueryIndex& index) {
    return !index.built || index.bodyCount != order.size() ||
           (!order.empty() && index.lastBody != order.back());
}

void rebuild(const WorldState& w, std::span<const BodyId> order, QueryIndex& index) {
    index.mobile.clear();
    for (BodyId id : order)
        if (w.slots[id.index].type != BodyType::Static)
            index.mobile.push_back(id.index);
    // The median, not the mean: one floor as wide as the level must not make every
    // piece as long as the level. A sample is enough for a length that only tunes speed.
    index.sizes.clear();
    const std::size_t stride = order.size() / kSizeSample + 1;
    for (std::size_t r = 0; r < order.size(); r += stride) {
        const Body& body = w.slots[order[r].index];
        index.sizes.push_back(2.0f * std::max(body.half.x, body.half.y));
    }
    float typical = 1.0f;
    if (!index.sizes.empty()) {
        auto middle = index.sizes.begin() + std::ptrdiff_t(index.sizes.size() / 2);
        std::nth_element(index.sizes.begin(), middle, index.sizes.end());
        typical = *middle;
    }
    index.pieceLength = kPieceBodies * typical;
    index.bodyCount = order.size();
    index.lastBody = order.empty() ? BodyId{} : order.back();
    index.built = true;
}

} // namespace

Candidates::Candidates(const WorldState& world) : w_(world), index_(world.queries) {
    const std::span<const BodyId> order = w_.order.live();
    std::lock_guard<std::mutex> lock(index_.mutex);
    if (orderChanged(order, index_))
        rebuild(w_, order, index_);
    // Never during a step: the step may be using the grid (a query from a callback).
    // Outside a step, bringing it up to date is what the next step would do first.
    // The state is not const, only the access to it (WorldAccess).
    if (w_.restingDirty && !w_.stepping)
        refreshRestingGrid(const_cast<WorldState&>(w_));
    gridUsable_ = !w_.restingDirty;
    if (!gridUsable_)
        return;
    listAwake();
    // Every body is in the grid (static or asleep) or awake. If some are neither, a static
    // body was made dynamic or kinematic since the index was built.
    if (w_.restingSlots.size() + awake_.size() != order.size()) {
        rebuild(w_, order, index_);
        listAwake();
    }
}

void Candidates::listAwake() {
    awake_.clear();
    for (std::uint32_t slot : index_.mobile)
        if (!w_.isResting(w_.slots[slot]))
            awake_.push_back(slot);
}

} // namespace jostle
