// Continuous collision of the physical model. Contacts stop what they foresee: the pairs
// that touch, or will within the step at the speeds it began with. This catches the rest,
// so that nothing passes through a wall however fast it goes, nor is pushed into one by
// the solver (docs/continuous-collision.md).
#include "continuous.hpp"

#include "../one_way.hpp"
#include "../shape_casts.hpp"
#include "contact_of.hpp"
#include "contacts.hpp"
#include "seams.hpp"
#include "solver_layers.hpp"
#include "step_context.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace jostle {

namespace {

/// After this many hits in one step, a body stops where the last one left it.
constexpr int kMaxHits = 4;

/// Whether the solver sent `body` where its contacts did not look: they were made for
/// bodies it could reach moving `before` (this step's velocity, before the solver), and it
/// now moves `after`, further along an axis than its skin allows.
bool movesUnforeseen(const StepContext& step, const Body& body, Vec2 before, Vec2 after) {
    auto beyond = [&](float was, float now, float half) {
        const float unforeseen = was * now < 0.0f ? std::abs(now) : std::abs(now) - std::abs(was);
        return unforeseen * step.dt > step.skinOf(half, half);
    };
    return beyond(before.x, after.x, body.half.x) || beyond(before.y, after.y, body.half.y);
}

/// The sweep of `body` by `motion` (relative to `obstacle`), where one of the two is not a
/// sharp box: the body's centre against the obstacle's outline, through the faces that
/// stop it (a static obstacle's faces that the level covers do not, a segment stops only
/// with its slope, a one-way box only with its blocking face).
std::optional<FirstHit> sweepShaped(const StepContext& step, std::uint32_t slot,
                                    std::uint32_t other, Vec2 motion) {
    const WorldState& w = step.world;
    const Body& body = w.slots[slot];
    const Body& obstacle = w.slots[other];
    const Shape& bodyShape = w.shapes[slot];
    const Shape& obstacleShape = w.shapes[other];
    const float radius = body.shape == ShapeKind::Round ? bodyShape.radius : 0.0f;
    const std::uint8_t stopping = pushingFaces(w, obstacle, body) & blockingFaces(obstacle);
    const CastOutline cast =
        castOutlineOf(body.half, radius, obstacle.half, obstacleShape, stopping,
                      std::max(2.0f * step.options.slop, kMinimumSkin));
    const std::optional<ShapeHit> hit = sweepShape(cast, body.position - obstacle.position, motion);
    if (!hit)
        return std::nullopt;
    const float size = std::min(reachOf(body.half, bodyShape, hit->normal),
                                reachOf(obstacle.half, obstacleShape, hit->normal));
    return FirstHit{Hit{hit->time, hit->normal, hit->axis}, other, hit->extent, size};
}

/// The first body `slot` meets moving by `motion` this step: static and kinematic ones,
/// and dynamic ones too if it is a bullet.
std::optional<FirstHit> firstHit(const StepContext& step, std::uint32_t slot, Vec2 motion) {
    const WorldState& w = step.world;
    const Body& body = w.slots[slot];
    const Box swept = sweptBox(body.position, body.half, motion);
    std::optional<FirstHit> first;
    auto consider = [&](std::uint32_t other) {
        const Body& obstacle = w.slots[other];
        if (other == slot || !w.isLive(other))
            return;
        if ((obstacle.isDynamic() && !body.bullet) || obstacle.sensor || body.sensor ||
            !canCollide(body, obstacle))
            return;
        const Vec2 relative = motion - obstacle.velocity * step.dt;
        std::optional<FirstHit> found;
        if (body.isBox() && obstacle.isBox()) {
            const Vec2 skin{step.skinOf(body.half.x, obstacle.half.x),
                            step.skinOf(body.half.y, obstacle.half.y)};
            const std::optional<Hit> hit = sweepBox(body.position - obstacle.position,
                                                    body.half + obstacle.half, relative, skin);
            if (hit)
                found = FirstHit{*hit, other};
        } else {
            found = sweepShaped(step, slot, other, relative);
        }
        // Only what the body runs into: a kinematic body coming at it from behind is the
        // contacts' business (they push it), not a reason to stop it.
        if (!found || dot(motion, found->hit.normal) >= 0.0f)
            return;
        // The sweep finds only what the body enters from outside; a segment lets through
        // what drops through it on purpose, as a one-way platform does.
        if (!stops(obstacle, found->hit.normal, true, body.dropThroughTime))
            return;
        // Nor does what the pre-solve callback let the body through in this step.
        if (isVetoed(step, slot, other))
            return;
        if (!first || found->hit.time < first->hit.time)
            first = found;
    };
    w.restingGrid.query(swept, [&](std::uint32_t i) {
        if (w.slots[w.restingSlots[i]].type == BodyType::Static)
            consider(w.restingSlots[i]);
    });
    w.movingGrid.query(swept, [&](std::uint32_t i) { consider(w.movingSlots[i]); });
    return first;
}

} // namespace

void addFoundContact(StepContext& step, std::uint32_t slot, const FirstHit& first, float speed) {
    const std::uint32_t obstacle = first.slot;
    const Vec2 normal = first.hit.normal;
    WorldState& w = step.world;
    ContinuousScratch& s = step.scratch.continuous;
    const bool bodyFirst = w.createdBefore(slot, obstacle);
    const std::uint32_t slotA = bodyFirst ? slot : obstacle;
    const std::uint32_t slotB = bodyFirst ? obstacle : slot;
    const std::uint32_t ia = step.solverBodyOf(slotA), ib = step.solverBodyOf(slotB);
    if (haveContact(step, ia, ib))
        return;
    // Found by an earlier hit of this sweep, or, for a dynamic obstacle (bullets), by its
    // own sweep: the rest of the list holds other bodies' hits.
    const bool dynamicObstacle = w.slots[obstacle].isDynamic();
    for (std::size_t k = dynamicObstacle ? 0 : s.sweepStart; k < s.found.size(); ++k)
        if (s.found[k].ia == ia && s.found[k].ib == ib)
            return;
    const Body& a = w.slots[slotA];
    const Body& b = w.slots[slotB];
    const Vec2 fromB = bodyFirst ? normal : -normal;
    Contact c = a.isBox() && b.isBox()
                    ? contactOf(step, a, b, fromB)
                    : contactAlongShape(step, a, b, fromB, first.extent, first.size);
    c.ia = ia;
    c.ib = ib;
    c.targetSpeed = 0.0f;
    c.approachSpeed = speed;
    s.found.push_back(c);
}

namespace {

/// Sweeps the body along `motion`; at the first hit, moves it there and takes away its
/// velocity into the obstacle, then sweeps again along what is left of its velocity
/// (sliding along a floor into a wall, say). The step's own integration then moves it by
/// that velocity from there, a path just swept clear. True if it hit something.
bool sweep(StepContext& step, std::uint32_t slot, Vec2 motion) {
    step.scratch.continuous.sweepStart = step.scratch.continuous.found.size();
    Body& body = step.world.slots[slot];
    for (int hits = 0; hits < kMaxHits; ++hits) {
        const std::optional<FirstHit> first = firstHit(step, slot, motion);
        if (!first)
            return hits > 0;
        const Hit& hit = first->hit;
        const std::uint32_t hitSlot = first->slot;
        // Where it touches the obstacle as the obstacle is now: the integration that
        // follows moves both by their velocities, which the hit has made equal along the
        // normal.
        const Body& obstacle = step.world.slots[hitSlot];
        body.position += (motion - obstacle.velocity * step.dt) * hit.time;
        const float into = dot(body.velocity - obstacle.velocity, hit.normal);
        // It stops going into the obstacle, and bounces off it as the impacts stage would.
        const float bounce =
            -into > step.restitutionThreshold() ? std::max(body.bounce, obstacle.bounce) : 0.0f;
        if (into < 0.0f)
            body.velocity -= hit.normal * ((1.0f + bounce) * into);
        const std::size_t found = step.scratch.continuous.found.size();
        addFoundContact(step, slot, *first, std::max(0.0f, -into));
        if (into < 0.0f && step.scratch.continuous.found.size() > found)
            step.scratch.continuous.found.back().collisionImpulse =
                -(1.0f + bounce) * into / body.invMass;
        motion = body.velocity * step.dt;
    }
    if (firstHit(step, slot, motion))
        body.velocity = {};
    return true;
}

/// When in the step the impacts last changed the path of the body in `slot` (0: never).
float changedAt(const StepContext& step, std::uint32_t slot) {
    const std::vector<std::uint32_t>& index = step.scratch.solverIndex;
    const std::vector<ImpactsScratch::OfBody>& of = step.scratch.impacts.ofBody;
    const std::uint32_t solver = slot < index.size() ? index[slot] : StepContext::kNoSolverBody;
    return solver < of.size() ? std::max(of[solver].changedAt.x, of[solver].changedAt.y) : 0.0f;
}

} // namespace

void sweepFastBodies(StepContext& step) {
    WorldState& w = step.world;
    ContinuousScratch& s = step.scratch.continuous;
    s.unforeseen.assign(w.slots.size(), 0);
    const auto solverBodies = std::uint32_t(step.bodies.size());
    w.tasks->forEachBlock(solverBodies, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const SolverBody& body = step.bodies[k];
            Vec2& velocity = w.slots[body.slot].velocity;
            const Vec2 solved{body.velocity[0], body.velocity[1]};
            if (body.invMass > 0.0f && movesUnforeseen(step, w.slots[body.slot], velocity, solved))
                s.unforeseen[body.slot] = 1;
            velocity = solved;
        }
    });
    // Which bodies hit something: looked for in blocks, since a body that is no bullet
    // meets only static and kinematic bodies, which no sweep moves. The sweeps themselves
    // run in order, a bullet meeting what the sweeps before it moved.
    const auto moving = std::uint32_t(w.movingSlots.size());
    s.toSweep.reset(w.tasks->blocksOf(moving, kBodiesPerBlock));
    w.tasks->forEachBlock(moving, kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const std::uint32_t slot = w.movingSlots[k];
            const Body& body = w.slots[slot];
            if (!body.isDynamic() || !w.isLive(slot))
                continue;
            const Vec2 motion = body.velocity * step.dt;
            const float size = std::min(body.half.x, body.half.y);
            if (std::abs(motion.x) <= size && std::abs(motion.y) <= size && !s.unforeseen[slot])
                continue;
            if (body.bullet || changedAt(step, slot) > 0.0f || firstHit(step, slot, motion))
                s.toSweep[block.index].push_back(slot);
        }
    });
    s.toSweep.forEachInOrder([&](std::uint32_t slot) {
        // A body the impacts moved is where its velocity took it from its last collision:
        // swept from there, for the rest of the step.
        const float since = changedAt(step, slot);
        Body& body = w.slots[slot];
        const Vec2 before = body.position;
        body.position += body.velocity * since;
        if (!sweep(step, slot, body.velocity * (step.dt - since)))
            body.position = before;
    });
    // What the sweeps met joins the step's contacts, for position correction and events.
    if (!s.found.empty()) {
        step.contacts.insert(step.contacts.end(), s.found.begin(), s.found.end());
        s.found.clear();
        orderBySupport(step);
        layerContacts(step);
    }
}

} // namespace jostle
