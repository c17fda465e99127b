// The physical model: every contact of the step solved together.
//
//   1. velocities: gravity, damping, clamp (as in the classic model);
//   2. contacts: every pair that overlaps, touches, or will touch within the step
//      (speculative contacts: the solver lets such a pair close its gap, no more);
//   3. support levels: static and kinematic bodies are level 0, a dynamic body touching
//      a level-k body is level k+1; contacts are solved from the ground up;
//   4. sequential impulses: a few passes over all contacts; each pass nudges the
//      accumulated normal impulse (never pulling: >= 0) and the friction impulse
//      (Coulomb: |friction| <= mu × normal), starting from last step's (warm starting);
//   5. shock propagation: one last normal pass, from the ground up, in which the lower
//      body of each contact is held fixed: what the passes before left unresolved, the
//      upper body takes, so a heavy box cannot squash a light one into the floor;
//   6. positions from velocities;
//   7. position correction: overlap beyond the slop is removed by moving the bodies
//      (the upper one, across support levels; both, by inverse mass, within a level);
//      velocities are left alone, so no energy is added.
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

struct Contact {
    std::uint32_t a, b; ///< slots
    Vec2 normal;        ///< unit, along x or y, pointing from b towards a
    float extent;       ///< sum of the half extents along the normal
    float slop;         ///< overlap left alone
    float friction;
    float invMassA, invMassB;
    float effectiveMass; ///< 1 / (invMassA + invMassB)
    /// The relative normal velocity must end >= this: 0 to stop, -gap/dt to let a
    /// speculative contact close its gap, -bounce × approach speed to bounce.
    float targetSpeed;
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    float bounceSpeed = 0.0f; ///< to remember: bounce at this speed next step
    /// Which body is held fixed across support levels: 0 none, 1 a, 2 b.
    int supporter = 0;
    std::uint32_t level = 0;  ///< the lower support level of the two
    float correctionA = 0.0f; ///< distance moved out by position correction, for separation()
    float correctionB = 0.0f;
};

/// Touching tolerance when the slop is 0, as a fraction of the half extent: float noise.
constexpr float kMinimumSkin = 1e-4f;

Vec2 tangentOf(Vec2 normal) {
    return {-normal.y, normal.x};
}

float combineFriction(FrictionMix mix, float a, float b) {
    return mix == FrictionMix::GeometricMean ? std::sqrt(a * b) : std::min(a, b);
}

class PhysicalStep {
public:
    PhysicalStep(WorldState& world, float dt) : w_(world), options_(world.def.physical), dt_(dt) {}

    void run() {
        for (BodyId id : w_.order) {
            Body& body = w_.slots[id.index];
            if (body.isDynamic() && !body.asleep)
                integrateVelocity(w_.def, body, dt_);
        }
        findPairs(w_, dt_, pairs_);
        buildContacts();
        orderBySupport();
        warmStart();
        for (int i = 0; i < options_.velocityIterations; ++i)
            solveVelocities();
        propagateShock();
        sweepFastBodies();
        integratePositions();
        for (int i = 0; i < options_.positionIterations; ++i)
            correctPositions();
        remember();
        if (w_.def.sleeping)
            fallAsleep();
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

    void buildContacts() {
        const float threshold = restitutionThreshold();
        contacts_.clear();
        contacts_.reserve(pairs_.size());
        for (const BodyPair& pair : pairs_) {
            if (!w_.isLive(pair.a) || !w_.isLive(pair.b))
                continue; // destroyed by a callback earlier in this loop
            const Body& a = w_.slots[pair.a];
            const Body& b = w_.slots[pair.b];
            const Vec2 d = a.position - b.position;
            const float gapX = std::abs(d.x) - (a.half.x + b.half.x);
            const float gapY = std::abs(d.y) - (a.half.y + b.half.y);
            // Overlap within twice the slop is resting contact, not penetration.
            const float slopX = options_.slop * std::min(a.half.x, b.half.x);
            const float slopY = options_.slop * std::min(a.half.y, b.half.y);
            const float skinX = skinOf(a.half.x, b.half.x);
            const float skinY = skinOf(a.half.y, b.half.y);
            const bool alongX = contactAxis(gapX, gapY, skinX, skinY) == Axis::X;
            const float gap = alongX ? gapX : gapY;
            const Vec2 normal = alongX ? Vec2{d.x < 0.0f ? -1.0f : 1.0f, 0.0f}
                                       : Vec2{0.0f, d.y < 0.0f ? -1.0f : 1.0f};
            const float approach = dot(a.velocity - b.velocity, normal);
            // Apart, and not closing the gap within this step: no contact.
            if (gap > 0.0f && gap + approach * dt_ > 0.0f)
                continue;

            Contact c;
            c.a = pair.a;
            c.b = pair.b;
            c.normal = normal;
            c.extent = alongX ? a.half.x + b.half.x : a.half.y + b.half.y;
            c.slop = alongX ? slopX : slopY;
            c.friction = combineFriction(options_.frictionMix, a.friction, b.friction);
            float bounce = std::max(a.bounce, b.bounce);

            if (w_.preSolve) {
                Collision info{w_.idOf(pair.a), w_.idOf(pair.b), normal, -gap, bounce, c.friction};
                const bool keep = w_.preSolve(info);
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
            const float invMassSum = c.invMassA + c.invMassB;
            if (invMassSum <= 0.0f)
                continue; // the callback made both infinitely heavy
            c.effectiveMass = 1.0f / invMassSum;

            // Warm start from last step's impulses if this is the same contact.
            const CachedContact* cached = nullptr;
            if (auto found = w_.contactCache.find(pairKey(pair.a, pair.b));
                found != w_.contactCache.end() && found->second.generationA == ba.generation &&
                found->second.generationB == bb.generation && found->second.normal == normal) {
                cached = &found->second;
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
    }

    /// Support levels (see the top of the file), then contacts sorted from the ground up,
    /// ties in pair order.
    void orderBySupport() {
        constexpr std::uint32_t unsupported = UINT32_MAX;
        levels_.assign(w_.slots.size(), unsupported);
        for (BodyId id : w_.order)
            if (!w_.slots[id.index].isDynamic())
                levels_[id.index] = 0;
        // Relax until nothing changes: a breadth-first search over the contact list, which
        // is short and already in a fixed order.
        for (bool changed = true; changed;) {
            changed = false;
            for (const Contact& c : contacts_) {
                std::uint32_t& la = levels_[c.a];
                std::uint32_t& lb = levels_[c.b];
                if (lb != unsupported && la > lb + 1) {
                    la = lb + 1;
                    changed = true;
                }
                if (la != unsupported && lb > la + 1) {
                    lb = la + 1;
                    changed = true;
                }
            }
        }
        for (Contact& c : contacts_) {
            const std::uint32_t la = levels_[c.a];
            const std::uint32_t lb = levels_[c.b];
            c.level = std::min(la, lb);
            c.supporter = la < lb ? 1 : lb < la ? 2 : 0;
        }
        std::stable_sort(contacts_.begin(), contacts_.end(),
                         [](const Contact& p, const Contact& q) { return p.level < q.level; });
    }

    void applyImpulse(const Contact& c, Vec2 impulse) {
        Body& a = w_.slots[c.a];
        Body& b = w_.slots[c.b];
        a.velocity += impulse * c.invMassA;
        b.velocity -= impulse * c.invMassB;
    }

    void warmStart() {
        for (const Contact& c : contacts_)
            applyImpulse(c, c.normal * c.normalImpulse + tangentOf(c.normal) * c.tangentImpulse);
    }

    void solveVelocities() {
        for (Contact& c : contacts_) {
            const Vec2 tangent = tangentOf(c.normal);
            // Normal: push (never pull) until the pair stops approaching.
            {
                const Vec2 relative = w_.slots[c.a].velocity - w_.slots[c.b].velocity;
                const float speed = dot(relative, c.normal);
                const float impulse = -c.effectiveMass * (speed - c.targetSpeed);
                const float total = std::max(c.normalImpulse + impulse, 0.0f);
                applyImpulse(c, c.normal * (total - c.normalImpulse));
                c.normalImpulse = total;
            }
            // Friction: stop the sliding, within Coulomb's cone.
            {
                const Vec2 relative = w_.slots[c.a].velocity - w_.slots[c.b].velocity;
                const float speed = dot(relative, tangent);
                const float impulse = -c.effectiveMass * speed;
                const float limit = c.friction * c.normalImpulse;
                const float total = std::clamp(c.tangentImpulse + impulse, -limit, limit);
                applyImpulse(c, tangent * (total - c.tangentImpulse));
                c.tangentImpulse = total;
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
            const Vec2 relative = w_.slots[c.a].velocity - w_.slots[c.b].velocity;
            const float speed = dot(relative, c.normal);
            const float total = std::max(c.normalImpulse - (speed - c.targetSpeed) / invMass, 0.0f);
            const Vec2 impulse = c.normal * (total - c.normalImpulse);
            if (c.supporter == 1)
                w_.slots[c.b].velocity -= impulse * c.invMassB;
            else
                w_.slots[c.a].velocity += impulse * c.invMassA;
            c.normalImpulse = total;
        }
    }

    /// Continuous collision: a body that moves more than its own half size in this step
    /// is swept along its motion against static and kinematic bodies (and, if it is a
    /// bullet, dynamic ones), and stopped where it first meets one, its velocity into
    /// that body removed. Contacts already stop what they foresee; this catches the rest,
    /// so nothing passes through a wall however fast it goes.
    void sweepFastBodies() {
        for (std::uint32_t slot : w_.movingSlots) {
            Body& body = w_.slots[slot];
            if (!body.isDynamic() || !w_.isLive(slot))
                continue;
            const Vec2 motion = body.velocity * dt_;
            const float size = std::min(body.half.x, body.half.y);
            if (std::abs(motion.x) <= size && std::abs(motion.y) <= size)
                continue;
            sweep(slot, motion);
        }
    }

    void sweep(std::uint32_t slot, Vec2 motion) {
        Body& body = w_.slots[slot];
        const Bounds swept{{std::min(body.position.x, body.position.x + motion.x) - body.half.x,
                            std::min(body.position.y, body.position.y + motion.y) - body.half.y},
                           {std::max(body.position.x, body.position.x + motion.x) + body.half.x,
                            std::max(body.position.y, body.position.y + motion.y) + body.half.y}};
        std::optional<Hit> first;
        std::uint32_t firstSlot = 0;
        auto consider = [&](std::uint32_t other) {
            const Body& obstacle = w_.slots[other];
            if (other == slot || !w_.isLive(other))
                return;
            if (obstacle.isDynamic() && !body.bullet)
                return;
            const Vec2 relative = motion - obstacle.velocity * dt_;
            const Vec2 skin{skinOf(body.half.x, obstacle.half.x),
                            skinOf(body.half.y, obstacle.half.y)};
            const std::optional<Hit> hit = sweepBox(body.box(), relative, obstacle.box(), skin);
            if (hit && (!first || hit->time < first->time)) {
                first = hit;
                firstSlot = other;
            }
        };
        w_.restingGrid.query(swept, [&](std::uint32_t i) {
            if (w_.slots[w_.restingSlots[i]].type == BodyType::Static)
                consider(w_.restingSlots[i]);
        });
        w_.movingGrid.query(swept, [&](std::uint32_t i) { consider(w_.movingSlots[i]); });
        if (!first)
            return;
        // Stop at the first hit: move there now, and take away the part of the velocity
        // that goes into the obstacle, so that the step's own motion starts from there.
        const Body& obstacle = w_.slots[firstSlot];
        const Vec2 relative = motion - obstacle.velocity * dt_;
        body.position += relative * first->time;
        const float into = dot(body.velocity - obstacle.velocity, first->normal);
        if (into < 0.0f)
            body.velocity -= first->normal * into;
    }

    float skinOf(float halfA, float halfB) const {
        const float smaller = std::min(halfA, halfB);
        return std::max(2.0f * options_.slop * smaller, kMinimumSkin * smaller);
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

    void correctPositions() {
        for (Contact& c : contacts_) {
            Body& a = w_.slots[c.a];
            Body& b = w_.slots[c.b];
            const float overlap = c.extent - dot(a.position - b.position, c.normal);
            // Centres that have passed each other along the normal (a kinematic body that
            // went on through what it pushed): pushing "out" would push through.
            if (overlap > c.extent)
                continue;
            const float largest = 0.25f * (c.extent - c.slop);
            const float correction =
                std::clamp(options_.correction * (overlap - c.slop), 0.0f, largest);
            if (correction <= 0.0f)
                continue;
            // Across support levels the supporter stays put; within a level the two share
            // the correction by inverse mass.
            const float shareA = c.supporter == 1   ? 0.0f
                                 : c.supporter == 2 ? (c.invMassA > 0.0f ? 1.0f : 0.0f)
                                                    : c.invMassA * c.effectiveMass;
            const float shareB = c.supporter == 2   ? 0.0f
                                 : c.supporter == 1 ? (c.invMassB > 0.0f ? 1.0f : 0.0f)
                                                    : c.invMassB * c.effectiveMass;
            const float moveA = correction * shareA;
            const float moveB = correction * shareB;
            a.position += c.normal * moveA;
            b.position -= c.normal * moveB;
            c.correctionA += moveA;
            c.correctionB += moveB;
        }
    }

    void remember() {
        w_.contactCache.clear();
        for (const Contact& c : contacts_) {
            Body& a = w_.slots[c.a];
            Body& b = w_.slots[c.b];
            // A pending bounce is kept only if the contact did stop the pair.
            const float bounceSpeed = c.normalImpulse > 0.0f ? c.bounceSpeed : 0.0f;
            w_.contactCache[pairKey(c.a, c.b)] = {a.generation,    b.generation,     c.normal,
                                                  c.normalImpulse, c.tangentImpulse, bounceSpeed};
            // How far the contact pushed each body out this step: its impulse's share
            // of the motion, and the position correction.
            a.separation += c.normal * (c.normalImpulse * c.invMassA * dt_ + c.correctionA);
            b.separation -= c.normal * (c.normalImpulse * c.invMassB * dt_ + c.correctionB);
        }
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
            Body& a = w_.slots[c.a];
            Body& b = w_.slots[c.b];
            if (a.isDynamic() && b.isDynamic()) {
                std::uint32_t ra = find(c.a), rb = find(c.b);
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

    /// Sleep when slower than this many half extents per second...
    static constexpr float kSleepSpeed = 0.05f;
    /// ... for this long, with all the island.
    static constexpr float kTimeToSleep = 0.5f;

    WorldState& w_;
    const PhysicalOptions options_; // a copy: a callback may change the world's
    float dt_;
    std::vector<BodyPair> pairs_;
    std::vector<Contact> contacts_;
    std::vector<std::uint32_t> levels_; ///< support level by slot
    std::vector<std::uint32_t> parent_; ///< union-find of islands, by slot
    std::vector<float> islandTime_;
    std::vector<std::uint32_t> islandOf_;
};

} // namespace

void stepPhysical(WorldState& world, float dt) {
    PhysicalStep(world, dt).run();
}

} // namespace jostle
