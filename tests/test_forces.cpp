// Forces and impulses (World::applyForce, applyImpulse), and the contacts a body has now
// (World::contacts, isTouching, contact points), in both models.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

class Forces : public ::testing::TestWithParam<Solver> {
protected:
    World world{WorldDef{.gravity = {0, 0}, .solver = GetParam(), .sleeping = false}};
};

TEST_P(Forces, AForceActsForOneStepAsForceOverMassTimesDt) {
    // A 20 × 10 box of density 2: mass 400. A force of (800, -400) for one step changes
    // its velocity by (800, -400) / 400 / 60 = (1/30, -1/60); the next step, none.
    const BodyId box = world.createBody({.x = 0, .y = 0, .hw = 10, .hh = 5, .density = 2});
    world.applyForce(box, {800, -400});
    world.step(kDt);
    EXPECT_FLOAT_EQ(world.velocity(box).x, 1.0f / 30.0f);
    EXPECT_FLOAT_EQ(world.velocity(box).y, -1.0f / 60.0f);
    world.step(kDt);
    EXPECT_FLOAT_EQ(world.velocity(box).x, 1.0f / 30.0f);
}

TEST_P(Forces, ForcesAddUpAndALastingOneAcceleratesSteadily) {
    // Two halves make a whole; applied before every step, a = F / m: after 60 steps of
    // 400 / 400, the speed is 1 and the distance travelled sum(k dt²) = 61 / 120.
    const BodyId box = world.createBody({.x = 0, .y = 0, .hw = 10, .hh = 5, .density = 2});
    for (int i = 0; i < 60; ++i) {
        world.applyForce(box, {200, 0});
        world.applyForce(box, {200, 0});
        world.step(kDt);
    }
    EXPECT_NEAR(world.velocity(box).x, 1.0f, 1e-5f);
    EXPECT_NEAR(world.position(box).x, 61.0f / 120.0f, 1e-5f);
}

TEST_P(Forces, AnImpulseChangesTheVelocityAtOnce) {
    const BodyId box = world.createBody({.x = 0, .y = 0, .hw = 10, .hh = 5, .mass = 4});
    world.applyImpulse(box, {8, -2});
    EXPECT_EQ(world.velocity(box), (Vec2{2, -0.5f}));
}

TEST_P(Forces, StaticAndKinematicBodiesAreNotMoved) {
    const BodyId wall = world.createBody({.type = BodyType::Static, .hw = 5, .hh = 5});
    const BodyId lift = world.createBody({.type = BodyType::Kinematic, .hw = 5, .hh = 5});
    for (BodyId id : {wall, lift}) {
        world.applyForce(id, {1e6f, 0});
        world.applyImpulse(id, {1e6f, 0});
    }
    world.step(kDt);
    EXPECT_EQ(world.velocity(wall), (Vec2{}));
    EXPECT_EQ(world.velocity(lift), (Vec2{}));
}

TEST_P(Forces, ArgumentsAreChecked) {
    const BodyId box = world.createBody({.hw = 5, .hh = 5});
    EXPECT_THROW(world.applyForce(box, {NAN, 0}), Error);
    EXPECT_THROW(world.applyImpulse(box, {0, INFINITY}), Error);
    world.destroyBody(box);
    EXPECT_THROW(world.applyForce(box, {1, 0}), Error);
}

TEST_P(Forces, AForceOnABodyDestroyedBeforeTheStepIsDropped) {
    const BodyId gone = world.createBody({.hw = 5, .hh = 5});
    world.applyForce(gone, {1000, 0});
    world.destroyBody(gone);
    const BodyId box = world.createBody({.hw = 5, .hh = 5}); // may take its slot
    world.step(kDt);
    EXPECT_EQ(world.velocity(box), (Vec2{}));
}

TEST_P(Forces, ContactsListWhatABodyTouchesWithWhereAndHowHard) {
    // A 10 × 10 crate (mass 100) at rest on a floor whose top is y = 0, under gravity 600,
    // its left edge at x = 20, and the floor from -100 to 100.
    world.setGravity({0, 600});
    const BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 10});
    const BodyId crate = world.createBody({.x = 25, .y = -5, .hw = 5, .hh = 5});
    const BodyId other = world.createBody({.x = -50, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    const std::vector<ContactInfo> contacts = world.contacts(crate);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_EQ(contacts[0].other, floor);
    EXPECT_EQ(contacts[0].normal, (Vec2{0, -1}));
    // The middle of the stretch they share: x from 20 to 30; y between the faces (the
    // crate rests within the slop of the top).
    EXPECT_NEAR(contacts[0].point.x, 25.0f, 1e-4f);
    EXPECT_NEAR(contacts[0].point.y, 0.0f, 0.05f);
    if (GetParam() == Solver::Physical) {
        // Holding it up against gravity for a step: m g dt = 100 × 600 / 60 = 1000.
        EXPECT_NEAR(contacts[0].impulse, 1000.0f, 1.0f);
    }
    const std::vector<ContactInfo> ofFloor = world.contacts(floor);
    ASSERT_EQ(ofFloor.size(), 2u);
    EXPECT_EQ(ofFloor[0].other, crate); // in the order of the bodies they pair with
    EXPECT_EQ(ofFloor[0].normal, (Vec2{0, 1}));
    EXPECT_EQ(ofFloor[1].other, other);
    EXPECT_TRUE(world.isTouching(crate, floor));
    EXPECT_TRUE(world.isTouching(floor, crate));
    EXPECT_FALSE(world.isTouching(crate, other));
}

TEST_P(Forces, AContactBeginSaysWhereTheBodiesMet) {
    world.setGravity({0, 600});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 10});
    world.createBody({.x = -95, .y = -50, .hw = 10, .hh = 5}); // overhangs the left end
    bool met = false;
    for (int i = 0; i < 60 && !met; ++i) {
        world.step(kDt);
        for (const ContactEvent& e : world.contactBegins()) {
            met = true;
            // Its bottom on the floor's top, over x from -100 (the floor's end) to -85.
            EXPECT_NEAR(e.point.x, -92.5f, 1e-3f);
            EXPECT_NEAR(e.point.y, 0.0f, 0.05f);
        }
    }
    EXPECT_TRUE(met);
}

TEST_P(Forces, NoSpeedLeavesTheRangeOfNumbersJostleWorksIn) {
    // A body of mass 1e-6 kicked by 1e4: 1e10 units/s, held to 1e9 on each axis
    // (math.hpp), as every speed is (found by fuzz_api: impulse-beyond-the-range).
    const BodyId light = world.createBody({.hw = 1, .hh = 1, .mass = 1e-6f});
    world.applyImpulse(light, {1e4f, -1e4f});
    EXPECT_EQ(world.velocity(light), (Vec2{kMaxMagnitude, -kMaxMagnitude}));
    // A character walking at 1e9 on a ground moving at 1e9 the same way.
    world.setGravity({0, 10});
    const BodyId belt = world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = 10, .hw = 1000, .hh = 5, .vx = 1e9f});
    const BodyId runner = world.createBody({.x = 0, .y = 3, .hw = 1, .hh = 2, .character = true});
    world.setWalkSpeed(runner, 1e9f);
    for (int i = 0; i < 3; ++i)
        world.step(kDt);
    (void)belt;
    EXPECT_LE(world.velocity(runner).x, kMaxMagnitude);
}

TEST_P(Forces, ContactsLeaveOutABodyDestroyedSinceTheStep) {
    world.setGravity({0, 600});
    const BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 10});
    const BodyId crate = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    ASSERT_EQ(world.contacts(floor).size(), 1u);
    world.destroyBody(crate);
    EXPECT_TRUE(world.contacts(floor).empty());
    EXPECT_FALSE(world.ground(floor));
}

INSTANTIATE_TEST_SUITE_P(Models, Forces, ::testing::Values(Solver::Classic, Solver::Physical),
                         [](const ::testing::TestParamInfo<Solver>& model) {
                             return model.param == Solver::Classic ? "Classic" : "Physical";
                         });

} // namespace
} // namespace jostle
