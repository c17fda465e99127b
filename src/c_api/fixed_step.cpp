// The C API's fixed-step clock: jostle::FixedStep behind an opaque pointer.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

jostle_fixed_step& clockOf(jostle_fixed_step* clock) {
    return required(clock, "clock");
}
const jostle_fixed_step& clockOf(const jostle_fixed_step* clock) {
    return required(clock, "clock");
}

} // namespace

extern "C" {

jostle_fixed_step* jostle_fixed_step_create(float dt, int max_steps_per_frame) {
    return guard<jostle_fixed_step*>(__func__, nullptr, [&] {
        return new jostle_fixed_step{FixedStep(dt, max_steps_per_frame)};
    });
}

void jostle_fixed_step_destroy(jostle_fixed_step* clock) {
    delete clock;
}

int jostle_fixed_step_advance(jostle_fixed_step* clock, float frame_seconds) {
    return guard(__func__, 0, [&] { return clockOf(clock).clock.advance(frame_seconds); });
}

} // extern "C"

namespace {

/// jostle_fixed_step_update and _update_each, under the name of `function`.
int update(const char* function, jostle_fixed_step* clock, jostle_world* world, float frameSeconds,
           jostle_after_step_fn afterStep, void* context) {
    return guard(function, 0, [&] {
        FixedStep& c = clockOf(clock).clock;
        jostle_world& w = outsideStep(world); // checked before the clock counts the frame
        const int steps = c.advance(frameSeconds);
        // A failing step (out of memory) is reported, and the steps taken stand.
        int taken = 0;
        guard(function, 0, [&] {
            c.takeSteps(w.world, steps, [&] {
                stepWorld(w, c.dt());
                ++taken;
                if (afterStep != nullptr)
                    afterStep(world, context);
            });
            return 0;
        });
        return taken;
    });
}

} // namespace

extern "C" {

int jostle_fixed_step_update(jostle_fixed_step* clock, jostle_world* world, float frame_seconds) {
    return update(__func__, clock, world, frame_seconds, nullptr, nullptr);
}

int jostle_fixed_step_update_each(jostle_fixed_step* clock, jostle_world* world,
                                  float frame_seconds, jostle_after_step_fn after_step,
                                  void* context) {
    return update(__func__, clock, world, frame_seconds, after_step, context);
}

bool jostle_fixed_step_remember_positions(jostle_fixed_step* clock, const jostle_world* world) {
    return guard(__func__, false, [&] {
        clockOf(clock).clock.rememberPositions(worldOf(world).world);
        return true;
    });
}

float jostle_fixed_step_alpha(const jostle_fixed_step* clock) {
    return guard(__func__, 0.0f, [&] { return clockOf(clock).clock.alpha(); });
}

jostle_vec2 jostle_fixed_step_draw_position(const jostle_fixed_step* clock,
                                            const jostle_world* world, jostle_body_id body) {
    return guard(__func__, jostle_vec2{}, [&] {
        const FixedStep& c = clockOf(clock).clock;
        return toC(c.drawPosition(worldOf(world).world, toCpp(body)));
    });
}

int jostle_fixed_step_read_draw_positions(const jostle_fixed_step* clock, const jostle_world* world,
                                          jostle_vec2* out, int capacity) {
    return guard(__func__, 0, [&] {
        const FixedStep& c = clockOf(clock).clock;
        const World& w = worldOf(world).world;
        return readEach(w, out, capacity,
                        [&](std::span<Vec2> read) { c.readDrawPositions(w, read); });
    });
}

double jostle_fixed_step_dropped_seconds(const jostle_fixed_step* clock) {
    return guard(__func__, 0.0, [&] { return clockOf(clock).clock.droppedSeconds(); });
}

float jostle_fixed_step_dt(const jostle_fixed_step* clock) {
    return guard(__func__, 0.0f, [&] { return clockOf(clock).clock.dt(); });
}

int jostle_fixed_step_max_steps_per_frame(const jostle_fixed_step* clock) {
    return guard(__func__, 0, [&] { return clockOf(clock).clock.maxStepsPerFrame(); });
}

bool jostle_fixed_step_reset(jostle_fixed_step* clock) {
    return guard(__func__, false, [&] {
        clockOf(clock).clock.reset();
        return true;
    });
}

int64_t jostle_fixed_step_pending_nanoseconds(const jostle_fixed_step* clock) {
    return guard(__func__, std::int64_t{0},
                 [&] { return clockOf(clock).clock.pendingNanoseconds(); });
}

bool jostle_fixed_step_set_pending_nanoseconds(jostle_fixed_step* clock, int64_t nanoseconds) {
    return guard(__func__, false, [&] {
        clockOf(clock).clock.setPendingNanoseconds(nanoseconds);
        return true;
    });
}

} // extern "C"
