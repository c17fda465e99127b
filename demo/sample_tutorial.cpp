// Sample 1: the tutorial's demo (examples/scenes/tutorial.json), boxes of different
// bounce and friction falling on platforms, in the classic model on the left and the
// physical model on the right: the same bodies, two worlds side by side.
#include "example_scenes.hpp" // generated (demo/CMakeLists.txt)
#include "sample_list.hpp"

namespace jostle::demo {

namespace {

/// examples/scenes/tutorial.json, built into the program (example_scenes.hpp), in the
/// model `solver`.
Scene tutorialScene(Solver solver) {
    Scene scene = parseScene(kTutorialSceneJson);
    scene.world.solver = solver;
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
