// Sample 6: crates of different masses to push around with a character (arrows or A/D,
// space to jump). The heavier the crate, the slower the pair moves: the physical model
// shares each push by inverse mass and friction holds a heavy crate back.
#include "runner.hpp"
#include "sample_list.hpp"

#include <string>

namespace jostle::demo {

namespace {

constexpr JumpDef kJump{.height = 90.0f, .timeToApex = 0.36f};
constexpr float kRunSpeed = 220.0f;

class CratesSample : public Sample {
public:
    const char* name() const override { return "crates"; }
    bool usesLetterKeys() const override { return true; }
    BodyId player() const override { return runner_.body(); }

    void reset() override {
        panes_.clear();
        Pane pane = paneWithWorld({.gravity = {0.0f, kJump.gravity()}});
        World& world = *pane.world;
        world.createBody({.type = BodyType::Static, .x = 500, .y = 520, .hw = 520, .hh = 20});
        world.createBody({.type = BodyType::Static, .x = -10, .y = 300, .hw = 10, .hh = 240});
        world.createBody({.type = BodyType::Static, .x = 1010, .y = 300, .hw = 10, .hh = 240});

        float x = 240.0f;
        for (const float mass : {0.5f, 2.0f, 8.0f, 32.0f}) {
            const BodyId crate = world.createBody(
                {.x = x, .y = 470, .hw = 28, .hh = 28, .friction = 0.5f, .mass = mass});
            pane.labels.push_back({crate, std::to_string(static_cast<int>(mass * 2.0f) / 2) +
                                              (mass < 1.0f ? ".5" : "") + " KG"});
            x += 170.0f;
        }
        const BodyId player = world.createBody(
            {.x = 80, .y = 470, .hw = 12, .hh = 22, .friction = 0.0f, .mass = 4.0f});
        runner_ = Runner(player, kRunSpeed, kJump);
        pane.labels.push_back({player, "YOU 4 KG"});
        pane.view = {{0.0f, 250.0f}, {1000.0f, 540.0f}};
        pane.title = "physical";
        panes_.push_back(std::move(pane));
    }

    void beforeStep(const Controls& controls, float /*dt*/) override {
        runner_.steer(*panes_.front().world, controls);
    }

private:
    Runner runner_;
};

} // namespace

std::unique_ptr<Sample> makeCratesSample() {
    return std::make_unique<CratesSample>();
}

} // namespace jostle::demo
