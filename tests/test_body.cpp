// The rules a BodyDef and a WorldDef must follow, one by one.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace jostle {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

BodyDef validDef() {
    return {.x = 1, .y = 2, .hw = 3, .hh = 4};
}

std::string problemWith(const std::function<void(BodyDef&)>& change) {
    BodyDef def = validDef();
    change(def);
    auto problem = checkBodyDef(def);
    return problem ? problem->field + ": " + problem->problem : "ok";
}

TEST(CheckBodyDef, AcceptsAValidDefinition) {
    EXPECT_EQ(problemWith([](BodyDef&) {}), "ok");
}

TEST(CheckBodyDef, DefaultSizeIsRejectedSoThatSizesAreChosen) {
    EXPECT_EQ(checkBodyDef(BodyDef{})->field, "hw");
}

TEST(CheckBodyDef, EveryRule) {
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = 0; }), "hw: must be > 0");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hh = -1; }), "hh: must be > 0");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.x = kNaN; }), "x: must be a finite number");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.y = kInf; }), "y: must be a finite number");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.vx = -kInf; }), "vx: must be a finite number");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = kNaN; }), "hw: must be a finite number");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.bounce = 1.5f; }), "bounce: must be in [0, 1]");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.bounce = -0.1f; }), "bounce: must be in [0, 1]");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.friction = 2; }), "friction: must be in [0, 1]");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.mass = -1; }), "mass: must be >= 0 (0: from density)");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.density = 0; }), "density: must be > 0");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.damping = -1; }), "damping: must be >= 0");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.gravityScale = kNaN; }),
              "gravityScale: must be a finite number");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.type = static_cast<BodyType>(7); }),
              "type: must be static, kinematic or dynamic");
    // The range of math.hpp: magnitudes up to 1e9, sizes, densities and masses from 1e-9.
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = d.hh = 1e9f; }), "ok");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = 1.0001e9f; }), "hw: must be of magnitude <= 1e9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.x = -1e30f; }), "x: must be of magnitude <= 1e9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.vy = 3e38f; }), "vy: must be of magnitude <= 1e9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.gravityScale = -2e9f; }),
              "gravityScale: must be of magnitude <= 1e9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = 1e-9f; }), "ok");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hh = 1e-10f; }), "hh: must be >= 1e-9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.hw = 1e-45f; }), "hw: must be >= 1e-9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.density = 1e-12f; }), "density: must be >= 1e-9");
    EXPECT_EQ(problemWith([](BodyDef& d) { d.mass = 1e-12f; }),
              "mass: must be 0 (from density) or >= 1e-9");
}

TEST(CheckWorldDef, Rules) {
    EXPECT_FALSE(checkWorldDef({}));
    EXPECT_EQ(checkWorldDef({.gravity = {0, kNaN}})->field, "gravity");
    EXPECT_EQ(checkWorldDef({.maxVelocity = 0})->field, "maxVelocity");
    EXPECT_EQ(checkWorldDef({.maxVelocity = kNaN})->field, "maxVelocity");
    EXPECT_FALSE(checkWorldDef({.maxVelocity = kInf})); // no clamp
}

TEST(Names, RoundTrip) {
    for (BodyType t : {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic})
        EXPECT_EQ(bodyTypeFromString(toString(t)), t);
    EXPECT_EQ(std::string(toString(BodyType::Kinematic)), "kinematic");
    EXPECT_FALSE(bodyTypeFromString("Static"));
    for (Solver s : {Solver::Classic, Solver::Physical})
        EXPECT_EQ(solverFromString(toString(s)), s);
    EXPECT_FALSE(solverFromString("box2d"));
}

} // namespace
} // namespace jostle
