// Sample 1: the tutorial's demo (examples/scenes/tutorial.json), boxes of different
// bounce and friction falling on platforms, in the classic model on the left and the
// physical model on the right: the same bodies, two worlds side by side.
#include "sample_list.hpp"

namespace jostle::demo {

namespace {

/// The bodies of examples/scenes/tutorial.json, in pixels. Built in code so that the
/// demo runs from any directory.
Scene tutorialScene(Solver solver) {
    Scene scene;
    scene.world.gravity = {0.0f, 800.0f};
    scene.world.maxVelocity = 1000.0f;
    scene.world.solver = solver;
    const auto add = [&scene](BodyDef def) { scene.bodies.push_back({"", def}); };
    const auto platform = [&add](float x, float y, float hw, float hh, float friction) {
        add({.type = BodyType::Static, .x = x, .y = y, .hw = hw, .hh = hh, .friction = friction});
    };
    platform(400, 600, 400, 20, 0.8f); // floor
    platform(-10, 300, 10, 300, 0.0f); // walls
    platform(810, 300, 10, 300, 0.0f);
    platform(200, 420, 120, 8, 0.5f);
    platform(560, 300, 110, 8, 0.5f);
    platform(330, 180, 70, 8, 0.5f);
    add({.x = 180, .y = 40, .hw = 20, .hh = 20, .bounce = 0, .friction = 0.8f});
    add({.x = 230, .y = 0, .hw = 8, .hh = 8, .bounce = 0.8f, .friction = 0.2f});
    add({.x = 560, .y = 60, .hw = 40, .hh = 6, .bounce = 0.1f, .friction = 1});
    add({.x = 520, .y = 20, .hw = 12, .hh = 12, .vx = 120, .bounce = 0, .friction = 0});
    add({.x = 600, .y = -20, .hw = 10, .hh = 14, .bounce = 0.6f, .friction = 0.9f});
    add({.x = 330, .y = 40, .hw = 16, .hh = 10, .bounce = 0.2f, .friction = 0.5f});
    add({.x = 340, .y = -40, .hw = 5, .hh = 5, .vx = -60, .bounce = 0.4f, .friction = 0.3f});
    add({.x = 700, .y = 100, .hw = 8, .hh = 30, .bounce = 0, .friction = 0.6f});
    add({.x = 80, .y = 200, .hw = 14, .hh = 14, .vx = 200, .bounce = 0.3f, .friction = 0.1f});
    return scene;
}

class TutorialSample : public Sample {
public:
    const char* name() const override { return "tutorial"; }

    void reset() override {
        panes_.clear();
        // The same view for both, so that the two models can be compared body for body.
        const WorldBox view{{-20.0f, -60.0f}, {820.0f, 620.0f}};
        for (Solver solver : {Solver::Classic, Solver::Physical}) {
            Pane pane = paneFromScene(tutorialScene(solver), toString(solver), 0.0f);
            pane.view = view;
            panes_.push_back(std::move(pane));
        }
    }
};

} // namespace

std::unique_ptr<Sample> makeTutorialSample() {
    return std::make_unique<TutorialSample>();
}

} // namespace jostle::demo
