// The classic model against the tutorial itself.
//
// `Tutorial` below is the tutorial's Lua code transliterated line by line into C++ floats,
// with plain structs and two arrays (statics, dynamics), nothing of jostle's. jostle's
// classic model, with its handles, storage and callbacks, must produce the very same
// floats, bit for bit, on random scenes. The one change from the printed code is the
// friction sign the tutorial's text asks for (tangent velocity is lost: `- tx*f`).
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace jostle {
namespace {

struct Shape {
    float x, y, hw, hh;
    float xv = 0, yv = 0;
    float bounce = 0, friction = 0;
};

struct Tutorial {
    float gravity = 0;
    float maxVelocity = 0; // 0: no clamp
    std::vector<Shape> statics;
    std::vector<Shape> dynamics;

    static void clampVec(float& x, float& y, float m) {
        const float d = std::sqrt(x * x + y * y);
        if (d > m) {
            const float n = m / d;
            x = x * n;
            y = y * n;
        }
    }

    static void moveShape(Shape& s, float dx, float dy) {
        s.x = s.x + dx;
        s.y = s.y + dy;
    }

    static bool testRectRect(const Shape& a, const Shape& b, float& sx, float& sy) {
        float dx = a.x - b.x, dy = a.y - b.y;
        float adx = std::abs(dx), ady = std::abs(dy);
        float shw = a.hw + b.hw, shh = a.hh + b.hh;
        if (adx >= shw || ady >= shh)
            return false;
        sx = shw - adx;
        sy = shh - ady;
        if (sx < sy) {
            if (sx > 0)
                sy = 0;
        } else {
            if (sy > 0)
                sx = 0;
        }
        if (dx < 0)
            sx = -sx;
        if (dy < 0)
            sy = -sy;
        return true;
    }

    static void solveCollision(Shape& a, const Shape& b, float sx, float sy) {
        float d = std::sqrt(sx * sx + sy * sy);
        float nx = sx / d, ny = sy / d;
        float vx = a.xv - b.xv, vy = a.yv - b.yv;
        float ps = vx * nx + vy * ny;
        if (ps > 0)
            return;
        moveShape(a, sx, sy);
        float px = nx * ps, py = ny * ps;
        float tx = vx - px, ty = vy - py;
        float r = 1 + std::max(a.bounce, b.bounce);
        float f = std::min(a.friction, b.friction);
        a.xv = a.xv - px * r - tx * f;
        a.yv = a.yv - py * r - ty * f;
    }

    static void checkCollision(Shape& a, const Shape& b) {
        float sx, sy;
        if (testRectRect(a, b, sx, sy))
            solveCollision(a, b, sx, sy);
    }

    void update(float dt) {
        float grav = gravity * dt;
        for (Shape& d : dynamics) {
            d.yv = d.yv + grav;
            if (maxVelocity > 0)
                clampVec(d.xv, d.yv, maxVelocity);
        }
        for (std::size_t i = 0; i < dynamics.size(); ++i) {
            Shape& d = dynamics[i];
            moveShape(d, d.xv * dt, d.yv * dt);
            for (const Shape& s : statics)
                checkCollision(d, s);
            for (std::size_t j = i + 1; j < dynamics.size(); ++j)
                checkCollision(d, dynamics[j]);
        }
    }
};

/// A random scene built twice: in jostle and in the transliteration. Bodies are created
/// in a random interleaving of statics and dynamics; each list keeps creation order.
struct TwinScenes {
    Tutorial tutorial;
    World world;
    std::vector<BodyId> dynamicIds;

    TwinScenes(unsigned seed, float gravity, float maxVelocity)
        : world(WorldDef{.gravity = {0, gravity},
                         .maxVelocity =
                             maxVelocity > 0 ? maxVelocity : std::numeric_limits<float>::infinity(),
                         .solver = Solver::Classic}) {
        tutorial.gravity = gravity;
        tutorial.maxVelocity = maxVelocity;
        std::mt19937 rng(seed);
        auto uniform = [&](float lo, float hi) {
            return std::uniform_real_distribution<float>(lo, hi)(rng);
        };
        // A box of walls so that things keep colliding.
        addStatic({0, 200, 220, 10});
        addStatic({-210, 0, 10, 200});
        addStatic({210, 0, 10, 200});
        const int count = 40;
        for (int i = 0; i < count; ++i) {
            if (uniform(0, 1) < 0.15f) {
                addStatic({uniform(-180, 180), uniform(-150, 180), uniform(5, 40), uniform(2, 10)});
                continue;
            }
            Shape s{uniform(-190, 190), uniform(-190, 150), uniform(2, 20), uniform(2, 20)};
            s.xv = uniform(-300, 300);
            s.yv = uniform(-300, 300);
            s.bounce = uniform(0, 1);
            s.friction = uniform(0, 1);
            // Some exact ties and touching edges too.
            if (i % 7 == 0)
                s.hh = s.hw;
            addDynamic(s);
        }
    }

    void addStatic(Shape s) {
        tutorial.statics.push_back(s);
        world.createBody({.type = BodyType::Static,
                          .x = s.x,
                          .y = s.y,
                          .hw = s.hw,
                          .hh = s.hh,
                          .bounce = s.bounce,
                          .friction = s.friction});
    }

    void addDynamic(Shape s) {
        tutorial.dynamics.push_back(s);
        dynamicIds.push_back(world.createBody({.type = BodyType::Dynamic,
                                               .x = s.x,
                                               .y = s.y,
                                               .hw = s.hw,
                                               .hh = s.hh,
                                               .vx = s.xv,
                                               .vy = s.yv,
                                               .bounce = s.bounce,
                                               .friction = s.friction}));
    }

    void expectSame(int step) {
        for (std::size_t i = 0; i < dynamicIds.size(); ++i) {
            const Shape& s = tutorial.dynamics[i];
            const Vec2 p = world.position(dynamicIds[i]);
            const Vec2 v = world.velocity(dynamicIds[i]);
            ASSERT_EQ(p.x, s.x) << "body " << i << " step " << step;
            ASSERT_EQ(p.y, s.y) << "body " << i << " step " << step;
            ASSERT_EQ(v.x, s.xv) << "body " << i << " step " << step;
            ASSERT_EQ(v.y, s.yv) << "body " << i << " step " << step;
        }
    }
};

class ClassicMatchesTutorial : public ::testing::TestWithParam<unsigned> {};

TEST_P(ClassicMatchesTutorial, StepForStepBitForBit) {
    const unsigned seed = GetParam();
    // Half the seeds with the velocity clamp, half without.
    TwinScenes twins(seed, 800.0f, seed % 2 ? 400.0f : 0.0f);
    const float dt = 1.0f / 60.0f;
    for (int step = 1; step <= 300; ++step) {
        twins.tutorial.update(dt);
        twins.world.step(dt);
        twins.expectSame(step);
        if (HasFatalFailure())
            return;
    }
}

INSTANTIATE_TEST_SUITE_P(RandomScenes, ClassicMatchesTutorial, ::testing::Range(1u, 21u));

} // namespace
} // namespace jostle
