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

// --- Found by the fuzzers (tests/fuzz; the input kept in tests/fuzz/corpus/) ------------

// Found by fuzz_api with JOSTLE_FUZZ_OPEN=float-range (tests/fuzz/corpus/api/
// density-mass-overflow-unchecked). checkBodyDef refused a density x area that
// overflows, but multiplied in another order than the mass the solver uses: with a thin,
// very dense body the check's product was finite and the mass infinite.
TEST(BodyDefs, TheDensityMassThatIsCheckedIsTheOneUsed) {
    // density × 4 overflows first: the mass density × 4 × hw × hh is infinite, however
    // small hw × hh is.
    const BodyDef def{.hw = 1e-30f, .hh = 50.5f, .density = 3e38f};
    EXPECT_TRUE(checkBodyDef(def).has_value());
    World world;
    EXPECT_THROW(world.createBody(def), Error);
    EXPECT_EQ(world.bodyCount(), 0u);
}

// Found by fuzz_api with JOSTLE_FUZZ_OPEN=float-range (tests/fuzz/corpus/api/
// setter-density-mass-overflow). createBody refuses a body whose density × area
// overflows, but setHalfExtents and setDensity made one: a dynamic body of infinite
// mass, which the solver treats as immovable and divides by.
TEST(BodyDefs, SettersRefuseAnInfiniteDensityMassAsCreateBodyDoes) {
    World world;
    BodyId box = world.createBody({.hw = 10, .hh = 10});
    EXPECT_THROW(world.setHalfExtents(box, {1e20f, 1e20f}), Error);
    EXPECT_EQ(world.halfExtents(box), (Vec2{10, 10}));
    EXPECT_THROW(world.setDensity(box, 3e38f), Error);
    EXPECT_EQ(world.mass(box), 400.0f);
    // With an explicit mass, the size does not matter to the mass.
    world.setMass(box, 2);
    world.setHalfExtents(box, {1e9f, 1e9f});
    EXPECT_EQ(world.mass(box), 2.0f);
}

// Found by fuzz_scene (tests/fuzz/corpus/scene/static-body-with-velocity). checkBodyDef,
// which promises nothing for a definition createBody accepts, passed a static body with a
// velocity, which createBody refuses: a scene file with one loaded, and addBodies, which
// checks every body with checkBodyDef before it creates any, threw halfway through,
// leaving the world half filled.
TEST(BodyDefs, CheckBodyDefRefusesAMovingStaticBodyAsCreateBodyDoes) {
    const BodyDef moving{.type = BodyType::Static, .hw = 1, .hh = 1, .vy = 1};
    ASSERT_TRUE(checkBodyDef(moving).has_value());
    EXPECT_EQ(checkBodyDef(moving)->field, "vy");
    World world;
    EXPECT_THROW(world.createBody(moving), Error);
    EXPECT_FALSE(checkBodyDef({.type = BodyType::Kinematic, .hw = 1, .hh = 1, .vy = 1}));
}

} // namespace
} // namespace jostle
