// The classic model: the tutorial's update(dt), checkCollision and solveCollision,
// line for line, plus the two options of its "Physics" section (mass, coulomb).
//
// One deliberate difference from the tutorial's code: its response line
//     a.xv = a.xv - px*r + tx*f
// *adds* the fraction f of the tangent velocity, while its text says friction is velocity
// "lost". jostle follows the text: the tangent velocity becomes (1 - f) × t.
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jostle {

void integrateVelocity(const WorldDef& def, Body& body, float dt) {
    // The tutorial: d.yv = d.yv + grav, with grav = gravity*dt computed once.
    const Vec2 grav = def.gravity * dt;
    body.velocity += body.gravityScale == 1.0f ? grav : grav * body.gravityScale;
    if (body.damping > 0.0f) {
        const float k = 1.0f + body.damping * dt;
        body.velocity = {body.velocity.x / k, body.velocity.y / k};
    }
    // clampVec(xv, yv, maxVelocity): scale the vector down to the largest speed.
    if (std::isfinite(def.maxVelocity)) {
        const float d = length(body.velocity);
        if (d > def.maxVelocity) {
            const float n = def.maxVelocity / d;
            body.velocity = body.velocity * n;
        }
    }
}

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
        // The tutorial keeps two lists, statics and dynamics, in creation order. Kinematic
        // bodies go with the statics: the dynamic bodies collide with them the same way.
        for (BodyId id : w_.order) {
            (w_.slots[id.index].isDynamic() ? dynamics_ : statics_).push_back(id.index);
        }

        // update velocity vectors
        for (std::uint32_t d : dynamics_)
            integrateVelocity(w_.def, w_.slots[d], dt_);

        // Kinematic bodies move by their own velocity before the dynamic ones.
        for (std::uint32_t s : statics_) {
            Body& k = w_.slots[s];
            if (k.type == BodyType::Kinematic)
                k.position += k.velocity * dt_;
        }

        // move dynamic objects, then check and resolve their collisions
        for (std::size_t i = 0; i < dynamics_.size(); ++i) {
            const std::uint32_t a = dynamics_[i];
            if (!w_.isLive(a))
                continue; // destroyed by a callback earlier in this step
            Body& d = w_.slots[a];
            d.position += d.velocity * dt_;
            if (resolveAgainst(a, statics_.begin(), statics_.end()) == Outcome::Destroyed)
                continue;
            resolveAgainst(a, dynamics_.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                           dynamics_.end());
        }
    }

private:
    using Iterator = std::vector<std::uint32_t>::const_iterator;

    Outcome resolveAgainst(std::uint32_t a, Iterator first, Iterator last) {
        for (; first != last; ++first) {
            if (checkCollision(a, *first) == Outcome::Destroyed)
                return Outcome::Destroyed;
        }
        return Outcome::Kept;
    }

    // checkCollision and solveCollision of the tutorial.
    Outcome checkCollision(std::uint32_t ia, std::uint32_t ib) {
        if (!w_.isLive(ib))
            return Outcome::Kept;
        const std::optional<Vec2> separation =
            shortestSeparation(w_.slots[ia].box(), w_.slots[ib].box());
        if (!separation)
            return Outcome::Kept;
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

        float bounce = std::max(w_.slots[ia].bounce, w_.slots[ib].bounce);
        float friction = std::min(w_.slots[ia].friction, w_.slots[ib].friction);
        if (w_.preSolve) {
            Collision c{w_.idOf(ia), w_.idOf(ib), {nx, ny}, d, bounce, friction};
            const bool keep = w_.preSolve(c);
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
        // separate the two objects: moveShape(a, sx, sy)
        ba.position.x = ba.position.x + sx;
        ba.position.y = ba.position.y + sy;
        ba.separation += Vec2{sx, sy};

        // penetration component
        const float px = nx * ps;
        const float py = ny * ps;
        // tangent component
        const float tx = vx - px;
        const float ty = vy - py;
        // restitution
        const float r = 1.0f + bounce;
        // friction
        const float f = friction;

        const ClassicOptions& options = w_.def.classic;
        if (!options.mass && !options.coulomb) {
            // change the velocity of shape a (the text's friction: minus, not plus)
            ba.velocity.x = ba.velocity.x - px * r - tx * f;
            ba.velocity.y = ba.velocity.y - py * r - ty * f;
            return Outcome::Kept;
        }
        const Vec2 change = velocityChange({px, py}, {tx, ty}, ps, r, f, options.coulomb);
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
    std::vector<std::uint32_t> statics_;
};

} // namespace

void stepClassic(WorldState& world, float dt) {
    ClassicStep(world, dt).run();
}

} // namespace jostle
