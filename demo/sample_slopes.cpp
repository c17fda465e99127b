// Sample 7: slopes and shapes (examples/scenes/slopes.json): a ball and a capsule going
// down a ramp, a hill of two ramps and a flat top, a one-sided segment that balls drop
// onto, and crates held by friction on a ramp; physical model.
#include "example_scenes.hpp" // generated (demo/CMakeLists.txt)
#include "sample_list.hpp"

namespace jostle::demo {

namespace {

class SlopesSample : public Sample {
public:
    const char* name() const override { return "slopes"; }

    void reset() override {
        panes_.clear();
        panes_.push_back(paneFromScene(parseScene(kSlopesSceneJson), "physical", 0.2f));
    }
};

} // namespace

std::unique_ptr<Sample> makeSlopesSample() {
    return std::make_unique<SlopesSample>();
}

} // namespace jostle::demo
