// The broadphase: the grid of resting bodies, and the pairs of the physical step.
#include "broadphase.hpp"

#include "physical/sleep.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace jostle {

void refreshRestingGrid(WorldState& world) {
    if (!world.restingDirty)
        return;
    world.restingDirty = false;
    world.restingSlots.clear();
    std::vector<Box>& boxes = world.boundsScratch;
    boxes.clear();
    for (BodyId id : world.order.live()) {
        const Body& body = world.slots[id.index];
        if (world.isResting(body)) {
            world.restingSlots.push_back(id.index);
            boxes.push_back(body.box());
        }
    }
    world.restingGrid.build(boxes, world.tasks.get());
}

namespace {

/// The box a body may sweep during the step: grown by its motion along each axis.
Box reach(const Body& body, float dt) {
    const Vec2 motion{std::abs(body.velocity.x) * dt, std::abs(body.velocity.y) * dt};
    return {body.position - body.half - motion, body.position + body.half + motion};
}

/// Grid items (BoxGrid::pairItems) and moving bodies per block of the pair search.
constexpr std::uint32_t kItemsPerBlock = 1024;
/// Grid items searched between two looks at whether a block has found too many pairs.
constexpr std::uint32_t kItemsPerCheck = 32;

/// Collects pairs, or, if it meets sleeping bodies, the islands to wake first. The grids
/// are searched in blocks, on any thread, each block keeping what it found; the budget is
/// then spent in block order on the calling thread, as one pass in order would spend it.
class PairFinder {
public:
    PairFinder(WorldState& world, float dt, std::vector<BodyPair>& pairs)
        : w_(world), dt_(dt), pairs_(pairs),
          budget_(static_cast<std::uint32_t>(world.def.physical.maxContactsPerBody)) {}

    /// False if sleeping bodies were found in the way and woken: run again.
    bool run() {
        pairs_.clear();
        w_.pairsLeftOut = 0;
        refreshRestingGrid(w_);
        buildMovingGrid();
        findMovingPairs();
        findRestingPairs();
        std::vector<std::uint32_t> toWake;
        w_.restingFound.forEachInOrder([&](const Found& found) {
            if (found.wake)
                toWake.push_back(found.slot);
            else
                add(w_.movingSlots[found.moving], found.slot);
        });
        for (std::uint32_t leftOut : w_.restingLeftOut)
            w_.pairsLeftOut += leftOut;
        for (std::uint32_t slot : toWake)
            wakeIsland(w_, slot);
        return toWake.empty();
    }

private:
    using Found = WorldState::RestingFind;

    /// The moving bodies, in creation order, and the grid of the boxes they may sweep:
    /// each block of bodies that are not static counts its moving (awake) ones, then
    /// writes them at its place.
    void buildMovingGrid() {
        const std::span<const BodyId> movers = w_.movers();
        const auto count = std::uint32_t(movers.size());
        std::vector<std::uint32_t>& starts = w_.blockStarts;
        starts.assign(w_.tasks->blocksOf(count, kBodiesPerBlock) + 1, 0);
        w_.tasks->forEachBlock(count, kBodiesPerBlock, [&](Block block) {
            std::uint32_t moving = 0;
            for (std::uint32_t k = block.begin; k < block.end; ++k)
                moving += w_.isResting(w_.slots[movers[k].index]) ? 0u : 1u;
            starts[block.index + 1] = moving;
        });
        for (std::size_t b = 1; b < starts.size(); ++b)
            starts[b] += starts[b - 1];
        w_.movingSlots.resize(starts.back());
        w_.movingDynamic.resize(starts.back());
        std::vector<Box>& bounds = w_.boundsScratch;
        bounds.resize(starts.back());
        w_.tasks->forEachBlock(count, kBodiesPerBlock, [&](Block block) {
            std::uint32_t at = starts[block.index];
            for (std::uint32_t k = block.begin; k < block.end; ++k) {
                const Body& body = w_.slots[movers[k].index];
                if (w_.isResting(body))
                    continue;
                w_.movingSlots[at] = movers[k].index;
                w_.movingDynamic[at] = body.isDynamic();
                bounds[at] = reach(body, dt_);
                ++at;
            }
        });
        w_.movingGrid.build(bounds, w_.tasks.get());
    }

    /// Pairs of moving bodies: found in blocks, then kept within the budget in order. A
    /// block keeps at most a budget of pairs for each of its grid items: one that finds
    /// more holds a pile, and keeping them all would take memory quadratic in the pile.
    /// It gives up, and its items are searched again in order, each pair spent as found.
    void findMovingPairs() {
        const BoxGrid& grid = w_.movingGrid;
        PerBlock<std::pair<std::uint32_t, std::uint32_t>>& found = w_.movingFound;
        const std::uint32_t blocks = w_.tasks->blocksOf(grid.pairItems(), kItemsPerBlock);
        found.reset(blocks);
        w_.movingPiled.assign(blocks, 0);
        w_.tasks->forEachBlock(grid.pairItems(), kItemsPerBlock, [&](Block block) {
            std::vector<std::pair<std::uint32_t, std::uint32_t>>& mine = found[block.index];
            const std::size_t most = std::size_t(block.end - block.begin) * budget_;
            for (std::uint32_t k = block.begin; k < block.end && mine.size() <= most;
                 k += kItemsPerCheck)
                grid.forEachPairOf(k, std::min(block.end, k + kItemsPerCheck),
                                   [&](std::uint32_t i, std::uint32_t j) {
                                       if (mine.size() <= most && isPair(i, j))
                                           mine.emplace_back(i, j);
                                   });
            if (mine.size() > most) {
                mine.clear();
                w_.movingPiled[block.index] = 1;
            }
        });
        // The moving grid holds its bodies in creation order: the smaller index is `a`.
        w_.pairsTaken.assign(w_.movingSlots.size(), 0);
        const std::uint32_t block = w_.tasks->blockSize(kItemsPerBlock);
        for (std::uint32_t b = 0; b < blocks; ++b) {
            if (!w_.movingPiled[b]) {
                for (const auto& [i, j] : found[b])
                    spend(i, j);
                continue;
            }
            const std::uint32_t begin = b * block;
            grid.forEachPairOf(begin, std::min(grid.pairItems(), begin + block),
                               [&](std::uint32_t i, std::uint32_t j) {
                                   if (isPair(i, j))
                                       spend(i, j);
                               });
        }
    }

    /// Whether the moving bodies i and j (grid indices) make a pair worth a contact.
    bool isPair(std::uint32_t i, std::uint32_t j) const {
        return w_.movingDynamic[i] || w_.movingDynamic[j] ||
               oneIsSensor(w_.movingSlots[i], w_.movingSlots[j]);
    }

    /// Keeps the pair of moving bodies i and j if the budget allows.
    void spend(std::uint32_t i, std::uint32_t j) {
        if (withinBudget(i, j))
            pairs_.push_back({w_.movingSlots[std::min(i, j)], w_.movingSlots[std::max(i, j)]});
        else
            ++w_.pairsLeftOut;
    }

    /// Moving bodies against resting ones. Resting bodies have a budget of their own (a
    /// crowd never crowds out the floor), each moving body's its own: blocks of moving
    /// bodies spend it themselves. A moving body wakes at most a budget of sleepers a
    /// round (run() goes round again while any woke).
    void findRestingPairs() {
        const auto moving = std::uint32_t(w_.movingSlots.size());
        PerBlock<Found>& found = w_.restingFound;
        const std::uint32_t blocks = w_.tasks->blocksOf(moving, kItemsPerBlock);
        found.reset(blocks);
        w_.restingLeftOut.assign(blocks, 0);
        w_.tasks->forEachBlock(moving, kItemsPerBlock, [&](Block block) {
            std::vector<Found>& mine = found[block.index];
            std::uint32_t leftOut = 0;
            for (std::uint32_t i = block.begin; i < block.end; ++i) {
                const std::uint32_t a = w_.movingSlots[i];
                const Body& body = w_.slots[a];
                // A kinematic body at rest wakes nobody, and meets only sensors (a
                // character moved by setPosition picks up a coin).
                const bool moves = body.velocity.x != 0.0f || body.velocity.y != 0.0f;
                std::uint32_t taken = 0, woken = 0;
                w_.restingGrid.query(w_.movingGrid.bounds(i), [&](std::uint32_t k) {
                    const std::uint32_t b = w_.restingSlots[k];
                    if (w_.slots[b].asleep) {
                        if ((body.isDynamic() || moves) && woken < budget_) {
                            mine.push_back({i, b, true});
                            ++woken;
                        }
                    } else if (body.isDynamic() || oneIsSensor(a, b)) {
                        if (taken < budget_) {
                            mine.push_back({i, b, false});
                            ++taken;
                        } else {
                            ++leftOut;
                        }
                    }
                });
            }
            w_.restingLeftOut[block.index] = leftOut;
        });
    }

    /// Whether the moving bodies i and j may have one more pair: a pair counts against
    /// each dynamic body in it (against a kinematic one only where no dynamic body is).
    bool withinBudget(std::uint32_t i, std::uint32_t j) {
        std::vector<std::uint32_t>& taken = w_.pairsTaken;
        const bool countI = w_.movingDynamic[i] || !w_.movingDynamic[j];
        const bool countJ = w_.movingDynamic[j] || !w_.movingDynamic[i];
        if ((countI && taken[i] >= budget_) || (countJ && taken[j] >= budget_))
            return false;
        taken[i] += countI ? 1u : 0u;
        taken[j] += countJ ? 1u : 0u;
        return true;
    }

    /// A sensor and a body it may report: sensors see every body that moves.
    bool oneIsSensor(std::uint32_t a, std::uint32_t b) const {
        return w_.slots[a].sensor != w_.slots[b].sensor;
    }

    void add(std::uint32_t a, std::uint32_t b) {
        if (w_.createdBefore(b, a))
            std::swap(a, b);
        pairs_.push_back({a, b});
    }

    WorldState& w_;
    float dt_;
    std::vector<BodyPair>& pairs_;
    std::uint32_t budget_;
};

} // namespace

void findPairs(WorldState& world, float dt, std::vector<BodyPair>& pairs) {
    PairFinder finder(world, dt, pairs);
    // Each round wakes at least one island, and woken bodies stay awake: this ends.
    while (!finder.run()) {
    }
}

} // namespace jostle
