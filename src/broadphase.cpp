// The broadphase: the grid of resting bodies, and the pairs of the physical step.
#include "broadphase.hpp"

#include "physical/sleep.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>

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
    world.restingGrid.build(boxes);
}

namespace {

/// The box a body may sweep during the step: grown by its motion along each axis.
Box reach(const Body& body, float dt) {
    const Vec2 motion{std::abs(body.velocity.x) * dt, std::abs(body.velocity.y) * dt};
    return {body.position - body.half - motion, body.position + body.half + motion};
}

/// Collects pairs, or, if it meets sleeping bodies, the islands to wake first.
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
        std::vector<std::uint32_t> toWake;
        // The moving grid holds its bodies in creation order: the smaller index is `a`.
        std::vector<std::uint32_t>& taken = w_.pairsTaken;
        taken.assign(w_.movingSlots.size(), 0);
        w_.movingGrid.forEachPair([&](std::uint32_t i, std::uint32_t j) {
            const std::uint32_t a = w_.movingSlots[std::min(i, j)];
            const std::uint32_t b = w_.movingSlots[std::max(i, j)];
            if (w_.movingDynamic[i] || w_.movingDynamic[j] || oneIsSensor(a, b)) {
                if (withinBudget(i, j))
                    pairs_.push_back({a, b});
                else
                    ++w_.pairsLeftOut;
            }
        });
        // Resting bodies have a budget of their own: a crowd never crowds out the floor.
        taken.assign(w_.movingSlots.size(), 0);
        for (std::uint32_t i = 0; i < w_.movingSlots.size(); ++i) {
            const std::uint32_t a = w_.movingSlots[i];
            const Body& body = w_.slots[a];
            // A kinematic body at rest wakes nobody, and meets only sensors (a character
            // moved by setPosition picks up a coin).
            const bool moving = body.velocity.x != 0.0f || body.velocity.y != 0.0f;
            w_.restingGrid.query(w_.movingGrid.bounds(i), [&](std::uint32_t k) {
                const std::uint32_t b = w_.restingSlots[k];
                if (w_.slots[b].asleep) {
                    if (body.isDynamic() || moving)
                        toWake.push_back(b);
                } else if (body.isDynamic() || oneIsSensor(a, b)) {
                    if (taken[i] < budget_) {
                        ++taken[i];
                        add(a, b);
                    } else {
                        ++w_.pairsLeftOut;
                    }
                }
            });
        }
        for (std::uint32_t slot : toWake)
            wakeIsland(w_, slot);
        return toWake.empty();
    }

private:
    void buildMovingGrid() {
        w_.movingSlots.clear();
        w_.movingDynamic.clear();
        std::vector<Box>& bounds_ = w_.boundsScratch;
        bounds_.clear();
        for (BodyId id : w_.order.live()) {
            const Body& body = w_.slots[id.index];
            if (!w_.isResting(body)) {
                w_.movingSlots.push_back(id.index);
                w_.movingDynamic.push_back(body.isDynamic());
                bounds_.push_back(reach(body, dt_));
            }
        }
        w_.movingGrid.build(bounds_);
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
