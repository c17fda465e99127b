// The scene in Box2D 2.4.1: every body a box with fixed rotation.
//
// Mapping, and why:
// - Box2D puts a skin of b2_polygonRadius (0.01) around every polygon and keeps resting
//   boxes that far apart, so a box made with SetAsBox(hw, hh) behaves as one of
//   hw + 0.01. We shrink the polygon by the skin so the box that collides is the scene's
//   box, and stacks stand as high as in the other engines.
// - Density is the jostle body's mass over the polygon's area, so masses agree.
// - friction = the body's friction (Box2D mixes sqrt(a b), jostle min(a, b): equal when a
//   pair shares one value, which the shared scenes keep to); restitution = bounce (both
//   mix with max); the restitution threshold is jostle's (2 |g| dt unless the scene sets
//   one), not Box2D's 1 unit/s.
// - Box2D caps a body's travel at b2_maxTranslation (2 units) per step, 120 units/s at
//   60 Hz; the shared scenes stay below it. A scene's maxVelocity cannot be mapped.
// - 8 velocity and 3 position iterations, Box2D's recommended setting; sleeping off;
//   continuous collision against static bodies on, as Box2D ships.
#include "engine.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

namespace jostle::bench {
namespace {

class Box2DEngine final : public Engine {
public:
    explicit Box2DEngine(const Scene& scene)
        : world_(std::make_unique<b2World>(b2Vec2(scene.world.gravity.x, scene.world.gravity.y))) {
        world_->SetAllowSleeping(false);
        const float threshold = restitutionThresholdOf(scene);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            addBody(scene.bodies[i].def, i, threshold);
    }

    void step(float dt) override { world_->Step(dt, kVelocityIterations, kPositionIterations); }

    void positions(std::span<Vec2> out) const override {
        for (b2Body* body = world_->GetBodyList(); body != nullptr; body = body->GetNext()) {
            const std::uintptr_t index = body->GetUserData().pointer;
            const b2Vec2& p = body->GetPosition();
            if (index < out.size())
                out[index] = {p.x, p.y};
        }
    }

private:
    void addBody(const BodyDef& def, std::size_t index, float threshold) {
        b2BodyDef bodyDef;
        bodyDef.type = byType(def.type, b2_staticBody, b2_kinematicBody, b2_dynamicBody);
        bodyDef.position.Set(def.x, def.y);
        bodyDef.linearVelocity.Set(def.vx, def.vy);
        bodyDef.fixedRotation = true;
        bodyDef.bullet = def.bullet;
        bodyDef.gravityScale = def.gravityScale;
        bodyDef.linearDamping = def.damping; // same law: v /= 1 + damping dt
        bodyDef.allowSleep = false;
        bodyDef.userData.pointer = index; // its place in the scene, for positions()
        b2Body* body = world_->CreateBody(&bodyDef);

        const float hw = std::max(def.hw - b2_polygonRadius, 0.5f * def.hw);
        const float hh = std::max(def.hh - b2_polygonRadius, 0.5f * def.hh);
        b2PolygonShape box;
        box.SetAsBox(hw, hh);
        b2FixtureDef fixture;
        fixture.shape = &box;
        const float mass = massOf(def);
        fixture.density = mass / (4.0f * hw * hh);
        fixture.friction = def.friction;
        fixture.restitution = def.bounce;
        fixture.restitutionThreshold = threshold;
        body->CreateFixture(&fixture);
    }

    static constexpr int kVelocityIterations = 8;
    static constexpr int kPositionIterations = 3;
    std::unique_ptr<b2World> world_;
};

} // namespace

std::unique_ptr<Engine> makeBox2D(const Scene& scene) {
    return std::make_unique<Box2DEngine>(scene);
}

std::string_view describeBox2D() {
    return "box2d: Box2D 2.4.1 (Debian libbox2d-dev), fixed rotation, SetAsBox shrunk by the "
           "0.01 skin, friction and bounce as the body's, 8 velocity / 3 position iterations, "
           "sleeping off";
}

} // namespace jostle::bench
