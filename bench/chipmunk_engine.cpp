// The scene in Chipmunk 7: every body a box with infinite moment of inertia, so it
// never rotates.
//
// Mapping, and why:
// - Chipmunk multiplies the friction of the two shapes, and their elasticity. A shape
//   gets the square root of the body's value, so a pair that shares one value (as the
//   shared scenes keep to) gets that value, as in jostle and Box2D; a pair with two values
//   gets sqrt(a b), Box2D's friction rule, where jostle takes min (friction) and max
//   (bounce).
// - Mass is the jostle body's; the shapes carry none.
// - Collision slop 0.005 units instead of Chipmunk's 0.1: the overlap jostle (1% of half
//   a unit box) and Box2D (b2_linearSlop) leave, so the penetration figures compare.
// - 8 iterations, as Box2D's velocity iterations. No sleeping (the sleep time threshold
//   stays at its default, infinity). Default spatial index (the bounding-box tree),
//   single-threaded cpSpace.
// - Debian builds Chipmunk with its debug checks on (it says so on standard output when
//   the first space is made): that is the Chipmunk a Debian user gets, so it is measured
//   as it comes.
// - Gravity scale, damping and maxVelocity, which Chipmunk has no per-body setting for,
//   go through a velocity-update function, only for scenes that use them.
#include "engine.hpp"

#include <chipmunk/chipmunk.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace jostle::bench {
namespace {

/// Chipmunk prints a banner on standard output when the first space is made. The bench's
/// standard output is its table (a markdown table may be pasted into a document), so the
/// first space is made once with standard output sent to /dev/null.
void swallowBanner() {
    static const bool done = [] {
        std::fflush(stdout);
        const int saved = dup(STDOUT_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        if (saved >= 0 && null >= 0)
            dup2(null, STDOUT_FILENO);
        cpSpaceFree(cpSpaceNew());
        std::fflush(stdout);
        if (saved >= 0 && null >= 0)
            dup2(saved, STDOUT_FILENO);
        if (null >= 0)
            close(null);
        if (saved >= 0)
            close(saved);
        return true;
    }();
    (void)done;
}

class ChipmunkEngine final : public Engine {
public:
    explicit ChipmunkEngine(const Scene& scene) : scene_(scene), space_(newSpace()) {
        cpSpaceSetUserData(space_, this);
        cpSpaceSetIterations(space_, kIterations);
        cpSpaceSetGravity(space_, cpv(scene.world.gravity.x, scene.world.gravity.y));
        cpSpaceSetCollisionSlop(space_, 0.005);
        const bool customVelocity = needsVelocityFunction(scene);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            addBody(scene.bodies[i].def, i, customVelocity);
    }

    ~ChipmunkEngine() override {
        // A space does not own its bodies and shapes: collect them, then free everything.
        std::vector<cpBody*> bodies;
        cpSpaceEachBody(
            space_,
            [](cpBody* body, void* data) {
                static_cast<std::vector<cpBody*>*>(data)->push_back(body);
            },
            &bodies);
        std::vector<cpShape*> shapes;
        for (cpBody* body : bodies)
            cpBodyEachShape(
                body,
                [](cpBody*, cpShape* shape, void* data) {
                    static_cast<std::vector<cpShape*>*>(data)->push_back(shape);
                },
                &shapes);
        cpSpaceFree(space_);
        for (cpShape* shape : shapes)
            cpShapeFree(shape);
        for (cpBody* body : bodies)
            cpBodyFree(body);
    }

    ChipmunkEngine(const ChipmunkEngine&) = delete;
    ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

    void step(float dt) override { cpSpaceStep(space_, dt); }

    void positions(std::span<Vec2> out) const override {
        struct Target {
            std::span<Vec2> out;
        } target{out};
        cpSpaceEachBody(
            space_,
            [](cpBody* body, void* data) {
                auto& to = static_cast<Target*>(data)->out;
                const auto index = reinterpret_cast<std::uintptr_t>(cpBodyGetUserData(body));
                const cpVect p = cpBodyGetPosition(body);
                if (index < to.size())
                    to[index] = {static_cast<float>(p.x), static_cast<float>(p.y)};
            },
            &target);
    }

private:
    static cpSpace* newSpace() {
        swallowBanner();
        return cpSpaceNew();
    }

    static bool needsVelocityFunction(const Scene& scene) {
        if (std::isfinite(scene.world.maxVelocity))
            return true;
        for (const SceneBody& body : scene.bodies)
            if (body.def.gravityScale != 1.0f || body.def.damping != 0.0f)
                return true;
        return false;
    }

    /// jostle's velocity step, in jostle's order: gravity × scale, damping, clamp.
    static void updateVelocity(cpBody* body, cpVect gravity, cpFloat damping, cpFloat dt) {
        const auto* self =
            static_cast<const ChipmunkEngine*>(cpSpaceGetUserData(cpBodyGetSpace(body)));
        const auto index = reinterpret_cast<std::uintptr_t>(cpBodyGetUserData(body));
        const BodyDef& def = self->scene_.bodies[index].def;
        cpBodyUpdateVelocity(body, cpvmult(gravity, def.gravityScale), damping, dt);
        cpVect v = cpvmult(cpBodyGetVelocity(body), 1.0 / (1.0 + cpFloat{def.damping} * dt));
        const cpFloat limit = self->scene_.world.maxVelocity;
        if (cpvlength(v) > limit)
            v = cpvmult(cpvnormalize(v), limit);
        cpBodySetVelocity(body, v);
    }

    void addBody(const BodyDef& def, std::size_t index, bool customVelocity) {
        cpBody* body = nullptr;
        switch (def.type) {
        case BodyType::Static:
            body = cpBodyNewStatic();
            break;
        case BodyType::Kinematic:
            body = cpBodyNewKinematic();
            break;
        case BodyType::Dynamic: {
            body = cpBodyNew(massOf(def), INFINITY);
            if (customVelocity)
                cpBodySetVelocityUpdateFunc(body, &ChipmunkEngine::updateVelocity);
            break;
        }
        }
        cpBodySetUserData(body, reinterpret_cast<cpDataPointer>(index));
        cpBodySetPosition(body, cpv(def.x, def.y));
        cpBodySetVelocity(body, cpv(def.vx, def.vy));
        cpSpaceAddBody(space_, body);

        cpShape* shape = cpBoxShapeNew(body, 2.0 * cpFloat{def.hw}, 2.0 * cpFloat{def.hh}, 0.0);
        cpShapeSetFriction(shape, std::sqrt(def.friction));
        cpShapeSetElasticity(shape, std::sqrt(def.bounce));
        cpSpaceAddShape(space_, shape);
    }

    static constexpr int kIterations = 8;
    const Scene& scene_;
    cpSpace* space_;
};

} // namespace

std::unique_ptr<Engine> makeChipmunk(const Scene& scene) {
    return std::make_unique<ChipmunkEngine>(scene);
}

std::string_view describeChipmunk() {
    return "chipmunk: Chipmunk 7.0.3 (Debian libchipmunk-dev, built with its debug checks on), "
           "infinite moment, sqrt of friction and bounce per shape (Chipmunk multiplies a "
           "pair's), collision slop 0.005, 8 iterations, no sleeping";
}

} // namespace jostle::bench
