// Sample 7: slopes and shapes (examples/scenes/slopes.json): a ball and a capsule going
// down a ramp, a hill of two ramps and a flat top, a one-sided segment that balls drop
// onto, and crates held by friction on a ramp; physical model. The keys steer a character
// (runner.hpp) that walks over the hill and sticks to it (BodyDef::snapDown).
#include "example_scenes.hpp" // generated (demo/CMakeLists.txt)
#include "runner.hpp"
#include "sample_list.hpp"

namespace jostle::demo {

namespace {

/// The scene's gravity is 800 px/s²: a jump 49 px high reaching the top in 0.35 s.
constexpr JumpDef kJump{.height = 49.0f, .timeToApex = 0.35f};
constexpr float kWalkSpeed = 160.0f;

class SlopesSample : public Sample {
public:
    const char* name() const override { return "slopes"; }
    bool usesLetterKeys() const override { return true; }
    BodyId player() const override { return runner_.body(); }

    void reset() override {
        panes_.clear();
        Pane pane = paneFromScene(parseScene(kSlopesSceneJson), "physical", 0.2f);
        // On the floor (top y 480) left of the hill. A step at 160 px/s goes 2.7 px across,
        // 1.3 px down the hill's 2:1 side: snapping 6 px keeps it on the ground.
        const BodyId player = pane.world->createBody(
            {.x = 260, .y = 468, .hw = 7, .hh = 12, .character = true, .snapDown = 6});
        runner_ = Runner(player, kWalkSpeed, kJump);
        pane.labels.push_back({player, "YOU"});
        panes_.push_back(std::move(pane));
    }

    void beforeStep(const Controls& controls, float /*dt*/) override {
        runner_.steer(*panes_.front().world, controls);
    }

private:
    Runner runner_;
};

} // namespace

std::unique_ptr<Sample> makeSlopesSample() {
    return std::make_unique<SlopesSample>();
}

} // namespace jostle::demo
