// Running a sample for the check: see sample_check.hpp.
#include "sample_check.hpp"

#include <bit>

namespace jostle::web {

namespace {

constexpr float kDt = 1.0f / 60.0f;

class Fnv1a {
public:
    void add(std::uint32_t word) {
        for (int byte = 0; byte < 4; ++byte) {
            value_ ^= (word >> (8 * byte)) & 0xFFu;
            value_ *= 1099511628211ULL;
        }
    }
    void add(Vec2 v) {
        add(std::bit_cast<std::uint32_t>(v.x));
        add(std::bit_cast<std::uint32_t>(v.y));
    }
    std::uint64_t value() const { return value_; }

private:
    std::uint64_t value_ = 14695981039346656037ULL;
};

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
    Fnv1a hash;
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
