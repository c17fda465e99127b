// The physical model: every contact of the step solved together.
//
//   1. velocities: gravity, damping, clamp (as in the classic model);
//   2. contacts: every pair that overlaps, touches, or will touch within the step
//      (speculative contacts: the solver lets such a pair close its gap, no more);
//   3. support levels: static and kinematic bodies are level 0, a dynamic body touching
//      a level-k body is level k+1; contacts are solved from the ground up, and in each
//      one body may hold the other (the lower along gravity; else one with a static body
//      right behind it);
//   4. sequential impulses: a few passes over all contacts; each pass nudges the
//      accumulated normal impulse (never pulling: >= 0) and the friction impulse
//      (Coulomb: |friction| <= mu × normal), starting from last step's (warm starting);
//   5. shock propagation: one last normal pass, from the ground up, in which the body
//      that holds the other is held fixed: what the passes before left unresolved, the
//      other takes, so a heavy box cannot squash a light one into the floor;
//   6. sweeps: a body moving further than its half size, or somewhere its contacts did
//      not look, is swept against static and kinematic bodies; what it meets becomes a
//      contact of the step;
//   7. positions from velocities;
//   8. position correction: overlap beyond the slop is removed by moving the bodies
//      (the held one stays; else both move, by inverse mass); velocities are left
//      alone, so no energy is added.
//
// Boxes do not rotate, so a contact is one normal along x or y and one tangent: the
// effective mass of a contact is 1 / (invMassA + invMassB) and nothing else.
// docs/physical-model.md explains the choices.
#include "collide.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jostle {

namespace {

float combineFriction(FrictionMix mix, float a, float b) {
    return mix == FrictionMix::GeometricMean ? std::sqrt(a * b) : std::min(a, b);
}

class PhysicalStep {
public:
    PhysicalStep(WorldState& world, float dt) : w_(world), options_(world.def.physical), dt_(dt) {}

    void run() {
        w_.events.beginStep(w_);
        carryRiders();
        for (BodyId id : w_.order) {
            Body& body = w_.slots[id.index];
            if (body.isDynamic() && !body.asleep) {
                integrateVelocity(w_.def, body, dt_);
                body.dropThroughTime = std::max(0.0f, body.dropThroughTime - dt_);
            }
        }
        findPairs(w_, dt_, pairs_);
        solverIndex_.assign(w_.slots.size(), kNoSolverBody);
        bodies_.clear();
        buildContacts();
        orderBySupport();
        warmStart();
        for (int i = 0; i < options_.velocityIterations; ++i)
            solveVelocities();
        propagateShock();
        sweepFlags_.assign(w_.slots.size(), 0);
        for (const SolverBody& body : bodies_) {
            Vec2& velocity = w_.slots[body.slot].velocity;
            const Vec2 solved{body.velocity[0], body.velocity[1]};
            if (body.invMass > 0.0f && movesUnforeseen(w_.slots[body.slot], velocity, solved))
                sweepFlags_[body.slot] = 1;
            velocity = solved;
        }
        sweepBodies();
        // Contacts the sweeps found join the step's, for position correction and events.
        if (!sweptContacts_.empty()) {
            contacts_.insert(contacts_.end(), sweptContacts_.begin(), sweptContacts_.end());
            sweptContacts_.clear();
            orderBySupport();
        }
        integratePositions();
        for (SolverBody& body : bodies_) {
            body.position[0] = w_.slots[body.slot].position.x;
            body.position[1] = w_.slots[body.slot].position.y;
        }
        // A pass that moved nothing leaves the next one nothing to do.
        for (int i = 0; i < options_.positionIterations && correctPositions(); ++i) {
        }
        for (const SolverBody& body : bodies_) {
            if (body.invMass > 0.0f) {
                // What position correction moved the body is part of its separation.
                Body& written = w_.slots[body.slot];
                const Vec2 corrected{body.position[0], body.position[1]};
                const Vec2 moved = corrected - written.position;
                written.separation += moved;
                written.position = corrected;
                // Still being pushed out of an overlap: not at rest, whatever its speed.
                if (length(moved) > kSleepSpeed * std::min(written.half.x, written.half.y) * dt_)
                    written.sleepTime = 0.0f;
            }
        }
        remember();
        report();
        for (BodyId id : w_.order) {
            Body& body = w_.slots[id.index];
            if (body.type == BodyType::Kinematic)
                body.lastStepVelocity = body.velocity;
        }
        if (w_.def.sleeping)
            fallAsleep();
        w_.events.publish(w_, std::find(w_.movingDynamic.begin(), w_.movingDynamic.end(),
                                        std::uint8_t{1}) != w_.movingDynamic.end());
    }

private:
    float restitutionThreshold() const {
        if (options_.restitutionThreshold > 0.0f)
            return options_.restitutionThreshold;
        return 2.0f * length(w_.def.gravity) * dt_;
    }

    /// The relative normal speed at which the pair really meets. `approach` is measured
    /// after this step's gravity, as if it had acted for the whole step; but the pair meets
    /// when it has crossed its gap, a fraction of the step (none if it already touches).
    /// Counting the whole step would hand a bouncing body g dt of speed at every bounce,
    /// and a bouncy box would hop forever at the height where that balances what the
    /// bounce takes away.
    float impactSpeed(const Body& a, const Body& b, Vec2 normal, float approach, float gap) const {
        auto acceleration = [&](const Body& body) {
            return body.isDynamic() ? w_.def.gravity * body.gravityScale : Vec2{};
        };
        const float gravityAlong = dot(acceleration(a) - acceleration(b), normal);
        const float before = approach - gravityAlong * dt_;
        const float meetAfter =
            gap > 0.0f && approach < 0.0f ? std::min(dt_, gap / -approach) : 0.0f;
        return before + gravityAlong * meetAfter;
    }

    std::uint32_t solverBodyOf(std::uint32_t slot) {
        std::uint32_t& index = solverIndex_[slot];
        if (index == kNoSolverBody) {
            const Body& body = w_.slots[slot];
            index = std::uint32_t(bodies_.size());
            bodies_.push_back({{body.velocity.x, body.velocity.y},
                               {body.position.x, body.position.y},
                               body.invMass,
                               slot});
        }
        return index;
    }

    /// A body standing on a kinematic body at the end of the last step gets whatever
    /// velocity the kinematic body gained since (the game changed it): riders stay put
    /// on a platform that starts, stops or turns, and do not lift off one that starts
    /// down. Friction alone would let them slide until it caught up. Each rider follows
    /// the first platform it stands on, in pair order.
    void carryRiders() {
        const Vec2 g = w_.def.gravity;
        if (g == Vec2{})
            return; // nothing stands on anything without gravity
        bool anyChanged = false;
        for (std::uint32_t slot : w_.movingSlots) {
            const Body& body = w_.slots[slot];
            if (body.type == BodyType::Kinematic && body.velocity != body.lastStepVelocity) {
                anyChanged = true;
                break;
            }
        }
        if (!anyChanged)
            return; // no platform changed its velocity: nobody to hand anything to
        carried_.assign(w_.slots.size(), 0);
        for (const TouchRecord& record : w_.events.touchingBefore()) {
            if (!w_.isCurrent(record.a) || !w_.isCurrent(record.b))
                continue;
            Body& a = w_.slots[record.a.index];
            Body& b = w_.slots[record.b.index];
            const bool aRides = a.isDynamic() && b.type == BodyType::Kinematic;
            const bool bRides = b.isDynamic() && a.type == BodyType::Kinematic;
            if (!aRides && !bRides)
                continue;
            Body& rider = aRides ? a : b;
            const Body& platform = aRides ? b : a;
            // The normal points from b towards a: the push the rider gets from below.
            const Vec2 up = aRides ? record.normal : -record.normal;
            const Vec2 change = platform.velocity - platform.lastStepVelocity;
            const std::uint32_t riderSlot = aRides ? record.a.index : record.b.index;
            if (dot(up, g) >= 0.0f || change == Vec2{} || carried_[riderSlot])
                continue;
            carried_[riderSlot] = 1;
            rider.velocity += change;
        }
    }

    /// Whether the face of static body `wall` that faces `other` along `axis` (0: x,
    /// 1: y) is, at the corner nearest `other`, covered by another static body flush
    /// against it: a seam between two boxes of a floor or a wall, which nothing can hit.
    /// A box sliding along a floor of separate boxes, or along a wall whose rows are
    /// separate boxes, meets the next box at such a corner; pushing on that face would
    /// stop it dead at the seam.
    bool isSeam(const Body& wall, const Body& other, int axis) const {
        const int along = 1 - axis; // the axis the face runs along
        const float wallCentre[2] = {wall.position.x, wall.position.y};
        const float wallHalf[2] = {wall.half.x, wall.half.y};
        const float otherCentre[2] = {other.position.x, other.position.y};
        const float otherHalf[2] = {other.half.x, other.half.y};
        // The face, and the corner of it nearest `other`; `inward` runs from that corner
        // along the face.
        const float side = otherCentre[axis] < wallCentre[axis] ? -1.0f : 1.0f;
        const float face = wallCentre[axis] + side * wallHalf[axis];
        const float end = otherCentre[along] < wallCentre[along] ? -1.0f : 1.0f;
        const float corner = wallCentre[along] + end * wallHalf[along];
        const float inward = -end;
        // Flush: within a hair of the face, on the far side of it from the wall. A hair is
        // a small fraction of the sizes, or a few float steps at the face's coordinate
        // (metre-sized tiles far from the origin round coarser than that fraction).
        const float tolerance =
            std::max(1e-4f * std::max(wallHalf[axis], otherHalf[axis]), 4.0f * ulpOf(face));
        // It must cover the face from the corner inward, a good part of the way.
        const float reach = 0.25f * std::min(wallHalf[along], otherHalf[along]);
        Bounds probe;
        float* lo[2] = {&probe.min.x, &probe.min.y};
        float* hi[2] = {&probe.max.x, &probe.max.y};
        *lo[axis] = *hi[axis] = face + side * tolerance;
        *lo[along] = std::min(corner, corner + inward * reach);
        *hi[along] = std::max(corner, corner + inward * reach);
        bool covered = false;
        w_.restingGrid.query(probe, [&](std::uint32_t k) {
            const Body& cover = w_.slots[w_.restingSlots[k]];
            if (covered || cover.type != BodyType::Static || &cover == &wall)
                return;
            const float coverMin[2] = {cover.position.x - cover.half.x,
                                       cover.position.y - cover.half.y};
            const float coverMax[2] = {cover.position.x + cover.half.x,
                                       cover.position.y + cover.half.y};
            // On the other side of the face, touching it...
            const float near = side > 0.0f ? coverMin[axis] : coverMax[axis];
            if (std::abs(near - face) > tolerance)
                return;
            // ... and spanning the probe along it.
            covered = coverMin[along] <= *lo[along] + tolerance &&
                      coverMax[along] >= *hi[along] - tolerance;
        });
        return covered;
    }

    /// Whether one-way `platform` blocks `other`, which lies along `outward` from it (a
    /// unit axis vector) with this gap between them at the start of the step: only on
    /// its blocking face, only if `other` was wholly on that side (within the skin), and
    /// not while `other` drops through on purpose.
    static bool blocks(const Body& platform, const Body& other, Vec2 outward, float gap,
                       float skin) {
        return outward == platform.oneWay && gap >= -skin && other.dropThroughTime <= 0.0f;
    }

    /// A contact of `a` and `b` along `normal` (a unit axis vector, from b towards a): its
    /// axis, signs, extent, slop and friction, the rest left to the caller.
    Contact contactAlong(const Body& a, const Body& b, Vec2 normal) const {
        Contact c;
        const bool alongX = normal.x != 0.0f;
        c.axis = alongX ? 0 : 1;
        c.sign = alongX ? normal.x : normal.y;
        c.tangentSign = alongX ? normal.x : -normal.y;
        c.extent = alongX ? a.half.x + b.half.x : a.half.y + b.half.y;
        c.slop =
            options_.slop * (alongX ? std::min(a.half.x, b.half.x) : std::min(a.half.y, b.half.y));
        c.friction = combineFriction(options_.frictionMix, a.friction, b.friction);
        return c;
    }

    void buildContacts() {
        const float threshold = restitutionThreshold();
        vetoed_.clear();
        contacts_.clear();
        contacts_.reserve(pairs_.size());
        sensorPairs_.clear();
        for (const BodyPair& pair : pairs_) {
            if (!w_.isLive(pair.a) || !w_.isLive(pair.b))
                continue; // destroyed by a callback earlier in this loop
            const Body& a = w_.slots[pair.a];
            const Body& b = w_.slots[pair.b];
            if (!canCollide(a, b))
                continue;
            if (a.sensor || b.sensor) {
                // Overlap is judged where the step leaves them (report()).
                if (a.sensor != b.sensor)
                    sensorPairs_.push_back(a.sensor ? pair : BodyPair{pair.b, pair.a});
                continue;
            }
            const Vec2 d = a.position - b.position;
            const float gapX = std::abs(d.x) - (a.half.x + b.half.x);
            const float gapY = std::abs(d.y) - (a.half.y + b.half.y);
            // Overlap within twice the slop is resting contact, not penetration.
            const float skinX = skinOf(a.half.x, b.half.x);
            const float skinY = skinOf(a.half.y, b.half.y);
            bool alongX = contactAxis(gapX, gapY, skinX, skinY) == Axis::X;
            // Met at a corner (neither overlapping along the other axis): if that corner
            // is a seam between two static bodies, the face the contact would push on is
            // inside the level, and the other axis is the one to push along.
            if (gapX >= -skinX && gapY >= -skinY && a.type != b.type &&
                (a.type == BodyType::Static || b.type == BodyType::Static)) {
                const bool aStatic = a.type == BodyType::Static;
                if (isSeam(aStatic ? a : b, aStatic ? b : a, alongX ? 0 : 1))
                    alongX = !alongX;
            }
            const float gap = alongX ? gapX : gapY;
            const Vec2 normal = alongX ? Vec2{d.x < 0.0f ? -1.0f : 1.0f, 0.0f}
                                       : Vec2{0.0f, d.y < 0.0f ? -1.0f : 1.0f};
            const float approach = dot(a.velocity - b.velocity, normal);
            // Apart, and neither moving fast enough towards the other to close the gap
            // within this step: no contact. Each body's own speed counts, not only the
            // pair's: two boxes falling together do not approach, but when the lower one
            // lands the upper one must be stopped too, in this very step.
            const float towardB = std::max(0.0f, -dot(a.velocity, normal));
            const float towardA = std::max(0.0f, dot(b.velocity, normal));
            if (gap > 0.0f && gap > (towardA + towardB) * dt_)
                continue;
            // One-way platforms block only from their one side (the normal points from b
            // towards a).
            const float skin = alongX ? skinX : skinY;
            if ((a.isOneWay() && !blocks(a, b, -normal, gap, skin)) ||
                (b.isOneWay() && !blocks(b, a, normal, gap, skin)))
                continue;

            Contact c = contactAlong(a, b, normal);
            c.approachSpeed = std::max(0.0f, -approach);
            float bounce = std::max(a.bounce, b.bounce);

            if (w_.preSolve) {
                Collision info{w_.idOf(pair.a), w_.idOf(pair.b), normal, -gap, bounce, c.friction};
                const bool keep = w_.preSolve(info);
                if (!keep)
                    vetoed_.push_back(pairKey(pair.a, pair.b));
                if (!keep || !w_.isLive(pair.a) || !w_.isLive(pair.b))
                    continue;
                if (!std::isnan(info.bounce))
                    bounce = std::clamp(info.bounce, 0.0f, 1.0f);
                if (!std::isnan(info.friction))
                    c.friction = std::clamp(info.friction, 0.0f, 1.0f);
            }
            // The callback may have created bodies: fetch again.
            const Body& ba = w_.slots[pair.a];
            const Body& bb = w_.slots[pair.b];
            c.invMassA = ba.invMass;
            c.invMassB = bb.invMass;
            c.ia = solverBodyOf(pair.a);
            c.ib = solverBodyOf(pair.b);
            const float invMassSum = c.invMassA + c.invMassB;
            if (invMassSum <= 0.0f)
                continue; // the callback made both infinitely heavy
            c.effectiveMass = 1.0f / invMassSum;

            // Warm start from last step's impulses if this is the same contact.
            const CachedContact* cached = nullptr;
            if (const CachedContact* found = w_.contactCache.find(pair.a, pair.b);
                found && found->generationA == ba.generation &&
                found->generationB == bb.generation && found->normal == normal) {
                cached = found;
                c.normalImpulse = cached->normalImpulse;
                c.tangentImpulse = cached->tangentImpulse;
            }

            // A speculative contact may close its gap, and no more.
            c.targetSpeed = gap > 0.0f ? -gap / dt_ : 0.0f;
            const float impact = impactSpeed(ba, bb, normal, approach, gap);
            if (cached && cached->bounceSpeed > 0.0f) {
                // Arrived at the surface last step: leave it now.
                c.targetSpeed = cached->bounceSpeed;
            } else if (bounce > 0.0f && impact < -threshold && approach < c.targetSpeed) {
                // Bouncing from where the pair is now would bounce from up to a step's
                // travel away from the surface, and gain that much height at every bounce.
                // So a pair still apart first closes its gap and bounces on the next step,
                // from the surface, at the speed it came in with.
                if (gap > 0.0f)
                    c.bounceSpeed = -bounce * impact;
                else
                    c.targetSpeed = -bounce * impact;
            }
            contacts_.push_back(c);
        }
        std::sort(vetoed_.begin(), vetoed_.end());
        // A callback may have destroyed a body after its contact was made: the body is left
        // out of the rest of the step (no impulses, no events, no cached contact whose
        // generations would be those of the slot's next body).
        if (w_.preSolve)
            std::erase_if(contacts_, [&](const Contact& c) {
                return !w_.isLive(bodies_[c.ia].slot) || !w_.isLive(bodies_[c.ib].slot);
            });
    }

    /// Support levels (see the top of the file), by a breadth-first search from the
    /// static and kinematic bodies over the contact graph; then contacts are sorted from
    /// the ground up, ties in pair order.
    void orderBySupport() {
        constexpr std::uint32_t unsupported = UINT32_MAX;
        const std::size_t n = bodies_.size();
        // The contact graph as adjacency lists (compressed: offsets, then neighbours).
        offsets_.assign(n + 1, 0);
        for (const Contact& c : contacts_) {
            ++offsets_[c.ia + 1];
            ++offsets_[c.ib + 1];
        }
        for (std::size_t i = 0; i < n; ++i)
            offsets_[i + 1] += offsets_[i];
        neighbours_.resize(offsets_[n]);
        fill_.assign(offsets_.begin(), offsets_.end() - 1);
        for (const Contact& c : contacts_) {
            neighbours_[fill_[c.ia]++] = c.ib;
            neighbours_[fill_[c.ib]++] = c.ia;
        }
        levels_.assign(n, unsupported);
        queue_.clear();
        for (std::uint32_t i = 0; i < n; ++i) {
            if (bodies_[i].invMass == 0.0f) {
                levels_[i] = 0;
                queue_.push_back(i);
            }
        }
        for (std::size_t head = 0; head < queue_.size(); ++head) {
            const std::uint32_t body = queue_[head];
            for (std::uint32_t k = offsets_[body]; k < offsets_[body + 1]; ++k) {
                const std::uint32_t other = neighbours_[k];
                if (levels_[other] == unsupported) {
                    levels_[other] = levels_[body] + 1;
                    queue_.push_back(other);
                }
            }
        }
        findBacking();
        // A stable counting sort by level; unsupported contacts (floating piles) last.
        // Contacts are large: the sort finds each one's destination, then moves them
        // there in place, along the cycles of the permutation.
        std::uint32_t top = 0;
        auto levelOf = [&](const Contact& c) { return std::min(levels_[c.ia], levels_[c.ib]); };
        for (Contact& c : contacts_) {
            const std::uint32_t la = levels_[c.ia];
            const std::uint32_t lb = levels_[c.ib];
            c.supporter = la < lb ? 1 : lb < la ? 2 : 0;
            if (w_.def.gravity != Vec2{}) {
                const float down = dot(c.normal(), w_.def.gravity); // > 0: a is below b
                // A body holds the other up only from below: one reached through a
                // sideways contact (a box leaning on a wall) is not a floor. Counting it as
                // one, a box between two supporters would be pushed both ways by position
                // correction, and stay squeezed.
                if ((c.supporter == 1 && !(down > 0.0f)) || (c.supporter == 2 && !(down < 0.0f)))
                    c.supporter = 0;
                // Within a level, the lower body of a contact along gravity holds the upper
                // one up. Both touch the ground, so the upper one reaches down into the
                // lower one or beside it into the ground: a heavy box that landed across a
                // plank and the floor. Sharing by inverse mass would push the plank into the
                // floor as hard as the floor pushes it out, and it would stay there.
                if (la == lb && la != unsupported && down != 0.0f)
                    c.supporter = down > 0.0f ? 1 : 2;
            }
            // (Without gravity there is no below: levels alone decide.)
            // Neither holding the other up, a body with a static or kinematic body right
            // behind it, on the side the contact pushes it to, holds the other: a light
            // box pressed against a wall by a heavy one. Sharing by inverse mass, the light
            // box would be pushed back into the wall nearly as far as the wall pushes it
            // out, and the pair would creep apart at a hundredth of the rate.
            // Between two dynamic bodies only: against a static or kinematic one, the body
            // holding would leave nobody to move, and the overlap would stay.
            if (c.supporter == 0 && c.invMassA > 0.0f && c.invMassB > 0.0f) {
                const bool aHeld = isBacked(c.ia, c.axis, c.sign);
                const bool bHeld = isBacked(c.ib, c.axis, -c.sign);
                c.supporter = aHeld && !bHeld ? 1 : bHeld && !aHeld ? 2 : 0;
            }
            if (levelOf(c) != unsupported)
                top = std::max(top, levelOf(c) + 1);
        }
        counts_.assign(std::size_t(top) + 2, 0);
        auto bucket = [&](const Contact& c) {
            const std::uint32_t level = levelOf(c);
            return level == unsupported ? top : level;
        };
        for (const Contact& c : contacts_)
            ++counts_[bucket(c) + 1];
        for (std::size_t i = 0; i + 1 < counts_.size(); ++i)
            counts_[i + 1] += counts_[i];
        destination_.resize(contacts_.size());
        for (std::size_t k = 0; k < contacts_.size(); ++k)
            destination_[k] = counts_[bucket(contacts_[k])]++;
        for (std::uint32_t k = 0; k < contacts_.size(); ++k) {
            while (destination_[k] != k) {
                const std::uint32_t to = destination_[k];
                std::swap(contacts_[k], contacts_[to]);
                std::swap(destination_[k], destination_[to]);
            }
        }
    }

    /// Which solver bodies touch a static or kinematic body, and on which sides: a bit
    /// per axis and direction (backingBit). Touch: a speculative contact, still apart
    /// (its target lets the gap close), is no backing yet.
    void findBacking() {
        backing_.assign(bodies_.size(), 0);
        for (const Contact& c : contacts_) {
            if (c.targetSpeed < 0.0f)
                continue;
            // The normal points from b towards a: b lies on a's side -sign, a on b's +sign.
            if (c.invMassB == 0.0f)
                backing_[c.ia] |= backingBit(c.axis, -c.sign);
            if (c.invMassA == 0.0f)
                backing_[c.ib] |= backingBit(c.axis, c.sign);
        }
    }

    static std::uint8_t backingBit(int axis, float direction) {
        return std::uint8_t(1u << (2 * axis + (direction > 0.0f ? 1 : 0)));
    }

    /// Whether solver body `i` has a static or kinematic body next to it along `axis`,
    /// in `direction` (its sign).
    bool isBacked(std::uint32_t i, int axis, float direction) const {
        return (backing_[i] & backingBit(axis, direction)) != 0;
    }

    /// Applies `impulse` along the contact's normal (n = 0) or tangent (n = 1) axis.
    void applyImpulse(const Contact& c, int axis, float impulse) {
        bodies_[c.ia].velocity[axis] += impulse * c.invMassA;
        bodies_[c.ib].velocity[axis] -= impulse * c.invMassB;
    }

    float relativeSpeed(const Contact& c, int axis) const {
        return bodies_[c.ia].velocity[axis] - bodies_[c.ib].velocity[axis];
    }

    void warmStart() {
        for (const Contact& c : contacts_) {
            applyImpulse(c, c.axis, c.sign * c.normalImpulse);
            applyImpulse(c, 1 - c.axis, c.tangentSign * c.tangentImpulse);
        }
    }

    // The passes below clamp the accumulated impulse by clamping the change to it, not by
    // clamping the sum and taking the difference: a light body under a heavy one needs a
    // change far below the float step of the impulse that holds the heavy one up, and
    // the difference of two sums would round it away, leaving the light body sinking.

    void solveVelocities() {
        for (Contact& c : contacts_) {
            // Normal: push (never pull) until the pair stops approaching.
            {
                const float speed = c.sign * relativeSpeed(c, c.axis);
                const float impulse =
                    std::max(-c.effectiveMass * (speed - c.targetSpeed), -c.normalImpulse);
                applyImpulse(c, c.axis, c.sign * impulse);
                c.normalImpulse += impulse;
            }
            // Friction: stop the sliding, within Coulomb's cone.
            {
                const int tangent = 1 - c.axis;
                const float speed = c.tangentSign * relativeSpeed(c, tangent);
                const float limit = c.friction * c.normalImpulse;
                const float impulse = std::clamp(
                    -c.effectiveMass * speed, -limit - c.tangentImpulse, limit - c.tangentImpulse);
                applyImpulse(c, tangent, c.tangentSign * impulse);
                c.tangentImpulse = std::clamp(c.tangentImpulse + impulse, -limit, limit);
            }
        }
    }

    void propagateShock() {
        for (Contact& c : contacts_) {
            if (c.supporter == 0)
                continue;
            // The supporter is held fixed: the other body takes the whole impulse.
            const float invMass = c.supporter == 1 ? c.invMassB : c.invMassA;
            if (invMass <= 0.0f)
                continue;
            const float speed = c.sign * relativeSpeed(c, c.axis);
            const float impulse = std::max(-(speed - c.targetSpeed) / invMass, -c.normalImpulse);
            if (c.supporter == 1)
                bodies_[c.ib].velocity[c.axis] -= c.sign * impulse * c.invMassB;
            else
                bodies_[c.ia].velocity[c.axis] += c.sign * impulse * c.invMassA;
            // Kept apart from the impulse both bodies felt: warm starting the next step
            // with it would hand the held body all of it, and a body ten trillion times
            // lighter than the one it holds up would be flung at a speed that floats
            // cannot tell from its neighbours'.
            c.shockImpulse = impulse;
        }
    }

    /// Whether the solver sent `body` where its contacts did not look: they were made
    /// for bodies it could reach moving `before` (this step's velocity, before the
    /// solver), and it now moves `after`, further along an axis than its skin allows. A
    /// light box rammed down by a heavy one that lands on it, while the box itself was
    /// on its way up, meets a floor that no contact of the step knows of.
    bool movesUnforeseen(const Body& body, Vec2 before, Vec2 after) const {
        auto beyond = [&](float was, float now, float half) {
            const float unforeseen =
                was * now < 0.0f ? std::abs(now) : std::abs(now) - std::abs(was);
            return unforeseen * dt_ > skinOf(half, half);
        };
        return beyond(before.x, after.x, body.half.x) || beyond(before.y, after.y, body.half.y);
    }

    /// Continuous collision: a body that moves more than its own half size in this step,
    /// or that the solver sent where its contacts did not look (movesUnforeseen), is
    /// swept along its motion against static and kinematic bodies (and, if it is a
    /// bullet, dynamic ones), and stopped where it first meets one, its velocity into
    /// that body removed. Contacts already stop what they foresee; this catches the rest,
    /// so nothing passes through a wall however fast it goes, nor is pushed into one.
    void sweepBodies() {
        for (std::uint32_t slot : w_.movingSlots) {
            Body& body = w_.slots[slot];
            if (!body.isDynamic() || !w_.isLive(slot))
                continue;
            const Vec2 motion = body.velocity * dt_;
            const float size = std::min(body.half.x, body.half.y);
            if (std::abs(motion.x) <= size && std::abs(motion.y) <= size && !sweepFlags_[slot])
                continue;
            sweep(slot, motion);
        }
    }

    /// A contact for a hit of the sweep of `slot` on `obstacle`, along `normal` (from the
    /// obstacle towards the body), met at `speed`: it holds the body on the obstacle's
    /// side when position correction pushes it there from the other side, and reports
    /// the touch. Unless a contact of the pair is in the step already.
    void addSweptContact(std::uint32_t slot, std::uint32_t obstacle, Vec2 normal, float speed) {
        const bool bodyFirst = w_.rank[slot] < w_.rank[obstacle];
        const std::uint32_t slotA = bodyFirst ? slot : obstacle;
        const std::uint32_t slotB = bodyFirst ? obstacle : slot;
        const std::uint32_t ia = solverBodyOf(slotA), ib = solverBodyOf(slotB);
        // The contact graph of orderBySupport holds the step's contacts so far.
        if (const std::size_t known = offsets_.size() - 1; ia < known && ib < known)
            for (std::uint32_t k = offsets_[ia]; k < offsets_[ia + 1]; ++k)
                if (neighbours_[k] == ib)
                    return;
        // Found by an earlier hit of this sweep, or, for a dynamic obstacle (bullets), by its
        // own sweep: the rest of the list holds other bodies' hits.
        const bool dynamicObstacle = w_.slots[obstacle].isDynamic();
        for (std::size_t k = dynamicObstacle ? 0 : sweepStart_; k < sweptContacts_.size(); ++k)
            if (sweptContacts_[k].ia == ia && sweptContacts_[k].ib == ib)
                return;
        const Body& a = w_.slots[slotA];
        const Body& b = w_.slots[slotB];
        Contact c = contactAlong(a, b, bodyFirst ? normal : -normal);
        c.ia = ia;
        c.ib = ib;
        c.invMassA = a.invMass;
        c.invMassB = b.invMass;
        c.effectiveMass = 1.0f / (a.invMass + b.invMass);
        c.targetSpeed = 0.0f;
        c.approachSpeed = speed;
        sweptContacts_.push_back(c);
    }

    /// Sweeps the body along `motion`; at the first hit, moves it there and takes away
    /// its velocity into the obstacle, then sweeps again along what is left of its
    /// velocity (sliding along a floor into a wall, say). The step's own integration then
    /// moves it by that velocity from there, a path just swept clear. If it still hits
    /// something after kMaxHits sweeps, it stops where the last one left it.
    void sweep(std::uint32_t slot, Vec2 motion) {
        sweepStart_ = sweptContacts_.size();
        Body& body = w_.slots[slot];
        for (int hits = 0; hits < kMaxHits; ++hits) {
            const std::optional<std::pair<Hit, std::uint32_t>> first = firstHit(slot, motion);
            if (!first)
                return;
            const auto [hit, hitSlot] = *first;
            // Stop at the hit: move there now, and take away the part of the velocity that
            // goes into the obstacle, so that the step's own motion starts from there.
            // Where it touches the obstacle as the obstacle is now: the integration that
            // follows moves both by their velocities, which the hit has made equal along
            // the normal.
            const Body& obstacle = w_.slots[hitSlot];
            body.position += (motion - obstacle.velocity * dt_) * hit.time;
            const float into = dot(body.velocity - obstacle.velocity, hit.normal);
            if (into < 0.0f)
                body.velocity -= hit.normal * into;
            addSweptContact(slot, hitSlot, hit.normal, std::max(0.0f, -into));
            motion = body.velocity * dt_;
        }
        if (firstHit(slot, motion))
            body.velocity = {};
    }

    /// The first body `slot` meets moving by `motion` this step: static and kinematic
    /// ones, and dynamic ones too if it is a bullet.
    std::optional<std::pair<Hit, std::uint32_t>> firstHit(std::uint32_t slot, Vec2 motion) {
        const Body& body = w_.slots[slot];
        const Bounds swept = sweptBounds(body.position, body.half, motion);
        std::optional<std::pair<Hit, std::uint32_t>> first;
        auto consider = [&](std::uint32_t other) {
            const Body& obstacle = w_.slots[other];
            if (other == slot || !w_.isLive(other))
                return;
            if ((obstacle.isDynamic() && !body.bullet) || obstacle.sensor || body.sensor ||
                !canCollide(body, obstacle))
                return;
            const Vec2 relative = motion - obstacle.velocity * dt_;
            const Vec2 skin{skinOf(body.half.x, obstacle.half.x),
                            skinOf(body.half.y, obstacle.half.y)};
            const std::optional<Hit> hit = sweepBox(body.box(), relative, obstacle.box(), skin);
            // Only what the body runs into: a kinematic body coming at it from behind is
            // the contacts' business (they push it), not a reason to stop it.
            if (!hit || dot(motion, hit->normal) >= 0.0f)
                return;
            // A one-way platform stops what meets its blocking face (having been on its
            // side at the start of the sweep), unless it drops through on purpose.
            if (obstacle.isOneWay() &&
                (hit->normal != obstacle.oneWay || body.dropThroughTime > 0.0f))
                return;
            // Nor does what the pre-solve callback let the body through in this step.
            if (isVetoed(slot, other))
                return;
            if (!first || hit->time < first->first.time)
                first = {{*hit, other}};
        };
        w_.restingGrid.query(swept, [&](std::uint32_t i) {
            if (w_.slots[w_.restingSlots[i]].type == BodyType::Static)
                consider(w_.restingSlots[i]);
        });
        w_.movingGrid.query(swept, [&](std::uint32_t i) { consider(w_.movingSlots[i]); });
        return first;
    }

    static constexpr int kMaxHits = 4;

    /// The two slots as one number, the same in either order.
    static std::uint64_t pairKey(std::uint32_t slotA, std::uint32_t slotB) {
        return std::uint64_t{std::min(slotA, slotB)} << 32 | std::max(slotA, slotB);
    }

    /// Whether the pre-solve callback vetoed the contact of these two bodies this step.
    bool isVetoed(std::uint32_t slotA, std::uint32_t slotB) const {
        return std::binary_search(vetoed_.begin(), vetoed_.end(), pairKey(slotA, slotB));
    }

    float skinOf(float halfA, float halfB) const {
        return contactSkin(options_.slop, halfA, halfB);
    }

    void integratePositions() {
        // The bodies that were moving when the step began (a callback may have created
        // others since: they join next step).
        for (std::uint32_t slot : w_.movingSlots) {
            Body& body = w_.slots[slot];
            if (w_.isLive(slot))
                body.position += body.velocity * dt_;
        }
    }

    /// How deep the pair of contact `c` overlaps along its normal where the solver bodies
    /// are now (negative: the gap between them).
    float overlapOf(const Contact& c) const {
        return c.extent -
               c.sign * (bodies_[c.ia].position[c.axis] - bodies_[c.ib].position[c.axis]);
    }

    /// One pass of position correction; false if it moved no body.
    bool correctPositions() {
        bool moved = false;
        for (Contact& c : contacts_) {
            SolverBody& a = bodies_[c.ia];
            SolverBody& b = bodies_[c.ib];
            const float overlap = overlapOf(c);
            // Centres that have passed each other along the normal (a kinematic body that
            // went on through what it pushed): pushing "out" would push through.
            if (overlap > c.extent)
                continue;
            const float excess = overlap - c.slop;
            if (!(excess > 0.0f))
                continue;
            // An excess within float noise goes at once: a fraction of it would round to
            // nothing, and a pair pushed from both sides (a box between a wall and a pile)
            // would stay a few float steps beyond the slop for good, and never sleep.
            const float correction = excess <= noiseOf(c) ? excess
                                                          : std::min(options_.correction * excess,
                                                                     0.25f * (c.extent - c.slop));
            // The body that holds the other stays put (orderBySupport); where neither holds,
            // the two share the correction by inverse mass.
            const float shareA = c.supporter == 1   ? 0.0f
                                 : c.supporter == 2 ? (c.invMassA > 0.0f ? 1.0f : 0.0f)
                                                    : c.invMassA * c.effectiveMass;
            const float shareB = c.supporter == 2   ? 0.0f
                                 : c.supporter == 1 ? (c.invMassB > 0.0f ? 1.0f : 0.0f)
                                                    : c.invMassB * c.effectiveMass;
            const float moveA = correction * shareA;
            const float moveB = correction * shareB;
            a.position[c.axis] += c.sign * moveA;
            b.position[c.axis] -= c.sign * moveB;
            moved = true;
        }
        return moved;
    }

    /// Events of the step (docs/events.md): contacts that touch where the step leaves
    /// them, sensor overlaps, bodies crushed by kinematic ones; touching flags.
    void report() {
        for (const Contact& c : contacts_) {
            // The solver bodies hold where the step leaves every body of a contact.
            const SolverBody& a = bodies_[c.ia];
            const SolverBody& b = bodies_[c.ib];
            const float gap = -overlapOf(c);
            const float skin = std::max(2.0f * c.slop, kMinimumSkin * c.extent);
            if (gap <= skin)
                recordContact(w_, a.slot, b.slot, c.normal(), c.approachSpeed);
            // Only a dynamic body against an infinitely heavy one can be crushed.
            if ((c.invMassA == 0.0f) != (c.invMassB == 0.0f))
                findCrush(c, a.slot, b.slot, -gap);
        }
        for (const BodyPair& pair : sensorPairs_) {
            if (!w_.isLive(pair.a) || !w_.isLive(pair.b))
                continue;
            const Bounds sensor = w_.slots[pair.a].bounds();
            const Bounds visitor = w_.slots[pair.b].bounds();
            // Overlapping, not merely touching.
            if (sensor.min.x < visitor.max.x && visitor.min.x < sensor.max.x &&
                sensor.min.y < visitor.max.y && visitor.min.y < sensor.max.y)
                recordSensor(w_, pair.a, pair.b);
        }
        reportCrushes();
    }

    /// A dynamic body that a kinematic body moving into it overlaps deeper than
    /// kCrushDepth of its size: a candidate, crushed if something holds it on the other
    /// side (reportCrushes).
    void findCrush(const Contact& c, std::uint32_t slotA, std::uint32_t slotB, float overlap) {
        const Body& a = w_.slots[slotA];
        const Body& b = w_.slots[slotB];
        const bool kinematicA = a.type == BodyType::Kinematic,
                   kinematicB = b.type == BodyType::Kinematic;
        if (kinematicA == kinematicB || (kinematicA ? !b.isDynamic() : !a.isDynamic()))
            return;
        const std::uint32_t body = kinematicA ? slotB : slotA;
        const std::uint32_t by = kinematicA ? slotA : slotB;
        // The direction from the kinematic body into the dynamic one.
        const Vec2 into = kinematicA ? -c.normal() : c.normal();
        const float half = c.axis == 0 ? w_.slots[body].half.x : w_.slots[body].half.y;
        if (dot(w_.slots[by].velocity, into) > 0.0f && overlap > kCrushDepth * half)
            crushCandidates_.push_back({body, by, into});
    }

    /// Each candidate with a contact on its far side, against something heavy (static,
    /// kinematic, or resting on them: a supported body), is crushed.
    void reportCrushes() {
        if (crushCandidates_.empty())
            return;
        for (const CrushCandidate& candidate : crushCandidates_) {
            for (const Contact& c : contacts_) {
                const std::uint32_t slotA = bodies_[c.ia].slot, slotB = bodies_[c.ib].slot;
                if (slotA != candidate.body && slotB != candidate.body)
                    continue;
                const std::uint32_t other = slotA == candidate.body ? slotB : slotA;
                // The other body pushes back against the kinematic one's push.
                const Vec2 push = slotA == candidate.body ? c.normal() : -c.normal();
                if (other == candidate.by || dot(push, candidate.into) >= 0.0f)
                    continue;
                // Heavy: static or kinematic, or a body that holds the candidate (resting
                // on the ground below it, or backed by a wall behind it).
                const bool otherHolds = c.supporter == (other == slotA ? 1 : 2);
                const bool heavy = !w_.slots[other].isDynamic() || otherHolds;
                if (heavy && c.totalImpulse() > 0.0f) {
                    w_.events.crushes.push_back(
                        {w_.idOf(candidate.body), w_.idOf(candidate.by), w_.idOf(other)});
                    break;
                }
            }
        }
        crushCandidates_.clear();
    }

    void remember() {
        ContactCache& cache = w_.contactCache;
        cache.beginRebuild(w_.slots.size());
        for (const Contact& c : contacts_)
            cache.count(bodies_[c.ia].slot);
        cache.endCounting();
        for (const Contact& c : contacts_) {
            const std::uint32_t slotA = bodies_[c.ia].slot, slotB = bodies_[c.ib].slot;
            Body& a = w_.slots[slotA];
            Body& b = w_.slots[slotB];
            // A pending bounce is kept only if the contact did stop the pair.
            const float total = c.totalImpulse();
            const float bounceSpeed = total > 0.0f ? c.bounceSpeed : 0.0f;
            cache.add(slotA, slotB,
                      {a.generation, b.generation, c.normal(), c.normalImpulse, c.tangentImpulse,
                       bounceSpeed});
            // How far the contact's impulse pushed each body out this step (position
            // correction was counted when it was written back); the held body felt none
            // of the shock pass's.
            a.separation +=
                c.normal() * ((c.supporter == 1 ? c.normalImpulse : total) * c.invMassA * dt_);
            b.separation -=
                c.normal() * ((c.supporter == 2 ? c.normalImpulse : total) * c.invMassB * dt_);
        }
        cache.endRebuild();
    }

    /// Float noise in the overlap of contact `c` where the solver bodies are now: a hair
    /// of the smaller half extent along the normal (kMinimumSkin), and four float steps
    /// at the pair's coordinates. Overlap within the slop and this is within the slop.
    float noiseOf(const Contact& c) const {
        const float pa = bodies_[c.ia].position[c.axis], pb = bodies_[c.ib].position[c.axis];
        const float largest = std::max({std::abs(pa), std::abs(pb), c.extent});
        return c.slop * noisePerSlop_ + 4.0f * ulpOf(largest);
    }

    /// Whether the pair overlaps deeper than the slop where the step leaves it, beyond
    /// float noise.
    bool beyondSlop(const Contact& c) const {
        const float overlap = overlapOf(c);
        // Centres that have passed each other: position correction leaves them alone.
        return overlap <= c.extent && overlap - c.slop > noiseOf(c);
    }

    /// Islands of awake dynamic bodies joined by contacts fall asleep together once every
    /// body of the island has been slow for kTimeToSleep. A body touching a moving
    /// kinematic body never sleeps: its platform may carry it off.
    void fallAsleep() {
        // Union-find over slots; the root of a set is its earliest-created body.
        parent_.resize(w_.slots.size());
        for (std::uint32_t slot : w_.movingSlots)
            parent_[slot] = slot;
        auto find = [&](std::uint32_t s) {
            while (parent_[s] != s)
                s = parent_[s] = parent_[parent_[s]];
            return s;
        };
        for (std::uint32_t slot : w_.movingSlots) {
            Body& body = w_.slots[slot];
            if (!body.isDynamic() || !w_.isLive(slot))
                continue;
            const float slow = kSleepSpeed * std::min(body.half.x, body.half.y);
            body.sleepTime = length(body.velocity) < slow ? body.sleepTime + dt_ : 0.0f;
        }
        for (const Contact& c : contacts_) {
            const std::uint32_t slotA = bodies_[c.ia].slot, slotB = bodies_[c.ib].slot;
            Body& a = w_.slots[slotA];
            Body& b = w_.slots[slotB];
            // Position correction has not finished with the pair: not at rest, however
            // slowly it moves them. Asleep, they would keep that overlap until woken.
            if (beyondSlop(c)) {
                a.sleepTime = 0.0f;
                b.sleepTime = 0.0f;
            }
            if (a.isDynamic() && b.isDynamic()) {
                std::uint32_t ra = find(slotA), rb = find(slotB);
                if (ra != rb) {
                    if (w_.rank[ra] > w_.rank[rb])
                        std::swap(ra, rb);
                    parent_[rb] = ra;
                }
            } else {
                const Body& other = a.isDynamic() ? b : a;
                if (other.type == BodyType::Kinematic &&
                    (other.velocity.x != 0.0f || other.velocity.y != 0.0f))
                    (a.isDynamic() ? a : b).sleepTime = 0.0f;
            }
        }
        // The shortest sleep time of each island decides.
        islandTime_.assign(w_.slots.size(), INFINITY);
        for (std::uint32_t slot : w_.movingSlots) {
            const Body& body = w_.slots[slot];
            if (body.isDynamic() && w_.isLive(slot)) {
                float& time = islandTime_[find(slot)];
                time = std::min(time, body.sleepTime);
            }
        }
        islandOf_.assign(w_.slots.size(), UINT32_MAX);
        for (std::uint32_t slot : w_.movingSlots) {
            Body& body = w_.slots[slot];
            if (!body.isDynamic() || !w_.isLive(slot) || islandTime_[find(slot)] < kTimeToSleep)
                continue;
            std::uint32_t& island = islandOf_[find(slot)];
            if (island == UINT32_MAX) {
                if (w_.freeIslands.empty()) {
                    island = std::uint32_t(w_.islands.size());
                    w_.islands.emplace_back();
                } else {
                    island = w_.freeIslands.back();
                    w_.freeIslands.pop_back();
                }
            }
            w_.islands[island].push_back(slot);
            body.asleep = true;
            body.island = island;
            body.velocity = {};
            w_.restingDirty = true;
        }
    }

    /// A body overlapped by a kinematic one deeper than this fraction of its half extent
    /// is being crushed (if held on the other side): the solver could not push it out.
    static constexpr float kCrushDepth = 0.1f;

    struct CrushCandidate {
        std::uint32_t body, by;
        Vec2 into;
    };
    std::vector<CrushCandidate> crushCandidates_;
    std::vector<BodyPair> sensorPairs_;
    std::vector<std::uint8_t> carried_; ///< by slot: already given its platform's change
    std::size_t sweepStart_ = 0;        ///< the first of sweptContacts_ the current sweep made

    /// Sleep when slower than this many half extents per second...
    static constexpr float kSleepSpeed = 0.05f;
    /// ... for this long, with all the island.
    static constexpr float kTimeToSleep = 0.5f;

    WorldState& w_;
    const PhysicalOptions options_; // a copy: a callback may change the world's
    float dt_;
    /// kMinimumSkin of the smaller half extent, as a multiple of a contact's slop.
    const float noisePerSlop_ = options_.slop > 0.0f ? kMinimumSkin / options_.slop : 0.0f;
    std::vector<BodyPair>& pairs_ = w_.pairs;
    std::vector<Contact>& contacts_ = w_.physical.contacts;
    static constexpr std::uint32_t kNoSolverBody = UINT32_MAX;
    std::vector<SolverBody>& bodies_ = w_.physical.bodies;
    std::vector<std::uint32_t>& solverIndex_ = w_.physical.solverIndex;
    std::vector<std::uint32_t>& levels_ = w_.physical.levels;
    std::vector<std::uint8_t>& backing_ = w_.physical.backing;
    std::vector<std::uint8_t>& sweepFlags_ = w_.physical.sweepFlags;
    std::vector<Contact>& sweptContacts_ = w_.physical.sweptContacts;
    std::vector<std::uint64_t>& vetoed_ = w_.physical.vetoed;
    std::vector<std::uint32_t>& offsets_ = w_.physical.offsets;
    std::vector<std::uint32_t>& neighbours_ = w_.physical.neighbours;
    std::vector<std::uint32_t>& fill_ = w_.physical.fill;
    std::vector<std::uint32_t>& queue_ = w_.physical.queue;
    std::vector<std::uint32_t>& counts_ = w_.physical.counts;
    std::vector<std::uint32_t>& destination_ = w_.physical.destination;
    std::vector<std::uint32_t>& parent_ = w_.physical.parent;
    std::vector<float>& islandTime_ = w_.physical.islandTime;
    std::vector<std::uint32_t>& islandOf_ = w_.physical.islandOf;
};

} // namespace

void stepPhysical(WorldState& world, float dt) {
    PhysicalStep(world, dt).run();
}

} // namespace jostle
