// Running a sample for the check: see sample_check.hpp.
#include "sample_check.hpp"

#include "shared/fnv1a.hpp"

namespace jostle::web {

namespace {

constexpr float kDt = 1.0f / 60.0f;

} // namespace

demo::Controls checkControls(int step) {
    demo::Controls controls;
    controls.right = step < 60;
    controls.left = step >= 90 && step < 150;
    controls.jumpPressed = step == 30;
    return controls;
}

std::uint64_t runSampleCheck(demo::Sample& sample, int steps) {
    sample.reset();
    shared::Fnv1a hash;
    for (int step = 0; step < steps; ++step) {
        sample.beforeStep(checkControls(step), kDt);
        for (demo::Pane& pane : sample.panes())
            pane.world->step(kDt);
        if (step % 10 != 9)
            continue;
        for (const demo::Pane& pane : sample.panes())
            for (const BodyId body : pane.world->bodies()) {
                hash.add(pane.world->position(body));
                hash.add(pane.world->velocity(body));
            }
    }
    return hash.value();
}

} // namespace jostle::web
