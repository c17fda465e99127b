// The scene in Box2D v3 (3.2), when CMake is given an installed one
// (-DJOSTLE_BENCH_BOX2D3=<prefix>; Debian packages only 2.4.1): every body a box with its
// rotation locked. Built alone against that prefix's headers, since both versions install
// box2d/box2d.h.
//
// Mapping, and why:
// - b2MakeBox(hw, hh): v3's polygons have no skin (its contacts are speculative), so the
//   box that collides is the scene's box.
// - Density is the jostle body's mass over the box's area, so masses agree; friction and
//   restitution as the body's (Box2D mixes friction by sqrt(a b), jostle by min(a, b):
//   equal when a pair shares one value, as the shared scenes do); the restitution
//   threshold is jostle's (2 |g| dt unless the scene sets one).
// - 4 substeps (Box2D's recommended count), sleeping off, continuous collision as Box2D
//   ships it; on N workers, its own scheduler (workerCount, no task callbacks).
#include "engine.hpp"

#include <box2d/box2d.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace jostle::bench {
namespace {

class Box2D3Engine final : public Engine {
public:
    Box2D3Engine(const Scene& scene, int workers) {
        b2WorldDef def = b2DefaultWorldDef();
        def.gravity = {scene.world.gravity.x, scene.world.gravity.y};
        def.enableSleep = false;
        def.restitutionThreshold = restitutionThresholdOf(scene);
        def.workerCount = workers;
        world_ = b2CreateWorld(&def);
        bodies_.reserve(scene.bodies.size());
        for (const SceneBody& body : scene.bodies)
            bodies_.push_back(addBody(body.def));
    }
    ~Box2D3Engine() override { b2DestroyWorld(world_); }
    Box2D3Engine(const Box2D3Engine&) = delete;
    Box2D3Engine& operator=(const Box2D3Engine&) = delete;

    void step(float dt) override { b2World_Step(world_, dt, kSubSteps); }

    void positions(std::span<Vec2> out) const override {
        for (std::size_t i = 0; i < bodies_.size() && i < out.size(); ++i) {
            const b2Vec2 p = b2Body_GetPosition(bodies_[i]);
            out[i] = {p.x, p.y};
        }
    }

private:
    b2BodyId addBody(const BodyDef& def) {
        b2BodyDef bodyDef = b2DefaultBodyDef();
        bodyDef.type = byType(def.type, b2_staticBody, b2_kinematicBody, b2_dynamicBody);
        bodyDef.position = {def.x, def.y};
        bodyDef.linearVelocity = {def.vx, def.vy};
        bodyDef.motionLocks.angularZ = true;
        bodyDef.isBullet = def.bullet;
        bodyDef.gravityScale = def.gravityScale;
        bodyDef.linearDamping = def.damping;
        bodyDef.enableSleep = false;
        const b2BodyId body = b2CreateBody(world_, &bodyDef);

        b2ShapeDef shape = b2DefaultShapeDef();
        shape.density = massOf(def) / (4.0f * def.hw * def.hh);
        shape.material.friction = def.friction;
        shape.material.restitution = def.bounce;
        const b2Polygon box = b2MakeBox(def.hw, def.hh);
        b2CreatePolygonShape(body, &shape, &box);
        return body;
    }

    static constexpr int kSubSteps = 4;
    b2WorldId world_;
    std::vector<b2BodyId> bodies_;
};

} // namespace

std::unique_ptr<Engine> makeBox2D3(const Scene& scene, int workers) {
    return std::make_unique<Box2D3Engine>(scene, workers);
}

std::string_view describeBox2D3() {
    return "box2d3: Box2D v3 (built by hand, -DJOSTLE_BENCH_BOX2D3), rotation locked, b2MakeBox "
           "(no skin), friction and bounce as the body's, 4 substeps, sleeping off, its own "
           "scheduler on N workers";
}

} // namespace jostle::bench
