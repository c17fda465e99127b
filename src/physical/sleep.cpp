// Sleep: islands of bodies at rest fall asleep together, and wake together when one of
// them is disturbed or an awake body comes near.
#include "sleep.hpp"

#include "step_context.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace jostle {

namespace {

/// At rest: slower than this many half extents (the smaller) per second...
constexpr float kRestingSpeed = 0.05f;
/// ... for this long, with all the island, to fall asleep.
constexpr float kTimeToSleep = 0.5f;

/// The island each body belongs to: a union-find over slots, whose root is the island's
/// earliest-created body.
class Islands {
public:
    Islands(const WorldState& world, std::vector<std::uint32_t>& parent)
        : world_(world), parent_(parent) {
        parent_.resize(world.slots.size());
        for (std::uint32_t slot : world.movingSlots)
            parent_[slot] = slot;
    }
    std::uint32_t find(std::uint32_t s) {
        while (parent_[s] != s)
            s = parent_[s] = parent_[parent_[s]];
        return s;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        std::uint32_t ra = find(a), rb = find(b);
        if (ra == rb)
            return;
        if (world_.createdBefore(rb, ra))
            std::swap(ra, rb);
        parent_[rb] = ra;
    }

private:
    const WorldState& world_;
    std::vector<std::uint32_t>& parent_;
};

/// How long each body has been at rest.
void updateRestTimes(StepContext& step, Islands& islands) {
    WorldState& w = step.world;
    const auto moving = std::uint32_t(w.movingSlots.size());
    w.tasks->forEachBlock(moving, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const std::uint32_t slot = w.movingSlots[k];
            Body& body = w.slots[slot];
            if (!body.isDynamic() || !w.isLive(slot))
                continue;
            body.sleepTime =
                length(body.velocity) < restingSpeed(body) ? body.sleepTime + step.dt : 0.0f;
        }
    });
    for (const Contact& c : step.contacts) {
        const std::uint32_t slotA = step.bodies[c.ia].slot, slotB = step.bodies[c.ib].slot;
        Body& a = w.slots[slotA];
        Body& b = w.slots[slotB];
        // Position correction has not finished with the pair: not at rest, however slowly
        // it moves them. Asleep, they would keep that overlap until woken.
        if (step.beyondSlop(c)) {
            a.sleepTime = 0.0f;
            b.sleepTime = 0.0f;
        }
        if (a.isDynamic() && b.isDynamic()) {
            islands.join(slotA, slotB);
        } else {
            const Body& other = a.isDynamic() ? b : a;
            if (other.type == BodyType::Kinematic &&
                (other.velocity.x != 0.0f || other.velocity.y != 0.0f))
                (a.isDynamic() ? a : b).sleepTime = 0.0f;
        }
    }
}

/// A free island of the world's list.
std::uint32_t newIsland(WorldState& w) {
    if (w.freeIslands.empty()) {
        w.islands.emplace_back();
        return std::uint32_t(w.islands.size() - 1);
    }
    const std::uint32_t island = w.freeIslands.back();
    w.freeIslands.pop_back();
    return island;
}

} // namespace

float restingSpeed(const Body& body) {
    return kRestingSpeed * std::min(body.half.x, body.half.y);
}

void fallAsleep(StepContext& step) {
    WorldState& w = step.world;
    if (!w.def.sleeping)
        return;
    SleepScratch& s = step.scratch.sleep;
    Islands islands(w, s.parent);
    updateRestTimes(step, islands);
    // The shortest rest of each island decides.
    s.islandTime.assign(w.slots.size(), INFINITY);
    for (std::uint32_t slot : w.movingSlots) {
        const Body& body = w.slots[slot];
        if (body.isDynamic() && w.isLive(slot)) {
            float& time = s.islandTime[islands.find(slot)];
            time = std::min(time, body.sleepTime);
        }
    }
    s.islandOf.assign(w.slots.size(), UINT32_MAX);
    for (std::uint32_t slot : w.movingSlots) {
        Body& body = w.slots[slot];
        const std::uint32_t root = islands.find(slot);
        if (!body.isDynamic() || !w.isLive(slot) || s.islandTime[root] < kTimeToSleep)
            continue;
        std::uint32_t& island = s.islandOf[root];
        if (island == UINT32_MAX)
            island = newIsland(w);
        w.islands[island].push_back(slot);
        body.asleep = true;
        body.island = island;
        body.velocity = {};
        w.restingDirty = true;
    }
}

// --- Waking ------------------------------------------------------------------------------

void wakeIsland(WorldState& world, std::uint32_t slot) {
    if (!world.slots[slot].asleep)
        return;
    const std::uint32_t island = world.slots[slot].island;
    for (std::uint32_t member : world.islands[island]) {
        Body& body = world.slots[member];
        body.asleep = false;
        body.sleepTime = 0.0f;
    }
    world.islands[island].clear();
    world.freeIslands.push_back(island);
    world.restingDirty = true;
}

void wakeTouching(WorldState& world, const Box& box) {
    // Nobody asleep, nobody to wake: and no need to bring the resting grid up to date,
    // which would make creating n static bodies cost n rebuilds.
    if (world.islands.size() == world.freeIslands.size())
        return;
    refreshRestingGrid(world);
    std::vector<std::uint32_t> sleepers;
    world.restingGrid.query(box, [&](std::uint32_t i) {
        if (world.slots[world.restingSlots[i]].asleep)
            sleepers.push_back(world.restingSlots[i]);
    });
    for (std::uint32_t slot : sleepers)
        wakeIsland(world, slot);
}

void disturb(WorldState& world, std::uint32_t slot) {
    ++world.changes;
    Body& body = world.slots[slot];
    body.sleepTime = 0.0f;
    wakeIsland(world, slot);
    if (body.type == BodyType::Static)
        world.restingDirty = true;
    wakeTouching(world, body.box());
}

} // namespace jostle
