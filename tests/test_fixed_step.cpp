// FixedStep: step counts worked out by hand from frame times, alpha, the cap, the
// tolerance that lets float frame times add up to a step, and argument checks.
//
// The hand calculations count time as FixedStep does, in whole nanoseconds: a frame of
// 0.1f seconds is 0.100000001490116 s, 100000001 ns.
#include "jostle/fixed_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace jostle {
namespace {

TEST(FixedStep, SixtyFramesOfOneSixtiethAreSixtySteps) {
    FixedStep clock(1.0f / 60.0f);
    int steps = 0;
    for (int frame = 0; frame < 60; ++frame) {
        ASSERT_EQ(clock.advance(1.0f / 60.0f), 1) << "frame " << frame;
        ASSERT_EQ(clock.alpha(), 0.0f);
        ++steps;
    }
    EXPECT_EQ(steps, 60);
    EXPECT_EQ(clock.droppedSeconds(), 0.0);
}

TEST(FixedStep, ShortFramesAddUpAndLongOnesGiveSeveralSteps) {
    // dt = 0.25 s = 250000000 ns; a frame of 0.1f is 100000001 ns.
    FixedStep clock(0.25f);
    EXPECT_EQ(clock.advance(0.1f), 0); // 100000001 ns waiting
    EXPECT_FLOAT_EQ(clock.alpha(), 0.4f);
    EXPECT_EQ(clock.advance(0.1f), 0); // 200000002
    EXPECT_FLOAT_EQ(clock.alpha(), 0.8f);
    EXPECT_EQ(clock.advance(0.1f), 1); // 300000003: a step, 50000003 left
    EXPECT_FLOAT_EQ(clock.alpha(), 0.2f);
    EXPECT_EQ(clock.advance(0.5f), 2); // 550000003: two steps, 50000003 left
    EXPECT_FLOAT_EQ(clock.alpha(), 0.2f);
    EXPECT_EQ(clock.advance(0.0f), 0); // a frame of no time changes nothing
    EXPECT_FLOAT_EQ(clock.alpha(), 0.2f);
    EXPECT_EQ(clock.advance(0.2f), 1); // 0.2f is 200000003 ns: a step, 6 ns left
    EXPECT_FLOAT_EQ(clock.alpha(), 6e-9f / 0.25f);
    EXPECT_EQ(clock.droppedSeconds(), 0.0);
}

TEST(FixedStep, TheCapDropsWholeStepsAndKeepsThePartOfAStep) {
    FixedStep clock(0.25f, 8);
    EXPECT_EQ(clock.advance(0.3f), 1); // 300000012 ns (0.3f is 0.300000011920929 s)
    EXPECT_NEAR(clock.alpha(), 0.2f, 1e-7f);
    // 50000012 + 3000000000 ns: 12 steps due, 8 taken, 4 (1 s) dropped, 50000012 kept.
    EXPECT_EQ(clock.advance(3.0f), 8);
    EXPECT_EQ(clock.droppedSeconds(), 1.0);
    EXPECT_NEAR(clock.alpha(), 0.2f, 1e-7f);
    // The next frame is back to normal, and says nothing was dropped.
    EXPECT_EQ(clock.advance(0.25f), 1);
    EXPECT_EQ(clock.droppedSeconds(), 0.0);
}

TEST(FixedStep, ExactlyTheCapDropsNothing) {
    FixedStep clock(0.25f, 4);
    EXPECT_EQ(clock.advance(1.0f), 4);
    EXPECT_EQ(clock.droppedSeconds(), 0.0);
    EXPECT_EQ(clock.alpha(), 0.0f);
}

TEST(FixedStep, HugeFramesAreCappedWithoutOverflow) {
    for (float frame : {1e9f, 1e30f, std::numeric_limits<float>::max()}) {
        FixedStep clock(1.0f / 60.0f, 8);
        EXPECT_EQ(clock.advance(frame), 8) << frame;
        // All but 8 steps and the part of a step left over: the frame, to a double's
        // precision.
        EXPECT_NEAR(clock.droppedSeconds(), static_cast<double>(frame),
                    static_cast<double>(frame) * 1e-9)
            << frame;
        EXPECT_GE(clock.alpha(), 0.0f);
        EXPECT_LT(clock.alpha(), 1.0f);
        EXPECT_EQ(clock.advance(1.0f / 60.0f), 1);
    }
}

// Frames at k times the step rate, as a display of 120, 144, 180 ... Hz gives them: one
// step every k frames, never 0 then 2, although k frames of 1.0f / (k × rate) do not
// add up to 1.0f / rate exactly in floats (five of 1.0f / 300 are 3 ns short of 1.0f / 60).
TEST(FixedStep, FrameRatesThatAreMultiplesOfTheStepRateStepEveryKthFrame) {
    for (int rate : {24, 25, 30, 50, 60, 75, 90, 100, 120, 144, 165, 240}) {
        for (int k = 1; k <= 12; ++k) {
            FixedStep clock(1.0f / static_cast<float>(rate));
            const float frame = 1.0f / static_cast<float>(rate * k);
            int total = 0;
            for (int i = 1; i <= rate * k; ++i) {
                const int steps = clock.advance(frame);
                ASSERT_EQ(steps, i % k == 0 ? 1 : 0)
                    << "step rate " << rate << ", frame rate " << rate * k << ", frame " << i;
                total += steps;
            }
            EXPECT_EQ(total, rate);
        }
    }
}

TEST(FixedStep, StepRatesThatAreMultiplesOfTheFrameRateStepKTimesAFrame) {
    for (int k = 1; k <= 8; ++k) {
        FixedStep clock(1.0f / static_cast<float>(30 * k), 8);
        for (int frame = 0; frame < 300; ++frame) {
            ASSERT_EQ(clock.advance(1.0f / 30.0f), k) << "k " << k << ", frame " << frame;
            // Nothing left over but the nanoseconds of float rounding.
            ASSERT_LT(clock.alpha(), 1e-3f);
        }
    }
}

// A million frames of 1/60 s at 60 steps per second: a million steps, not one more or
// less (a float accumulator would have drifted by hours of rounding).
TEST(FixedStep, LongRunsDoNotDrift) {
    FixedStep clock(1.0f / 60.0f);
    long long total = 0;
    for (int frame = 0; frame < 1000000; ++frame)
        total += clock.advance(1.0f / 60.0f);
    EXPECT_EQ(total, 1000000);
}

// Frame times that jitter: the steps taken are the time given divided by dt, to within
// the one step that may be waiting or taken a thousandth of dt early.
TEST(FixedStep, JitteryFramesGiveTheirTimeInSteps) {
    const float dt = 1.0f / 60.0f;
    FixedStep clock(dt, 1000);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> frames(0.0f, 0.05f);
    long double time = 0;
    long long total = 0;
    for (int frame = 0; frame < 100000; ++frame) {
        const float seconds = frames(random);
        time += static_cast<long double>(seconds);
        total += clock.advance(seconds);
        ASSERT_EQ(clock.droppedSeconds(), 0.0);
    }
    // Counting in nanoseconds rounds each frame by at most 0.5 ns: 50 µs in all.
    const long double exact = time / static_cast<long double>(dt);
    EXPECT_LE(std::fabs(static_cast<long double>(total) - exact), 1.0L) << exact;
}

TEST(FixedStep, AlphaIsAlwaysInZeroToOne) {
    for (float dt : {1e-6f, 1.0f / 60.0f, 0.25f, 3600.0f}) {
        FixedStep clock(dt, 4);
        std::mt19937 random(11);
        std::uniform_real_distribution<float> frames(0.0f, 3.0f * dt);
        for (int frame = 0; frame < 10000; ++frame) {
            clock.advance(frames(random));
            ASSERT_GE(clock.alpha(), 0.0f) << "dt " << dt;
            ASSERT_LT(clock.alpha(), 1.0f) << "dt " << dt;
        }
    }
}

TEST(FixedStep, SameFrameTimesGiveTheSameStepsEveryRun) {
    const auto run = [] {
        FixedStep clock(1.0f / 60.0f, 3);
        std::mt19937 random(3);
        std::uniform_real_distribution<float> frames(0.0f, 0.1f);
        std::vector<double> record;
        for (int frame = 0; frame < 10000; ++frame) {
            record.push_back(clock.advance(frames(random)));
            record.push_back(static_cast<double>(clock.alpha()));
            record.push_back(clock.droppedSeconds());
        }
        return record;
    };
    EXPECT_EQ(run(), run());
}

TEST(FixedStep, UpdateStepsTheWorld) {
    // dt = 0.25 and vx = 4: each step moves the body by exactly 1.
    World world;
    const BodyId body = world.createBody({.hw = 1, .hh = 1, .vx = 4});
    FixedStep clock(0.25f);
    EXPECT_EQ(clock.update(world, 0.6f), 2);
    EXPECT_EQ(world.position(body).x, 2.0f);
    EXPECT_NEAR(clock.alpha(), 0.4f, 1e-6f); // 0.6f is 600000024 ns
    EXPECT_EQ(clock.update(world, 0.1f), 0);
    EXPECT_EQ(world.position(body).x, 2.0f);
}

TEST(FixedStep, UpdateHandsTheGameEachStepsEventsNotOnlyTheLastOnes) {
    // Three boxes falling onto a floor from heights they reach in different steps of one
    // frame: read once after update(), the world's events hold the last step's begins
    // alone; read in afterStep, every landing.
    auto landings = [](bool eachStep) {
        World world(WorldDef{.gravity = {0, 1000}});
        world.createBody({.type = BodyType::Static, .y = 10, .hw = 100, .hh = 10});
        // Fallen g dt² n(n + 1) / 2 after n steps (semi-implicit Euler): 0.28 after one,
        // 0.83 and 1.67 after two and three, 4.17 and 5.83 after five and six. Gaps of 0.1,
        // 1 and 4.5 close in the first, third and sixth steps of the eight.
        for (float gap : {0.1f, 1.0f, 4.5f})
            world.createBody({.x = 10.0f * gap, .y = -1.0f - gap, .hw = 1, .hh = 1});
        FixedStep clock(1.0f / 60.0f, 8);
        std::size_t begins = 0;
        if (eachStep)
            clock.update(world, 8.0f / 60.0f, [&] { begins += world.contactBegins().size(); });
        else {
            clock.update(world, 8.0f / 60.0f);
            begins = world.contactBegins().size();
        }
        return begins;
    };
    EXPECT_EQ(landings(true), 3u);
    EXPECT_LT(landings(false), 3u);
}

TEST(FixedStep, AfterStepIsCalledOncePerStepTaken) {
    World world;
    FixedStep clock(0.25f, 3);
    int calls = 0;
    EXPECT_EQ(clock.update(world, 0.6f, [&] { ++calls; }), 2);
    EXPECT_EQ(calls, 2);
    EXPECT_EQ(clock.update(world, 2.0f, [&] { ++calls; }), 3); // the cap
    EXPECT_EQ(calls, 5);
}

TEST(FixedStep, ResetForgetsWhereBodiesWereSoARestoredWorldIsDrawnWhereItIs) {
    // A box at 4 units/s, steps of 0.25 s: stepped from 1 to 2, alpha 0.5, then restored to
    // a snapshot of x = 0, it is drawn between 1 and 0 (0.5) until reset() forgets the step.
    World world(WorldDef{.gravity = {0, 0}});
    const BodyId box = world.createBody({.hw = 1, .hh = 1, .vx = 4});
    const std::vector<std::byte> start = world.snapshot();
    FixedStep clock(0.25f);
    clock.update(world, 0.25f);
    clock.update(world, 0.375f);
    ASSERT_EQ(world.position(box).x, 2.0f);
    world.restore(start);
    EXPECT_FLOAT_EQ(clock.drawPosition(world, box).x, 0.5f);
    clock.reset();
    EXPECT_EQ(clock.drawPosition(world, box), (Vec2{0, 0}));
}

TEST(FixedStep, ResetForgetsTheTimeLeftOver) {
    FixedStep clock(0.25f, 1);
    clock.advance(0.9f); // 3 steps due, 1 taken, 0.5 s dropped, 0.15 s left over
    EXPECT_GT(clock.droppedSeconds(), 0.0);
    EXPECT_GT(clock.alpha(), 0.0f);
    clock.reset();
    EXPECT_EQ(clock.alpha(), 0.0f);
    EXPECT_EQ(clock.droppedSeconds(), 0.0);
    EXPECT_EQ(clock.advance(0.2f), 0);
}

TEST(FixedStep, SettingsAreKept) {
    const FixedStep clock(0.125f, 5);
    EXPECT_EQ(clock.dt(), 0.125f);
    EXPECT_EQ(clock.maxStepsPerFrame(), 5);
    EXPECT_EQ(FixedStep().dt(), 1.0f / 60.0f);
    EXPECT_EQ(FixedStep().maxStepsPerFrame(), 8);
}

TEST(FixedStep, BadSettingsThrow) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (float dt : {0.0f, -1.0f / 60.0f, nan, inf, 1e-7f, 3601.0f})
        EXPECT_THROW(FixedStep{dt}, Error) << dt;
    for (int maxSteps : {0, -1, 100001})
        EXPECT_THROW((FixedStep{1.0f / 60.0f, maxSteps}), Error) << maxSteps;
    EXPECT_NO_THROW((FixedStep{FixedStep::kMinDt, 1}));
    EXPECT_NO_THROW((FixedStep{FixedStep::kMaxDt, FixedStep::kMaxStepsLimit}));
}

TEST(FixedStep, BadFrameTimesThrowAndChangeNothing) {
    FixedStep clock(0.25f);
    clock.advance(0.1f);
    const float alpha = clock.alpha();
    for (float frame :
         {-0.001f, -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
          std::numeric_limits<float>::quiet_NaN()}) {
        EXPECT_THROW(clock.advance(frame), Error) << frame;
        EXPECT_EQ(clock.alpha(), alpha);
    }
    EXPECT_EQ(clock.advance(-0.0f), 0); // negative zero is zero
}

TEST(FixedStep, DrawsEachBodyBetweenItsLastTwoSteps) {
    // Steps of 0.25 s; a box moving at 4 units/s covers 1 unit a step, so its positions
    // after each step are whole numbers and what lies between them is alpha.
    World world(WorldDef{.gravity = {0, 0}});
    const BodyId box = world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .vx = 4});
    FixedStep clock(0.25f);
    EXPECT_EQ(clock.drawPosition(world, box), (Vec2{0, 0})); // nothing stepped yet
    EXPECT_EQ(clock.update(world, 0.375f), 1);               // 1.5 steps: at 1, alpha 0.5
    EXPECT_FLOAT_EQ(clock.drawPosition(world, box).x, 0.5f);
    EXPECT_EQ(clock.update(world, 0.5f), 2); // 2 steps: at 3, alpha 0.5
    EXPECT_FLOAT_EQ(clock.drawPosition(world, box).x, 2.5f);
    EXPECT_EQ(clock.update(world, 0.125f), 1); // 0.125 + 0.125: at 4, alpha 0
    EXPECT_FLOAT_EQ(clock.drawPosition(world, box).x, 3.0f);
    EXPECT_EQ(clock.update(world, 0.125f), 0); // no step: alpha 0.5
    EXPECT_FLOAT_EQ(clock.drawPosition(world, box).x, 3.5f);
    // A body made since the last step is drawn where it is.
    const BodyId late = world.createBody({.x = 7, .y = 0, .hw = 1, .hh = 1, .vx = 4});
    EXPECT_EQ(clock.drawPosition(world, late), (Vec2{7, 0}));
    // All at once, in the order of World::bodies().
    std::vector<Vec2> all(3);
    EXPECT_EQ(clock.readDrawPositions(world, all), 2u);
    EXPECT_FLOAT_EQ(all[0].x, 3.5f);
    EXPECT_EQ(all[1], (Vec2{7, 0}));
    // A slot reused by another body is not mistaken for the old one.
    world.destroyBody(box);
    const BodyId reused = world.createBody({.x = -5, .y = 0, .hw = 1, .hh = 1});
    EXPECT_EQ(clock.drawPosition(world, reused), (Vec2{-5, 0}));
    EXPECT_THROW(clock.drawPosition(world, box), Error);
}

TEST(FixedStep, ItsPendingTimeSavedAndPutBackGivesTheSameStepsToCome) {
    // dt = 1/4 s is 250,000,000 ns; three frames of 1/8 s (floats that are exact) leave
    // 375,000,000 - 250,000,000 ns pending: half a step.
    FixedStep clock(0.25f), copy(0.25f);
    for (int frame = 0; frame < 3; ++frame)
        clock.advance(0.125f);
    EXPECT_EQ(clock.pendingNanoseconds(), 125'000'000);
    copy.setPendingNanoseconds(clock.pendingNanoseconds());
    EXPECT_FLOAT_EQ(copy.alpha(), 0.5f);
    for (float frame : {0.1f, 0.17f, 0.33f, 0.05f})
        EXPECT_EQ(copy.advance(frame), clock.advance(frame)) << frame;
    // Its range: from -dt/1000 (a step taken early) to just under dt less that tolerance.
    EXPECT_NO_THROW(copy.setPendingNanoseconds(-250'000));
    EXPECT_NO_THROW(copy.setPendingNanoseconds(249'749'999));
    EXPECT_THROW(copy.setPendingNanoseconds(249'750'000), Error);
    EXPECT_THROW(copy.setPendingNanoseconds(-250'001), Error);
    EXPECT_EQ(copy.pendingNanoseconds(), 249'749'999); // refused: unchanged
}

} // namespace
} // namespace jostle
