// The world's storage, shared by World (the API) and the solvers.
#pragma once

#include "body_state.hpp"
#include "box_grid.hpp"
#include "broadphase.hpp"
#include "creation_order.hpp"
#include "events.hpp"
#include "geometry.hpp"
#include "handles.hpp"
#include "jostle/world.hpp"
#include "physical/contact_cache.hpp"
#include "query_index.hpp"
#include "room.hpp"
#include "shapes.hpp"
#include "tasks.hpp"
#include "tilemap.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace jostle {

struct PhysicalScratch;

struct WorldState {
    WorldState();
    ~WorldState(); // where PhysicalScratch is whole (world_state.cpp)
    WorldState(const WorldState&) = delete;
    WorldState& operator=(const WorldState&) = delete;

    WorldDef def;
    PreSolveFn preSolve;
    /// Asks the pre-solve callback about `c`. What it throws is kept, and the step goes on
    /// as if it had answered true, `c` as it was given, from then on: step() throws it once
    /// the step is whole, so that a world is never left half stepped.
    bool askPreSolve(Collision& c);
    /// What the pre-solve callback threw during this step, if anything.
    std::exception_ptr preSolveThrew;

    /// This world's serial number, unique in the process (handles.hpp): every BodyId and
    /// TileMapId it gives carries it. Handles are the only thing it touches: nothing in
    /// the simulation depends on it.
    std::uint32_t serial = 0;

    /// Bodies by slot index; a BodyId's index points here.
    std::vector<Body> slots;
    /// Slots free for reuse.
    std::vector<std::uint32_t> freeSlots;
    /// Live bodies in creation order: the order every solver processes them in.
    CreationOrder order;

    /// True while step() runs. Slots freed meanwhile wait in pendingFree, so that no
    /// slot a solver still refers to is reused before the step ends.
    bool stepping = false;
    std::vector<std::uint32_t> pendingFree;
    /// True while move() walks the world: its filter may read the world, not change it.
    bool moveUnderWay = false;
    /// True while debugDraw walks the world (a const function): its DebugDraw may read the
    /// world, not change it.
    mutable bool drawing = false;

    /// Last step's contacts of the physical model, by pairKey. Only looked up, never
    /// iterated, so its hash order cannot leak into the results.
    ContactCache contactCache;
    /// Buffers of the physical step and of the broadphase, kept from step to step.
    /// (physical/scratch.hpp: only the stages see it, so that a stage's buffers are theirs.)
    std::unique_ptr<PhysicalScratch> physical;
    std::vector<BodyPair> pairs;
    std::vector<Box> boundsScratch;
    /// Pairs each moving body has taken of its budget (PhysicalOptions::maxContactsPerBody),
    /// by moving-grid index, and how many pairs the last step left out for want of it.
    std::vector<std::uint32_t> pairsTaken;
    std::uint64_t pairsLeftOut = 0;

    /// When each slot's body was created, as a count of the bodies created before it in
    /// this world: "created before" is the order every solver, event list and query
    /// result follows. Set by createBody, never renumbered.
    std::vector<std::uint64_t> created;
    std::uint64_t bodiesCreated = 0;
    /// Each slot's shape beyond its box (radius, slope), read only when Body::shape says
    /// it is not a box.
    std::vector<Shape> shapes;
    /// How many live bodies are not sharp boxes: the classic model refuses them.
    std::uint32_t shapedBodies = 0;
    /// Each slot's settings as the user gave them, which no step reads.
    std::vector<KeptAsGiven> asGiven;
    /// How many live bodies may snap to the ground (Body::maySnap): the step looks for
    /// ground under them.
    std::uint32_t snappingBodies = 0;
    /// How many live bodies are conveyors (a surfaceVelocity): with none, contacts do not
    /// look at surface velocities.
    std::uint32_t conveyors = 0;
    /// How many live bodies slip round corners (KeptAsGiven::slipsRoundCorners).
    std::uint32_t cornerBodies = 0;
    /// Makes every table indexed by body slot able to hold `n` slots without growing again
    /// (createBody grows them together, by room.hpp's slotRoomAfter).
    void reserveSlots(std::size_t n) {
        slots.reserve(n);
        created.reserve(n);
        shapes.reserve(n);
        asGiven.reserve(n);
        events.touching.reserve(n);
        order.reserve(n);
    }
    /// Counts the body in `slot` in (`in`) or out of each count above that it belongs to:
    /// when it is made or destroyed, and around a change to its settings.
    void count(std::uint32_t slot, bool in) {
        auto add = [in](std::uint32_t& bodies, bool belongs) {
            if (belongs)
                bodies = in ? bodies + 1 : bodies - 1;
        };
        const Body& body = slots[slot];
        add(shapedBodies, !body.isBox());
        add(snappingBodies, body.maySnap());
        add(conveyors, body.surfaceVelocity != Vec2{});
        add(cornerBodies, asGiven[slot].slipsRoundCorners());
    }

    /// The broadphase of bodies at rest: static and sleeping bodies, rebuilt only when
    /// one of them changes (restingDirty), so a still level costs nothing per step.
    BoxGrid restingGrid;
    std::vector<std::uint32_t> restingSlots; ///< grid index -> slot
    bool restingDirty = true;
    /// The broadphase of moving bodies (awake dynamic and kinematic), rebuilt every step.
    BoxGrid movingGrid;
    std::vector<std::uint32_t> movingSlots;  ///< grid index -> slot, in creation order
    std::vector<std::uint8_t> movingDynamic; ///< grid index -> is the body dynamic
    std::vector<std::uint32_t> blockStarts;  ///< the broadphase's scratch: where each block writes
    /// What each block of the pair search found (broadphase.cpp): pairs of moving grid
    /// indices (none from a block that found more than its budget: a pile, searched again
    /// in order), and resting bodies met by moving ones with the pairs left out.
    PerBlock<std::pair<std::uint32_t, std::uint32_t>> movingFound;
    std::vector<std::uint8_t> movingPiled; ///< by block: found too many to keep
    struct RestingFind {
        std::uint32_t moving; ///< moving grid index
        std::uint32_t slot;   ///< the resting body
        bool wake;            ///< asleep: its island wakes
    };
    PerBlock<RestingFind> restingFound;
    std::vector<std::uint32_t> restingLeftOut; ///< by block

    /// Where the last step's time went (World::profile).
    StepProfile profile;

    /// The threads a step may share its work with (jostle/tasks.hpp).
    std::unique_ptr<TaskRunner> tasks;
    /// keepInsideTheWorld's scratch: whether each block of bodies moved a sleeping one.
    std::vector<std::uint8_t> movedAsleepByBlock;

    /// Forces applied since the last step (World::applyForce), in the order given.
    std::vector<std::pair<BodyId, Vec2>> forces;

    /// Counts changes made to bodies through the API (see disturb), so that a step can
    /// tell that a callback moved something under its feet.
    std::uint64_t changes = 0;

    /// Sleeping islands: the bodies that fell asleep together and wake together.
    std::vector<std::vector<std::uint32_t>> islands;
    std::vector<std::uint32_t> freeIslands;

    /// What the last step reported (docs/events.md).
    StepEvents events;

    /// The tile maps and the bodies they are made of (jostle/tilemap.hpp).
    TileMaps tileMaps;

    /// What queries keep between calls (jostle/query.hpp); mutable: queries take a
    /// const World.
    mutable QueryIndex queries;

    /// The handle of the body in `slot`.
    BodyId idOf(std::uint32_t slot) const { return {slot, slots[slot].generation, serial}; }
    /// The handle of the body `ref` names.
    BodyId idFor(SlotRef ref) const { return {ref.index, ref.generation, serial}; }
    SlotRef refOf(std::uint32_t slot) const { return {slot, slots[slot].generation}; }
    /// True if `id` names a live body of this world.
    bool isCurrent(BodyId id) const { return jostle::isCurrent(slots, serial, id); }
    /// True if `ref` still names a live body (its slot not reused since).
    bool isCurrent(SlotRef ref) const {
        return jostle::isCurrent(slots, ref.index, ref.generation);
    }
    bool isLive(std::uint32_t slot) const { return slots[slot].alive; }
    bool isResting(const Body& body) const { return body.type == BodyType::Static || body.asleep; }
    /// The live bodies that are not static, in creation order: what the step's loops over
    /// bodies that move walk, so that a level's static boxes cost them nothing. Made again
    /// from order.live() when bodies have come, gone or changed type since. For the step,
    /// on its calling thread (the list is rebuilt in place).
    std::span<const BodyId> movers() const {
        if (moversAt_ != order.changes() || moversTypesAt_ != typeChanges)
            listMovers();
        return movers_;
    }
    /// One more each time a body changes type (World::setType).
    std::uint64_t typeChanges = 0;
    /// Calls visit(body, block) for every body of movers(), in blocks of kBodiesPerBlock in
    /// creation order on the world's workers: visit may write only `body`, and what is its
    /// block's own (by block.index).
    template <class Visit> void forEachMover(Visit&& visit) {
        const std::span<const BodyId> moving = movers();
        tasks->forEachBlock(std::uint32_t(moving.size()), kBodiesPerBlock, [&](Block block) {
            for (std::uint32_t k = block.begin; k < block.end; ++k)
                visit(slots[moving[k].index], block);
        });
    }
    /// Calls visit(other, normal, record) for each body that `id` touched at the end of the
    /// last step and that is still there; `normal` points from `other` towards `id`.
    template <class Visit> void forEachContactOf(BodyId id, Visit&& visit) const {
        const SlotRef self{id.index, id.generation};
        events.forEachTouchOf(id.index, [&](const TouchRecord& r) {
            const bool isA = r.a == self;
            if ((isA || r.b == self) && isCurrent(isA ? r.b : r.a))
                visit(idFor(isA ? r.b : r.a), isA ? r.normal : -r.normal, r);
        });
    }
    /// Whether the body in slot `a` was created before the one in slot `b`.
    bool createdBefore(std::uint32_t a, std::uint32_t b) const { return created[a] < created[b]; }

private:
    void listMovers() const {
        auto moves = [&](BodyId id) { return slots[id.index].type != BodyType::Static; };
        const std::span<const BodyId> live = order.live();
        movers_.clear();
        makeRoom(movers_, std::size_t(std::count_if(live.begin(), live.end(), moves)));
        for (BodyId id : live)
            if (moves(id))
                movers_.push_back(id);
        moversAt_ = order.changes();
        moversTypesAt_ = typeChanges;
    }
    mutable std::vector<BodyId> movers_;
    mutable std::uint64_t moversAt_ = ~std::uint64_t{0}, moversTypesAt_ = ~std::uint64_t{0};
};

} // namespace jostle
