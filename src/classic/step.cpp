// The classic model: the tutorial's update(dt), checkCollision and solveCollision,
// line for line, plus the two options of its "Physics" section (mass, coulomb). One file,
// a little past 400 lines, so that it reads beside the tutorial from top to bottom.
//
// One deliberate difference from the tutorial's code: its response line
//     a.xv = a.xv - px*r + tx*f
// *adds* the fraction f of the tangent velocity, while its text says friction is velocity
// "lost". jostle follows the text: the tangent velocity becomes (1 - f) × t.
#include "step.hpp"

#include "../broadphase.hpp"
#include "../characters.hpp"
#include "../integrate.hpp"
#include "../world_state.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jostle {

namespace {

/// What happened to the body being resolved.
enum class Outcome { Kept, Destroyed };

/// Velocity change of the pair's relative velocity, by the options of the model.
/// p is the normal (penetration) component of the relative velocity, t the tangent one.
Vec2 velocityChange(Vec2 p, Vec2 t, float ps, float r, float f, bool coulomb) {
    const Vec2 normalChange = -(p * r);
    Vec2 tangentChange = -(t * f);
    if (coulomb) {
        // Coulomb's law: the friction impulse is at most friction × the normal impulse.
        const float cap = f * std::abs(ps) * r;
        const float wanted = length(tangentChange);
        if (wanted > cap)
            tangentChange = tangentChange * (cap / wanted);
    }
    return normalChange + tangentChange;
}

class ClassicStep {
public:
    ClassicStep(WorldState& world, float dt) : w_(world), dt_(dt) {}

    void run() {
        w_.events.beginStep(w_);
        // The tutorial keeps two lists, statics and dynamics, in creation order. Static
        // bodies are in the world's resting grid; the kinematic ones, which the dynamic
        // bodies collide with the same way, move first and have a grid of their own.
        for (BodyId id : w_.movers())
            (w_.slots[id.index].isDynamic() ? dynamics_ : kinematics_).push_back(id.index);

        // update velocity vectors
        applyForces(w_, dt_);
        for (std::uint32_t d : dynamics_)
            integrateVelocity(w_.def, w_.slots[d], dt_);
        walkCharacters(w_);

        // Kinematic bodies move by their own velocity before the dynamic ones.
        for (std::uint32_t s : kinematics_) {
            Body& k = w_.slots[s];
            k.position += k.velocity * dt_;
            stopAtTheEdge(k);
        }
        buildGrids();
        reportKinematicVisitors();

        // move dynamic objects, then check and resolve their collisions
        for (std::size_t i = 0; i < dynamics_.size(); ++i) {
            const std::uint32_t a = dynamics_[i];
            if (!w_.isLive(a))
                continue; // destroyed by a callback earlier in this step
            Body& d = w_.slots[a];
            if (w_.def.classic.ccd && sweepMove(a) == Outcome::Destroyed)
                continue;
            if (!w_.def.classic.ccd) {
                d.position += d.velocity * dt_;
                stopAtTheEdge(d);
            }
            if (resolveAgainstStatics(a) == Outcome::Destroyed)
                continue;
            resolveAgainstLaterDynamics(a, i);
        }
    }

private:
    // --- Pruning -------------------------------------------------------------------------
    //
    // The tutorial resolves a body against every static body, then every later dynamic
    // body, in creation order. Pairs whose boxes do not even touch do nothing there, so
    // the broadphase leaves them out, and the rest are visited in the same order: the
    // results are the tutorial's, bit for bit. The only subtlety is that the body moves
    // while it is resolved: candidates are gathered for a region around it, and gathered
    // again (for the bodies not yet visited) whenever it leaves that region.

    void buildGrids() {
        // Static bodies have their own grid in the world, rebuilt only when they change.
        refreshRestingGrid(w_);
        // Kinematic bodies over the step they have just made (where they are now, and
        // for the ccd option's sweeps where they were); dynamic bodies where they start
        // the step, which is where the later ones still are when an earlier one meets
        // them.
        std::vector<Box> kinematic, dynamic;
        for (std::uint32_t s : kinematics_) {
            const Body& k = w_.slots[s];
            const Vec2 back = k.velocity * dt_;
            kinematic.push_back(sweptBox(k.position, k.half, -back));
        }
        kinematicGrid_.build(kinematic);
        dynamicIndex_.assign(w_.slots.size(), 0);
        for (std::uint32_t i = 0; i < dynamics_.size(); ++i) {
            dynamicIndex_[dynamics_[i]] = i;
            dynamic.push_back(w_.slots[dynamics_[i]].box());
        }
        w_.movingGrid.build(dynamic);
        w_.movingSlots = dynamics_;
        builtAt_ = w_.changes;
    }

    /// Sensors see kinematic bodies too, which the tutorial's loop never resolves: each
    /// kinematic body, where it has moved to, against the static and kinematic sensors it
    /// overlaps.
    void reportKinematicVisitors() {
        for (std::uint32_t k : kinematics_) {
            const Body& visitor = w_.slots[k];
            const Box box = visitor.box();
            auto consider = [&](std::uint32_t s) {
                const Body& sensor = w_.slots[s];
                if (s != k && sensor.sensor && !visitor.sensor && canCollide(sensor, visitor) &&
                    overlaps(sensor.box(), box))
                    recordSensor(w_, s, k);
            };
            w_.restingGrid.query(box, [&](std::uint32_t i) { consider(w_.restingSlots[i]); });
            kinematicGrid_.query(box, [&](std::uint32_t i) { consider(kinematics_[i]); });
        }
    }

    /// A callback changed bodies (moved one, say): the grids are rebuilt from where the
    /// bodies are now.
    void refreshGrids() {
        if (builtAt_ != w_.changes)
            buildGrids();
    }

    /// The region in which a body's candidates are gathered: its box and half its size
    /// again around it, room for the small pushes of most collisions.
    static Box regionAround(const Body& body) {
        return {body.position - body.half * 2.0f, body.position + body.half * 2.0f};
    }

    static bool contains(const Box& outer, const Box& inner) {
        return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y &&
               inner.max.x <= outer.max.x && inner.max.y <= outer.max.y;
    }

    /// Static and kinematic bodies touching `region`, created after `after` (a creation
    /// count, WorldState::created), in creation order.
    void gatherStatics(const Box& region, std::int64_t after) {
        candidates_.clear();
        w_.restingGrid.query(region, [&](std::uint32_t k) {
            const std::uint32_t s = w_.restingSlots[k];
            if (w_.slots[s].type == BodyType::Static && std::int64_t(w_.created[s]) > after)
                candidates_.push_back(s);
        });
        kinematicGrid_.query(region, [&](std::uint32_t k) {
            const std::uint32_t s = kinematics_[k];
            if (std::int64_t(w_.created[s]) > after)
                candidates_.push_back(s);
        });
        std::sort(candidates_.begin(), candidates_.end(),
                  [&](std::uint32_t p, std::uint32_t q) { return w_.createdBefore(p, q); });
    }

    /// Dynamic bodies touching `region` that come after position `after` in dynamics_.
    void gatherDynamics(const Box& region, std::int64_t after) {
        candidates_.clear();
        w_.movingGrid.query(region, [&](std::uint32_t k) {
            if (std::int64_t(k) > after)
                candidates_.push_back(dynamics_[k]);
        });
        std::sort(candidates_.begin(), candidates_.end(), [&](std::uint32_t p, std::uint32_t q) {
            return dynamicIndex_[p] < dynamicIndex_[q];
        });
    }

    Outcome resolveAgainstStatics(std::uint32_t a) {
        return resolveInOrder(
            a, -1, [&](const Box& region, std::int64_t after) { gatherStatics(region, after); },
            [&](std::uint32_t s) { return std::int64_t(w_.created[s]); });
    }

    Outcome resolveAgainstLaterDynamics(std::uint32_t a, std::size_t index) {
        return resolveInOrder(
            a, std::int64_t(index),
            [&](const Box& region, std::int64_t after) { gatherDynamics(region, after); },
            [&](std::uint32_t b) { return std::int64_t(dynamicIndex_[b]); });
    }

    /// Resolves `a` against what gather(region, after) finds around it, in order: if a
    /// collision moves `a` out of the region the candidates were gathered for, the rest
    /// are gathered again around where it is now, after the last one visited (placeOf
    /// gives a body's place in the order).
    template <class Gather, class PlaceOf>
    Outcome resolveInOrder(std::uint32_t a, std::int64_t after, Gather&& gather,
                           PlaceOf&& placeOf) {
        for (;;) {
            refreshGrids();
            const Box region = regionAround(w_.slots[a]);
            gather(region, after);
            bool left = false;
            for (std::uint32_t b : candidates_) { // checkCollision gathers nothing

                after = placeOf(b);
                if (checkCollision(a, b) == Outcome::Destroyed)
                    return Outcome::Destroyed;
                if (!contains(region, w_.slots[a].box())) {
                    left = true;
                    break;
                }
            }
            if (!left)
                return Outcome::Kept;
        }
    }

    // --- Continuous collision (the ccd option) -------------------------------------------

    /// Moves the body by v*dt, but stops it at the first static or kinematic body in its
    /// way and responds there as solveCollision would, with that face's normal; then goes
    /// on with the rest of the step at the velocity the response left (sliding along a
    /// floor, or bouncing off it), hitting what that meets in turn. After kMaxHits hits
    /// in one step the body stays where the last one stopped it.
    Outcome sweepMove(std::uint32_t a) {
        refreshGrids();
        float remaining = 1.0f; // of the step
        for (int hits = 0; hits < kMaxHits && remaining > 0.0f; ++hits) {
            Body& body = w_.slots[a];
            const Vec2 motion = body.velocity * (dt_ * remaining);
            const std::optional<std::pair<Hit, std::uint32_t>> first =
                firstHit(a, motion, remaining);
            if (!first) {
                body.position += motion;
                stopAtTheEdge(body);
                return Outcome::Kept;
            }
            const auto [hit, hitSlot] = *first;
            body.position += motion * hit.time;
            stopAtTheEdge(body);
            remaining *= 1.0f - hit.time;
            const Vec2 va = body.velocity;
            const Vec2 vb = w_.slots[hitSlot].velocity;
            const float vx = va.x - vb.x;
            const float vy = va.y - vb.y;
            const float ps = vx * hit.normal.x + vy * hit.normal.y;
            if (ps > 0.0f)
                continue;
            if (respond(a, hitSlot, hit.normal.x, hit.normal.y, vx, vy, ps, 0.0f) ==
                Outcome::Destroyed)
                return Outcome::Destroyed;
        }
        return Outcome::Kept;
    }

    /// The first static or kinematic body that `a` meets moving by `motion` over the last
    /// `remaining` of the step. Kinematic bodies have already moved for the whole step:
    /// each is swept back from where it was that much earlier, by its own velocity.
    std::optional<std::pair<Hit, std::uint32_t>> firstHit(std::uint32_t a, Vec2 motion,
                                                          float remaining) {
        const Body& body = w_.slots[a];
        const Box swept = sweptBox(body.position, body.half, motion);
        // The kinematic grid holds each kinematic body's sweep over the step: whatever
        // could cross the body's path is found.
        gatherStatics(swept, -1);
        std::optional<std::pair<Hit, std::uint32_t>> first;
        for (std::uint32_t s : candidates_) {
            const Body& obstacle = w_.slots[s];
            // The grids are not rebuilt within a sweep: one destroyed by the callback of
            // an earlier hit is still in them.
            if (!w_.isLive(s) || obstacle.sensor || body.sensor || !canCollide(body, obstacle))
                continue;
            // The obstacle where it was at the start of what is left of the step.
            const Vec2 obstacleMotion = obstacle.velocity * (dt_ * remaining);
            const Vec2 from = obstacle.position - obstacleMotion;
            const std::optional<Hit> hit = sweepBox(body.position - from, body.half + obstacle.half,
                                                    motion - obstacleMotion, {});
            if (hit && (!first || hit->time < first->first.time))
                first = {{*hit, s}};
        }
        return first;
    }

    static constexpr int kMaxHits = 4;

    // --- The tutorial's checkCollision and solveCollision ---------------------------------

    Outcome checkCollision(std::uint32_t ia, std::uint32_t ib) {
        if (!w_.isLive(ib) || !canCollide(w_.slots[ia], w_.slots[ib]))
            return Outcome::Kept;
        const Body& a = w_.slots[ia];
        const Body& b = w_.slots[ib];
        const std::optional<Vec2> separation =
            shortestSeparation(a.position - b.position, a.half + b.half);
        if (!separation)
            return Outcome::Kept;
        // A sensor notes the overlap and pushes nothing.
        if (w_.slots[ia].sensor || w_.slots[ib].sensor) {
            if (w_.slots[ia].sensor != w_.slots[ib].sensor)
                w_.slots[ia].sensor ? recordSensor(w_, ia, ib) : recordSensor(w_, ib, ia);
            return Outcome::Kept;
        }
        const float sx = separation->x;
        const float sy = separation->y;

        // find the collision normal
        const float d = std::sqrt(sx * sx + sy * sy);
        const float nx = sx / d;
        const float ny = sy / d;
        // relative velocity
        Vec2 va = w_.slots[ia].velocity;
        Vec2 vb = w_.slots[ib].velocity;
        const float vx = va.x - vb.x;
        const float vy = va.y - vb.y;
        // penetration speed; objects moving apart?
        const float ps = vx * nx + vy * ny;
        if (ps > 0.0f)
            return Outcome::Kept;
        return respond(ia, ib, nx, ny, vx, vy, ps, d);
    }

    /// solveCollision from "objects moving towards each other" on: the pre-solve
    /// callback, separation by (nx, ny) × depth, and the velocity response.
    Outcome respond(std::uint32_t ia, std::uint32_t ib, float nx, float ny, float vx, float vy,
                    float ps, float depth) {
        const Vec2 normal{nx, ny};
        const Vec2 down = w_.events.down;
        float bounce = std::max(w_.slots[ia].bounce, w_.slots[ib].bounce);
        // A character rubs only on floors (characters.hpp).
        float friction = std::min(frictionAgainst(w_.slots[ia], normal, down),
                                  frictionAgainst(w_.slots[ib], -normal, down));
        if (w_.preSolve) {
            Collision c{w_.idOf(ia), w_.idOf(ib), {nx, ny}, depth, bounce, friction};
            const bool keep = w_.askPreSolve(c);
            // The callback may have destroyed either body or created others (which may
            // have moved the slots in memory: nothing is held across this call).
            if (!w_.isLive(ia))
                return Outcome::Destroyed;
            if (!keep || !w_.isLive(ib))
                return Outcome::Kept;
            // The callback's values, kept sane: clamped to [0, 1], NaN ignored.
            if (!std::isnan(c.bounce))
                bounce = std::clamp(c.bounce, 0.0f, 1.0f);
            if (!std::isnan(c.friction))
                friction = std::clamp(c.friction, 0.0f, 1.0f);
        }

        Body& ba = w_.slots[ia];
        Body& bb = w_.slots[ib];
        // separate the two objects: moveShape(a, sx, sy), with (sx, sy) = n * depth
        if (depth > 0.0f) {
            const float sx = nx * depth;
            const float sy = ny * depth;
            ba.position.x = ba.position.x + sx;
            ba.position.y = ba.position.y + sy;
            ba.separation += Vec2{sx, sy};
            stopAtTheEdge(ba);
        }
        recordContact(w_, ia, ib, normal, -ps, 0.0f);

        // penetration component
        const float px = nx * ps;
        const float py = ny * ps;
        // tangent component; friction slows what is left of it once a character's walk
        // over its floor is taken out
        const float tx = vx - px;
        const float ty = vy - py;
        const Vec2 walk =
            keepsATangentSpeed(ba, bb, w_.conveyors > 0) ? walkOver(ba, bb, normal, down) : Vec2{};
        const float wx = tx - walk.x;
        const float wy = ty - walk.y;
        // restitution
        const float r = 1.0f + bounce;
        // friction
        const float f = friction;

        const ClassicOptions& options = w_.def.classic;
        if (!options.mass && !options.coulomb) {
            // change the velocity of shape a (the text's friction: minus, not plus)
            ba.velocity.x = ba.velocity.x - px * r - wx * f;
            ba.velocity.y = ba.velocity.y - py * r - wy * f;
            return Outcome::Kept;
        }
        const Vec2 change = velocityChange({px, py}, {wx, wy}, ps, r, f, options.coulomb);
        if (!options.mass) {
            ba.velocity += change;
            return Outcome::Kept;
        }
        // Impulse = Mass × ChangeInVelocity, shared so that the relative velocity changes
        // by `change`: a gets invMassA / (invMassA + invMassB) of it, b the rest, opposite.
        const float invMassSum = ba.invMass + bb.invMass;
        if (invMassSum > 0.0f) {
            ba.velocity += change * (ba.invMass / invMassSum);
            bb.velocity -= change * (bb.invMass / invMassSum);
        }
        return Outcome::Kept;
    }

    WorldState& w_;
    float dt_;
    std::vector<std::uint32_t> dynamics_;
    std::vector<std::uint32_t> kinematics_;
    std::vector<std::uint32_t> dynamicIndex_; ///< by slot: place in dynamics_
    BoxGrid kinematicGrid_;
    std::vector<std::uint32_t> candidates_;
    std::uint64_t builtAt_ = 0;
};

} // namespace

void stepClassic(WorldState& world, float dt) {
    ClassicStep(world, dt).run();
    world.events.publish(world, true);
}

} // namespace jostle
