// jostle/fixed_step.hpp: a fixed time step from variable frame times (header-only).
//
// A world stepped by a constant dt behaves the same on every machine and at every frame
// rate; a game's frames take whatever time they take. FixedStep stands between the two:
// each frame, tell it how long the frame took, and it tells you how many steps of dt to
// take now, carrying the rest of the time over to the next frame. docs/fixed-step.md.
//
//     jostle::FixedStep clock(1.0f / 60.0f);
//     while (running) {
//         clock.update(world, secondsSinceLastFrame());
//         draw(clock.drawPosition(world, player));   // between the last two steps
//     }
//
// Time is counted in whole nanoseconds, so nothing drifts: 60 frames of 1/60 s are 60
// steps of 1/60 s, exactly, however long the game runs.
#pragma once

#include "jostle/error.hpp"
#include "jostle/visibility.h"
#include "jostle/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace jostle {
JOSTLE_EXPORT_BEGIN

class FixedStep {
public:
    /// The shortest and longest step accepted, in seconds: a microsecond and an hour.
    static constexpr float kMinDt = 1e-6f;
    static constexpr float kMaxDt = 3600.0f;
    /// The most steps one frame may ask for.
    static constexpr int kMaxStepsLimit = 100000;

    /// `dt`: the step, in seconds, in [kMinDt, kMaxDt]. `maxStepsPerFrame`: the most
    /// steps advance() returns for one frame, in [1, kMaxStepsLimit]. Anything else
    /// throws jostle::Error.
    ///
    /// Why a cap: if the steps of one frame take longer to compute than the frame they
    /// catch up with, the next frame is longer still and asks for more steps, until the
    /// game freezes. With a cap, a slow machine plays in slow motion instead, and a long
    /// pause (a breakpoint, a window dragged) costs at most that many steps.
    explicit FixedStep(float dt = 1.0f / 60.0f, int maxStepsPerFrame = 8)
        : dt_(dt), maxSteps_(maxStepsPerFrame) {
        if (!(dt >= kMinDt && dt <= kMaxDt))
            throw Error("FixedStep: dt must be a number of seconds from 1e-6 to 3600");
        if (maxStepsPerFrame < 1 || maxStepsPerFrame > kMaxStepsLimit)
            throw Error("FixedStep: maxStepsPerFrame must be from 1 to 100000");
        dtTicks_ = std::llround(static_cast<double>(dt) * kTicksPerSecond);
        toleranceTicks_ = dtTicks_ / kToleranceDivisor;
    }

    /// Adds the time of one frame, in seconds (finite and >= 0, else jostle::Error and
    /// nothing changes), and returns how many steps of dt() to take now: from 0 to
    /// maxStepsPerFrame(). The time left over, less than a step, waits for later frames.
    ///
    /// If more than maxStepsPerFrame() steps are due, the whole steps beyond the cap are
    /// dropped: that time is never simulated, and droppedSeconds() says how much it was.
    /// The part of a step left over is kept, so alpha() stays smooth.
    ///
    /// A step is also taken when the time falls short of it by less than a thousandth of
    /// dt, and the shortfall is paid back by later frames. That is what makes frame
    /// times meant to add up to a step do so despite float rounding: three frames of
    /// 1.0f / 180 are one step of 1.0f / 60, though as floats they sum to a few
    /// nanoseconds less.
    int advance(float frameSeconds) {
        if (!(std::isfinite(frameSeconds) && frameSeconds >= 0.0f))
            throw Error("FixedStep::advance: frameSeconds must be a finite number >= 0");
        // A frame beyond kLongestFrame (31 years) is cut to it: the cap drops all but
        // a few steps of it anyway, and the tick count stays far from overflowing.
        const double seconds = std::min(static_cast<double>(frameSeconds), kLongestFrame);
        dropped_ = static_cast<double>(frameSeconds) - seconds;

        accumulated_ += std::llround(seconds * kTicksPerSecond);
        // accumulated_ >= -toleranceTicks_ always: the numerator is never negative.
        const std::int64_t due = (accumulated_ + toleranceTicks_) / dtTicks_;
        const std::int64_t steps = std::min<std::int64_t>(due, maxSteps_);
        accumulated_ -= due * dtTicks_;
        dropped_ += static_cast<double>((due - steps) * dtTicks_) / kTicksPerSecond;
        return static_cast<int>(steps);
    }

    /// advance(frameSeconds), then world.step(dt()) that many times; returns the number
    /// of steps. For games that draw the world as it is after the last step. If a step
    /// throws (a callback of yours did), the steps left are not taken and their time is
    /// lost. It also keeps where every body was before the last step, for drawPosition.
    ///
    /// A world's events (contactBegins() and the rest) are the last step's: a frame of
    /// several steps that reads them once, after update(), misses the others'. Read them
    /// in `afterStep`, which update(world, frameSeconds, afterStep) calls after each step.
    int update(World& world, float frameSeconds) {
        return update(world, frameSeconds, [] {});
    }
    /// update(world, frameSeconds), calling afterStep() after each step: where a game reads
    /// the step's events. It may change the world, as between any two steps; what it
    /// throws stops the steps as a step's error does.
    template <class AfterStep> int update(World& world, float frameSeconds, AfterStep&& afterStep) {
        const int steps = advance(frameSeconds);
        takeSteps(world, steps, [&] {
            world.step(dt_);
            afterStep();
        });
        return steps;
    }

    /// Calls step() `steps` times (what advance() returned), keeping where every body of
    /// `world` is before the last one, as update() does: for a binding or a game that
    /// steps the world its own way.
    template <class Step> void takeSteps(const World& world, int steps, Step&& step) {
        for (int i = 0; i < steps; ++i) {
            if (i == steps - 1)
                rememberPositions(world);
            step();
        }
    }

    /// Where to draw a body now: between where it was before the last step update()
    /// took and where it is, by alpha(), so that motion looks smooth when the frame rate
    /// and the step rate differ. Where it is, for a body that update() has not stepped
    /// yet (created since). Throws jostle::Error for a stale BodyId, as World does.
    Vec2 drawPosition(const World& world, BodyId id) const {
        const Vec2 now = world.position(id);
        const Before* before = beforeOf(id);
        return before ? lerp(before->position, now) : now;
    }

    /// Keeps where every body of `world` is now, for drawPosition: update() calls it
    /// before the last step it takes; call it yourself before the last step of a frame
    /// if you step the world by hand.
    void rememberPositions(const World& world) {
        const std::span<const BodyId> bodies = world.bodies();
        scratch_.resize(bodies.size());
        world.readPositions(scratch_);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (bodies[i].index >= before_.size())
                before_.resize(std::size_t(bodies[i].index) + 1);
            before_[bodies[i].index] = {bodies[i], scratch_[i]};
        }
    }

    /// drawPosition of every body, in the order of World::bodies(), into `out`: as many as
    /// fit. Returns how many.
    std::size_t readDrawPositions(const World& world, std::span<Vec2> out) const {
        const std::size_t count = world.readPositions(out);
        const std::span<const BodyId> bodies = world.bodies();
        for (std::size_t i = 0; i < count; ++i)
            if (const Before* before = beforeOf(bodies[i]))
                out[i] = lerp(before->position, out[i]);
        return count;
    }

    /// How far the time left over reaches towards the next step, in [0, 1): draw each
    /// body at previous + (current - previous) × alpha() to show it where it is now,
    /// between the last step and the next, so that motion looks smooth when the frame
    /// rate and the step rate differ.
    float alpha() const {
        const double fraction = static_cast<double>(std::max<std::int64_t>(accumulated_, 0)) /
                                static_cast<double>(dtTicks_);
        // accumulated_ < dtTicks_ - toleranceTicks_, so fraction < 0.999: never 1.
        return static_cast<float>(fraction);
    }

    /// The seconds the last advance() dropped because of the cap (0 if none).
    double droppedSeconds() const { return dropped_; }

    float dt() const { return dt_; }
    int maxStepsPerFrame() const { return maxSteps_; }

    /// The time left over, not yet stepped, in whole nanoseconds: all a clock carries from
    /// frame to frame. Saved beside a world's snapshot (docs/rollback.md), it lets a saved
    /// game or a replay resume with the same steps to come. From a little below 0 (a step
    /// taken early, within the tolerance of advance()) to just under a step.
    std::int64_t pendingNanoseconds() const { return accumulated_; }
    /// Puts back what pendingNanoseconds() gave, of a clock with the same dt. Throws
    /// jostle::Error, changing nothing, for a value no such clock can have.
    void setPendingNanoseconds(std::int64_t nanoseconds) {
        if (nanoseconds < -toleranceTicks_ || nanoseconds >= dtTicks_ - toleranceTicks_)
            throw Error("FixedStep::setPendingNanoseconds: nanoseconds must be from " +
                        std::to_string(-toleranceTicks_) + " to " +
                        std::to_string(dtTicks_ - toleranceTicks_ - 1) + " for a dt of " +
                        std::to_string(dtTicks_) + " ns");
        accumulated_ = nanoseconds;
    }

    /// Forgets the time left over, the dropped time and where bodies were before the last
    /// step, as a new FixedStep would: for after a pause, a level load or a restored
    /// snapshot, so that the first frame neither catches up with the time nor draws a body
    /// between where it was before and where it is now. (A rollback that steps again after
    /// its restore needs none of it: update() and takeSteps() remember the positions anew.)
    void reset() {
        accumulated_ = 0;
        dropped_ = 0.0;
        before_.clear();
    }

private:
    /// Where a body was before the last step update() took.
    struct Before {
        BodyId body;
        Vec2 position;
    };

    /// `id`'s, or nullptr if update() has not seen that body (created since).
    const Before* beforeOf(BodyId id) const {
        return id.index < before_.size() && before_[id.index].body == id ? &before_[id.index]
                                                                         : nullptr;
    }

    static constexpr double kTicksPerSecond = 1e9;
    /// Longer than the most time the cap lets through, kMaxStepsLimit × kMaxDt, and
    /// short enough that accumulated_ never overflows.
    static constexpr double kLongestFrame = 1e9;
    /// The tolerance is dt divided by this.
    static constexpr std::int64_t kToleranceDivisor = 1000;

    /// previous + (current - previous) × alpha().
    Vec2 lerp(Vec2 previous, Vec2 current) const {
        return previous + (current - previous) * alpha();
    }

    float dt_;
    int maxSteps_;
    std::vector<Before> before_; ///< by slot: the body there and where it was
    std::vector<Vec2> scratch_;
    std::int64_t dtTicks_ = 0;
    std::int64_t toleranceTicks_ = 0;
    /// Nanoseconds not yet stepped; down to -toleranceTicks_ after a step taken early.
    std::int64_t accumulated_ = 0;
    double dropped_ = 0.0;
};

JOSTLE_EXPORT_END
} // namespace jostle
